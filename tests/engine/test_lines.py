"""Modem lines: a primitive's `lines dtr = COND, rts = COND` sets DTR and RTS before its
request (an RPLIDAR A1's motor, an Arduino's reset pulse), or alone, in the runtime and a
generated driver alike; the clause is checked, travels through JSON and the printer, and
shows in `--trace` and `rdisc dump`.

Why no real device: a pseudo-terminal refuses the modem-line ioctls (TIOCMBIS: "Inappropriate
ioctl for device"), so the levels cannot be read back from one. Two stand-ins keep what was set:
the ScriptedPort records each line change in order with the bytes written, and pyserial's own
`loop://` port keeps `.dtr` / `.rts` through pyserial's real setters and echoes writes. The pty's
refusal is itself tested, on a real pty: it is what a port without modem lines does.
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
import serial  # type: ignore[import-untyped]
from conftest import untimed

from rdisc.compile import compile_path
from rdisc.emit.dump import dump
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json
from tests.syntax.test_printer import parsed

LIDAR = """\
robot lidar { author "tests" }
state spinning: bool = False
state status: int = 0
connection link: serial { baud 115200  startup reset() }
/// RPLIDAR A1: its motor runs while DTR is cleared; nothing is written.
primitive motor(on: bool) on link lines dtr = not on { spinning = on }
primitive scan() on link lines rts = False, dtr = not spinning pack "BB" (0xA5, 0x20)
primitive health() on link lines rts = True pack "BB" (0xA5, 0x52) unpack "<BH" { status = out[0] }
primitive echo(level: bool) on link lines rts = level pack "BB" (0x5A, 7) unpack "BB" { status = out[1] }
primitive pulse(level: bool) on link lines dtr = level
interface reset() { pulse(False) delay 1 ms  pulse(True) }
interface spin(on: bool) { motor(on) }
input start: Contact -> spin(contact)
"""

KINDS = ["runtime", "driver"]


@pytest.mark.parametrize("kind", KINDS)
def test_lines_are_set_in_order_before_the_request(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"\x01\x02\x00")
    seen: list[tuple[str, str, bytes]] = []
    implementation = implementation_of(kind, LIDAR, tmp_path, "lidar")
    with implementation.connect(port, threads=False, on_io=lambda *event: seen.append(event)) as robot:
        assert port.events == [("dtr", False), ("dtr", True)]  # the startup hook's reset pulse
        robot.inputs.start(contact=True)  # through an input and an interface: the motor runs
        assert robot.state["spinning"] is True
        robot.primitives.scan()
        robot.primitives.health()
        assert robot.state["status"] == 1
    assert port.events == [
        ("dtr", False), ("dtr", True),
        ("dtr", False),
        ("rts", False), ("dtr", False), ("write", b"\xa5\x20"),
        ("rts", True), ("write", b"\xa5\x52"),
    ]  # fmt: skip
    assert seen == [
        ("lines", "link", b"dtr=False"), ("lines", "link", b"dtr=True"),
        ("lines", "link", b"dtr=False"),
        ("lines", "link", b"rts=False dtr=False"), ("write", "link", b"\xa5\x20"),
        ("lines", "link", b"rts=True"), ("write", "link", b"\xa5\x52"), ("read", "link", b"\x01\x02\x00"),
    ]  # fmt: skip


@pytest.fixture
def loop() -> Iterator[Any]:
    """pyserial's loop:// port: its real dtr/rts setters, its levels kept, its writes echoed."""
    port = serial.serial_for_url("loop://", timeout=0.5)
    yield port
    port.close()


@pytest.mark.parametrize("kind", KINDS)
def test_pyserial_keeps_the_levels_set(kind: str, tmp_path: Path, loop: Any) -> None:
    with implementation_of(kind, LIDAR, tmp_path, "lidar").connect(loop, threads=False) as robot:
        assert (loop.dtr, loop.rts) == (True, True)
        robot.primitives.motor(True)
        assert (loop.dtr, loop.rts) == (False, True)
        robot.primitives.echo(False)  # the echoed request is its reply
        assert (loop.dtr, loop.rts, robot.state["status"]) == (False, False, 7)
        robot.primitives.motor(on=False)
        robot.primitives.echo(True)
        assert (loop.dtr, loop.rts) == (True, True)


PTY = """\
robot lidar { author "tests" }
connection link: serial { baud 115200 }
primitive scan() on link lines rts = False, dtr = False pack "BB" (0xA5, 0x20)
"""


@pytest.mark.parametrize("kind", KINDS)
def test_a_port_that_refuses_is_a_connection_error_and_nothing_is_written(kind: str, tmp_path: Path) -> None:
    master, slave = os.openpty()
    try:
        implementation = implementation_of(kind, PTY, tmp_path, "pty")
        with implementation.connect(os.ttyname(slave), threads=False) as robot:
            with pytest.raises(Exception) as raised:  # the runtime's or the driver's own RdisConnectionError
                robot.primitives.scan()
            assert type(raised.value).__name__ == "RdisConnectionError"
            assert str(raised.value) == "link: scan: cannot set rts = False: [Errno 25] Inappropriate ioctl for device"
            assert isinstance(raised.value.__cause__, OSError)
        os.set_blocking(master, False)
        with pytest.raises(BlockingIOError):
            os.read(master, 16)
    finally:
        os.close(master)
        os.close(slave)


def diagnostics_of(tmp_path: Path, text: str) -> list[tuple[str, str]]:
    source = tmp_path / "bad.rdis"
    source.write_text(text, encoding="utf-8")
    return [(d.code, d.message) for d in compile_path(str(source)).diagnostics.items]


def test_lines_are_checked(tmp_path: Path) -> None:
    assert diagnostics_of(tmp_path, """\
robot bad { author "tests" }
connection link: serial { baud 115200 }
connection net: tcp { address "socket://10.0.0.2:4000" }
primitive twice(on: bool) on link lines dtr = on, dtr = not on
primitive number(n: int) on link lines rts = n
primitive input_line() on link lines cts = True
primitive remote(on: bool) on net lines dtr = on pack "B" (1)
primitive listens() on link lines dtr = True unpack "B"
primitive both() on link lines dtr = True lines rts = True
primitive nothing() on link
""") == [
        ("E203", "`dtr` is given twice in `twice`"),
        ("E401", "`rts` takes a bool, but this is an int"),
        ("E211", "`cts` is not a modem line a primitive sets"),
        ("E211", "`remote` sets modem lines, but connection `net` is `tcp`, which has none"),
        ("E202", "primitive `listens` has neither `pack` nor `format`"),
        ("E203", "`lines` is given twice in `both`"),
        ("E202", "primitive `nothing` has neither `pack` nor `format`"),
    ]


def test_lines_go_through_json_and_back(tmp_path: Path) -> None:
    _, built = through_json(LIDAR, tmp_path, "lidar")
    primitives = {p["name"]: p for p in json.loads(built)["primitives"]}
    assert primitives["motor"] == {
        "name": "motor", "parameters": ["on"], "parameterTypes": ["bool"], "connection": "link",
        "lines": {"dtr": "<not on>"}, "postActions": ["spinning = on"],
        "doc": "RPLIDAR A1: its motor runs while DTR is cleared; nothing is written.",
    }  # fmt: skip
    assert primitives["scan"] == {
        "name": "scan", "parameters": [], "parameterTypes": [], "connection": "link",
        "lines": {"rts": "<False>", "dtr": "<not spinning>"}, "pack": "BB", "formatArgs": ["<165>", "<32>"],
    }  # fmt: skip


def test_lines_print_and_parse_back() -> None:
    module = parsed(LIDAR)
    text = print_module(module)
    assert parsed(text) == module
    assert "primitive motor(on: bool) on link lines dtr = not on { spinning = on }\n" in text
    assert 'primitive scan() on link lines rts = False, dtr = not spinning pack "BB" (165, 32)\n' in text
    assert "    on link\n    lines rts = level\n" in text  # one clause a line when it is too long


def test_dump_and_budget_show_the_lines(tmp_path: Path) -> None:
    source = tmp_path / "lidar.rdis"
    source.write_text(LIDAR, encoding="utf-8")
    model = compile_path(str(source)).model
    assert model is not None
    blocks = dump(model).split("\n\n")
    assert blocks[0] == "primitive motor(on: bool) on link\n  lines: dtr = not on\n  request: none\n  reply: none"
    assert blocks[1].splitlines()[:3] == [
        "primitive scan() on link", "  lines: rts = False, dtr = not spinning (set before the request)",
        "  request: 2 bytes"]
    assert message_bytes(model.primitives["motor"]) == 0  # no byte on the wire
    assert message_bytes(model.primitives["scan"]) == 2


def test_trace_shows_the_lines(tmp_path: Path, rdisc: Any) -> None:
    source = tmp_path / "lidar.rdis"
    source.write_text(LIDAR, encoding="utf-8")
    result = rdisc("run", source, "--port", "loop://", "--call", "scan", "--trace")
    assert result.returncode == 0, result.stderr
    assert untimed(result.stderr) == [
        "link lines dtr=False", "link lines dtr=True", "link lines rts=False dtr=True", "link > a5 20"]
