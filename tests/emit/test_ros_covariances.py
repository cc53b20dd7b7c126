"""The declared noise in ROS messages (rdisc/semantics/covariance.py): an Odometry's and an
Imu's covariances filled by the ROS 1 and ROS 2 nodes' one filling of each output, the variance
(a deviation's square) on the diagonal at the field's place; run in process on the generated
module, with a message of plain namespaces."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType, SimpleNamespace

import pytest

from tests.support.nodes import node_of, odometry, quaternion, vector

ODOMETRY = '''robot wheels { author "t" }
state x: float = 0.0
state speed: float = 0.0
connection port: serial { baud 9600 }
primitive read() on port pack "B" (1) unpack "<hh" { x = out[0] / 1000.0  speed = out[1] / 1000.0 }
interface poll() triggers odom { read() }
output odom: Odometry {
    x = x
    y = 0.0
    theta = 0.0
    linear = speed
    angular = 0.0
    noise x 0.02 "m"
    noise theta 0.5 "rad"
    noise angular 0.25
}
'''
IMU = '''interface turn() triggers imu { read() }
adapter Turning ros "sensor_msgs/Imu" {
    rate: float unit "rad/s" ros "angular_velocity.z"
    heading: float unit "rad" ros "orientation:yaw"
}
output imu: Turning {
    rate = speed
    heading = x
    noise rate 0.5 "rad/s"
    noise heading [0.125]
}
'''


def _node(kind: str, tmp_path: Path) -> ModuleType:
    return node_of(ODOMETRY + IMU, kind, tmp_path, "wheels")


def _diagonal(side: int, **at: float) -> list[float]:
    values = [0.0] * side * side
    for place, value in at.items():
        index = int(place.removeprefix("d"))
        values[index * side + index] = value
    return values


@pytest.mark.parametrize("kind", ["ros1", "ros2"])
def test_an_odometry_carries_its_fields_variances(kind: str, tmp_path: Path) -> None:
    node = _node(kind, tmp_path)
    msg = odometry()
    node._ros_fill_odom(msg, {"x": 1.5, "y": 0.0, "theta": 0.0, "linear": 0.25, "angular": 0.0})
    assert msg.pose.pose.position.x == 1.5
    assert msg.pose.covariance == _diagonal(6, d0=0.02 * 0.02, d5=0.25)  # x, then yaw
    assert msg.twist.covariance == _diagonal(6, d5=0.0625)  # the turn rate: angular z


@pytest.mark.parametrize("kind", ["ros1", "ros2"])
def test_an_imu_carries_its_fields_variances(kind: str, tmp_path: Path) -> None:
    node = _node(kind, tmp_path)
    msg = SimpleNamespace(orientation=quaternion(), angular_velocity=vector(), linear_acceleration=vector(),
                          orientation_covariance=[0.0] * 9, angular_velocity_covariance=[0.0] * 9,
                          linear_acceleration_covariance=[0.0] * 9)
    node._ros_fill_imu(msg, {"rate": 0.5, "heading": 0.0})
    assert msg.angular_velocity.z == 0.5
    assert msg.orientation_covariance == _diagonal(3, d2=0.125)  # a covariance given as written
    assert msg.angular_velocity_covariance == _diagonal(3, d2=0.25)
    assert msg.linear_acceleration_covariance == [0.0] * 9  # no noise declared: left as it was
