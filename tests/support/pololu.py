"""Pololu's CRC-7 as its guides print it in C (Maestro section 5.d, Motoron "Cyclic redundancy
check"): polynomial 0x91, least significant bit first. The tests' reference, written apart from
rdisc's catalogue so the two can disagree."""

from __future__ import annotations


def crc7(data: bytes) -> int:
    crc = 0
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc ^ 0x91) >> 1 if crc & 1 else crc >> 1
    return crc
