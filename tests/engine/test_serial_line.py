"""A connection's serial line: `databits`, `parity` and `stopbits` (8N1 unless said; S.BUS is
100000 baud 8E2, Modbus RTU 8E1) open the port with pyserial's `bytesize`, `parity` and
`stopbits`, in the runtime and a generated driver alike; the clauses are checked (E215), travel
through JSON and the printer, and count in the link budget.

On a real pseudo-terminal: Linux's pty driver keeps a stop-bit setting (CSTOPB) but forces 8
data bits and no parity on whatever is set (pty_set_termios), so those two are read from what
pyserial wrote with `tcsetattr` and from the open port's own attributes.
"""

from __future__ import annotations

import json
import os
import termios
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
import serial  # type: ignore[import-untyped]

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.semantics.budget import budget
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import implementation_of, through_json
from tests.syntax.test_printer import parsed

SBUS = """\
robot sbus { author "tests" }
/// A radio receiver's S.BUS: 100000 baud, 8 data bits, even parity, 2 stop bits.
connection rc: serial { baud 100000  parity even  stopbits 2 }
primitive send(value: int in 0..255) on rc pack "B" (value)
"""

SEVEN = """\
robot seven { author "tests" }
connection link: serial { baud 9600  databits 7  parity odd }
primitive send(value: int in 0..127) on link pack "B" (value)
"""

PLAIN = """\
robot plain { author "tests" }
connection link: serial { baud 115200 }
primitive send(value: int in 0..255) on link pack "B" (value)
"""

KINDS = ["runtime", "driver"]


@pytest.fixture
def pty() -> Iterator[tuple[int, int]]:
    master, slave = os.openpty()
    yield master, slave
    os.close(master)
    os.close(slave)


@pytest.fixture
def opened(monkeypatch: pytest.MonkeyPatch) -> list[tuple[Any, list[int]]]:
    """Each port pyserial opens, with the control flags it writes to the terminal."""
    ports: list[tuple[Any, list[int]]] = []
    written: list[int] = []
    open_url, set_attributes = serial.serial_for_url, termios.tcsetattr

    def serial_for_url(*args: Any, **kwargs: Any) -> Any:
        port = open_url(*args, **kwargs)
        ports.append((port, list(written)))
        written.clear()
        return port

    def tcsetattr(fd: int, when: int, attributes: list[Any]) -> None:
        written.append(attributes[2])
        set_attributes(fd, when, attributes)

    monkeypatch.setattr(serial, "serial_for_url", serial_for_url)
    monkeypatch.setattr(termios, "tcsetattr", tcsetattr)
    return ports


def _character(cflag: int) -> tuple[int, bool, bool, bool]:
    """Data bits, parity enabled, parity odd, two stop bits: a control flag's serial line."""
    sizes = {termios.CS5: 5, termios.CS6: 6, termios.CS7: 7, termios.CS8: 8}
    return (sizes[cflag & termios.CSIZE], bool(cflag & termios.PARENB), bool(cflag & termios.PARODD),
            bool(cflag & termios.CSTOPB))


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize(("text", "settings", "character"), [
    (SBUS, (100000, 8, "E", 2), (8, True, False, True)),
    (SEVEN, (9600, 7, "O", 1), (7, True, True, False)),
    (PLAIN, (115200, 8, "N", 1), (8, False, False, False)),
], ids=["8E2", "7O1", "8N1"])
def test_the_port_opens_with_the_stated_line(kind: str, text: str, settings: tuple[int, int, str, int],
                                             character: tuple[int, bool, bool, bool], tmp_path: Path,
                                             pty: tuple[int, int], opened: list[tuple[Any, list[int]]]) -> None:
    master, slave = pty
    implementation = implementation_of(kind, text, tmp_path, f"line_{kind}")
    with implementation.connect(os.ttyname(slave), threads=False) as robot:
        [(port, written)] = opened
        assert (port.baudrate, port.bytesize, port.parity, port.stopbits) == settings
        assert _character(written[-1]) == character  # what pyserial set on the terminal
        assert _character(termios.tcgetattr(slave)[2])[3] == character[3]  # the pty keeps the stop bits
        robot.primitives.send(0x0F)
        assert os.read(master, 16) == b"\x0f"
    if kind == "driver" and text == SBUS:
        driver = Path(implementation.__file__).read_text(encoding="utf-8")
        assert "  connection rc: serial, 100000 baud, 8E2\n" in driver
        assert '_C_RC = Connection("rc", 100000, frequency=10.0, parity="even", stop_bits=2)\n' in driver


def diagnostics_of(tmp_path: Path, text: str) -> list[tuple[str, str]]:
    source = tmp_path / "bad.rdis"
    source.write_text(text, encoding="utf-8")
    return [(d.code, d.message) for d in compile_path(str(source)).diagnostics.items]


def test_the_line_is_checked(tmp_path: Path) -> None:
    assert diagnostics_of(tmp_path, """\
robot bad { author "tests" }
connection a: serial { parity evn  databits 9  stopbits 3 }
connection b: serial { databits 8  stopbits 1.5  parity odd  parity even }
connection c: tcp { address "socket://10.0.0.2:502"  parity even }
connection d: serial { databits 5  stopbits 1.5  parity mark }
connection e: serial { databits 7.5  stopbits 0 }
primitive p() on a pack "B" (1)
""") == [
        ("E215", "a character has 5, 6, 7 or 8 data bits, not 9"),
        ("E215", "unknown parity `evn`"),
        ("E215", "a character ends with 1, 1.5 or 2 stop bits, not 3"),
        ("E203", "`parity` is given twice in `b`"),
        ("E215", "1.5 stop bits go with 5 data bits, not 8"),
        ("E215", "`c` is a tcp connection, which has no serial line to set"),
        ("E215", "a character has 5, 6, 7 or 8 data bits, not 7.5"),
        ("E215", "a character ends with 1, 1.5 or 2 stop bits, not 0"),
    ]


def test_the_rates_of_radio_control_buses_are_standard(tmp_path: Path) -> None:
    assert diagnostics_of(tmp_path, """\
robot rc { author "tests" }
connection sbus: serial { baud 100000 }
connection crsf: serial { baud 420000 }
connection odd: serial { baud 100001 }
""") == [("W201", "100001 is not a standard baud rate")]


def test_the_line_goes_through_json_and_back(tmp_path: Path) -> None:
    text = SBUS.replace("stopbits 2 }", "stopbits 2 }\nconnection old: serial { databits 5  stopbits 1.5 }")
    compilation, built = through_json(text, tmp_path, "sbus")
    connections = {c["name"]: c for c in json.loads(built)["connections"]["spp"]}
    assert connections["rc"] == {
        "name": "rc", "baud": 100000, "parity": "even", "stopBits": 2, "singleThreading": {"freqHz": 10},
        "doc": "A radio receiver's S.BUS: 100000 baud, 8 data bits, even parity, 2 stop bits.",
    }  # fmt: skip
    assert connections["old"] == {"name": "old", "baud": 9600, "dataBits": 5, "stopBits": 1.5,
                                  "singleThreading": {"freqHz": 10}}
    model = compilation.model
    assert model is not None
    assert [(c.data_bits, c.parity, c.stop_bits) for c in model.connections.values()] == [
        (8, "even", 2.0), (5, "none", 1.5)]


def test_the_line_prints_and_parses_back() -> None:
    text = SEVEN.replace("parity odd }", "parity odd  stopbits 1.5 }")
    module = parsed(text)
    printed = print_module(module)
    assert parsed(printed) == module
    assert "connection link: serial {\n    baud 9600\n    databits 7\n    parity odd\n    stopbits 1.5\n}\n" in printed


def test_the_budget_counts_the_line_bits(tmp_path: Path) -> None:
    """12 bits a byte at 8E2, 10 at 8N1: the same baud carries fewer bytes."""
    source = tmp_path / "sbus.rdis"
    source.write_text(SBUS.replace("stopbits 2 }", "stopbits 2 }\nconnection plain: serial { baud 100000 }"))
    model = compile_path(str(source)).model
    assert model is not None
    budgets = {b.connection: b.capacity for b in budget(model, Diagnostics())}
    assert budgets == {"rc": 100000 / 12, "plain": 100000 / 10}
