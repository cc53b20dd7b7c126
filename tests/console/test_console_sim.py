"""`rdisc console examples/create2.rdis --sim` in a real browser (Debian's Chromium driven by
Playwright): the page drives the MuJoCo simulation of the Create 2's body on the wall clock,
with no device attached. A `set_velocity` submitted from the form moves the `odom` output's x,
the page says it is a simulation, and a page of another site still cannot drive the robot
(`--record` with `--sim`: tests/runtime/test_record.py).

Nothing here asserts a duration: the page's DOM is read a bounded number of times, and every
other wait is for a condition, with a generous timeout."""

from __future__ import annotations

import json
import re
import signal
import socket
import subprocess
import sys
from collections.abc import Iterator

import pytest
from conftest import REPO, cli_env

from console.test_console import CHROMIUM, WAIT_MS

pytest.importorskip("mujoco")
playwright_api = pytest.importorskip("playwright.sync_api")
if not CHROMIUM.exists():
    pytest.skip("Debian's chromium is not installed (apt-get install chromium)", allow_module_level=True)

CREATE2 = REPO / "examples" / "create2.rdis"
POLLS = 300  # reads of the page's odometry, 50 ms apart: the robot needs some 20 of them to move 5 cm


def _console(*extra: str) -> tuple[subprocess.Popen[str], str]:
    """`rdisc console examples/create2.rdis --sim` on a free loopback port, and its address."""
    process = subprocess.Popen([sys.executable, "-m", "rdisc", "console", str(CREATE2), "--sim", "--http",
                                "127.0.0.1:0", *extra], cwd=REPO, env=cli_env(),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert process.stdout is not None
    line = process.stdout.readline()  # printed once it listens (after the startup hooks)
    found = re.search(r"http://127\.0\.0\.1:\d+/", line)
    if found is None:
        process.kill()
        raise AssertionError(f"no address printed: {line!r} {process.communicate()}")
    assert line.startswith("rdisc console: create2, simulated, on "), line
    return process, found.group(0)


def _stop(process: subprocess.Popen[str], signum: signal.Signals) -> tuple[int, str]:
    """Signal the console; its exit status and what it printed on stderr."""
    process.send_signal(signum)
    try:
        _, stderr = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
            process.communicate()
    return process.returncode, stderr


@pytest.fixture(scope="module")
def console() -> Iterator[str]:
    process, url = _console()
    try:
        yield url
    finally:
        status, stderr = _stop(process, signal.SIGTERM)
        assert status == 143, stderr
        assert "Traceback" not in stderr, stderr


@pytest.fixture(scope="module")
def browser() -> Iterator[object]:
    with playwright_api.sync_playwright() as p:
        launched = p.chromium.launch(executable_path=str(CHROMIUM), args=["--no-sandbox"])
        yield launched
        launched.close()


@pytest.fixture
def page(browser, console: str):
    context = browser.new_context()
    opened = context.new_page()
    opened.set_default_timeout(WAIT_MS)
    opened.goto(console)
    playwright_api.expect(opened.locator("[data-rdis-status]")).to_have_text("connected", timeout=WAIT_MS)
    yield opened
    context.close()


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


def test_the_page_says_it_is_a_simulation(page) -> None:
    badge = page.locator("header [data-rdis-sim]")
    playwright_api.expect(badge).to_be_visible(timeout=WAIT_MS)
    assert badge.inner_text() == "simulation"
    assert page.title() == "create2 (simulation) — rdisc console"


def test_a_page_of_another_site_cannot_drive_the_simulation(browser, console: str) -> None:
    from websockets.exceptions import InvalidStatus
    from websockets.sync.client import connect

    ws_url = console.replace("http", "ws") + "ws"
    attack = f"""<!DOCTYPE html><title>waiting</title><script>
      const ws = new WebSocket({json.dumps(ws_url)});
      ws.onopen = () => {{ document.title = "opened"; }};
      ws.onclose = () => {{ if (document.title === "waiting") document.title = "refused"; }};
    </script>"""
    context = browser.new_context()
    try:
        context.route("http://elsewhere.example/", lambda route: route.fulfill(body=attack, content_type="text/html"))
        other = context.new_page()
        other.goto("http://elsewhere.example/")
        playwright_api.expect(other).to_have_title("refused", timeout=WAIT_MS)
    finally:
        context.close()
    port = int(console.rstrip("/").rsplit(":", 1)[1])
    for origin in ("http://elsewhere.example", None):
        with pytest.raises(InvalidStatus) as refused:
            connect(ws_url, origin=origin, sock=socket.create_connection(("127.0.0.1", port)))
        assert refused.value.response.status_code == 403

