"""Interfaces that call interfaces: a call names a primitive of that name, or else an
interface; the calls run in order, through the callee's own calls and delays, alike in
the runtime and a generated driver; the link budget counts the callee's bytes; calls
that lead back to their interface are refused (E210)."""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path
from rdisc.semantics.budget import budget
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

SERVOS = """\
robot servos { author "tests" }
state moves: int = 0
connection link: serial { baud 9600 }
primitive led(on: int) on link pack "BB" (1, on)
primitive goto(id: int, pos: int in 0..1023) on link pack "<BBH" (2, id, pos) { moves = moves + 1 }
interface home(id: int) { goto(id, 512) delay 30 ms  led(1) }
interface home_all() { home(1)  home(2) delay 20 ms  led(0) }
interface wave(pos: int) { home_all()  goto(3, pos) }
interface tick() periodic { home(4) }
interface led(on: int) { goto(9, on) }
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, SERVOS, tmp_path_factory.mktemp("interface_calls"), "servos")


def test_calls_run_through_the_interfaces_they_call(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        started = time.monotonic()
        robot.call_interface("wave", 7)
        took = time.monotonic() - started
        assert bytes(port.written).hex(" ") == (
            "02 01 00 02 01 01"  # home(1): goto(1, 512), led(1)
            " 02 02 00 02 01 01"  # home(2)
            " 01 00"  # led(0)
            " 02 03 07 00")  # goto(3, 7)
        assert robot.state["moves"] == 3
        assert took >= 0.08  # 30 ms in each home, 20 ms after the second (a floor: a busy machine only adds)


def test_a_name_of_both_kinds_is_the_primitive(implementation: Any) -> None:
    """`led` is a primitive and an interface: in a body it names the primitive, as before
    interfaces could be called (`home`'s `led(1)` writes `01 01`, not a goto)."""
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.call_interface("tick")
        assert bytes(port.written).hex(" ") == "02 04 00 02 01 01"
        robot.call_interface("led", 5)
        assert bytes(port.written).hex(" ").endswith("01 01 02 09 05 00")


def test_an_argument_out_of_a_callees_range_is_refused_before_anything_is_sent(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(ValueError, match=r"goto: parameter pos is 2000, outside 0\.\.1023"):
            robot.call_interface("wave", 2000)
        assert bytes(port.written).hex(" ") == "02 01 00 02 01 01 02 02 00 02 01 01 01 00"  # home_all ran first


def test_the_budget_and_the_json_carry_the_calls(tmp_path: Path) -> None:
    compilation, built = through_json(SERVOS, tmp_path, "servos")
    assert not compilation.diagnostics.items
    (link,) = budget(compilation.model, compilation.diagnostics)
    (tick,) = link.periodic
    assert (tick.interface, tick.bytes, tick.delay_ms) == ("tick", 6, 30.0)
    wave = next(i for i in json.loads(built)["interfaces"] if i["name"] == "wave")
    assert [c["name"] for c in wave["primitiveCalls"]] == ["home_all", "goto"]


CYCLES = """\
robot cycles { author "tests" }
connection link: serial { baud 9600 }
primitive led(on: int) on link pack "BB" (1, on)
interface a() { b()  led(1) }
interface b() { c() }
interface c() { a() }
interface d() { d() }
interface e() { a()  b() }
"""


def test_calls_that_lead_back_are_refused_once_each(tmp_path: Path) -> None:
    source = tmp_path / "cycles.rdis"
    source.write_text(CYCLES, encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E210", "interface `c` calls `a`, which leads back to it: `a` -> `b` -> `c` -> `a`"),
        ("E210", "interface `d` calls `d`, which leads back to it: `d` -> `d`"),
    ]


BUMPERS = """\
robot bumpers { author "tests" }
state bumps: int = 0
connection link: serial { baud 9600 }
primitive bumpers() on link pack "B" (142) unpack "B" { bumps = out[0] }
interface poll() periodic triggers left_bump, right_bump {
    bumpers()
}
output left_bump: Range { distance = 0.0 if bumps & 2 != 0 else 1.0 }
output right_bump: Range { distance = 0.0 if bumps & 1 != 0 else 1.0 }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_interface_triggers_several_outputs_in_order(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, BUMPERS, tmp_path, "bumpers")
    delivered: list[dict[str, Any]] = []
    with implementation.connect(ScriptedPort(b"\x02"), threads=False, on_output=delivered.append) as robot:
        robot.call_interface("poll")
    assert delivered == [{"name": "left_bump", "contents": {"distance": 0.0}},
                         {"name": "right_bump", "contents": {"distance": 1.0}}]


def test_several_outputs_go_through_json_and_back(tmp_path: Path) -> None:
    _, built = through_json(BUMPERS, tmp_path, "bumpers")
    (poll,) = json.loads(built)["interfaces"]
    assert poll["triggers"] == ["left_bump", "right_bump"]  # one output is a name, as in the thesis


def test_an_output_triggered_twice_is_one_error(tmp_path: Path) -> None:
    source = tmp_path / "twice.rdis"
    source.write_text(BUMPERS.replace("triggers left_bump, right_bump", "triggers left_bump, right_bump, left_bump"),
                      encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E203", "`left_bump` is triggered twice")]
