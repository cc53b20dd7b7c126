"""examples/arm.rdis against ROBOTIS's published dynamixel-sdk, byte for byte, over real ptys.

An emulated bus of six X-series servos (protocol 2.0, tests/devices/dynamixel.py) sits on a pty. dynamixel-sdk's
GroupSyncWrite, GroupSyncRead and GroupBulkRead talk to it, and so do the rdisc runtime and the driver
`rdisc emit-python` generates: every packet they write must be the SDK's, and the positions
they read from the same status packets must be the ones the SDK's getData returns.

The bus answers from the protocol as the e-Manual states it, not with rdisc's or the SDK's
code; one servo's present position is a multi-turn value whose bytes hold FF FF FD, so its
status packet is stuffed.
"""

from __future__ import annotations

import math
import struct
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("dynamixel_sdk")

import dynamixel_sdk as sdk
from devices.dynamixel import IDS, PRESENT, TEMPERATURE, XBus, status

from rdisc.emit.python import import_driver
from rdisc.runtime import load

ROOT = Path(__file__).resolve().parents[2]
DESCRIPTION = ROOT / "examples" / "arm.rdis"
GOAL, TORQUE = 116, 64
TORQUE_PACKET = 26  # bytes of the sync write of six 1-byte values the startup hook sends


@pytest.fixture
def bus() -> Iterator[XBus]:
    with XBus() as device:
        yield device


def _sdk(bus: XBus) -> tuple[Any, Any]:
    port = sdk.PortHandler(bus.port)
    assert port.openPort() and port.setBaudRate(1_000_000)
    return port, sdk.PacketHandler(2.0)


def _sdk_sync_write(bus: XBus, address: int, size: int, values: list[int]) -> bytes:
    """The packet dynamixel-sdk's GroupSyncWrite sends for six values."""
    port, handler = _sdk(bus)
    try:
        group = sdk.GroupSyncWrite(port, handler, address, size)
        for dxl_id, value in zip(IDS, values):
            assert group.addParam(dxl_id, list(value.to_bytes(size, "little")))
        bus.clear()
        assert group.txPacket() == sdk.COMM_SUCCESS
        return bus.wait_until(lambda: len(bus.received) >= 14 + 6 * (size + 1), 5, "the sync write")
    finally:
        port.closePort()


def _sdk_sync_read(bus: XBus) -> tuple[bytes, dict[int, int]]:
    """The packet GroupSyncRead sends for Present Position, and the positions it reads back."""
    port, handler = _sdk(bus)
    try:
        group = sdk.GroupSyncRead(port, handler, PRESENT, 4)
        for dxl_id in IDS:
            assert group.addParam(dxl_id)
        bus.clear()
        assert group.txPacket() == sdk.COMM_SUCCESS
        # The SDK's reply timeout is a few milliseconds of wall clock: wait until the bus has
        # answered (six status packets, one stuffed) before it reads, so a busy machine cannot fail it.
        answers = sum(len(status(i, bus.errors[i], struct.pack("<i", bus.present[i]))) for i in IDS)
        deadline = time.monotonic() + 10
        while port.ser.in_waiting < answers and time.monotonic() < deadline:
            time.sleep(0.005)
        assert group.rxPacket() == sdk.COMM_SUCCESS
        positions = {i: struct.unpack("<i", struct.pack("<I", group.getData(i, PRESENT, 4)))[0] for i in IDS}
        return bus.received, positions
    finally:
        port.closePort()


def _sdk_bulk_read(bus: XBus) -> tuple[bytes, int, int]:
    """The packet GroupBulkRead sends for servo 1's Present Position (4 bytes) and servo 6's
    Present Temperature (1 byte), and the two values it reads back."""
    port, handler = _sdk(bus)
    try:
        group = sdk.GroupBulkRead(port, handler)
        assert group.addParam(1, PRESENT, 4) and group.addParam(6, TEMPERATURE, 1)
        bus.clear()
        assert group.txPacket() == sdk.COMM_SUCCESS
        answers = len(status(1, 0, struct.pack("<i", bus.present[1]))) + len(status(6, 0, b"\0"))
        deadline = time.monotonic() + 10  # as for the sync read: the bus has answered before the SDK reads
        while port.ser.in_waiting < answers and time.monotonic() < deadline:
            time.sleep(0.005)
        assert group.rxPacket() == sdk.COMM_SUCCESS
        position = struct.unpack("<i", struct.pack("<I", group.getData(1, PRESENT, 4)))[0]
        return bus.received, position, group.getData(6, TEMPERATURE, 1)
    finally:
        port.closePort()


@pytest.fixture(scope="module", params=["runtime", "driver"])
def arm(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    if request.param == "runtime":
        return load(DESCRIPTION)
    return import_driver(DESCRIPTION, tmp_path_factory.mktemp("arm"), "arm_driver")


def test_torque_is_one_sync_write_as_the_sdk_sends_it(bus: XBus, arm: Any) -> None:
    on = _sdk_sync_write(bus, TORQUE, 1, [1] * 6)
    off = _sdk_sync_write(bus, TORQUE, 1, [0] * 6)
    bus.clear()
    with arm.connect(bus.port, timeout=5.0, threads=False):  # the startup hook: torque on
        assert bus.wait_for(len(on), 5) == on
        bus.clear()
    assert bus.wait_for(len(off), 5) == off  # the terminate hook: torque off


ANGLES = [0.0, -1.5, 1.5, math.pi / 2, -math.pi, 3.2]  # the last beyond half a turn: clamped to 4095


def test_a_move_is_the_sdks_sync_write_of_six_goals(bus: XBus, arm: Any) -> None:
    goals = [min(4095, max(0, round(a * 4096 / (2 * math.pi)) + 2048)) for a in ANGLES]
    assert goals == [2048, 1070, 3026, 3072, 0, 4095]
    expected = _sdk_sync_write(bus, GOAL, 4, goals)
    bus.clear()
    with arm.connect(bus.port, timeout=5.0, threads=False) as robot:
        bus.wait_for(TORQUE_PACKET, 5)  # the startup hook's, then nothing but the move
        bus.clear()
        robot.interfaces.move(ANGLES)
        assert bus.wait_for(len(expected), 5) == expected
        bus.clear()
        robot.primitives.sync_goal(goals)  # the primitive, given the units directly
        assert bus.wait_for(len(expected), 5) == expected


def test_a_sync_read_asks_and_reads_as_the_sdk_does(bus: XBus, arm: Any) -> None:
    request, positions = _sdk_sync_read(bus)
    assert positions == bus.present  # the SDK read the six status packets, the stuffed one too
    bus.clear()
    with arm.connect(bus.port, timeout=5.0, threads=False) as robot:
        delivered: list[dict[str, Any]] = []
        robot.on_output(delivered.append)
        bus.wait_for(TORQUE_PACKET, 5)
        bus.clear()
        robot.interfaces.read_joints()
        assert bus.received == request
        assert robot.state.present == tuple(positions[i] for i in IDS)
        assert robot.state.error == (0, 0, 0, 0x80, 0, 0)
        (joints,) = delivered
        assert joints["contents"]["name"] == ("waist", "shoulder", "elbow", "wrist_pitch", "wrist_roll", "gripper")
        assert joints["contents"]["position"] == pytest.approx(
            [(positions[i] - 2048) * 2 * math.pi / 4096 for i in IDS])



def test_a_bulk_read_asks_and_reads_as_the_sdk_does(bus: XBus, arm: Any) -> None:
    bus.present[1] = -123456  # a multi-turn position, to tell it from the temperature
    request, position, temperature = _sdk_bulk_read(bus)
    assert (position, temperature) == (-123456, 36)
    bus.clear()
    with arm.connect(bus.port, timeout=5.0, threads=False) as robot:
        bus.wait_for(TORQUE_PACKET, 5)
        bus.clear()
        robot.primitives.bulk_read_waist_gripper()
        assert bus.received == request
        assert request.hex(" ") == "ff ff fd 00 fe 0d 00 92 01 84 00 04 00 06 92 00 01 00 " + request[-2:].hex(" ")
        assert robot.state.present[0] == position
        assert robot.state.gripper_temperature == temperature
        assert robot.state.present[1:] == (2048,) * 5  # the others' as they were
