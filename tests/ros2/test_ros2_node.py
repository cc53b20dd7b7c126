"""The ROS 2 node `rdisc emit-ros2` writes for the Create, run as a process on an emulated device (a
pseudo-terminal), against an independent ROS 2 participant in another process (participant.py:
Cyclone DDS with types from rosbags' ROS 2 definitions, not rdisc's), both on loopback in a domain
of their own (ROS_DOMAIN_ID).

Twists on `set_velocity` must reach the device as thesis Table 4.3's "Expected" bytes; the bumper
output arrives, decoded by rosbags, with the right range, a stamp and its frame id; a reliable
reader of the best-effort output is reported by both sides; the node announces itself on
`ros_discovery_info`; SIGINT and SIGTERM leave the stop command as the last bytes written."""

from __future__ import annotations

import json
import math
import os
import queue
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from conftest import run_rdisc

from tests.devices import CreateEmulator
from tests.devices.create import TABLE_4_3
from tests.devices.dynamixel import XBus, sync_goals
from tests.ros2.loopback import LOOPBACK
from tests.support import threads

pytest.importorskip("cyclonedds")
typesys = pytest.importorskip("rosbags.typesys")

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
STOP = bytes([137, 0, 0, 0, 0])  # the terminate hook: drive(0, 0)


@pytest.fixture(scope="module")
def node_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("node") / "irobot_create_node.py"
    done = run_rdisc("emit-ros2", REPO / "examples" / "create.rdis", "-o", path)
    assert done.returncode == 0, done.stderr
    return path


@pytest.fixture()
def dds_env() -> dict[str, str]:
    """A domain of this test process's own (from its pid: another run beside it picks another), on loopback."""
    return dict(os.environ, ROS_DOMAIN_ID=str(10 + os.getpid() % 200), CYCLONEDDS_URI=LOOPBACK)


def _start_node(node_file: Path, env: dict[str, str], device: CreateEmulator) -> subprocess.Popen[str]:
    return subprocess.Popen([sys.executable, str(node_file), "--ros-args", "-p", f"port:={device.port}"], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


class Participant:
    """participant.py, its JSON lines read as they come."""

    def __init__(self, env: dict[str, str], node: str = "irobot_create") -> None:
        self.process = subprocess.Popen([sys.executable, str(HERE / "participant.py"), "jazzy", node],
                                        env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        self.events: queue.Queue[dict[str, Any]] = queue.Queue()
        self.seen: list[dict[str, Any]] = []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        assert self.process.stdout is not None
        for line in self.process.stdout:
            self.events.put(json.loads(line))

    def wait(self, wanted: Callable[[dict[str, Any]], bool], what: str, timeout: float = 20) -> dict[str, Any]:
        """The first event (since the last one waited for) that is `wanted`, within `timeout` seconds."""
        deadline = time.monotonic() + timeout
        while True:
            try:
                event = self.events.get(timeout=max(0.0, deadline - time.monotonic()))
            except queue.Empty:
                raise AssertionError(f"no {what} within {timeout} s; saw {self.seen[-5:]}") from None
            self.seen.append(event)
            if wanted(event):
                return event

    def so_far(self, key: str) -> list[Any]:
        """What every event with `key` said until now, those not yet waited for included."""
        while not self.events.empty():
            self.seen.append(self.events.get())
        return [event[key] for event in self.seen if key in event]

    def twist(self, linear: float, angular: float) -> None:
        self.send_line(f"{linear} {angular}")

    def send(self, joints: dict[str, list[Any]]) -> None:
        self.send_line(json.dumps(joints))

    def send_line(self, line: str) -> None:
        assert self.process.stdin is not None
        self.process.stdin.write(line + "\n")
        self.process.stdin.flush()

    def stop(self) -> None:
        if self.process.stdin is not None:
            self.process.stdin.close()  # the end of its input ends it
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


@pytest.fixture()
def participant(dds_env: dict[str, str]) -> Iterator[Participant]:
    other = Participant(dds_env)
    try:
        yield other
    finally:
        other.stop()


def _stop(process: subprocess.Popen[str], signum: int) -> tuple[str, str]:
    if process.poll() is None:
        process.send_signal(signum)
    try:
        return process.communicate(timeout=15)
    except subprocess.TimeoutExpired:
        process.kill()
        return process.communicate()


def test_twists_bumpers_qos_and_shutdown(node_file: Path, dds_env: dict[str, str], participant: Participant) -> None:
    store = typesys.get_typestore(typesys.Stores.ROS2_JAZZY)
    with CreateEmulator() as device:
        node = _start_node(node_file, dds_env, device)
        try:
            participant.wait(lambda e: "matched" in e or "unmatched" in e, "subscription to set_velocity")
            assert participant.seen[-1] == {"matched": True}  # the node subscribed: its startup hooks are done
            assert device.opcodes()[:2] == [128, 132]
            for (linear, angular), _expected in TABLE_4_3:
                participant.twist(linear, angular)
            drives = device.wait_for_commands(len(TABLE_4_3), timeout=15, opcode=137)
            assert [cmd for _, cmd in drives] == [
                bytes([137]) + v.to_bytes(2, "big", signed=True) + r.to_bytes(2, "big", signed=True)
                for _, (_op, v, r) in TABLE_4_3
            ]
            clear = store.deserialize_cdr(bytes.fromhex(participant.wait(lambda e: "bump" in e, "a bump")["bump"]),
                                          "sensor_msgs/msg/Range")
            device.bumpers = 0b01  # the right bumper: the output carries range 0
            hit = participant.wait(lambda e: "bump" in e and store.deserialize_cdr(
                bytes.fromhex(e["bump"]), "sensor_msgs/msg/Range").range == 0.0, "a bump of range 0")
            pressed = store.deserialize_cdr(bytes.fromhex(hit["bump"]), "sensor_msgs/msg/Range")
            assert (clear.range, pressed.range, pressed.variance, pressed.header.frame_id) == (1.0, 0.0, 0.0, "")
            stamp = pressed.header.stamp.sec + pressed.header.stamp.nanosec / 1e9
            assert stamp > clear.header.stamp.sec > 0  # the time it was read: later than the clear one's
            # Its reliable reader of the best-effort output: refused on its side (reliability, policy 11), and
            # reported by the node (on stderr, below).
            assert participant.so_far("incompatible")[:1] == [11]
            discovery = participant.so_far("discovery")
            assert discovery, "the node is not on ros_discovery_info"
            info = store.deserialize_cdr(bytes.fromhex(discovery[-1]), "rmw_dds_common/msg/ParticipantEntitiesInfo")
            (entry,) = info.node_entities_info_seq
            assert (entry.node_namespace, entry.node_name) == ("/", "irobot_create")
            assert (len(entry.reader_gid_seq), len(entry.writer_gid_seq)) == (1, 2)  # set_velocity; errors, detect_bump
            assert bytes(info.gid.data[:12]) == bytes(entry.writer_gid_seq[0].data[:12])  # one participant's GUIDs
            # Cyclone's threads and the node's own leave SIGINT and SIGTERM to the main thread.
            assert not threads.READABLE or threads.interrupts_reach_only_the_main_thread(node.pid)
        finally:
            _, stderr = _stop(node, signal.SIGINT)
        assert node.returncode == 130, stderr
        assert "Traceback" not in stderr, stderr
        assert ("irobot_create_node.py: /detect_bump: a subscription asks for what this publisher does not offer "
                "(reliability): no messages flow between them") in stderr.splitlines()
        device.wait_until(lambda: device.received.endswith(STOP), 5, "the stop command")
        time.sleep(0.05)
        assert device.commands[-1][1] == STOP


@pytest.mark.parametrize(("after", "signals", "status"), [
    (0.0, [signal.SIGTERM], 143),  # during the startup hooks
    (2.5, [signal.SIGTERM, signal.SIGINT], 143),  # running, a second signal on the way out
], ids=["SIGTERM at start-up", "SIGTERM then SIGINT running"])  # SIGINT alone: the test above
def test_signals_leave_the_robot_stopped(node_file: Path, dds_env: dict[str, str], after: float,
                                         signals: list[signal.Signals], status: int) -> None:
    with CreateEmulator() as device:
        node = _start_node(node_file, dds_env, device)
        printed = device.signal_once_open(node, after, signals, 0.01)
    # On a loaded machine both signals may be pending when the interpreter looks, and CPython then
    # handles them in the order of their numbers (SIGINT first), as tests/runtime/test_signals.py says.
    assert node.returncode in {status, *(130 for s in signals[1:] if s == signal.SIGINT)}, printed


ARM_JOINTS = ["waist", "shoulder", "elbow", "wrist_pitch", "wrist_roll", "gripper"]


def test_the_arm_s_joints_over_ros_2(dds_env: dict[str, str], tmp_path: Path) -> None:
    """examples/arm.rdis's node: the positions its six servos report arrive on `joint_states`,
    stamped, under the joints' names; six positions on `joint_command` are one sync write of the
    six goals its transmissions give; five of the six are an error, and nothing is written."""
    path = tmp_path / "arm_node.py"
    done = run_rdisc("emit-ros2", REPO / "examples" / "arm.rdis", "-o", path)
    assert done.returncode == 0, done.stderr
    store = typesys.get_typestore(typesys.Stores.ROS2_JAZZY)
    present = {1: 2048, 2: 1024, 3: 3072, 4: 2560, 5: 0, 6: 4095}
    angles = [(present[i] - 2048) * 2 * math.pi / 4096 for i in sorted(present)]
    with XBus() as bus:
        bus.present = present
        node = subprocess.Popen([sys.executable, str(path), "--ros-args", "-p", f"port:={bus.port}"], env=dds_env,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        arm = Participant(dds_env, "arm")
        try:
            arm.wait(lambda e: "matched" in e or "unmatched" in e, "subscription to joint_command")
            assert arm.seen[-1] == {"matched": True}

            def decoded(event: dict[str, Any]) -> Any:
                return store.deserialize_cdr(bytes.fromhex(event["joint_states"]), "sensor_msgs/msg/JointState")

            state = decoded(arm.wait(lambda e: "joint_states" in e and list(decoded(e).position) == pytest.approx(
                angles, abs=1e-12), "the servos' positions"))
            assert list(state.name) == ARM_JOINTS and state.header.stamp.sec > 0
            assert not threads.READABLE or threads.interrupts_reach_only_the_main_thread(node.pid)  # joint_states' too
            arm.send({"name": ARM_JOINTS[:5], "position": [0.0] * 5})
            arm.wait(lambda e: e.get("error") == ("RdisValueError: joint_command: sync_goal takes waist, shoulder, "
                                                  "elbow, wrist_pitch, wrist_roll, gripper together; missing: "
                                                  "gripper"), "the error of five joints")
            assert sync_goals(bus.received) == []
            arm.send({"name": ARM_JOINTS, "position": [0.0, -math.pi / 2, math.pi / 2,
                                                      math.pi / 4, 0.1, -0.1]})
            bus.wait_until(lambda: bool(sync_goals(bus.received)), 15, "a sync write of goals")
            assert sync_goals(bus.received) == [[2048, 1024, 3072, 2560, 2048 + 65, 2048 - 65]]
        finally:
            arm.stop()
            _, stderr = _stop(node, signal.SIGINT)
        assert node.returncode == 130, stderr


_SIGNAL_AT_FIRST_CALL = """\
import os, runpy, signal, sys
target, sys.argv = sys.argv[1], sys.argv[2:]  # the node's own command line
def profile(frame, event, arg):
    if event == "call" and frame.f_code.co_name == target:
        sys.setprofile(None)
        os.kill(os.getpid(), signal.SIGINT)
sys.setprofile(profile)
runpy.run_path(sys.argv[0], run_name="__main__")
"""


@pytest.mark.parametrize("target", ["_ros2_command_line", "_ros2_check_installed"])
def test_a_signal_before_the_robot_runs_ends_the_node_with_130_and_no_traceback(node_file: Path, dds_env: dict[str, str],
                                                                               target: str) -> None:
    """SIGINT as the node reads its command line, or as it looks for Cyclone DDS (before its
    robot is made and `run_command` handles signals): 130, one process, no traceback."""
    done = subprocess.run([sys.executable, "-c", _SIGNAL_AT_FIRST_CALL, target, str(node_file), "--ros-args", "-p",
                           "port:=loop://"], env=dds_env, capture_output=True, text=True, timeout=120,
                          check=False)
    assert (done.returncode, done.stderr) == (130, "")


# The node's module loaded (not run), its ROS 2 node made, and the listener of a subscription
# called as Cyclone calls it while the reader is being made (or goes): with no reader, for
# `Entity.get_entity` does not know it yet. Then a message written to the subscription's topic,
# which the node's own thread hands to the callback.
_LISTENER_WITHOUT_A_READER = """
import importlib.util, os, sys, time
spec = importlib.util.spec_from_file_location("node", sys.argv[1])
node_module = sys.modules["node"] = importlib.util.module_from_spec(spec)
spec.loader.exec_module(node_module)
messages = node_module._ros2_messages()
node = node_module._Ros2Node("listener_test", {}, messages)
got = []
listener = node.listener(node.topic("twists"), got.append)
listener.on_data_available(None)
from cyclonedds.pub import DataWriter
from cyclonedds.topic import Topic
reader = node.subscription("twists", messages.geometry_msgs.Twist, got.append)
writer = DataWriter(node.participant, Topic(node.participant, node.topic("twists"), messages.geometry_msgs.Twist),
                    qos=node.default)
twist = messages.geometry_msgs.Twist()
twist.linear.x = 0.25
for _ in range(100):  # until the reader is matched: the node's thread calls the callback
    writer.write(twist)
    time.sleep(0.1)
    if got:
        break
print(got[0].linear.x if got else None, flush=True)
node.close()
os._exit(0)  # (Cyclone's entities finalised at the interpreter's exit can wait on its threads)
"""


def test_a_subscription_s_listener_called_before_its_reader_is_known_raises_nothing(
        node_file: Path, dds_env: dict[str, str]) -> None:
    """Cyclone may call a reader's listener while the reader is being made, before Python knows
    the entity (`Entity.get_entity` gives None): the node printed a traceback on Cyclone's thread
    for each such call (a fresh machine's CI run). It takes nothing then, and what came is taken once
    the reader is made; messages after it still arrive."""
    done = subprocess.run([sys.executable, "-c", _LISTENER_WITHOUT_A_READER, str(node_file)], env=dds_env,
                          capture_output=True, text=True, timeout=120, check=False)
    assert (done.returncode, done.stdout, done.stderr) == (0, "0.25\n", "")
