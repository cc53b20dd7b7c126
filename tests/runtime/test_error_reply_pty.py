"""A Modbus RTU server's exception over a real pty (examples/modbus.rdis): the server answers
the first read with 01 83 02 C0 F1 (the Modbus specification's example) and the second with its
registers; the first is an RdisDeviceError with the code and its name, written once (not
retried), the second is read from its first byte. The runtime and the generated driver alike."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load
from tests.devices import pty_device

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "modbus.rdis"
REQUEST = bytes.fromhex("01 03 00 6B 00 02 B5 D7")  # unit 1 reads 2 registers from 0x6B
EXCEPTION = bytes.fromhex("01 83 02 C0 F1")  # ILLEGAL DATA ADDRESS
REPLY = bytes.fromhex("01 03 04 00 01 00 02 2A 32")


@pytest.fixture(params=["runtime", "driver"])
def connect(request: pytest.FixtureRequest, tmp_path: Path) -> tuple[Callable[[str], Any], type[Exception]]:
    if request.param == "runtime":
        return (lambda port: load(EXAMPLE).connect(port, timeout=5.0, threads=False)), errors.RdisDeviceError
    driver = import_driver(EXAMPLE, tmp_path, "modbus_driver")
    return (lambda port: driver.connect(port, timeout=5.0, threads=False)), driver.RdisDeviceError


def test_an_exception_then_a_reply(connect: tuple[Callable[[str], Any], type[Exception]]) -> None:
    make, device_error = connect
    answers = [EXCEPTION, REPLY]
    with pty_device(lambda data: answers.pop(0)) as dev, make(dev.port) as robot:
        with pytest.raises(device_error) as caught:
            robot.call_primitive("read_holding", 0x6B)
        assert str(caught.value) == "read_holding: the device answered error 2 (ILLEGAL_DATA_ADDRESS)"
        assert (caught.value.code, caught.value.name) == (2, "ILLEGAL_DATA_ADDRESS")
        assert dev.wait_for(len(REQUEST)) == REQUEST
        robot.call_primitive("read_holding", 0x6B)
        assert robot.state["holding"] == (1, 2)
        assert dev.received == REQUEST * 2 and answers == []
