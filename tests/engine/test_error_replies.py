"""`error ...`: a reply the device may send instead of the one asked for raises a typed
RdisDeviceError carrying the device's code and its enum name, distinct from a protocol error:
a Modbus RTU exception (the function code with 0x80 set, in a frame of its own), a NACK byte
before an unframed reply, and a marker inside the reply's frame. Alike in the runtime and a
generated driver, byte for byte against the Modbus specification's example frames."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

MODBUS = """\
robot modbus { author "tests" }
/// Modbus's exception codes.
enum Exception { ILLEGAL_FUNCTION = 1, ILLEGAL_DATA_ADDRESS = 2, ILLEGAL_DATA_VALUE = 3, SLAVE_DEVICE_FAILURE = 4 }
const UNIT = 0x11
state registers: int[3]
connection bus: serial { baud 19200 }
/// Modbus RTU: unit, function, data, then CRC-16/MODBUS, low byte first.
frame rtu(unit: int in 1..247, function: int in 0..255) {
    field unit "B" = unit
    field function "B" = function
    payload
    checksum "crc16-modbus" "<H"
}
/// Read holding registers (0x03): three from `start`; an exception is 0x83 and its code.
primitive read_three(start: int in 0..65535) on bus frame rtu(UNIT, 0x03) pack ">HH" (start, 3)
    unpack ">BHHH" expect out[0] == 6 error frame rtu(UNIT, 0x83) unpack "B" code Exception
    { registers = [out[1], out[2], out[3]] }
/// The same, resent twice after a timeout or a reply that does not match.
primitive read_retried(start: int in 0..65535) on bus frame rtu(UNIT, 0x03) pack ">HH" (start, 3)
    unpack ">BHHH" expect out[0] == 6 retry 2 error frame rtu(UNIT, 0x83) unpack "B" code Exception
    { registers = [out[1], out[2], out[3]] }
/// Under `skip unmatched`: another unit's replies are read past, this unit's exception is not.
primitive read_listening(start: int in 0..65535) on bus frame rtu(UNIT, 0x03) pack ">HH" (start, 3)
    unpack ">BHHH" skip unmatched error frame rtu(UNIT, 0x83) unpack "B" code Exception
    { registers = [out[1], out[2], out[3]] }
"""

# The Modbus specification's example (and simplymodbus.ca's): unit 0x11 reads 3 registers from
# 0x006B; the CRC is 0x8776, sent low byte first.
REQUEST = bytes.fromhex("11 03 00 6B 00 03 76 87")
REPLY = bytes.fromhex("11 03 06 AE 41 56 52 43 40 49 AD")


def crc16_modbus(data: bytes) -> bytes:
    """CRC-16/MODBUS (poly 0xA001 reflected, init 0xFFFF), low byte first: the spec's."""
    crc = 0xFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return crc.to_bytes(2, "little")


def exception(code: int, unit: int = 0x11) -> bytes:
    body = bytes([unit, 0x83, code])
    return body + crc16_modbus(body)


def test_the_crc_is_the_specs() -> None:
    assert crc16_modbus(REQUEST[:-2]) == REQUEST[-2:] and crc16_modbus(REPLY[:-2]) == REPLY[-2:]
    assert exception(2, unit=1) == bytes.fromhex("01 83 02 C0 F1")  # the spec's exception example


@pytest.fixture(scope="module", params=["runtime", "driver"])
def modbus(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, MODBUS, tmp_path_factory.mktemp("modbus"), "modbus")


def _names(error: BaseException) -> list[str]:
    return [kind.__name__ for kind in type(error).__mro__]


def test_a_reply_is_read_as_ever(modbus: Any) -> None:
    port = ScriptedPort(REPLY)
    with modbus.connect(port, threads=False) as robot:
        robot.call_primitive("read_three", 0x6B)
        assert bytes(port.written) == REQUEST
        assert robot.state["registers"] == (0xAE41, 0x5652, 0x4340)


def test_an_exception_raises_the_devices_code_and_its_name(modbus: Any) -> None:
    port = ScriptedPort(exception(2) + REPLY)
    with modbus.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:  # the driver's RdisDeviceError is its own class
            robot.call_primitive("read_three", 0x6B)
        error = caught.value
        assert _names(error)[:2] == ["RdisDeviceError", "RdisError"] and "RdisProtocolError" not in _names(error)
        assert str(error) == "read_three: the device answered error 2 (ILLEGAL_DATA_ADDRESS)"
        assert (error.code, error.name, error.values) == (2, "ILLEGAL_DATA_ADDRESS", (2,))
        assert robot.state["registers"] == (0, 0, 0)  # no post-action ran
        robot.call_primitive("read_three", 0x6B)  # the next reply is read from its first byte
        assert robot.state["registers"] == (0xAE41, 0x5652, 0x4340)
        assert bytes(port.written) == REQUEST * 2


def test_a_code_the_enum_lacks_has_no_name(modbus: Any) -> None:
    port = ScriptedPort(exception(9))
    with modbus.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read_three", 0x6B)
        assert str(caught.value) == "read_three: the device answered error 9 (not a member of Exception)"
        assert (caught.value.code, caught.value.name) == (9, None)


def test_a_device_error_is_not_retried(modbus: Any) -> None:
    port = ScriptedPort(exception(4) + REPLY)
    with modbus.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read_retried", 0x6B)
        assert str(caught.value) == "read_retried: the device answered error 4 (SLAVE_DEVICE_FAILURE)"
        assert port.writes == [REQUEST]  # the device said why: asking again would not change it


def test_a_corrupt_exception_is_a_protocol_error(modbus: Any) -> None:
    broken = exception(2)[:-1] + bytes([exception(2)[-1] ^ 0xFF])
    port = ScriptedPort(broken)
    with modbus.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read_three", 0x6B)
        assert type(caught.value).__name__ == "RdisProtocolError"
        assert str(caught.value) == (f"read_three: rtu: checksum {broken[3:].hex(' ')} does not match the reply, "
                                     f"which sums to {crc16_modbus(broken[:3]).hex(' ')}")


def test_another_units_replies_are_read_past_to_this_units_exception(modbus: Any) -> None:
    other = bytes.fromhex("12 03 06 AE 41 56 52 43 40")
    port = ScriptedPort(other + crc16_modbus(other) + exception(3, unit=0x12) + exception(3))
    with modbus.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read_listening", 0x6B)
        assert (type(caught.value).__name__, caught.value.code) == ("RdisDeviceError", 3)


NACK = """\
robot nack { author "tests" }
enum Refusal { BUSY = 1, BAD_COMMAND = 3 }
state position: int = 0
connection link: serial { baud 9600 }
/// The position, after an ACK byte (06); a NACK (15) and a reason instead when it cannot.
primitive position() on link pack "B" (0x21) unpack "<BH" expect out[0] == 0x06 error "\\x15" unpack "B" code Refusal
    { position = out[1] }
frame packet { header "\\xAA"  length "B" = payload  payload  checksum "xor" "B" }
/// Inside a frame with a length: a payload starting EE is the error, its code after it.
primitive speed() on link frame packet pack "B" (0x22) unpack "<h" error "\\xEE" unpack "B"
    { position = out[0] }
"""


def _packet(payload: bytes) -> bytes:
    body = bytes([len(payload)]) + payload
    check = 0
    for byte in body:
        check ^= byte
    return b"\xaa" + body + bytes([check])


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_nack_before_an_unframed_reply(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"\x15\x03" + b"\x06\x00\x02")
    with implementation_of(kind, NACK, tmp_path, "nack").connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("position")
        assert str(caught.value) == "position: the device answered error 3 (BAD_COMMAND)"
        robot.call_primitive("position")
        assert robot.state["position"] == 0x200
        assert port.writes == [b"\x21", b"\x21"]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_marker_inside_the_replys_frame(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(_packet(b"\xee\x05") + _packet(b"\x9c\xff"))
    with implementation_of(kind, NACK, tmp_path, "nack").connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("speed")
        assert str(caught.value) == "speed: the device answered error 5"
        assert (caught.value.code, caught.value.name) == (5, None)
        robot.call_primitive("speed")
        assert robot.state["position"] == -100
        assert port.writes == [_packet(b"\x22")] * 2


def test_the_error_goes_through_json_and_the_printer(tmp_path: Path) -> None:
    for text, name in ((MODBUS, "modbus"), (NACK, "nack")):
        compilation, built = through_json(text, tmp_path, name)
        assert compilation.model is not None
        module = parse(text, "x.rdis", Diagnostics())
        printed = print_module(module)
        assert print_module(parse(printed, "x.rdis", Diagnostics())) == printed
    _, built = through_json(MODBUS, tmp_path, "modbus")
    assert json.loads(built)["primitives"][0]["error"] == {
        "frame": {"name": "rtu", "arguments": ["<17>", "<131>"]}, "unpack": "B", "codes": "Exception"}
    _, built = through_json(NACK, tmp_path, "nack")
    assert [p["error"] for p in json.loads(built)["primitives"]] == [
        {"marker": "\x15", "unpack": "B", "codes": "Refusal"}, {"marker": "\xee", "unpack": "B"}]


def test_rdisc_runtime_exports_the_device_error() -> None:
    from rdisc.runtime import RdisDeviceError, RdisError, RdisProtocolError

    assert issubclass(RdisDeviceError, RdisError) and not issubclass(RdisDeviceError, RdisProtocolError)


ACK = """\
robot ack { author "tests" }
enum Refusal { BUSY = 1, BAD_CHECKSUM = 2 }
state sent: int = 0
connection link: serial { baud 9600 }
frame command { request { header "\\xAA"  length "B" = payload  payload }  reply { header "\\x06" } }
frame nak { request { payload }  reply { header "\\x15"  payload } }
/// Acknowledged by 06, refused by 15 and a reason, in a frame of its own.
primitive go(n: int in 0..255) on link frame command pack "B" (n) error frame nak() unpack "B" code Refusal
    { sent = n }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_acknowledgement_or_a_refusal_in_its_own_frame(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"\x06" + b"\x15\x01" + b"\x06")
    with implementation_of(kind, ACK, tmp_path, "ack").connect(port, threads=False) as robot:
        robot.call_primitive("go", 1)  # the 06 is not skipped looking for the error's header
        assert robot.state["sent"] == 1
        with pytest.raises(Exception) as caught:
            robot.call_primitive("go", 2)
        assert str(caught.value) == "go: the device answered error 1 (BUSY)"
        assert robot.state["sent"] == 1
        robot.call_primitive("go", 3)
        assert robot.state["sent"] == 3
        assert port.writes == [b"\xaa\x01\x01", b"\xaa\x01\x02", b"\xaa\x01\x03"]
