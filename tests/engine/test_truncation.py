"""MAVLink 2's payload truncation (`payload trimmed`: trailing zero bytes dropped when written,
the first kept, and zero-filled when read) and NUL-padded strings (`NZ`: read back to the first
NUL), in the runtime and a generated driver alike, through JSON and the printer and `rdisc
dump`. The bytes follow the MAVLink 2 serialization rules; tests/conformance/
test_conformance_mavlink.py holds them against pymavlink."""

from __future__ import annotations

import json
import struct
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path
from rdisc.emit.dump import dump
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json
from tests.syntax.test_printer import parsed

TRIMMED = """\
robot trimmed { author "tests" }
state x: int = 0
state y: int = 0
state name: string = ""
connection link: serial { baud 57600 }
/// FD, the length of what is sent, a message id, the payload without its trailing zeros, an XOR.
frame packet(msg: int in 0..255) {
    header "\\xFD"  length "B" = payload  field msg "B" = msg  payload trimmed  checksum "xor" "B"
}
/// Only written: never in one step, as its size is not fixed.
primitive move(x: int, y: int) on link frame packet(1) pack "<hhB" (x, y, 0)
/// Read back: a reply shorter than "<ih8Z" (14 bytes) is zero-filled to it.
primitive where() on link frame packet(2) pack "B" (0) unpack "<ih8Z" { x = out[0]  y = out[1]  name = out[2] }
"""


def packet(msg: int, payload: bytes) -> bytes:
    body = bytes([len(payload), msg]) + payload
    check = 0
    for byte in body:
        check ^= byte
    return b"\xfd" + body + bytes([check])


@pytest.fixture(scope="module", params=["runtime", "driver"])
def trimmed(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, TRIMMED, tmp_path_factory.mktemp("trimmed"), "trimmed")


@pytest.mark.parametrize(("x", "y", "sent"), [
    (0x0102, 0x0304, b"\x02\x01\x04\x03"),  # the last byte, 0, dropped
    (5, 0, b"\x05"),  # four zeros dropped
    (0, 0, b"\x00"),  # every byte zero: the first is kept
    (-1, 0, b"\xff\xff"),
])
def test_trailing_zero_bytes_are_not_sent(trimmed: Any, x: int, y: int, sent: bytes) -> None:
    port = ScriptedPort()
    with trimmed.connect(port, threads=False) as robot:
        robot.call_primitive("move", x, y)
        assert port.writes == [packet(1, sent)]


@pytest.mark.parametrize(("payload", "state"), [
    (struct.pack("<ih", 7, -2) + b"AB", (7, -2, "AB")),  # the name's padding was not sent
    (b"\x07", (7, 0, "")),  # one byte: the other 13 zero
    (struct.pack("<ih8s", -1, 3, b"ABCDEFGH"), (-1, 3, "ABCDEFGH")),  # whole: 8 characters, no NUL
    (struct.pack("<ih8s", 1, 1, b"A\x00B"), (1, 1, "A")),  # text to the first NUL
])
def test_a_trimmed_reply_is_zero_filled_and_its_name_unpadded(trimmed: Any, payload: bytes,
                                                              state: tuple[int, int, str]) -> None:
    port = ScriptedPort(packet(2, payload))
    with trimmed.connect(port, threads=False) as robot:
        robot.call_primitive("where")
        assert port.writes == [packet(2, b"\x00")]
        assert (robot.state["x"], robot.state["y"], robot.state["name"]) == state


def test_a_reply_longer_than_its_decoding_is_refused(trimmed: Any) -> None:
    port = ScriptedPort(packet(2, bytes(15)))
    with trimmed.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("where")
        assert type(caught.value).__name__ == "RdisProtocolError"
        assert str(caught.value) == "where: expected 14 bytes, got 15"


def test_trimmed_and_padded_go_through_json_the_printer_and_dump(tmp_path: Path) -> None:
    _, built = through_json(TRIMMED, tmp_path, "trimmed")
    frame = json.loads(built)["frames"][0]
    assert {"payload": "trimmed"} in frame["request"]
    assert json.loads(built)["primitives"][1]["unpack"] == "<ih8Z"
    printed = print_module(parsed(TRIMMED))
    assert "payload trimmed  checksum" in printed or "payload trimmed\n" in printed
    assert print_module(parsed(printed)) == printed
    source = tmp_path / "trimmed.rdis"
    source.write_text(TRIMMED, encoding="utf-8")
    model = compile_path(str(source)).model
    assert model is not None
    text = dump(model)
    assert "       9     8  payload text, padded  out[2]" in text
    assert "      17     0  payload trimmed       trailing zero bytes dropped; put back when read" in text
