"""An input reads a sensor (thesis §7.2.4): the sensor is read through its primitive first when
its cached value is older than its cache time, and not at all within it, in the runtime and a
generated driver alike (exact bytes on a scripted port, the robot's clock the test's)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_text
from rdisc.emit.python import import_driver
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

DESCRIPTION = """\
robot lift { author "tests" }
connection port: serial { baud 115200 }
/// The platform's height above its lowest, in mm.
primitive level() on port pack "B" (1) unpack "B" { }
sensor height: int from level() cache 100 ms
primitive go(speed: int in 0..255) on port pack "BB" (2, speed)
interface move(v: float) { go(clamp(round(v * 100), 0, 255)) }
/// Slower the higher the platform stands: the speed less a tenth of the height.
input drive: DifferentialSpeed -> move(linear - height / 1000.0)
"""


class Clock:
    def __init__(self) -> None:
        self.now = 10.0

    def __call__(self) -> float:
        return self.now


@pytest.fixture(params=["runtime", "driver"])
def opened(request: pytest.FixtureRequest, tmp_path: Path) -> Any:
    source = tmp_path / "lift.rdis"
    source.write_text(DESCRIPTION, encoding="utf-8")
    made = load(source) if request.param == "runtime" else import_driver(source, tmp_path, "lift_driver")
    port = ScriptedPort(b"\x32" * 3)  # each level() answers 50 mm
    clock = Clock()
    robot = made.connect(port, threads=False)
    robot._clock = clock
    yield robot, port, clock
    robot.close()


def test_the_checker_lets_an_input_read_a_sensor() -> None:
    compilation = compile_text("lift.rdis", DESCRIPTION)
    assert compilation.diagnostics.items == []


def test_an_input_reads_its_sensor_once_per_cache_time(opened: Any) -> None:
    robot, port, clock = opened
    robot.call_input("drive", linear=0.5, angular=0.0)  # reads the height (50 mm): 0.5 - 0.05 = 0.45 m/s
    assert bytes(port.written) == bytes([1]) + bytes([2, 45])
    clock.now += 0.05  # within the cache time: no read
    robot.call_input("drive", linear=0.3, angular=0.0)
    assert bytes(port.written) == bytes([1, 2, 45, 2, 25])
    clock.now += 0.2  # stale: read again first
    robot.call_input("drive", linear=0.3, angular=0.0)
    assert bytes(port.written) == bytes([1, 2, 45, 2, 25, 1, 2, 25])
    assert robot.sensor_age("height") == 0.0


def test_a_failed_read_raises_and_writes_no_command(opened: Any) -> None:
    robot, port, _ = opened
    port.script = b""  # the device says nothing to level()
    with pytest.raises(Exception, match=r"^level: no reply within 1 s$") as raised:
        robot.call_input("drive", linear=0.5, angular=0.0)
    assert type(raised.value).__name__ == "RdisTimeout"  # the driver's own class, or the engine's
    assert bytes(port.written) == bytes([1])  # the read only: no stale or missing value drives it
