"""`rdisc adapters`: the domain adapters, each with its fields, units and ROS paths, and what it is
in every framework rdisc speaks (ROS 1, ROS 2, and the schema a Foxglove session or recording
names); exact text and JSON, a description's own adapters beside the standard ones, an unknown
name refused. Every ROS type it names is one whose ROS 2 definition rdisc holds."""

from __future__ import annotations

import json
from pathlib import Path

from rdisc.lowering.messages import definition
from tests.conftest import run_rdisc

STANDARD = ["DifferentialSpeed", "Range", "Contact", "Battery", "Odometry", "Pose2D", "JointPosition", "JointState",
            "Temperature"]


def test_one_adapter_as_text() -> None:
    result = run_rdisc("adapters", "DifferentialSpeed", "JointState")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == """\
DifferentialSpeed
  The velocity of a differential-drive robot (thesis section 4.11.2): the speed along its heading and the rate \
of turn about its vertical axis. Positive `angular` turns to the left (counter-clockwise seen from above), as in \
ROS (REP 103).
  ROS 1 geometry_msgs/Twist   ROS 2 geometry_msgs/msg/Twist   Foxglove geometry_msgs/msg/Twist (ros2msg, CDR)
  linear   float  m/s    linear.x
  angular  float  rad/s  angular.z

JointState
  The joints of a robot, all at once (an arm, a leg, a pan-tilt head): each joint's name, as in the robot's \
URDF, and its position, in the same order. A description fixes the number of joints by the arrays it gives.
  ROS 1 sensor_msgs/JointState   ROS 2 sensor_msgs/msg/JointState   Foxglove sensor_msgs/msg/JointState \
(ros2msg, CDR)
  name      string[]  -    name
  position  float[]   rad  position
"""


def test_every_standard_adapter_as_json_with_its_three_frameworks() -> None:
    result = run_rdisc("adapters", "--format", "json")
    assert (result.returncode, result.stderr) == (0, "")
    adapters = json.loads(result.stdout)
    assert [a["name"] for a in adapters] == STANDARD
    assert all(a["standard"] for a in adapters)
    contact = adapters[STANDARD.index("Contact")]
    assert contact == {
        "name": "Contact", "standard": True,
        "doc": "A binary contact: a bumper, a cliff or wheel-drop switch, a limit switch.",
        "ros1": "std_msgs/Bool", "ros2": "std_msgs/msg/Bool",
        "foxglove": {"schema": "std_msgs/msg/Bool", "schemaEncoding": "ros2msg", "messageEncoding": "cdr"},
        "fields": [{"name": "contact", "type": "bool", "unit": None, "ros": "data",
                    "doc": "True while the contact is made (the bumper is pressed)."}]}
    for adapter in adapters:  # each type's ROS 2 definition is one rdisc holds, as its nodes and recordings use
        assert adapter["ros2"] == adapter["ros1"].replace("/", "/msg/", 1)
        assert definition(adapter["ros1"]).strip()


def test_a_description_s_own_adapter_is_listed_beside_the_standard_ones(tmp_path: Path) -> None:
    source = tmp_path / "d.rdis"
    source.write_text('robot d { author "tests" }\n/// A gripper\'s opening.\nadapter Opening {\n'
                      '    /// Between the jaws.\n    width: float unit "m"\n}\n', encoding="utf-8")
    result = run_rdisc("adapters", "Opening", "--description", source)
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == ("Opening  (declared by the description)\n  A gripper's opening.\n  no framework message\n"
                             "  width  float  m  -\n")


def test_an_unknown_adapter_is_a_usage_error() -> None:
    result = run_rdisc("adapters", "Twist", "Range", "Pose")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == "rdisc: no adapter `Twist`, `Pose`; `rdisc adapters` lists them\n"


def test_a_description_that_does_not_check_is_said(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("robot {\n", encoding="utf-8")
    result = run_rdisc("adapters", "--description", source)
    assert (result.returncode, result.stdout) == (1, "")
    assert result.stderr == f"rdisc: {source} does not check: `rdisc check {source}` says why\n"
