"""The node `rdisc emit-ros` writes, without ROS: it is the generated driver with the
bridge in place of its command line, it imports the adapters' ROS messages and reads
and writes their fields in its own code (nothing is looked up from a string when it
runs), and it is clean for ruff and `mypy --strict`. (tests/ros runs it against a
real roscore.) A description with a body gives the node its URDF and joint states."""

from __future__ import annotations

import ast
import importlib.util
import math
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest
from conftest import run_rdisc

from rdisc.compile import compile_path, compile_text
from rdisc.emit.canonical import to_json
from rdisc.emit.python import to_python
from rdisc.emit.ros import to_ros
from rdisc.emit.urdf import to_urdf

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
    assert node.endswith('if __name__ == "__main__":\n    sys.exit(command_line(ros_main))  # SIGINT and SIGTERM '
                         'handled from here: 130 or 143, no traceback\n')
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


def _ruff_and_mypy_strict_find_nothing(path: Path, tmp_path: Path, mypy_cache: Path) -> None:
    for command in (["ruff", "check", "--isolated", "--no-cache"],
                    ["mypy", "--strict", "--no-error-summary", "--cache-dir", str(mypy_cache)]):
        done = subprocess.run([sys.executable, "-m", *command, str(path)], capture_output=True, text=True,
                              check=False, cwd=tmp_path)
        assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.parametrize("example", ["create", "servos"])
def test_ruff_and_mypy_strict_find_nothing(example: str, tmp_path: Path, mypy_cache: Path) -> None:
    path = tmp_path / f"{example}_node.py"
    path.write_text(_node(example)[0] if example == "create" else _settings_node(tmp_path), encoding="utf-8")
    _ruff_and_mypy_strict_find_nothing(path, tmp_path, mypy_cache)


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


def _description_constant(node: str) -> str:
    """The value of the node's `_ROS_DESCRIPTION`, read as Python reads it."""
    (value,) = [n.value for n in ast.parse(node).body
                if isinstance(n, ast.Assign) and [ast.unparse(t) for t in n.targets] == ["_ROS_DESCRIPTION"]]
    text = ast.literal_eval(value)
    assert isinstance(text, str)
    return text


def test_a_body_gives_the_node_its_urdf_and_joint_states() -> None:
    """The arm's node carries `rdisc emit-urdf`'s URDF, sets it as robot_description unless told
    not to, and publishes each measured joint's position, converted from its servo's state."""
    compilation = compile_path(str(REPO / "examples" / "arm.rdis"))
    assert compilation.model is not None
    node = _node("arm")[0]
    assert _description_constant(node) == to_urdf(compilation.model, "arm.rdis")
    assert ('    without_signals(lambda: rospy.init_node(ROBOT))\n'
            '    if rospy.get_param("~publish_description", True):\n'
            '        rospy.set_param("robot_description", _ROS_DESCRIPTION)\n'
            '    joint_states_rate = rospy.get_param("~joint_states_rate", 20.0)\n') in node  # the bus's 20 Hz
    conversion = "(state[\"present\"][{}] - 2048) / 651.8986469044033,"
    assert ('_ROS_JOINTS = (\n    "waist",\n    "shoulder",\n    "elbow",\n    "wrist_pitch",\n    "wrist_roll",\n'
            '    "gripper",\n)\n') in node
    assert ("    return (\n        [\n" + "".join(f"            {conversion.format(i)}\n" for i in range(6))
            + "        ],\n        [],  # no velocity\n        [],  # no effort\n    )\n") in node
    assert '    joint_states = rospy.Publisher("joint_states", sensor_msgs_msg.JointState, queue_size=10)\n' in node
    assert "    without_signals(lambda: rospy.Timer(rospy.Duration(1.0 / joint_states_rate), publish_joint_states))\n" in node


MIXED = """\
robot mixer { author "tests" }
state ticks: int = 0
state speed: float = 0.0
state torque: int[2]
connection c: serial { baud 9600 }
primitive poll() on c pack "B" (1) unpack ">hfhh" { ticks = out[0]  speed = out[1]  torque = [out[2], out[3]] }
link base {}
link wheel { mass 1  inertia [0.1, 0.1, 0.1] }
link arm { mass 1  inertia [0.1, 0.1, 0.1] }
link idle { mass 1  inertia [0.1, 0.1, 0.1] }
joint spin: continuous base -> wheel { axis [0, 1, 0] velocity 10 effort 1 }
joint lift: revolute base -> arm { limit -1..1 velocity 2 effort 3 }
joint rest: revolute base -> idle { limit -1..1 velocity 2 effort 3 }
transmission drive: spin { measure velocity from speed { raw = velocity / 2.5  velocity = raw * 2.5 } }
transmission hoist: lift {
    measure position from ticks { raw = round(position * 100)  position = raw / 100 }
    measure effort from torque[1] { raw = round(effort * 10)  effort = raw / 10 }
}
"""


def _emitted_node(tmp_path: Path, text: str = MIXED, name: str = "mixer") -> Path:
    """The node `rdisc emit-ros` writes for `text` (the mixer's description unless said)."""
    source = tmp_path / f"{name}.rdis"
    source.write_text(text, encoding="utf-8")
    node = tmp_path / f"{name}_node.py"
    done = run_rdisc("emit-ros", source, "-o", node)
    assert done.returncode == 0, done.stderr
    return node


def test_joint_states_convert_what_each_joint_measures(tmp_path: Path) -> None:
    """Each measured joint once, in the body's order (`rest` measures nothing: left out); each
    quantity some joint measures is a list over all of them, NaN where a joint does not measure
    it; the conversions run as compiled, with the helper one of them needs (`_mul`) in the node."""
    path = _emitted_node(tmp_path)
    spec = importlib.util.spec_from_file_location("mixer_node", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["mixer_node"] = module  # dataclasses look their module up by name
    try:
        spec.loader.exec_module(module)  # the node imports rospy only in ros_main
    finally:
        del sys.modules["mixer_node"]
    assert module._ROS_JOINTS == ("spin", "lift")
    position, velocity, effort = module._ros_joint_states({"ticks": -157, "speed": 1.5, "torque": (7, -23)})
    assert (math.isnan(position[0]), position[1]) == (True, -1.57)
    assert (velocity[0], math.isnan(velocity[1])) == (3.75, True)
    assert (math.isnan(effort[0]), effort[1]) == (True, -2.3)
    text = path.read_text(encoding="utf-8")
    assert "            _mul(state[\"speed\"], 2.5),\n" in text
    assert 'rospy.get_param("~joint_states_rate", 10.0)' in text  # no periodic work: joint_state_publisher's rate


def test_a_body_measuring_nothing_gives_only_the_description(tmp_path: Path) -> None:
    node = _emitted_node(tmp_path, MIXED[: MIXED.index("transmission")]).read_text(encoding="utf-8")
    assert 'rospy.set_param("robot_description", _ROS_DESCRIPTION)' in node
    assert "joint_states" not in node and "_ros_joint_states" not in node


def test_the_node_of_a_body_is_clean_for_ruff_and_mypy_strict(tmp_path: Path, mypy_cache: Path) -> None:
    path = _emitted_node(tmp_path)
    _ruff_and_mypy_strict_find_nothing(path, tmp_path, mypy_cache)


def test_a_body_s_node_can_simulate_it_from_the_json_it_carries(tmp_path: Path) -> None:
    """For `~sim` the node carries the description as `rdisc build` writes it; rdisc's JSON
    importer rebuilds the same Model from it (its canonical JSON again byte for byte), and the
    node's `_ros_simulation` makes the MuJoCo simulation of that body on the wall clock."""
    pytest.importorskip("mujoco")
    compilation = compile_path(str(REPO / "examples" / "create2.rdis"))
    assert compilation.model is not None
    path = tmp_path / "create2_node.py"
    path.write_text(to_ros(compilation.model, "create2.rdis", sources=compilation.sources), encoding="utf-8")
    spec = importlib.util.spec_from_file_location("create2_node", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["create2_node"] = module  # dataclasses look their module up by name
    try:
        spec.loader.exec_module(module)
        assert module._ROS_CANONICAL == to_json(compilation.model)
        again = compile_text("create2.json", module._ROS_CANONICAL)
        assert again.model is not None and not again.diagnostics.items
        assert to_json(again.model) == module._ROS_CANONICAL
        simulation = module._ros_simulation()
    finally:
        del sys.modules["create2_node"]
    assert (simulation.realtime, list(simulation.model.joints)) == (True, list(compilation.model.joints))
    node = path.read_text(encoding="utf-8")
    assert ('    sim = rospy.get_param("~sim", False)\n'
            '    if not isinstance(sim, bool):\n'
            '        raise _ros_refuse([f"~sim is {sim!r}: give true (simulate the body) or false (the device)"])\n'
            '    simulation = _ros_simulation() if sim else None\n') in node
    assert "on_io=on_io if rospy.get_param(\"~trace\", False) else None, sim=simulation)\n" in node


def test_a_node_without_a_body_has_nothing_to_simulate() -> None:
    node = _node("create")[0]
    assert "~sim" not in node and "_ROS_CANONICAL" not in node and "rdisc" not in node.split("def ros_main")[1]


COMMANDED = """\
robot commander { author "tests" }
connection c: serial { baud 9600 }
primitive move(speed: int in -100..100 unit "count", gain: int = 3) on c pack ">bB" (speed, gain)
primitive both(a: int unit "count", b: int) on c pack ">bb" (a, b)
link base {}
link wheel { mass 1  inertia [0.1, 0.1, 0.1] }
link arm { mass 1  inertia [0.1, 0.1, 0.1] }
joint spin: continuous base -> wheel { axis [0, 1, 0] velocity 10 effort 1 }
joint lift: revolute base -> arm { limit -1..1 velocity 2 effort 3 }
transmission drive: spin { command velocity to move.speed { raw = round(velocity * 10)  velocity = raw / 10 } }
transmission hoist: lift { command position to both.a { raw = round(position * 100)  position = raw / 100 } }
"""


class _Recorder:
    """A robot that records the calls joint_command makes."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, tuple[object, ...]]] = []

    def call_primitive(self, name: str, *args: object) -> None:
        self.calls.append((name, args))


def _commands(node: Path, messages: list[dict[str, list[object]]]) -> tuple[list[tuple[str, tuple[object, ...]]],
                                                                             list[str]]:
    """The calls and the reported errors of the node's _ros_joint_command for each message."""
    spec = importlib.util.spec_from_file_location("commander_node", node)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["commander_node"] = module
    try:
        spec.loader.exec_module(module)
    finally:
        del sys.modules["commander_node"]
    robot, reported = _Recorder(), []
    for fields in messages:
        msg = SimpleNamespace(**{"name": [], "position": [], "velocity": [], "effort": [], **fields})
        module._ros_joint_command(robot, msg, lambda err: reported.append(f"{type(err).__name__}: {err}"))
    return robot.calls, reported


def test_joint_command_calls_each_target_its_transmissions_bind_fully(tmp_path: Path) -> None:
    """`move` is reachable (speed bound, gain its default); `both` is not (b unbound), so `lift`
    is no joint a command takes; a velocity missing is reported and nothing is sent."""
    node = _emitted_node(tmp_path, COMMANDED, "commander")
    calls, reported = _commands(node, [
        {"name": ["spin"], "velocity": [-4.26]},
        {"name": ["spin"], "position": [1.0]},
        {"name": ["lift", "spin"], "position": [0.5, 0.0], "velocity": [0.0, 2.0]},  # parallel to the names
    ])
    assert calls == [("move", (-43, 3)), ("move", (20, 3))]
    assert reported == ["RdisValueError: joint_command: move: no velocity of spin",
                        "RdisValueError: joint_command: no command takes lift"]


def test_joint_command_refuses_a_message_that_is_not_one_value_a_name(tmp_path: Path) -> None:
    """A JointState's positions, velocities and efforts are one a name, or none; a name is given
    once. Anything else is reported and nothing of it sent (the extra velocity was dropped and the
    last of a repeated name taken). A flood of names costs one report of bounded length."""
    node = _emitted_node(tmp_path, COMMANDED, "commander")
    calls, reported = _commands(node, [
        {"name": ["spin"], "velocity": [1.0, 2.0]},
        {"name": ["spin", "lift"], "position": [0.5]},
        {"name": ["spin", "spin"], "velocity": [1.0, 2.0]},
        {"name": ["spin"] * 12_000, "velocity": [1.0] * 12_000},
        {"name": [f"j{i}" for i in range(12_000)]},
        {"name": ["x" * 100_000]},
    ])
    assert calls == []
    assert reported == [
        "RdisValueError: joint_command: 2 velocity values for 1 joint names (one for each, or none)",
        "RdisValueError: joint_command: 1 position values for 2 joint names (one for each, or none)",
        "RdisValueError: joint_command: spin is named twice",
        "RdisValueError: joint_command: spin is named twice",
        "RdisValueError: joint_command: no command takes j0, j1, j2, j3, j4 and 11995 more",
        f"RdisValueError: joint_command: no command takes {'x' * 37}...",
    ]


def test_the_create_2_s_wheels_are_drive_direct(tmp_path: Path) -> None:
    """Both wheels' velocities (rad/s) are one drive_direct of mm/s, right first as it takes them."""
    node = tmp_path / "create2_node.py"
    node.write_text(_node("create2")[0], encoding="utf-8")
    calls, reported = _commands(node, [{"name": ["left_wheel_joint", "right_wheel_joint"], "velocity": [5.0, -2.0]},
                                       {"name": ["left_wheel_joint"], "velocity": [5.0]}])
    assert calls == [("drive_direct", (-72, 180))]
    assert reported == [("RdisValueError: joint_command: drive_direct takes right_wheel_joint, left_wheel_joint "
                         "together; missing: right_wheel_joint")]
