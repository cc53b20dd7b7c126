"""Who may drive the robot through `rdisc console`, and that it is left stopped: a real console
process on the emulated Create (a pty), reached by raw WebSocket and HTTP clients.

- the credential: the page and the WebSocket need the token of the printed address; without it,
  with another, or with a forged `Host: 127.0.0.1:P`, the answer is 403 and nothing is driven;
- beyond loopback only with --allow-remote, and then the banner warns;
- a page that goes away leaves the robot stopped (the terminate hook runs), the robot open;
- a call nested 60,000 deep is refused with a message, the connection kept;
- with 30 pages calling a device that never answers, SIGINT's stop is not queued behind their
  calls: no page's drive after it, and it comes within about one reply timeout's worth of polls.

Nothing here waits for a time: every wait is for a condition, with a generous timeout, and
what is asserted is counts and order."""

from __future__ import annotations

import json
import re
import signal
import socket
import subprocess
import sys
import threading
import urllib.error
import urllib.request
from collections.abc import Iterator
from typing import Any

import pytest
from conftest import REPO, cli_env, console_origin, console_ws, run_rdisc_here, start_console, stop_process
from devices import CreateEmulator
from devices.create import DRIVE, SENSORS, STOP

from rdisc.console.server import MAX_DEPTH

pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

CREATE = REPO / "examples" / "create.rdis"
# The bumpers polled every tick: `rdisc replay` does not yet follow a recording's clock for a
# sensor's cache, so a recording of the sensor Create may replay a bumper read more or fewer.
POLLED_CREATE = REPO / "tests" / "runtime" / "data" / "polled" / "create.rdis"
GO = {"kind": "input", "name": "set_velocity", "values": {"linear": "0.2", "angular": "0"}}
GO_BYTES = bytes.fromhex("89 00 c8 7f ff")  # Table 4.3: 0.2 m/s straight ahead


def _drives(dev: CreateEmulator, start: int = 0) -> list[bytes]:
    with dev._cond:
        return [c for _, c in dev.commands[start:] if c[0] == DRIVE]


def _result(ws: Any) -> dict[str, Any]:
    """The next call's result on a raw client, past the events pushed meanwhile."""
    while True:
        message = json.loads(ws.recv(timeout=30))
        if message["type"] == "result":
            return message


@pytest.fixture(scope="module")
def console() -> Iterator[tuple[CreateEmulator, str]]:
    with CreateEmulator() as dev:
        process, _, url = start_console(CREATE, "--port", dev.port)
        try:
            yield dev, url
        finally:
            status, stderr = stop_process(process, signal.SIGTERM)
            assert status == 143, stderr
            assert "Traceback" not in stderr, stderr


def test_the_printed_address_carries_a_token(console) -> None:
    _, url = console
    token = url.partition("?token=")[2]
    assert len(token) >= 43  # secrets.token_urlsafe(32)


@pytest.mark.parametrize("query", ["", "?token=", "?token=wrong", "?nothing=1", "TOKEN_TWICE"])
def test_a_websocket_without_the_token_is_refused(console, query: str) -> None:
    from websockets.exceptions import InvalidStatus
    from websockets.sync.client import connect

    dev, url = console
    base = console_ws(url).partition("?")[0]
    token = url.partition("?")[2]
    ws_url = base + (f"?{token}&{token}" if query == "TOKEN_TWICE" else query)
    before = len(dev.commands)
    # the console's own Origin and Host
    with pytest.raises(InvalidStatus) as refused, connect(ws_url, origin=console_origin(url)) as ws:
        ws.send(json.dumps({"id": 1, **GO}))
    assert refused.value.response.status_code == 403
    assert b"token" in refused.value.response.body
    assert _drives(dev, before) == []


def test_a_forged_host_without_the_token_is_refused(console) -> None:
    """A program elsewhere (or any local process) that says `Host: 127.0.0.1:P` and the console's
    Origin: all the checks a browser enforces pass, and the token is still asked for."""
    dev, url = console
    port = int(console_origin(url).rsplit(":", 1)[1])
    before = len(dev.commands)
    with socket.create_connection(("127.0.0.1", port)) as raw:
        raw.sendall(f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nOrigin: http://127.0.0.1:{port}\r\n"
                    "Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                    "Sec-WebSocket-Version: 13\r\n\r\n".encode("ascii"))
        answer = b""
        while b"\r\n\r\n" not in answer:
            chunk = raw.recv(4096)
            if not chunk:
                break
            answer += chunk
    assert answer.startswith(b"HTTP/1.1 403"), answer
    assert _drives(dev, before) == []


def test_the_page_needs_the_token(console) -> None:
    _, url = console
    base = url.partition("?")[0]
    for refused in (base, base + "?token=wrong"):
        with pytest.raises(urllib.error.HTTPError) as answer:
            urllib.request.urlopen(refused, timeout=30)
        assert answer.value.code == 403
        assert b"token" in answer.value.read()
    with urllib.request.urlopen(url, timeout=30) as page:
        assert page.status == 200
        assert page.headers["Referrer-Policy"] == "no-referrer"
        assert b"<title>irobot_create" in page.read()


def test_with_the_token_a_raw_client_drives_the_robot(console) -> None:
    from websockets.sync.client import connect

    dev, url = console
    before = len(dev.commands)
    with connect(console_ws(url), origin=console_origin(url)) as ws:
        assert json.loads(ws.recv(timeout=30))["type"] == "hello"
        ws.send(json.dumps({"id": 5, **GO}))
        assert _result(ws) == {"type": "result", "id": 5, "ok": True}
        dev.wait_until(lambda: GO_BYTES in _drives(dev, before), 30, "the drive")


def test_a_call_nested_too_deep_is_refused_and_the_connection_kept(console) -> None:
    from websockets.sync.client import connect

    dev, url = console
    before = len(dev.commands)
    with connect(console_ws(url), origin=console_origin(url)) as ws:
        assert json.loads(ws.recv(timeout=30))["type"] == "hello"
        ws.send("[" * 60_000)  # within the size a message may have (64 KiB)
        assert _result(ws) == {"type": "result", "id": None, "ok": False, "error": "ValueError",
                               "message": f"a call nests its values at most {MAX_DEPTH} deep"}
        ws.send(json.dumps({"id": 6, "kind": "input", "name": "set_velocity",
                            "values": {"linear": "0.2", "angular": "0", "x": "[\\\"" * 100}}))
        assert _result(ws)["message"] == "set_velocity has no parameter or field named 'x'"  # text, not nesting
        ws.send(json.dumps({"id": 7, **GO}))  # still connected: the next call is made
        assert _result(ws) == {"type": "result", "id": 7, "ok": True}
    dev.wait_until(lambda: GO_BYTES in _drives(dev, before), 30, "the drive")


def test_beyond_loopback_needs_allow_remote() -> None:
    done = subprocess.run([sys.executable, "-m", "rdisc", "console", str(CREATE), "--port", "loop://", "--http",
                           "0.0.0.0:0"], cwd=REPO, env=cli_env(), capture_output=True, text=True, timeout=120,
                          check=False)
    assert done.returncode == 2, done.stderr
    assert "rdisc console: --http 0.0.0.0:0 serves beyond this machine" in done.stderr
    assert "--allow-remote" in done.stderr
    assert "Traceback" not in done.stderr
    assert done.stdout == ""


def test_with_allow_remote_the_banner_warns() -> None:
    process = subprocess.Popen([sys.executable, "-m", "rdisc", "console", str(CREATE), "--port", "loop://",
                                "--http", "0.0.0.0:0", "--allow-remote"], cwd=REPO, env=cli_env(),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert process.stdout is not None
    try:
        banner, warning = process.stdout.readline(), process.stdout.readline()
    finally:
        status, stderr = stop_process(process, signal.SIGINT)
    assert re.search(r"on http://0\.0\.0\.0:\d+/\?token=[A-Za-z0-9_-]{43}", banner), banner
    assert warning.startswith("rdisc console: WARNING: served beyond this machine (0.0.0.0:0): anyone on the "
                              "network who has this address can drive the robot"), warning
    assert status == 130 and "Traceback" not in stderr, stderr


def test_the_last_page_closing_stops_the_robot_and_keeps_it_open() -> None:
    from websockets.sync.client import connect

    with CreateEmulator() as dev:
        process, _, url = start_console(CREATE, "--port", dev.port)
        try:
            for round_ in range(2):  # the robot stays open for the next page
                before = len(dev.commands)
                with connect(console_ws(url), origin=console_origin(url)) as ws:
                    assert json.loads(ws.recv(timeout=30))["type"] == "hello"
                    ws.send(json.dumps({"id": 1, **GO}))
                    assert _result(ws)["ok"] is True, round_
                    dev.wait_until(lambda: GO_BYTES in _drives(dev, before), 30, "the drive")  # noqa: B023
                dev.wait_until(lambda: _drives(dev, before)[-1:] == [STOP], 30,  # noqa: B023
                               "the stop once the page closed")
                assert _drives(dev, before) == [GO_BYTES, STOP]
        finally:
            status, stderr = stop_process(process, signal.SIGINT)
        assert status == 130 and "Traceback" not in stderr, stderr
        assert stderr.count("rdisc console: the last page closed: shutdown() ran (the terminate hook); the robot "
                            "stays open for the next page") == 2, stderr


PAGES = 30


def test_sigint_s_stop_is_not_queued_behind_page_calls() -> None:
    """30 pages (more than asyncio's thread pool has threads, below 26 cores) call set_velocity as fast
    as they are answered, against a Create that never answers (its bumper poll waits a whole reply
    timeout, 0.1 s, each time, holding the port); SIGINT once every page is connected and 30 drives
    went out. After SIGINT no page call writes again (at most the one in progress, before the
    stop), and the stop comes before the poll could have timed out twice more."""
    from websockets.exceptions import ConnectionClosed
    from websockets.sync.client import connect

    with CreateEmulator(mode="silent") as dev:
        process, _, url = start_console(CREATE, "--port", dev.port, "--timeout", "0.1")
        ended = threading.Event()
        opened: list[int] = []

        def page(number: int) -> None:
            try:
                with connect(console_ws(url), origin=console_origin(url), open_timeout=60) as ws:
                    opened.append(number)
                    for n in range(10_000):
                        ws.send(json.dumps({"id": n, **GO}))
                        if _result(ws)["ok"] is not True or ended.is_set():
                            return
            except (ConnectionClosed, OSError, TimeoutError):
                return  # the console stopped

        pages = [threading.Thread(target=page, args=(n,), daemon=True) for n in range(PAGES)]
        try:
            for thread in pages:
                thread.start()
            dev.wait_until(lambda: len(opened) == PAGES, 120, "every page connected")  # each with a call queued
            dev.wait_until(lambda: len(_drives(dev)) >= PAGES, 120, "the pages' drives")
            with dev._cond:
                signalled = len(dev.commands)
            status, stderr = stop_process(process, signal.SIGINT)
        finally:
            ended.set()
            if process.poll() is None:
                process.kill()
                process.communicate()
        for thread in pages:
            thread.join(timeout=60)
        assert status == 130, stderr
        assert "Traceback" not in stderr, stderr
        dev.wait_until(lambda: STOP in _drives(dev, signalled), 30, "the stop")
        with dev._cond:
            after = [c for _, c in dev.commands[signalled:]]
        stop = after.index(STOP)
        assert [c for c in after[stop + 1:] if c[0] == DRIVE] == [], after  # no page's drive after the stop
        assert len([c for c in after[:stop] if c == GO_BYTES]) <= 2, after  # the call in progress at most
        assert len([c for c in after[:stop] if c[0] == SENSORS]) <= 2, after  # within about one timed-out poll


@pytest.mark.parametrize("ping", ["0", "inf", "soon"])
def test_a_ping_that_is_no_time_is_a_usage_error(ping: str) -> None:
    done = run_rdisc_here("console", CREATE, "--port", "loop://", "--ping", ping)  # refused before it serves
    assert done.returncode == 2, done.stderr
    assert "argument --ping: not a" in done.stderr and "Traceback" not in done.stderr, done.stderr


def test_the_help_tells_of_the_token_and_allow_remote() -> None:
    done = subprocess.run([sys.executable, "-m", "rdisc", "console", "--help"], cwd=REPO, env=cli_env(),
                          capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stderr
    text = " ".join(done.stdout.split())
    assert "The address it prints carries a token, new each run" in text
    assert "--allow-remote" in text and "whenever the last page closes" in text


def _masked_text(text: str) -> bytes:
    """One WebSocket text frame as a client sends it (masked; under 126 bytes)."""
    data = text.encode("utf-8")
    assert len(data) < 126
    mask = b"\x01\x02\x03\x04"
    return bytes([0x81, 0x80 | len(data)]) + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(data))


def test_a_page_that_stops_answering_pings_leaves_the_robot_stopped() -> None:
    """A client that makes a call and then goes quiet (never reads, so never answers the server's
    pings, as a machine that dropped off the network): it is closed, and the terminate hook runs."""
    with CreateEmulator() as dev:
        process, _, url = start_console(CREATE, "--port", dev.port, "--ping", "0.5")  # gone within 1 s, not 10
        try:
            port = int(console_origin(url).rsplit(":", 1)[1])
            query = url.partition("?")[2]
            with socket.create_connection(("127.0.0.1", port)) as raw:
                raw.sendall(f"GET /ws?{query} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n"
                            f"Origin: http://127.0.0.1:{port}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                            "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n"
                            .encode("ascii"))
                answer = b""
                while b"\r\n\r\n" not in answer:
                    answer += raw.recv(1)
                assert answer.startswith(b"HTTP/1.1 101"), answer
                raw.sendall(_masked_text(json.dumps({"id": 1, **GO})))
                dev.wait_until(lambda: GO_BYTES in _drives(dev), 30, "the drive")
                dev.wait_until(lambda: _drives(dev)[-1:] == [STOP], 60, "the stop once the page stopped answering")
        finally:
            status, stderr = stop_process(process, signal.SIGINT)
        assert status == 130 and "Traceback" not in stderr, stderr
        assert "rdisc console: the last page closed: shutdown() ran" in stderr, stderr


def test_a_recorded_session_replays_the_stop_of_the_last_page_closing(tmp_path) -> None:
    """With --record, the terminate hook run when the last page closed is recorded as the host's
    call, so `rdisc replay` writes the same bytes."""
    from websockets.sync.client import connect

    pytest.importorskip("mcap")
    path = tmp_path / "console.mcap"
    with CreateEmulator() as dev:
        process, _, url = start_console(POLLED_CREATE, "--port", dev.port, "--record", path)
        try:
            with connect(console_ws(url), origin=console_origin(url)) as ws:
                assert json.loads(ws.recv(timeout=30))["type"] == "hello"
                ws.send(json.dumps({"id": 1, **GO}))
                assert _result(ws)["ok"] is True
            dev.wait_until(lambda: _drives(dev)[-2:] == [GO_BYTES, STOP], 30, "the stop once the page closed")
        finally:
            status, stderr = stop_process(process, signal.SIGINT)
    assert status == 130 and "Traceback" not in stderr, stderr
    replayed = run_rdisc_here("replay", path, POLLED_CREATE)
    assert replayed.returncode == 0, replayed.stdout + replayed.stderr
