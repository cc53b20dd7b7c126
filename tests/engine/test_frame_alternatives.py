"""Frames with optional parts and alternatives. `optional { ... }`: parts a reply may lack, all
together (NMEA's `*hh`); a request writes them. `either { ... } or { ... }`: layouts of a side,
a request written with the first whose length field can state its payload, a reply read by the
header that comes (VESC's 02 LEN and 03 LEN LEN). Runtime and generated driver alike."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.diagnostics import Diagnostics
from rdisc.emit.dump import dump
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

VESC = """\
robot vesc { author "tests" }
state major: int = 0
state minor: int = 0
connection uart: serial { baud 115200 }
/// 02 LEN for a payload up to 255 bytes, 03 LEN LEN for a longer one.
frame vesc {
    either { header "\\x02"  length "B" = payload } or { header "\\x03"  length ">H" = payload }
    payload  checksum "crc16-xmodem" ">H" over payload  terminator "\\x03"
}
primitive firmware() on uart frame vesc pack "B" (0) unpack "BBB*" { major = out[1]  minor = out[2] }
primitive listen() on uart frame vesc pack "B" (0) unpack "BBB*" skip unmatched { major = out[1]  minor = out[2] }
primitive write(data: bytes in 0..400) on uart frame vesc pack "B*" (1, data)
"""

SENTENCES = """\
robot gps { author "tests" }
state talker: string = ""
connection gps: serial { baud 4800 }
frame sentence {
    header "$"  payload  optional { literal "*"  checksum "xor" hex over payload }  terminator "\\r\\n"
}
primitive gga() on gps frame sentence format "" () regex r"(\\w\\w)GGA,\\d*$" { talker = out[0] }
primitive send(text: string) on gps frame sentence format "{}" (text)
"""

# A payload whose size is known (a length field): one byte after it says whether the optional parts came.
SIZED = """\
robot sized { author "tests" }
state value: int = 0
connection link: serial { baud 9600 }
frame tagged {
    header "\\xAA"  length "B" = payload  payload  optional { literal "\\x55"  checksum "sum" "B" over payload }
    terminator "\\x0D"
}
primitive read() on link frame tagged pack "B" (7) unpack "<H" { value = out[0] }
"""


BOTH = VESC + """\
frame sentence {
    header "$"  payload  optional { literal "*"  checksum "xor" hex over payload }  terminator "\\r\\n"
}
primitive gga() on uart frame sentence format "" () regex r"(\\w\\w)GGA,\\d*$"
"""


def crc16_xmodem(data: bytes) -> int:
    reg = 0
    for byte in data:
        reg ^= byte << 8
        for _ in range(8):
            reg = ((reg << 1) ^ 0x1021) & 0xFFFF if reg & 0x8000 else (reg << 1) & 0xFFFF
    return reg


def vesc_frame(payload: bytes) -> bytes:
    """VESC's framing, as its firmware (packet.c) writes it."""
    size = len(payload)
    head = bytes([2, size]) if size <= 255 else bytes([3, size >> 8, size & 0xFF])
    return head + payload + crc16_xmodem(payload).to_bytes(2, "big") + b"\x03"


@pytest.fixture(scope="module", params=["runtime", "driver"])
def kind(request: pytest.FixtureRequest) -> str:
    return str(request.param)


def test_the_writer_takes_the_first_layout_that_states_the_size(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, VESC, tmp_path, "vesc").connect(port, threads=False) as robot:
        for size in (0, 3, 254, 255, 256, 400):
            port.written.clear()
            robot.call_primitive("write", bytes(range(256))[:size] + bytes(max(0, size - 256)))
            assert bytes(port.written) == vesc_frame(b"\x01" + bytes(range(256))[:size] + bytes(max(0, size - 256)))
        port.written.clear()
        robot.call_primitive("write", b"ab")
    assert bytes(port.written).hex(" ") == "02 03 01 61 62 43 cf 03"
    assert vesc_frame(b"\x01" + bytes(300))[:3].hex(" ") == "03 01 2d"


def test_a_reply_is_read_by_the_header_that_comes(kind: str, tmp_path: Path) -> None:
    long_reply = b"\x00\x06\x01" + bytes(297)
    port = ScriptedPort(b"\x99\x55" + vesc_frame(b"\x00\x05\x02hw") + vesc_frame(long_reply))
    with implementation_of(kind, VESC, tmp_path, "vesc").connect(port, threads=False) as robot:
        robot.call_primitive("firmware")
        assert (robot.state["major"], robot.state["minor"]) == (5, 2)
        robot.call_primitive("firmware")
        assert (robot.state["major"], robot.state["minor"]) == (6, 1)
    assert bytes(port.written) == vesc_frame(b"\x00") * 2


def test_a_false_header_is_read_past_to_the_next_frame(kind: str, tmp_path: Path) -> None:
    """03 in the noise starts a long frame whose length runs past what came; with `skip unmatched`
    the reader gives back all but that byte and finds the real frame's 02 in them."""
    port = ScriptedPort(b"\x03\x00\x09" + vesc_frame(b"\x00\x04\x07"))
    with implementation_of(kind, VESC, tmp_path, "vesc").connect(port, threads=False) as robot:
        robot.call_primitive("listen")
        assert (robot.state["major"], robot.state["minor"]) == (4, 7)


def test_a_bad_crc_in_either_layout_is_refused(kind: str, tmp_path: Path) -> None:
    for frame in (vesc_frame(b"\x00\x05\x02"), vesc_frame(b"\x00\x05\x02" + bytes(300))):
        broken = frame[:-3] + bytes([frame[-3] ^ 1]) + frame[-2:]
        port = ScriptedPort(broken)
        with implementation_of(kind, VESC, tmp_path, "vesc").connect(port, threads=False) as robot:
            with pytest.raises(Exception, match=r"^firmware: vesc: checksum [0-9a-f]{2} [0-9a-f]{2} does not match") as raised:
                robot.call_primitive("firmware")
            assert type(raised.value).__name__ == "RdisProtocolError"


def test_optional_parts_are_read_when_they_come_and_checked(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"noise$GPGGA,1\r\n$GNGGA,2*56\r\n")
    with implementation_of(kind, SENTENCES, tmp_path, "gps").connect(port, threads=False) as robot:
        robot.call_primitive("gga")
        assert robot.state["talker"] == "GP"
        robot.call_primitive("gga")
        assert robot.state["talker"] == "GN"
        port.script = b"$GLGGA,2*56\r\n"  # a checksum that came is checked
        with pytest.raises(Exception, match='^gga: sentence: checksum "56" does not match the reply, which sums '
                                            'to "54"$') as raised:
            robot.call_primitive("gga")
        assert type(raised.value).__name__ == "RdisProtocolError"
        port.written.clear()
        robot.call_primitive("send", "GPTXT,1")
    assert bytes(port.written) == b"$GPTXT,1*52\r\n"  # a request writes the optional parts


def test_after_a_sized_payload_one_byte_tells_whether_they_came(kind: str, tmp_path: Path) -> None:
    with_check = bytes.fromhex("aa 02 34 12 55 46 0d")
    without = bytes.fromhex("aa 02 78 56 0d")
    port = ScriptedPort(with_check + without + bytes.fromhex("aa 02 34 12 55 47 0d"))
    with implementation_of(kind, SIZED, tmp_path, "sized").connect(port, threads=False) as robot:
        robot.call_primitive("read")
        assert robot.state["value"] == 0x1234
        robot.call_primitive("read")
        assert robot.state["value"] == 0x5678
        with pytest.raises(Exception, match="^read: tagged: checksum 47 does not match the reply, which sums "
                                            "to 46$") as raised:
            robot.call_primitive("read")
        assert type(raised.value).__name__ == "RdisProtocolError"
    assert bytes(port.written) == bytes.fromhex("aa 01 07 55 07 0d") * 3


# What the checker refuses in optional parts and alternatives: tests/semantics/cases/frame_alternatives.rdis.


def test_json_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(BOTH, tmp_path, "both")
    assert not compilation.diagnostics.items
    frames = {f["name"]: f for f in json.loads(built)["frames"]}
    crc = {"checksum": "crc16-xmodem", "kind": "crc", "width": 16, "poly": 4129, "init": 0, "reflectIn": False,
           "reflectOut": False, "xorOut": 0, "format": ">H", "covers": [2, 2]}
    short = [{"header": "\u0002"}, {"length": "B", "adjust": 0}, {"payload": True}, crc, {"terminator": "\u0003"}]
    long = [{"header": "\u0003"}, {"length": ">H", "adjust": 0}, {"payload": True}, crc, {"terminator": "\u0003"}]
    assert (frames["vesc"]["request"], frames["vesc"]["moreRequests"]) == (short, [long])
    assert (frames["vesc"]["reply"], frames["vesc"]["moreReplies"]) == (short, [long])
    assert frames["sentence"]["reply"] == [
        {"header": "$"}, {"payload": True}, {"optional": 2}, {"literal": "*"},
        {"checksum": "xor", "kind": "xor", "width": 8, "format": "hex", "covers": [1, 1]}, {"terminator": "\r\n"}]
    for text in (VESC, SENTENCES, SIZED):
        printed = print_module(parse("f.rdis", text, Diagnostics()))
        assert print_module(parse("g.rdis", printed, Diagnostics())) == printed
        assert parse("g.rdis", printed, Diagnostics()).decls == parse("f.rdis", text, Diagnostics()).decls
    printed = print_module(parse("f.rdis", VESC, Diagnostics()))
    assert '    either { header "\\x02"  length "B" = payload } or { header "\\x03"  length ">H" = payload }\n' in printed
    printed = print_module(parse("f.rdis", SENTENCES, Diagnostics()))
    assert '    optional { literal "*"  checksum "xor" hex over payload }\n' in printed
    model = compilation.model
    assert model is not None
    assert dump(model).split("\n\n")[0] == """\
primitive firmware() on uart, frame vesc()
  request, alternative 1: 6 bytes
  offset  size  kind                  value
       0     1  header                02
       1     1  length                "B" = payload
       2     1  payload u8            00 (0)
       3     2  checksum              crc16-xmodem as >H, over payload
       5     1  terminator            03
  request, alternative 2: 7 bytes
  offset  size  kind                  value
       0     1  header                03
       1     2  length                ">H" = payload
       3     1  payload u8            00 (0)
       4     2  checksum              crc16-xmodem as >H, over payload
       6     1  terminator            03
  reply, alternative 1: 8+n bytes
  offset  size  kind                  value
       0     1  header                02
       1     1  length                "B" = payload
       2     1  payload u8            out[0]
       3     1  payload u8            out[1]
       4     1  payload u8            out[2]
       5     n  payload bytes (the rest)  out[3]
       ?     2  checksum              crc16-xmodem as >H, over payload
       ?     1  terminator            03
  reply, alternative 2: 9+n bytes
  offset  size  kind                  value
       0     1  header                03
       1     2  length                ">H" = payload
       3     1  payload u8            out[0]
       4     1  payload u8            out[1]
       5     1  payload u8            out[2]
       6     n  payload bytes (the rest)  out[3]
       ?     2  checksum              crc16-xmodem as >H, over payload
       ?     1  terminator            03"""
    gga = dump(model).split("\n\n")[3]
    assert "  reply: 6+n bytes, 3 of them optional (a reply may lack them)\n" in gga
    assert "       ?     1  literal (optional)    2A\n" in gga
    # the budget: the request's layout by its size (1 byte: 02 LEN), the reply's shortest
    assert message_bytes(model.primitives["firmware"], model.frames) == 6 + 3 + 5
    # a request writes the optional `*hh` ($ *hh CR LF); a reply is counted without it ($ CR LF), its regex
    # at its shortest ("GPGGA," and the line end the budget counts for a regex)
    assert message_bytes(model.primitives["gga"], model.frames) == (1 + 3 + 2) + (1 + 2) + (6 + 1)


def test_json_import_refuses_a_bad_optional_count(tmp_path: Path, rdisc: Any) -> None:
    _, built = through_json(SENTENCES, tmp_path, "gps")
    bad = json.loads(built)
    bad["frames"][0]["reply"][2] = {"optional": 9}
    (tmp_path / "bad.json").write_text(json.dumps(bad), encoding="utf-8")
    result = rdisc("check", tmp_path / "bad.json")
    assert result.returncode == 1
    assert "error[E008]: `optional` is the number of parts after it that a reply may lack (1 to 3)" in result.stderr
