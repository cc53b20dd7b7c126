"""`rdisc console` in a real browser (Debian's Chromium driven by Playwright) against the
emulated Create on a pty: what a form sends reaches the device as thesis Table 4.3's bytes,
a pressed bumper shows in `detect_bump`'s panel, the trace shows the bytes, a page of
another site cannot drive the robot, and stopping the console runs the terminate hook.

Nothing here waits for a time: every wait is for a condition, with a generous timeout."""

from __future__ import annotations

import json
import os
import signal
import socket
import struct
import subprocess
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from conftest import REPO, console_origin, console_ws, start_console, stop_process
from devices import CreateEmulator
from devices.create import DRIVE, STOP, TABLE_4_3

CHROMIUM = Path("/usr/bin/chromium")
# The bumpers polled every tick (as before they became a sensor): the trace test counts on polls
CREATE = REPO / "tests" / "runtime" / "data" / "polled" / "create.rdis"
WAIT_MS = 30_000  # a generous limit for any one condition (never a measure of speed)
ON_CI = os.environ.get("CI", "").lower() in ("1", "true", "yes")

playwright_api = pytest.importorskip("playwright.sync_api")
if not CHROMIUM.exists():
    if ON_CI:
        raise RuntimeError("the console's tests need Debian's chromium (.ci/run installs it)")
    pytest.skip("Debian's chromium is not installed (apt-get install chromium)", allow_module_level=True)


@dataclass
class Running:
    """A console serving the emulated Create."""

    dev: CreateEmulator
    process: subprocess.Popen[str]
    url: str

    def stop(self, signum: signal.Signals) -> tuple[int, str]:
        """Signal the console; its exit status and what it printed on stderr."""
        return stop_process(self.process, signum)


def _console(dev: CreateEmulator, *extra: str) -> Running:
    """`rdisc console examples/create.rdis` on the emulator's pty, on a free loopback port."""
    process, _, url = start_console(CREATE, "--port", dev.port, *extra)
    return Running(dev, process, url)


@pytest.fixture(scope="module")
def console() -> Iterator[Running]:
    with CreateEmulator() as dev:
        running = _console(dev)
        try:
            yield running
        finally:
            status, stderr = running.stop(signal.SIGTERM)
            assert status == 143, stderr
            assert "Traceback" not in stderr, stderr


def launched_chromium() -> Iterator[object]:
    """Debian's Chromium under Playwright, for the `browser` fixture (tests/console/conftest.py)."""
    with playwright_api.sync_playwright() as p:
        launched = p.chromium.launch(executable_path=str(CHROMIUM), args=["--no-sandbox"])
        yield launched
        launched.close()


def opened_page(browser, url: str) -> Iterator[object]:
    """A page of its own at the console's `url`, once its WebSocket is connected."""
    context = browser.new_context()
    opened = context.new_page()
    opened.set_default_timeout(WAIT_MS)
    opened.goto(url)
    playwright_api.expect(opened.locator("[data-rdis-status]")).to_have_text("connected", timeout=WAIT_MS)
    yield opened
    context.close()


def refused_elsewhere(browser, attack: str) -> None:
    """`attack`, a page of another site (http://elsewhere.example/) in a context of its own,
    until its title says the console refused its WebSocket."""
    context = browser.new_context()
    try:
        context.route("http://elsewhere.example/", lambda route: route.fulfill(body=attack, content_type="text/html"))
        other = context.new_page()
        other.goto("http://elsewhere.example/")
        playwright_api.expect(other).to_have_title("refused", timeout=WAIT_MS)
    finally:
        context.close()


@pytest.fixture
def page(browser, console: Running):
    """A page of the console; once it closed (the last page), the stop its terminate hook sends."""
    opened = opened_page(browser, console.url)
    yield next(opened)
    stops = _stops(console.dev)
    next(opened, None)  # closed
    console.dev.wait_until(lambda: _stops(console.dev) > stops, 30, "the stop once the last page closed")


def _stops(dev: CreateEmulator) -> int:
    with dev._cond:
        return sum(1 for _, c in dev.commands if c == STOP)


def _drive_bytes(velocity: int, radius: int) -> bytes:
    return struct.pack(">Bhh", DRIVE, velocity, radius)


def _send(page, name: str, **fields: float) -> None:
    """Fill the input's form, submit it and wait until the console answers "done"."""
    form = page.locator(f'form[data-rdis-input="{name}"]')
    for field, value in fields.items():
        form.locator(f'input[name="{field}"]').fill(str(value))
    form.locator("button[type=submit]").click()
    playwright_api.expect(form.locator(".result")).to_have_text("done", timeout=WAIT_MS)


def test_the_page_shows_the_description(page) -> None:
    form = page.locator('form[data-rdis-input="set_velocity"]')
    assert form.locator('input[name="linear"]').count() == 1
    assert form.locator('input[name="angular"]').count() == 1
    assert "m/s" in form.inner_text() and "rad/s" in form.inner_text()
    assert page.locator('[data-rdis-output="detect_bump"] [data-field="distance"]').count() == 1
    assert page.locator('form[data-rdis-interface="drive"] input[name="velocity"]').count() == 1
    assert page.locator('form[data-rdis-primitive="drive"] input[name="radius"]').count() == 1
    assert page.locator('[data-rdis-state] tr[data-name="bumperStates"]').count() == 1
    assert page.locator("[data-rdis-sim]").count() == 0  # a device, not a simulation
    assert page.locator("[data-rdis-body]").count() == 0  # so no view of a simulated body
    # the graph: a node clicked shows its details
    page.locator('[data-rdis-graph] svg g.node[id="input:set_velocity"]').click()
    details = page.locator("[data-rdis-details]")
    playwright_api.expect(details).to_contain_text("input set_velocity", timeout=WAIT_MS)
    playwright_api.expect(details).to_contain_text("calls drive()", timeout=WAIT_MS)
    playwright_api.expect(details).to_contain_text("create.rdis:", timeout=WAIT_MS)


def test_set_velocity_from_the_form_reaches_the_device_as_table_4_3(page, console: Running) -> None:
    dev = console.dev
    for (linear, angular), (opcode, velocity, radius) in TABLE_4_3:
        before = len(dev.drives())
        _send(page, "set_velocity", linear=linear, angular=angular)
        dev.wait_for_commands(before + 1, timeout=30, opcode=DRIVE)
        sent = [c for _, c in dev.commands if c[0] == DRIVE][before:]
        assert sent == [_drive_bytes(velocity, radius)], (linear, angular)


def test_the_trace_shows_the_bytes_written_and_read(page, console: Running) -> None:
    _send(page, "set_velocity", linear=0.2, angular=0)
    trace = page.locator("[data-rdis-trace] tbody")
    written = trace.locator("tr.write", has_text="89 00 c8 7f ff").first
    playwright_api.expect(written).to_contain_text("btserial", timeout=WAIT_MS)
    assert written.locator("td").nth(2).inner_text() == ">"
    assert written.get_attribute("title") == "btserial > 89 00 c8 7f ff"  # as `rdisc run --trace` prints it
    polled = trace.locator("tr.write", has_text="8e 07").first  # the bumper poll, Sensors packet 7
    playwright_api.expect(polled).to_be_attached(timeout=WAIT_MS)
    playwright_api.expect(trace.locator("tr.read").first).to_contain_text("<", timeout=WAIT_MS)


def test_a_pressed_bumper_shows_in_the_detect_bump_panel(page, console: Running) -> None:
    distance = page.locator('[data-rdis-output="detect_bump"] [data-field="distance"]')
    state = page.locator('[data-rdis-state] tr[data-name="bumperStates"] [data-value]')
    playwright_api.expect(distance).to_have_text("1", timeout=WAIT_MS)
    console.dev.bumpers = 1  # the right bumper
    try:
        playwright_api.expect(distance).to_have_text("0", timeout=WAIT_MS)
        playwright_api.expect(state).to_have_text("1", timeout=WAIT_MS)
    finally:
        console.dev.bumpers = 0
    playwright_api.expect(distance).to_have_text("1", timeout=WAIT_MS)
    count = page.locator('[data-rdis-output="detect_bump"] [data-count]')
    assert int(count.inner_text()) > 0
    painted = page.locator('[data-rdis-output="detect_bump"] canvas[data-plot]').evaluate(
        "c => c.getContext('2d').getImageData(0, 0, c.width, c.height).data.some(v => v !== 0)")
    assert painted  # the plot of distance over time is drawn


def test_a_primitive_form_sends_one_device_command(page, console: Running) -> None:
    dev = console.dev
    before = len(dev.drives())
    form = page.locator('form[data-rdis-primitive="drive"]')
    form.locator('input[name="velocity"]').fill("100")
    form.locator('input[name="radius"]').fill("-1")
    form.locator("button[type=submit]").click()
    playwright_api.expect(form.locator(".result")).to_have_text("done", timeout=WAIT_MS)
    dev.wait_for_commands(before + 1, timeout=30, opcode=DRIVE)
    assert [c for _, c in dev.commands if c[0] == DRIVE][before:] == [bytes.fromhex("89 00 64 ff ff")]


def test_a_bad_value_is_refused_and_shown_as_an_error(page, console: Running) -> None:
    from websockets.sync.client import connect

    before = len(console.dev.commands)
    with connect(console_ws(console.url), origin=console_origin(console.url)) as ws:
        hello = json.loads(ws.recv())
        assert hello["type"] == "hello"
        ws.send(json.dumps({"id": 7, "kind": "input", "name": "set_velocity",
                            "values": {"linear": "fast", "angular": "0"}}))
        reply = next(m for m in map(json.loads, iter(ws.recv, None)) if m["type"] == "result")
    assert reply == {"type": "result", "id": 7, "ok": False, "error": "ValueError",
                     "message": "set_velocity: linear must be a number, not 'fast'"}
    errors = page.locator("[data-rdis-errors]")
    playwright_api.expect(errors).to_contain_text("ValueError: set_velocity: linear must be a number, not 'fast'",
                                                  timeout=WAIT_MS)
    assert not [c for _, c in console.dev.commands[before:] if c[0] == DRIVE]


def test_a_page_of_another_site_cannot_drive_the_robot(browser, console: Running) -> None:
    """A page from another origin, open in the same browser, tries the console's WebSocket."""
    ws_url = console_ws(console.url)  # even with the token, the Origin is refused
    attack = f"""<!DOCTYPE html><title>waiting</title><script>
      const ws = new WebSocket({json.dumps(ws_url)});
      ws.onopen = () => {{ document.title = "opened";
        ws.send(JSON.stringify({{id: 1, kind: "input", name: "set_velocity", values: {{linear: "0.5", angular: "0"}}}}));
        ws.send(JSON.stringify({{id: 2, kind: "primitive", name: "drive", values: {{velocity: "500", radius: "0"}}}})); }};
      ws.onclose = () => {{ if (document.title === "waiting") document.title = "refused"; }};
    </script>"""
    before = len(console.dev.commands)
    refused_elsewhere(browser, attack)
    assert not [c for _, c in console.dev.commands[before:] if c[0] == DRIVE]


def test_a_foreign_origin_is_answered_403(console: Running) -> None:
    from websockets.exceptions import InvalidStatus
    from websockets.sync.client import connect

    before = len(console.dev.commands)
    ws_url = console_ws(console.url)  # with the token: the Origin and Host are what is refused
    port = int(console_origin(console.url).rsplit(":", 1)[1])
    own = console_origin(console.url)
    # another site's page; no Origin at all; this console's Origin sent to another name that
    # leads here (DNS rebinding: the Host is not the console's)
    for url, origin in ((ws_url, "http://elsewhere.example"), (ws_url, None),
                        (ws_url.replace("127.0.0.1", "elsewhere.example"), own)):
        with pytest.raises(InvalidStatus) as refused:
            connect(url, origin=origin, sock=socket.create_connection(("127.0.0.1", port)))
        assert refused.value.response.status_code == 403
    assert not [c for _, c in console.dev.commands[before:] if c[0] == DRIVE]


def test_stopping_the_console_runs_the_terminate_hook() -> None:
    with CreateEmulator() as dev:
        running = _console(dev)
        dev.wait_for_commands(2, timeout=30)
        status, stderr = running.stop(signal.SIGINT)
        assert status == 130, stderr
        assert "Traceback" not in stderr, stderr
        dev.wait_until(lambda: bool(dev.commands) and dev.commands[-1][1] == STOP, 30, "the stop command last")
        assert dev.commands[-1][1] == STOP
        assert dev.opcodes()[:2] == [128, 132]  # the startup hook: Start, Full


def test_the_plot_s_axes_are_at_round_values(page) -> None:
    """The plot's gridlines and labels: the smallest step of 1, 2 or 5 times a power of ten that
    gives no more than about the ticks asked for."""
    assert page.evaluate("[ticks(0, 0.37, 5), ticks(-1.5, 1.5, 4), ticks(12.3, 14.1, 5), ticks(0, 1000, 4)]") == [
        [0, 0.1, 0.2, 0.3], [-1, 0, 1], [12.5, 13, 13.5, 14], [0, 500, 1000]]


def test_the_page_opens_only_through_the_printed_address(browser, console: Running) -> None:
    """The address the console printed carries its token, and the page passes it on to its WebSocket
    (every page of these tests opens through it); without the token the page is refused."""
    context = browser.new_context()
    try:
        refused = context.new_page().goto(console_origin(console.url) + "/")
        assert refused is not None and refused.status == 403
        opened = next(opened_page(browser, console.url))
        playwright_api.expect(opened.locator("[data-rdis-status]")).to_have_text("connected", timeout=WAIT_MS)
        opened.context.close()
    finally:
        context.close()


def _raw(page, hex_text: str) -> None:
    """Type bytes into the raw terminal and send them; wait until the console answers."""
    form = page.locator("form[data-rdis-raw]")
    form.locator('input[name="hex"]').fill(hex_text)
    form.locator("button[type=submit]").click()
    playwright_api.expect(form.locator(".result")).not_to_have_text("…", timeout=WAIT_MS)


def _sensor_requests(dev: CreateEmulator, packet: int) -> list[bytes]:
    with dev._cond:
        return [c for _, c in dev.commands if c == bytes([142, packet])]


def test_the_raw_terminal_sends_typed_bytes_and_shows_the_answer(page, console: Running) -> None:
    """Sensors packet 22 (the voltage, 15000 mV), typed as hex: the device receives exactly those
    bytes once, and the page shows its two-byte answer in hex and ASCII, as miniterm does."""
    assert _sensor_requests(console.dev, 22) == []
    _raw(page, "8e 16")
    playwright_api.expect(page.locator("form[data-rdis-raw] .result")).to_have_text("done", timeout=WAIT_MS)
    assert _sensor_requests(console.dev, 22) == [b"\x8e\x16"]
    log = page.locator("[data-rdis-raw-log] li")
    assert log.all_inner_texts() == ["btserial > 8e 16..", "btserial < 3a 98:."]
    assert log.nth(1).locator(".hex").inner_text() == "3a 98" and log.nth(1).locator(".ascii").inner_text() == ":."
    trace = page.locator("[data-rdis-trace] tbody")  # the trace shows them as it shows a call's bytes
    playwright_api.expect(trace.locator("tr.write", has_text="8e 16")).to_have_count(1, timeout=WAIT_MS)
    playwright_api.expect(trace.locator("tr.read", has_text="3a 98")).to_have_count(1, timeout=WAIT_MS)


def test_bad_hex_in_the_raw_terminal_is_a_message(page, console: Running) -> None:
    before = len(console.dev.commands)
    _raw(page, "8e zz")
    playwright_api.expect(page.locator("form[data-rdis-raw] .result")).to_have_text(
        "ValueError: raw: 'z' is not a hex digit (type the bytes as hex: 8e 16)", timeout=WAIT_MS)
    with console.dev._cond:
        assert all(c == b"\x8e\x07" for _, c in console.dev.commands[before:])  # only the bumper polls
    assert page.locator("[data-rdis-raw-log] li").count() == 0


def test_the_paused_trace_holds_what_comes_and_shows_it_when_resumed(page, console: Running) -> None:
    rows = page.locator("[data-rdis-trace] tbody tr")
    playwright_api.expect(rows.first).to_be_attached(timeout=WAIT_MS)
    page.locator("[data-rdis-trace-pause]").click()
    frozen = rows.all_inner_texts()
    _raw(page, "8e 13")  # the distance, packet 19: 00 00
    console.dev.wait_until(lambda: bool(_sensor_requests(console.dev, 19)), 30, "the raw request")
    held = page.locator("[data-rdis-trace-held]")
    playwright_api.expect(held).not_to_have_text("0 held", timeout=WAIT_MS)
    assert rows.all_inner_texts() == frozen  # the display is frozen while bytes keep coming
    page.locator("[data-rdis-trace-pause]").click()
    playwright_api.expect(held).to_have_text("", timeout=WAIT_MS)
    playwright_api.expect(page.locator("[data-rdis-trace] tbody tr.write", has_text="8e 13")).to_have_count(
        1, timeout=WAIT_MS)
    assert rows.first.inner_text() != frozen[0]


def test_the_trace_filtered_by_primitive_shows_only_its_lines(page, console: Running) -> None:
    _raw(page, "8e 1a")  # the capacity, packet 26: no primitive's request
    trace = page.locator("[data-rdis-trace] tbody")
    playwright_api.expect(trace.locator("tr.write", has_text="8e 1a")).to_be_visible(timeout=WAIT_MS)
    rows = """() => Array.from(document.querySelectorAll('[data-rdis-trace] tbody tr')).map(
        (row) => [row.hidden, row.className, row.cells[3].textContent, row.cells[4].textContent])"""
    page.locator("[data-rdis-trace-filter]").select_option("bumpers")
    filtered = page.evaluate(rows)
    assert ["write", "8e 1a", ""] in [row[1:] for row in filtered if row[0]]  # hidden
    shown = {tuple(row[1:]) for row in filtered if not row[0]}
    assert shown == {("write", "8e 07", "bumpers"), ("read", "00", "bumpers")}  # the bumper polls, not a raw send
    page.locator("[data-rdis-trace-filter]").select_option("")
    assert not any(row[0] for row in page.evaluate(rows))
