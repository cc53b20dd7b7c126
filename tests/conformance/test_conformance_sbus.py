"""examples/sbus.rdis against rfrx (2.1.2), a published S.BUS receiver driver, byte for byte: the
frames rdisc writes are decoded by rfrx's `SbusDecoder` into the channels and flags they were
written with, and the frames it decodes (built here as the protocol packs them, sixteen 11-bit
channels from the lowest bit up, `<22s{11*16}`) are read into the channels and flags it gives;
a frame whose header or footer it refuses is read past. rfrx decodes and never encodes, so the
frames come from both sides. The runtime and the generated driver alike.
"""

from __future__ import annotations

import random
from pathlib import Path
from typing import Any

import pytest

sbus = pytest.importorskip("rfrx.sbus")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "sbus.rdis"
_draw = random.Random(23)
CHANNELS = [[992] * 16, [172] * 16, [1811] * 16, [0] * 16, [2047] * 16, [0, 2047] * 8,
            list(range(172, 1772, 100)), *([_draw.randrange(2048) for _ in range(16)] for _ in range(5))]
FLAGS = [(bool(n & 8), bool(n & 4), bool(n & 2), bool(n & 1)) for n in range(16)]  # ch17, ch18, lost, failsafe


def frame(channels: list[int], ch17: bool, ch18: bool, lost: bool, safe: bool, footer: int = 0) -> bytes:
    """An S.BUS frame as the protocol packs it, its flags where rfrx reads them."""
    packed = sum(value << (11 * i) for i, value in enumerate(channels)).to_bytes(22, "little")
    return b"\x0f" + packed + bytes([ch17 << 7 | ch18 << 6 | lost << 5 | safe << 4, footer])


def decoded(data: bytes) -> tuple[list[int], tuple[bool, bool, bool, bool]]:
    """rfrx's reading: the channels, and its flags (each the bit's value, 0 when clear) as bools."""
    reading = sbus.SbusDecoder(data)
    return reading.chans, (bool(reading.ch17), bool(reading.ch18), bool(reading.frame_lost), bool(reading.failsafe))


@pytest.fixture(scope="module", params=["runtime", "driver"])
def described(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, EXAMPLE.read_text(encoding="utf-8"), tmp_path_factory.mktemp("sbus"),
                             "sbus")


def _read(described: Any, data: bytes) -> tuple[list[int], tuple[bool, bool, bool, bool]]:
    with described.connect(ScriptedPort(data), threads=False) as robot:
        robot.call_primitive("read")
        state = robot.state
        return list(state["channels"]), (state["channel17"], state["channel18"], state["frame_lost"],
                                         state["failsafe"])


@pytest.mark.parametrize("channels", CHANNELS)
@pytest.mark.parametrize("flags", [FLAGS[0], FLAGS[5], FLAGS[10], FLAGS[15]])
def test_a_written_frame_is_what_rfrx_decodes(described: Any, channels: list[int],
                                              flags: tuple[bool, bool, bool, bool]) -> None:
    port = ScriptedPort()
    with described.connect(port, threads=False) as robot:
        robot.call_primitive("write", channels, *flags)
    assert len(port.written) == 25
    assert decoded(bytes(port.written)) == (channels, flags)


@pytest.mark.parametrize("channels", CHANNELS)
def test_a_frame_is_read_as_rfrx_decodes_it(described: Any, channels: list[int]) -> None:
    data = frame(channels, *FLAGS[9])
    assert _read(described, data) == decoded(data) == (channels, FLAGS[9])


@pytest.mark.parametrize("flags", FLAGS)
def test_every_flag(described: Any, flags: tuple[bool, bool, bool, bool]) -> None:
    data = frame(CHANNELS[6], *flags)
    assert _read(described, data) == decoded(data) == (CHANNELS[6], flags)


def test_a_frame_joined_midway_is_read_past(described: Any) -> None:
    first, second = frame(CHANNELS[7], *FLAGS[3]), frame(CHANNELS[8], *FLAGS[12])
    with pytest.raises(sbus.SbusError, match="Wrong"):  # rfrx reads 25 bytes where they fall, and refuses them
        decoded((first[11:] + second)[:25])
    assert _read(described, first[11:] + second) == decoded(second) == (CHANNELS[8], FLAGS[12])


def test_a_frame_with_a_wrong_footer_is_refused_by_both(described: Any) -> None:
    data = frame(CHANNELS[0], *FLAGS[0], footer=0x04)
    with pytest.raises(sbus.SbusError, match="Wrong end byte"):
        decoded(data)
    with described.connect(ScriptedPort(data), threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("read")
    assert type(caught.value).__name__ == "RdisTimeout"  # read past: no frame within the timeout
    assert list(robot.state["channels"]) == [0] * 16
