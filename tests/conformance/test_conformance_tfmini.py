"""examples/tfmini.rdis against tfmini (0.3.2), the published TFmini driver, byte for byte:
tfmini's own TFmini class runs over a port that records what it writes and answers with the
bytes given (its pyserial `Serial`, replaced in its module): setting the standard or the Pixhawk
output format writes the three configuration commands rdisc writes, each answered as the manual
says; a measurement frame (after bytes of a frame begun before the read) is read as tfmini's
`Std.process` reads it, and a text line as its `Pix.get` does. A frame whose sum tfmini refuses
is refused, and so is a command the sensor answers with another status than 1 (tfmini's own
reading of the answer says it failed, though its `format` goes on). The runtime and the
generated driver alike.
"""

from __future__ import annotations

import struct
from pathlib import Path
from typing import Any

import pytest

driver = pytest.importorskip("tfmini.tfmini")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "tfmini.rdis"


def answer(value: int, command: int, status: int = 1) -> bytes:
    """The sensor's answer to a configuration command (TFmini manual): 42 57 02, a status, then
    the command's last four bytes."""
    return bytes([0x42, 0x57, 0x02, status, 0x00, 0x00, value, command])


def frame(centimetres: int, strength: int, mode: int = 2) -> bytes:
    """A standard-format measurement: 59 59, distance, strength, mode, spare, sum."""
    body = b"\x59\x59" + struct.pack("<HHBB", centimetres, strength, mode, 0)
    return body + bytes([sum(body) & 0xFF])


class Serial(ScriptedPort):
    """pyserial's Serial as tfmini makes it (then `open()`): the one fake port, reading the bytes
    given (its script); the writes are recorded."""

    given = b""

    def __init__(self) -> None:
        super().__init__(Serial.given)
        self.is_open = False

    def open(self) -> None:
        self.is_open = True

    def close(self) -> None:
        super().close()
        self.is_open = False

    def flushInput(self) -> None:  # pyserial's old name, which tfmini calls
        pass


def tfmini(monkeypatch: pytest.MonkeyPatch, mode: int, given: bytes) -> Any:
    """tfmini's TFmini in `mode` on a port that reads `given`."""
    monkeypatch.setattr(driver, "Serial", Serial)
    monkeypatch.setattr(Serial, "given", given)
    return driver.TFmini("/dev/ttyTF", mode=mode)


@pytest.fixture(scope="module", params=["runtime", "driver"])
def lidar(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    folder = tmp_path_factory.mktemp("tfmini")
    return implementation_of(request.param, EXAMPLE.read_text(encoding="utf-8"), folder, "tfmini")


@pytest.mark.parametrize(("mode", "interface", "value"), [(driver.TFmini.STD_MODE, "standard_output", 1),
                                                          (driver.TFmini.PIX_MODE, "pixhawk_output", 4)])
def test_setting_the_output_format_writes_tfminis_commands(lidar: Any, monkeypatch: pytest.MonkeyPatch, mode: int,
                                                           interface: str, value: int) -> None:
    answers = answer(1, 2) + answer(value, 6) + answer(0, 2)
    sensor = tfmini(monkeypatch, mode, answers)
    assert sensor.proto.serial.script == b""  # tfmini read every answer
    port = ScriptedPort(answers)
    with lidar.connect(port, threads=False) as robot:
        robot.call_interface(interface)
        assert bytes(port.written) == bytes(sensor.proto.serial.written)


def test_a_refused_command_is_refused(lidar: Any, monkeypatch: pytest.MonkeyPatch) -> None:
    sensor = tfmini(monkeypatch, driver.TFmini.STD_MODE, answer(1, 2) + answer(1, 6) + answer(0, 2))
    sensor.proto.serial.script = answer(1, 2, status=0xFF)  # tfmini's own reading of an answer: refused
    assert sensor.proto._SerialBase__sendRespond(b"\x42\x57\x02\x00\x00\x00\x01\x02") is False
    port = ScriptedPort(answer(1, 2, status=0xFF))
    with lidar.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("configure", 1, 2)
    assert type(caught.value).__name__ == "RdisProtocolError"


@pytest.mark.parametrize(("centimetres", "strength", "before"), [
    (30, 0, b""),
    (123, 2048, b"\x07\x00"),  # the end of a frame begun before the read
    (1200, 65535, b"\x59\x00"),  # a 59 that starts no header
    (745, 12, frame(999, 1)[3:]),
])
def test_a_measurement_is_read_as_tfmini_reads_it(lidar: Any, monkeypatch: pytest.MonkeyPatch, centimetres: int,
                                                 strength: int, before: bytes) -> None:
    configured = answer(1, 2) + answer(1, 6) + answer(0, 2)
    sensor = tfmini(monkeypatch, driver.TFmini.STD_MODE, configured + before + frame(centimetres, strength))
    metres = sensor.read()
    port = ScriptedPort(before + frame(centimetres, strength))
    with lidar.connect(port, threads=False) as robot:
        robot.call_primitive("measure")
        assert bytes(port.written) == b""
        assert (robot.state["distance"], robot.state["strength"]) == (metres, sensor.strength)
        assert (robot.state["distance"], robot.state["strength"]) == (centimetres / 100, strength)


def test_a_frame_whose_sum_is_wrong_is_refused(lidar: Any) -> None:
    bad = bytearray(frame(123, 2048))
    bad[-1] ^= 0x10
    with pytest.raises(Exception, match="checksum"):
        driver.Std.process(None, bytes(bad[2:]))
    port = ScriptedPort(bytes(bad))
    with lidar.connect(port, threads=False) as robot, pytest.raises(Exception, match="checksum") as caught:
        robot.call_primitive("measure")
    assert type(caught.value).__name__ == "RdisProtocolError"


@pytest.mark.parametrize("text", [b"0.30", b"1.23", b"11.99"])
def test_a_pixhawk_line_is_read_as_tfmini_reads_it(lidar: Any, monkeypatch: pytest.MonkeyPatch, text: bytes) -> None:
    configured = answer(1, 2) + answer(4, 6) + answer(0, 2)
    sensor = tfmini(monkeypatch, driver.TFmini.PIX_MODE, configured + text + b"\r\n" + b"9.99\r\n")
    metres = sensor.read()
    port = ScriptedPort(text + b"\r\n")
    with lidar.connect(port, threads=False) as robot:
        robot.call_primitive("measure_text")
        assert robot.state["distance"] == metres == float(text)
