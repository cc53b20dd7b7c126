"""Conditional post-actions (`x = value when COND`): the state variable, or one element of an
array, is stored only when COND holds over the reply, and otherwise kept as it was. In the
runtime and a generated driver alike, over a scripted port; through JSON, the printer and the
checker."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

WHEN = """\
robot gauge { author "tests" }
connection link: serial { baud 9600 }
state level: int = 0
state peak: int = 0
state seen: int[4]
/// A reading: a status byte (1: valid) and a level, kept per slot when not zero.
primitive read(slot: int in 0..3) on link pack "BB" (0x52, slot) unpack "<BH" {
    level = out[1] when out[0] == 1
    peak = out[1] when out[1] > peak
    seen[slot] = out[1] when out[0] != 0
}
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_post_action_is_made_only_when_its_condition_holds(kind: str, tmp_path: Path) -> None:
    replies = bytes.fromhex("01 2c 01"  # valid, 300
                            "00 c8 00"  # invalid, 200: level and seen[1] kept
                            "02 f4 01")  # status 2, 500: level kept, seen[2] and peak stored
    port = ScriptedPort(replies)
    with implementation_of(kind, WHEN, tmp_path, "gauge").connect(port, threads=False) as robot:
        robot.call_primitive("read", 0)
        assert (robot.state["level"], robot.state["peak"], list(robot.state["seen"])) == (300, 300, [300, 0, 0, 0])
        robot.call_primitive("read", 1)
        assert (robot.state["level"], robot.state["peak"], list(robot.state["seen"])) == (300, 300, [300, 0, 0, 0])
        robot.call_primitive("read", 2)
        assert (robot.state["level"], robot.state["peak"], list(robot.state["seen"])) == (300, 500, [300, 0, 500, 0])
    assert bytes(port.written) == bytes.fromhex("52 00 52 01 52 02")


def test_when_goes_through_json_and_the_printer(tmp_path: Path) -> None:
    compilation, built = through_json(WHEN, tmp_path, "gauge")
    assert not compilation.diagnostics.items
    (read,) = json.loads(built)["primitives"]
    assert read["postActions"] == ["level = __out__[1] when __out__[0] == 1",
                                   "peak = __out__[1] when __out__[1] > peak",
                                   "seen[slot] = __out__[1] when __out__[0] != 0"]
    printed = print_module(parse("g.rdis", WHEN, Diagnostics()))
    assert "    level = out[1] when out[0] == 1" in printed.splitlines()
    assert print_module(parse("g.rdis", printed, Diagnostics())) == printed


def test_what_the_checker_refuses_of_when(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
connection link: serial { baud 9600 }
state level: int = 0
primitive read() on link pack "B" (1) unpack "B" { level = out[0] when out[0] }
primitive other() on link pack "B" (1) unpack "B" { level = out[0] when missing }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E401", "`when` takes a bool, but this is an int"),
        ("E103", "unknown name `missing` in a post-action"),
    ]
