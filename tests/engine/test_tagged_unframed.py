"""Tagged replies without a frame (Firmata's stream): the first byte says what follows and
how long it is. The engine reads the tag, then exactly the bytes its entry unpacks; an entry
may be for a range of tags (0xE0..0xEF, a pin in the low nibble) and read the tag as `tag`;
`skip unmatched` reads past bytes that start no tag, within the reply's deadline; every byte
read reaches the I/O callbacks. In the runtime and a generated driver alike, over a scripted
port and a real pty; through JSON, the printer, `rdisc dump` and the link budget."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.emit.dump import dump
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.devices import pty_device
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

FIRMATA = """\
robot firmata { author "tests" }
state port: int = 0
state bits: int = 0
state pin: int = 0
state analog: int = 0
state major: int = 0
state minor: int = 0
state word: int = 0
connection link: serial { baud 57600 }
/// Messages as they come: digital (0x90 | port), analog (0xE0 | pin), the version.
primitive listen() on link format "" () skip unmatched reply tag "B" {
    0x90..0x9F: unpack "BB" { port = tag & 0x0F  bits = out[0] | out[1] << 7 }
    0xE0..0xEF: unpack "BB" { pin = tag & 0x0F  analog = out[0] | out[1] << 7 }
    0xF9: unpack "BB" { major = out[0]  minor = out[1] }
}
/// Asks for the version; any other answer is an error.
primitive version() on link pack "B" (0xF9) reply tag "B" {
    0xF9: unpack "BB" { major = out[0]  minor = out[1] }
}
/// A two-byte tag, looked for again from the byte after a wrong tag's first.
primitive wide() on link format "" () skip unmatched reply tag ">H" {
    0xABCD: unpack "<H" { word = out[0] + tag }
}
"""

STREAM = bytes.fromhex(
    "05"        # the end of a message begun before the listener: no tag, read past
    "e3 10 02"  # analog pin 3: 0x10 | 0x02 << 7
    "92 7f 01"  # digital port 2: 0x7f | 0x01 << 7
    "f9 02 05"  # version 2.5
)


def _state(robot: Any) -> dict[str, int]:
    return {k: robot.state[k] for k in ("port", "bits", "pin", "analog", "major", "minor")}


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_listener_reads_each_message_by_its_tag(kind: str, tmp_path: Path) -> None:
    seen: list[tuple[str, str]] = []
    port = ScriptedPort(STREAM)
    implementation = implementation_of(kind, FIRMATA, tmp_path, "firmata")
    with implementation.connect(port, threads=False, on_io=lambda d, _c, b: seen.append((d, b.hex(" ")))) as robot:
        robot.call_primitive("listen")
        assert _state(robot) == {"port": 0, "bits": 0, "pin": 3, "analog": 272, "major": 0, "minor": 0}
        robot.call_primitive("listen")
        assert _state(robot) == {"port": 2, "bits": 255, "pin": 3, "analog": 272, "major": 0, "minor": 0}
        robot.call_primitive("listen")
        assert _state(robot) == {"port": 2, "bits": 255, "pin": 3, "analog": 272, "major": 2, "minor": 5}
        with pytest.raises(TimeoutError) as caught:
            robot.call_primitive("listen")  # the stream is over
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisTimeout", "listen: no matching reply within 1 s")
    assert bytes(port.written) == b""  # a listener writes nothing
    # Every byte read, the skipped one too, each once and in order.
    assert seen == [("read", "05 e3 10 02"), ("read", "92 7f 01"), ("read", "f9 02 05")]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_without_skip_an_unknown_tag_is_a_protocol_error_naming_it(kind: str, tmp_path: Path) -> None:
    seen: list[tuple[str, str]] = []
    implementation = implementation_of(kind, FIRMATA, tmp_path, "firmata")
    port = ScriptedPort(bytes.fromhex("f0 79 f7"))
    with implementation.connect(port, threads=False, on_io=lambda d, _c, b: seen.append((d, b.hex(" ")))) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("version")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "version: no reply entry for tag 240")
        assert _state(robot)["major"] == 0
        port.script = bytes.fromhex("f9 02")  # the right tag, but one byte of two after it
        with pytest.raises(Exception) as caught:
            robot.call_primitive("version")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "version: expected 2 bytes after tag 249, got 1")
        port.script = bytes.fromhex("f9 02 05")
        robot.call_primitive("version")
        assert (robot.state["major"], robot.state["minor"]) == (2, 5)
    assert bytes(port.written).hex(" ") == "f9 f9 f9"
    assert seen == [("write", "f9"), ("read", "f0"), ("write", "f9"), ("read", "f9 02"),
                    ("write", "f9"), ("read", "f9 02 05")]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_wide_tag_is_looked_for_from_the_byte_after_a_wrong_ones_first(kind: str, tmp_path: Path) -> None:
    seen: list[tuple[str, str]] = []
    implementation = implementation_of(kind, FIRMATA, tmp_path, "firmata")
    port = ScriptedPort(bytes.fromhex("ab ab cd 01 00"))  # ab ab is no tag; ab cd is, then 1 (LE)
    with implementation.connect(port, threads=False, on_io=lambda d, _c, b: seen.append((d, b.hex(" ")))) as robot:
        robot.call_primitive("wide")
        assert robot.state["word"] == 1 + 0xABCD
        port.script = bytes.fromhex("ab cd 01")  # the deadline passes within the entry
        with pytest.raises(TimeoutError) as caught:
            robot.call_primitive("wide")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisTimeout", "wide: no matching reply within 1 s")
    assert seen == [("read", "ab ab cd 01 00"), ("read", "ab cd 01")]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_listener_over_a_real_serial_line(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, FIRMATA, tmp_path, "firmata")
    with pty_device(lambda data: None) as device, implementation.connect(device.port, threads=False) as robot:
        device.send(STREAM)
        for _ in range(3):
            robot.call_primitive("listen")
        assert _state(robot) == {"port": 2, "bits": 255, "pin": 3, "analog": 272, "major": 2, "minor": 5}
        device.send(bytes.fromhex("f0 79"))  # a sysex start, then no tag at all: read past until the deadline
        with pytest.raises(TimeoutError) as caught:
            robot.call_primitive("listen")
        assert str(caught.value) == "listen: no matching reply within 1 s"
        assert device.received == b""


FRAMED = """\
robot framed { author "tests" }
state v: int = 0
connection link: serial { baud 9600 }
frame ended { request { payload } reply { payload  terminator "\\xFF" } }
primitive poll(n: int) on link frame ended pack "B" (n) reply tag "B" { 0x10..0x1F: unpack "B" { v = out[0] * 100 + tag + n } }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_through_a_frame_a_range_entry_reads_its_tag_too(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(bytes.fromhex("13 07 ff"))
    with implementation_of(kind, FRAMED, tmp_path, "framed").connect(port, threads=False) as robot:
        robot.call_primitive("poll", 2)
        assert robot.state["v"] == 700 + 0x13 + 2
    assert bytes(port.written).hex() == "02"


def test_ranges_go_through_json_the_printer_and_dump(tmp_path: Path) -> None:
    compilation, built = through_json(FIRMATA, tmp_path, "firmata")
    assert not compilation.diagnostics.items
    listen = next(p for p in json.loads(built)["primitives"] if p["name"] == "listen")
    assert listen["replyTable"] == {"tag": "B", "cases": [
        {"value": 144, "last": 159, "unpack": "BB",
         "postActions": ["port = tag & 15", "bits = __out__[0] | __out__[1] << 7"]},
        {"value": 224, "last": 239, "unpack": "BB",
         "postActions": ["pin = tag & 15", "analog = __out__[0] | __out__[1] << 7"]},
        {"value": 249, "unpack": "BB", "postActions": ["major = __out__[0]", "minor = __out__[1]"]},
    ]}
    printed = print_module(parse("f.rdis", FIRMATA, Diagnostics()))
    assert "    224..239: unpack \"BB\" {\n        pin = tag & 15\n" in printed
    assert print_module(parse("f.rdis", printed, Diagnostics())) == printed
    model = compilation.model
    assert model is not None
    assert dump(model).split("\n\n")[0] == """\
primitive listen() on link
  request: 0+n bytes
  offset  size  kind                  value
       0     n  text                  ""
  reply tagged 144..159: 3 bytes
  offset  size  kind                  value
       0     1  tag u8                in 144..159
       1     1  u8                    out[0]
       2     1  u8                    out[1]
  reply tagged 224..239: 3 bytes
  offset  size  kind                  value
       0     1  tag u8                in 224..239
       1     1  u8                    out[0]
       2     1  u8                    out[1]
  reply tagged 249: 3 bytes
  offset  size  kind                  value
       0     1  tag u8                = 249
       1     1  u8                    out[0]
       2     1  u8                    out[1]"""
    # The link budget counts the tag and the longest entry after it.
    assert [message_bytes(model.primitives[n], model.frames) for n in ("listen", "version", "wide")] == [3, 4, 4]


def test_what_the_checker_refuses(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
state v: int = 0
connection link: serial { baud 9600 }
primitive rest() on link format "" () reply tag "B" { 0x10: unpack "B" 0x20..0x2F: unpack "B*" }
primitive line() on link format "" () reply tag "B" { 0x10: regex "(\\\\d+)" }
primitive named(tag: int) on link pack "B" (tag) reply tag "B" { 1: unpack "B" { v = tag } }
primitive twice() on link format "" () reply tag "B" { 0xE0..0xEF: unpack "BB" 0xE5: unpack "B" }
primitive empty() on link format "" () reply tag "B" { 0xEF..0xE0: unpack "BB" }
primitive keyed(r: int in 0..3) on link pack "BB" (1, r) reply r { 0..1: unpack "B" 2..3: unpack "BB" { v = tag } }
primitive skips() on link pack "B" (1) skip unmatched unpack "B"
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E505", ("`rest` reads its reply without a frame, so its entry for tags 32..47 needs a fixed size, "
                  "but it ends in `*` (the rest of the message)")),
        ("E505", ("`line` reads its reply without a frame, so its entry for tag 16 needs a fixed size, "
                  "but it is a `regex`")),
        ("E104", "`tag` names the tag of the reply of `named` and cannot name a parameter of it"),
        ("E203", "229 has two entries in the reply table"),
        ("E204", "the range 239..224 is empty"),
        ("E103", "unknown name `tag` in a post-action"),
        ("E504", "`skip unmatched` reads past frames that do not decode, but `skips` does not decode a framed reply"),
    ]


SYSEX = """\
robot sysex { author "tests" }
state analog: int = 0
state major: int = 0
state minor: int = 0
state sketch: string = ""
connection link: serial { baud 57600 }
/// Messages as they come; a sysex message runs from F0 to F7 (REPORT_FIRMWARE is 0x79).
primitive listen() on link format "" () skip unmatched reply tag "B" {
    0xE0..0xEF: unpack "BB" { analog = out[0] | out[1] << 7 }
    0xF0: unpack "BBB*" until "\\xF7" {
        major = out[1] if out[0] == 0x79 else major
        minor = out[2] if out[0] == 0x79 else minor
        sketch = ascii(unpack7(out[3])) if out[0] == 0x79 else sketch
    }
}
/// Asks for the firmware; the answer is a sysex message.
primitive firmware() on link pack "BBB" (0xF0, 0x79, 0xF7) reply tag "B" {
    0xF0: unpack "BBB*" until "\\xF7" { major = out[1]  minor = out[2]  sketch = ascii(unpack7(out[3])) }
}
"""
# "Std" in Firmata's 7-bit pairs (low 7 bits, then the high bit).
REPORT = bytes.fromhex("f0 79 02 05 53 00 74 00 64 00 f7")


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_sysex_message_is_read_to_its_end_byte(kind: str, tmp_path: Path) -> None:
    seen: list[tuple[str, str]] = []
    port = ScriptedPort(bytes.fromhex("e3 10 02") + REPORT + bytes.fromhex("f0 71 01"))  # the last never ends
    implementation = implementation_of(kind, SYSEX, tmp_path, "sysex")
    with implementation.connect(port, threads=False, on_io=lambda d, _c, b: seen.append((d, b.hex(" ")))) as robot:
        robot.call_primitive("listen")
        robot.call_primitive("listen")
        assert [robot.state[k] for k in ("analog", "major", "minor", "sketch")] == [272, 2, 5, "Std"]
        with pytest.raises(TimeoutError) as caught:
            robot.call_primitive("listen")
        assert str(caught.value) == "listen: no matching reply within 1 s"
    assert seen == [("read", "e3 10 02"), ("read", REPORT.hex(" ")), ("read", "f0 71 01")]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_sysex_answer_over_a_real_serial_line(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, SYSEX, tmp_path, "sysex")
    answers = [REPORT, bytes.fromhex("f0 79 02")]  # the second never ends
    with pty_device(lambda data: answers.pop(0) if data == bytes.fromhex("f0 79 f7") else None) as device, \
            implementation.connect(device.port, threads=False) as robot:
        robot.call_primitive("firmware")
        assert [robot.state[k] for k in ("major", "minor", "sketch")] == [2, 5, "Std"]
        with pytest.raises(Exception) as caught:  # without `skip unmatched`, a protocol error
            robot.call_primitive("firmware")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "firmware: no end f7 after tag 240 within 1 s")


def test_until_goes_through_json_the_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(SYSEX, tmp_path, "sysex")
    assert not compilation.diagnostics.items
    firmware = next(p for p in json.loads(built)["primitives"] if p["name"] == "firmware")
    assert firmware["replyTable"]["cases"] == [{"value": 240, "unpack": "BBB*", "until": "\u00f7", "postActions": [
        "major = __out__[1]", "minor = __out__[2]", "sketch = ascii(unpack7(__out__[3]))"]}]
    printed = print_module(parse("s.rdis", SYSEX, Diagnostics()))
    assert '    240: unpack "BBB*" until "\\xf7" {' in printed  # as frames print their bytes
    assert print_module(parse("s.rdis", printed, Diagnostics())) == printed
    model = compilation.model
    assert model is not None
    assert dump(model).split("\n\n")[1].rstrip().splitlines()[-8:] == [
        "  reply tagged 240: 5+n bytes",
        "  offset  size  kind                  value",
        "       0     1  tag u8                = 240",
        "       1     1  u8                    out[0]",
        "       2     1  u8                    out[1]",
        "       3     1  u8                    out[2]",
        "       4     n  bytes (the rest)      out[3]",
        "       ?     1  end (dropped)         F7",
    ]
    # The budget counts the tag, the fixed part and the end byte (the rest at its shortest).
    assert message_bytes(model.primitives["firmware"], model.frames) == 3 + 1 + 3 + 1


def test_what_the_checker_refuses_of_until(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
connection link: serial { baud 9600 }
frame ended { request { payload } reply { payload  terminator "\\xFF" } }
primitive framed() on link frame ended pack "B" (1) reply tag "B" { 1: unpack "B*" until "\\xF7" }
primitive keyed(r: int in 0..1) on link pack "B" (r) reply r { 0..1: unpack "B*" until "\\xF7" }
primitive fixed() on link format "" () reply tag "B" { 0xF0: unpack "BB" until "\\xF7" }
primitive line() on link format "" () reply tag "B" { 0xF0: regex "(.*)" until "\\xF7" }
primitive long() on link format "" () reply tag "B" { 0xF0: unpack "B*" until "123456789" }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E505", "`until` is for a tagged reply read without a frame, and `framed` does not read one"),
        ("E505", "`until` is for a tagged reply read without a frame, and `keyed` does not read one"),
        ("E505", "an entry read `until` its end takes what comes before the end as bytes: its `unpack` ends in `*`"),
        ("E505", "an entry read `until` its end is decoded by an `unpack`"),
        ("E505", "`until` is 1 to 8 bytes (characters up to \\xff)"),
    ]
