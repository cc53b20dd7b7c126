"""`rdisc run --foxglove`: the live session through the Foxglove WebSocket protocol, watched by a
client written here (the protocol, `foxglove.sdk.v1`, over the `websockets` library), its
messages decoded by rosbags from the schema text the server advertised."""

from __future__ import annotations

import json
import os
import re
import select
import signal
import struct
import subprocess
import sys
import time
from typing import Any

import pytest
from conftest import cli_env, console_origin, console_ws, stop_process
from devices import CreateEmulator
from devices.create import STOP
from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from runtime_support import DATA, REPO
from websockets.sync.client import connect

pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

SUBPROTOCOL = "foxglove.sdk.v1"  # foxglove.websocket.v1 as foxglove-sdk names it (the SDK takes no other)
MESSAGE_DATA = 0x01  # the opcode of a binary frame of message data


def _line(process: subprocess.Popen[str], timeout: float = 20) -> str:
    """The process's next line on stdout, waited for at most `timeout` seconds."""
    assert process.stdout is not None
    ready, _, _ = select.select([process.stdout], [], [], timeout)
    assert ready, "no line on stdout"
    return process.stdout.readline()


def _typestore(name: str, text: str) -> Any:
    """A rosbags typestore that knows the message `name` from its ros2msg schema text alone
    (its own fields, then each message it uses under its `MSG:` line)."""
    first, *used = text.split("=" * 80 + "\n")
    types = dict(get_types_from_msg(first, name))
    for part in used:
        head, _, body = part.partition("\n")
        package, _, message = head.removeprefix("MSG: ").partition("/")
        types.update(get_types_from_msg(body, f"{package}/msg/{message}"))
    store = get_typestore(Stores.EMPTY)
    store.register(types)
    return store


class Client:
    """A Foxglove WebSocket client: the channels the server advertised, subscriptions by topic,
    and each message received decoded with its channel's advertised schema."""

    def __init__(self, socket: Any) -> None:
        self.socket = socket
        assert self.socket.subprotocol == SUBPROTOCOL
        self.info = json.loads(self.socket.recv(timeout=10))
        self.channels: dict[str, dict[str, Any]] = {}
        while not self.channels:  # the server advertises its channels after its serverInfo
            message = json.loads(self.socket.recv(timeout=10))
            if message["op"] == "advertise":
                self.channels = {channel["topic"]: channel for channel in message["channels"]}
        self.topics: dict[int, str] = {}

    def subscribe(self, *topics: str) -> None:
        subscriptions = [{"id": 10 + i, "channelId": self.channels[topic]["id"]} for i, topic in enumerate(topics)]
        self.topics.update({s["id"]: topic for s, topic in zip(subscriptions, topics)})
        self.socket.send(json.dumps({"op": "subscribe", "subscriptions": subscriptions}))

    def receive(self, until: Any, limit: int = 400) -> list[tuple[str, int, Any]]:
        """(topic, timestamp, decoded message) of each message received, in order, until
        `until(that list)` holds (at most `limit` messages)."""
        found: list[tuple[str, int, Any]] = []
        while not until(found):
            assert len(found) < limit, found[-5:]
            frame = self.socket.recv(timeout=10)
            if isinstance(frame, str):
                continue  # a status, or channels advertised again
            opcode, subscription, stamp = struct.unpack_from("<BIQ", frame)
            assert opcode == MESSAGE_DATA
            channel = self.channels[self.topics[subscription]]
            assert (channel["encoding"], channel["schemaEncoding"]) == ("cdr", "ros2msg")
            store = _typestore(channel["schemaName"], channel["schema"])
            found.append((channel["topic"], stamp, store.deserialize_cdr(frame[13:], channel["schemaName"])))
        return found


def _rdisc_run(dev: CreateEmulator, *args: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "rdisc", "run", str(DATA / "fast_create.rdis"), "--port", dev.port,
         "--duration", "60", *args],
        cwd=REPO, env=cli_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def test_a_client_subscribes_to_outputs_state_and_bytes_and_decodes_them_with_the_advertised_schemas() -> None:
    with CreateEmulator(bumpers=0) as dev:
        process = _rdisc_run(dev, "--foxglove", "127.0.0.1:0")
        try:
            said = _line(process)
            assert said.startswith("rdisc run: Foxglove on ws://127.0.0.1:"), said
            port = int(said.split("ws://127.0.0.1:")[1].split()[0])
            with connect(f"ws://127.0.0.1:{port}", subprotocols=[SUBPROTOCOL], open_timeout=10, max_queue=None) as socket:
                client = Client(socket)
                assert client.info["op"] == "serverInfo" and client.info["name"] == "fast_create"
                assert {topic: (c["schemaName"], c["encoding"]) for topic, c in client.channels.items()} == {
                    "/set_velocity": ("geometry_msgs/msg/Twist", "cdr"),
                    "/detect_bump": ("sensor_msgs/msg/Range", "cdr"),
                    "/battery_charge": ("sensor_msgs/msg/Range", "cdr"),
                    "/state/bumperStates": ("std_msgs/msg/Int64", "cdr"),
                    "/state/charge": ("std_msgs/msg/Int64", "cdr"),
                    "/rdisc/btserial/write": ("std_msgs/msg/UInt8MultiArray", "cdr"),
                    "/rdisc/btserial/read": ("std_msgs/msg/UInt8MultiArray", "cdr"),
                    "/rdisc/runs": ("std_msgs/msg/String", "cdr"),
                    "/rosout": ("rcl_interfaces/msg/Log", "cdr")}

                client.subscribe("/detect_bump", "/state/bumperStates", "/rdisc/btserial/write", "/rdisc/btserial/read")
                first = client.receive(lambda found: any(topic == "/detect_bump" for topic, _, _ in found))
                dev.bumpers = 2  # the left bumper: the state changes, and the range with it

                def changed(found: list[tuple[str, int, Any]]) -> bool:
                    return any(t == "/state/bumperStates" for t, _, _ in found) and any(
                        t == "/detect_bump" and m.range == 0.0 for t, _, m in found)

                later = client.receive(changed)
        finally:
            process.send_signal(signal.SIGINT)
            _, stderr = process.communicate(timeout=20)
        assert process.returncode == 130, stderr
        assert dev.commands[-1][1] == STOP  # the terminate hook ran, Foxglove or not
    found = first + later
    ranges = [m for topic, _, m in found if topic == "/detect_bump"]
    values = [m.range for m in ranges]
    ones = values.count(1.0)
    assert ones >= 1 and values == [1.0] * ones + [0.0] * (len(values) - ones)  # no bumper, then the left
    assert {(m.radiation_type, m.field_of_view, m.min_range, m.max_range) for m in ranges} == {(0, 0.0, 0.0, 0.0)}
    assert all(m.header.stamp.sec > 0 for m in ranges)
    assert [m.data for topic, _, m in later if topic == "/state/bumperStates"] == [2]
    writes = [bytes(m.data) for topic, _, m in found if topic == "/rdisc/btserial/write"]
    polls = writes.count(bytes([142, 7]))  # the bumpers' poll, 20 times a second
    assert polls >= 2 and writes[-polls:] == [bytes([142, 7])] * polls
    assert writes[:-polls] in ([], [b"\x84"], [b"\x80", b"\x84"])  # the startup's end, if it was that early
    reads = [bytes(m.data) for topic, _, m in found if topic == "/rdisc/btserial/read"]
    zeros = reads.count(b"\x00")
    assert zeros >= 1 and reads == [b"\x00"] * zeros + [b"\x02"] * (len(reads) - zeros)  # the bumpers' byte
    stamps = [stamp for _, stamp, _ in found]
    assert stamps == sorted(stamps) and abs(stamps[0] / 1e9 - time.time()) < 600  # the host's clock, in order


@pytest.mark.parametrize(("address", "message"), [
    ("8766", "rdisc run: --foxglove `8766` is not HOST:PORT"),
    ("0.0.0.0:0", ("rdisc run: --foxglove 0.0.0.0:0 serves beyond this machine, where anyone on the network could "
                  "watch the robot: add --allow-remote if that is meant")),
    ("192.0.2.1:0", ("rdisc run: cannot serve Foxglove on 192.0.2.1:0: Failed to bind port: Cannot assign "
                    "requested address (os error 99)")),
], ids=["no-port", "beyond-loopback", "not-this-machine"])
def test_a_bad_address_is_a_usage_error_in_one_line(rdisc, address, message) -> None:
    extra = ["--allow-remote"] if address.startswith("192.") else []
    result = rdisc("run", DATA / "fast_create.rdis", "--port", "loop://", "--foxglove", address, *extra)
    assert (result.returncode, result.stderr, result.stdout) == (2, message + "\n", "")


def test_without_foxglove_sdk_it_says_what_to_install(rdisc, tmp_path) -> None:
    """With the package hidden (a `foxglove` that cannot be imported first on the path)."""
    (tmp_path / "foxglove").mkdir()
    (tmp_path / "foxglove" / "__init__.py").write_text("raise ImportError('hidden by the test')\n")
    env = cli_env()
    env["PYTHONPATH"] = os.pathsep.join([str(tmp_path), env.get("PYTHONPATH", "")])
    result = subprocess.run(
        [sys.executable, "-m", "rdisc", "run", str(DATA / "fast_create.rdis"), "--port", "loop://", "--foxglove"],
        cwd=REPO, env=env, capture_output=True, text=True, timeout=60, check=False)
    assert (result.returncode, result.stderr) == (
        2, ("rdisc run: --foxglove needs the foxglove-sdk and mcap-ros2-support packages "
           "(pip install foxglove-sdk mcap-ros2-support)\n"))
    plain = subprocess.run([sys.executable, "-m", "rdisc", "run", str(DATA / "fast_create.rdis"), "--port", "loop://",
                            "--call", "drive", "velocity=0.1", "radius=0"],
                           cwd=REPO, env=env, capture_output=True, text=True, timeout=60, check=False)
    assert (plain.returncode, plain.stderr) == (0, "")  # rdisc runs without it


def test_the_console_serves_its_pages_calls_to_foxglove_too() -> None:
    """`rdisc console --foxglove`: a call a page makes reaches Foxglove as the host's, as the
    input's message, on /rdisc/runs and as the bytes it wrote."""
    with CreateEmulator() as dev:
        process = subprocess.Popen(
            [sys.executable, "-m", "rdisc", "console", str(DATA / "fast_create.rdis"), "--port", dev.port,
             "--http", "127.0.0.1:0", "--foxglove", "127.0.0.1:0"],
            cwd=REPO, env=cli_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            said = _line(process)
            assert said.startswith("rdisc console: Foxglove on ws://127.0.0.1:"), said
            port = int(said.split("ws://127.0.0.1:")[1].split()[0])
            page = re.search(r"http://127\.0\.0\.1:\d+/\?token=[A-Za-z0-9_-]+", _line(process))
            assert page is not None
            with connect(f"ws://127.0.0.1:{port}", subprotocols=[SUBPROTOCOL], open_timeout=10, max_queue=None) as socket:
                client = Client(socket)
                client.subscribe("/detect_bump", "/set_velocity", "/rdisc/runs", "/rdisc/btserial/write")
                client.receive(lambda found: len(found) > 0)  # subscribed: the bumpers' poll is arriving
                with connect(console_ws(page.group(0)), origin=console_origin(page.group(0)), max_queue=None) as ws:
                    assert json.loads(ws.recv(timeout=30))["type"] == "hello"
                    ws.send(json.dumps({"id": 1, "kind": "input", "name": "set_velocity",
                                        "values": {"linear": "0.2", "angular": "0"}}))
                    found = client.receive(lambda found: any(
                        t == "/rdisc/btserial/write" and bytes(m.data)[0] == 0x89 for t, _, m in found))
        finally:
            status, stderr = stop_process(process, signal.SIGINT)
        assert status == 130 and "Traceback" not in stderr, stderr
    twists = [(m.linear.x, m.linear.y, m.angular.z) for topic, _, m in found if topic == "/set_velocity"]
    assert twists == [(0.2, 0.0, 0.0)]
    runs = [json.loads(m.data) for topic, _, m in found if topic == "/rdisc/runs"]
    calls = [run for run in runs if "call" in run]  # the bumpers' poll runs there too, as often as it comes
    assert calls == [{"call": "input", "name": "set_velocity", "values": {"linear": 0.2, "angular": 0.0}}]
    drives = [bytes(m.data) for topic, _, m in found if topic == "/rdisc/btserial/write" and m.data[0] == 0x89]
    assert drives == [bytes.fromhex("89 00 c8 7f ff")]  # Table 4.3: 0.2 m/s straight ahead


def test_beyond_loopback_with_allow_remote_it_serves_and_warns(rdisc) -> None:
    result = rdisc("run", DATA / "fast_create.rdis", "--port", "loop://", "--foxglove", "0.0.0.0:0", "--allow-remote",
                   "--call", "drive", "velocity=0.1", "radius=0")
    assert (result.returncode, result.stderr) == (0, "")
    said = result.stdout.splitlines()
    assert len(said) == 2 and re.fullmatch(
        r"rdisc run: Foxglove on ws://0\.0\.0\.0:\d+ \(in Foxglove: Open connection, Foxglove WebSocket\)", said[0])
    assert said[1] == ("rdisc run: WARNING: served beyond this machine (0.0.0.0:0): anyone on the network can watch "
                       "the robot")
