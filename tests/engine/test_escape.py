"""Escaping between a frame's flags: SLIP (RFC 1055: C0 as DB DC, DB as DB DD) and HDLC-like
framing (RFC 1662: 7E and 7D as 7D and the byte XOR 20, the FCS over the unescaped bytes and
escaped with them). Written and read through the one engine, by the runtime and the driver."""

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

SLIP = """\
robot slip { author "tests" }
state a: int = 0
state b: int = 0
state word: int = 0
connection link: serial { baud 115200 }
/// SLIP with an END before each packet too (as sliplib writes it).
frame slip { header "\\xC0"  payload  terminator "\\xC0"  escape "\\xDB" { "\\xC0": "\\xDC", "\\xDB": "\\xDD" } }
primitive pair(x: int in 0..255, y: int in 0..255) on link frame slip pack "BB" (x, y) unpack "<BBH" {
    a = out[0]  b = out[1]  word = out[2]
}
primitive send(data: bytes in 0..300) on link frame slip pack "*" (data)
"""

# The same framing without the END before a packet, as RFC 1055's send_packet writes it.
SLIP_BARE = SLIP.replace('header "\\xC0"  payload', "payload")

HDLC = """\
robot gimbal { author "tests" }
state status: int = 0
state angle: int = 0
connection uart: serial { baud 115200 }
/// RFC 1662: 7E, the bytes with 7E and 7D sent as 7D and the byte XOR 20, FCS-16 low byte first, 7E.
frame hdlc {
    header "\\x7E"  length "B" = payload  payload  checksum "crc16-x25" "<H"  terminator "\\x7E"
    escape "\\x7D" xor 0x20 for "\\x7E\\x7D"
}
primitive command(a: int in 0..255, b: int in 0..255) on uart frame hdlc pack "BB" (a, b) unpack "<BBh" {
    status = out[0]  angle = out[2]
}
primitive listen() on uart frame hdlc pack "BB" (0, 0) unpack "<BBh" skip unmatched { status = out[0]  angle = out[2] }
"""


GOOD = b"\x04\x00\x7d\x52\x7e"  # a reply's length and payload, whose FCS is 7E E7


def fcs16(data: bytes) -> int:
    """RFC 1662's FCS-16 (appendix C.2), bit by bit: its ones' complement is what is sent."""
    fcs = 0xFFFF
    for byte in data:
        fcs ^= byte
        for _ in range(8):
            fcs = (fcs >> 1) ^ 0x8408 if fcs & 1 else fcs >> 1
    return fcs ^ 0xFFFF


def rfc1662(body: bytes) -> bytes:
    """A frame as RFC 1662 sends it: the FCS appended low byte first, then 7E and 7D (the only
    bytes this link's map asks for) sent as 7D, byte XOR 20, between two flags."""
    data = body + fcs16(body).to_bytes(2, "little")
    escaped = b"".join(bytes([0x7D, b ^ 0x20]) if b in (0x7D, 0x7E) else bytes([b]) for b in data)
    return b"\x7e" + escaped + b"\x7e"


def slip(packet: bytes) -> bytes:
    """RFC 1055's send_packet, with an END first."""
    table = {0xC0: b"\xdb\xdc", 0xDB: b"\xdb\xdd"}
    return b"\xc0" + b"".join(table.get(b, bytes([b])) for b in packet) + b"\xc0"


@pytest.fixture(scope="module", params=["runtime", "driver"])
def kind(request: pytest.FixtureRequest) -> str:
    return str(request.param)


def test_slip_escapes_end_and_esc_both_ways(kind: str, tmp_path: Path) -> None:
    # the reply C0 DB DB 01: a = C0, b = DB, word = 0x01DB
    assert slip(bytes.fromhex("c0 db db 01")).hex(" ") == "c0 db dc db dd db dd 01 c0"
    port = ScriptedPort(bytes.fromhex("c0 db dc db dd db dd 01 c0"))
    with implementation_of(kind, SLIP, tmp_path, "slip").connect(port, threads=False) as robot:
        robot.call_primitive("pair", 0xC0, 0xDB)
        assert (robot.state["a"], robot.state["b"], robot.state["word"]) == (0xC0, 0xDB, 0x01DB)
        assert bytes(port.written).hex(" ") == "c0 db dc db dd c0"
        port.written.clear()
        data = bytes(range(256)) + b"\xc0\xdb" * 22
        robot.call_primitive("send", data)
        assert bytes(port.written) == slip(data)
        assert len(port.written) == 2 + 300 + 2 + 22 * 2


def test_slip_without_a_leading_end_drops_empty_packets(kind: str, tmp_path: Path) -> None:
    """RFC 1055 sends END to flush line noise, so packets may come as END END data END: two ENDs
    in a row hold an empty packet, which a reader drops."""
    port = ScriptedPort(bytes.fromhex("c0 c0 db dd 07 34 12 c0"))
    with implementation_of(kind, SLIP_BARE, tmp_path, "bare").connect(port, threads=False) as robot:
        robot.call_primitive("pair", 0xDB, 0x01)
        assert (robot.state["a"], robot.state["b"], robot.state["word"]) == (0xDB, 0x07, 0x1234)
    assert bytes(port.written).hex(" ") == "db dd 01 c0"


def test_hdlc_escapes_the_length_the_payload_and_the_fcs(kind: str, tmp_path: Path) -> None:
    # the request 02 03 7D (length, payload): its FCS is 7E F1, sent as 7D 5E F1
    request = rfc1662(b"\x02\x03\x7d")
    assert request.hex(" ") == "7e 02 03 7d 5d 7d 5e f1 7e"
    # the reply 04 00 7D 52 7E: status 0, 7D, angle 0x7E52; its FCS is 7E E7
    assert rfc1662(GOOD).hex(" ") == "7e 04 00 7d 5d 52 7d 5e 7d 5e e7 7e"
    port = ScriptedPort(rfc1662(GOOD))
    with implementation_of(kind, HDLC, tmp_path, "gimbal").connect(port, threads=False) as robot:
        robot.call_primitive("command", 0x03, 0x7D)
        assert (robot.state["status"], robot.state["angle"]) == (0, 0x7E52)
    assert bytes(port.written) == request


def test_garbage_before_the_flag_and_fill_flags_are_read_past(kind: str, tmp_path: Path) -> None:
    reply = rfc1662(b"\x04\x05\x00\x10\x00")
    port = ScriptedPort(b"\x11\x7d\x22" + b"\x7e\x7e" + reply)
    with implementation_of(kind, HDLC, tmp_path, "gimbal").connect(port, threads=False) as robot:
        robot.call_primitive("command", 1, 2)
        assert (robot.state["status"], robot.state["angle"]) == (5, 16)
        port.script = reply + reply  # the closing flag of one is not taken for the opening of the next
        robot.call_primitive("command", 1, 2)
        robot.call_primitive("command", 1, 2)
        assert (robot.state["status"], robot.state["angle"]) == (5, 16)


BAD = [
    (bytes.fromhex("7e 04 00 7d 01 04 7e 00 00 7e"), (r"^command: hdlc: the escape b'\}' comes before b'\\x01', "
                                                      r"which is no code: ")),
    (bytes.fromhex("7e 04 00 7d 7e"), r"^command: hdlc: the packet ends in the escape b'\}': "),
    (rfc1662(GOOD)[:-2] + b"\xe6\x7e", (r"^command: hdlc: checksum 7e e6 does not match the reply, which "
                                       r"sums to 7e e7$")),
    (rfc1662(b"\x05\x00\x7d\x04\x7e"), r"^command: hdlc: length field says 5, but the payload is 4 bytes"),
    (rfc1662(b"\x03"), r"^command: hdlc: length field says 3, but the payload is 0 bytes"),
    (bytes.fromhex("7e 01 7e"), (r"^command: hdlc: a 3-byte packet, unescaped, where its parts take 5 bytes and "
                                 r"the payload: ")),
]


@pytest.mark.parametrize(("reply", "message"), BAD)
def test_a_bad_packet_is_a_protocol_error(kind: str, tmp_path: Path, reply: bytes, message: str) -> None:
    port = ScriptedPort(reply)
    with implementation_of(kind, HDLC, tmp_path, "gimbal").connect(port, threads=False) as robot:
        with pytest.raises(Exception, match=message) as raised:
            robot.call_primitive("command", 1, 2)
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert robot.state["status"] == 0


def test_skip_unmatched_reads_past_a_bad_packet(kind: str, tmp_path: Path) -> None:
    """A packet with a bad escape, one with a bad FCS: read past to the next that decodes (whose
    opening flag was the closing flag of the one before)."""
    bad_fcs = rfc1662(b"\x04\x09\x00\x01\x00")[:-2] + b"\x00\x7e"
    port = ScriptedPort(bytes.fromhex("7e 04 7d 07 7e") + bad_fcs[1:] + rfc1662(b"\x04\x03\x00\x02\x00")[1:])
    with implementation_of(kind, HDLC, tmp_path, "gimbal").connect(port, threads=False) as robot:
        robot.call_primitive("listen")
        assert (robot.state["status"], robot.state["angle"]) == (3, 2)


def test_a_request_is_escaped_after_its_size_is_checked(kind: str, tmp_path: Path) -> None:
    """The length field states the unescaped payload: 255 bytes fit "B" however many are escaped."""
    text = HDLC + "primitive blob(data: bytes in 0..255) on uart frame hdlc pack \"*\" (data)\n"
    port = ScriptedPort()
    with implementation_of(kind, text, tmp_path, "blob").connect(port, threads=False) as robot:
        robot.call_primitive("blob", b"\x7e" * 255)
    assert bytes(port.written) == rfc1662(b"\xff" + b"\x7e" * 255)
    assert len(port.written) == 2 + 1 + 255 * 2 + 2


# What the checker refuses in an escaping frame: tests/semantics/cases/escape.rdis.


def test_json_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(SLIP, tmp_path, "slip")
    frame = json.loads(built)["frames"][0]
    assert frame["escaping"] == {"escape": "\u00db", "codes": {"\u00c0": "\u00dc", "\u00db": "\u00dd"}}
    model = compilation.model
    assert model is not None
    assert dump(model).split("\n\n")[0].splitlines()[:3] == [
        "primitive pair(x: int in 0..255, y: int in 0..255) on link, frame slip()",
        "  escaped between the flags: C0 as DB DC, DB as DB DD",
        "  request: 4 bytes",
    ]
    # at their worst every byte between the flags is escaped: C0 x y C0, C0 a b w w C0
    assert message_bytes(model.primitives["pair"], model.frames) == (1 + 2 * 2 + 1) + (1 + 2 * 4 + 1)
    compilation, built = through_json(HDLC, tmp_path, "gimbal")
    frame = json.loads(built)["frames"][0]
    assert frame["escaping"] == {"escape": "}", "codes": {"~": "^", "}": "]"}}
    model = compilation.model
    assert model is not None
    assert "  escaped between the flags: 7E as 7D 5E, 7D as 7D 5D\n" in dump(model)
    assert message_bytes(model.primitives["command"], model.frames) == (2 + 2 * 5) + (2 + 2 * 7)
    for text in (SLIP, SLIP_BARE, HDLC):
        printed = print_module(parse("f.rdis", text, Diagnostics()))
        assert print_module(parse("g.rdis", printed, Diagnostics())) == printed
        assert parse("g.rdis", printed, Diagnostics()).decls == parse("f.rdis", text, Diagnostics()).decls
    assert '    escape "}" xor 0x20 for "~}"\n' in print_module(parse("f.rdis", HDLC, Diagnostics()))
    assert '    escape "\\xdb" { "\\xc0": "\\xdc", "\\xdb": "\\xdd" }\n' in print_module(parse("f.rdis", SLIP, Diagnostics()))


def test_json_import_reads_the_table_and_refuses_a_bad_one(tmp_path: Path, rdisc: Any) -> None:
    _, built = through_json(HDLC, tmp_path, "gimbal")
    (tmp_path / "gimbal.json").write_text(built, encoding="utf-8")
    result = rdisc("import", tmp_path / "gimbal.json")
    assert result.returncode == 0, result.stderr
    assert '    escape "}" { "~": "^", "}": "]" }\n' in result.stdout
    bad = json.loads(built)
    bad["frames"][0]["escaping"] = {"escape": "}", "codes": {"~": "^"}, "xor": 32}
    (tmp_path / "bad.json").write_text(json.dumps(bad), encoding="utf-8")
    result = rdisc("check", tmp_path / "bad.json")
    assert result.returncode == 1
    assert "error[E008]: unknown member `xor` in `escaping`" in result.stderr
    del bad["frames"][0]["escaping"]["xor"]
    (tmp_path / "bad.json").write_text(json.dumps(bad), encoding="utf-8")
    result = rdisc("check", tmp_path / "bad.json")
    assert result.returncode == 1
    assert ('error[E510]: the escape "}" is not itself escaped, so a reader takes the same byte in the data for an '
            "escape") in result.stderr
