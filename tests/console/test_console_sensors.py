"""The console's page says how old each sensor's value is: the Create's bumpers, a sensor kept
100 ms and read by its 40 Hz output, show the age the state event gives (`sensor_ages`)."""

from __future__ import annotations

import re
import signal

from conftest import REPO, start_console, stop_process
from devices import CreateEmulator

from console.test_console import WAIT_MS, opened_page, playwright_api

CREATE = REPO / "examples" / "create.rdis"


def test_a_sensor_s_row_shows_how_old_its_value_is(browser) -> None:
    with CreateEmulator() as dev:
        process, _, url = start_console(CREATE, "--port", dev.port)
        try:
            opened = opened_page(browser, url)
            page = next(opened)
            age = page.locator('[data-rdis-state] tr[data-name="bumperStates"] [data-age]')
            playwright_api.expect(age).to_have_text(re.compile(r"^read \d+\.\d{3} s before$"),
                                                    timeout=WAIT_MS)
            assert page.locator('[data-rdis-state] tr[data-name="bumperStates"] [data-value]').inner_text() == "0"
            next(opened, None)
        finally:
            status, stderr = stop_process(process, signal.SIGTERM)
        assert "Traceback" not in stderr, stderr
        assert status in (0, 143), stderr
