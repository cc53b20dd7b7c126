"""MAVLink 2's payload truncation and its NUL-padded `char[16]` names, against pymavlink (2.4.41),
the published MAVLink library: a request rdisc frames is the one pymavlink packs (its trailing
zero bytes dropped, the first kept), and a reply pymavlink packs, trimmed, is read back whole
(zero-filled to its decoding's size), its name read as text without its padding; each CRC seeded
with its message's CRC_EXTRA byte (`seed EXTRAS[sent]`), never sent, so that frames are compared
whole, CRC included, and a reply whose CRC lacks its seed is refused. The runtime and the
generated driver alike.
"""

from __future__ import annotations

import io
import struct
from typing import Any

import pytest

mavlink = pytest.importorskip("pymavlink.dialects.v20.common")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

DESCRIPTION = """\
robot mavlink { author "tests" }
state value: float = 0.0
state count: int = 0
state index: int = 0
state name: string = ""
state kind: int = 0
/// CRC_EXTRA by message id: PARAM_REQUEST_READ, PARAM_VALUE, PARAM_SET.
const EXTRAS = { 20: 214, 22: 220, 23: 168 }
connection link: serial { baud 57600 }
/// MAVLink 2 from system 1, component 1, sequence 0: FD, LEN, flags, SEQ, SYSID, COMPID, MSGID
/// (24 bits), the payload without its trailing zero bytes, CRC-16/MCRF4XX seeded with CRC_EXTRA.
frame mav2(sent: int in 0..65535, answer: int in 0..65535) {
    request {
        header "\\xFD"  length "B" = payload  literal "\\x00\\x00\\x00\\x01\\x01"  field sent "<H" = sent  literal "\\x00"
        payload trimmed  checksum "crc16-mcrf4xx" "<H" seed EXTRAS[sent]
    }
    reply {
        header "\\xFD"  length "B" = payload  literal "\\x00\\x00\\x00\\x01\\x01"  field answer "<H" = answer
        literal "\\x00"  payload trimmed  checksum "crc16-mcrf4xx" "<H" seed EXTRAS[answer]
    }
}
/// PARAM_SET (23), answered by PARAM_VALUE (22).
primitive param_set(system: int in 0..255, component: int in 0..255, id: string, set_to: float, type: int in 0..255)
    on link frame mav2(23, 22) pack "<fBB16ZB" (set_to, system, component, id, type)
    unpack "<fHH16ZB" { value = out[0]  count = out[1]  index = out[2]  name = out[3]  kind = out[4] }
/// PARAM_REQUEST_READ (20), by index (-1: by name), answered by PARAM_VALUE (22).
primitive param_read(at: int in -1..32767, id: string) on link frame mav2(20, 22) pack "<hBB16Z" (at, 1, 1, id)
    unpack "<fHH16ZB" { value = out[0]  count = out[1]  index = out[2]  name = out[3]  kind = out[4] }
/// PARAM_REQUEST_READ under message ids given at run time, which EXTRAS may lack; once, then read past.
primitive read_as(sent: int in 0..65535, answer: int in 0..65535, at: int in -1..32767, id: string)
    on link frame mav2(sent, answer) pack "<hBB16Z" (at, 1, 1, id)
    unpack "<fHH16ZB" { value = out[0]  count = out[1]  index = out[2]  name = out[3]  kind = out[4] }
primitive read_past(sent: int in 0..65535, answer: int in 0..65535, at: int in -1..32767, id: string)
    on link frame mav2(sent, answer) pack "<hBB16Z" (at, 1, 1, id) skip unmatched
    unpack "<fHH16ZB" { value = out[0]  count = out[1]  index = out[2]  name = out[3]  kind = out[4] }
"""


def crc_mcrf4xx(data: bytes) -> bytes:
    """CRC-16/MCRF4XX (MAVLink's X.25 accumulation), low byte first, of the bytes alone."""
    crc = 0xFFFF
    for byte in data:
        t = (byte ^ crc) & 0xFF
        t = (t ^ (t << 4)) & 0xFF
        crc = ((crc >> 8) ^ (t << 8) ^ (t << 3) ^ (t >> 4)) & 0xFFFF
    return struct.pack("<H", crc)


def packed(message: Any) -> bytes:
    """The message as pymavlink packs it, from system 1, component 1, sequence 0."""
    return bytes(message.pack(mavlink.MAVLink(io.BytesIO(), srcSystem=1, srcComponent=1)))


def reply(message: Any) -> bytes:
    """pymavlink's frame, whole: its CRC seeded with the message's CRC_EXTRA."""
    return packed(message)


def unseeded(message: Any) -> bytes:
    """pymavlink's frame with the CRC of its bytes alone, without the seed."""
    frame = packed(message)[:-2]
    return frame + crc_mcrf4xx(frame[1:])


@pytest.fixture(scope="module", params=["runtime", "driver"])
def mav(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, DESCRIPTION, tmp_path_factory.mktemp("mavlink"), "mavlink")


VALUE = mavlink.MAVLink_param_value_message(b"RATE_RLL_P", 0.25, 0, 300, 7)  # its name's padding and type 0 trimmed


def test_pymavlink_trims_what_the_tests_give_it() -> None:
    assert [reply(VALUE)[1], reply(mavlink.MAVLink_param_value_message(b"", 0.0, 0, 0, 0))[1]] == [18, 1]  # of 25


@pytest.mark.parametrize(("system", "component", "name", "value", "kind"), [
    (1, 1, b"RATE", 0.0, 0),  # all but "RATE" trailing zeros: 10 bytes of 23 sent
    (1, 1, b"", 0.0, 0),  # all zeros but the first two: the first kept
    (0, 0, b"", 0.0, 0),  # every byte zero: the first is kept
    (1, 1, b"SYSID_THISMAV", 1.5, 9),  # nothing to trim
    (7, 1, b"EXACTLY16CHARSXX", -2.0, 0),  # a name of 16, no NUL after it
])
def test_a_request_is_trimmed_as_pymavlink_trims_it(mav: Any, system: int, component: int, name: bytes,
                                                    value: float, kind: int) -> None:
    expected = packed(mavlink.MAVLink_param_set_message(system, component, name, value, kind))
    port = ScriptedPort(reply(VALUE))
    with mav.connect(port, threads=False) as robot:
        robot.call_primitive("param_set", system, component, name.decode(), value, kind)
        assert bytes(port.written) == expected


@pytest.mark.parametrize("message", [
    VALUE,
    mavlink.MAVLink_param_value_message(b"SYSID_THISMAV", 1.0, 9, 300, 12),
    mavlink.MAVLink_param_value_message(b"EXACTLY16CHARSXX", 0.0, 0, 0, 0),  # 16 characters, then zeros
    mavlink.MAVLink_param_value_message(b"", 0.0, 0, 0, 0),  # one byte sent: 23 put back
])
def test_a_trimmed_reply_is_read_whole_and_its_name_without_padding(mav: Any, message: Any) -> None:
    data = reply(message)
    port = ScriptedPort(data)
    with mav.connect(port, threads=False) as robot:
        robot.call_primitive("param_read", -1, message.param_id)
        assert bytes(port.written) == packed(
            mavlink.MAVLink_param_request_read_message(1, 1, message.param_id.encode(), -1))
        decoded = mavlink.MAVLink(io.BytesIO()).decode(bytearray(packed(message)))  # pymavlink's own reading
        assert robot.state["name"] == decoded.param_id == message.param_id
        assert (robot.state["value"], robot.state["count"], robot.state["index"], robot.state["kind"]) == (
            decoded.param_value, decoded.param_count, decoded.param_index, decoded.param_type)


def test_the_seeds_are_pymavlinks_crc_extras() -> None:
    assert [mavlink.MAVLink_param_request_read_message.crc_extra, mavlink.MAVLink_param_value_message.crc_extra,
            mavlink.MAVLink_param_set_message.crc_extra] == [214, 220, 168]


def test_a_reply_whose_crc_lacks_its_seed_is_refused(mav: Any) -> None:
    data = unseeded(VALUE)
    port = ScriptedPort(data)
    with mav.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("param_read", -1, VALUE.param_id)
    seeded = packed(VALUE)[-2:]
    assert type(caught.value).__name__ == "RdisProtocolError"  # the runtime's or the driver's own class
    assert str(caught.value) == (f"param_read: mav2: checksum {data[-2:].hex(' ')} does not match the reply, "
                                 f"which sums to {seeded.hex(' ')}")


def unknown(message: Any, message_id: int) -> bytes:
    """pymavlink's frame of `message` under another message id, its CRC of its bytes alone."""
    frame = bytearray(packed(message)[:-2])
    frame[7:10] = message_id.to_bytes(3, "little")
    return bytes(frame) + crc_mcrf4xx(bytes(frame[1:]))


def test_a_request_whose_seed_the_table_lacks_is_refused_before_it_is_sent(mav: Any) -> None:
    port = ScriptedPort(reply(VALUE))
    with mav.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("read_as", 99, 22, -1, "X")
    assert type(caught.value).__name__ == "RdisValueError"
    assert str(caught.value) == "read_as: the checksum's seed table has no entry for 99"
    assert bytes(port.written) == b""


def test_a_reply_whose_seed_the_table_lacks_is_a_protocol_error(mav: Any) -> None:
    """A reply of message 99, which EXTRAS lacks: another message, not a failed port."""
    port = ScriptedPort(unknown(VALUE, 99))
    with mav.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("read_as", 20, 99, -1, "X")
    assert type(caught.value).__name__ == "RdisProtocolError"
    assert str(caught.value) == "read_as: mav2: reply answer is 99, which seed table EXTRAS lacks"
    assert bytes(port.written) == packed(mavlink.MAVLink_param_request_read_message(1, 1, b"X", -1))


def test_a_reply_whose_seed_the_table_lacks_is_read_past_under_skip_unmatched(mav: Any) -> None:
    data = unknown(VALUE, 99)
    port = ScriptedPort(data)
    events: list[tuple[str, str, bytes]] = []
    with mav.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.on_trace(lambda when, *event: events.append(event))
        robot.call_primitive("read_past", 20, 99, -1, "X")
    assert type(caught.value).__name__ == "RdisTimeout"
    assert events == [
        ("write", "link", packed(mavlink.MAVLink_param_request_read_message(1, 1, b"X", -1))),
        ("skip", "link", b"read_past: mav2: reply answer is 99, which seed table EXTRAS lacks"),
        ("skip", "link", b"read_past: mav2: no header b'\\xfd' in the reply (after 28 bytes)"),  # its other bytes
        ("read", "link", data),
    ]
