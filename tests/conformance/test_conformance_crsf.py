"""examples/crsf.rdis against two published CRSF drivers, byte for byte, the runtime and the
generated driver alike.

rpycrsf (0.1.0) for the RC channels: the frames rdisc writes are the ones `pack_rc_channels`
builds (sixteen 11-bit channels packed into 22 bytes, `<22s{11*16}`, the first in the lowest bits;
CRC-8/DVB-S2 over type and payload), the ones its `Drone` writes on a pseudo-terminal for its
sticks and switches are the `sticks` interface's, and the channels `unpack_rc_channels` reads
are the ones rdisc reads. crsf-parser (0.3.2) for the telemetry: the link statistics and battery
frames (its 24-bit capacity, `>3s{24}`) that `crsf_build_frame` builds are read into the values
its `CRSFParser` gives, past frames of other types; a frame whose CRC it counts as an error is an
RdisProtocolError. crsf-parser packs the channels in the reverse order (its first channel in the
highest bits): a test says so.
"""

from __future__ import annotations

import os
import random
from pathlib import Path
from typing import Any

import pytest

crsf = pytest.importorskip("crsf_parser")
rpycrsf = pytest.importorskip("rpycrsf")

from crsf_parser.handling import crsf_build_frame
from crsf_parser.payloads import PacketsTypes
from rpycrsf import protocol

from tests.engine.test_one_engine import ScriptedPort, implementation_of

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "crsf.rdis"
_draw = random.Random(23)
CHANNELS = [
    [992] * 16,  # centred
    [172] * 16,  # -100 %
    [1811] * 16,  # +100 %
    [0] * 16,
    [2047] * 16,  # every bit set
    [0, 2047] * 8,
    list(range(172, 1772, 100)),
    *([_draw.randrange(2048) for _ in range(16)] for _ in range(5)),
]
STATE = {"uplink_rssi_ant_1": "uplink_rssi_1", "uplink_rssi_ant_2": "uplink_rssi_2",
         "uplink_link_quality": "uplink_quality", "uplink_snr": "uplink_snr", "diversity_active_antenna": "antenna",
         "rf_mode": "rf_mode", "uplink_tx_power": "tx_power", "downlink_rssi": "downlink_rssi",
         "downlink_link_quality": "downlink_quality", "downlink_snr": "downlink_snr"}  # crsf-parser's names: ours
STATE_NAMES = list(STATE)
LINKS = [dict(zip(STATE_NAMES, values, strict=True)) for values in [
    (80, 90, 100, -5, 1, 2, 3, 70, 99, 7),
    (0, 255, 0, -128, 0, 0, 6, 255, 0, 127),  # each field's ends
]]
BATTERIES = [{"voltage": 168, "current": 123, "capacity": 0x123456, "remaining": 77},
             {"voltage": 0, "current": 65535, "capacity": 0xFFFFFF, "remaining": 100},
             {"voltage": 252, "current": 0, "capacity": 0, "remaining": 0}]


@pytest.fixture(scope="module", params=["runtime", "driver"])
def described(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, EXAMPLE.read_text(encoding="utf-8"), tmp_path_factory.mktemp("crsf"),
                             "crsf")


def parsed(data: bytes) -> list[tuple[Any, Any]]:
    """What crsf-parser's stream parser makes of the bytes: (frame, status) each."""
    frames: list[tuple[Any, Any]] = []
    crsf.CRSFParser(lambda frame, status: frames.append((frame, status))).parse_stream(bytearray(data))
    return frames


@pytest.mark.parametrize("channels", CHANNELS)
def test_channels_are_packed_as_rpycrsf_packs_them(described: Any, channels: list[int]) -> None:
    port = ScriptedPort()
    with described.connect(port, threads=False) as robot:
        robot.call_primitive("send_channels", channels)
    assert bytes(port.written) == protocol.pack_rc_channels(channels)


@pytest.mark.parametrize("channels", CHANNELS)
def test_channels_are_read_as_rpycrsf_reads_them(described: Any, channels: list[int]) -> None:
    data = protocol.pack_rc_channels(channels)
    with described.connect(ScriptedPort(data), threads=False) as robot:
        robot.call_primitive("read_channels")
        assert list(robot.state["channels"]) == protocol.unpack_rc_channels(data[3:-1]) == channels


def test_crsf_parser_packs_the_channels_in_the_reverse_order() -> None:
    channels = list(range(100, 1700, 100))
    built = bytes(crsf_build_frame(PacketsTypes.RC_CHANNELS_PACKED, {"channels": channels}))
    assert built == protocol.pack_rc_channels(channels[::-1])  # its channel 1 where the others put channel 16


SETTINGS = [  # (roll, pitch, yaw, throttle, armed, angle, althold)
    (0.0, 0.0, 0.0, 0.0, False, False, False),
    (1.0, -1.0, 0.5, 1.0, True, True, True),  # 1811.5 rounds to 1812, as Python rounds it
    (-0.25, 0.75, -1.0, 0.5, True, False, True),
    (0.1, 0.2, 0.3, 0.4, False, True, False),
]


@pytest.mark.parametrize("setting", SETTINGS)
def test_sticks_and_switches_are_the_drones(described: Any, setting: tuple[Any, ...]) -> None:
    roll, pitch, yaw, throttle, armed, angle, althold = setting
    end, other = os.openpty()
    drone = rpycrsf.Drone(os.ttyname(other), auto_start=False)  # no thread: one frame a send()
    try:
        drone.set_sticks(roll=roll, pitch=pitch, yaw=yaw, throttle=throttle)
        drone.arm(armed)
        drone.set_mode(angle)
        drone.set_althold(althold)
        drone.send()
        theirs = os.read(end, 100)
    finally:
        drone.ser.close()
        os.close(end)
        os.close(other)
    port = ScriptedPort()
    with described.connect(port, threads=False) as robot:
        robot.call_interface("sticks", *setting)
    assert bytes(port.written) == theirs


def test_a_channel_past_11_bits_is_refused(described: Any) -> None:
    port = ScriptedPort()
    with described.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("send_channels", [992] * 15 + [2048])
    assert type(caught.value).__name__ == "RdisValueError" and port.written == b""


@pytest.mark.parametrize("link", LINKS)
def test_link_statistics_are_read_past_other_frames(described: Any, link: dict[str, int]) -> None:
    data = bytes(crsf_build_frame(PacketsTypes.LINK_STATISTICS, link))
    before = bytes(crsf_build_frame(PacketsTypes.BATTERY_SENSOR, BATTERIES[0]))  # another type: read past
    [(_, _), (frame, status)] = parsed(before + data)
    assert status is crsf.PacketValidationStatus.VALID
    with described.connect(ScriptedPort(before + data), threads=False) as robot:
        robot.call_primitive("link_statistics")
        assert {name: robot.state[ours] for name, ours in STATE.items()} == {
            name: int(frame.payload[name]) for name in STATE} == link


@pytest.mark.parametrize("battery", BATTERIES)
def test_the_battery_sensor_and_its_24_bit_capacity(described: Any, battery: dict[str, int]) -> None:
    data = bytes(crsf_build_frame(PacketsTypes.BATTERY_SENSOR, battery))
    [(frame, _)] = parsed(data)
    with described.connect(ScriptedPort(data), threads=False) as robot:
        robot.call_primitive("battery")
        state = robot.state
        assert (state["voltage"], state["current"], state["capacity"], state["remaining"]) == (
            frame.payload.voltage / 10, frame.payload.current / 10, frame.payload.capacity, frame.payload.remaining)
        assert (state["capacity"], state["remaining"]) == (battery["capacity"], battery["remaining"])


def test_a_wrong_crc_is_refused_by_both(described: Any) -> None:
    data = bytearray(crsf_build_frame(PacketsTypes.LINK_STATISTICS, LINKS[0]))
    data[-1] ^= 0x01
    [(_, status)] = parsed(bytes(data))
    assert status is crsf.PacketValidationStatus.CRC
    with described.connect(ScriptedPort(bytes(data)), threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("link_statistics")
    assert type(caught.value).__name__ == "RdisProtocolError" and "checksum" in str(caught.value)
    assert robot.state["uplink_quality"] == 0
