"""`when COND` on a call: an interface makes the call only when the condition holds, over
state and its parameters (Firmata turns reporting off only for a pin that reports), in the
runtime and a generated driver alike; the condition travels through JSON."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.compile import compile_path
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

FIRMATA = """\
robot pins { author "tests" }
state reporting: bool = False
connection link: serial { baud 57600 }
primitive report(pin: int, on: bool) on link pack "BB?" (0xD0, pin, on) { reporting = on }
primitive reset() on link pack "B" (0xFF)
interface stop(pin: int) { report(pin, False) when reporting  reset() delay 5 ms when pin > 3 }
interface start(pin: int) { report(pin, True) }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_call_is_made_only_when_its_condition_holds(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, FIRMATA, tmp_path, "pins")
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.call_interface("stop", 2)  # not reporting, pin 2: neither call
        assert bytes(port.written) == b""
        robot.call_interface("start", 2)
        robot.call_interface("stop", 5)  # reporting, pin 5: both
        assert bytes(port.written).hex(" ") == "d0 02 01 d0 05 00 ff"
        assert robot.state["reporting"] is False
        port.written.clear()
        robot.call_interface("start", 1)
        robot.call_interface("stop", 1)  # reporting, pin 1: only the first (each call its own condition)
        robot.call_interface("stop", 6)  # not reporting, pin 6: only the second
        assert bytes(port.written).hex(" ") == "d0 01 01 d0 01 00 ff"


def test_the_condition_goes_through_json_and_back(tmp_path: Path) -> None:
    compilation, built = through_json(FIRMATA, tmp_path, "pins")
    assert not compilation.diagnostics.items
    assert '"when": "<reporting>"' in built and '"when": "<pin > 3>"' in built


def test_a_condition_is_a_bool_given_once(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text(FIRMATA.replace("when pin > 3", "when pin when pin > 1"), encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E203", "`when` is given twice in `reset`"),
        ("E401", "`when` takes a bool, but this is an int"),
    ]
