"""An output says when its data was read (`OutputMessage.read_ns`, what ROS headers and
recordings stamp): the moment the reply behind its state was stored, not the moment it was
delivered; before any reply, its delivery. Alike in the runtime and a generated driver."""

from __future__ import annotations

import time
from typing import Any

import pytest

from tests.engine.test_one_engine import ScriptedPort, implementation_of

LEVEL = """\
robot level { author "tests" }
state level: int = 0
connection link: serial { baud 9600 }
primitive read_level() on link pack "B" (1) unpack "B" { level = out[0] }
primitive beep() on link pack "B" (2)
interface poll() triggers reading { read_level() delay 40 ms }
interface chirp() triggers reading { beep() }
output reading: Range { distance = float(level) }
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, LEVEL, tmp_path_factory.mktemp("read_times"), "level")


def test_an_output_is_stamped_when_its_reply_was_read(implementation: Any) -> None:
    """The reply is read, then 40 ms pass before the output is delivered: its read_ns is before
    them. A later output from the same state, with no reply read since, keeps that time."""
    delivered: list[Any] = []
    with implementation.connect(ScriptedPort(b"\x07"), threads=False) as robot:
        robot.on_output(delivered.append)
        before = time.time_ns()
        robot.call_interface("poll")
        after = time.time_ns()
        robot.call_interface("chirp")
    assert delivered == [{"name": "reading", "contents": {"distance": 7.0}}] * 2
    read = delivered[0].read_ns
    assert before <= read <= after - 40_000_000  # a delay is a floor: a busy machine only adds
    assert delivered[1].read_ns == read


def test_an_output_before_any_reply_is_stamped_when_it_is_delivered(implementation: Any) -> None:
    delivered: list[Any] = []
    with implementation.connect(ScriptedPort(), threads=False) as robot:
        robot.on_output(delivered.append)
        before = time.time_ns()
        robot.call_interface("chirp")
        after = time.time_ns()
    assert delivered == [{"name": "reading", "contents": {"distance": 0.0}}]
    assert before <= delivered[0].read_ns <= after
