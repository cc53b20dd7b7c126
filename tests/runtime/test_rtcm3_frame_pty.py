"""An RTCM 3 frame over a real pty: preamble D3, 6 reserved bits and a 10-bit length, the
payload, then the CRC-24Q of all of them as three big-endian bytes (`">3s{24}"`, one integer of
three bytes). The vector is message 1005 (a base station's position), as u-blox's ubxlib holds it
in its GNSS decoder tests (gnss/test/u_gnss_dec_test.c, taken from SparkFun's
Example_RTCM_Binary_Output.txt): written byte for byte, read back, and a corrupt CRC refused; the
runtime and the generated driver alike."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load
from tests.devices import pty_device

DESCRIPTION = """\
robot rtcm { author "tests" }
connection gnss: serial { baud 115200 }
state station: int = 0
state kind: int = 0
state position: int = 0
/// RTCM 3: D3, six reserved bits and the payload's length in ten, the payload, its CRC-24Q.
frame rtcm3 {
    header "\\xD3"  bits ">H" { length: 10 = payload  field reserved: 6 = 0 }
    payload  checksum "crc24-lte-a" ">3s{24}" over header .. payload
}
/// Message 1005: its number and station in twelve bits each, then 16 bytes of position.
primitive base(x: int in 0..0xFFFFFFFFFFFFFFFF) on gnss frame rtcm3 \
pack ">3s{12,12}QQ" (0, 1005, x, 0xDECABC0980351031) \
unpack ">3s{12,12}QQ" { station = out[0]  kind = out[1]  position = out[2] }
"""
MESSAGE_1005 = bytes.fromhex("D3 00 13 3E D0 00 03 3C FF 55 48 17 B5 02 DE CA BC 09 80 35 10 31 09 FA 3C")
X = 0x033CFF554817B502


@pytest.fixture(params=["runtime", "driver"])
def connect(request: pytest.FixtureRequest, tmp_path: Path) -> tuple[Callable[[str], Any], type[Exception]]:
    source = tmp_path / "rtcm.rdis"
    source.write_text(DESCRIPTION)
    if request.param == "runtime":
        return (lambda port: load(source).connect(port, timeout=5.0, threads=False)), errors.RdisProtocolError
    driver = import_driver(source, tmp_path, "rtcm_driver")
    return (lambda port: driver.connect(port, timeout=5.0, threads=False)), driver.RdisProtocolError


def test_message_1005_is_written_and_read_with_its_crc24q(connect: tuple[Callable[[str], Any],
                                                                         type[Exception]]) -> None:
    make, protocol_error = connect
    corrupt = MESSAGE_1005[:-1] + bytes([MESSAGE_1005[-1] ^ 0x01])
    answers = [MESSAGE_1005, corrupt]
    received = bytearray()

    def answer(chunk: bytes) -> bytes | None:
        received.extend(chunk)
        if len(received) % len(MESSAGE_1005):
            return None
        return answers.pop(0)

    with pty_device(answer) as dev, make(dev.port) as robot:
        robot.call_primitive("base", X)
        assert dev.wait_for(len(MESSAGE_1005)) == MESSAGE_1005
        assert (robot.state["station"], robot.state["kind"], robot.state["position"]) == (0, 1005, X)
        with pytest.raises(protocol_error) as caught:
            robot.call_primitive("base", X)
        assert str(caught.value) == ("base: rtcm3: checksum 09 fa 3d does not match the reply, "
                                     "which sums to 09 fa 3c")
        assert dev.received == MESSAGE_1005 * 2 and answers == []
