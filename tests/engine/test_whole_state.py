"""Post-actions that set most of the state variables: a generated driver writes them as one
function giving the whole new state, in the state's order (`Primitive.renews`), which the engine
publishes as it is instead of merging so many changes into the old one. What a reader sees is
what the runtime's merge gives: the same variables in the same order, those not set kept, the
values computed in the description's order (so the same error, when two would fail), and no
state changed by a reply whose post-actions fail."""

from __future__ import annotations

import struct
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from rdisc.emit.python import import_driver
from tests.engine.test_one_engine import implementation_of
from tests.support.ports import ScriptedPort

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
PACKET_100 = struct.Struct(">B6?BBxBBhhBHhbHHH4H3xBBB?B6hB6HBB4hB")  # as examples/create2.rdis reads it
WHOLE = """\
robot whole { author "tests" }
setting LIMIT: int in 0..100 = 5
state a: int = 0
state b: int = 1
state c: float = 0.0
state d: int = 9
state e: int = 0
connection link: serial { baud 57600 }
/// Four of the six variables (the setting one of them): the whole state, in a driver.
primitive read() on link pack "B" (0x01) unpack "<BB" {
    c = 10 / out[0]  a = 10 % out[0]  b = out[1] + LIMIT  d = out[1]
}
/// One of them: merged into the state.
primitive poke(x: int) on link pack "BB" (0x02, x) { e = x }
"""


class Device:
    """Answers `read` with `divisor` and 3."""

    def __init__(self, divisor: int) -> None:
        self.divisor = divisor

    def answer(self, request: bytes) -> bytes:
        return bytes([self.divisor, 3]) if request == b"\x01" else b""

    def listen(self) -> bytes:
        return b""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, WHOLE, tmp_path_factory.mktemp("whole"), "whole_state")


def connected(implementation: Any, port: ScriptedPort) -> Any:
    if isinstance(implementation, ModuleType):  # a driver takes each setting by keyword
        return implementation.connect(port, threads=False, LIMIT=7)
    return implementation.connect(port, threads=False, settings={"LIMIT": 7})


def test_only_a_driver_s_post_actions_that_set_most_of_the_state_give_it_whole(tmp_path: Path) -> None:
    driver = implementation_of("driver", WHOLE, tmp_path, "whole_plans")
    plans = driver._DEVICE.primitives
    assert (plans["read"].renews, plans["poke"].renews) == (True, False)
    given = driver._p_read_actions({"LIMIT": 7, "a": 0, "b": 1, "c": 0.0, "d": 9, "e": 8}, [], (4, 3))
    assert list(given.items()) == [("LIMIT", 7), ("a", 2), ("b", 10), ("c", 2.5), ("d", 3), ("e", 8)]
    create2 = import_driver(EXAMPLES / "create2.rdis", tmp_path, "create2_whole")._DEVICE
    sensors = create2.primitives["sensors"]  # packet 100: 69 of the 75 variables, none of which can fail
    assert sensors.renews and list(sensors.actions(create2.state, [], PACKET_100.unpack(bytes(80)))) == list(create2.state)
    assert not implementation_of("runtime", WHOLE, tmp_path, "whole_runtime").device.primitives["read"].renews


def test_the_state_read_whole_is_the_state_merged(implementation: Any) -> None:
    port = ScriptedPort(device=Device(4))
    with connected(implementation, port) as robot:
        robot.primitives.poke(11)
        robot.primitives.read()
        assert list(robot.state.items()) == [("LIMIT", 7), ("a", 2), ("b", 10), ("c", 2.5), ("d", 3), ("e", 11)]
        robot.primitives.poke(12)
        assert list(robot.state.items()) == [("LIMIT", 7), ("a", 2), ("b", 10), ("c", 2.5), ("d", 3), ("e", 12)]


def test_the_first_failing_value_is_the_description_s_first(implementation: Any) -> None:
    """`c = 10 / out[0]` comes before `a = 10 % out[0]` in the description, after it in the state:
    a zero divides first, as the runtime computes it, and nothing is stored."""
    port = ScriptedPort(device=Device(0))
    with connected(implementation, port) as robot:
        with pytest.raises(Exception) as raised:
            robot.primitives.read()
        assert (type(raised.value).__name__, str(raised.value)) == ("RdisValueError", "read: division by zero")
        assert dict(robot.state) == {"LIMIT": 7, "a": 0, "b": 1, "c": 0.0, "d": 9, "e": 0}
