"""Recordings: `rdisc run --record FILE.mcap` (and a generated driver's, and `rdisc console`'s)
against the emulated Create on a pty, read back with the `mcap` and `mcap-ros2-support` readers,
then `rdisc replay` with the same description and with changed ones. The console is driven over
its WebSocket as a page of its own address drives it (no browser); every wait is for a condition."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from conftest import cli_env, console_origin, console_ws, start_console, stop_process
from devices import CreateEmulator
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from runtime_support import DATA, EXAMPLES
from websockets.sync.client import connect

CREATE2 = EXAMPLES / "create2.rdis"
# The bumpers polled every tick: a sensor (examples/create.rdis) reads by the clock; a replay follows the recorded
# timestamps (tests/runtime/test_replay_sensors.py), but its 40 Hz ticks come exactly at its 100 ms cache time,
# where microseconds between a run's stamp and the live decision could decide a read the other way.
CREATE = DATA / "polled" / "create.rdis"
pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

CALLS = ("--call", "set_velocity", "linear=0.2", "angular=0",
         "--call", "set_velocity", "linear=-0.2", "angular=-0.4")


def record(command: list[str], path: Path) -> subprocess.CompletedProcess[str]:
    """Run `command --port PTY --record path` against a Create whose right bumper is pressed."""
    with CreateEmulator(bumpers=1) as dev:
        result = subprocess.run([*command, "--port", dev.port, "--record", str(path), *CALLS, "--duration", "0.3"],
                                env=cli_env(), capture_output=True, text=True, check=False)
        dev.wait_for_commands(1, opcode=137)
    assert result.returncode == 0, result.stderr
    return result


def messages(path: Path) -> list[tuple[str, str, Any]]:
    """(topic, schema name, decoded message) of every message, in order."""
    with path.open("rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        return [(channel.topic, schema.name, message)
                for schema, channel, _, message in reader.iter_decoded_messages(log_time_order=True)]


@pytest.fixture(scope="module")
def recording(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("record") / "create.mcap"
    record([sys.executable, "-m", "rdisc", "run", str(CREATE)], path)
    return path


def test_inputs_are_recorded_as_twists(recording) -> None:
    twists = [(schema, m.linear.x, m.linear.y, m.angular.z) for topic, schema, m in messages(recording)
              if topic == "/set_velocity"]
    assert twists == [("geometry_msgs/msg/Twist", 0.2, 0.0, 0.0), ("geometry_msgs/msg/Twist", -0.2, 0.0, -0.4)]


def test_outputs_are_recorded_as_ranges(recording) -> None:
    ranges = [(schema, m.range, m.header.frame_id) for topic, schema, m in messages(recording)
              if topic == "/detect_bump"]
    assert ranges
    assert set(ranges) == {("sensor_msgs/msg/Range", 0.0, "")}


def test_outputs_are_stamped_when_their_reply_was_read_and_name_their_frame(tmp_path: Path) -> None:
    """tests/runtime/data/framed_create.rdis: `detect_bump` names the bumper link, `base_bump`
    (no `frame`) the base. Each Range's header stamp is when the bumpers' reply was read: after
    the read was seen, before the Range was recorded (recording times are the host's clock) and,
    but for the last poll (closing cuts its delay short), at least the poll's 60 ms delay before;
    the two outputs of one poll carry the same stamp."""
    path = tmp_path / "framed.mcap"
    with CreateEmulator(bumpers=1) as dev:
        result = subprocess.run([sys.executable, "-m", "rdisc", "run", str(DATA / "framed_create.rdis"), "--port",
                                 dev.port, "--record", str(path), "--duration", "0.3"],
                                env=cli_env(), capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stderr
    with path.open("rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        found = [(channel.topic, message.log_time, decoded)
                 for _, channel, message, decoded in reader.iter_decoded_messages(log_time_order=True)]
    polls: list[tuple[int, dict[str, tuple[int, str, float, int]]]] = []  # each read's time, the Ranges after it
    for topic, logged, decoded in found:
        if topic == "/rdisc/btserial/read":
            polls.append((logged, {}))
        elif topic in ("/detect_bump", "/base_bump"):
            stamp = decoded.header.stamp.sec * 1_000_000_000 + decoded.header.stamp.nanosec
            assert polls and polls[-1][0] <= stamp < logged, (polls[-1][0], stamp, logged)
            polls[-1][1][topic] = (stamp, decoded.header.frame_id, decoded.range, logged)
    delivered = [ranges for _, ranges in polls if ranges]
    assert len(delivered) >= 3
    for ranges in delivered[:-1]:
        assert all(logged - stamp >= 60_000_000 for stamp, _, _, logged in ranges.values()), ranges
    for ranges in delivered:
        assert {topic: (frame, distance) for topic, (_, frame, distance, _) in ranges.items()} == {
            "/detect_bump": ("bumper", 0.0), "/base_bump": ("base", 0.0)}
        assert ranges["/detect_bump"][0] == ranges["/base_bump"][0]  # one reply read: one time
    stamps = [ranges["/detect_bump"][0] for ranges in delivered]
    assert stamps == sorted(set(stamps))  # each poll's own


def test_the_bytes_each_way(recording) -> None:
    found = messages(recording)
    assert {schema for topic, schema, _ in found if topic.startswith("/rdisc/btserial/")} \
        == {"std_msgs/msg/UInt8MultiArray"}
    writes = [bytes(m.data) for topic, _, m in found if topic == "/rdisc/btserial/write"]
    reads = [bytes(m.data) for topic, _, m in found if topic == "/rdisc/btserial/read"]
    assert writes[:2] == [b"\x80", b"\x84"]  # the startup hook
    drives = [w for w in writes if w[0] == 137]
    assert drives == [bytes.fromhex("89 00 c8 7f ff"), bytes.fromhex("89 ff 38 01 f4"), bytes.fromhex("89 00 00 00 00")]
    assert writes[-1] == bytes.fromhex("89 00 00 00 00")  # the terminate hook
    polls = [w for w in writes if w[0] == 142]
    assert polls and set(polls) == {b"\x8e\x07"}
    assert reads == [b"\x01"] * len(polls)


def test_the_runs_in_order_and_the_file_is_ros2(recording) -> None:
    runs = [json.loads(m.data) for topic, _, m in messages(recording) if topic == "/rdisc/runs"]
    calls = [run for run in runs if "call" in run]
    assert calls == [{"call": "input", "name": "set_velocity", "values": {"linear": 0.2, "angular": 0}},
                     {"call": "input", "name": "set_velocity", "values": {"linear": -0.2, "angular": -0.4}}]
    assert {json.dumps(run) for run in runs if "call" not in run} \
        <= {'{"periodic": "get_bumpers", "connection": "btserial"}', '{"keepalive": "get_bumpers", "connection": "btserial"}'}
    with recording.open("rb") as f:
        reader = make_reader(f)
        assert reader.get_header().profile == "ros2"
        summary = reader.get_summary()
        assert summary is not None
        assert {s.encoding for s in summary.schemas.values()} == {"ros2msg"}
        assert {c.message_encoding for c in summary.channels.values()} == {"cdr"}
        twist = next(s for s in summary.schemas.values() if s.name == "geometry_msgs/msg/Twist")
        assert twist.data.decode() == ("Vector3 linear\nVector3 angular\n" + "=" * 80
                                       + "\nMSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n")
        metadata = {m.name: m.metadata for m in reader.iter_metadata()}
        assert metadata == {"rdisc": {"robot": "irobot_create", "timeout": "1.0", "settings": "{}"}}


def test_replay_with_the_same_description_finds_no_difference(rdisc, recording) -> None:
    result = rdisc("replay", recording, CREATE)
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout == ""


def test_replay_names_the_output_and_the_field_that_differ(rdisc, recording, tmp_path) -> None:
    changed = tmp_path / "create.rdis"
    changed.write_text(CREATE.read_text().replace("== 0 else 0.0", "== 0 else 0.25"))
    result = rdisc("replay", recording, changed)
    assert result.returncode == 1
    lines = result.stdout.splitlines()
    assert lines[0] == "detect_bump #1: distance (range): recorded 0.0, replayed 0.25"
    assert all(line.startswith("detect_bump") for line in lines)
    assert f"{changed} differs from {recording}" in result.stderr


def test_replay_names_a_write_that_differs(rdisc, recording, tmp_path) -> None:
    changed = tmp_path / "create.rdis"
    changed.write_text(CREATE.read_text().replace("round(velocity * 1000)", "round(velocity * 500)"))
    result = rdisc("replay", recording, changed)
    assert result.returncode == 1
    drives = [line for line in result.stdout.splitlines() if "recorded 89" in line]
    assert [line.split(": ", 1)[1] for line in drives] == ["recorded 89 00 c8 7f ff, replayed 89 00 64 7f ff",
                                                           "recorded 89 ff 38 01 f4, replayed 89 ff 9c 01 f4"]
    assert all(line.startswith("btserial writes #") for line in drives)


def test_replay_of_what_is_not_a_recording(rdisc, tmp_path) -> None:
    junk = tmp_path / "junk.mcap"
    junk.write_bytes(b"not an mcap file")
    result = rdisc("replay", junk, CREATE)
    assert result.returncode == 2
    assert result.stderr.startswith(f"rdisc replay: {junk}: not a readable recording")
    assert "Traceback" not in result.stderr


def test_a_driver_records_too_and_its_recording_replays(rdisc, tmp_path) -> None:
    driver = tmp_path / "create_driver.py"
    assert rdisc("emit-python", CREATE, "-o", driver).returncode == 0
    path = tmp_path / "driver.mcap"
    record([sys.executable, str(driver)], path)
    twists = [(m.linear.x, m.angular.z) for topic, _, m in messages(path) if topic == "/set_velocity"]
    assert twists == [(0.2, 0.0), (-0.2, -0.4)]
    result = rdisc("replay", path, CREATE)
    assert result.returncode == 0, result.stdout + result.stderr


def test_without_the_mcap_libraries_record_says_what_to_install(rdisc, tmp_path) -> None:
    hidden = tmp_path / "hidden" / "mcap_ros2"
    hidden.mkdir(parents=True)
    (hidden / "__init__.py").write_text("raise ImportError('hidden by the test')\n")
    with CreateEmulator() as dev:
        result = rdisc("run", CREATE, "--port", dev.port, "--record", tmp_path / "x.mcap",
                       env={"PYTHONPATH": str(hidden.parent)})
    assert result.returncode == 2
    assert result.stderr == ("rdisc run: --record needs the mcap and mcap-ros2-support packages "
                             "(pip install mcap mcap-ros2-support)\n")
    assert not (tmp_path / "x.mcap").exists()


def call(page, ident: int, kind: str, name: str, **values: str) -> dict:
    """Make one call as the page does; the console's result for it."""
    page.send(json.dumps({"id": ident, "kind": kind, "name": name, "values": values}))
    while True:
        event = json.loads(page.recv(timeout=60))
        if event["type"] == "result" and event["id"] == ident:
            return event


def test_the_consoles_page_calls_are_recorded_as_the_hosts(rdisc, tmp_path) -> None:
    path = tmp_path / "console.mcap"
    with CreateEmulator() as dev:
        process, _, url = start_console(CREATE, "--port", dev.port, "--record", path)
        try:
            with connect(console_ws(url), origin=console_origin(url), compression=None) as page:
                assert call(page, 1, "input", "set_velocity", linear="0.2", angular="0")["ok"] is True
                refused = call(page, 2, "primitive", "drive", velocity="100000", radius="0")
                assert refused["ok"] is False
                dev.wait_for_commands(1, opcode=137)
                # stopped with the page open: the last page closing would run the terminate hook too
                status, stderr = stop_process(process, signal.SIGINT)
        finally:
            if process.poll() is None:
                process.kill()
                process.communicate()
    assert status == 130, stderr
    assert "Traceback" not in stderr
    found_messages = messages(path)
    twists = [(schema, m.linear.x, m.angular.z) for topic, schema, m in found_messages if topic == "/set_velocity"]
    assert twists == [("geometry_msgs/msg/Twist", 0.2, 0.0)]
    calls = [json.loads(m.data) for topic, _, m in found_messages if topic == "/rdisc/runs"]
    assert [c for c in calls if "call" in c] == [
        {"call": "input", "name": "set_velocity", "values": {"linear": 0.2, "angular": 0.0}},
        {"call": "primitive", "name": "drive", "values": {"velocity": 100000, "radius": 0}}]
    writes = [bytes(m.data) for topic, _, m in found_messages if topic == "/rdisc/btserial/write"]
    assert writes[:2] == [b"\x80", b"\x84"]  # the startup hook
    assert [w for w in writes if w[0] == 137] == [bytes.fromhex("89 00 c8 7f ff"), bytes.fromhex("89 00 00 00 00")]
    errors = [m.msg for topic, _, m in found_messages if topic == "/rosout"]
    assert errors == [f"{refused['error']}: {refused['message']}"]
    assert rdisc("replay", path, CREATE).returncode == 0


def test_a_simulated_session_is_recorded(tmp_path: Path) -> None:
    """`rdisc console --sim --record`: the page's call, the simulated odometry and the bytes written."""
    pytest.importorskip("mujoco")
    path = tmp_path / "sim.mcap"
    process, _, url = start_console(CREATE2, "--sim", "--record", path)
    try:
        with connect(console_ws(url), origin=console_origin(url), compression=None) as ws:
            assert call(ws, 1, "input", "set_velocity", linear="0.2", angular="0")["ok"] is True
            for _ in range(1000):  # the odometry's pushes, until it has moved
                event = json.loads(ws.recv(timeout=60))
                if event["type"] == "output" and event["contents"]["x"] > 0.01:
                    break
            assert event["type"] == "output" and event["contents"]["x"] > 0.01, event
    finally:
        status, stderr = stop_process(process, signal.SIGINT)
    assert status == 130, stderr
    assert "Traceback" not in stderr, stderr
    found = messages(path)
    assert [(m.linear.x, m.angular.z) for topic, _, m in found if topic == "/set_velocity"] == [(0.2, 0.0)]
    odometry = [m.pose.pose.position.x for topic, _, m in found if topic == "/odom"]
    assert odometry[-1] > 0.01 and odometry == sorted(odometry)
    writes = [bytes(m.data) for topic, _, m in found if topic == "/rdisc/oi/write"]
    assert bytes.fromhex("91 00 c8 00 c8") in writes  # drive_direct(200, 200)


def test_a_console_record_file_that_cannot_be_written_is_a_usage_error(rdisc, tmp_path) -> None:
    where = tmp_path / "no-such-folder" / "x.mcap"
    result = rdisc("console", CREATE, "--port", "loop://", "--record", where)
    assert result.returncode == 2
    assert result.stderr.startswith(f"rdisc console: cannot write {where}: ")
    assert "Traceback" not in result.stderr
