"""Mimic joints (`mimic JOINT multiplier M offset O`, URDF's `<mimic>`): a parallel gripper's
second finger follows the first. Checked (E603 for a leader that is missing, fixed, itself or
a mimic), carried through the canonical JSON both ways, written as URDF's `<mimic>` (read back
by urchin; `check_urdf` and `ign sdf -k` take it) and as a MuJoCo joint equality that really
holds the follower to its leader in the physics."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc.compile import compile_text
from rdisc.emit.canonical import to_json
from rdisc.emit.mjcf import to_mjcf
from rdisc.emit.sdf import to_sdf
from rdisc.emit.urdf import to_urdf
from rdisc.semantics import model as m
from tests.emit.body_tools import Tree, check_urdf, ign_sdf_check, require_module

GRIPPER = """\
robot gripper { description "a parallel gripper" }
link palm { mass 0.2  inertia [0.0001, 0.0001, 0.0001] }
link left { visual box(0.01, 0.01, 0.05)  mass 0.02  inertia [0.00001, 0.00001, 0.00001] }
link right { visual box(0.01, 0.01, 0.05)  mass 0.02  inertia [0.00001, 0.00001, 0.00001] }
joint left_finger: prismatic palm -> left { at [0, 0.02, 0] axis [0, 1, 0] limit 0..0.03 velocity 0.1 effort 10 }
joint right_finger: prismatic palm -> right {
    at [0, -0.02, 0] axis [0, 1, 0] limit -0.03..0 velocity 0.1 effort 10
    mimic left_finger multiplier -1 offset 0.001
}
"""


def _model(text: str = GRIPPER, name: str = "gripper.rdis") -> m.Model:
    compilation = compile_text(name, text)
    assert compilation.model is not None and compilation.diagnostics.items == [], compilation.diagnostics.items
    return compilation.model


def test_the_model_holds_the_mimic() -> None:
    joints = _model().joints
    assert joints["right_finger"].mimic == m.Mimic("left_finger", -1.0, 0.001)
    assert joints["left_finger"].mimic is None


def test_the_mimic_goes_through_the_canonical_json_and_back() -> None:
    text = to_json(_model())
    joints = {j["name"]: j for j in json.loads(text)["joints"]}
    assert joints["right_finger"]["mimic"] == {"joint": "left_finger", "multiplier": -1, "offset": 0.001}
    assert _model(text, "gripper.json").joints == _model().joints


def test_urdf_tools_read_the_mimic(tmp_path: Path) -> None:
    urchin = require_module("urchin")
    path = tmp_path / "gripper.urdf"
    path.write_text(to_urdf(_model(), "gripper.rdis"), encoding="utf-8")
    mimic = {j.name: j.mimic for j in urchin.URDF.load(str(path), lazy_load_meshes=True).joints}
    assert mimic["left_finger"] is None
    assert (mimic["right_finger"].joint, mimic["right_finger"].multiplier, mimic["right_finger"].offset) == \
        ("left_finger", -1.0, 0.001)
    assert isinstance(check_urdf(path), Tree)
    assert ign_sdf_check(path) == (0, "Valid.")
    sdf = tmp_path / "gripper.sdf"
    sdf.write_text(to_sdf(_model(), "gripper.rdis"), encoding="utf-8")
    assert ign_sdf_check(sdf) == (0, "Valid.")


def test_mujoco_holds_the_follower_to_its_leader() -> None:
    mujoco = require_module("mujoco")
    physics = mujoco.MjModel.from_xml_string(to_mjcf(_model()))
    data = mujoco.MjData(physics)
    leader, follower = physics.joint("left_finger"), physics.joint("right_finger")
    for _ in range(500):  # the leader held open at 2 cm; the follower is moved only by the equality
        data.qpos[leader.qposadr[0]], data.qvel[leader.dofadr[0]] = 0.02, 0.0
        mujoco.mj_step(physics, data)
    assert data.qpos[follower.qposadr[0]] == pytest.approx(-0.02 + 0.001, abs=1e-6)


@pytest.mark.parametrize(("mimic", "expected"), [
    ("mimic left_fingr", ("E102", "left_fingr")),
    ("mimic right_finger", ("E603", "right_finger", "joint `right_finger` cannot mimic itself")),
    ("mimic mount", ("E603", "mount", "joint `mount` is fixed: there is nothing to mimic")),
    ("mimic middle_finger", ("E603", "middle_finger", "joint `middle_finger` mimics `left_finger` itself")),
    ("mimic left_finger multiplier 0", ("E603", "0", "a mimic's multiplier is not 0")),
])
def test_a_mimic_of_nothing_that_moves_is_refused(mimic: str, expected: tuple[str, ...]) -> None:
    text = GRIPPER.replace("mimic left_finger multiplier -1 offset 0.001", mimic) + (
        "link camera { }\njoint mount: fixed palm -> camera { }\n"
        "link middle { mass 0.02  inertia [0.00001, 0.00001, 0.00001] }\n"
        "joint middle_finger: prismatic palm -> middle { axis [0, 1, 0] limit 0..0.03 velocity 0.1 effort 10 "
        "mimic left_finger }\n")
    found = [(d.code, text[d.span.start:d.span.end], d.message) for d in compile_text("g.rdis", text).diagnostics.items
             if d.severity == 1]
    assert [f[:len(expected)] for f in found] == [expected]
