"""Six emulated Dynamixel X-series servos (protocol 2.0, ROBOTIS e-Manual) on one pty bus.

The bus answers from the protocol as the e-Manual states it, with its own CRC-16/BUYPASS
(`_crc`, bit by bit) and byte stuffing, not with rdisc's or dynamixel-sdk's code: a sync
read of Present Position is answered by each servo in the order asked, with its status
packet, and so is a bulk read of Present Position or Present Temperature, each servo its own
address and length; everything else (sync writes) is taken without an answer, as the servos do.
"""

from __future__ import annotations

import struct

from . import PtyDevice

IDS = [1, 2, 3, 4, 5, 6]
PRESENT = 132  # Present Position's address
TEMPERATURE = 146  # Present Temperature's address (1 byte)
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
        self.present = {1: 0, 2: 1024, 3: 2048, 4: 3071, 5: 4095, 6: STUFFED}  # each servo's, by ID
        self.errors = {i: 0 for i in IDS}
        self.errors[4] = 0x80  # a hardware alert: reported, the data still valid
        self.temperatures = {i: 30 + i for i in IDS}
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
            elif packet[7] == 0x92:  # bulk read: ID, start, length for each servo
                for at in range(8, size - 2, 5):
                    dxl_id, start, length = struct.unpack_from("<BHH", packet, at)
                    data = struct.pack("<i", self.present[dxl_id]) if start == PRESENT else \
                        bytes([self.temperatures[dxl_id]])
                    assert (start, length) in ((PRESENT, 4), (TEMPERATURE, 1))
                    self.send(status(dxl_id, self.errors[dxl_id], data))

    def _cleared(self) -> None:
        self._pending.clear()


def sync_goals(received: bytes) -> list[list[int]]:
    """The goals of each sync write of Goal Position (0x83 at 116, 4 bytes) among the Dynamixel
    packets `received` (FF FF FD 00, ID, length, instruction, parameters, CRC)."""
    goals: list[list[int]] = []
    at = received.find(b"\xff\xff\xfd\x00")
    while 0 <= at and at + 7 <= len(received):
        size = int.from_bytes(received[at + 5:at + 7], "little") + 7
        packet = received[at:at + size]
        if packet[7] == 0x83 and packet[8:12] == bytes([116, 0, 4, 0]):
            goals.append([int.from_bytes(packet[i + 1:i + 5], "little", signed=True) for i in range(12, size - 2, 5)])
        at = received.find(b"\xff\xff\xfd\x00", at + size)
    return goals
