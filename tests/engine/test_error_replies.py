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
        module = parse("x.rdis", text, Diagnostics())
        printed = print_module(module)
        assert print_module(parse("x.rdis", printed, Diagnostics())) == printed
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


STATUS = """\
robot status { author "tests" }
/// TMCL's refusals: a status below 100.
enum Status { WRONG_CHECKSUM = 1, INVALID_COMMAND = 2, WRONG_TYPE = 3, INVALID_VALUE = 4 }
state value: int = 0
state level: int = 0
connection link: serial { baud 9600 }
/// A TMCL datagram: host, module, then the payload and the low byte of the sum.
frame tmcl(module: int in 0..255) {
    request { field module "B" = module  payload  checksum "sum" "B" }
    reply { field host "B" = 2  field module "B" = module  payload  checksum "sum" "B" }
}
/// GAP: the reply's status says whether it is the value or the module's refusal.
primitive get(index: int in 0..255, limit: int in 0..255) on link frame tmcl(1) pack ">BBBi" (6, index, 0, 0)
    unpack ">BBi" error when out[0] < limit code Status expect out[1] == 6 { value = out[2] }
/// Unframed, unnamed: a nonzero first byte is an error.
primitive read_level() on link pack "B" (0x21) unpack "BB" error when out[0] != 0 retry 2 { level = out[1] }
"""


def _datagram(status: int, command: int, value: int) -> bytes:
    body = bytes([2, 1, status, command]) + value.to_bytes(4, "big", signed=True)
    return body + bytes([sum(body) & 0xFF])


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_reply_whose_status_says_no_is_the_devices_error(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(_datagram(100, 6, -7) + _datagram(2, 6, 0) + _datagram(9, 6, 0) + _datagram(50, 6, 5)
                        + _datagram(99, 7, 0))
    with implementation_of(kind, STATUS, tmp_path, "status").connect(port, threads=False) as robot:
        robot.call_primitive("get", 1, 100)
        assert robot.state["value"] == -7
        for said, code, name in (("error 2 (INVALID_COMMAND)", 2, "INVALID_COMMAND"),
                                 ("error 9 (not a member of Status)", 9, None)):
            with pytest.raises(Exception) as caught:
                robot.call_primitive("get", 1, 100)
            assert type(caught.value).__name__ == "RdisDeviceError"
            assert str(caught.value) == f"get: the device answered {said}"
            assert (caught.value.code, caught.value.name, caught.value.values) == (code, name, (code, 6, 0))
        robot.call_primitive("get", 1, 50)  # the condition reads the parameters: 50 is not below 50
        assert robot.state["value"] == 5
        with pytest.raises(Exception) as caught:  # the error is told before the `expect` is held
            robot.call_primitive("get", 1, 100)
        assert type(caught.value).__name__ == "RdisDeviceError" and robot.state["value"] == 5


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_unframed_reply_that_says_no_is_not_retried(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"\x03\x09" + b"\x00\x2a")
    with implementation_of(kind, STATUS, tmp_path, "status").connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read_level")
        assert str(caught.value) == "read_level: the device answered error 3"
        assert port.writes == [b"\x21"]
        robot.call_primitive("read_level")
        assert robot.state["level"] == 42


def test_an_error_when_goes_through_json_and_the_printer(tmp_path: Path) -> None:
    module = parse("x.rdis", STATUS, Diagnostics())
    printed = print_module(module)
    assert "error when out[0] < limit code Status" in printed
    assert print_module(parse("x.rdis", printed, Diagnostics())) == printed
    _, built = through_json(STATUS, tmp_path, "status")
    assert [p["error"] for p in json.loads(built)["primitives"]] == [
        {"when": "<__out__[0] < limit>", "codes": "Status"}, {"when": "<__out__[0] != 0>"}]


def test_the_languages_error_when_example_writes_and_reads_what_it_says(tmp_path: Path) -> None:
    doc = (Path(__file__).resolve().parents[2] / "docs" / "language.md").read_text(encoding="utf-8")
    (block,) = [b for b in doc.split("```rdis\n") if "primitive actual_position" in b]
    text = 'robot doc { author "tests" }\nconnection serial0: serial { baud 115200 }\n' + block.split("```")[0]
    port = ScriptedPort(bytes.fromhex("02 01 64 06 00 00 03 E8 58") + bytes.fromhex("02 01 03 06 00 00 00 00 0C"))
    with implementation_of("runtime", text, tmp_path, "doc").connect(port, threads=False) as robot:
        robot.call_primitive("actual_position", 0)
        assert port.writes == [bytes.fromhex("01 06 01 00 00 00 00 00 08")] and robot.state["actual"] == 1000
        with pytest.raises(Exception) as caught:
            robot.call_primitive("actual_position", 0)
        assert str(caught.value) == "actual_position: the device answered error 3 (WRONG_TYPE)"
