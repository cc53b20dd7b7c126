"""A ROS 2 node's body follows its settings: `-p TRACK:=0.3` publishes as robot_description the URDF
`rdisc emit-urdf --set TRACK=0.3` writes (the node has rdisc build its body again from the canonical
JSON it carries), received by an independent Cyclone DDS reader (reader.py) and decoded by rosbags.
A value out of the setting's range, one the body refuses, or rdisc missing is said, exit status 2:
never a robot_description at other values than the device's. The device is pyserial's `loop://`."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import run_rdisc

from tests.ros2.loopback import first_messages
from tests.semantics.test_body_settings import DRIVE

HERE = Path(__file__).resolve().parent


def _node(folder: Path, text: str = DRIVE) -> tuple[Path, Path]:
    source, node_file = folder / "rover.rdis", folder / "rover_node.py"
    source.write_text(text, encoding="utf-8")
    done = run_rdisc("emit-ros2", source, "-o", node_file)
    assert done.returncode == 0, done.stderr
    return source, node_file


@pytest.fixture(scope="module")
def rover(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """DRIVE and its ROS 2 node, written once for the module."""
    return _node(tmp_path_factory.mktemp("rover"))


def test_robot_description_is_the_body_at_the_settings_given(rover: tuple[Path, Path]) -> None:
    pytest.importorskip("cyclonedds")
    typesys = pytest.importorskip("rosbags.typesys")
    source, node_file = rover
    urdf = run_rdisc("emit-urdf", source, "--set", "TRACK=0.3")
    assert (urdf.returncode, urdf.stderr) == (0, "")
    cdr = first_messages(node_file, ["port:=loop://", "TRACK:=0.3"], {"robot_description": "std_msgs/msg/String"},
                         seed=131)["robot_description"]
    store = typesys.get_typestore(typesys.Stores.ROS2_JAZZY)
    published = store.deserialize_cdr(bytes.fromhex(cdr), "std_msgs/msg/String").data
    assert published == urdf.stdout
    assert '<origin xyz="0 0.15 0.036" rpy="0 0 0" />' in published


@pytest.mark.parametrize(("text", "value", "isolated", "said"), [
    (None, "3", False, "rover_node.py: rover: setting TRACK is 3.0, outside 0.1..1.0"),
    (DRIVE.replace("angular * TRACK / 2", "angular * 0.235 / 2"), "0.3", False,
     ("rover_node.py: robot_description at TRACK = 0.3: E613 a counter-clockwise command of 0.5 rad/s to input `go` "
     "turns the body's base at 0.3933 rad/s: the input gives the wheels' speeds as if they were 0.236 m apart, the "
     "body's wheel joints are 0.3 m apart")),
    (None, "0.3", True, (f"rover_node.py: robot_description at TRACK = 0.3 is the body built again by rdisc, which "
     f"{sys.executable} cannot import (No module named 'rdisc'): put rdisc on PYTHONPATH, or give "
     "publish_description false")),
])
def test_a_body_the_node_cannot_build_at_the_value_given_is_said(rover: tuple[Path, Path], tmp_path: Path,
                                                                text: str | None, value: str, isolated: bool,
                                                                said: str) -> None:
    """DRIVE's node (None), or one whose input turns the body with a constant wheel base (E613 at 0.3)."""
    _, node_file = rover if text is None else _node(tmp_path, text)
    python = [sys.executable, "-I", "-S"] if isolated else [sys.executable]
    done = subprocess.run([*python, str(node_file), "--ros-args", "-p", "port:=loop://", "-p", f"TRACK:={value}"],
                          capture_output=True, text=True, check=False, cwd=tmp_path, timeout=60)
    assert (done.returncode, done.stdout, done.stderr.splitlines()) == (2, "", [said])


def test_sim_builds_the_body_at_the_settings_given(rover: tuple[Path, Path]) -> None:
    """`sim:=true`'s simulation (the node's own function, run in process) is the body at the values given."""
    pytest.importorskip("mujoco")
    spec = importlib.util.spec_from_file_location("rover_node", rover[1])
    assert spec is not None and spec.loader is not None
    node = importlib.util.module_from_spec(spec)
    sys.modules["rover_node"] = node  # its dataclasses look their module up
    try:
        spec.loader.exec_module(node)
        at = {given: node._ros_simulation(settings).model.joints["left_joint"].origin.xyz
              for given, settings in (("default", {}), ("given", {"TRACK": 0.3}))}
    finally:
        del sys.modules["rover_node"]
    assert at == {"default": (0, 0.1175, 0.036), "given": (0, 0.15, 0.036)}
