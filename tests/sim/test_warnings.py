"""What the simulation does that the device would not is said, never done quietly (issue 26, part 3):
a command beyond its joint's range, which MuJoCo holds at the limit where the real servo would go on,
is one warning as it crosses, not one a command."""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("mujoco")

from rdisc.compile import compile_path
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
