"""The emulated devices themselves, through pyserial on their ptys."""

from __future__ import annotations

import os
import time

import pytest
import serial

from devices import CreateEmulator, KoalaEmulator, pty_device


def open_port(dev, timeout: float = 0.5) -> serial.Serial:
    return serial.serial_for_url(dev.port, baudrate=57600, timeout=timeout)


def test_pty_device_echoes_through_a_handler() -> None:
    with pty_device(lambda data: data.upper()) as dev:
        port = open_port(dev)
        try:
            port.write(b"abc")
            assert port.read(3) == b"ABC"
            assert dev.wait_for(3) == b"abc"
        finally:
            port.close()


def test_create_answers_the_bumper_query_and_records_commands() -> None:
    with CreateEmulator() as dev:
        port = open_port(dev)
        try:
            port.write(bytes([128, 132, 137, 0, 200, 0x7F, 0xFF]))
            dev.wait_for_commands(3)
            assert dev.opcodes() == [128, 132, 137]
            assert dev.drives() == [(200, 32767)]
            assert dev.oi_mode == "full"
            dev.bumpers = 3
            port.write(bytes([142, 7]))
            assert port.read(1) == b"\x03"
            dev.sensors[25] = 0x1234
            port.write(bytes([142, 25]))
            assert port.read(2) == b"\x12\x34"
        finally:
            port.close()


@pytest.mark.parametrize(("mode", "expected"), [("silent", b""), ("short", b"\x12")])
def test_create_fault_modes(mode: str, expected: bytes) -> None:
    with CreateEmulator(mode=mode) as dev:
        dev.sensors[25] = 0x1234
        port = open_port(dev, timeout=0.2)
        try:
            port.write(bytes([142, 25]))
            assert port.read(2) == expected
        finally:
            port.close()


def test_create_wait_for_times_out_with_what_it_got() -> None:
    with CreateEmulator() as dev, pytest.raises(TimeoutError, match="1 bytes"):
        dev.wait_for(1, timeout=0.05)


def test_koala_answers_each_command() -> None:
    with KoalaEmulator() as dev:
        port = open_port(dev)
        try:
            port.write(b"D,10,-20\n")
            assert port.read_until(b"\n") == b"d\r\n"
            assert dev.speeds == (10, -20)
            port.write(b"E\n")
            assert port.read_until(b"\n") == b"e,10,-20\r\n"
            dev.counters = (5, 6)
            port.write(b"H\n")
            assert port.read_until(b"\n") == b"h,5,6\r\n"
            port.write(b"G,0,0\n")
            assert port.read_until(b"\n") == b"g\r\n"
            dev.proximity[3] = 700
            port.write(b"N\n")
            assert port.read_until(b"\n") == b"n,0,0,0,700" + b",0" * 12 + b"\r\n"
            assert dev.lines == ["D,10,-20", "E", "H", "G,0,0", "N"]
            assert dev.counters == (0, 0)
        finally:
            port.close()


@pytest.mark.parametrize(("mode", "expected"), [("silent", b""), ("garbage", b"#?garbage!\r\n"), ("unterminated", b"e,0,0")])
def test_koala_fault_modes(mode: str, expected: bytes) -> None:
    with KoalaEmulator(mode=mode) as dev:
        port = open_port(dev, timeout=0.2)
        try:
            port.write(b"E\n")
            assert port.read_until(b"\n") == expected
        finally:
            port.close()


def test_slow_device_answers_late() -> None:
    with KoalaEmulator(reply_delay=0.2) as dev:
        port = open_port(dev, timeout=1.0)
        try:
            start = time.monotonic()
            port.write(b"E\n")
            assert port.read_until(b"\n") == b"e,0,0\r\n"
            assert time.monotonic() - start >= 0.18
        finally:
            port.close()


def test_closing_the_master_breaks_the_port() -> None:
    with CreateEmulator() as dev:
        port = open_port(dev)
        try:
            dev.close_master()
            with pytest.raises((serial.SerialException, OSError)):
                port.write(bytes([142, 7]))
                port.read(1)
        finally:
            port.close()


def test_leaving_the_block_closes_every_descriptor() -> None:
    before = len(os.listdir("/proc/self/fd"))
    for _ in range(3):
        with KoalaEmulator():
            pass
    assert len(os.listdir("/proc/self/fd")) == before
