"""examples/firmata.rdis writes StandardFirmata's commands and reads its messages as pyFirmata2
(2.5.1, a maintained fork of pyFirmata) does, and makes the same board layout of an Arduino Uno's
capability report.

Why: pyFirmata2 is what Python users drive Firmata boards with. Its Board opens a real pyserial
port (here one end of a pty, with an emulated Uno on the other), asks the capability query itself
when given no layout (`auto_setup`) and turns the report into pin lists with
`pin_list_to_board_dict`; its pins write port messages keeping the port's other output bits, PWM
and servo values as analog messages, and its iterate() reads the board's messages. The same
lists come from the description's `pin_modes` (a bit a mode, from `reply each until "\\x7F"` and
`bitset`). pyFirmata2 looks for a digital pin as the pairs (0, 1), (1, 1) side by side, as
StandardFirmata 2.3 sends them; StandardFirmata 2.5 puts input pull-up (11, 1) between them, and
pyFirmata2 then finds only the pins without modes, which the description, reading a set of modes
a pin, does not. Both the runtime and the generated driver are checked.

pyFirmata2's Board waits 5 s for an Arduino to reset and 0.1 s for the report, by the clock; the
harness's Board waits instead until the emulator's bytes have arrived, and starts no thread.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest

pyfirmata2 = pytest.importorskip("pyfirmata2")

from tests.devices import pty_device
from tests.engine.test_one_engine import ScriptedPort, implementation_of
from tests.engine.test_records import uno_report

DESCRIPTION = (Path(__file__).resolve().parents[2] / "examples" / "firmata.rdis").read_text(encoding="utf-8")
NAME = b"StandardFirmata.ino"
FIRMWARE = b"\xf0\x79\x02\x05" + bytes(b for c in NAME for b in (c & 0x7F, c >> 7)) + b"\xf7"
# REPORT_VERSION 2.5, the firmware's name, analog pin 0 at 512, digital port 1 with pin 10 high
STREAM = b"\xf9\x02\x05" + FIRMWARE + b"\xe0\x00\x04" + b"\x91\x04\x00"


def _arrived(board: Any, size: int) -> None:
    """Until `size` bytes wait in the board's port (a bound, not a test of time)."""
    deadline = time.monotonic() + 10.0
    while board.sp.in_waiting < size and time.monotonic() < deadline:
        time.sleep(0.001)


class Board(pyfirmata2.Board):  # type: ignore[misc]
    """pyFirmata2's Board, whose waits by the clock wait for the emulator's bytes instead."""

    expected = 0  # the bytes of the capability report the emulator answers

    def _Board__pass_time(self, t: float) -> None:
        if t < 1:  # after the capability query; the longer wait is for a reset, which an emulator needs not
            _arrived(self, self.expected)


def _board(port: str, report: bytes) -> Any:
    Board.expected = len(report)
    return Board(port, layout=None, baudrate=57600)


@contextmanager
def _uno(report: bytes) -> Iterator[tuple[Any, Any]]:
    """An emulated Uno on a pty answering the capability query with `report`, and pyFirmata2's
    Board on it, set up by that query as pyFirmata2 does; closed after."""
    with pty_device(lambda data: report if data == b"\xf0\x6b\xf7" else None) as dev:
        board = _board(dev.port, report)
        try:
            yield dev, board
        finally:
            board.exit()


def _layout(modes: tuple[int, ...], pins: int) -> dict[str, tuple[int, ...]]:
    """pyFirmata2's board dict from the description's sets of modes: pins 0..pins-1 renumbered as
    it does (its digital pins those not analog, its analog pins counted from 0), servo pins the
    digital ones, disabled the pins with no mode."""
    analog = [p for p in range(pins) if modes[p] >> 2 & 1]
    disabled = [p for p in range(pins) if modes[p] == 0]
    digital = [p for p in range(pins) if (modes[p] & 3 == 3 or modes[p] == 0) and p not in analog]
    return {"digital": tuple(range(len(digital))), "analog": tuple(range(len(analog))),
            "pwm": tuple(p for p in range(pins) if modes[p] >> 3 & 1), "servo": tuple(range(len(digital))),
            "disabled": tuple(disabled)}


def _rdisc_modes(kind: str, report: bytes, tmp_path: Path) -> tuple[tuple[int, ...], int, bytes]:
    port = ScriptedPort(report)
    with implementation_of(kind, DESCRIPTION, tmp_path, "firmata").connect(port, threads=False) as robot:
        robot.call_primitive("capabilities")
        return robot.state["pin_modes"], robot.state["pins"], bytes(port.written)


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_the_capability_query_and_layout_are_pyfirmata2s(kind: str, tmp_path: Path) -> None:
    report = uno_report(pullup=False)  # StandardFirmata 2.3
    with _uno(report) as (dev, board):
        layout = board._layout
    asked = dev.received
    modes, pins, written = _rdisc_modes(kind, report, tmp_path)
    assert written == asked == b"\xf0\x6b\xf7"
    assert layout == _layout(modes, pins) == {
        "digital": tuple(range(14)), "analog": tuple(range(6)), "pwm": (3, 5, 6, 9, 10, 11),
        "servo": tuple(range(14)), "disabled": (0, 1)}


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_firmata_2_5_report_loses_pyfirmata2_its_digital_pins(kind: str, tmp_path: Path) -> None:
    report = uno_report(pullup=True)
    # its layout has 2 digital pins, and PWM pins past them
    with pty_device(lambda data: report if data == b"\xf0\x6b\xf7" else None) as dev, pytest.raises(IndexError):
        _board(dev.port, report)
    pin_lists: list[list[int]] = [[]]  # the report split as its _handle_report_capability_response does
    for byte in report[2:-1]:
        pin_lists[-1].append(byte)
        if byte == 0x7F:
            pin_lists.append([])
    layout = pyfirmata2.util.pin_list_to_board_dict(pin_lists[:-1])
    modes, pins, _ = _rdisc_modes(kind, report, tmp_path)
    assert layout["digital"] == (0, 1) and layout["pwm"] == (3, 5, 6, 9, 10, 11)
    assert _layout(modes, pins)["digital"] == tuple(range(14))
    assert all(modes[p] >> 11 & 1 for p in range(2, 20))  # input pull-up, which pyFirmata2 does not know


REQUESTS: list[tuple[str, str, tuple[Any, ...], str]] = [
    ("primitive", "set_pin_mode", (13, 1), "f4 0d 01"),
    ("interface", "digital_write", (13, True), "91 20 00"),
    ("primitive", "set_pin_mode", (12, 1), "f4 0c 01"),
    ("interface", "digital_write", (12, True), "91 30 00"),  # pin 13 kept high
    ("interface", "digital_write", (13, False), "91 10 00"),
    ("primitive", "set_pin_mode", (3, 3), "f4 03 03"),
    ("primitive", "analog_write", (3, round(0.5 * 255)), "e3 00 01"),
    ("primitive", "report_analog", (0, True), "c0 01"),
    ("primitive", "report_digital", (1, True), "d1 01"),
    ("interface", "servo", (9, 90), "f0 70 09 20 04 60 12 f7 e9 5a 00"),
    ("primitive", "sampling_interval", (19,), "f0 7a 13 00 f7"),
    ("request", "query_firmware", (), "f0 79 f7"),
]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_commands_are_written_as_pyfirmata2_writes_them(kind: str, tmp_path: Path) -> None:
    report = uno_report(pullup=False)
    with _uno(report) as (dev, board):
        board.digital[13].mode = pyfirmata2.OUTPUT
        board.digital[13].write(1)
        board.digital[12].mode = pyfirmata2.OUTPUT
        board.digital[12].write(1)
        board.digital[13].write(0)
        board.digital[3].mode = pyfirmata2.PWM
        board.digital[3].write(0.5)
        board.analog[0].enable_reporting()
        board.digital_ports[1].enable_reporting()
        board.servo_config(9, 544, 2400, 90)
        board.setSamplingInterval(19)
        board.send_sysex(pyfirmata2.REPORT_FIRMWARE, [])
        expected = bytes.fromhex(" ".join(r[3] for r in REQUESTS))
        theirs = dev.wait_for(3 + len(expected))[3:]
    port = ScriptedPort(FIRMWARE)
    ours = bytearray()
    with implementation_of(kind, DESCRIPTION, tmp_path, "firmata").connect(port, threads=False) as robot:
        for what, name, args, hex_ in REQUESTS:
            start = len(port.written)
            if what == "interface":
                robot.call_interface(name, *args)
            else:
                robot.call_primitive("query_firmware" if what == "request" else name, *args)
            assert bytes(port.written[start:]).hex(" ") == hex_, name
        ours += port.written
    assert bytes(ours) == theirs == expected


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_the_boards_messages_are_read_as_pyfirmata2_reads_them(kind: str, tmp_path: Path) -> None:
    report = uno_report(pullup=False)
    with _uno(report) as (dev, board):
        board.analog[0].enable_reporting()
        board.digital[10].mode = pyfirmata2.INPUT  # and reports its port
        dev.send(STREAM)
        _arrived(board, len(STREAM))
        while board.bytes_available():
            board.iterate()
        theirs = (board.firmata_version, board.firmware_version, board.firmware, board.analog[0].value,
                  board.digital[10].value)
    with implementation_of(kind, DESCRIPTION, tmp_path, "firmata").connect(ScriptedPort(STREAM),
                                                                            threads=False) as robot:
        for _ in range(4):
            robot.call_primitive("listen")
        s = robot.state
        ours = ((s["protocol_major"], s["protocol_minor"]), (s["firmware_major"], s["firmware_minor"]),
                s["firmware_name"], round(s["analog"][0] / 1023, 4), bool(s["inputs"][1] >> 2 & 1))
    assert ours == theirs == ((2, 5), (2, 5), "StandardFirmata.ino", 0.5005, True)


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_the_firmware_query_reads_the_name_pyfirmata2_reads(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(FIRMWARE)
    with implementation_of(kind, DESCRIPTION, tmp_path, "firmata").connect(port, threads=False) as robot:
        robot.call_primitive("query_firmware")
        assert (robot.state["firmware_major"], robot.state["firmware_minor"], robot.state["firmware_name"]) == \
            (2, 5, pyfirmata2.util.two_byte_iter_to_str(FIRMWARE[4:-1]))
    assert bytes(port.written) == b"\xf0\x79\xf7"
