"""MuJoCo reads what rdisc writes of every example's body, both ways a user would give it:
the URDF (MuJoCo's own importer) and the MJCF. Each names the description's moving joints as
the description does, which is what a JointState, ros2_control and the simulation look them up
by. (The test body with every part of the language, tests/emit/body_tools.TWISTY, names mesh
files that do not exist, which MuJoCo rightly refuses: it is judged by the other tools.)"""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.emit.mjcf import to_mjcf
from rdisc.emit.urdf import to_urdf
from tests.emit.body_tools import EXAMPLES, model_of, require_module


@pytest.mark.parametrize("source", EXAMPLES, ids=lambda p: p.stem)
@pytest.mark.parametrize("form", ["urdf", "mjcf"])
def test_mujoco_loads_the_body_with_the_description_s_joint_names(source: Path, form: str, tmp_path: Path) -> None:
    mujoco = require_module("mujoco")
    model = model_of(source)
    text = to_urdf(model, source.name) if form == "urdf" else to_mjcf(model)
    path = tmp_path / f"body.{'urdf' if form == 'urdf' else 'xml'}"
    path.write_text(text, encoding="utf-8")
    physics = mujoco.MjModel.from_xml_path(str(path))
    named = [physics.joint(i).name for i in range(physics.njnt)]
    moving = [name for name, joint in model.joints.items() if joint.moves()]
    assert [name for name in named if name in model.joints] == moving
    roots = {link for link in model.links if all(j.child != link for j in model.joints.values())}
    assert set(named) - set(model.joints) <= {f"{root}_free" for root in roots}  # a mobile base's free joint
