"""Servo gains from the actuator and the inertia it moves (issue 26: a light link chatters and
reads 0 rad). The example arm's gripper jaw made a 5 g servo horn: with a gain from the servo's
stall torque alone it rang at ω·dt ≈ 12 and was thrown through its limits; derived from its
inertia too, it holds the angle it is commanded."""

from __future__ import annotations

from pathlib import Path

import pytest

mujoco = pytest.importorskip("mujoco")

from rdisc.compile import compile_path, compile_text
from rdisc.semantics import model as m
from rdisc.semantics.reflected import STABLE_STEP, TIMESTEP, joint_inertia, position_gain, steps_per_period
from rdisc.sim import Simulation
from tests.engine.test_one_engine import implementation_of

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE_ARM = ROOT / "examples" / "arm.rdis"
JAW = """    visual box(0.02, 0.004, 0.06) at [0, 0, 0.03]
    collision box(0.02, 0.004, 0.06) at [0, 0, 0.03]
    mass 0.02
    centre [0, 0, 0.03]
    inertia [0.00000603, 0.00000667, 0.000000693]"""
HORN = """    visual box(0.004, 0.004, 0.03) at [0, 0, 0.015]
    collision box(0.004, 0.004, 0.03) at [0, 0, 0.015]
    mass 0.005  centre [0, 0, 0.015]  inertia [0.000000381, 0.000000381, 0.0000000133]"""


def _horn_arm() -> str:
    text = EXAMPLE_ARM.read_text(encoding="utf-8")
    assert JAW in text
    return text.replace(JAW, HORN)


def _model(text: str) -> m.Model:
    compilation = compile_text("horn.rdis", text)
    assert compilation.model is not None and not compilation.diagnostics.has_errors()
    return compilation.model


def test_the_inertia_a_joint_moves_is_mujocos() -> None:
    """Every link a joint carries, about its axis at the zero pose: as MuJoCo's own mass matrix."""
    model = compile_path(str(EXAMPLE_ARM)).model
    assert model is not None
    physics = Simulation(model).physics
    found = joint_inertia(model.links, model.joints)
    for joint in model.joints.values():
        want = float(physics.dof_M0[physics.joint(joint.name).dofadr[0]])
        assert found[joint.name] == pytest.approx(want, rel=0.01, abs=1e-6)


def test_a_5_g_horn_holds_its_commanded_angle(tmp_path: Path) -> None:
    """Through the arm's JointState input, in the runtime: the horn goes to 0.5 rad and stays."""
    text = _horn_arm()
    model = _model(text)
    horn = joint_inertia(model.links, model.joints)["gripper"]
    stall = 4.1 / 0.05  # the gain the servo's stall torque alone would give
    assert steps_per_period(stall, horn, TIMESTEP) > STABLE_STEP  # that gain could not be integrated
    sim = Simulation(model)
    robot = implementation_of("runtime", text, tmp_path, "arm").connect(sim=sim)
    try:
        robot.call_input("command", name=[], position=[0.0, 0.0, 0.0, 0.0, 0.0, 0.5])
        seen = []
        for _ in range(10):
            robot.run_for(0.1)
            seen.append(sim.position("gripper"))
    finally:
        robot.close()
    assert all(abs(angle - 0.5) < 0.005 for angle in seen[2:]), seen
    velocity = float(sim.data.qvel[sim.physics.joint("gripper").dofadr[0]])
    assert abs(velocity) < 1e-3  # still, not ringing
    physics_gain = float(sim.physics.actuator_gainprm[sim.physics.actuator("gripper_servo_position").id][0])
    assert physics_gain == position_gain(4.1, horn, TIMESTEP) < stall


def test_a_heavy_link_keeps_its_servos_gain() -> None:
    """The shoulder carries 0.058 kg m²: the stall torque's gain (82 N m/rad) is well inside the limit."""
    model = compile_path(str(EXAMPLE_ARM)).model
    assert model is not None
    physics = Simulation(model).physics
    assert float(physics.actuator_gainprm[physics.actuator("shoulder_servo_position").id][0]) == 4.1 / 0.05
