"""Bit fields in one integer of a frame: `bits "<I" { length: 30 = payload  field mode: 2 = mode }`,
RPLIDAR's response descriptor. A request packs the fields from the lowest bit up; a reply's
length bit field gives the payload's size and its other fields are checked like `field`s.
Runtime and generated driver alike."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from conftest import check_text

from rdisc.diagnostics import Diagnostics
from rdisc.emit.dump import dump
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

RPLIDAR = """\
robot rplidar { author "tests" }
state model: int = 0
state hardware: int = 0
state quality: int = 0
state distance: int = 0
connection serial0: serial { baud 115200 }
frame rplidar(mode: int in 0..3, type: int in 0..255) {
    request { header "\\xA5"  payload }
    reply { header "\\xA5\\x5A"  bits "<I" { length: 30 = payload  field mode: 2 = mode }  field type "B" = type  payload }
}
primitive get_info() on serial0 frame rplidar(0, 4) pack "B" (0x50) unpack "<BBBB16s" { model = out[0]  hardware = out[3] }
primitive scan() on serial0 frame rplidar(1, 0x81) pack "B" (0x20) unpack "<BHH" { quality = out[0] >> 2  distance = out[2] }
primitive raw() on serial0 frame rplidar(0, 0x20) pack "B" (0x59) unpack "*" { distance = len(out[0]) }
"""

# A request with bits: a 4-bit command under a 12-bit length (plus the command byte counted), and
# a parameter's bit field beside a constant one.
PACKED = """\
robot packed { author "tests" }
state echo: int = 0
connection link: serial { baud 9600 }
frame packed(channel: int) {
    header "\\xAA"
    bits ">H" { field channel: 3 = channel  field flag: 1 = 1  length: 12 = payload + 1 }
    payload
    checksum "sum" "B" over length .. payload
}
primitive send(channel: int in 0..7, data: bytes in 0..100) on link frame packed(channel) pack "B*" (9, data)
primitive put(channel: int) on link frame packed(channel) pack "B" (1)
primitive get(channel: int in 0..7) on link frame packed(channel) pack "B" (2) unpack "<H" { echo = out[0] }
"""

INFO = bytes.fromhex("A5 5A 14 00 00 00 04")
SCAN = bytes.fromhex("A5 5A 05 00 00 40 81")


@pytest.fixture(scope="module", params=["runtime", "driver"])
def kind(request: pytest.FixtureRequest) -> str:
    return str(request.param)


def test_rplidar_descriptors_give_the_length_and_are_checked(kind: str, tmp_path: Path) -> None:
    info = bytes([0x18, 0x1D, 0x01, 0x07]) + bytes(range(16))
    port = ScriptedPort(b"\x00\xA5" + INFO + info + SCAN + bytes.fromhex("3E 81 02 34 12"))
    with implementation_of(kind, RPLIDAR, tmp_path, "rplidar").connect(port, threads=False) as robot:
        robot.call_primitive("get_info")
        assert (robot.state["model"], robot.state["hardware"]) == (0x18, 7)
        robot.call_primitive("scan")
        assert (robot.state["quality"], robot.state["distance"]) == (0x3E >> 2, 0x1234)
        # a descriptor's length alone says where a `*` payload ends: 0x123 bytes, bits 0..29 of 23 01 00 00
        port.script = bytes.fromhex("A5 5A 23 01 00 00 20") + bytes(0x123) + b"\xA5"
        robot.call_primitive("raw")
        assert robot.state["distance"] == 0x123
        assert port.script == b"\xA5"
        # a single response where many were asked for: the mode bits are 0, not 1
        port.script = bytes.fromhex("A5 5A 05 00 00 00 81") + bytes(5)
        with pytest.raises(Exception, match=r"^scan: rplidar: reply mode is 0, expected 1$") as raised:
            robot.call_primitive("scan")
        assert type(raised.value).__name__ == "RdisProtocolError"
        # mode 3: both top bits; the length below them is still 5
        port.script = bytes.fromhex("A5 5A 05 00 00 C0 81") + bytes(5)
        with pytest.raises(Exception, match=r"^scan: rplidar: reply mode is 3, expected 1$"):
            robot.call_primitive("scan")
        port.script = bytes.fromhex("A5 5A 14 00 00 00 06") + bytes(20)
        with pytest.raises(Exception, match=r"^get_info: rplidar: reply type is 6, expected 4$"):
            robot.call_primitive("get_info")
    assert bytes(port.written).hex(" ") == "a5 50 a5 20 a5 59 a5 20 a5 20 a5 50"


def test_a_length_bit_field_over_the_largest_frame_is_refused(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(bytes.fromhex("A5 5A FF FF FF 3F 20") + bytes(100))
    with (implementation_of(kind, RPLIDAR, tmp_path, "rplidar").connect(port, threads=False) as robot,
          pytest.raises(Exception, match=r"^raw: rplidar: length field says 1073741823, which no payload fits$")):
        robot.call_primitive("raw")


def test_a_request_packs_its_bit_fields_from_the_lowest_bit(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, PACKED, tmp_path, "packed").connect(port, threads=False) as robot:
        robot.call_primitive("send", 5, b"xyz")
        # channel 5 in bits 0..2, flag in bit 3, length 4 + 1 in bits 4..15: 0x005D, big-endian
        assert bytes(port.written).hex(" ") == "aa 00 5d 09 78 79 7a " + f"{(0x5D + 9 + 0x78 + 0x79 + 0x7A) & 0xFF:02x}"
        port.written.clear()
        robot.call_primitive("send", 7, bytes(100))
        assert bytes(port.written)[:3].hex(" ") == "aa 06 6f"  # 101 + 1 = 0x66 in bits 4..15, 7 and 1 below
        port.written.clear()
        with pytest.raises(Exception, match=r"^put: field channel is 9, which does not fit its 3 bits \(0 to 7\)$") as raised:
            robot.call_primitive("put", 9)
        assert type(raised.value).__name__ == "RdisValueError"
        assert port.written == b""


def test_a_reply_checks_each_bit_field_against_its_request(kind: str, tmp_path: Path) -> None:
    def reply(channel: int, flag: int, value: bytes) -> bytes:
        word = channel | flag << 3 | (len(value) + 1) << 4
        body = word.to_bytes(2, "big") + value
        return b"\xAA" + body + bytes([sum(body) & 0xFF])

    port = ScriptedPort(reply(3, 1, b"\x34\x12"))
    with implementation_of(kind, PACKED, tmp_path, "packed").connect(port, threads=False) as robot:
        robot.call_primitive("get", 3)
        assert robot.state["echo"] == 0x1234
        port.script = reply(2, 1, b"\x34\x12")
        with pytest.raises(Exception, match=r"^get: packed: reply channel is 2, expected 3$"):
            robot.call_primitive("get", 3)
        port.script = reply(3, 0, b"\x34\x12")
        with pytest.raises(Exception, match=r"^get: packed: reply flag is 0, expected 1$"):
            robot.call_primitive("get", 3)


# What the checker refuses in bit fields: tests/semantics/cases/bit_fields.rdis.


def test_a_length_bit_field_must_state_every_payload(tmp_path: Path) -> None:
    text = """\
robot r { author "t" }
connection c: serial { baud 9600 }
frame f(m: int) { header "\\xA5" bits "B" { length: 4 = payload  field m: 4 = m } payload }
primitive p() on c frame f(2) pack "20s" ("")
primitive q(x: bytes in 0..30) on c frame f(2) pack "*" (x)
primitive r() on c frame f(20) pack "B" (1)
"""
    _, result = check_text(tmp_path, text)
    errors_ = [line for line in result.stderr.splitlines() if line.startswith(("error[", "  = help"))]
    assert errors_ == [
        'error[E503]: the length field "B" bits 0..3 of frame `f` cannot state the 20-byte payload of `p`',
        "  = help: it states payloads of 0 to 15 bytes",
        ('error[E503]: the length field "B" bits 0..3 of frame `f` cannot state every payload of `q`: 0 to 30 bytes, '
        "as parameter `x` allows"),
        "  = help: it states payloads of 0 to 15 bytes; narrow the range of parameter `x`",
        "error[E403]: 20 does not fit the 4 bits of field `m` of frame `f`",
    ], result.stderr
    assert "field `m` is 4 bits, 0 to 15" in result.stderr


def test_json_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(RPLIDAR + PACKED.split("\n", 1)[1].replace("connection link", "connection l2")
                                      .replace("state echo", "state echo2").replace("on link", "on l2")
                                      .replace("echo = ", "echo2 = "), tmp_path, "both")
    assert not compilation.diagnostics.items
    frames = {f["name"]: f for f in json.loads(built)["frames"]}
    assert frames["rplidar"]["reply"] == [
        {"header": "\u00a5Z"},
        {"bits": "<I", "fields": [{"length": True, "width": 30, "adjust": 0},
                                  {"field": "mode", "width": 2, "value": "<mode>"}]},
        {"field": "type", "format": "B", "value": "<type>"}, {"payload": True}]
    assert frames["packed"]["request"][1] == {"bits": ">H", "fields": [
        {"field": "channel", "width": 3, "value": "<channel>"}, {"field": "flag", "width": 1, "value": "<1>"},
        {"length": True, "width": 12, "adjust": 1}]}
    assert frames["packed"]["request"][3]["covers"] == [1, 2]
    for text in (RPLIDAR, PACKED):
        printed = print_module(parse("f.rdis", text, Diagnostics()))
        assert print_module(parse("g.rdis", printed, Diagnostics())) == printed
        assert parse("g.rdis", printed, Diagnostics()).decls == parse("f.rdis", text, Diagnostics()).decls
    printed = print_module(parse("f.rdis", PACKED, Diagnostics()))
    assert '    bits ">H" { field channel: 3 = channel  field flag: 1 = 1  length: 12 = payload + 1 }\n' in printed
    model = compilation.model
    assert model is not None
    assert dump(model).split("\n\n")[1] == """\
primitive scan() on serial0, frame rplidar(1, 129)
  request: 2 bytes
  offset  size  kind                  value
       0     1  header                A5
       1     1  payload u8            20 (32)
  reply: 12 bytes
  offset  size  kind                  value
       0     2  header                A5 5A
       2     4  bits                  "<I": length = payload (bits 0..29), mode = mode (bits 30..31)
       6     1  field type            "B" = type
       7     1  payload u8            out[0]
       8     2  payload u16 LE        out[1]
      10     2  payload u16 LE        out[2]"""
    send = dump(model).split("\n\n")[3]
    assert ('       1     2  bits                  ">H": channel = channel (bits 0..2), flag = 1 (bit 3), '
            "length = payload + 1 (bits 4..15)\n") in send
    assert "       ?     1  checksum              sum as B, over length .. payload" in send
    # the budget counts the bits' integer as its four bytes: A5 50, then A5 5A u32 type and 20 bytes
    assert message_bytes(model.primitives["get_info"], model.frames) == 2 + 7 + 20
