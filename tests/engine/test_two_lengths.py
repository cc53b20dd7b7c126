"""Two length fields in one frame (Kobuki's command packet: the packet's length, then its
sub-payload's ID and length): each states the payload with its own adjustment, both written
from its size, and a reply whose second disagrees with the first is no frame of this device
(an RdisProtocolError, read past under `skip unmatched`). In the runtime and a generated
driver alike, with exact bytes; through the checker, JSON, the printer and `rdisc dump`."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from conftest import check_text

from rdisc.emit.dump import dump
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

TWO = """\
robot base { author "tests" }
connection link: serial { baud 115200 }
frame command(id: int in 0..255) {
    header "\\xAA\\x55"  length "B" = payload + 2  field id "B" = id  length "B" = payload  payload  checksum "xor" "B"
}
state left: int = 0
state right: int = 0
/// Wheel currents (ID 6): asked for, answered in a packet of the same shape.
primitive currents() on link frame command(6) pack "B" (0) unpack "BB" { left = out[0]  right = out[1] }
/// The same, where packets of another shape on the line are read past.
primitive currents_skipping() on link frame command(6) pack "B" (0) skip unmatched unpack "BB" {
    left = out[0]  right = out[1]
}
"""


def packet(data: str, stated: int | None = None) -> bytes:
    """A packet of one sub-payload of ID 6: its second length `stated` (else the data's)."""
    body = bytes.fromhex(data)
    inner = bytes([len(body) + 2, 6, len(body) if stated is None else stated]) + body
    check = 0
    for byte in inner:
        check ^= byte
    return b"\xaa\x55" + inner + bytes([check])


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_both_lengths_written_and_the_second_checked_when_read(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(packet("05 07") + packet("01 02", stated=3) + packet("01 02", stated=3) + packet("08 09"))
    implementation = implementation_of(kind, TWO, tmp_path, "two")
    with implementation.connect(port, threads=False) as robot:
        robot.call_primitive("currents")
        assert (robot.state["left"], robot.state["right"]) == (5, 7)
        assert bytes(port.written).hex(" ") == "aa 55 03 06 01 00 04"
        with pytest.raises(Exception) as caught:
            robot.call_primitive("currents")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "currents: command: the second length field says 3, but the payload is 2 bytes")
        assert (robot.state["left"], robot.state["right"]) == (5, 7)
        robot.call_primitive("currents_skipping")  # the packet whose lengths disagree is read past
        assert (robot.state["left"], robot.state["right"]) == (8, 9)


def test_two_lengths_through_json_the_printer_and_dump(tmp_path: Path) -> None:
    compilation, built = through_json(TWO, tmp_path, "two")
    frame = json.loads(built)["frames"][0]
    assert [part for part in frame["request"] if "length" in part] == [
        {"length": "B", "adjust": 2}, {"length": "B", "adjust": 0}]
    model = compilation.model
    assert model is not None
    assert """\
  request: 7 bytes
  offset  size  kind                  value
       0     2  header                AA 55
       2     1  length                "B" = payload + 2
       3     1  field id              "B" = id
       4     1  length                "B" = payload
       5     1  payload u8            00 (0)
       6     1  checksum              xor as B, over length .. payload
""" in dump(model)


def test_what_the_checker_refuses_of_two_lengths(tmp_path: Path) -> None:
    text = """\
robot r { author "tests" }
connection link: serial { baud 115200 }
frame three { header "\\xAA"  length "B" = payload  length "B" = payload  length "B" = payload  payload }
frame narrow { header "\\xAA"  length "<H" = payload  length "B" = payload  payload }
frame bits_too { header "\\xAA"  bits "<H" { length: 10 = payload  field flag: 6 = 1 }  length "B" = payload  payload }
primitive a() on link frame three pack "B" (1)
primitive b() on link frame narrow pack "B" (1)
primitive c() on link frame bits_too pack "B" (1)
"""
    _, result = check_text(tmp_path, text)
    errors = [line for line in result.stderr.splitlines() if line.startswith(("error", "  = help"))]
    assert errors == [
        "error[E501]: frame `three` has more than two length fields",
        "  = help: a frame states its payload twice at most",
        ("error[E503]: the second length field of frame `narrow` states payloads of 0 to 255 bytes, but the first "
        "0 to 65535"),
        ("  = help: each length field states the same payload: give the second a format and an adjustment that "
        "hold every size the first states"),
        "error[E501]: frame `bits_too` has two length fields",
        ("  = help: two `length` fields may each state the payload (a packet's length and its sub-payload's), "
        "not in a `bits`"),
    ]
