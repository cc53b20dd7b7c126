"""One covariance over several fields of an output (`noise (x, y, theta) [...]`, thesis §7.2.3):
how a pose's errors go together, which a deviation per field cannot say. Checked as every
covariance is (square, symmetric, positive semi-definite: E731, E733), each field once; through
the printer and JSON both ways; and carried into the ROS 1 and ROS 2 nodes' messages at the
fields' places, the off-diagonal values included (an Odometry's 6x6 pose and twist, an Imu's 3x3)."""

from __future__ import annotations

import json
from pathlib import Path
from types import ModuleType, SimpleNamespace

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import through_json
from tests.support.nodes import node_of, odometry, quaternion, vector

HEAD = '''robot wheels { author "t" }
state x: float = 0.0
state speed: float = 0.0
connection port: serial { baud 9600 }
primitive read() on port pack "B" (1) unpack "<hh" { x = out[0] / 1000.0  speed = out[1] / 1000.0 }
interface poll() triggers odom { read() }
'''
POSE = "noise (x, y, theta) [0.04, 0.01, 0.002; 0.01, 0.09, 0; 0.002, 0, 0.25]"
TWIST = "noise (linear, angular) [0.0625, 0.015625; 0.015625, 0.125]"
ODOMETRY = f'''output odom: Odometry {{
    x = x
    y = 0.0
    theta = 0.0
    linear = speed
    angular = 0.0
    {POSE}
    {TWIST}
}}
'''
IMU = '''interface turn() triggers imu { read() }
adapter Turning ros "sensor_msgs/Imu" {
    roll_rate: float unit "rad/s" ros "angular_velocity.x"
    yaw_rate: float unit "rad/s" ros "angular_velocity.z"
    heading: float unit "rad" ros "orientation:yaw"
}
output imu: Turning {
    roll_rate = 0.0
    yaw_rate = speed
    heading = x
    noise (yaw_rate, roll_rate) [0.5, 0.25; 0.25, 0.75]
    noise heading 0.125
}
'''


def errors(tmp_path: Path, text: str) -> list[tuple[str, str, str]]:
    path = tmp_path / "wheels.rdis"
    path.write_text(HEAD + text, encoding="utf-8")
    compilation = compile_path(str(path))
    whole = HEAD + text
    return [(d.code, whole[d.span.start:d.span.end], d.message) for d in compilation.diagnostics.sorted()
            if d.severity == 1]


def test_an_odometry_with_covariances_over_its_pose_and_its_twist_checks(tmp_path: Path) -> None:
    assert errors(tmp_path, ODOMETRY + IMU) == []


@pytest.mark.parametrize(("change", "found"), [
    ((POSE, "noise (x, y, theta) [1, 2, 0; 2, 1, 0; 0, 0, 1]"),
     ("E733", "[1, 2, 0; 2, 1, 0; 0, 0, 1]", ("the covariance of (x, y, theta) is not positive semi-definite: some "
      "combination of its values would have a negative variance"))),
    ((POSE, "noise (x, y, theta) [1, 0; 0, 1]"),
     ("E731", "[1, 0; 0, 1]", "the covariance of (x, y, theta) is 2 by 2, over 3 fields")),
    ((POSE, "noise (x, y) [1, 0.5; 0.25, 1]"),
     ("E731", "[1, 0.5; 0.25, 1]",
      "the covariance of (x, y) is not symmetric: row 2, column 1 is 0.25, row 1, column 2 0.5")),
    ((POSE, "noise (x, x) [1, 0; 0, 1]"), ("E731", "x", "field `x` is named twice in one noise")),
    ((POSE, "noise (x, z) [1, 0; 0, 1]"), ("E731", "z", "adapter `Odometry` has no field `z`")),
    ((TWIST, "noise (linear, theta) [1, 0; 0, 1]"), ("E731", "theta", "the noise of `theta` is given twice")),
    ((TWIST, TWIST + '\n    noise angular 0.1 "rad/s"'), ("E731", "angular", "the noise of `angular` is given twice")),
])
def test_each_refusal_says_what_is_wrong(tmp_path: Path, change: tuple[str, str], found: tuple[str, str, str]) -> None:
    assert ODOMETRY.count(change[0]) == 1
    assert errors(tmp_path, ODOMETRY.replace(change[0], change[1])) == [found]


def test_a_covariance_over_an_array_field_and_another_is_refused(tmp_path: Path) -> None:
    text = ('output odom: JointState {\n    name = ["a", "b"]\n    position = [x, speed]\n'
            "    noise (position, name) [1, 0; 0, 1]\n}\n")
    assert errors(tmp_path, text) == [
        ("E731", "position", ("field `position` is float[]: a covariance over several fields is over numbers, "
         "one value each"))]


def test_the_clause_prints_and_parses_back_alike() -> None:
    first = parse("a.rdis", HEAD + ODOMETRY, Diagnostics())
    printed = print_module(first)
    assert "    noise (x, y, theta) [0.04, 0.01, 0.002; 0.01, 0.09, 0.0; 0.002, 0.0, 0.25]\n" in printed
    assert parse("b.rdis", printed, Diagnostics()).decls == first.decls


def test_it_goes_through_json_and_back(tmp_path: Path) -> None:
    _, built = through_json(HEAD + ODOMETRY, tmp_path, "wheels")
    (output,) = json.loads(built)["domainOutputs"]
    assert output["noise"] == [
        {"fields": ["x", "y", "theta"], "covariance": [[0.04, 0.01, 0.002], [0.01, 0.09, 0], [0.002, 0, 0.25]]},
        {"fields": ["linear", "angular"], "covariance": [[0.0625, 0.015625], [0.015625, 0.125]]}]


def test_json_that_mixes_a_field_and_fields_is_refused(tmp_path: Path) -> None:
    _, built = through_json(HEAD + ODOMETRY, tmp_path, "wheels")
    document = json.loads(built)
    document["domainOutputs"][0]["noise"][0]["field"] = "x"
    (tmp_path / "mixed.json").write_text(json.dumps(document), encoding="utf-8")
    compilation = compile_path(str(tmp_path / "mixed.json"))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E008", "a noise over `fields` (two or more) has a `covariance` only")]


def _node(kind: str, tmp_path: Path) -> ModuleType:
    return node_of(HEAD + ODOMETRY + IMU, kind, tmp_path, "joint")


# An Odometry's covariances, row by row: x, y, z, rotation about x, y, z (REP 103).
POSE_COVARIANCE = [
    0.04, 0.01, 0.0, 0.0, 0.0, 0.002,
    0.01, 0.09, 0.0, 0.0, 0.0, 0.0,
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    0.002, 0.0, 0.0, 0.0, 0.0, 0.25,
]  # fmt: skip
TWIST_COVARIANCE = [
    0.0625, 0.0, 0.0, 0.0, 0.0, 0.015625,
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    0.015625, 0.0, 0.0, 0.0, 0.0, 0.125,
]  # fmt: skip


@pytest.mark.parametrize("kind", ["ros1", "ros2"])
def test_an_odometry_carries_its_pose_s_and_twist_s_covariances_whole(kind: str, tmp_path: Path) -> None:
    node = _node(kind, tmp_path)
    msg = odometry()
    node._ros_fill_odom(msg, {"x": 1.5, "y": 0.0, "theta": 0.0, "linear": 0.25, "angular": 0.0})
    assert (msg.pose.covariance, msg.twist.covariance) == (POSE_COVARIANCE, TWIST_COVARIANCE)


@pytest.mark.parametrize("kind", ["ros1", "ros2"])
def test_an_imu_carries_its_rates_covariance_at_their_axes(kind: str, tmp_path: Path) -> None:
    node = _node(kind, tmp_path)
    msg = SimpleNamespace(orientation=quaternion(), angular_velocity=vector(), linear_acceleration=vector(),
                          orientation_covariance=[0.0] * 9, angular_velocity_covariance=[0.0] * 9,
                          linear_acceleration_covariance=[0.0] * 9)
    node._ros_fill_imu(msg, {"roll_rate": 0.0, "yaw_rate": 0.5, "heading": 0.0})
    assert msg.angular_velocity_covariance == [0.75, 0.0, 0.25,  # about x, y, z: yaw_rate is z, roll_rate x
                                               0.0, 0.0, 0.0,
                                               0.25, 0.0, 0.5]
    assert msg.orientation_covariance == [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.125 * 0.125]
    assert msg.linear_acceleration_covariance == [0.0] * 9


def test_the_simulation_s_odometry_check_takes_x_s_and_y_s_variances_from_one_covariance(tmp_path: Path) -> None:
    """How far an Odometry may be from the simulated base: three deviations of x and y together,
    read from the diagonal of a covariance over (x, y, theta) as from two deviations."""
    from rdisc.sim.odometry import DEVIATIONS, _error

    compilation = compile_path(str(_source(tmp_path)))
    assert compilation.model is not None
    assert _error(compilation.model.outputs["odom"]) == DEVIATIONS * (0.04 + 0.09) ** 0.5


def _source(tmp_path: Path) -> Path:
    path = tmp_path / "wheels.rdis"
    path.write_text(HEAD + ODOMETRY, encoding="utf-8")
    return path
