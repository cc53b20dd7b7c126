"""examples/motoron.rdis against the Pololu Motoron Motor Controller User's Guide, over real ptys.

The Motoron's serial responses end with a CRC-7 byte unless "Set protocol options" turned CRC
for responses off, as its commands do for CRC for commands (guide, sections 9 and 11; the
motoron Python library's `MotoronSerial.__read_response` reads `length + crc_enabled` bytes).
Both are settings of the description, so the reply's layout as well as the request's is chosen
when connecting (`either when`). An emulated Motoron on a pty reads each command as the guide
states it (compact, or 0xAA, the device number and the command without bit 7; a CRC byte when
CRC for commands is on, a wrong one ignored with the CRC error flag set) and answers with its
variables, low byte first, and a CRC byte when CRC for responses is on: its own CRC, the guide's
C code, not rdisc's. The rdisc runtime and the driver `rdisc emit-python` generates both go
through it, byte for byte.
"""

from __future__ import annotations

import struct
from pathlib import Path
from typing import Any

import pytest
from devices import PtyDevice

from rdisc.emit.python import import_driver
from rdisc.runtime import load
from tests.support.pololu import crc7

ROOT = Path(__file__).resolve().parents[2]
DESCRIPTION = ROOT / "examples" / "motoron.rdis"

GET_FIRMWARE_VERSION, GET_VARIABLES, COAST_NOW = 0x87, 0x9A, 0xA5
CLEAR_LATCHED_STATUS_FLAGS, SET_SPEED = 0xA9, 0xD1
DATA_BYTES = {GET_FIRMWARE_VERSION: 0, GET_VARIABLES: 3, COAST_NOW: 0, CLEAR_LATCHED_STATUS_FLAGS: 2, SET_SPEED: 3}
CRC_ERROR, RESET = 1 << 1, 1 << 9  # status flags
GUIDE_SET_SPEED_1_100 = bytes([0xD1, 0x01, 0x64, 0x00, 0x68])  # section 11: "Set speed" of motor 1 to 100, CRC
GUIDE_CLEAR_RESET_FLAG = bytes([0xA9, 0x00, 0x04])  # the guide's initialization sequence, CRC disabled



class Motoron(PtyDevice):
    """A Motoron M3S of device number `number`, its CRC options as given: three motors' speeds
    (reached at once: no acceleration limits) and its status flags (the reset flag set at power-up)."""

    def __init__(self, number: int = 16, crc_commands: bool = True, crc_responses: bool = True) -> None:
        super().__init__()
        self.number = number
        self.crc_commands = crc_commands
        self.crc_responses = crc_responses
        self.speed = [0, 0, 0]
        self.status = RESET
        self._pending = bytearray()

    def handle(self, data: bytes) -> None:
        self._pending += data
        crc = int(self.crc_commands)
        while self._pending:
            addressed = self._pending[0] == 0xAA
            head = 3 if addressed else 1
            if len(self._pending) < head:
                return
            command = self._pending[head - 1] | (0x80 if addressed else 0)
            size = head + DATA_BYTES.get(command, 0) + crc
            if len(self._pending) < size:
                return
            packet, self._pending = bytes(self._pending[:size]), self._pending[size:]
            if crc and crc7(packet[:-1]) != packet[-1]:
                self.status |= CRC_ERROR
                continue
            if addressed and packet[1] != self.number:
                continue  # another device's command
            self._run(command, packet[head : size - crc])

    def _run(self, command: int, data: bytes) -> None:
        if command == SET_SPEED:
            speed = data[1] | data[2] << 7
            self.speed[data[0] - 1] = speed - (1 << 14) if speed & 1 << 13 else speed
        elif command == COAST_NOW:
            self.speed = [0, 0, 0]
        elif command == CLEAR_LATCHED_STATUS_FLAGS:
            self.status &= ~(data[0] | data[1] << 7)
        elif command == GET_FIRMWARE_VERSION:
            self._answer(struct.pack("<HBB", 0x00CC, 0x04, 0x01))  # product 204, firmware 1.04
        elif command == GET_VARIABLES:
            motor, offset, length = data
            variables = struct.pack("<xH", self.status) if motor == 0 else \
                struct.pack("<6xh", self.speed[motor - 1])
            self._answer(variables[offset : offset + length])

    def _answer(self, data: bytes) -> None:
        self.send(data + (bytes([crc7(data)]) if self.crc_responses else b""))

    def _cleared(self) -> None:
        self._pending.clear()


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Any]:
    if request.param == "runtime":
        return "runtime", load(DESCRIPTION)
    return "driver", import_driver(DESCRIPTION, tmp_path_factory.mktemp("motoron"), "motoron_driver")


def _connect(implementation: tuple[str, Any], motoron: Motoron, **settings: Any) -> Any:
    kind, made = implementation
    given = {"settings": settings} if kind == "runtime" else settings
    return made.connect(motoron.port, timeout=5.0, threads=False, **given)


def test_the_guides_example_byte_for_byte(implementation: tuple[str, Any]) -> None:
    assert bytes([*GUIDE_SET_SPEED_1_100[:-1], crc7(GUIDE_SET_SPEED_1_100[:-1])]) == GUIDE_SET_SPEED_1_100
    with Motoron() as motoron, _connect(implementation, motoron) as robot:
        robot.primitives.set_speed(1, 100)
        assert motoron.wait_for(5, 5) == GUIDE_SET_SPEED_1_100
        assert motoron.speed == [100, 0, 0] and motoron.status == RESET


def test_the_guides_start_up_without_crc(implementation: tuple[str, Any]) -> None:
    with Motoron(crc_commands=False, crc_responses=False) as motoron, \
            _connect(implementation, motoron, crc_commands=False, crc_responses=False) as robot:
        robot.interfaces.start()
        assert motoron.wait_for(3, 5) == GUIDE_CLEAR_RESET_FLAG
        assert motoron.status == 0


# (settings, the request of get_current_speed(2), the reply's bytes with speed -300)
LAYOUTS = [
    ({}, "9A 02 06 02", True),  # the defaults: compact, CRC both ways
    ({"crc_commands": False, "crc_responses": False}, "9A 02 06 02", False),
    ({"crc_responses": False}, "9A 02 06 02", False),  # CRC on commands only
    ({"crc_commands": False}, "9A 02 06 02", True),  # CRC on responses only
    ({"pololu": True, "device": 17}, "AA 11 1A 02 06 02", True),
    ({"pololu": True, "device": 17, "crc_commands": False, "crc_responses": False}, "AA 11 1A 02 06 02", False),
]


@pytest.mark.parametrize(("settings", "request_hex", "answered"), LAYOUTS)
def test_the_settings_choose_the_request_and_the_reply(implementation: tuple[str, Any], settings: dict[str, Any],
                                                       request_hex: str, answered: bool) -> None:
    """The reply is read as the settings say: with its CRC byte (checked) or without one."""
    crc_commands, crc_responses = settings.get("crc_commands", True), settings.get("crc_responses", True)
    request = bytes.fromhex(request_hex)
    request += bytes([crc7(request)]) if crc_commands else b""
    with Motoron(settings.get("device", 16), crc_commands, crc_responses) as motoron, \
            _connect(implementation, motoron, **settings) as robot:
        motoron.speed[1] = -300
        robot.primitives.get_current_speed(2)
        assert motoron.received == request
        assert list(robot.state["speed"]) == [0, -300, 0]
        robot.primitives.get_status_flags()
        assert robot.state["status"] == RESET
        robot.primitives.get_firmware_version()  # four bytes and the CRC byte when asked, read whole
    assert answered == crc_responses


def test_a_reply_with_a_wrong_crc_byte_is_refused(implementation: tuple[str, Any]) -> None:
    with Motoron() as motoron, _connect(implementation, motoron) as robot:
        motoron.speed[0] = 5
        motoron._answer = lambda data: motoron.send(data + b"\x00")  # type: ignore[method-assign]
        with pytest.raises(Exception) as caught:
            robot.primitives.get_current_speed(1)
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", ("get_current_speed: command: checksum 00 does not match the reply, which sums to "
            f"{crc7(struct.pack('<h', 5)):02x}"))
        assert list(robot.state["speed"]) == [0, 0, 0]
