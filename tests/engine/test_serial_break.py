"""`lines break 10 ms`: a serial break (TX held low: a LIN or DMX frame's start, a device woken
or reset) sent among a primitive's modem lines, in the order written, before its request; in the
runtime and a generated driver alike, over the ScriptedPort, pyserial's `loop://` and a real pty.
The break is pyserial's `break_condition` held for the duration (its POSIX `send_break` rounds a
break to 0.25 s steps). Checked, through JSON and the printer, and shown to `on_io` and `--trace`."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest
import serial  # type: ignore[import-untyped]

from rdisc.compile import compile_path
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json
from tests.syntax.test_printer import parsed

WAKE = """\
robot wake { author "tests" }
state woken: int = 0
connection link: serial { baud 19200 }
/// A LIN-like header: a break of 13 bit times and more, then the sync byte and the id.
primitive header(id: int in 0..63) on link lines break 10 ms pack "BB" (0x55, id)
/// DTR cleared, a break, RTS asserted: in this order, and nothing written.
primitive reset() on link lines dtr = False, break 0.02 s, rts = True { woken = woken + 1 }
"""

KINDS = ["runtime", "driver"]


@pytest.mark.parametrize("kind", KINDS)
def test_the_break_comes_before_the_request_in_order(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    seen: list[tuple[str, str, bytes]] = []
    with implementation_of(kind, WAKE, tmp_path, "wake").connect(port, threads=False,
                                                                 on_io=lambda *event: seen.append(event)) as robot:
        robot.call_primitive("header", 0x3C)
        robot.call_primitive("reset")
        assert port.events == [("break", True), ("break", False), ("write", b"\x55\x3c"),
                               ("dtr", False), ("break", True), ("break", False), ("rts", True)]
        assert seen == [("lines", "link", b"break=10ms"), ("write", "link", b"\x55\x3c"),
                        ("lines", "link", b"dtr=False break=20ms rts=True")]
        assert robot.state["woken"] == 1


@pytest.mark.parametrize("kind", KINDS)
def test_pyserials_loop_port_holds_the_break_then_releases_it(kind: str, tmp_path: Path) -> None:
    loop = serial.serial_for_url("loop://", timeout=0.05)
    held: list[bool] = []
    original = type(loop)._update_break_state

    def watched(self: object) -> None:
        held.append(loop.break_condition)
        original(self)

    type(loop)._update_break_state = watched  # pyserial calls it from its `break_condition` setter
    try:
        with implementation_of(kind, WAKE, tmp_path, "wake").connect(loop, threads=False) as robot:
            robot.call_primitive("header", 1)
            assert held == [True, False] and loop.break_condition is False
            assert loop.read(2) == b"\x55\x01"  # the loop echoes what was written after the break
    finally:
        type(loop)._update_break_state = original


@pytest.mark.parametrize("kind", KINDS)
def test_a_break_on_a_real_pty_then_the_bytes(kind: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    master, slave = os.openpty()
    slept: list[float] = []
    sleep = time.sleep
    monkeypatch.setattr(time, "sleep", lambda seconds: (slept.append(seconds), sleep(seconds))[1])
    try:
        with implementation_of(kind, WAKE, tmp_path, "wake").connect(os.ttyname(slave), threads=False) as robot:
            robot.call_primitive("header", 0x3C)
            assert slept == [0.01]  # the break is held its duration, and nothing else waits
        os.set_blocking(master, False)
        assert os.read(master, 16) == b"\x55\x3c"
    finally:
        os.close(master)
        os.close(slave)


@pytest.mark.parametrize("kind", KINDS)
def test_a_port_that_refuses_a_break_is_a_connection_error(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(fail=True)
    with implementation_of(kind, WAKE, tmp_path, "wake").connect(port, threads=False) as robot:
        with pytest.raises(Exception) as raised:
            robot.call_primitive("header", 1)
        assert type(raised.value).__name__ == "RdisConnectionError"
        assert str(raised.value) == "link: header: cannot send a break of 10 ms: [Errno 5] the device is gone"
        assert port.writes == []


def test_the_break_goes_through_json_and_the_printer(tmp_path: Path) -> None:
    _, built = through_json(WAKE, tmp_path, "wake")
    assert '"lines": {\n        "break": "<10.0>"\n      }' in built
    assert '"dtr": "<False>",\n        "break": "<20.0>",\n        "rts": "<True>"' in built
    printed = print_module(parsed(WAKE))
    assert print_module(parsed(printed)) == printed
    assert "lines break 10 ms pack" in printed and "lines dtr = False, break 0.02 s, rts = True" in printed


def diagnostics_of(tmp_path: Path, text: str) -> list[tuple[str, str]]:
    source = tmp_path / "bad.rdis"
    source.write_text(text, encoding="utf-8")
    return [(d.code, d.message) for d in compile_path(str(source)).diagnostics.items]


def test_a_break_is_checked(tmp_path: Path) -> None:
    assert diagnostics_of(tmp_path, """\
robot bad { author "tests" }
connection link: serial { baud 115200 }
connection net: tcp { address "socket://10.0.0.2:4000" }
primitive none() on link lines break 0 ms
primitive long() on link lines break 11 s
primitive twice() on link lines break 1 ms, break 2 ms
primitive remote() on net lines break 10 ms pack "B" (1)
""") == [
        ("E211", "a break is held from more than 0 to 10000 ms, not 0 ms"),
        ("E211", "a break is held from more than 0 to 10000 ms, not 11000 ms"),
        ("E203", "`break` is given twice in `twice`"),
        ("E211", "`remote` sets modem lines, but connection `net` is `tcp`, which has none"),
    ]
