"""`rdisc emit-ros2` without DDS: the node is clean for ruff and `mypy --strict` (the Create, and the
arm with its body), says what is missing where cyclonedds is not, refuses a command line it does not
take, and a description naming a message rdisc has no ROS 2 definition of is refused when emitted."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import run_rdisc

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def nodes(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The ROS 2 nodes of the Create and of the arm, written once for the module."""
    folder = tmp_path_factory.mktemp("nodes")
    written = {}
    for example in ("create", "arm"):
        written[example] = folder / f"{example}_node.py"
        done = run_rdisc("emit-ros2", REPO / "examples" / f"{example}.rdis", "-o", written[example])
        assert done.returncode == 0, done.stderr
    return written


def test_ruff_and_mypy_strict_find_nothing(nodes: dict[str, Path], tmp_path: Path, mypy_cache: Path) -> None:
    for command in (["ruff", "check", "--isolated", "--no-cache"],
                    ["mypy", "--strict", "--no-error-summary", "--cache-dir", str(mypy_cache)]):
        done = subprocess.run([sys.executable, "-m", *command, *map(str, nodes.values())], capture_output=True,
                              text=True, check=False, cwd=tmp_path)
        assert done.returncode == 0, done.stdout + done.stderr


def test_without_cyclonedds_the_node_says_so(nodes: dict[str, Path], tmp_path: Path) -> None:
    """Run by a python without site packages (no cyclonedds whatever is installed): exit status 2, one line."""
    node = nodes["create"]
    done = subprocess.run([sys.executable, "-I", "-S", str(node), "--ros-args", "-p", "port:=loop://"],
                          capture_output=True, text=True, check=False, cwd=tmp_path, timeout=60)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr.splitlines() == [
        (f"create_node.py: Cyclone DDS is not here: {sys.executable} cannot import cyclonedds; pip install "
        "cyclonedds (a ROS 2 installation is not needed)")]


@pytest.mark.parametrize(("words", "said"), [
    (["--port", "x"], ("create_node.py: `--port` is no option of this node: give --ros-args -p NAME:=VALUE (port, "
                      "timeout, trace, publish_description, joint_states_rate, sim or a setting) and -r FROM:=TO")),
    (["--ros-args", "-p", "port=x"], "create_node.py: -p `port=x` is not NAME:=VALUE"),
    (["--ros-args", "--log-level", "debug"], ("create_node.py: --ros-args --log-level: this node takes -p NAME:=VALUE "
                                             "and -r FROM:=TO")),
    (["--ros-args", "-p", "port:=a", "-p", "port:=b"], "create_node.py: -p port given twice"),
])
def test_a_command_line_it_does_not_take_is_refused(nodes: dict[str, Path], tmp_path: Path, words: list[str],
                                                    said: str) -> None:
    done = subprocess.run([sys.executable, str(nodes["create"]), *words], capture_output=True, text=True,
                          check=False, cwd=tmp_path, timeout=60)
    assert (done.returncode, done.stderr.splitlines()) == (2, [said])


def test_a_domain_id_out_of_range_is_refused(nodes: dict[str, Path], tmp_path: Path) -> None:
    pytest.importorskip("cyclonedds")
    done = subprocess.run([sys.executable, str(nodes["create"]), "--ros-args", "-p", "port:=loop://"],
                          capture_output=True, text=True, check=False, cwd=tmp_path, timeout=60,
                          env=dict(os.environ, ROS_DOMAIN_ID="233"))
    assert (done.returncode, done.stderr.splitlines()) == (
        2, ["create_node.py: ROS_DOMAIN_ID is '233': give a domain from 0 to 232"])


def test_a_message_without_a_ros_2_definition_is_refused(tmp_path: Path) -> None:
    source = tmp_path / "odd.rdis"
    source.write_text('robot odd { author "tests" }\nstate v: float = 0.0\nconnection c: serial { baud 9600 }\n'
                      'adapter Level ros "std_msgs/Float64" { level: float ros "data" }\n'
                      'adapter Far ros "sensor_msgs/Range" { far: float ros "ranges[0]" }\n'
                      "output level: Level { level = v }\noutput far: Far { far = v }\n", encoding="utf-8")
    done = run_rdisc("emit-ros2", source, "-o", tmp_path / "odd_node.py")
    assert done.returncode == 1
    assert done.stderr.splitlines()[-1] == (
        f"rdisc emit-ros2: {source}: adapter Level: rdisc has no ROS 2 definition of std_msgs/Float64 (it has "
        "builtin_interfaces/Time, geometry_msgs/Point, geometry_msgs/Pose, geometry_msgs/Pose2D, "
        "geometry_msgs/PoseWithCovariance, geometry_msgs/Quaternion, geometry_msgs/Twist, "
        "geometry_msgs/TwistWithCovariance, geometry_msgs/Vector3, nav_msgs/Odometry, sensor_msgs/BatteryState, "
        "sensor_msgs/Imu, sensor_msgs/JointState, sensor_msgs/Range, sensor_msgs/Temperature, std_msgs/Bool, "
        "std_msgs/Header, "
        "std_msgs/String); adapter Far, field far: sensor_msgs/Range has no member `ranges` (`ranges[0]`)")
    assert not (tmp_path / "odd_node.py").exists()
