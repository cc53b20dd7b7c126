"""`until COND every P within T` on a call in an interface: the call made again every P until
COND (over state and the interface's parameters) holds after it, at most T / P more times, else
an RdisTimeout saying how many calls were made. Alike in the runtime and a generated driver."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

MOVER = """\
robot mover { author "tests" }
state moving: bool = False
state position: int = 0
connection link: serial { baud 57600 }
primitive go(goal: int) on link pack "<BH" (0x03, goal)
primitive status() on link pack "B" (0x04) unpack "<?H" { moving = out[0]  position = out[1] }
/// Move, then ask until the servo has stopped at the goal.
interface move_to(goal: int in 0..4095) {
    go(goal)
    status() until not moving and position == goal every 10 ms within 30 ms
}
/// A write-only call polled too (not one plain write: the poll is in the way).
interface nudge(goal: int) { go(goal) until moving every 10 ms within 20 ms }
adapter Goal { goal: int }
input set_goal: Goal -> nudge(goal)
"""


class Servo:
    """A servo that reaches its goal on the `arrives`-th status request after a move."""

    def __init__(self, arrives: int) -> None:
        self.arrives = arrives
        self.asked = 0
        self.goal = 0

    def answer(self, request: bytes) -> bytes:
        if request[0] == 0x03:
            self.goal = int.from_bytes(request[1:3], "little")
            self.asked = 0
            return b""
        self.asked += 1
        there = self.asked >= self.arrives
        return bytes([not there]) + (self.goal if there else 100).to_bytes(2, "little")

    def listen(self) -> bytes:
        return b""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, MOVER, tmp_path_factory.mktemp("poll"), "mover")


def test_polls_until_the_condition_holds(implementation: Any) -> None:
    port = ScriptedPort(device=Servo(arrives=3))
    with implementation.connect(port, threads=False) as robot:
        robot.call_interface("move_to", 512)
        assert port.writes == [b"\x03\x00\x02", b"\x04", b"\x04", b"\x04"]
        assert (robot.state["moving"], robot.state["position"]) == (False, 512)


def test_a_condition_that_holds_at_once_makes_one_call(implementation: Any) -> None:
    port = ScriptedPort(device=Servo(arrives=1))
    with implementation.connect(port, threads=False) as robot:
        robot.call_interface("move_to", 7)
        assert port.writes == [b"\x03\x07\x00", b"\x04"]


def test_not_within_the_limit_is_a_timeout_saying_how_many_calls(implementation: Any) -> None:
    port = ScriptedPort(device=Servo(arrives=5))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:  # the driver's RdisTimeout is its own class
            robot.call_interface("move_to", 512)
        assert type(caught.value).__name__ == "RdisTimeout"
        assert str(caught.value) == "move_to: status() did not meet its `until` within 0.03 s (4 calls, every 0.01 s)"
        assert port.writes == [b"\x03\x00\x02"] + [b"\x04"] * 4
        assert robot.state["position"] == 100


def test_a_write_only_call_is_polled_too(implementation: Any) -> None:
    port = ScriptedPort(device=Servo(arrives=1))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_interface("nudge", 7)
        assert str(caught.value) == "nudge: go() did not meet its `until` within 0.02 s (3 calls, every 0.01 s)"
        assert port.writes == [b"\x03\x07\x00"] * 3
        with pytest.raises(Exception) as caught:  # an input's one call: not a plain write either
            robot.call_input("set_goal", goal=8)
        assert str(caught.value) == "nudge: go() did not meet its `until` within 0.02 s (3 calls, every 0.01 s)"
        assert port.writes[3:] == [b"\x03\x08\x00"] * 3


def test_until_goes_through_json_and_back(tmp_path: Path) -> None:
    compilation, built = through_json(MOVER, tmp_path, "mover")
    assert not compilation.diagnostics.items
    calls = next(i for i in json.loads(built)["interfaces"] if i["name"] == "move_to")["primitiveCalls"]
    assert {k: calls[1][k] for k in ("until", "every", "within")} == {
        "until": "<not moving and position == goal>", "every": 10, "within": 30}


def test_until_is_printed_back_as_written() -> None:
    diagnostics = Diagnostics()
    printed = print_module(parse("mover.rdis", MOVER, diagnostics))
    assert not diagnostics.items
    assert "    status() until not moving and position == goal every 10 ms within 30 ms\n" in printed
    again = Diagnostics()
    assert print_module(parse("mover.rdis", printed, again)) == printed and not again.items


@pytest.mark.parametrize(("option", "expected"), [
    ("until position every 10 ms within 1 s", [("E401", "`until` takes a bool, but this is an int")]),
    ("until position == 1 every 0 ms within 1 s",
     [("E204", "a poll's interval must be positive and at most its limit, not every 0 ms within 1000 ms")]),
    ("until position == 1 every 2 s within 1 s",
     [("E204", "a poll's interval must be positive and at most its limit, not every 2000 ms within 1000 ms")]),
    ("until position == 1 every 1 ms within 200 s",
     [("E204", "a poll makes at most 100000 calls, not 200001 (every 1 ms within 200000 ms)")]),
    ("until position == 1 every 1 ms within 1 s until position == 2 every 1 ms within 1 s",
     [("E203", "`until` is given twice in `status`")]),
    ("until position == 1", [("E001", "expected `every`, found `}`")]),  # the interval and limit are said
    ("until out[0] == 1 every 1 ms within 1 s", [("E103", "`out` is not in scope in an interface")]),
])
def test_what_the_checker_refuses(tmp_path: Path, option: str, expected: list[tuple[str, str]]) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text(MOVER.replace("until not moving and position == goal every 10 ms within 30 ms", option),
                      encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == expected


def test_json_with_until_but_no_interval_is_refused(tmp_path: Path) -> None:
    _, built = through_json(MOVER, tmp_path, "mover")
    document = json.loads(built)
    call = next(i for i in document["interfaces"] if i["name"] == "move_to")["primitiveCalls"][1]
    del call["every"]
    (tmp_path / "cut.json").write_text(json.dumps(document), encoding="utf-8")
    compilation = compile_path(str(tmp_path / "cut.json"))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E008", "a call with `until` gives `every` and `within` (ms)")]
