"""A VESC frame as rdisc writes and reads it is the one pyvesc (1.0.5) frames and unframes.

Why: VESC's framing has two layouts, 02 LEN (a payload up to 255 bytes) and 03 LEN LEN (a
longer one), both followed by the payload's CRC16-XMODEM big-endian and 03. The description
says it with `either`; pyvesc's `frame`/`unframe` are the published reading of the firmware's
packet.c. Both the runtime and the generated driver are checked, at the sizes around the switch.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

with warnings.catch_warnings():  # pyvesc compares ints with `is`: a SyntaxWarning on compiling it
    warnings.simplefilter("ignore", SyntaxWarning)
    codec = pytest.importorskip("pyvesc.packet.codec")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

DESCRIPTION = """\
robot vesc { author "tests" }
state command: int = 0
state size: int = 0
connection uart: serial { baud 115200 }
frame vesc {
    either { header "\\x02"  length "B" = payload } or { header "\\x03"  length ">H" = payload }
    payload  checksum "crc16-xmodem" ">H" over payload  terminator "\\x03"
}
primitive send(data: bytes in 0..1000) on uart frame vesc pack "*" (data)
primitive receive() on uart frame vesc pack "B" (0) unpack "B*" { command = out[0]  size = len(out[1]) }
"""
SIZES = [1, 2, 100, 254, 255, 256, 257, 300, 1000]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_requests_are_framed_as_pyvesc_frames_them(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, DESCRIPTION, tmp_path, "vesc").connect(port, threads=False) as robot:
        for size in SIZES:
            data = bytes((i * 7 + size) & 0xFF for i in range(size))
            port.written.clear()
            robot.call_primitive("send", data)
            assert bytes(port.written) == codec.frame(data), size


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_replies_pyvesc_frames_are_read(kind: str, tmp_path: Path) -> None:
    payloads = [bytes([4 + size % 50]) + bytes(size - 1) for size in SIZES]
    script = b"".join(codec.frame(p) for p in payloads)
    assert [codec.unframe(codec.frame(p))[0] for p in payloads] == payloads
    port = ScriptedPort(script)
    with implementation_of(kind, DESCRIPTION, tmp_path, "vesc").connect(port, threads=False) as robot:
        for payload in payloads:
            robot.call_primitive("receive")
            assert (robot.state["command"], robot.state["size"]) == (payload[0], len(payload) - 1)
