"""`rdisc console examples/create2.rdis --sim` in a real browser (Debian's Chromium driven by
Playwright): the page drives the MuJoCo simulation of the Create 2's body on the wall clock,
with no device attached. A `set_velocity` submitted from the form moves the `odom` output's x,
the page says it is a simulation, and a page of another site still cannot drive the robot
(`--record` with `--sim`: tests/runtime/test_record.py).

Nothing here asserts a duration: the page's DOM is read a bounded number of times, and every
other wait is for a condition, with a generous timeout."""

from __future__ import annotations

import json
import signal
import socket
import subprocess
from collections.abc import Iterator

import pytest
from conftest import REPO, console_origin, console_ws, start_console, stop_process

from console.test_console import WAIT_MS, opened_page, playwright_api, refused_elsewhere

pytest.importorskip("mujoco")

CREATE2 = REPO / "examples" / "create2.rdis"
POLLS = 300  # reads of the page's odometry, 50 ms apart: the robot needs some 20 of them to move 5 cm


def _console(*extra: str) -> tuple[subprocess.Popen[str], str]:
    """`rdisc console examples/create2.rdis --sim` on a free loopback port, and its address."""
    process, line, url = start_console(CREATE2, "--sim", *extra)
    assert line.startswith("rdisc console: create2, simulated, on "), line
    return process, url


@pytest.fixture(scope="module")
def console() -> Iterator[str]:
    process, url = _console()
    try:
        yield url
    finally:
        status, stderr = stop_process(process, signal.SIGTERM)
        assert status == 143, stderr
        assert "Traceback" not in stderr, stderr


@pytest.fixture
def page(browser, console: str):
    yield from opened_page(browser, console)


def test_set_velocity_from_the_form_moves_the_simulated_odometry(page) -> None:
    x = page.locator('[data-rdis-output="odom"] [data-field="x"]')
    y = page.locator('[data-rdis-output="odom"] [data-field="y"]')
    form = page.locator('form[data-rdis-input="set_velocity"]')
    form.locator('input[name="linear"]').fill("0.2")
    form.locator('input[name="angular"]').fill("0")
    form.locator("button[type=submit]").click()
    playwright_api.expect(form.locator(".result")).to_have_text("done", timeout=WAIT_MS)
    seen: list[float] = []
    for _ in range(POLLS):
        text = x.inner_text()
        if text != "–":  # an odometry has been shown
            seen.append(float(text))
            if seen[-1] > 0.05:
                break
        page.wait_for_timeout(50)
    assert seen and seen[-1] > 0.05, seen  # it drove forward, more than 5 cm
    assert seen == sorted(seen), seen  # and never back
    assert abs(float(y.inner_text())) < 0.01  # straight ahead
    state = page.locator('[data-rdis-state] tr[data-name="odom_x"] [data-value]')
    assert float(state.inner_text()) > 0.05
    drive = page.locator("[data-rdis-trace] tbody tr.write", has_text="91 00 c8 00 c8").first
    playwright_api.expect(drive).to_contain_text("oi", timeout=WAIT_MS)  # drive_direct(200, 200), as the bytes go


def test_the_base_drives_forward_in_the_top_view(page) -> None:
    """The view of the body: the base's frame as the simulation has it, drawn further right
    (+x) as it drives, its wheels turning in the joints' numbers."""
    page.wait_for_selector("[data-rdis-body][data-t]", timeout=WAIT_MS)  # a first pose has been drawn
    base = page.locator('[data-rdis-body] g[data-view="top"] g[data-rdis-link="base"]')
    wheel = page.locator('[data-rdis-body] [data-rdis-joints] tr[data-name="left_wheel_joint"] [data-value]')

    def drawn() -> tuple[float, float, float]:
        x, y, _ = (float(v) for v in base.get_attribute("data-at").split())
        return x, y, float(base.locator("circle").get_attribute("cx"))

    start_x, start_y, start_cx = drawn()
    start_wheel = float(wheel.inner_text())
    form = page.locator('form[data-rdis-input="set_velocity"]')
    form.locator('input[name="linear"]').fill("0.2")
    form.locator('input[name="angular"]').fill("0")
    form.locator("button[type=submit]").click()
    playwright_api.expect(form.locator(".result")).to_have_text("done", timeout=WAIT_MS)
    for _ in range(POLLS):
        x, y, cx = drawn()
        if x - start_x > 0.05:
            break
        page.wait_for_timeout(50)
    assert x - start_x > 0.05 and abs(y - start_y) < 0.01, (start_x, x, y)  # straight ahead, more than 5 cm
    assert cx > start_cx  # drawn further right
    assert float(wheel.inner_text()) - start_wheel > 1  # 5 cm is 1.4 rad of a 36 mm wheel
    assert page.locator('[data-rdis-body] g[data-view="top"] g[data-rdis-link]').count() == 4


def test_the_page_says_it_is_a_simulation(page) -> None:
    badge = page.locator("header [data-rdis-sim]")
    playwright_api.expect(badge).to_be_visible(timeout=WAIT_MS)
    assert badge.inner_text() == "simulation"
    assert page.title() == "create2 (simulation) — rdisc console"


def test_a_page_of_another_site_cannot_drive_the_simulation(browser, console: str) -> None:
    from websockets.exceptions import InvalidStatus
    from websockets.sync.client import connect

    ws_url = console_ws(console)  # even with the token, the Origin is refused
    attack = f"""<!DOCTYPE html><title>waiting</title><script>
      const ws = new WebSocket({json.dumps(ws_url)});
      ws.onopen = () => {{ document.title = "opened"; }};
      ws.onclose = () => {{ if (document.title === "waiting") document.title = "refused"; }};
    </script>"""
    refused_elsewhere(browser, attack)
    port = int(console_origin(console).rsplit(":", 1)[1])
    for origin in ("http://elsewhere.example", None):
        with pytest.raises(InvalidStatus) as refused:
            connect(ws_url, origin=origin, sock=socket.create_connection(("127.0.0.1", port)))
        assert refused.value.response.status_code == 403

