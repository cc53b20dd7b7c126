"""examples/koala.rdis through the runtime, against the emulated Koala (ASCII lines)."""

from __future__ import annotations

import math

import pytest
from devices import KoalaEmulator
from runtime_support import KOALA, Recorder

from rdisc.runtime import load


@pytest.fixture
def koala():
    with KoalaEmulator() as dev:
        outputs, errors = Recorder(), Recorder()
        robot = load(KOALA).connect(dev.port, on_output=outputs, on_error=errors)
        try:
            yield dev, robot, outputs, errors
        finally:
            robot.close()
            dev.wait_for_lines(2, prefix="D,0,0")  # startup's, then terminate's
        assert errors.snapshot() == []


def test_startup_stops_and_zeroes_the_counters(koala) -> None:
    dev, _, _, _ = koala
    assert dev.wait_for_lines(2)[:2] == ["D,0,0", "G,0,0"]


@pytest.mark.parametrize(("linear", "angular", "line"), [
    (0.2, 0.0, "D,44,44"),        # 0.2 / 0.0045 = 44.4
    (0.2, 0.5, "D,27,62"),        # (0.2 -+ 0.5 * 0.32 / 2) / 0.0045
    (0.0, -1.0, "D,36,-36"),
    (2.0, 0.0, "D,127,127"),      # limited to maxSpeed
])
def test_set_velocity_writes_one_ascii_line(koala, linear, angular, line) -> None:
    dev, robot, _, _ = koala
    robot.call_input("set_velocity", linear=linear, angular=angular)
    assert dev.wait_for_lines(1, prefix="D,")[-1] == line
    assert dev.speeds == tuple(int(v) for v in line[2:].split(","))


def test_periodic_reads_update_state_and_report_odometry(koala) -> None:
    dev, robot, outputs, _ = koala
    dev.speeds = (10, 20)
    dev.counters = (1000, 1000)  # 4.5 cm straight ahead
    def moved(o: dict) -> bool:  # a tick whose two reads both came after the change
        return o["name"] == "odometry" and o["contents"]["x"] > 0 and o["contents"]["linear"] > 0

    odometry = outputs.wait(lambda items: any(moved(o) for o in items))
    last = next(o for o in odometry if moved(o))["contents"]
    assert last["x"] == pytest.approx(0.045)
    assert last["y"] == pytest.approx(0.0, abs=1e-12)
    assert last["theta"] == pytest.approx(0.0, abs=1e-12)
    assert last["linear"] == pytest.approx(15 * 0.0045)
    assert last["angular"] == pytest.approx(10 * 0.0045 / 0.32)
    assert robot.state["leftCount"] == 1000
    assert list(last) == ["x", "y", "theta", "linear", "angular"]


def test_a_turn_on_the_spot_changes_only_the_heading(koala) -> None:
    dev, robot, outputs, _ = koala
    dev.counters = (-1000, 1000)
    outputs.wait(lambda items: robot.state["rightCount"] == 1000 and items[-1]["name"] == "obstacle")
    assert robot.state["odomTheta"] == pytest.approx(2 * 1000 * 0.000045 / 0.32)
    assert math.hypot(robot.state["odomX"], robot.state["odomY"]) == pytest.approx(0.0, abs=1e-12)


def test_proximity_reports_an_obstacle(koala) -> None:
    dev, _, outputs, _ = koala
    outputs.wait(lambda items: {"name": "obstacle", "contents": {"distance": 1.0}} in items)
    dev.proximity[7] = 800
    outputs.wait(lambda items: {"name": "obstacle", "contents": {"distance": 0.0}} in items)


def test_every_line_is_one_command_and_each_reply_is_read(koala) -> None:
    dev, robot, _, _ = koala
    dev.wait_for_lines(6)
    for _ in range(5):
        robot.call_input("set_velocity", linear=0.1, angular=0.0)
    lines = dev.wait_for_lines(5, prefix="D,22")
    assert len(lines) == 5
    assert set(dev.lines) <= {"D,0,0", "G,0,0", "E", "H", "N", "D,22,22"}
