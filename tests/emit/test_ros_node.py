"""The node `rdisc emit-ros` writes, without ROS: it is the generated driver with the
bridge in place of its command line, it imports the adapters' ROS messages and reads
and writes their fields in its own code (nothing is looked up from a string when it
runs), and it is clean for ruff and `mypy --strict`. (tests/ros runs it against a
real roscore.)"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.emit.python import to_python
from rdisc.emit.ros import to_ros

REPO = Path(__file__).resolve().parents[2]


def _node(example: str) -> tuple[str, str]:
    compilation = compile_path(str(REPO / "examples" / f"{example}.rdis"))
    assert compilation.model is not None
    name = f"{example}.rdis"
    return (to_ros(compilation.model, name, sources=compilation.sources),
            to_python(compilation.model, name, sources=compilation.sources))


def test_the_node_is_the_driver_with_a_ros_main() -> None:
    node, driver = _node("create")
    body = driver.removesuffix('if __name__ == "__main__":\n    sys.exit(main())\n')
    assert node.startswith(body)
    assert node.endswith('if __name__ == "__main__":\n    sys.exit(ros_main())\n')
    assert "import geometry_msgs.msg as geometry_msgs_msg  # type: ignore" in node
    assert ('def _ros_read_set_velocity(msg: Any) -> dict[str, Any]:\n'
            '    """The fields of input set_velocity from a geometry_msgs/Twist."""\n'
            '    return {"linear": msg.linear.x, "angular": msg.angular.z}\n') in node
    assert ('def _ros_fill_detect_bump(msg: Any, contents: dict[str, Any]) -> None:\n'
            '    """A sensor_msgs/Range filled with the fields of output detect_bump."""\n'
            '    msg.range = contents["distance"]\n') in node
    bridge = node[len(body):]
    for dynamic in ("getattr", "setattr", "import_module", "__import__", "eval(", "exec("):
        assert dynamic not in bridge, dynamic


LISTS_AND_YAW = """\
robot arm { author "tests" }
state angle: float = 0.0
connection c: serial { baud 9600 }
primitive go(goal: int) on c pack ">h" (goal)
interface move(angle: float) { go(round(angle * 100)) }
input joint: JointPosition -> move(position)
output pose: Odometry { x = 0.0  y = 0.0  theta = angle  linear = 0.0  angular = 0.0 }
output where: JointPosition { name = "j1"  position = angle }
"""


def test_list_items_and_yaw_are_code_too(tmp_path: Path) -> None:
    source = tmp_path / "arm.rdis"
    source.write_text(LISTS_AND_YAW, encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None
    node = to_ros(compilation.model, "arm.rdis", sources=compilation.sources)
    assert ('    return {"name": _ros_item(msg.name, 0), "position": _ros_item(msg.position, 0)}\n') in node
    assert '    _ros_set_yaw(msg.pose.pose.orientation, contents["theta"])\n' in node
    assert '    msg.position = _ros_with(msg.position, 0, contents["position"])\n' in node


SETTINGS = """\
robot servos { author "tests" }
setting BAUD: int in 9600..1000000 = 57600
setting ID: int in 0..253 = 1
connection bus: serial { baud BAUD startup hello(ID) }
primitive ping(id: int) on bus pack "BB" (0xFF, id)
interface hello(id: int) { ping(id) }
"""


def _settings_node(tmp_path: Path) -> str:
    source = tmp_path / "servos.rdis"
    source.write_text(SETTINGS, encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None
    return to_ros(compilation.model, "servos.rdis", sources=compilation.sources)


def test_settings_are_read_as_private_parameters(tmp_path: Path) -> None:
    assert """\
    given = (p.name for p in _DEVICE.settings if rospy.has_param(f"~{p.name}"))
    settings = {name: rospy.get_param(f"~{name}") for name in given}
    robot = Servos(timeout=float(rospy.get_param("~timeout", 1.0)))
    robot.on_output(on_output)
    robot.on_error(on_error)
    if rospy.get_param("~trace", False):
        robot.on_io(on_io)
    robot.open(ports, settings=settings)
    rospy.on_shutdown(robot.close)
""" in _settings_node(tmp_path)


@pytest.mark.parametrize("example", ["create", "servos"])
def test_ruff_and_mypy_strict_find_nothing(example: str, tmp_path: Path) -> None:
    path = tmp_path / f"{example}_node.py"
    path.write_text(_node(example)[0] if example == "create" else _settings_node(tmp_path), encoding="utf-8")
    for command in (["ruff", "check", "--isolated", "--no-cache"],
                    ["mypy", "--strict", "--no-error-summary", "--cache-dir", str(tmp_path / "cache")]):
        done = subprocess.run([sys.executable, "-m", *command, str(path)], capture_output=True, text=True,
                              check=False, cwd=tmp_path)
        assert done.returncode == 0, done.stdout + done.stderr


def test_without_ros_the_node_says_what_is_missing(tmp_path: Path) -> None:
    """Run by a python without ROS (isolated, no site packages: no rospy whatever is
    installed), the node says so and ends with exit status 2, not a traceback."""
    node = tmp_path / "create_node.py"
    node.write_text(_node("create")[0], encoding="utf-8")
    done = subprocess.run([sys.executable, "-I", "-S", str(node), "--port", "loop://"], capture_output=True,
                          text=True, check=False, cwd=tmp_path, timeout=60)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr.splitlines() == [
        (f"create_node.py: ROS 1 is not here: {sys.executable} has no rospy; run the node with the python3 of a "
        "ROS 1 installation (Debian: apt install python3-rospy)"),
        "create_node.py: geometry_msgs/Twist is not a ROS message here: install its package",
        "create_node.py: sensor_msgs/Range is not a ROS message here: install its package",
        "create_node.py: std_msgs/String is not a ROS message here: install its package",
    ]
