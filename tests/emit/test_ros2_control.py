"""`rdisc emit-urdf --ros2-control [mock]`: the `<ros2_control>` block, exact for the arm, agreeing
with the URDF's own joints and transmissions for every body, still read by urdfdom's `check_urdf`;
and each URDF transmission's `mechanicalReduction` and offset where its conversion is a gear ratio."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rdisc.semantics import model as m
from tests.emit.body_tools import EXAMPLES, Tree, check_urdf, model_of, write_twisty

REPO = Path(__file__).resolve().parents[2]
ARM = REPO / "examples" / "arm.rdis"

ARM_LIMITS = [("waist", 2.6), ("shoulder", 1.8), ("elbow", 2.2), ("wrist_pitch", 1.8), ("wrist_roll", 2.6)]
ARM_BLOCK = (
    '  <ros2_control name="arm" type="system">\n'
    "    <!-- The joints through the rdisc ROS 2 node (rdisc emit-ros2): commands on /joint_command, states on"
    " /joint_states, each converted by its transmission there. -->\n"
    "    <hardware>\n"
    "      <plugin>joint_state_topic_hardware_interface/JointStateTopicSystem</plugin>\n"
    '      <param name="joint_commands_topic">/joint_command</param>\n'
    '      <param name="joint_states_topic">/joint_states</param>\n'
    "    </hardware>\n"
    + "".join(
        f'    <joint name="{joint}">\n'
        '      <command_interface name="position">\n'
        f'        <param name="min">{low}</param>\n'
        f'        <param name="max">{high}</param>\n'
        "      </command_interface>\n"
        '      <state_interface name="position" />\n'
        "    </joint>\n"
        for joint, low, high in [*((j, -limit, limit) for j, limit in ARM_LIMITS), ("gripper", -0.2, 1)])
    + "  </ros2_control>\n"
)


def test_the_arm_s_block_is_exact_and_the_rest_is_the_urdf(rdisc) -> None:
    """Six position joints, each bounded by its `limit`, stated by what the servos report: the
    block goes last, and everything before it is the URDF `emit-urdf` writes without it."""
    plain = rdisc("emit-urdf", ARM)
    result = rdisc("emit-urdf", ARM, "--ros2-control")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == plain.stdout.removesuffix("</robot>\n") + ARM_BLOCK + "</robot>\n"


def test_mock_hardware_states_what_it_is_commanded(rdisc, tmp_path: Path) -> None:
    """mock_components/GenericSystem, integrating a commanded velocity: the Create 2's wheels take a
    velocity and state it beside the position their encoders give."""
    result = rdisc("emit-urdf", REPO / "examples" / "create2.rdis", "--ros2-control", "mock")
    assert (result.returncode, result.stderr) == (0, "")
    block = ET.fromstring(result.stdout).find("ros2_control")
    assert block is not None
    hardware = block.find("hardware")
    assert hardware is not None
    assert [(e.tag, e.text, e.attrib) for e in hardware] == [
        ("plugin", "mock_components/GenericSystem", {}), ("param", "true", {"name": "calculate_dynamics"})]
    assert [(j.get("name"), [(i.tag, i.get("name")) for i in j]) for j in block.findall("joint")] == [
        (wheel, [("command_interface", "velocity"), ("state_interface", "position"), ("state_interface", "velocity")])
        for wheel in ("left_wheel_joint", "right_wheel_joint")]


@pytest.fixture(params=[*EXAMPLES, "twisty"], ids=lambda p: p if isinstance(p, str) else p.stem)
def body(request, tmp_path: Path, rdisc) -> tuple[m.Model, Path]:
    """A description with a body, and its URDF with the topic-based block."""
    source = request.param
    if source == "twisty":
        source = tmp_path / "twisty.rdis"
        write_twisty(source)
    out = tmp_path / "out.urdf"
    result = rdisc("emit-urdf", source, "-o", out, "--ros2-control")
    assert (result.returncode, result.stdout, result.stderr) == (0, "", "")
    return model_of(source), out


def test_check_urdf_still_reads_the_tree(body) -> None:
    model, urdf = body
    tree = check_urdf(urdf)
    assert isinstance(tree, Tree), tree
    assert (tree.name, len(tree.edges)) == (model.robot.name, len(model.joints))


QUANTITIES = {"hardware_interface/PositionJointInterface": "position",
              "hardware_interface/VelocityJointInterface": "velocity",
              "hardware_interface/EffortJointInterface": "effort"}


def test_the_block_s_joints_and_interfaces_agree_with_the_urdf(body) -> None:
    """Read back from the file alone: each ros2_control joint is a moving URDF joint with a
    transmission; its command interfaces are that transmission's hardware interfaces, bounded by
    the URDF joint's `<limit>` (lower..upper, ±velocity, ±effort); every joint a transmission
    commands is there."""
    _, urdf = body
    robot = ET.parse(urdf).getroot()
    joints = {j.get("name"): j for j in robot.findall("joint")}
    commanded = {}
    for transmission in robot.findall("transmission"):
        joint = transmission.find("joint")
        assert joint is not None
        named = [QUANTITIES.get(e.text or "") for e in joint.findall("hardwareInterface")]
        if None not in named:
            commanded[joint.get("name")] = named
    block = robot.find("ros2_control")
    assert block is not None and block.get("name") == robot.get("name") and block.get("type") == "system"
    seen = {}
    for joint in block.findall("joint"):
        name = joint.get("name")
        urdf_joint = joints[name]
        assert urdf_joint.get("type") != "fixed"
        limit = urdf_joint.find("limit")
        assert limit is not None
        bounds = {"position": (limit.get("lower"), limit.get("upper")),
                  "velocity": (f"-{limit.get('velocity')}", limit.get("velocity")),
                  "effort": (f"-{limit.get('effort')}", limit.get("effort"))}
        interfaces = joint.findall("command_interface")
        seen[name] = [i.get("name") for i in interfaces]
        for interface in interfaces:
            given = {p.get("name"): p.text for p in interface.findall("param")}
            low, high = bounds[interface.get("name") or ""]
            assert given == ({} if low is None else {"min": low, "max": high})
    assert seen == commanded


def test_a_body_without_transmissions_has_nothing_for_ros2_control(rdisc, tmp_path: Path) -> None:
    source = tmp_path / "still.rdis"
    source.write_text('robot still { description "a body, nothing moves it" }\nlink base { mass 1  inertia [1, 1, 1] }\n',
                      encoding="utf-8")
    result = rdisc("emit-urdf", source, "--ros2-control", "-o", tmp_path / "still.urdf")
    assert (result.returncode, result.stdout) == (1, "")
    assert result.stderr == (f"rdisc emit-urdf: {source}: robot `still` has no transmission: ros2_control has no joint "
                             "to drive (bind one with `transmission NAME: JOINT { command ... }`)\n")
    assert not (tmp_path / "still.urdf").exists()


# ---- the ROS 1 transmissions: a gear ratio as mechanicalReduction ----------------------------------

WRAPPED = """\
robot wrapped { description "a joint measured through a counter that wraps" }
state count: int = 0
connection c: serial { baud 9600 }
primitive go(goal: int in -10000..10000) on c pack "<h" (goal)
link base { mass 1  inertia [1, 1, 1] }
link wheel { mass 0.1  inertia [0.001, 0.001, 0.001] }
link arm { mass 0.1  inertia [0.001, 0.001, 0.001] }
joint spin: continuous base -> wheel { velocity 10  effort 1 }
joint lift: revolute base -> arm { limit -1..1  velocity 1  effort 2 }
transmission counted: spin { measure position from count { raw = round(position * 100) % 65536  position = raw / 100 } }
transmission pushed: lift { command effort to go.goal { raw = round(effort * 2000)  effort = raw / 2000 } }
"""


def _transmissions(text: str) -> dict[str, tuple[str | None, str | None]]:
    """Each transmission's mechanicalReduction and joint offset, as written."""
    found = {}
    for t in ET.fromstring(text).findall("transmission"):
        offset = t.find("joint/offset")
        found[t.get("name")] = (t.findtext("actuator/mechanicalReduction"), None if offset is None else offset.text)
    return found


def test_a_linear_conversion_is_the_mechanical_reduction_and_offset(rdisc) -> None:
    """The arm's `raw = round(position * UNITS_PER_RAD) + CENTRE`: SimpleTransmission's
    `actuator = (joint - offset) * reduction` with reduction 4096 / 2π and offset -2048 / (4096 / 2π) = -π,
    written as the numbers read back exactly; the Create 2's wheels, a velocity in mm/s at a
    36 mm rim: 36, no offset."""
    arm = _transmissions(rdisc("emit-urdf", ARM).stdout)
    reduction = 4096 / (2 * 3.141592653589793)
    assert set(arm.values()) == {(repr(reduction), repr(-2048 / reduction))}
    assert float(repr(-2048 / reduction)) == -math.pi
    create2 = _transmissions(rdisc("emit-urdf", REPO / "examples" / "create2.rdis").stdout)
    assert create2 == {"left_drive": ("36", None), "right_drive": ("36", None)}


def test_an_effort_divides_and_what_is_no_ratio_stays_1(rdisc, tmp_path: Path) -> None:
    """An effort's actuator value is the joint's divided by the reduction (2000 per N m: 1/2000);
    a measure through a counter that wraps (`% 65536`) is no ratio: 1, and the comment says it."""
    source = tmp_path / "wrapped.rdis"
    source.write_text(WRAPPED, encoding="utf-8")
    result = rdisc("emit-urdf", source, "-o", tmp_path / "wrapped.urdf")
    assert (result.returncode, result.stderr) == (0, "")
    text = (tmp_path / "wrapped.urdf").read_text(encoding="utf-8")
    assert _transmissions(text) == {"counted": ("1", None), "pushed": (repr(1 / 2000), None)}
    assert "<!-- measures position from count: raw = round(position * 100) % 65536; position = raw / 100 -->" in text
    assert isinstance(check_urdf(tmp_path / "wrapped.urdf"), Tree)
