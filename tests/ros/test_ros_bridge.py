"""The ROS bridge against a real roscore: `rdisc emit-ros` of the Create (and of the arm,
for the body), run by the system python3 against an emulated device on a pseudo-terminal.

Twists published on `set_velocity` must reach the device as the "Expected" bytes of
thesis Table 4.3; a bumper hit must appear on `detect_bump`; shutting the node down
must send the stop command. roscore listens on a free loopback port. Without ROS
the tests skip, but under CI (CI=true) a missing ROS is a failure. Every process
started here is stopped here.
"""

from __future__ import annotations

import importlib.util
import json
import math
import os
import re
import select
import shutil
import signal
import socket
import subprocess
import sysconfig
import termios
import time
import xmlrpc.client
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from conftest import run_rdisc

from rdisc.compile import compile_path
from tests.devices import CreateEmulator
from tests.devices.create import TABLE_4_3
from tests.devices.dynamixel import IDS, XBus, sync_goals
from tests.semantics.test_body_settings import DRIVE
from tests.semantics.test_joint_noise import POSE_COVARIANCE, TWIST_COVARIANCE

pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
PYTHON3 = "/usr/bin/python3"


def _ros_missing() -> str | None:
    if shutil.which("roscore") is None or not Path(PYTHON3).exists():
        return "roscore is not installed (apt-get install ros-core python3-rospy ...)"
    probe = subprocess.run([PYTHON3, "-c", "import rospy, geometry_msgs.msg, sensor_msgs.msg, serial"],
                           capture_output=True, check=False)
    return None if probe.returncode == 0 else "the system python3 has no rospy, ROS messages or pyserial"


MISSING = _ros_missing()
if MISSING is not None:
    if os.environ.get("CI") == "true":
        pytest.fail(f"ROS is required under CI: {MISSING}", pytrace=False)
    pytest.skip(MISSING, allow_module_level=True)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _stop(process: subprocess.Popen, sig: int = signal.SIGINT) -> str:
    if process.poll() is None:
        process.send_signal(sig)
        try:
            process.wait(timeout=15)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
    return process.stdout.read() if process.stdout else ""


@pytest.fixture(scope="module")
def ros_env(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, str]]:
    port = _free_port()
    env = dict(os.environ, ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_HOSTNAME="127.0.0.1",
               ROS_LOG_DIR=str(tmp_path_factory.mktemp("roslog")), PYTHONPATH="",
               PYTHONFAULTHANDLER="1")  # a node that hangs writes its threads' stacks on SIGABRT (`stacks_of`)
    core = subprocess.Popen(["roscore", "-p", str(port)], env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        deadline = time.monotonic() + 30
        while subprocess.run(["rosparam", "list"], env=env, capture_output=True, check=False).returncode != 0:
            assert time.monotonic() < deadline, "roscore did not start"
            time.sleep(0.2)
        yield env
    finally:
        os.killpg(core.pid, signal.SIGINT)
        try:
            core.wait(timeout=15)
        except subprocess.TimeoutExpired:
            os.killpg(core.pid, signal.SIGKILL)
            core.wait()


@pytest.fixture(scope="module")
def node_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("node") / "irobot_create_node.py"
    done = run_rdisc("emit-ros", str(REPO / "examples" / "create.rdis"), "-o", str(path))
    assert done.returncode == 0, done.stderr
    return path


def _start_node(node_file: Path, env: dict[str, str], device: CreateEmulator) -> subprocess.Popen:
    return subprocess.Popen([PYTHON3, str(node_file), f"_port:={device.port}"], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)


def test_twists_bumpers_and_shutdown(ros_env: dict[str, str], node_file: Path) -> None:
    with CreateEmulator() as device:
        node = _start_node(node_file, ros_env, device)
        twists = subprocess.Popen([PYTHON3, str(HERE / "twists.py")], env=ros_env, stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE, text=True)
        try:
            assert twists.stdout is not None and twists.stdin is not None
            assert twists.stdout.readline().strip() == "ready"  # the node subscribed
            device.wait_for_commands(1, timeout=15, opcode=132)  # the startup hook has taken full control
            for (linear, angular), _expected in TABLE_4_3:
                twists.stdin.write(f"{linear} {angular}\n")
                twists.stdin.flush()
                assert twists.stdout.readline().startswith("sent ")
            drives = device.wait_for_commands(len(TABLE_4_3), timeout=15, opcode=137)
            assert [cmd for _, cmd in drives] == [
                bytes([137]) + v.to_bytes(2, "big", signed=True) + r.to_bytes(2, "big", signed=True)
                for _, (_op, v, r) in TABLE_4_3
            ]
            device.bumpers = 0b01  # the right bumper: the output carries distance 0
            ranges: list[str] = []
            for _ in range(10):  # the first may have been published before the bumper was pressed
                echo = subprocess.run(["rostopic", "echo", "-n", "1", "/detect_bump/range"], env=ros_env,
                                      capture_output=True, text=True, timeout=30, check=False)
                ranges.append(echo.stdout.split()[0] if echo.stdout.split() else echo.stderr)
                if ranges[-1] == "0.0":
                    break
            assert ranges[-1] == "0.0", ranges
        finally:
            if twists.stdin is not None:
                twists.stdin.close()  # the end of its input ends twists.py (a signal would wait on its read)
            _stop(twists, signal.SIGTERM)
            output = _stop(node)
        stop = bytes([137, 0, 0, 0, 0])  # the terminate hook: drive(0, 0)
        device.wait_until(lambda: device.received.endswith(stop), 10, "the stop command")
        assert node.returncode == 0, output


def test_a_range_is_stamped_when_its_reply_was_read_and_names_its_frame(ros_env: dict[str, str],
                                                                         tmp_path: Path) -> None:
    """tests/runtime/data/framed_create.rdis: `detect_bump` is in the bumper's frame, `base_bump`
    (no `frame`) in the base's. Each Range's stamp is when the bumpers' reply was read: after the
    device wrote that reply and before it wrote the next (the node polls again only after reading),
    and at least the poll's 60 ms delay before the Range arrived, which was published after it."""
    node_file = tmp_path / "framed_node.py"
    done = run_rdisc("emit-ros", REPO / "tests" / "runtime" / "data" / "framed_create.rdis", "-o", node_file)
    assert done.returncode == 0, done.stderr
    with CreateEmulator(bumpers=0b01) as device:
        node = _start_node(node_file, ros_env, device)
        listeners = [_listen(ros_env, "range", "detect_bump"), _listen(ros_env, "range", "base_bump")]
        try:
            bumper = _until(listeners[0], lambda m: True)[-1]
            base = _until(listeners[1], lambda m: True)[-1]
        finally:
            for listener in listeners:
                _stop(listener)
            output = _stop(node)
        replies = [at for at, data in device.sent]
    assert node.returncode == 0, output
    assert (bumper["frame_id"], bumper["range"], base["frame_id"], base["range"]) == ("bumper", 0.0, "base", 0.0)
    for ranged in (bumper, base):
        stamp = ranged["stamp"]
        read = [at for at in replies if at <= stamp]
        assert stamp > 0 and read, (stamp, replies[:3])
        later = replies[len(read):]
        assert not later or stamp < later[0]  # the reply before it, not a later one
        assert ranged["received"] - stamp >= 60_000_000  # published after the delay, stamped before it


# An Odometry of a robot with a body: the Create's voltage sensor (15000 mV) read as how far it went (15 m).
TRAVELLED = """\
robot travelled { author "tests" }
state x: float = 0.0
connection link: serial { baud 57600  threading single at 20 Hz }
primitive voltage() on link pack "BB" (142, 22) unpack ">H" { x = out[0] / 1000 }
interface poll() periodic triggers odom { voltage() }
output odom: Odometry { x = x  y = 0.0  theta = 0.0  linear = 0.0  angular = 0.0 }
link chassis { mass 2  inertia [0.1, 0.1, 0.1] }
"""


def test_an_odometry_is_in_odom_with_the_base_as_its_child_frame(ros_env: dict[str, str], tmp_path: Path) -> None:
    """REP 105: the pose in the fixed `odom` frame, the body's base (`chassis`) its child frame,
    stamped when the device's reply was read."""
    source, node_file = tmp_path / "travelled.rdis", tmp_path / "travelled_node.py"
    source.write_text(TRAVELLED, encoding="utf-8")
    done = run_rdisc("emit-ros", str(source), "-o", str(node_file))
    assert done.returncode == 0, done.stderr
    with CreateEmulator() as device:
        node = _start_node(node_file, ros_env, device)
        listener = _listen(ros_env, "odom")
        try:
            odometry = _until(listener, lambda m: m["x"] == 15.0)[-1]
        finally:
            _stop(listener)
            _stop(node)
        replies = [at for at, _ in device.sent]
    assert (odometry["frame_id"], odometry["child_frame_id"]) == ("odom", "chassis")
    assert any(at <= odometry["stamp"] for at in replies)


# An Odometry's pose and twist errors, and an Imu's rates', each one covariance over several fields.
COVARIANT = """\
robot covariant { author "tests" }
state x: float = 0.0
connection link: serial { baud 57600  threading single at 20 Hz }
primitive voltage() on link pack "BB" (142, 22) unpack ">H" { x = out[0] / 1000 }
interface poll() periodic triggers odom, imu { voltage() }
output odom: Odometry {
    x = x  y = 0.0  theta = 0.0  linear = 0.0  angular = 0.0
    noise (x, y, theta) [0.04, 0.01, 0.002; 0.01, 0.09, 0; 0.002, 0, 0.25]
    noise (linear, angular) [0.0625, 0.015625; 0.015625, 0.125]
}
adapter Turning ros "sensor_msgs/Imu" {
    roll_rate: float unit "rad/s" ros "angular_velocity.x"
    yaw_rate: float unit "rad/s" ros "angular_velocity.z"
    heading: float unit "rad" ros "orientation:yaw"
}
output imu: Turning {
    roll_rate = 0.0  yaw_rate = x  heading = 0.0
    noise (yaw_rate, roll_rate) [0.5, 0.25; 0.25, 0.75]
    noise heading 0.125
}
"""


def test_covariances_over_several_fields_reach_an_odometry_and_an_imu(ros_env: dict[str, str],
                                                                      tmp_path: Path) -> None:
    """`noise (x, y, theta) [...]`: the 3x3 covariance at x, y and the yaw of the pose's 6x6, off the
    diagonal too; the twist's at its linear x and angular z; an Imu's rates at their axes of its 3x3."""
    source, node_file = tmp_path / "covariant.rdis", tmp_path / "covariant_node.py"
    source.write_text(COVARIANT, encoding="utf-8")
    done = run_rdisc("emit-ros", str(source), "-o", str(node_file))
    assert done.returncode == 0, done.stderr
    with CreateEmulator() as device:
        node = _start_node(node_file, ros_env, device)
        odometry_listener, imu_listener = _listen(ros_env, "odom"), _listen(ros_env, "imu")
        try:
            odometry = _until(odometry_listener, lambda m: m["x"] == 15.0)[-1]
            imu = _until(imu_listener, lambda m: m["yaw_rate"] == 15.0)[-1]
        finally:
            _stop(odometry_listener)
            _stop(imu_listener)
            _stop(node)
    # The same matrices as the node's fill functions are held to, in process.
    assert (odometry["pose_covariance"], odometry["twist_covariance"]) == (POSE_COVARIANCE, TWIST_COVARIANCE)
    assert imu["angular_velocity"] == [0.75, 0.0, 0.25, 0.0, 0.0, 0.0, 0.25, 0.0, 0.5]
    assert imu["orientation"] == [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.015625]
    assert imu["linear_acceleration"] == [0.0] * 9


# Appendix C's mapping: the bumpers published as a std_msgs/Bool "hit", by an adapter of the description's own.
HIT = """\
robot hit_create { author "tests" }
state bumps: int = 0
adapter Hit ros "std_msgs/Bool" { hit: bool ros "data" }
connection link: serial { baud 57600  threading single at 20 Hz }
primitive bumpers() on link pack "BB" (142, 7) unpack "B" { bumps = out[0] }
interface poll() periodic triggers hit { bumpers() }
output hit: Hit { hit = (bumps & 3) != 0 }
"""


def _echo(env: dict[str, str], topic: str, wanted: Callable[[str], bool]) -> list[str]:
    """What `rostopic echo -n 1 TOPIC` printed (the message, without its `---`), up to ten
    times until `wanted(message)`."""
    seen: list[str] = []
    for _ in range(10):
        done = subprocess.run(["rostopic", "echo", "-n", "1", topic], env=env, capture_output=True, text=True,
                              timeout=30, check=False)
        words = done.stdout.split()
        seen.append(" ".join(words[:-1]) if words else done.stderr)
        if wanted(seen[-1]):
            break
    return seen


def test_a_description_maps_an_output_to_another_message(ros_env: dict[str, str], tmp_path: Path) -> None:
    source = tmp_path / "hit.rdis"
    source.write_text(HIT)
    node_file = tmp_path / "hit_node.py"
    done = run_rdisc("emit-ros", str(source), "-o", str(node_file))
    assert done.returncode == 0, done.stderr
    with CreateEmulator(bumpers=0b10) as device:  # the left bumper
        node = _start_node(node_file, ros_env, device)
        try:
            assert _echo(ros_env, "/hit/data", lambda message: message == "True")[-1] == "True"
        finally:
            _stop(node)


# Arrays through ROS: two "joints" (the Create's voltage and charge sensors, read as one array) published as
# one sensor_msgs/JointState, and a JointState moving both "wheels" at once.
JOINTS = """\
robot joints_create { author "tests" }
const PACKETS = [22, 25]
const NAMES = ["volts", "charge"]
state reading: int[2]
connection link: serial { baud 57600  threading single at 20 Hz }
primitive sensor(i: int in 0..1) on link pack "BB" (142, PACKETS[i]) unpack ">H" { reading[i] = out[0] }
primitive drive(velocity: int, radius: int) on link pack ">Bhh" (137, velocity, radius)
interface poll() periodic triggers joints { sensor(0)  sensor(1) }
interface wheels(p: float[2]) { drive(round(p[0] * 1000), round(p[1] * 1000)) }
output joints: JointState { name = NAMES  position = [reading[0] / 1000, reading[1] / 1000] }
input move: JointState -> wheels(position)
"""


def test_arrays_travel_as_one_joint_state(ros_env: dict[str, str], tmp_path: Path) -> None:
    source = tmp_path / "joints.rdis"
    source.write_text(JOINTS)
    node_file = tmp_path / "joints_node.py"
    done = run_rdisc("emit-ros", str(source), "-o", str(node_file))
    assert done.returncode == 0, done.stderr
    with CreateEmulator() as device:  # voltage 15000 mV, charge 2000 mAh
        node = _start_node(node_file, ros_env, device)
        try:
            assert _echo(ros_env, "/joints/name", lambda m: m.startswith("-"))[-1] == "- volts - charge"
            assert _echo(ros_env, "/joints/position", lambda m: m.startswith("["))[-1] == "[15.0, 2.0]"
            # `rostopic pub -1` stays 3 s after publishing: waited for once the drive went out
            publisher = subprocess.Popen(["rostopic", "pub", "-1", "/move", "sensor_msgs/JointState",
                                          "{name: [left, right], position: [0.2, -0.1]}"], env=ros_env,
                                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            device.wait_until(lambda: (200, -100) in device.drives(), 10, "the drive command")
        finally:
            _stop(node)
        _published(publisher)


def test_device_errors_are_published_and_the_node_keeps_serving(ros_env: dict[str, str], node_file: Path) -> None:
    with CreateEmulator(mode="silent") as device:  # never answers: every bumper poll times out
        node = _start_node(node_file, ros_env, device)
        try:
            for _ in range(2):  # an error, and another after it: the node goes on polling and publishing
                errors = _echo(ros_env, "/irobot_create/errors", lambda message: message.startswith("data: "))
                assert errors[0].startswith('data: "RdisTimeout: bumpers: no reply within'), errors
                assert node.poll() is None  # still serving
        finally:
            _stop(node)


# Seconds after the first command reached the device, the signals, and the gaps between them:
# during the start-up hook (its 50 ms delay), and while running.
SIGNAL_MOMENTS = {
    "start-up, twice": (0.0, [signal.SIGINT, signal.SIGINT], 0.005),
    "start-up delay, burst": (0.02, [signal.SIGINT] * 4, 0.002),
    "running, twice": (1.0, [signal.SIGINT, signal.SIGINT], 0.01),
    "running, SIGTERM then SIGINT": (1.0, [signal.SIGTERM, signal.SIGINT], 0.001),
}


@pytest.mark.parametrize(("after", "signals", "gap"), SIGNAL_MOMENTS.values(), ids=SIGNAL_MOMENTS.keys())
def test_signals_at_any_moment_leave_the_robot_stopped(ros_env: dict[str, str], tmp_path: Path, after: float,
                                                       signals: list[signal.Signals], gap: float) -> None:
    """However the node is signalled once its port is open, the stop command is the last thing
    written and nothing prints a traceback (rospy shuts down on SIGINT and SIGTERM alike)."""
    node_path = tmp_path / "fast_create_node.py"
    done = run_rdisc("emit-ros", REPO / "tests" / "runtime" / "data" / "fast_create.rdis", "-o", node_path)
    assert done.returncode == 0, done.stderr
    with CreateEmulator() as device:
        device.signal_once_open(_start_node(node_path, ros_env, device), after, signals, gap)


# The fast Create whose twist starts an interface of three commands, 200 ms apart.
DANCE = re.sub(r"input set_velocity: DifferentialSpeed -> drive\((?:.|\n)*?\n\)\n", """\
interface dance(linear: float, angular: float) {
    drive(100, 0) delay 200 ms
    drive(200, 0) delay 200 ms
    drive(round(linear * 1000) + 300, round(angular))
}

input set_velocity: DifferentialSpeed -> dance(linear, angular)
""", (REPO / "tests" / "runtime" / "data" / "fast_create.rdis").read_text(encoding="utf-8"))


def test_a_signal_during_a_twist_s_call_of_several_commands_leaves_the_stop_last(ros_env: dict[str, str],
                                                                                  tmp_path: Path) -> None:
    """SIGINT while the subscriber's call of an interface of three commands is in its first delay:
    the call writes nothing more, the terminate hook's stop is the last command the device gets."""
    assert "-> dance(linear, angular)" in DANCE
    source, node_path = tmp_path / "dance.rdis", tmp_path / "dance_node.py"
    source.write_text(DANCE, encoding="utf-8")
    done = run_rdisc("emit-ros", str(source), "-o", str(node_path))
    assert done.returncode == 0, done.stderr
    with CreateEmulator() as device:
        node = _start_node(node_path, ros_env, device)
        twists = subprocess.Popen([PYTHON3, str(HERE / "twists.py")], env=ros_env, stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE, text=True)
        try:
            assert twists.stdout is not None and twists.stdin is not None
            assert twists.stdout.readline().strip() == "ready"  # the node subscribed
            twists.stdin.write("0.0 0.0\n")
            twists.stdin.flush()
            device.wait_until(lambda: (100, 0) in device.drives(), 15, "the dance's first command")
            device.signal_once_open(node, 0.05, [signal.SIGINT], 0.0)  # the stop last, no traceback
        finally:
            twists.stdin.close()
            _stop(twists, signal.SIGTERM)
            if node.returncode is None:  # not signalled yet: the test failed before
                _stop(node)
    assert (300, 0) not in device.drives(), device.drives()


SETTINGS = """\
robot servos { author "tests" }
setting BAUD: int in 9600..1000000 = 57600
setting ID: int in 0..253 = 1
connection bus: serial { baud BAUD startup hello(ID) }
primitive ping(id: int) on bus pack "BB" (0xFF, id)
interface hello(id: int) { ping(id) }
"""


def test_settings_are_the_node_s_private_parameters(ros_env: dict[str, str], tmp_path: Path) -> None:
    source, path = tmp_path / "servos.rdis", tmp_path / "servos_node.py"
    source.write_text(SETTINGS, encoding="utf-8")
    done = run_rdisc("emit-ros", str(source), "-o", str(path))
    assert done.returncode == 0, done.stderr
    master, slave = os.openpty()
    node = subprocess.Popen([PYTHON3, str(path), f"_port:={os.ttyname(slave)}", "_ID:=9", "_BAUD:=115200"],
                            env=ros_env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        received = b""
        deadline = time.monotonic() + 30
        while len(received) < 2 and time.monotonic() < deadline:
            ready, _, _ = select.select([master], [], [], 0.2)
            if ready:
                received += os.read(master, 64)
        assert received == b"\xff\x09", _stop(node)  # the startup hook, with the ID given
        assert termios.tcgetattr(slave)[5] == termios.B115200  # the port opened at the baud given
    finally:
        _stop(node)
        os.close(master)
        os.close(slave)


def _listen(env: dict[str, str], *what: str) -> subprocess.Popen:
    """tests/ros/listen.py on `joint_states`, `tf`, `odom` or `range TOPIC`: a JSON line a message, for a
    minute at most."""
    return subprocess.Popen([PYTHON3, str(HERE / "listen.py"), *what], env=env, stdout=subprocess.PIPE, text=True)


def _until(listener: subprocess.Popen, wanted: Callable[[dict[str, Any]], bool]) -> list[dict[str, Any]]:
    """The messages `listener` printed, up to the first that is `wanted`."""
    assert listener.stdout is not None
    seen: list[dict[str, Any]] = []
    for line in listener.stdout:
        seen.append(json.loads(line))
        if wanted(seen[-1]):
            return seen
    raise AssertionError(f"not among the {len(seen)} messages; the last: {seen[-3:]}")


def _quaternion(axis: tuple[float, float, float], angle: float) -> list[float]:
    """The rotation by `angle` about the unit `axis`, as (x, y, z, w)."""
    s = math.sin(angle / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2)]


ROBOT_STATE_PUBLISHER = Path("/usr/lib/robot_state_publisher/robot_state_publisher")


def test_the_arm_s_body_and_joint_states_reach_robot_state_publisher(ros_env: dict[str, str], tmp_path: Path) -> None:
    """examples/arm.rdis's node against six emulated servos: it sets robot_description to its
    URDF and publishes the positions the servos report on joint_states, stamped, under the
    joints' names; ROS's own robot_state_publisher turns both into the transforms of the arm
    (each joint's origin, turned about its axis by the servo's angle)."""
    tf_here = subprocess.run([PYTHON3, "-c", "import tf2_msgs.msg"], capture_output=True, check=False).returncode == 0
    if not (ROBOT_STATE_PUBLISHER.exists() and tf_here) and os.environ.get("CI") != "true":
        pytest.skip("robot_state_publisher is not installed (apt-get install ros-robot-state-publisher "
                    "python3-tf2-msgs)")
    arm = REPO / "examples" / "arm.rdis"
    node_file = tmp_path / "arm_node.py"
    done = run_rdisc("emit-ros", str(arm), "-o", str(node_file))
    assert done.returncode == 0, done.stderr
    present = {1: 2048, 2: 1024, 3: 3072, 4: 2560, 5: 0, 6: 4095}  # the centre, -90°, +90°, +45°, -180°, ~+180°
    angles = [(present[i] - 2048) * 2 * math.pi / 4096 for i in IDS]
    names = ["waist", "shoulder", "elbow", "wrist_pitch", "wrist_roll", "gripper"]
    with XBus() as bus:
        bus.present = present
        node = subprocess.Popen([PYTHON3, str(node_file), f"_port:={bus.port}"], env=ros_env, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True)
        listeners = [_listen(ros_env, "joint_states"), _listen(ros_env, "tf")]
        publisher: subprocess.Popen | None = None
        try:
            seen = _until(listeners[0], lambda m: m["position"] == pytest.approx(angles, abs=1e-12))
            # robot_description was set before the node opened its port: robot_state_publisher reads it as it starts
            publisher = subprocess.Popen([str(ROBOT_STATE_PUBLISHER)], env=ros_env, stdout=subprocess.PIPE,
                                         stderr=subprocess.STDOUT, text=True)
            assert {(tuple(m["name"]), len(m["position"]), tuple(m["velocity"]), tuple(m["effort"]))
                    for m in seen} == {(tuple(names), 6, (), ())}  # before the first read: the state's defaults
            stamps = [m["stamp"] for m in seen]
            assert stamps[0] > 0 and stamps == sorted(stamps)

            got = subprocess.run(["rosparam", "get", "/robot_description"], env=ros_env, capture_output=True,
                                 text=True, check=True, timeout=60)
            urdf = subprocess.run([PYTHON3, "-c", "import sys, yaml; sys.stdout.write(yaml.safe_load(sys.stdin))"],
                                  input=got.stdout, capture_output=True, text=True, check=True).stdout
            emitted = run_rdisc("emit-urdf", str(arm)).stdout
            assert urdf == emitted
            urchin = pytest.importorskip("urchin")
            (tmp_path / "arm.urdf").write_text(urdf, encoding="utf-8")
            robot = urchin.URDF.load(str(tmp_path / "arm.urdf"), lazy_load_meshes=True)
            assert (len(robot.links), [j.name for j in robot.joints]) == (7, names)

            model = compile_path(str(arm)).model
            assert model is not None
            expected = {joint.child: (joint.parent, list(joint.origin.xyz), _quaternion(joint.axis, angle))
                        for joint, angle in zip(model.joints.values(), angles)}
            transforms: dict[str, tuple[str, list[float]]] = {}  # each child's, once turned by its angle

            def all_there(t: dict[str, Any]) -> bool:
                turn = expected[t["child"]][2] if t["child"] in expected else None
                if turn is not None and any(t["rotation"] == pytest.approx([sign * v for v in turn], abs=1e-9)
                                            for sign in (1, -1)):  # q and -q are the same rotation
                    transforms[t["child"]] = (t["parent"], t["translation"])
                return len(transforms) == len(expected)

            _until(listeners[1], all_there)
            assert transforms == {child: (parent, pytest.approx(xyz)) for child, (parent, xyz, _) in expected.items()}
        finally:
            for process in (*([publisher] if publisher else []), *listeners):
                _stop(process)
            output = _stop(node)
        assert node.returncode == 0, output


def test_a_joint_states_rate_that_is_no_rate_stops_the_node(ros_env: dict[str, str], tmp_path: Path) -> None:
    node_file = tmp_path / "arm_node.py"
    done = run_rdisc("emit-ros", REPO / "examples" / "arm.rdis", "-o", node_file)
    assert done.returncode == 0, done.stderr
    refused = subprocess.run([PYTHON3, str(node_file), "_port:=/dev/null", "_joint_states_rate:=0"], env=ros_env,
                             capture_output=True, text=True, check=False, timeout=60)
    assert (refused.returncode, refused.stderr.splitlines()[-1:]) == (
        2, ["arm_node.py: ~joint_states_rate is 0: give Hz, above 0, at most 1000"]), refused.stderr


CREATE2 = REPO / "examples" / "create2.rdis"


@pytest.fixture(scope="module")
def create2_node(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("create2") / "create2_node.py"
    done = run_rdisc("emit-ros", str(CREATE2), "-o", str(path))
    assert done.returncode == 0, done.stderr
    return path


def _with_rdisc(ros_env: dict[str, str], *places: str) -> dict[str, str]:
    """ros_env with `places` first on the system python3's path (Debian's rospy and messages still found after)."""
    return dict(ros_env, PYTHONPATH=os.pathsep.join(places))


def test_robot_description_is_the_body_at_the_settings_given(ros_env: dict[str, str], tmp_path: Path) -> None:
    """`_TRACK:=0.3` on a body that reads TRACK: robot_description is what `rdisc emit-urdf --set
    TRACK=0.3` writes (the node has rdisc build the body again: the work tree and this python's
    site-packages on the system python3's PYTHONPATH, as for `_sim:=true`), asked of the master over
    its XML-RPC, in process."""
    source, node_file = tmp_path / "rover.rdis", tmp_path / "rover_node.py"
    source.write_text(DRIVE, encoding="utf-8")
    done = run_rdisc("emit-ros", str(source), "-o", str(node_file))
    assert done.returncode == 0, done.stderr
    parameters = xmlrpc.client.ServerProxy(ros_env["ROS_MASTER_URI"])
    if parameters.hasParam("/test_ros_bridge", "/robot_description")[2]:  # another test's node's
        parameters.deleteParam("/test_ros_bridge", "/robot_description")
    master, slave = os.openpty()
    node = subprocess.Popen([PYTHON3, str(node_file), f"_port:={os.ttyname(slave)}", "_TRACK:=0.3"],
                            env=_with_rdisc(ros_env, str(REPO), sysconfig.get_paths()["purelib"]), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    try:
        _until_subscribed(ros_env, "/go")  # the node is up (robot_description set before), its signal handlers too
        urdf = parameters.getParam("/test_ros_bridge", "/robot_description")[2]
    finally:
        output = _stop(node)
        os.close(master)
        os.close(slave)
        parameters.deleteParam("/test_ros_bridge", "/robot_description")
    assert node.returncode == 0, output
    assert urdf == run_rdisc("emit-urdf", str(source), "--set", "TRACK=0.3").stdout
    assert '<origin xyz="0 0.15 0.036" rpy="0 0 0" />' in urdf


def test_sim_true_drives_the_simulated_body_from_a_twist(ros_env: dict[str, str], create2_node: Path) -> None:
    """`_sim:=true`: the Create 2's node runs against the MuJoCo simulation of its body, on the
    system python3 given this python's rdisc and MuJoCo through PYTHONPATH (the work tree, as
    an editable install is a .pth file PYTHONPATH does not read, then this python's
    site-packages: the same minor version, so MuJoCo's and numpy's compiled modules load). A
    Twist on set_velocity turns the simulated wheels: odom's x grows, y stays near 0, and
    joint_states reads the wheels turning, as from the device."""
    if importlib.util.find_spec("mujoco") is None:
        if os.environ.get("CI") == "true":
            pytest.fail("MuJoCo is required under CI (pip install '.[test]')", pytrace=False)
        pytest.skip("MuJoCo is not installed (pip install mujoco)")
    env = _with_rdisc(ros_env, str(REPO), sysconfig.get_paths()["purelib"])
    node = subprocess.Popen([PYTHON3, str(create2_node), "_sim:=true"], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    listeners = [_listen(ros_env, "odom"), _listen(ros_env, "joint_states")]
    twists = subprocess.Popen([PYTHON3, str(HERE / "twists.py")], env=ros_env, stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, text=True)
    try:
        assert twists.stdout is not None and twists.stdin is not None
        assert twists.stdout.readline().strip() == "ready"  # the node subscribed
        twists.stdin.write("0.2 0\n")
        twists.stdin.flush()
        assert twists.stdout.readline().startswith("sent ")
        odometry = _until(listeners[0], lambda m: m["x"] > 0.1)
        xs = [m["x"] for m in odometry]
        assert xs == sorted(xs) and all(abs(m["y"]) < 0.005 for m in odometry), odometry[-5:]
        wheels = _until(listeners[1], lambda m: min(m["position"]) > 1.0)  # rad: 36 mm of travel each
        assert wheels[-1]["name"] == ["left_wheel_joint", "right_wheel_joint"]
    finally:
        if twists.stdin is not None:
            twists.stdin.close()
        for process in (twists, *listeners):
            _stop(process, signal.SIGTERM)
        output = _stop(node)
    assert node.returncode == 0, output


PROG = "create2_node.py"
SIM_MISSING = {
    "neither": ((), [(f"{PROG}: ~sim needs rdisc, which {PYTHON3} cannot import: put rdisc on PYTHONPATH, "
                      "or pip install 'rdisc[sim]'"),
                     f"{PROG}: ~sim needs MuJoCo, which {PYTHON3} cannot import: pip install mujoco"]),
    "no MuJoCo": ((str(REPO),), [f"{PROG}: ~sim needs MuJoCo, which {PYTHON3} cannot import: pip install mujoco"]),
}


@pytest.mark.parametrize(("places", "said"), SIM_MISSING.values(), ids=SIM_MISSING.keys())
def test_sim_true_without_rdisc_or_mujoco_says_which_and_exits_2(ros_env: dict[str, str], create2_node: Path,
                                                                  places: tuple[str, ...], said: list[str]) -> None:
    probe = "import importlib.util as u; print(u.find_spec('rdisc') is None, u.find_spec('mujoco') is None)"
    here = subprocess.run([PYTHON3, "-c", probe], env=_with_rdisc(ros_env, *places), cwd=create2_node.parent,
                          capture_output=True, text=True, check=True).stdout.split()  # not the work tree's rdisc
    if here != ["False" if places else "True", "True"]:
        pytest.skip(f"{PYTHON3} has rdisc or MuJoCo installed of its own")
    refused = subprocess.run([PYTHON3, str(create2_node), "_sim:=true"], env=_with_rdisc(ros_env, *places),
                             capture_output=True, text=True, check=False, timeout=60)
    assert (refused.returncode, refused.stderr.splitlines()[-len(said):]) == (2, said), refused.stderr
    assert "Traceback" not in refused.stderr


def test_a_sim_that_is_no_bool_stops_the_node(ros_env: dict[str, str], create2_node: Path) -> None:
    refused = subprocess.run([PYTHON3, str(create2_node), "_sim:=1"], env=ros_env, capture_output=True, text=True,
                             check=False, timeout=60)
    assert (refused.returncode, refused.stderr.splitlines()[-1:]) == (
        2, [f"{PROG}: ~sim is 1: give true (simulate the body) or false (the device)"]), refused.stderr


def _publish_joints(env: dict[str, str], names: list[str], quantity: str, values: list[float]) -> subprocess.Popen:
    """One JointState on joint_command, latched for the node to take (`rostopic pub -1`); the
    process stays 3 s for late subscribers, so it is returned to be waited for at the end."""
    message = json.dumps({"name": names, quantity: values})
    return subprocess.Popen(["rostopic", "pub", "-1", "/joint_command", "sensor_msgs/JointState", message], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def _published(publisher: subprocess.Popen) -> None:
    """`rostopic pub -1` ended by itself, successfully."""
    output = publisher.communicate(timeout=60)[0]
    assert publisher.returncode == 0, output


def _until_subscribed(env: dict[str, str], topic: str) -> None:
    """Until the master lists a subscriber of `topic` (a message published before would be lost
    to it); asked over the master's XML-RPC, in process. Bounded: a caller retries on a miss."""
    master = xmlrpc.client.ServerProxy(env["ROS_MASTER_URI"])
    deadline = time.monotonic() + 20
    while time.monotonic() < deadline:
        _, _, (_, subscribed, _) = master.getSystemState("/test_ros_bridge")
        if any(name == topic and nodes for name, nodes in subscribed):
            return
        time.sleep(0.05)


ARM_JOINTS = ["waist", "shoulder", "elbow", "wrist_pitch", "wrist_roll", "gripper"]


def test_a_joint_state_on_joint_command_moves_the_arm_s_servos(ros_env: dict[str, str], tmp_path: Path) -> None:
    """examples/arm.rdis's node: six positions on joint_command are one sync write of six goals,
    each the transmission's `raw = round(position * UNITS_PER_RAD) + CENTRE`; five joints of the
    six is a line on ~errors, and nothing is written for it."""
    node_file = tmp_path / "arm_node.py"
    done = run_rdisc("emit-ros", REPO / "examples" / "arm.rdis", "-o", node_file)
    assert done.returncode == 0, done.stderr
    with XBus() as bus:
        # the rate given: a test before may have left a private parameter of the arm's on the master
        node = subprocess.Popen([PYTHON3, str(node_file), f"_port:={bus.port}", "_joint_states_rate:=20"], env=ros_env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        listener = _listen(ros_env, "joint_states")
        publishers: list[subprocess.Popen] = []
        try:
            _until(listener, lambda m: True)  # the node is up
            shown = ""
            for _ in range(5):  # the echo may still subscribe after a message was published
                echo = subprocess.Popen(["rostopic", "echo", "-n", "1", "/arm/errors"], env=ros_env,
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                _until_subscribed(ros_env, "/arm/errors")
                publishers.append(_publish_joints(ros_env, ARM_JOINTS[:5], "position", [0.0] * 5))
                try:
                    shown = echo.communicate(timeout=10)[0].split("---")[0]
                    break
                except subprocess.TimeoutExpired:
                    _stop(echo)
            error = subprocess.run([PYTHON3, "-c", "import sys, yaml; sys.stdout.write(yaml.safe_load(sys.stdin)['data'])"],
                                   input=shown, capture_output=True, text=True, check=True).stdout
            assert error == ("RdisValueError: joint_command: sync_goal takes waist, shoulder, elbow, wrist_pitch, "
                             "wrist_roll, gripper together; missing: gripper")
            assert sync_goals(bus.received) == []
            publishers.append(_publish_joints(ros_env, ARM_JOINTS, "position",
                                              [0.0, -math.pi / 2, math.pi / 2, math.pi / 4, 0.1, -0.1]))
            bus.wait_until(lambda: bool(sync_goals(bus.received)), 15, "a sync write of goals")
            assert sync_goals(bus.received) == [[2048, 1024, 3072, 2560, 2048 + 65, 2048 - 65]]
        finally:
            _stop(listener)
            output = _stop(node)
        assert node.returncode == 0, output
        for publisher in publishers:
            _published(publisher)
