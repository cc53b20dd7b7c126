"""A plain exchange (`Primitive.asked`: a plain pack written, a fixed number of bytes read back, no
frame, error reply or `retry`) runs in one step: its reply's known size read in one read and
decoded by its struct. Counted in Python calls, not timed (benchmarks/driver_speed.py's sensor
figures depend on it); and whatever the step, the callbacks, the typed errors and the state see
what the general way shows them. Alike in the runtime and a generated driver."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from rdisc.emit.python import import_driver
from tests.engine.test_one_engine import implementation_of
from tests.support.calls import calls_made
from tests.support.ports import ScriptedPort

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SERVO = """\
robot servo { author "tests" }
state position: int = 0
state asked: int = 0
connection link: serial { baud 57600 }
/// The position of servo `id`: its reply echoes the id.
primitive once(id: int in 0..253) on link pack "BB" (0x02, id) unpack "<BH" expect out[0] == id
    { position = out[1]  asked = id }
"""


class Servo:
    """A servo that answers every request with its id and position 512 (`short`: one byte less)."""

    def __init__(self, short: bool = False) -> None:
        self.short = short

    def answer(self, request: bytes) -> bytes:
        reply = bytes([request[1]]) + (512).to_bytes(2, "little")
        return reply[:-1] if self.short else reply

    def listen(self) -> bytes:
        return b""



@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, SERVO, tmp_path_factory.mktemp("plain"), "plain_servo")


def test_a_plain_exchange_costs_few_calls(implementation: Any) -> None:
    """`robot.primitives.once(7)`: the typed method, the robot's one step, its request, the
    exchange, the port's reset, write and read, the decoding, the `expect` and the post-actions.
    The general way (each layer a call of its own, the reply read through the port's reader)
    made 43 calls in the runtime and 34 in a driver; the port's own calls are 5 of them."""
    port = ScriptedPort(device=Servo())
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.once(7)  # the runtime's typed method made once
        made = calls_made(lambda: robot.primitives.once(7))
        assert (robot.state["position"], robot.state["asked"]) == (512, 7)
        assert port.writes == [b"\x02\x07", b"\x02\x07"]
    assert made <= (18 if isinstance(implementation, ModuleType) else 27), made


def test_the_create_2_sensor_packet_costs_a_driver_few_calls(tmp_path: Path) -> None:
    """Packet 100 (80 bytes, 69 values) through a generated driver's `robot.primitives.sensors()`:
    the method, the robot's one step, its request, the exchange, the port's reset, write and read,
    the post-actions and their 64-bit test. 31 calls before, through the general way."""
    packet = bytes(range(80))
    port = ScriptedPort(packet * 2)
    driver = import_driver(EXAMPLES / "create2.rdis", tmp_path, "create2_plain")
    with driver.connect(port, threads=False) as robot:
        robot.primitives.sensors()
        made = calls_made(robot.primitives.sensors)
        assert port.writes == [b"\x8e\x64", b"\x8e\x64"]
        assert (robot.state["bump_left"], robot.state["distance"]) == (False, int.from_bytes(packet[12:14], "big",
                                                                                               signed=True))
    assert made <= 13, made


def test_the_callbacks_see_the_request_and_the_reply(implementation: Any) -> None:
    port = ScriptedPort(device=Servo())
    seen: list[tuple[Any, ...]] = []
    with implementation.connect(port, threads=False) as robot:
        robot.on_io(lambda kind, connection, data: seen.append((kind, connection, data)))
        robot.on_trace(lambda when, kind, connection, data: seen.append(("trace", kind, data)))
        robot.primitives.once(7)
    assert seen == [("write", "link", b"\x02\x07"), ("trace", "write", b"\x02\x07"),
                    ("read", "link", b"\x07\x00\x02"), ("trace", "read", b"\x07\x00\x02")]


@pytest.mark.parametrize(("servo", "error", "said"), [
    (None, "RdisTimeout", "once: no reply within 1 s"),
    (Servo(short=True), "RdisProtocolError", "once: expected 3 bytes, got 2"),
])
def test_a_reply_missing_or_short_is_the_general_ways_error(implementation: Any, servo: Servo | None,
                                                             error: str, said: str) -> None:
    """(The driver's errors are its own classes: known here by name.)"""
    port = ScriptedPort(device=servo)
    seen: list[tuple[str, bytes]] = []
    with implementation.connect(port, threads=False) as robot:
        robot.on_io(lambda kind, connection, data: seen.append((kind, data)))
        with pytest.raises(Exception) as raised:
            robot.primitives.once(7)
        assert (type(raised.value).__name__, str(raised.value)) == (error, said)
        assert robot.state["position"] == 0  # no post-action ran
    assert seen[0] == ("write", b"\x02\x07")


def test_a_reply_that_fails_its_expect_changes_no_state(implementation: Any) -> None:
    port = ScriptedPort(device=Servo())
    with implementation.connect(port, threads=False) as robot:
        port.device = type("Other", (), {"answer": lambda self, request: b"\x08\x00\x02",
                                         "listen": lambda self: b""})()
        with pytest.raises(Exception) as raised:
            robot.primitives.once(7)
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert str(raised.value) == "once: reply (8, 512) does not meet its `expect`"
        assert robot.state["position"] == 0


def test_a_failing_port_is_a_connection_error(implementation: Any) -> None:
    port = ScriptedPort(device=Servo())
    with implementation.connect(port, threads=False) as robot:
        port.fail = True
        with pytest.raises(Exception) as raised:
            robot.primitives.once(7)
        assert type(raised.value).__name__ == "RdisConnectionError"
        assert str(raised.value) == "link: [Errno 5] the device is gone"
