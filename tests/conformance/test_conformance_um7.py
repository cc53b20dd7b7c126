"""examples/um7.rdis against um7py (0.5.18), Redshift Labs' published UM7 driver, byte for byte:
um7py's own register accessors (`get_fw_revision`, `dreg_temperature`, `creg_com_rates5 = ...`)
run over a port that records what they write and answers with packets its `construct_packet`
builds; rdisc must write the same request and read the same values from the same answer. The
broadcasts are read as um7py's `decode_euler_broadcast` and `decode_health_broadcast` read them.
The runtime and the generated driver alike.

um7py is made without its constructor, which looks for a USB device by its udev properties; its
reader finds a packet's end at the next "snp", so the port gives it the next packet's preamble
after each answer, as a streaming sensor would. um7py divides the Euler broadcast's rates by
91.02222 where its own DREG_EULER_PHI_THETA_DOT accessor (and the datasheet) divides by 16: the
description follows the datasheet, and the test compares the rates so scaled.
"""

from __future__ import annotations

import struct
from pathlib import Path
from typing import Any

import pytest

um7_serial = pytest.importorskip("um7py.um7_serial")
svd = pytest.importorskip("um7py.rsl_xml_svd.rsl_svd_parser")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "um7.rdis"
PARSER = svd.RslSvdParser(svd_file=str(Path(svd.__file__).with_name("um7.svd")))
DEGREES, RATE = 91.02222, 16.0


def um7py(answer: bytes) -> Any:
    """um7py's UM7Serial on a port answering `answer`, then the next packet's preamble."""
    driver = um7_serial.UM7Serial.__new__(um7_serial.UM7Serial)
    driver.port, driver.buffer, driver.buffer_size, driver.svd_parser = ScriptedPort(answer + b"snp"), b"", 125, PARSER
    return driver


def packet(kind: int, address: int, data: bytes = b"") -> bytes:
    """A packet as um7py's construct_packet builds it: the sensor's answers are built so too."""
    return bytes(um7py(b"").construct_packet(kind, address, data))


@pytest.fixture(scope="module", params=["runtime", "driver"])
def um7(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, EXAMPLE.read_text(encoding="utf-8"), tmp_path_factory.mktemp("um7"), "um7")


def ours(um7: Any, answer: bytes, primitive: str, *args: Any) -> tuple[bytes, dict[str, Any]]:
    """What rdisc writes for a primitive answered by `answer`, and its state after."""
    port = ScriptedPort(answer)
    with um7.connect(port, threads=False) as robot:
        robot.call_primitive(primitive, *args)
        return bytes(port.written), dict(robot.state)


@pytest.mark.parametrize("revision", [b"U7A3", b"U7C1", b"ZZZZ"])
def test_the_firmware_revision(um7: Any, revision: bytes) -> None:
    answer = packet(0x80, 0xAA, revision)
    driver = um7py(answer)
    assert driver.get_fw_revision == revision.decode()
    written, state = ours(um7, answer, "get_firmware")
    assert written == bytes(driver.port.written)
    assert state["firmware"] == revision.decode()


@pytest.mark.parametrize("celsius", [21.5, -40.0, 85.25])
def test_the_temperature(um7: Any, celsius: float) -> None:
    answer = packet(0x80, 0x5F, struct.pack(">f", celsius))
    driver = um7py(answer)
    _, (temperature,) = driver.dreg_temperature
    written, state = ours(um7, answer, "get_temperature")
    assert written == bytes(driver.port.written)
    assert state["temperature"] == temperature == celsius


@pytest.mark.parametrize("health", [0, 0x1C3E0120, 0xFFFFFFFF])
def test_the_health_register(um7: Any, health: int) -> None:
    answer = packet(0x80, 0x55, health.to_bytes(4, "big"))
    driver = um7py(answer)
    register = driver.dreg_health[0]
    written, state = ours(um7, answer, "get_health")
    assert written == bytes(driver.port.written)
    assert state["health"] == register.raw_value == health


@pytest.mark.parametrize(("phi", "theta", "psi"), [(0, 0, 0), (8192, -4096, -16384), (-32768, 32767, 32767)])
def test_the_euler_angles(um7: Any, phi: int, theta: int, psi: int) -> None:
    answer = packet(0x80, 0x70, struct.pack(">hh", phi, theta))
    driver = um7py(answer)
    _, roll, pitch = driver.dreg_euler_phi_theta
    written, state = ours(um7, answer, "get_roll_pitch")
    assert written == bytes(driver.port.written)
    assert (state["roll"], state["pitch"]) == (roll / DEGREES, pitch / DEGREES) == (phi / DEGREES, theta / DEGREES)
    answer = packet(0x80, 0x71, struct.pack(">hxx", psi))
    driver = um7py(answer)
    _, (yaw,) = driver.dreg_euler_psi
    written, state = ours(um7, answer, "get_yaw")
    assert written == bytes(driver.port.written)
    assert state["yaw"] == yaw / DEGREES == psi / DEGREES


@pytest.mark.parametrize("rates", [(0, 0, 0, 0), (50, 100, 1, 255), (255, 255, 255, 255)])
def test_the_broadcast_rates_read_and_written(um7: Any, rates: tuple[int, int, int, int]) -> None:
    answer = packet(0x80, 0x05, bytes(rates))
    driver = um7py(answer)
    assert driver.creg_com_rates5[1:] == rates
    written, state = ours(um7, answer, "get_rates")
    assert written == bytes(driver.port.written)
    assert list(state["rates"]) == list(rates)
    acknowledged = packet(0x00, 0x05)
    driver = um7py(acknowledged)
    driver.creg_com_rates5 = int.from_bytes(bytes(rates), "big")
    written, state = ours(um7, acknowledged, "set_rates", *rates)
    assert written == bytes(driver.port.written)
    assert list(state["rates"]) == list(rates)


@pytest.mark.parametrize(("angles", "rates", "time"), [
    ((0, 0, 0), (0, 0, 0), 0.0),
    ((910, -1820, 16383), (16, -160, 32767), 12.5),
    ((-32768, 32767, -1), (-32768, 1, 2), 1234.75),
])
def test_the_euler_broadcast_past_another(um7: Any, angles: tuple[int, ...], rates: tuple[int, ...],
                                          time: float) -> None:
    broadcast = packet(0xD4, 0x70, struct.pack(">hhh2xhhh2xf", *angles, *rates, time))
    health = packet(0x80, 0x55, (0x1C3E0120).to_bytes(4, "big"))
    driver = um7py(b"")
    assert driver.verify_checksum(broadcast) and driver.check_packet(broadcast)
    decoded = driver.decode_euler_broadcast(broadcast)
    written, state = ours(um7, health + broadcast, "euler")
    assert written == b""
    assert (state["roll"], state["pitch"], state["yaw"], state["euler_time"]) == (
        decoded.roll, decoded.pitch, decoded.yaw, decoded.time_stamp)
    assert [state["roll_rate"], state["pitch_rate"], state["yaw_rate"]] == pytest.approx(
        [decoded.roll_rate * DEGREES / RATE, decoded.pitch_rate * DEGREES / RATE, decoded.yaw_rate * DEGREES / RATE])


@pytest.mark.parametrize("health", [0, 0x00000120, 0xFC000000])
def test_the_health_broadcast(um7: Any, health: int) -> None:
    broadcast = packet(0x80, 0x55, health.to_bytes(4, "big"))
    decoded = um7py(b"").decode_health_broadcast(broadcast)
    written, state = ours(um7, broadcast, "health_broadcast")
    assert written == b"" and state["health"] == decoded.health == health


def test_a_packet_whose_sum_is_wrong_is_refused(um7: Any) -> None:
    answer = bytearray(packet(0x80, 0x5F, struct.pack(">f", 21.5)))
    answer[-1] ^= 0x01
    with pytest.raises(um7_serial.RslException, match="checksum"):
        _ = um7py(bytes(answer)).dreg_temperature
    port = ScriptedPort(bytes(answer))
    with um7.connect(port, threads=False) as robot, pytest.raises(Exception, match="checksum") as caught:
        robot.call_primitive("get_temperature")
    assert type(caught.value).__name__ == "RdisProtocolError"
