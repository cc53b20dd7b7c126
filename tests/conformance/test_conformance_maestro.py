"""examples/maestro.rdis against the Pololu Maestro Servo Controller User's Guide, over real ptys.

No published Python driver of the compact protocol can be pinned: maestro-servo 0.2.0 talks
to the Maestro by USB control transfers (pyusb), not by its serial commands; pymaestro 0.1's
sdist ships only an __init__ importing modules it lacks; pololu-motors 0.2.x, whose Maestro
class writes the serial protocol, does not build on Python 3.11 (its setup.py's regex is
refused); and ucan-servo-mcp's usc.py speaks its board's own text commands. So the bytes
are held against the guide (section 5.e): its examples as literals, and an emulated Maestro
on a pty that reads each command as the guide states it (a command byte with bit 7 set, data
bytes without; a 14-bit value as its low 7 bits, then bits 7-13; replies low byte first),
with its own decoding, not rdisc's. The rdisc runtime and the driver `rdisc emit-python`
generates both go through it. The Pololu protocol and its CRC-7 byte (section 5.c-d) are held
as the guide's bytes on a scripted port.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from devices import PtyDevice

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load
from tests.support.pololu import crc7
from tests.support.ports import ScriptedPort

ROOT = Path(__file__).resolve().parents[2]
DESCRIPTION = ROOT / "examples" / "maestro.rdis"
JOINTS = ("pan", "tilt", "shoulder", "elbow", "wrist", "gripper")

SET_TARGET, SET_SPEED, SET_ACCELERATION, SET_MULTIPLE_TARGETS = 0x84, 0x87, 0x89, 0x9F
GET_POSITION, GET_MOVING_STATE, GET_ERRORS, GO_HOME = 0x90, 0x93, 0xA1, 0xA2
PROTOCOL_ERROR = 1 << 4  # the error register's bit 4: a packet the Maestro cannot make sense of
DATA_BYTES = {SET_TARGET: 3, SET_SPEED: 3, SET_ACCELERATION: 3, GET_POSITION: 1,
              GET_MOVING_STATE: 0, GET_ERRORS: 0, GO_HOME: 0}

# The guide's own examples (section 5.e), as bytes.
GUIDE_SET_TARGET_2_1500US = bytes([0x84, 0x02, 0x70, 0x2E])  # "in hex: 0x84, 0x02, 0x70, 0x2E"
GUIDE_SET_TARGET_0_1500US = bytes([0x84, 0x00, 0x70, 0x2E])  # section 5.c, the compact protocol
GUIDE_SET_SPEED_5_140 = bytes([0x87, 0x05, 0x0C, 0x01])  # "sets the speed of servo channel 5 to ... 140"
# "to set channel 3 to 0 (off) and channel 4 to 6000 (neutral), you would send the following bytes"
GUIDE_SET_MULTIPLE_TARGETS_3_4 = bytes([0x9F, 0x02, 0x03, 0x00, 0x00, 0x70, 0x2E])


class Maestro(PtyDevice):
    """A Maestro of `channels` channels as the guide describes it: targets, speed and
    acceleration limits, positions, the error register (cleared as it is read) and home
    positions. Set Multiple Targets is a Mini Maestro's (12 channels or more): a Micro
    Maestro 6 takes it for a protocol error, as it does an unknown command or a channel it
    lacks."""

    def __init__(self, channels: int = 6) -> None:
        super().__init__()
        self.channels = channels
        self.position = [6000] * channels
        self.target = [6000] * channels
        self.speed = [0] * channels
        self.acceleration = [0] * channels
        self.home = [0] * channels  # "Off": no pulses after Go Home
        self.errors = 0
        self._pending = bytearray()

    def handle(self, data: bytes) -> None:
        self._pending += data
        while self._pending:
            command = self._pending[0]
            if command == SET_MULTIPLE_TARGETS and self.channels > 6:
                if len(self._pending) < 3:
                    return
                size = 3 + 2 * self._pending[1]
            elif command in DATA_BYTES:
                size = 1 + DATA_BYTES[command]
            else:
                self.errors |= PROTOCOL_ERROR
                del self._pending[0]
                continue
            if len(self._pending) < size:
                return
            packet, self._pending = bytes(self._pending[:size]), self._pending[size:]
            if any(b & 0x80 for b in packet[1:]):  # a data byte with bit 7 set: not a packet
                self.errors |= PROTOCOL_ERROR
                continue
            self._run(packet)

    def _run(self, packet: bytes) -> None:
        command, data = packet[0], packet[1:]
        if command in (SET_TARGET, SET_SPEED, SET_ACCELERATION, GET_POSITION) and data[0] >= self.channels:
            self.errors |= PROTOCOL_ERROR
        elif command == SET_TARGET:
            self._set_target(data[0], data[1] | data[2] << 7)
        elif command == SET_SPEED:
            self.speed[data[0]] = data[1] | data[2] << 7
        elif command == SET_ACCELERATION:
            self.acceleration[data[0]] = data[1] | data[2] << 7
        elif command == SET_MULTIPLE_TARGETS:
            count, first = data[0], data[1]
            if first + count > self.channels:
                self.errors |= PROTOCOL_ERROR
                return
            for i in range(count):
                self._set_target(first + i, data[2 + 2 * i] | data[3 + 2 * i] << 7)
        elif command == GET_POSITION:
            self.send(struct.pack("<H", self.position[data[0]]))
        elif command == GET_MOVING_STATE:
            self.send(bytes([int(self.position != self.target)]))
        elif command == GET_ERRORS:
            errors, self.errors = self.errors, 0  # cleared before the answer leaves: the host may look at once
            self.send(struct.pack("<H", errors))
        elif command == GO_HOME:
            self.position = list(self.home)
            self.target = list(self.home)

    def _set_target(self, channel: int, target: int) -> None:
        """Without limits a channel's pulse width is its target at once; with them it moves."""
        self.target[channel] = target
        if not self.speed[channel] and not self.acceleration[channel]:
            self.position[channel] = target

    def _cleared(self) -> None:
        self._pending.clear()


def compact(command: int, channel: int, value: int) -> bytes:
    """A command with a channel and a 14-bit value, as the guide's C example writes it."""
    return bytes([command, channel, value & 0x7F, (value >> 7) & 0x7F])


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest,
                   tmp_path_factory: pytest.TempPathFactory) -> tuple[Any, type[Exception]]:
    """The description run by the runtime, or its generated driver, with its RdisValueError."""
    if request.param == "runtime":
        return load(DESCRIPTION), errors.RdisValueError
    driver = import_driver(DESCRIPTION, tmp_path_factory.mktemp("maestro"), "maestro_driver")
    return driver, driver.RdisValueError


@pytest.fixture
def micro() -> Iterator[Maestro]:
    with Maestro() as device:
        yield device


@pytest.fixture
def robot(micro: Maestro, implementation: tuple[Any, type[Exception]]) -> Iterator[Any]:
    with implementation[0].connect(micro.port, timeout=5.0, threads=False) as connected:
        yield connected


def test_the_guides_examples_byte_for_byte(micro: Maestro, robot: Any) -> None:
    assert compact(SET_TARGET, 2, 6000) == GUIDE_SET_TARGET_2_1500US  # the rule the test holds rdisc to
    robot.primitives.set_target(2, 6000)
    assert micro.wait_for(4, 5) == GUIDE_SET_TARGET_2_1500US
    micro.clear()
    robot.primitives.set_target(0, 1500 * 4)
    assert micro.wait_for(4, 5) == GUIDE_SET_TARGET_0_1500US
    micro.clear()
    robot.primitives.set_speed(5, 140)
    assert micro.wait_for(4, 5) == GUIDE_SET_SPEED_5_140
    assert micro.target[2] == micro.position[2] == 6000 and micro.speed[5] == 140
    assert micro.errors == 0


@pytest.mark.parametrize("target", [0, 1, 127, 128, 6000, 4095 * 4, 0x3FFF])
def test_every_target_splits_7_and_7_bits(micro: Maestro, robot: Any, target: int) -> None:
    robot.primitives.set_target(5, target)
    assert micro.wait_for(4, 5) == compact(SET_TARGET, 5, target)
    assert micro.target[5] == target and micro.errors == 0


def test_speed_and_acceleration_limits_on_every_channel(micro: Maestro, robot: Any) -> None:
    robot.interfaces.limit_all(0x3FFF, 255)
    expected = b"".join(compact(SET_SPEED, ch, 0x3FFF) + compact(SET_ACCELERATION, ch, 255) for ch in range(6))
    assert micro.wait_for(len(expected), 5) == expected
    assert micro.speed == [0x3FFF] * 6 and micro.acceleration == [255] * 6 and micro.errors == 0


@pytest.mark.parametrize("call", [
    ("set_target", (0, 0x4000)), ("set_target", (0, -1)), ("set_target", (6, 6000)),
    ("set_speed", (1, 0x4000)), ("set_acceleration", (1, 256)), ("get_position", (6,)),
])
def test_a_value_the_protocol_cannot_carry_is_refused_before_anything_is_written(
        micro: Maestro, robot: Any, implementation: tuple[Any, type[Exception]],
        call: tuple[str, tuple[int, ...]]) -> None:
    name, args = call
    with pytest.raises(implementation[1]):
        getattr(robot.primitives, name)(*args)
    robot.primitives.go_home()  # the next command's byte is the first the device sees
    assert micro.wait_for(1, 5) == bytes([GO_HOME])


def test_pulse_widths_in_seconds(micro: Maestro, robot: Any, implementation: tuple[Any, type[Exception]]) -> None:
    widths = [0.0, 0.001, 0.0015, 0.002, 0.0025, 0.004095]  # 0 stops the pulses; 4095 us the most here
    robot.interfaces.move_pulses(widths)
    targets = [0, 4000, 6000, 8000, 10000, 4095 * 4]
    expected = b"".join(compact(SET_TARGET, ch, t) for ch, t in enumerate(targets))
    assert micro.wait_for(len(expected), 5) == expected
    assert micro.target == targets
    micro.clear()
    with pytest.raises(implementation[1]):  # one width past 14 bits: no channel moves
        robot.interfaces.move_pulses([0.0015] * 5 + [0.0041])
    with pytest.raises(implementation[1]):
        robot.interfaces.move_pulses([-0.001] + [0.0015] * 5)
    robot.primitives.go_home()
    assert micro.wait_for(1, 5) == bytes([GO_HOME])


ANGLES = [0.0, -math.pi / 2, math.pi / 2, 0.5, -0.25, 1.0]


def test_angles_are_pulse_widths_around_1500_us(micro: Maestro, robot: Any,
                                                 implementation: tuple[Any, type[Exception]]) -> None:
    targets = [round(4 * (1500 + a * 500 / (math.pi / 2))) for a in ANGLES]  # 1000-2000 us over a half turn
    assert targets == [6000, 4000, 8000, 6637, 5682, 7273]
    robot.interfaces.move(ANGLES)
    expected = b"".join(compact(SET_TARGET, ch, t) for ch, t in enumerate(targets))
    assert micro.wait_for(len(expected), 5) == expected
    micro.clear()
    robot.inputs.command(name=list(JOINTS), position=ANGLES)  # a JointState: the same six commands
    assert micro.wait_for(len(expected), 5) == expected
    micro.clear()
    with pytest.raises(implementation[1]):  # past a quarter turn: refused, nothing written
        robot.interfaces.move([0.0] * 5 + [1.6])
    robot.primitives.go_home()
    assert micro.wait_for(1, 5) == bytes([GO_HOME])


def test_read_joints_reads_every_position_and_the_errors(micro: Maestro, robot: Any) -> None:
    micro.position = [0, 4000, 6000, 8000, 4095 * 4, 0x3FFF]  # edge values: both bytes of each in use
    micro.errors = 0x0110  # protocol error (bit 4) and script program counter error (bit 8)
    delivered: list[dict[str, Any]] = []
    robot.on_output(delivered.append)
    robot.interfaces.read_joints()
    assert micro.received == b"".join(bytes([GET_POSITION, ch]) for ch in range(6)) + bytes([GET_ERRORS])
    assert robot.state.position == (0, 4000, 6000, 8000, 16380, 16383)
    assert robot.state.errors == 0x0110
    assert micro.errors == 0  # cleared as the Maestro answered
    (joints,) = delivered
    assert joints["contents"]["name"] == JOINTS
    assert joints["contents"]["position"] == pytest.approx(
        [(p - 6000) * (math.pi / 2) / 2000 for p in micro.position])
    robot.primitives.get_errors()
    assert robot.state.errors == 0


def test_moving_state_while_a_limited_channel_moves(micro: Maestro, robot: Any) -> None:
    robot.primitives.get_moving_state()
    assert robot.state.moving is False
    robot.primitives.set_speed(3, 10)
    robot.primitives.set_target(3, 7000)
    robot.primitives.get_moving_state()
    assert micro.received == (bytes([GET_MOVING_STATE]) + compact(SET_SPEED, 3, 10) + compact(SET_TARGET, 3, 7000)
                              + bytes([GET_MOVING_STATE]))
    assert robot.state.moving is True
    robot.primitives.go_home()
    robot.primitives.get_moving_state()
    assert robot.state.moving is False
    assert micro.position == micro.home


def test_the_emulator_reads_the_guides_set_multiple_targets() -> None:
    mini = Maestro(channels=12)  # not started: its handler alone
    mini.handle(GUIDE_SET_MULTIPLE_TARGETS_3_4)
    assert mini.target[3:5] == [0, 6000] and mini.errors == 0
    micro = Maestro()
    micro.handle(GUIDE_SET_MULTIPLE_TARGETS_3_4)
    assert micro.errors == PROTOCOL_ERROR and micro.target == [6000] * 6


def test_set_multiple_targets_on_a_mini_maestro(implementation: tuple[Any, type[Exception]]) -> None:
    targets = [0, 4000, 6000, 8000, 4095 * 4, 0x3FFF]
    expected = bytes([SET_MULTIPLE_TARGETS, 6, 0]) + b"".join(compact(SET_TARGET, 0, t)[2:] for t in targets)
    with Maestro(channels=12) as mini, implementation[0].connect(mini.port, timeout=5.0, threads=False) as robot:
        robot.interfaces.set_all_targets(targets)
        assert mini.wait_for(len(expected), 5) == expected
        robot.primitives.get_errors()  # a reply after the command: it has been read
        assert mini.target[:6] == targets and mini.target[6:] == [6000] * 6
        assert robot.state.errors == 0
        with pytest.raises(implementation[1]):
            robot.interfaces.set_all_targets([6000] * 5 + [0x4000])
    with Maestro() as micro, implementation[0].connect(micro.port, timeout=5.0, threads=False) as robot:
        robot.interfaces.set_all_targets(targets)  # a Micro Maestro does not know the command
        robot.primitives.get_errors()
        assert robot.state.errors & PROTOCOL_ERROR
        assert micro.target == [6000] * 6


# The guide's Pololu protocol (section 5.c): 0xAA, the device number, the command byte with bit 7
# cleared, the same data bytes; "Pololu protocol, device number 12" for the example above.
GUIDE_POLOLU_SET_TARGET_2_1500US = bytes([0xAA, 0x0C, 0x04, 0x02, 0x70, 0x2E])



def test_the_reference_crc7_gives_the_guides_example() -> None:
    assert crc7(bytes([0x83, 0x01])) == 0x17  # "the CRC-7 of 0x83, 0x01 is 0x17"


@pytest.mark.parametrize(("settings", "expected"), [
    ({}, GUIDE_SET_TARGET_2_1500US),
    ({"protocol": 1}, GUIDE_POLOLU_SET_TARGET_2_1500US),
    ({"protocol": 2}, GUIDE_POLOLU_SET_TARGET_2_1500US + bytes([crc7(GUIDE_POLOLU_SET_TARGET_2_1500US)])),
    ({"protocol": 1, "device": 3}, bytes([0xAA, 0x03, 0x04, 0x02, 0x70, 0x2E])),
])
def test_the_protocol_setting_chooses_the_framing(implementation: tuple[Any, type[Exception]],
                                                  settings: dict[str, int], expected: bytes) -> None:
    described = implementation[0]
    given = settings if hasattr(described, "RdisValueError") else {"settings": settings}
    port = ScriptedPort(bytes([0x70, 0x17]))  # Get Position's reply, the same in every protocol
    with described.connect(port, threads=False, **given) as robot:
        robot.primitives.set_target(2, 6000)
        robot.primitives.get_position(1)
        assert robot.state["position"][1] == 0x1770
    get_position = bytes([GET_POSITION, 1])
    if settings.get("protocol", 0):
        get_position = bytes([0xAA, settings.get("device", 12), GET_POSITION & 0x7F, 1])
        if settings["protocol"] == 2:
            get_position += bytes([crc7(get_position)])
    assert bytes(port.written) == expected + get_position
