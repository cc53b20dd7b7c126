"""examples/modbus.rdis against minimalmodbus (2.1.1), the published Modbus RTU driver, byte
for byte: the requests rdisc writes are the ones minimalmodbus builds (`_create_payload`, framed
by `_embed_payload` with its CRC), the replies it frames are read, and every exception reply
minimalmodbus reports as the server's (`_check_response_slaveerrorcode`) is an RdisDeviceError
with the same code, named by the description's enum. The runtime and the generated driver alike.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

mm = pytest.importorskip("minimalmodbus")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "modbus.rdis"
UNIT = 17
NAMES = {1: "ILLEGAL_FUNCTION", 2: "ILLEGAL_DATA_ADDRESS", 3: "ILLEGAL_DATA_VALUE", 4: "SERVER_DEVICE_FAILURE",
         6: "SERVER_DEVICE_BUSY", 8: "MEMORY_PARITY_ERROR", 10: "GATEWAY_PATH_UNAVAILABLE",
         11: "GATEWAY_TARGET_FAILED"}


@pytest.fixture(scope="module", params=["runtime", "driver"])
def modbus(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Any]:
    folder = tmp_path_factory.mktemp("modbus")
    return request.param, implementation_of(request.param, EXAMPLE.read_text(encoding="utf-8"), folder, "modbus")


def _connect(modbus: tuple[str, Any], port: ScriptedPort) -> Any:
    kind, implementation = modbus
    if kind == "runtime":
        return implementation.connect(port, threads=False, settings={"UNIT": UNIT})
    return implementation.connect(port, threads=False, UNIT=UNIT)


def _request(function: int, address: int, value: Any, registers: int, form: Any) -> bytes:
    payload = mm._create_payload(function, address, value, 0, registers, 0, False, mm.BYTEORDER_BIG, form)
    return mm._embed_payload(UNIT, mm.MODE_RTU, function, payload)


def _exception(function: int, code: int) -> bytes:
    body = bytes([UNIT, function | 0x80, code])
    return body + mm._calculate_crc(body)


@pytest.mark.parametrize("start", [0, 0x6B, 40000, 65534])
def test_read_holding_registers(modbus: tuple[str, Any], start: int) -> None:
    values = [start ^ 0x1234, 0xBEEF]
    reply = mm._embed_payload(UNIT, mm.MODE_RTU, 3, bytes([4]) + b"".join(v.to_bytes(2, "big") for v in values))
    port = ScriptedPort(reply)
    with _connect(modbus, port) as robot:
        robot.call_primitive("read_holding", start)
        assert bytes(port.written) == _request(3, start, None, 2, mm._Payloadformat.REGISTERS)
        payload = mm._extract_payload(reply, UNIT, mm.MODE_RTU, 3)
        assert list(robot.state["holding"]) == mm._parse_payload(
            payload, 3, start, None, 0, 2, 0, False, mm.BYTEORDER_BIG, mm._Payloadformat.REGISTERS) == values


@pytest.mark.parametrize(("address", "value"), [(0, 0), (0x10, 300), (65535, 65535)])
def test_write_single_register_and_its_echo(modbus: tuple[str, Any], address: int, value: int) -> None:
    request = _request(6, address, value, 1, mm._Payloadformat.REGISTER)
    port = ScriptedPort(request)  # the server echoes the request
    with _connect(modbus, port) as robot:
        robot.call_primitive("write_register", address, value)
        assert bytes(port.written) == request
        assert robot.state["written"] == value


@pytest.mark.parametrize("code", sorted(NAMES))
@pytest.mark.parametrize(("primitive", "function", "args"), [("read_holding", 3, (0x6B,)), ("read_input", 4, (7,)),
                                                              ("write_register", 6, (1, 2))])
def test_an_exception_is_the_servers_code(modbus: tuple[str, Any], primitive: str, function: int, args: tuple[int, ...],
                                          code: int) -> None:
    reply = _exception(function, code)
    with pytest.raises(mm.SlaveReportedException):  # what minimalmodbus makes of these bytes
        mm._check_response_slaveerrorcode(reply)
    port = ScriptedPort(reply)
    with _connect(modbus, port) as robot:
        with pytest.raises(Exception) as caught:  # the driver's RdisDeviceError is its own class
            robot.call_primitive(primitive, *args)
        assert type(caught.value).__name__ == "RdisDeviceError"
        assert (caught.value.code, caught.value.name) == (code, NAMES[code])
        assert str(caught.value) == f"{primitive}: the device answered error {code} ({NAMES[code]})"
        assert robot.state["written"] == 0 and robot.state["input"] == 0


def test_another_units_exception_is_a_protocol_error(modbus: tuple[str, Any]) -> None:
    body = bytes([UNIT + 1, 0x83, 2])
    port = ScriptedPort(body + mm._calculate_crc(body))
    with _connect(modbus, port) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read_holding", 0)
        assert type(caught.value).__name__ == "RdisProtocolError"
