"""Framed payloads of tagged sub-payloads (Kobuki's feedback): `reply each tag "B" length "B"`
reads sub-payloads until the payload ends, in any order and any subset, each decoded by the
entry its tag chooses and its post-actions run in turn; an unknown tag is skipped by its
length, or refused without one; a length that is not its entry's size is refused before any
state changes. In the runtime and a generated driver alike, with exact bytes; through the
checker, JSON, the printer, `rdisc dump` and the link budget."""

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

KOBUKI = (Path(__file__).parents[2] / "examples" / "kobuki.rdis").read_text(encoding="utf-8")

# AA 55, the length 0x1f, Basic Sensor Data (01, 15 bytes), Inertial Sensor (04, 7 bytes) and
# an ID this description does not know (0D, 3 bytes), then the XOR of the length and payload.
FEEDBACK = bytes.fromhex(
    "aa 55 1f"
    "01 0f 34 12 02 00 01 e8 03 fe ff fb 07 01 00 a0 00"  # stamp 0x1234, bumper 2, cliff 1, 1000, 65534
    "04 07 7c fc 64 00 00 00 00"  # angle -900 (-9.00 degrees), rate 100, 3 unused bytes
    "0d 03 aa bb cc"  # skipped by its length
    "b7"
)
INERTIAL_ONLY = bytes.fromhex("aa 55 09 04 07 30 f8 c8 00 00 00 00 0a")  # angle -2000, rate 200


def _sensors(robot: Any) -> dict[str, Any]:
    return {k: robot.state[k] for k in ("timestamp", "bumper", "wheel_drop", "cliff", "left_encoder",
                                         "right_encoder", "battery", "angle", "angle_rate", "cliff_adc")}


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_kobuki_feedback_sub_payloads_in_any_subset(kind: str, tmp_path: Path) -> None:
    seen: list[tuple[str, str]] = []
    port = ScriptedPort(FEEDBACK + INERTIAL_ONLY)
    implementation = implementation_of(kind, KOBUKI, tmp_path, "kobuki")
    with implementation.connect(port, threads=False, on_io=lambda d, _c, b: seen.append((d, b.hex(" ")))) as robot:
        robot.call_primitive("feedback")
        assert _sensors(robot) == {"timestamp": 0x1234, "bumper": 2, "wheel_drop": 0, "cliff": 1,
                                   "left_encoder": 1000, "right_encoder": 65534, "battery": 160,
                                   "angle": -9.0, "angle_rate": 1.0, "cliff_adc": (0, 0, 0)}
        robot.call_primitive("feedback")  # the inertial sensor alone: the rest stays as it was
        assert _sensors(robot) == {"timestamp": 0x1234, "bumper": 2, "wheel_drop": 0, "cliff": 1,
                                   "left_encoder": 1000, "right_encoder": 65534, "battery": 160,
                                   "angle": -20.0, "angle_rate": 2.0, "cliff_adc": (0, 0, 0)}
        robot.call_interface("drive", 0.2, -0.5)
    assert seen == [("read", FEEDBACK.hex(" ")), ("read", INERTIAL_ONLY.hex(" ")),
                    ("write", "aa 55 06 01 04 c8 00 0c fe 39")]  # base control: 200 mm/s, radius -500 mm
    assert bytes(port.written).hex(" ") == "aa 55 06 01 04 c8 00 0c fe 39"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_length_not_its_entrys_size_changes_nothing(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, KOBUKI, tmp_path, "kobuki")
    cases = [
        # Current (06) first, then the inertial sensor with 6 bytes where its entry decodes 7.
        (bytes.fromhex("aa 55 0c 06 02 05 06 04 06 7c fc 64 00 00 00 ed"),
         "feedback: the sub-payload of tag 4 at offset 4 is 6 bytes; its entry decodes 7"),
        # Current, then a length of 9 where 1 byte is left.
        (bytes.fromhex("aa 55 07 06 02 05 06 0d 09 01 05"),
         "feedback: the sub-payload of tag 13 at offset 4 is 9 bytes, but 1 remain"),
        # Current, then one byte: no room for a tag and a length.
        (bytes.fromhex("aa 55 05 06 02 05 06 0d 0f"),
         "feedback: 1 bytes at offset 4 are no sub-payload (its head is 2)"),
    ]
    for packet, message in cases:
        with implementation.connect(ScriptedPort(packet), threads=False) as robot:
            with pytest.raises(Exception) as caught:
                robot.call_primitive("feedback")
            assert (type(caught.value).__name__, str(caught.value)) == ("RdisProtocolError", message)
            assert (robot.state["left_current"], robot.state["right_current"]) == (0, 0)  # current's not kept


FIXED = """\
robot fixed { author "tests" }
state trail: int = 0
connection link: serial { baud 9600 }
frame counted { header "\\x02"  length "B" = payload  payload }
/// Sub-payloads without lengths: each entry's size says where the next tag is.
primitive poll(n: int) on link frame counted pack "B" (n) reply each tag "B" {
    1: unpack "B" { trail = trail * 100 + out[0] }
    2..3: unpack "<H" { trail = trail * 100 + out[0] + tag * n }
}
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_without_lengths_sub_payloads_are_their_entries_sizes(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(bytes.fromhex("02 07 01 07 02 09 00 01 03" "02 00" "02 04 01 07 05 00"))
    with implementation_of(kind, FIXED, tmp_path, "fixed").connect(port, threads=False) as robot:
        robot.call_primitive("poll", 0)
        assert robot.state["trail"] == 70903  # 7, then 9, then 3: each entry's post-actions, in turn
        robot.call_primitive("poll", 1)  # an empty payload: no sub-payloads
        assert robot.state["trail"] == 70903
        with pytest.raises(Exception) as caught:  # a tag without an entry cannot be skipped
            robot.call_primitive("poll", 2)
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "poll: no reply entry for tag 5 at offset 2")
        assert robot.state["trail"] == 70903
    assert bytes(port.written).hex(" ") == "02 01 00 02 01 01 02 01 02"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_feedback_over_a_real_serial_line(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, KOBUKI, tmp_path, "kobuki")
    with pty_device(lambda data: None) as device, implementation.connect(device.port, threads=False) as robot:
        device.send(FEEDBACK)
        robot.call_primitive("feedback")
        assert (robot.state["timestamp"], robot.state["angle"]) == (0x1234, -9.0)
        assert device.received == b""


def test_sub_payloads_go_through_json_the_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(KOBUKI, tmp_path, "kobuki")
    assert not compilation.diagnostics.items
    feedback = next(p for p in json.loads(built)["primitives"] if p["name"] == "feedback")
    table = feedback["replyTable"]
    assert {k: v for k, v in table.items() if k != "cases"} == {"tag": "B", "each": True, "length": "B"}
    assert table["cases"][1:] == [
        {"value": 4, "unpack": "<hh3x", "postActions": ["angle = __out__[0] / 100.0",
                                                         "angle_rate = __out__[1] / 100.0"]},
        {"value": 5, "unpack": "<3(H)", "postActions": ["cliff_adc = __out__[0]"]},
        {"value": 6, "unpack": "<BB", "postActions": ["left_current = __out__[0]", "right_current = __out__[1]"]},
    ]
    printed = print_module(parse("k.rdis", KOBUKI, Diagnostics()))
    assert 'reply each tag "B" length "B" {\n    1: unpack "<HBBBHHbbBBBB" {\n' in printed
    assert print_module(parse("k.rdis", printed, Diagnostics())) == printed
    fixed = print_module(parse("f.rdis", FIXED, Diagnostics()))
    assert 'reply each tag "B" {\n    1: unpack "B" { trail = trail * 100 + out[0] }\n' in fixed
    model = compilation.model
    assert model is not None
    assert dump(model).split("\n\n")[1].splitlines()[4:15] == [
        "  reply: 4+n bytes",
        "  offset  size  kind                  value",
        "       0     2  header                AA 55",
        '       2     1  length                "B" = payload',
        "       3     n  payload sub-payloads  each a tag and its bytes (an unknown tag skipped by its length)",
        "       ?     1  checksum              xor as B, over length .. payload",
        "  sub-payload tagged 1: 17 bytes",
        "  offset  size  kind                  value",
        "       0     1  tag u8                = 1",
        "       1     1  length u8             = 15",
        "       2     2  u16 LE                out[0]",
    ]
    # The budget counts the frame and every entry once, each with its tag and length.
    assert message_bytes(model.primitives["feedback"], model.frames) == 4 + 17 + 9 + 8 + 4


def test_what_the_checker_refuses_of_sub_payloads(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
connection link: serial { baud 9600 }
frame counted { header "\\x02"  length "B" = payload  payload }
primitive bare() on link format "" () reply each tag "B" length "B" { 1: unpack "B" }
primitive rest() on link frame counted format "" () reply each tag "B" { 1: unpack "B*" }
primitive line() on link frame counted format "" () reply each tag "B" length "B" { 1: regex "(.*)" }
primitive signed() on link frame counted format "" () reply each tag "B" length "b" { 1: unpack "B" }
primitive big() on link frame counted format "" () reply each tag "B" length "B" { 1: unpack "300s" }
primitive ended() on link frame counted format "" () reply each tag "B" length "B" { 1: unpack "B*" until "\\xF7" }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E505", ("the reply of `bare` is a sequence of sub-payloads until its payload ends, so it is read "
                  "through a frame")),
        ("E505", ("the sub-payloads have no length field, so the entry for tag 1 needs a fixed size, but it "
                  "ends in `*` (the rest of the message)")),
        ("E505", "the sub-payload of tag 1 is bytes: decode it with `unpack`"),
        ("E505", 'a sub-payload\'s length is one unsigned integer: a struct format such as "B" or "<H", not "b"'),
        ("E505", 'the entry for tag 1 decodes 300 bytes, more than a sub-payload\'s length field "B" states (255)'),
        ("E503", 'the length field "B" of frame `counted` cannot state the 300-byte payload of `big`'),
        ("E505", "`until` is for a tagged reply read without a frame, and `ended` does not read one"),
    ]
