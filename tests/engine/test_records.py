"""Replies of records ended by a marker (Firmata's capability report): `reply each until "\\x7F"`
reads a framed payload as records, each decoded by the primitive's `unpack` and its post-actions
run for it with its position as `index`; `bitset(a)` keeps a pin's modes in one int. Every record
is decoded before any post-action runs, and the post-actions of all are published together, so a
bad report changes no state. In the runtime and a generated driver alike, with exact bytes;
through the checker, JSON, the printer, `rdisc dump` and the link budget."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.emit.dump import dump
from rdisc.emit.python import import_driver
from rdisc.runtime import load
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

FIRMATA = (Path(__file__).parents[2] / "examples" / "firmata.rdis").read_text(encoding="utf-8")


def uno_report(pullup: bool = True) -> bytes:
    """StandardFirmata's capability report for an Arduino Uno (Boards.h): pins 2..19 digital
    (input, pull-up since Firmata 2.5, output), 14..19 analog, 3 5 6 9 10 11 PWM, 2..19 servo,
    18 and 19 I2C; RX and TX (0, 1) none."""
    out = bytearray(b"\xf0\x6c")
    for pin in range(20):
        if 2 <= pin <= 19:
            out += bytes([0, 1, 11, 1, 1, 1] if pullup else [0, 1, 1, 1])
        if 14 <= pin <= 19:
            out += bytes([2, 10])
        if pin in (3, 5, 6, 9, 10, 11):
            out += bytes([3, 8])
        if 2 <= pin <= 19:
            out += bytes([4, 14])
        if pin in (18, 19):
            out += bytes([6, 1])
        out += b"\x7f"
    return bytes(out + b"\xf7")


DIGITAL = 1 | 1 << 1 | 1 << 11 | 1 << 4  # input, output, pull-up, servo


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_the_capability_report_gives_each_pins_modes(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(uno_report())
    with implementation_of(kind, FIRMATA, tmp_path, "firmata").connect(port, threads=False) as robot:
        robot.call_primitive("capabilities")
        modes = robot.state["pin_modes"]
        assert robot.state["pins"] == 20
    assert bytes(port.written) == b"\xf0\x6b\xf7"
    assert modes[:20] == (0, 0, DIGITAL, DIGITAL | 8, DIGITAL, DIGITAL | 8, DIGITAL | 8, DIGITAL, DIGITAL,
                          DIGITAL | 8, DIGITAL | 8, DIGITAL | 8, DIGITAL, DIGITAL, *[DIGITAL | 4] * 4,
                          DIGITAL | 4 | 64, DIGITAL | 4 | 64)
    assert modes[20:] == (0,) * 108


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_empty_report_has_no_records(kind: str, tmp_path: Path) -> None:
    with implementation_of(kind, FIRMATA, tmp_path, "firmata").connect(ScriptedPort(b"\xf0\x6c\xf7"),
                                                                         threads=False) as robot:
        robot.call_primitive("capabilities")
        assert robot.state["pins"] == 0


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_bad_report_changes_no_state(kind: str, tmp_path: Path) -> None:
    cases = [
        # pin 0 fine, pin 1 an odd byte: not whole (mode, resolution) pairs
        (b"\xf0\x6c\x00\x01\x7f\x00\x01\x0b\x7f\xf7", "capabilities: record 1: "),
        # the last pin's pairs without their 7F
        (b"\xf0\x6c\x00\x01\x7f\x00\x01\xf7",
         "capabilities: the reply's last 2 bytes end in no 7f, so they are no record"),
        # 1025 pins with no modes
        (b"\xf0\x6c" + b"\x7f" * 1025 + b"\xf7", "capabilities: more than 1024 records"),
        # 129 pins: pin 128 is past pin_modes (int[128]), after 128 pins were read
        (b"\xf0\x6c" + b"\x00\x01\x7f" * 129 + b"\xf7", "capabilities: "),
        # a mode past 63: no bit of an int holds it
        (b"\xf0\x6c\x00\x01\x7f\x40\x01\x7f\xf7", "capabilities: bitset(): element 0 is 64, not a bit from 0 to 63"),
    ]
    errors = ["RdisProtocolError", "RdisProtocolError", "RdisProtocolError", "RdisValueError", "RdisValueError"]
    implementation = implementation_of(kind, FIRMATA, tmp_path, "firmata")
    for (packet, message), error in zip(cases, errors):
        with implementation.connect(ScriptedPort(uno_report() + packet), threads=False) as robot:
            robot.call_primitive("capabilities")
            before = dict(robot.state)
            with pytest.raises(Exception) as caught:
                robot.call_primitive("capabilities")
            assert type(caught.value).__name__ == error
            assert str(caught.value).startswith(message), str(caught.value)
            assert dict(robot.state) == before


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_index_past_the_array_is_named(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"\xf0\x6c" + b"\x7f" * 129 + b"\xf7")
    robot = implementation_of(kind, FIRMATA, tmp_path, "firmata").connect(port, threads=False)
    with robot, pytest.raises(Exception) as caught:
        robot.call_primitive("capabilities")
    assert type(caught.value).__name__ == "RdisValueError"
    assert str(caught.value) == "capabilities: index 128 is outside pin_modes, which has 128 values"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_records_through_json_read_the_same(kind: str, tmp_path: Path) -> None:
    compilation, built = through_json(FIRMATA, tmp_path, "firmata")
    assert not compilation.diagnostics.items
    prim = next(p for p in json.loads(built)["primitives"] if p["name"] == "capabilities")
    assert (prim["unpack"], prim["recordsUntil"]) == ("<*(BB)", "\x7f")
    assert prim["postActions"] == ["pin_modes[index] = bitset(__out__[0])", "pins = index + 1"]
    source = tmp_path / "firmata.json"
    implementation = load(source) if kind == "runtime" else import_driver(source, tmp_path, "firmata_json_driver")
    port = ScriptedPort(uno_report(pullup=False))
    with implementation.connect(port, threads=False) as robot:
        robot.call_primitive("capabilities")
        assert robot.state["pin_modes"][13:15] == (1 | 2 | 16, 1 | 2 | 4 | 16)
    assert bytes(port.written) == b"\xf0\x6b\xf7"


def test_the_printer_dump_and_the_budget(tmp_path: Path) -> None:
    printed = print_module(parse("f.rdis", FIRMATA, Diagnostics()))
    assert '    reply each until "\\x7f"\n    unpack "<*(BB)" {\n        pin_modes[index] = bitset(out[0])\n' in printed
    assert print_module(parse("f.rdis", printed, Diagnostics())) == printed
    source = tmp_path / "firmata.rdis"
    source.write_text(FIRMATA, encoding="utf-8")
    compilation = compile_path(str(source))
    model = compilation.model
    assert model is not None
    text = dump(model)
    start = text.index("primitive capabilities()")
    assert text[start:text.index("\n\n", start)].splitlines()[-7:] == [
        "  reply: records, each: 4+n bytes",
        "  offset  size  kind                  value",
        "       0     2  header                F0 6C",
        "       2     n  payload u8 x k        out[0][i]",
        "       ?     n  payload u8 x k        out[1][i]",
        "       ?     1  payload record end    7F",
        "       ?     1  terminator            F7",
    ]
    # the request (3), the frame's reply (3), one record of the most pairs the group holds, its marker
    assert message_bytes(model.primitives["capabilities"], model.frames) == 3 + 3 + 2 * 1024 + 1


# What the checker refuses in records: tests/semantics/cases/records.rdis.
