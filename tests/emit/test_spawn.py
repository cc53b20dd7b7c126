"""`spawn floating|fixed at XYZ rpy RPY` on the root link: how and where the body meets the world.
`fixed` welds it there (URDF and SDF: a fixed joint `world_to_ROOT` from the world, as Gazebo
reads them; MJCF: a body without a free joint, at the pose); `floating` frees it (MJCF's free
joint, whatever the wheels say), placed at the pose. Checked: only the root link, the two
words, once, and the added joint's name free (E601, E203, E607); through the JSON both ways;
and in MuJoCo's physics: a bolted arm stays up, a floating one falls to the floor."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rdisc.compile import compile_text
from rdisc.emit.canonical import to_json
from rdisc.emit.mjcf import to_mjcf
from rdisc.emit.sdf import to_sdf
from rdisc.emit.urdf import to_urdf
from rdisc.semantics import model as m
from tests.emit.body_tools import Tree, check_urdf, ign_sdf_check, require_module

ARM = """\
robot bolted {{ description "an arm on a table" }}
link base {{
    collision box(0.1, 0.1, 0.02) at [0, 0, 0.01]  mass 1  inertia [0.001, 0.001, 0.001]
    spawn {kind} at [0.5, 0, 0.75] rpy [0, 0, 1.5707963267948966]
}}
link arm {{
    collision box(0.02, 0.02, 0.2) at [0, 0, 0.1]  mass 0.1  inertia [0.0004, 0.0004, 0.00001]
}}
joint lift: revolute base -> arm {{ at [0, 0, 0.02] axis [0, 1, 0] limit -1..1 velocity 1 effort 1 }}
"""


def _model(kind: str, name: str = "arm.rdis", text: str | None = None) -> m.Model:
    compilation = compile_text(name, text if text is not None else ARM.format(kind=kind))
    assert compilation.model is not None and compilation.diagnostics.items == [], compilation.diagnostics.items
    return compilation.model


def test_the_root_link_holds_its_spawn() -> None:
    model = _model("fixed")
    assert model.links["base"].spawn == m.Spawn(False, m.Pose((0.5, 0.0, 0.75), (0.0, 0.0, 1.5707963267948966)))
    assert _model("floating").links["base"].spawn == m.Spawn(True, model.links["base"].spawn.pose)  # type: ignore


@pytest.mark.parametrize("kind", ["fixed", "floating"])
def test_the_spawn_goes_through_the_canonical_json_and_back(kind: str) -> None:
    text = to_json(_model(kind))
    base = next(link for link in json.loads(text)["links"] if link["name"] == "base")
    assert base["spawn"] == {"floating": kind == "floating", "xyz": [0.5, 0, 0.75], "rpy": [0, 0, 1.5707963267948966]}
    assert _model(kind, "arm.json", text).links == _model(kind).links


def test_a_fixed_root_is_welded_to_the_world_in_urdf_and_sdf(tmp_path: Path) -> None:
    model = _model("fixed")
    urdf, sdf = tmp_path / "arm.urdf", tmp_path / "arm.sdf"
    urdf.write_text(to_urdf(model, "arm.rdis"), encoding="utf-8")
    sdf.write_text(to_sdf(model, "arm.rdis"), encoding="utf-8")
    tree = check_urdf(urdf)
    assert isinstance(tree, Tree) and (tree.root, tree.edges) == ("world", [("world", "base"), ("base", "arm")])
    welded = ET.parse(urdf).getroot().find("joint[@name='world_to_base']")
    assert welded is not None and welded.get("type") == "fixed"
    assert welded.find("origin").attrib == {"xyz": "0.5 0 0.75", "rpy": "0 0 1.5707963267948966"}  # type: ignore
    assert ign_sdf_check(urdf) == ign_sdf_check(sdf) == (0, "Valid.")
    model_element = ET.parse(sdf).getroot().find("model")
    assert model_element is not None and model_element.findtext("pose") == "0.5 0 0.75 0 0 1.5707963267948966"
    joint = model_element.find("joint[@name='world_to_base']")
    assert joint is not None and (joint.findtext("parent"), joint.findtext("child")) == ("world", "base")


def test_a_floating_root_adds_no_joint(tmp_path: Path) -> None:
    text = to_urdf(_model("floating"), "arm.rdis")
    assert "world" not in text


@pytest.mark.parametrize(("kind", "stays_up"), [("fixed", True), ("floating", False)])
def test_mujoco_places_the_base_and_holds_it_or_lets_it_fall(kind: str, stays_up: bool) -> None:
    mujoco = require_module("mujoco")
    physics = mujoco.MjModel.from_xml_string(to_mjcf(_model(kind)))
    data = mujoco.MjData(physics)
    mujoco.mj_forward(physics, data)
    base = physics.body("base").id
    assert list(data.xpos[base]) == pytest.approx([0.5, 0.0, 0.75])
    assert [physics.joint(i).name for i in range(physics.njnt)] == (["lift"] if stays_up else ["base_free", "lift"])
    for _ in range(1000):  # two simulated seconds
        mujoco.mj_step(physics, data)
    assert bool(data.xpos[base][2] > 0.7) is stays_up


def test_a_wheeled_base_spawned_fixed_does_not_roll() -> None:
    """Without `spawn`, a body with a wheel is a mobile base (a free joint); `spawn fixed` says otherwise."""
    wheel = ("link wheel { collision cylinder(0.03, 0.01)  mass 0.05  inertia [0.00001, 0.00001, 0.00002] }\n"
             "joint spin: continuous base -> wheel { axis [0, 1, 0] velocity 10 effort 1 }\n")
    mujoco = require_module("mujoco")
    for kind, joints in (("fixed", ["lift", "spin"]), ("floating", ["base_free", "lift", "spin"])):
        physics = mujoco.MjModel.from_xml_string(to_mjcf(_model(kind, text=ARM.format(kind=kind) + wheel)))
        assert sorted(physics.joint(i).name for i in range(physics.njnt)) == joints


@pytest.mark.parametrize(("change", "expected"), [
    (("link arm {{", "link arm {{ spawn fixed"),
     ("E601", "spawn fixed", "link `arm` hangs from joint `lift`: only the root link is spawned")),
    (("spawn {kind}", "spawn hovering"), ("E601", "hovering", "a link is spawned `floating` or `fixed`, not `hovering`")),
    (("spawn {kind}", "spawn fixed spawn {kind}"), ("E203", "spawn fixed at [0.5, 0, 0.75] rpy [0, 0, 1.5707963267948966]",
                                                             "`spawn` is given twice in `base`")),
    (("joint lift", "joint world_to_base"),
     ("E607", "world_to_base", ("joint `world_to_base` takes the name of the joint that fixes `base` to the world "
      "in the URDF and SDF"))),
])
def test_a_spawn_that_cannot_be_is_refused(change: tuple[str, str], expected: tuple[str, str, str]) -> None:
    text = ARM.replace(*change).format(kind="fixed")
    found = [(d.code, text[d.span.start:d.span.end], d.message) for d in compile_text("a.rdis", text).diagnostics.items
             if d.severity == 1]
    assert found == [expected]
