"""Recordings read by an independent reader: `rosbags` opens the MCAP file of `rdisc run --record`
(and a generated driver's) as a rosbag2, and decodes every message with its own CDR decoder and
its own definitions of the ROS 2 Humble messages, not with the `mcap` libraries rdisc writes
with. The session is on a real pty against a bench device whose description has an output of
every standard adapter and inputs of four (tests/runtime/data/bench.rdis)."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from conftest import cli_env
from devices import BenchEmulator
from devices.bench import READINGS
from rosbags.highlevel import AnyReader
from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from runtime_support import DATA

from rdisc.engine import recording
from rdisc.lowering import messages

BENCH = DATA / "bench.rdis"
HUMBLE = get_typestore(Stores.ROS2_HUMBLE)
CALLS = ("--call", "set_velocity", "linear=0.5", "angular=-0.25",
         "--call", "set_pose", "x=1.5", "y=-2", "theta=0.5",
         "--call", "set_joint", "name=pan", "position=0.75",
         "--call", "command", "name=[pan,tilt,roll]", "position=[0.1,0.2,-0.3]",
         "--call", "report")


def record(command: list[str], path: Path, *calls: str,
           answers: dict[str, str | None] | None = None) -> subprocess.CompletedProcess[str]:
    """`command --port PTY --record path CALLS` against the bench device."""
    with BenchEmulator(answers) as dev:
        return subprocess.run([*command, "--port", dev.port, "--record", str(path), *calls], env=cli_env(),
                              capture_output=True, text=True, check=False)


def rosbag(path: Path) -> list[tuple[str, str, int, Any]]:
    """(topic, type, log time, message decoded by rosbags's Humble typestore) of every message."""
    with Reader(path) as reader:
        return [(connection.topic, connection.msgtype, stamp, HUMBLE.deserialize_cdr(raw, connection.msgtype))
                for connection, stamp, raw in reader.messages()]


RDISC = [sys.executable, "-m", "rdisc"]


@pytest.fixture(scope="module", params=["runtime", "driver"])
def session(request, tmp_path_factory) -> Path:
    """A recorded session of every call of CALLS, by `rdisc run` or by the bench's driver."""
    folder = tmp_path_factory.mktemp(request.param)
    command = [*RDISC, "run", str(BENCH)]
    if request.param == "driver":
        driver = folder / "bench_driver.py"
        emitted = subprocess.run([*RDISC, "emit-python", str(BENCH), "-o", str(driver)], env=cli_env(),
                                 capture_output=True, text=True, check=False)
        assert emitted.returncode == 0, emitted.stderr
        command = [sys.executable, str(driver)]
    path = folder / "bench.mcap"
    result = record(command, path, *CALLS)
    assert result.returncode == 0, result.stderr
    return path


def only(found: list[tuple[str, str, int, Any]], topic: str, kind: str) -> tuple[int, Any]:
    """The one message on a topic, checked to be of its type: (log time, message)."""
    on_topic = [(msgtype, stamp, message) for name, msgtype, stamp, message in found if name == topic]
    assert [msgtype for msgtype, _, _ in on_topic] == [kind]
    return on_topic[0][1], on_topic[0][2]


def stamped(stamp: int, message: Any) -> None:
    """A message's header carries its log time, and no frame."""
    assert (message.header.stamp.sec, message.header.stamp.nanosec) == divmod(stamp, 1_000_000_000)
    assert message.header.frame_id == ""


def read_stamped(found: list[tuple[str, str, int, Any]], stamp: int, message: Any) -> None:
    """An output's header carries when its data was read: after the reply's bytes were recorded
    and before the output was (the time its state was read, not the time it was recorded); and
    no frame, the bench having no body."""
    header = message.header.stamp.sec * 1_000_000_000 + message.header.stamp.nanosec
    reads = [at for topic, _, at, _ in found if topic == "/rdisc/line/read" and at <= header]
    assert reads and header < stamp, (reads[-1:], header, stamp)
    assert message.header.frame_id == ""


def test_every_input_as_its_message(session) -> None:
    found = rosbag(session)
    _, twist = only(found, "/set_velocity", "geometry_msgs/msg/Twist")
    assert (twist.linear.x, twist.linear.y, twist.linear.z) == (0.5, 0.0, 0.0)
    assert (twist.angular.x, twist.angular.y, twist.angular.z) == (0.0, 0.0, -0.25)
    _, pose = only(found, "/set_pose", "geometry_msgs/msg/Pose2D")
    assert (pose.x, pose.y, pose.theta) == (1.5, -2.0, 0.5)
    stamp, joint = only(found, "/set_joint", "sensor_msgs/msg/JointState")
    stamped(stamp, joint)
    assert (joint.name, joint.position.tolist(), joint.velocity.tolist(), joint.effort.tolist()) \
        == (["pan"], [0.75], [], [])
    stamp, joints = only(found, "/command", "sensor_msgs/msg/JointState")
    stamped(stamp, joints)
    assert (joints.name, joints.position.tolist()) == (["pan", "tilt", "roll"], [0.1, 0.2, -0.3])


def test_every_output_as_its_message(session) -> None:
    found = rosbag(session)
    stamp, range_ = only(found, "/range", "sensor_msgs/msg/Range")
    read_stamped(found, stamp, range_)
    assert (range_.radiation_type, range_.field_of_view, range_.min_range, range_.max_range, range_.range) \
        == (0, 0.0, 0.0, 0.0, 0.5)
    _, contact = only(found, "/contact", "std_msgs/msg/Bool")
    assert contact.data is True
    stamp, battery = only(found, "/battery", "sensor_msgs/msg/BatteryState")
    read_stamped(found, stamp, battery)
    assert (battery.voltage, battery.current, battery.charge, battery.capacity, battery.percentage) \
        == (12.25, -1.5, 2.0, 4.0, 0.75)
    assert (battery.temperature, battery.design_capacity, battery.power_supply_status, battery.present,
            battery.cell_voltage.tolist(), battery.location, battery.serial_number) == (0.0, 0.0, 0, False, [], "", "")
    stamp, odometry = only(found, "/odometry", "nav_msgs/msg/Odometry")
    read_stamped(found, stamp, odometry)
    assert odometry.child_frame_id == ""
    position, orientation = odometry.pose.pose.position, odometry.pose.pose.orientation
    assert (position.x, position.y, position.z) == (1.5, -2.0, 0.0)
    assert (orientation.x, orientation.y, orientation.z, orientation.w) == (0.0, 0.0, math.sin(0.25), math.cos(0.25))
    assert (odometry.twist.twist.linear.x, odometry.twist.twist.angular.z) == (0.25, -0.125)
    assert odometry.pose.covariance.tolist() == [0.0] * 36 == odometry.twist.covariance.tolist()
    _, pose = only(found, "/pose", "geometry_msgs/msg/Pose2D")
    assert (pose.x, pose.y, pose.theta) == (1.5, -2.0, 0.5)
    _, speeds = only(found, "/speeds", "geometry_msgs/msg/Twist")
    assert (speeds.linear.x, speeds.angular.z) == (0.25, -0.125)
    stamp, head = only(found, "/head", "sensor_msgs/msg/JointState")
    read_stamped(found, stamp, head)
    assert (head.name, head.position.tolist()) == (["pan"], [0.1])
    stamp, joints = only(found, "/joints", "sensor_msgs/msg/JointState")
    read_stamped(found, stamp, joints)
    assert (joints.name, joints.position.tolist()) == (["pan", "tilt", "roll"], [0.1, 0.2, -0.3])
    stamp, temperature = only(found, "/temperature", "sensor_msgs/msg/Temperature")
    read_stamped(found, stamp, temperature)
    assert (temperature.temperature, temperature.variance) == (36.5, 0.25)


def test_the_bytes_runs_and_errors_as_their_messages(session) -> None:
    found = rosbag(session)
    writes = [bytes(m.data) for topic, kind, _, m in found if topic == "/rdisc/line/write"]
    assert writes == [b"V,0.5,-0.25\n", b"P,1.5,-2.0,0.5\n", b"J,pan,0.75\n", b"M,0.1,0.2,-0.3\n", b"S\n"]
    reads = [bytes(m.data) for topic, kind, _, m in found if topic == "/rdisc/line/read"]
    assert reads == [b"v\n", b"p\n", b"j\n", b"m\n", f"s,{READINGS}\n".encode()]
    assert {kind for topic, kind, _, _ in found if topic.startswith("/rdisc/line/")} == {"std_msgs/msg/UInt8MultiArray"}
    runs = [m.data for topic, kind, _, m in found if topic == "/rdisc/runs" and kind == "std_msgs/msg/String"]
    assert runs[-1] == '{"call": "interface", "name": "report", "values": {}}'
    assert not [topic for topic, _, _, _ in found if topic == "/rosout"]


def test_rosbags_opens_the_file_alone_with_its_times_in_order(session) -> None:
    """An MCAP file of profile ros2 is a rosbag2 to rosbags (no metadata.yaml needed); its
    connections are CDR, and the log times only grow."""
    with Reader(session) as reader:
        assert {c.ext.serialization_format for c in reader.connections} == {"cdr"}
        stamps = [stamp for _, stamp, _ in reader.messages()]
        assert reader.message_count == len(stamps)
        assert (reader.start_time, reader.end_time) == (stamps[0], stamps[-1] + 1)
    assert stamps == sorted(stamps) and len(set(stamps)) == len(stamps)


def test_the_schemas_written_are_rosbags_own_definitions(session) -> None:
    """Each channel's schema text, parsed by rosbags, is field for field (names, types, order,
    constants) the message as ROS 2 Humble defines it; AnyReader decodes with those texts."""
    with Reader(session) as reader:
        definitions = {c.msgtype: c.msgdef.data for c in reader.connections}
    assert set(definitions) == {
        "std_msgs/msg/String", "std_msgs/msg/UInt8MultiArray", "geometry_msgs/msg/Twist", "geometry_msgs/msg/Pose2D",
        "sensor_msgs/msg/JointState", "sensor_msgs/msg/Range", "std_msgs/msg/Bool", "sensor_msgs/msg/BatteryState",
        "nav_msgs/msg/Odometry", "sensor_msgs/msg/Temperature"}
    for name, text in definitions.items():
        for part, (kind, fields) in _parsed(name, text).items():
            assert (kind, fields) == HUMBLE.fielddefs[part], part
    with AnyReader([session]) as reader:
        decoded = [reader.deserialize(raw, c.msgtype) for c, _, raw in reader.messages()]
    assert len(decoded) == len(rosbag(session))


def _parsed(name: str, text: str) -> dict[str, Any]:
    """A ros2msg schema's message and each one it uses, under its `MSG:` line, parsed by rosbags."""
    first, *used = text.split("=" * 80 + "\n")
    found = dict(get_types_from_msg(first, name))
    for part in used:
        head, _, body = part.partition("\n")
        package, _, message = head.removeprefix("MSG: ").partition("/")
        found.update(get_types_from_msg(body, f"{package}/msg/{message}"))
    return found


@pytest.mark.parametrize("name", [*messages.DEFINITIONS, "rdisc bytes", "rdisc text", "rdisc log"])
def test_every_definition_rdisc_has_is_rosbags_own(name) -> None:
    """The definitions of every standard adapter's message and of the recording's own channels,
    whether a session uses them or not."""
    own = {"rdisc bytes": (recording.BYTES_TYPE, recording._BYTES_SCHEMA),
           "rdisc text": (recording.TEXT_TYPE, recording._TEXT_SCHEMA), "rdisc log": (recording.LOG_TYPE, recording._LOG_SCHEMA)}
    kind, text = own[name] if name in own else (messages.ros2_name(name), messages.definition(name))
    for part, definition in _parsed(kind, text).items():
        assert definition == HUMBLE.fielddefs[part], part


# ---- rdisc replay compares errors --------------------------------------------------------------------

QUERY = 'primitive query() on line format "Q\\n" () regex r"^q$"'


def variant(tmp_path: Path, name: str, query: str) -> Path:
    """bench.rdis with another `query` primitive."""
    text = BENCH.read_text()
    assert QUERY in text
    path = tmp_path / f"{name}.rdis"
    path.write_text(text.replace(QUERY, query))
    return path


def test_a_refused_reply_recorded_and_not_replayed_is_a_difference(rdisc, tmp_path) -> None:
    path = tmp_path / "refused.mcap"
    result = record([*RDISC, "run", str(BENCH)], path, "--call", "ask", answers={"Q": "nope"})
    assert result.returncode == 1
    refusal = "RdisProtocolError: query: reply 'nope' does not match '^q$'"
    assert [m.msg for topic, _, _, m in rosbag(path) if topic == "/rosout"] == [refusal]
    assert rdisc("replay", path, BENCH).stdout == ""
    lenient = variant(tmp_path, "lenient", 'primitive query() on line format "Q\\n" () regex r"^\\w+$"')
    result = rdisc("replay", path, lenient)
    assert result.returncode == 1
    assert result.stdout == f"error #1: recorded, not replayed: {refusal}\n"


def test_an_error_only_in_the_replay_is_a_difference(rdisc, tmp_path) -> None:
    lenient = variant(tmp_path, "lenient", 'primitive query() on line format "Q\\n" () regex r"^\\w+$"')
    path = tmp_path / "accepted.mcap"
    result = record([*RDISC, "run", str(lenient)], path, "--call", "ask", "--call", "report", answers={"Q": "nope"})
    assert result.returncode == 0, result.stderr
    assert rdisc("replay", path, lenient).stdout == ""
    result = rdisc("replay", path, BENCH)
    assert result.returncode == 1
    assert result.stdout == ("error #1: replayed, not recorded: "
                             "RdisProtocolError: query: reply 'nope' does not match '^q$'\n")


def test_a_timeout_recorded_replays_as_it_read_and_its_absence_is_a_difference(rdisc, tmp_path) -> None:
    path = tmp_path / "timeout.mcap"
    result = record([*RDISC, "run", str(BENCH)], path, "--timeout", "0.2", "--call", "ask", answers={"Q": None})
    assert result.returncode == 1
    timeout = "RdisTimeout: query: no reply within 0.2 s"
    assert [m.msg for topic, _, _, m in rosbag(path) if topic == "/rosout"] == [timeout]
    same = rdisc("replay", path, BENCH)
    assert (same.returncode, same.stdout) == (0, "")
    unanswered = variant(tmp_path, "unanswered", 'primitive query() on line format "Q\\n" ()')
    result = rdisc("replay", path, unanswered)
    assert result.returncode == 1
    assert result.stdout == f"error #1: recorded, not replayed: {timeout}\n"


def test_errors_are_matched_by_their_text_not_their_place() -> None:
    """One error more in the replay is one line, not every later error shifted."""
    from rdisc.runtime.replay import _error_differences

    assert _error_differences(["A", "B", "C"], ["A", "X", "B", "C"]) == ["error #2: replayed, not recorded: X"]
    assert _error_differences(["A", "B"], ["A", "C"]) == ["error #2: recorded, not replayed: B",
                                                          "error #2: replayed, not recorded: C"]
    assert _error_differences([str(n) for n in range(8)], []) == [
        *(f"error #{n + 1}: recorded, not replayed: {n}" for n in range(5)), "errors: 3 more differ"]
