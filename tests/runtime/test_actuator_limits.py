"""Actuators' limits (thesis §7.2.6) in the runtime and a generated driver alike: a command faster
than its actuator's `velocity` or `acceleration` is slowed to them (`limit shape`) or refused with
an RdisLimitError naming the actuator, the limit and the value, nothing written (`limit refuse`).

The robot's clock is injected (`robot._clock`), so each command's time since the one before is
the test's; what is written is read on a pseudo-terminal, byte for byte.
"""

from __future__ import annotations

import importlib.util
import re
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from conftest import cli_env, run_rdisc
from devices import pty_device
from runtime_support import DATA, REPO

from rdisc import engine
from rdisc.compile import compile_path
from rdisc.emit.python import to_python
from rdisc.runtime import load

LIMITS = DATA / "actuator_limits.rdis"
ARM = REPO / "examples" / "arm.rdis"


def _driver_robot(folder: Path, description: Path, name: str) -> Callable[[], engine.Robot]:
    """The generated driver's robot class for `description`, imported from a file."""
    compilation = compile_path(str(description))
    assert compilation.model is not None
    path = folder / f"{description.stem}_limits_driver.py"
    path.write_text(to_python(compilation.model, description.name), encoding="utf-8")
    spec = importlib.util.spec_from_file_location(f"{description.stem}_limits_{abs(hash(str(path)))}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    made: Callable[[], engine.Robot] = getattr(module, name)
    return made


@pytest.fixture(params=["runtime", "driver"])
def way(request: pytest.FixtureRequest) -> str:
    return str(request.param)


def _maker(way: str, folder: Path, description: Path, name: str) -> Callable[[], engine.Robot]:
    if way == "runtime":
        device = load(description).device
        return lambda: engine.Robot(device)
    return _driver_robot(folder, description, name)


def _refusal(robot: engine.Robot) -> type[Exception]:
    """RdisLimitError as the robot raises it: the engine's, or the driver's own (it carries the engine)."""
    made: type[Exception] = sys.modules[type(robot).__module__].__dict__.get("RdisLimitError", engine.RdisLimitError)
    return made


class Clock:
    """The robot's clock, moved by the test."""

    def __init__(self) -> None:
        self.now = 64.0

    def __call__(self) -> float:
        return self.now


@pytest.fixture
def device() -> Iterator[Any]:
    with pty_device(lambda data: None) as dev:
        yield dev


def _opened(robot: engine.Robot, port: str, clock: Clock) -> engine.Robot:
    robot._clock = clock
    robot._sleep = lambda seconds: None
    robot.open(port, threads=False)
    return robot


def _written(device: Any, expected: bytes) -> None:
    """The pseudo-terminal has received exactly `expected`, nothing more."""
    assert device.wait_for(len(expected), timeout=5.0) == expected


def test_a_servo_s_position_moves_toward_the_command_no_faster_than_its_limits(way, device, tmp_path) -> None:
    """velocity 2 rad/s, acceleration 10 rad/s², 0.01 rad a step: 0.1 s after a still command the
    speed may be 1 rad/s (0.1 rad, 10 steps), then 2 rad/s (20 steps) each 0.1 s; an interface's
    call of the servo is held alike; a command within reach is written as it is."""
    clock = Clock()
    robot = _opened(_maker(way, tmp_path, LIMITS, "Limits")(), device.port, clock)
    try:
        robot.primitives.servo(512)  # the first command: nothing before it, written as it is
        for _ in range(3):
            clock.now += 0.1
            robot.interfaces.lift(2.0)  # 712: 522, 542, 562
        clock.now += 1.0
        robot.primitives.servo(600)  # from 562, 0.38 rad in 1 s: within reach
    finally:
        robot.close()
    _written(device, bytes.fromhex("02 0200" "02 020a" "02 021e" "02 0232" "02 0258"))


def test_a_servo_given_limit_refuse_refuses_a_command_beyond_them_and_writes_nothing(way, device, tmp_path) -> None:
    clock = Clock()
    robot = _opened(_maker(way, tmp_path, LIMITS, "Limits")(), device.port, clock)
    try:
        robot.primitives.guard(512)
        clock.now += 0.1
        with pytest.raises(_refusal(robot)) as fast:
            robot.primitives.guard(612)
        robot.primitives.guard(517)  # 0.5 rad/s: within both limits
        clock.now += 0.1
        with pytest.raises(_refusal(robot)) as sudden:
            robot.primitives.guard(537)  # 2 rad/s, but from 0.5 rad/s in 0.1 s
        robot.primitives.guard(522)
    finally:
        robot.close()
    assert str(fast.value) == ("actuator guard_motor: a position of 1 rad 0.1 s after 0 rad moves at 10 rad/s, over "
                               "its velocity limit of 2 rad/s: not written (`limit refuse`)")
    assert (fast.value.actuator, fast.value.limit, fast.value.most) == ("guard_motor", "velocity", 2.0)
    assert str(sudden.value) == ("actuator guard_motor: a position of 0.25 rad 0.1 s after 0.05 rad changes its speed "
                                 "from 0.5 to 2 rad/s, at 15 rad/s², over its acceleration limit of 10 rad/s²: not "
                                 "written (`limit refuse`)")
    assert (sudden.value.actuator, sudden.value.limit, sudden.value.most) == ("guard_motor", "acceleration", 10.0)
    # a caller handling bad values handles it
    assert [k.__name__ for k in type(sudden.value).__mro__[:3]] == ["RdisLimitError", "RdisValueError", "RdisError"]
    _written(device, bytes.fromhex("04 0200" "04 0205" "04 020a"))


def test_a_wheel_s_speed_is_clamped_to_its_velocity_and_changed_by_its_acceleration(way, device, tmp_path) -> None:
    """velocity 5 rad/s (50 steps of 0.1 rad/s), acceleration 20 rad/s² (20 steps each 0.1 s)."""
    clock = Clock()
    robot = _opened(_maker(way, tmp_path, LIMITS, "Limits")(), device.port, clock)
    try:
        robot.primitives.wheel(100)  # the first: only its velocity holds it
        for _ in range(6):
            clock.now += 0.1
            robot.primitives.wheel(-100)
    finally:
        robot.close()
    speeds = [50, 30, 10, -10, -30, -50, -50]
    _written(device, b"".join(bytes([3]) + speed.to_bytes(2, "big", signed=True) for speed in speeds))


def test_a_wheel_given_limit_refuse_refuses_a_speed_beyond_its_limits(way, device, tmp_path) -> None:
    clock = Clock()
    robot = _opened(_maker(way, tmp_path, LIMITS, "Limits")(), device.port, clock)
    try:
        with pytest.raises(_refusal(robot)) as fast:
            robot.primitives.brake(60)
        robot.primitives.brake(40)
        clock.now += 0.1
        with pytest.raises(_refusal(robot)) as sudden:
            robot.primitives.brake(-40)
        robot.primitives.brake(20)
    finally:
        robot.close()
    assert str(fast.value) == ("actuator brake_motor: a velocity of 6 rad/s, over its velocity limit of 5 rad/s: "
                               "not written (`limit refuse`)")
    assert str(sudden.value) == ("actuator brake_motor: a velocity of -4 rad/s 0.1 s after 4 rad/s changes at "
                                 "80 rad/s², over its acceleration limit of 20 rad/s²: not written (`limit refuse`)")
    _written(device, bytes.fromhex("05 0028" "05 0014"))


def test_the_arm_s_joint_state_input_is_shaped_joint_by_joint(way, device, tmp_path) -> None:
    """examples/arm.rdis: each servo at most 4.8 rad/s (`limit shape`). A JointState moving the
    waist by 1 rad 0.1 s after the last moves it by 0.48 rad; the others, still, stay."""
    clock = Clock()
    robot = _opened(_maker(way, tmp_path, ARM, "Arm")(), device.port, clock)
    try:
        robot.inputs.command(name=[], position=[0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
        clock.now += 0.1
        robot.inputs.command(name=[], position=[1.0, 0.0, 0.0, 0.0, 0.0, -0.1])
    finally:
        robot.close()
    oracle = engine.Robot(load(ARM).device)  # a goal's bytes, as a first command writes them
    torque = oracle.request("sync_torque", [1] * 6)
    still = oracle.request("sync_goal", [2048] * 6)
    moved = oracle.request("sync_goal", [2048 + 313, 2048, 2048, 2048, 2048, 2048 - 65])  # 0.48 rad; 0.1 rad
    off = oracle.request("sync_torque", [0] * 6)
    _written(device, torque + still + moved + off)


REFUSED = re.compile(r"(.+): RdisLimitError: actuator guard_motor: a position of 4\.88 rad [0-9.e-]+ s after 0 rad "
                     r"moves at [0-9.e+]+ rad/s, over its velocity limit of 2 rad/s: not written \(`limit refuse`\)")


def test_rdisc_run_and_the_driver_s_command_line_stop_at_a_refused_call(device, tmp_path) -> None:
    """`rdisc run` and the driver's own command line: a call beyond the limits ends the run (exit 1)
    with the refusal, after the call before it was written and before the call after it."""
    calls = ("--call", "guard", "goal=512", "--call", "guard", "goal=1000", "--call", "wheel", "speed=40")
    compilation = compile_path(str(LIMITS))
    assert compilation.model is not None
    driver = tmp_path / "limits_driver.py"
    driver.write_text(to_python(compilation.model, LIMITS.name), encoding="utf-8")
    ran = run_rdisc("run", LIMITS, "--port", device.port, *calls)
    assert ran.returncode == 1
    said = REFUSED.fullmatch(ran.stderr.strip())
    assert said is not None and said[1] == "rdisc run", ran.stderr
    assert device.wait_for(3, timeout=5.0) == bytes.fromhex("04 0200")
    device.clear()
    done = subprocess.run([sys.executable, str(driver), "--port", device.port, *calls], capture_output=True, text=True,
                          env=cli_env(), timeout=60, check=False)
    assert done.returncode == 1
    said = REFUSED.fullmatch(done.stderr.strip())
    assert said is not None, done.stderr
    assert device.wait_for(3, timeout=5.0) == bytes.fromhex("04 0200")
