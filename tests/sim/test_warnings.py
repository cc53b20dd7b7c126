"""A simulation that never lies quietly (issue 26, part 3): a command beyond its joint's range, which
MuJoCo holds at the limit where the real servo would go on, is one warning as it crosses, not one a
command; and a free base starts resting on the floor, whatever its origin."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

pytest.importorskip("mujoco")

from rdisc.compile import compile_path, compile_text
from rdisc.runtime import load
from rdisc.sim import Simulation
from tests.conftest import run_rdisc

ARM = Path(__file__).resolve().parents[2] / "examples" / "arm.rdis"
CLIPPED = ("joint `shoulder`: a position command of 2.5 is beyond its range -1.8..1.8; the simulation holds it "
           "at 1.8, where the device would go on")


def test_a_command_beyond_the_joint_s_limit_is_one_warning_each_time_it_crosses() -> None:
    model = compile_path(str(ARM)).model
    assert model is not None
    sim = Simulation(model)
    robot = load(ARM).connect(sim=sim, threads=False)
    # Each command a second after the last by the robot's clock (the physics not stepped): the
    # servo's 4.8 rad/s (`limit shape`) reaches each as it is.
    seconds = iter(range(1, 100))
    robot._clock = lambda: float(next(seconds))
    try:
        robot.call_interface("move", [0.0, 1.0, 0.0, 0.0, 0.0, 0.0])  # within: nothing to say
        assert sim.warnings == []
        for _ in range(3):  # the device's range takes 2.5 rad (0..4095 is a turn); the joint's stops at 1.8
            robot.call_interface("move", [0.0, 2.5, 0.0, 0.0, 0.0, 0.0])
        assert sim.warnings == [CLIPPED]
        robot.call_interface("move", [0.0, 1.0, 0.0, 0.0, 0.0, 0.0])
        robot.call_interface("move", [0.0, 2.5, 0.0, 0.0, 0.0, 0.0])
        assert sim.warnings == [CLIPPED, CLIPPED]
    finally:
        robot.close()


def test_rdisc_sim_says_each_clipped_command_on_stderr() -> None:
    done = run_rdisc("sim", str(ARM), "--call", "move", "angle=[0, 2.5, 0, 0, 0, 0]", "--duration", "0.1")
    assert done.returncode == 0
    assert done.stderr.splitlines()[-1] == f"rdisc sim: warning: {CLIPPED}"


BASE_IN_THE_MIDDLE = """\
robot cart { author "tests" }
link base { collision box(0.3, 0.2, 0.16)  mass 2  inertia [0.01, 0.02, 0.02] }
link left { collision cylinder(0.05, 0.02)  mass 0.1  inertia [0.0001, 0.0001, 0.0001] }
link right { collision cylinder(0.05, 0.02)  mass 0.1  inertia [0.0001, 0.0001, 0.0001] }
joint left_wheel: continuous base -> left { at [0, 0.12, -0.03]  rpy [-1.5707963267948966, 0, 0]  axis [0, 0, 1] }
joint right_wheel: continuous base -> right { at [0, -0.12, -0.03]  rpy [-1.5707963267948966, 0, 0]  axis [0, 0, 1] }
"""


def test_a_base_whose_origin_is_its_centre_starts_resting_on_the_floor() -> None:
    """Its box reaches 8 cm below its origin, its wheels 3 + 5 cm: it starts 8 cm up, not inside the floor."""
    compilation = compile_text("cart.rdis", BASE_IN_THE_MIDDLE)
    assert compilation.model is not None, [d.message for d in compilation.diagnostics.items]
    sim = Simulation(compilation.model)
    assert abs(sim.link_poses()["base"][2] - 0.08) < 1e-12
    sim.advance(0.5)
    assert abs(sim.link_poses()["base"][2] - 0.08) < 1e-3  # and stays there: nothing threw it up


def test_a_link_never_touches_its_parent_even_one_welded_to_the_world() -> None:
    """The arm's turret sits on its base plate, which is welded to the world (where MuJoCo's own
    parent filter does not reach): the MJCF excludes each joint's two links from colliding."""
    model = compile_path(str(ARM)).model
    assert model is not None
    sim = Simulation(model)
    sim.advance(0.2)
    physics, data = sim.physics, sim.data
    touching = {(physics.body(physics.geom_bodyid[c.geom1]).name, physics.body(physics.geom_bodyid[c.geom2]).name)
                for c in data.contact[:data.ncon]}
    joined = {(j.parent, j.child) for j in model.joints.values()}
    assert not touching & (joined | {(b, a) for a, b in joined}), touching


def test_a_joint_faster_than_its_velocity_is_one_warning() -> None:
    """The arm's shoulder said to move at 0.05 rad/s: its simulated servo swings it to 1 rad far faster."""
    text = ARM.read_text(encoding="utf-8")
    start = text.index("joint shoulder:")
    end = text.index("}", start)  # the joint's block
    text = text[:start] + text[start:end].replace("velocity SPEED", "velocity 0.05", 1) + text[end:]
    compilation = compile_text("slow.rdis", text)
    assert compilation.model is not None, [d.message for d in compilation.diagnostics.items]
    sim = Simulation(compilation.model)
    robot = load(compilation.model).connect(sim=sim, threads=False)
    try:
        robot.call_interface("move", [0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
        robot.run_for(0.5)
        assert sim.warnings == []
        robot.call_interface("move", [0.0, 1.0, 0.0, 0.0, 0.0, 0.0])
        robot.run_for(1.0)
    finally:
        robot.close()
    assert len(sim.warnings) == 1
    assert re.fullmatch(r"joint `shoulder` moves at [\d.]+, more than 2 times its velocity 0\.05: the physics is "
                        r"unstable, or the simulated servo does what the device's could not", sim.warnings[0])
