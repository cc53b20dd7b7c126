"""The declared noise on the wire (thesis §7.2.3): the ROS 2 node `rdisc emit-ros2` writes, run as a
process, publishes each output's covariances as the description declares them, received by an
independent Cyclone DDS reader in another process (reader.py: types from rosbags' definitions) and
decoded by rosbags. An Odometry's pose and twist covariances carry a sensor's noise (`x = x_m`), a
state variable's (`linear = speed`) and the fields' own; an Imu (a description's own adapter) its
orientation and angular velocity variances, a covariance given as a matrix as it is; every other
element is 0, exactly. The device is pyserial's `loop://`: each request comes back as its reply."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import run_rdisc

from tests.ros2.loopback import first_messages

pytest.importorskip("cyclonedds")
typesys = pytest.importorskip("rosbags.typesys")

HERE = Path(__file__).resolve().parent

DESCRIPTION = """robot wheels { author "tests" }
state speed: float = 0.0 noise 0.1 "m/s"
connection port: serial { baud 115200  threading single at 20 Hz }
primitive position() on port pack "<f" (1.5) unpack "<f"
sensor x_m: float from position() cache 100 ms noise 0.05 "m"
primitive velocity() on port pack "<f" (0.25) unpack "<f" { speed = out[0] }
interface poll() periodic triggers odom, imu { velocity() }
output odom: Odometry {
    x = x_m  y = 0.0  theta = 0.0  linear = speed  angular = 0.0
    noise theta 0.5 "rad"
    noise angular 0.25
}
adapter Turning ros "sensor_msgs/Imu" {
    rate: float unit "rad/s" ros "angular_velocity.z"
    heading: float unit "rad" ros "orientation:yaw"
}
output imu: Turning { rate = speed  heading = 0.0  noise rate 0.5 "rad/s"  noise heading [0.125] }
"""


def _diagonal(side: int, **at: float) -> list[float]:
    """A side-by-side matrix, row after row, 0 but at the diagonal places given (`d0=...`)."""
    rows = [0.0] * (side * side)
    for place, value in at.items():
        index = int(place[1:])
        rows[index * side + index] = value
    return rows


def test_the_declared_covariances_arrive_over_dds(tmp_path: Path) -> None:
    source, node_file = tmp_path / "wheels.rdis", tmp_path / "wheels_node.py"
    source.write_text(DESCRIPTION, encoding="utf-8")
    done = run_rdisc("emit-ros2", source, "-o", node_file)
    assert done.returncode == 0, done.stderr
    got = first_messages(node_file, ["port:=loop://"],
                         {"odom": "nav_msgs/msg/Odometry", "imu": "sensor_msgs/msg/Imu"}, seed=97)
    store = typesys.get_typestore(typesys.Stores.ROS2_JAZZY)
    odom = store.deserialize_cdr(bytes.fromhex(got["odom"]), "nav_msgs/msg/Odometry")
    assert (odom.pose.pose.position.x, odom.twist.twist.linear.x) == (1.5, 0.25)
    assert list(odom.pose.covariance) == _diagonal(6, d0=0.05 ** 2, d5=0.5 ** 2)
    assert list(odom.twist.covariance) == _diagonal(6, d0=0.1 ** 2, d5=0.25 ** 2)
    imu = store.deserialize_cdr(bytes.fromhex(got["imu"]), "sensor_msgs/msg/Imu")
    assert imu.angular_velocity.z == 0.25
    assert list(imu.orientation_covariance) == _diagonal(3, d2=0.125)
    assert list(imu.angular_velocity_covariance) == _diagonal(3, d2=0.5 ** 2)
    assert list(imu.linear_acceleration_covariance) == [0.0] * 9
