"""Generated bodies through every tool that reads rdisc's models: `check_urdf` and urchin on the
URDF, `ign sdf -k` (libsdformat, as Gazebo loads a `robot_description`) on the URDF and on the
SDF, MuJoCo on the URDF and on the MJCF. The examples' bodies go through the same tools in
test_urdf.py, test_sdf.py and test_mujoco_reads.py; here a seeded sample of trees no example has
(every joint kind and shape, turned frames and axes, off-centre masses, branches). Each tool is
one test, one subprocess at most, so the whole costs seconds."""

from __future__ import annotations

import random
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.emit.mjcf import rolls, to_mjcf
from rdisc.emit.sdf import to_sdf
from rdisc.emit.urdf import to_urdf
from rdisc.semantics import model as m
from tests.emit.body_tools import Tree, check_urdf, ign_sdf_check, require_module

SAMPLE = 3  # generated bodies: each costs two `ign sdf -k` runs of about a second


def generated(seed: int) -> str:
    """A body of 3 to 6 links, each hung from an earlier one by a joint of a random kind, with a shape
    of each kind, rotated frames and a mass on every link."""
    draw = random.Random(seed)

    def vector(scale: float) -> str:
        return "[" + ", ".join(f"{draw.uniform(-scale, scale):.4f}" for _ in range(3)) + "]"

    def shape() -> str:
        match draw.choice(("box", "cylinder", "sphere")):
            case "box":
                return f"box({draw.uniform(0.01, 0.2):.3f}, {draw.uniform(0.01, 0.2):.3f}, {draw.uniform(0.01, 0.2):.3f})"
            case "cylinder":
                return f"cylinder({draw.uniform(0.01, 0.1):.3f}, {draw.uniform(0.01, 0.2):.3f})"
            case _:
                return f"sphere({draw.uniform(0.01, 0.1):.3f})"

    count = draw.randint(3, 6)
    lines = [f'robot generated{seed} {{ description "a generated body" }}']
    for i in range(count):
        kind = shape()
        lines.append(f"link part{i} {{ visual {kind} at {vector(0.05)} rpy {vector(1.5)}  collision {kind}  "
                     f"mass {draw.uniform(0.05, 2):.3f}  centre {vector(0.02)}  inertia [0.002, 0.003, 0.004] }}")
    for i in range(1, count):
        kind = draw.choice(("fixed", "revolute", "continuous", "prismatic"))
        items = f"at {vector(0.2)} rpy {vector(3)}"
        if kind != "fixed":
            items += f"  axis {vector(1)}  velocity 2  effort 3"
        if kind in ("revolute", "prismatic"):
            items += "  limit -0.5..0.5"
        lines.append(f"joint move{i}: {kind} part{draw.randrange(i)} -> part{i} {{ {items} }}")
    return "\n".join(lines) + "\n"


BODIES = [f"generated{seed}" for seed in range(SAMPLE)]
_models: dict[str, m.Model] = {}


def model(body: str, folder: Path) -> m.Model:
    """The checked model of a generated body (each compiled once)."""
    key = body
    if key not in _models:
        path = folder / f"{body}.rdis"
        path.write_text(generated(int(body.removeprefix("generated"))), encoding="utf-8")
        compilation = compile_path(str(path))
        assert compilation.model is not None and not compilation.diagnostics.has_errors(), \
            [d.message for d in compilation.diagnostics.items]
        _models[key] = compilation.model
    return _models[key]


def _written(tmp_path: Path, text: str, suffix: str) -> Path:
    path = tmp_path / f"body{suffix}"
    path.write_text(text, encoding="utf-8")
    return path


def _check_urdf(body: m.Model, tmp_path: Path) -> None:
    tree = check_urdf(_written(tmp_path, to_urdf(body, "body.rdis"), ".urdf"))
    assert isinstance(tree, Tree), tree
    assert (tree.name, tree.root) == (body.robot.name, body.root_link().name)  # type: ignore[union-attr]
    assert sorted(tree.edges) == sorted((j.parent, j.child) for j in body.joints.values())


def _ign_urdf(body: m.Model, tmp_path: Path) -> None:
    assert ign_sdf_check(_written(tmp_path, to_urdf(body, "body.rdis"), ".urdf")) == (0, "Valid.")


def _ign_sdf(body: m.Model, tmp_path: Path) -> None:
    assert ign_sdf_check(_written(tmp_path, to_sdf(body, "body.rdis"), ".sdf")) == (0, "Valid.")


def _moving(body: m.Model) -> set[str]:
    return {j.name for j in body.joints.values() if j.moves()}


def _mujoco_names(physics: object, count: int) -> set[str]:
    mujoco = require_module("mujoco")
    return {mujoco.mj_id2name(physics, mujoco.mjtObj.mjOBJ_JOINT, i) for i in range(count)}


def _mujoco_urdf(body: m.Model, tmp_path: Path) -> None:
    mujoco = require_module("mujoco")
    physics = mujoco.MjModel.from_xml_string(to_urdf(body, "body.rdis"))
    assert _mujoco_names(physics, physics.njnt) == _moving(body)


def _mujoco_mjcf(body: m.Model, tmp_path: Path) -> None:
    mujoco = require_module("mujoco")
    physics = mujoco.MjModel.from_xml_string(to_mjcf(body))
    root = body.root_link()
    assert root is not None
    free = {f"{root.name}_free"} if rolls(body) else set()
    assert _mujoco_names(physics, physics.njnt) == _moving(body) | free
    assert physics.nbody == len(body.links) + 1  # and the world


def _urchin(body: m.Model, tmp_path: Path) -> None:
    urchin = require_module("urchin")
    robot = urchin.URDF.load(str(_written(tmp_path, to_urdf(body, "body.rdis"), ".urdf")), lazy_load_meshes=True)
    assert {link.name for link in robot.links} == set(body.links)
    assert {joint.name for joint in robot.joints} == set(body.joints)


TOOLS: dict[str, Callable[[m.Model, Path], None]] = {
    "check_urdf": _check_urdf, "ign-urdf": _ign_urdf, "ign-sdf": _ign_sdf, "mujoco-urdf": _mujoco_urdf,
    "mujoco-mjcf": _mujoco_mjcf, "urchin": _urchin,
}


@pytest.mark.parametrize("tool", TOOLS)
@pytest.mark.parametrize("body", BODIES)
def test_every_tool_accepts_the_model(body: str, tool: str, tmp_path: Path) -> None:
    TOOLS[tool](model(body, tmp_path), tmp_path)


def test_the_generated_bodies_use_every_joint_kind_and_shape(tmp_path: Path) -> None:
    """The sample is no sample of one kind: its bodies have every joint kind and shape between them."""
    bodies = [model(f"generated{seed}", tmp_path) for seed in range(SAMPLE)]
    kinds = {j.kind for b in bodies for j in b.joints.values()}
    shapes = {s.kind for b in bodies for link in b.links.values() for s in link.collisions}
    assert kinds == set(m.JointKind) and shapes == {m.ShapeKind.BOX, m.ShapeKind.CYLINDER, m.ShapeKind.SPHERE}


# Two transmissions commanding one parameter (a servo bus's goal for two joints), no actuators
# named: the URDF names each transmission's actuator after it (`lifter_actuator`, `tilter_actuator`),
# never twice one name; every tool reads that model, its ros2_control block too.
SHARED = """robot lift { author "tests" }
connection link: serial { baud 115200 }
primitive servo(goal: int in 0..1023) on link pack ">BH" (2, goal)
link base { mass 1  inertia [0.001, 0.001, 0.001] }
link arm { mass 0.2  centre [0.1, 0, 0]  inertia [0.0001, 0.0007, 0.0007] }
link tilt_arm { mass 0.2  centre [0.1, 0, 0]  inertia [0.0001, 0.0007, 0.0007] }
joint lift: revolute base -> arm { limit -1.5..1.5 velocity 2 effort 1 axis [0, 0, 1] }
joint tilt: revolute base -> tilt_arm { limit -1.5..1.5 velocity 2 effort 1 axis [0, 1, 0] at [0, 0, 0.1] }
transmission lifter: lift {
    command position to servo.goal { raw = round(position * 195.3) + 512  position = (raw - 512) / 195.3 }
}
transmission tilter: tilt {
    command position to servo.goal { raw = round(position * 195.3) + 512  position = (raw - 512) / 195.3 }
}
"""


@pytest.mark.parametrize("tool", TOOLS)
def test_every_tool_accepts_two_transmissions_on_one_parameter(tool: str, tmp_path: Path) -> None:
    path = tmp_path / "lift.rdis"
    path.write_text(SHARED, encoding="utf-8")
    compilation = compile_path(str(path))
    assert compilation.model is not None, [d.message for d in compilation.diagnostics.items]
    actuators = [a.get("name") for a in ET.fromstring(to_urdf(compilation.model, "lift.rdis")).iter("actuator")]
    assert actuators == ["lifter_actuator", "tilter_actuator"]
    TOOLS[tool](compilation.model, tmp_path)
    if tool == "check_urdf":  # and with its ros2_control block
        with_block = to_urdf(compilation.model, "lift.rdis", ros2_control_hardware="topic")
        tree = check_urdf(_written(tmp_path, with_block, ".urdf"))
        assert isinstance(tree, Tree) and sorted(tree.edges) == [("base", "arm"), ("base", "tilt_arm")], tree
