"""`--foxglove` against hostile clients: a real Foxglove WebSocket server (rdisc's, in process)
on a robot whose port is the scripted fake, a well-behaved client subscribed to the bytes written
while another sends what the protocol does not hold. Each hostile message is answered with a
status that says what is wrong, or its connection is dropped; the watching client keeps getting
its messages, the device gets exactly the bytes of the calls the host made (a client cannot
publish, call a service or set a parameter), and nothing on stderr is a traceback."""

from __future__ import annotations

import json
import struct
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from engine.test_one_engine import ScriptedPort

from rdisc import engine
from rdisc.runtime import load

pytest.importorskip("foxglove")
pytest.importorskip("mcap_ros2")

from websockets.exceptions import ConnectionClosed
from websockets.sync.client import ClientConnection, connect

from rdisc.runtime.foxglove import FoxgloveServer

DESCRIPTION = """
robot t { }
connection link: serial { baud 9600 }
primitive move(speed: int in -100..100) on link pack "<b" (speed)
interface go(s: int in 0..7 = 5) { move(s) }
input set_velocity: DifferentialSpeed -> go(round(linear * 7))
"""
SUBPROTOCOL = "foxglove.sdk.v1"


class Served:
    def __init__(self, tmp: Path) -> None:
        (tmp / "t.rdis").write_text(DESCRIPTION)
        self.port = ScriptedPort()
        self.robot = load(tmp / "t.rdis").connect(self.port, threads=False)
        self.server = FoxgloveServer(engine.Session(self.robot), "t", "127.0.0.1", 0)

    @contextmanager
    def client(self) -> Iterator[tuple[ClientConnection, dict[str, int]]]:
        """A connected client and the channels' ids by topic."""
        with connect(f"ws://127.0.0.1:{self.server.port}", subprotocols=[SUBPROTOCOL], max_size=None) as socket:
            assert json.loads(socket.recv(timeout=10))["op"] == "serverInfo"
            advertised = json.loads(socket.recv(timeout=10))
            yield socket, {channel["topic"]: channel["id"] for channel in advertised["channels"]}


@pytest.fixture(scope="module")
def served(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Served]:
    found = Served(tmp_path_factory.mktemp("foxglove"))
    yield found
    found.server.stop()
    found.robot.close()


def statuses(socket: ClientConnection, count: int) -> list[str]:
    """The next `count` status messages' texts."""
    found = []
    while len(found) < count:
        message = socket.recv(timeout=10)
        if isinstance(message, str) and (status := json.loads(message))["op"] == "status":
            found.append(status["message"])
    return found


def written(watcher: ClientConnection) -> bytes:
    """The next message the watcher gets: the CDR of /rdisc/link/write's UInt8MultiArray, its data."""
    frame = watcher.recv(timeout=10)
    while isinstance(frame, str):
        frame = watcher.recv(timeout=10)
    opcode, subscription = struct.unpack_from("<BI", frame)
    assert (opcode, subscription) == (1, 7)
    return bytes(frame[13:][-1:])  # one byte written: the array's last byte


HOSTILE: list[tuple[Any, str]] = [
    ("{bad", "Invalid message: key must be a string at line 1 column 2"),
    ("[]", "Invalid message: missing field `op` at line 1 column 2"),
    (json.dumps({"op": "subscribe", "subscriptions": [{"id": 1, "channelId": 99999}]}), "Unknown channel ID: 99999"),
    (json.dumps({"op": "subscribe", "subscriptions": "x"}),
     'Invalid message: invalid type: string "x", expected a sequence'),
    (json.dumps({"op": "advertise", "channels": [{"id": 1, "topic": "/set_velocity", "encoding": "json",
                                                  "schemaName": "geometry_msgs/msg/Twist"}]}),
     "Server does not support clientPublish capability"),
    (json.dumps({"op": "setParameters", "parameters": [{"name": "speed", "value": 1e308}]}),
     "Server does not support parameters capability"),
    (b"\x01", "Invalid message: Buffer too short"),  # client data, shorter than its channel id
    (b"\x01\x01\x00\x00\x00" + struct.pack("<d", float("nan")) * 4, "Unknown channel ID: 1"),  # publish, NaN
    (b"\xff" * 100, "Invalid message: Unknown binary opcode 255"),
]


def test_each_hostile_message_is_answered_with_a_status_and_reaches_no_device(
        served: Served, capfd: pytest.CaptureFixture[str]) -> None:
    with served.client() as (watcher, channels), served.client() as (hostile, _):
        watcher.send(json.dumps({"op": "subscribe", "subscriptions": [
            {"id": 7, "channelId": channels["/rdisc/link/write"]}]}))
        for message, status in HOSTILE:
            hostile.send(message)
            assert statuses(hostile, 1) == [status]
        before = len(served.port.written)
        engine.make_call(served.robot, "interface", "go", {"s": 3})  # the host's call, after all of them
        assert bytes(served.port.written[before:]) == b"\x03"
        assert written(watcher) == b"\x03"
    assert "Traceback" not in capfd.readouterr().err


def test_thousands_of_subscriptions_cost_one_connection_and_the_others_are_served(
        served: Served, capfd: pytest.CaptureFixture[str]) -> None:
    with served.client() as (watcher, channels), served.client() as (hostile, _):
        watcher.send(json.dumps({"op": "subscribe", "subscriptions": [
            {"id": 7, "channelId": channels["/rdisc/link/write"]}]}))
        hostile.send(json.dumps({"op": "subscribe", "subscriptions": [
            {"id": number, "channelId": channels["/rdisc/link/write"]} for number in range(20_000)]}))
        answered = []
        with pytest.raises(ConnectionClosed):  # dropped: its answers (each a duplicate) fill the backlog at once
            while len(answered) < 20_000:
                answered.append(json.loads(hostile.recv(timeout=10))["message"])
        assert answered[-1] == ("Disconnected because the message backlog on the server is full. "
                                "The backlog size is configurable in the server setup.")
        before = len(served.port.written)
        engine.make_call(served.robot, "interface", "go", {"s": 4})
        assert bytes(served.port.written[before:]) == b"\x04"
        assert written(watcher) == b"\x04"
    assert "Traceback" not in capfd.readouterr().err
