"""examples/arm.rdis against ROBOTIS's published dynamixel-sdk, byte for byte, over real ptys.

An emulated bus of six X-series servos (protocol 2.0) sits on a pty. dynamixel-sdk's
GroupSyncWrite and GroupSyncRead talk to it, and so do the rdisc runtime and the driver
`rdisc emit-python` generates: every packet they write must be the SDK's, and the positions
they read from the same status packets must be the ones the SDK's getData returns.

The bus answers from the protocol as the e-Manual states it, with its own CRC-16/BUYPASS
(`_crc`, bit by bit) and byte stuffing, not with rdisc's or the SDK's code; one servo's present
position is a multi-turn value whose bytes hold FF FF FD, so its status packet is stuffed.
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
from devices import PtyDevice

from rdisc.emit.python import import_driver
from rdisc.runtime import load

ROOT = Path(__file__).resolve().parents[2]
DESCRIPTION = ROOT / "examples" / "arm.rdis"
IDS = [1, 2, 3, 4, 5, 6]
GOAL, PRESENT, TORQUE = 116, 132, 64
TORQUE_PACKET = 26  # bytes of the sync write of six 1-byte values the startup hook sends
STUFFED = -33554688  # 0xFDFFFF00 as int32: little-endian 00 FF FF FD


def _crc(data: bytes) -> int:
    """CRC-16/BUYPASS (poly 0x8005, init 0, no reflection): the e-Manual's packet CRC."""
    crc = 0
    for byte in data:
        crc ^= byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x8005) if crc & 0x8000 else crc << 1
            crc &= 0xFFFF
    return crc


def _stuffed(body: bytes) -> bytes:
    """An FD after every FF FF FD past the header."""
    out = bytearray(body[:4])
    for byte in body[4:]:
        out.append(byte)
        if out[-3:] == b"\xff\xff\xfd" and len(out) > 4 + 2:
            out.append(0xFD)
    return bytes(out)


def status(dxl_id: int, error: int, data: bytes) -> bytes:
    """A status packet: FF FF FD 00 ID LEN 55 ERR DATA CRC, LEN and CRC over the stuffed packet."""
    params = _stuffed(b"\xff\xff\xfd\x00" + bytes([dxl_id, 0, 0, 0x55, error]) + data)[9:]
    body = b"\xff\xff\xfd\x00" + bytes([dxl_id]) + struct.pack("<H", len(params) + 4) + b"\x55" + bytes([error]) + params
    return body + struct.pack("<H", _crc(body))


class XBus(PtyDevice):
    """Six X-series servos on one bus: a sync read is answered by each, in the order asked."""

    def __init__(self) -> None:
        super().__init__()
        self.present = {1: 0, 2: 1024, 3: 2048, 4: 3071, 5: 4095, 6: STUFFED}
        self.errors = {i: 0 for i in IDS}
        self.errors[4] = 0x80  # a hardware alert: reported, the data still valid
        self._pending = bytearray()

    def handle(self, data: bytes) -> None:
        self._pending += data
        while len(self._pending) >= 10:
            size = struct.unpack_from("<H", self._pending, 5)[0] + 7
            if len(self._pending) < size:
                return
            packet, self._pending = bytes(self._pending[:size]), self._pending[size:]
            if packet[7] == 0x82:  # sync read: start, length, IDs
                start, length = struct.unpack_from("<HH", packet, 8)
                assert (start, length) == (PRESENT, 4)
                for dxl_id in packet[12:-2]:
                    self.send(status(dxl_id, self.errors[dxl_id], struct.pack("<i", self.present[dxl_id])))

    def _cleared(self) -> None:
        self._pending.clear()


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

