"""Noise declared on a state variable or a sensor reaches the ROS message of an output that
publishes it as it is (rdisc/semantics/covariance.py `carried`): an Odometry field assigned a
noisy state variable, or a sensor, carries its variance where the field's own noise would."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

import pytest

from tests.emit.test_ros_covariances import _diagonal
from tests.support.nodes import node_of, odometry

TEXT = '''robot wheels { author "t" }
state x: float = 0.0 noise 0.5 "m"
state scaled: float = 0.0 noise 0.5
state speed: float = 0.0 noise 3
connection port: serial { baud 9600 }
primitive read() on port pack "B" (1) unpack "<hhh" { x = out[0]  scaled = out[1]  speed = out[2] }
primitive gyro() on port pack "B" (2) unpack "<f"
sensor turning: float from gyro() cache 100 ms noise 0.25 "rad/s"
interface poll() triggers odom { read() }
output odom: Odometry {
    x = x
    y = scaled / 1000.0
    theta = 0.0
    linear = speed
    angular = turning
    noise linear 0.125
}
'''


def _node(kind: str, tmp_path: Path) -> ModuleType:
    return node_of(TEXT, kind, tmp_path, "carried")


@pytest.mark.parametrize("kind", ["ros1", "ros2"])
def test_a_state_variables_and_a_sensors_noise_reach_the_odometry(kind: str, tmp_path: Path) -> None:
    node = _node(kind, tmp_path)
    msg = odometry()
    node._ros_fill_odom(msg, {"x": 1.0, "y": 0.0, "theta": 0.0, "linear": 0.0, "angular": 0.0})
    # x as it is: its variance; y converted (/ 1000): none carried, 0.
    assert msg.pose.covariance == _diagonal(6, d0=0.25)
    # linear: the field's own noise wins over the state's; angular: the sensor's.
    assert msg.twist.covariance == _diagonal(6, d0=0.015625, d5=0.0625)
