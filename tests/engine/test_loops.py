"""Loops in interface bodies: `for i in 0..5 { ... }` over a constant range (both ends
included) and `for id in IDS { ... }` over a constant array. The checker writes each loop
out as its calls, the variable a constant in each round, so the runtime and a generated
driver, the link budget and canonical JSON see plain calls; the printer keeps the loop."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from conftest import check_text

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.semantics.budget import budget, exchange
from rdisc.syntax import ast
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

ARM = """\
robot arm { author "tests" }
const IDS = [3, 5, 7]
state position: int[3]
state limp: bool = False
connection bus: serial { baud 57600 }
primitive torque(id: int, on: bool) on bus pack "<BB?" (0x18, id, on)
primitive read_position(id: int) on bus pack "<BB" (0x24, id) unpack "<H" { position[(id - 3) // 2] = out[0] }
primitive relax() on bus pack "B" (0xFF) { limp = True }
primitive goal(id: int, pos: int in 0..1023) on bus pack "<BBH" (0x1E, id, pos)
interface torque_all(on: bool) {
    for i in 0..2 { torque(IDS[i], on) delay 2 ms }
}
interface read_all() periodic {
    for id in IDS { read_position(id) }
}
interface wave(p: int[3]) {
    for i in 0..2 {
        for step in [0, 100] { goal(IDS[i], p[i] + step) priority 2 - i when not limp or step == 0 }
    }
    torque_all(True) priority 3
}
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, ARM, tmp_path_factory.mktemp("loops"), "arm")


def test_a_loop_makes_its_calls_in_order(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.interfaces.torque_all(True)
        assert bytes(port.written).hex(" ") == "18 03 01 18 05 01 18 07 01"


def test_a_loop_over_a_constant_array_reads_each_value(implementation: Any) -> None:
    port = ScriptedPort(bytes.fromhex("0100 0200 0300"))
    with implementation.connect(port, threads=False) as robot:
        robot.tick()  # read_all: the periodic interface
        assert bytes(port.written).hex(" ") == "24 03 24 05 24 07"
        assert robot.state.position == (1, 2, 3)


def test_nested_loops_with_priorities_conditions_and_parameters(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.interfaces.wave([10, 20, 30])
        assert bytes(port.written).hex(" ") == (
            "1e 07 1e 00 1e 07 82 00"  # i = 2 first (priority 0): 30, then 30 + 100
            " 1e 05 14 00 1e 05 78 00"  # i = 1
            " 1e 03 0a 00 1e 03 6e 00"  # i = 0
            " 18 03 01 18 05 01 18 07 01")  # torque_all(True), a call of an interface
        port.written.clear()
        robot.primitives.relax()  # limp: `when not limp or step == 0` makes only the first step of each
        port.written.clear()
        robot.interfaces.wave([1, 2, 3])
        assert bytes(port.written).hex(" ") == "1e 07 03 00 1e 05 02 00 1e 03 01 00 18 03 01 18 05 01 18 07 01"


def test_a_rounds_value_is_refused_when_it_runs_as_a_written_one_would_be(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(ValueError, match=r"^goal: parameter pos is 1030, outside 0\.\.1023$"):
            robot.interfaces.wave([0, 0, 930])
        assert bytes(port.written).hex(" ") == "1e 07 a2 03"  # 930 went; 930 + 100 is refused


def test_the_budget_counts_every_round(tmp_path: Path) -> None:
    compilation, _ = through_json(ARM, tmp_path, "arm")
    assert compilation.model is not None and not compilation.diagnostics.items
    (bus,) = budget(compilation.model, compilation.diagnostics)
    (read_all,) = bus.periodic
    assert (read_all.interface, read_all.bytes, read_all.delay_ms) == ("read_all", 12, 0.0)  # 3 x (2 + 2)
    torque_all = exchange(compilation.model, compilation.model.interfaces["torque_all"], "bus")
    assert (torque_all.bytes, torque_all.delay_ms) == (9, 6.0)
    wave = exchange(compilation.model, compilation.model.interfaces["wave"], "bus")
    assert (wave.bytes, wave.delay_ms) == (6 * 4 + 9, 6.0)  # a call not made by `when` counts as made


def test_json_carries_the_calls_a_loop_makes(tmp_path: Path) -> None:
    """Written out: JSON has no loop, and reads back as the same calls."""
    _, built = through_json(ARM, tmp_path, "arm")
    interfaces = {i["name"]: i["primitiveCalls"] for i in json.loads(built)["interfaces"]}
    assert interfaces["torque_all"] == [
        {"name": "torque", "arguments": [f"<{id_}>", "<on>"], "delay": 2, "priority": 0} for id_ in (3, 5, 7)
    ]
    assert interfaces["read_all"] == [
        {"name": "read_position", "arguments": [f"<{id_}>"], "delay": 0, "priority": 0} for id_ in (3, 5, 7)
    ]
    assert interfaces["wave"][:2] == [
        {"name": "goal", "arguments": ["<3>", "<p[0] + 0>"], "delay": 0, "priority": 2, "when": "<not limp or 0 == 0>"},
        {"name": "goal", "arguments": ["<3>", "<p[0] + 100>"], "delay": 0, "priority": 2,
         "when": "<not limp or 100 == 0>"},
    ]


def test_the_printer_keeps_the_loops() -> None:
    module = parse("arm.rdis", ARM, Diagnostics())
    printed = print_module(module)
    assert "interface wave(p: int[3]) {\n    for i in 0..2 {\n        for step in [0, 100] {\n" \
        "            goal(IDS[i], p[i] + step) priority 2 - i when not limp or step == 0\n        }\n    }\n" \
        "    torque_all(True) priority 3\n}\n" in printed
    again = parse("again.rdis", printed, Diagnostics())
    assert again.decls == module.decls
    (loop,) = next(d for d in again.decls if isinstance(d, ast.InterfaceDecl) and d.name.text == "read_all").body
    assert isinstance(loop, ast.ForStmt) and loop.high is None and [c.call.target.text for c in loop.body] == [
        "read_position"]


HEAD = """\
robot a { author "tests" }
const IDS = [1, 2, 3]
state position: int[3]
connection link: serial { baud 9600 }
primitive torque(id: int, on: bool) on link pack "<BB?" (0x18, id, on)
primitive read(id: int) on link pack "B" (id) unpack "<H" { position[id] = out[0] }
"""
# What the checker refuses in loops, one error each: tests/semantics/cases/loops.rdis.


def test_a_refused_loop_says_what_to_write_instead(tmp_path: Path) -> None:
    _, result = check_text(tmp_path, HEAD + "interface a(p: int[3]) { for x in p { torque(x, True) } }\n"
                           "interface b() { for position in IDS { torque(position, True) } }\n")
    assert result.stderr == """\
error[E212]: a loop goes over a constant array or a range, not an array known only when it runs
 --> PATH:7:35
  |
7 | interface a(p: int[3]) { for x in p { torque(x, True) } }
  |                                   ^
  |
  = help: loop over its indexes and read its elements: `for i in 0..2 { ... p[i] ... }`

error[E101]: loop variable `position` has the name of a state variable
 --> PATH:8:21
  |
3 | state position: int[3]
  |       -------- a state variable `position`
...
8 | interface b() { for position in IDS { torque(position, True) } }
  |                     ^^^^^^^^
  |
  = help: give the loop variable a name of its own

2 errors emitted
""".replace("PATH", str(tmp_path / "d.rdis"))


def test_calls_in_loops_meet_the_cycle_and_connection_checks(tmp_path: Path) -> None:
    source = tmp_path / "d.rdis"
    source.write_text(HEAD + """\
connection other: serial { baud 9600 }
primitive ping() on other pack "B" (1)
interface a() { for i in 0..2 { b(i) } }
interface b(k: int) { for j in 0..1 { a() } }
interface c() periodic { for i in 0..1 { torque(i, True)  ping() } }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E208", "periodic interface `c` uses two connections"),
        ("E210", "interface `b` calls `a`, which leads back to it: `a` -> `b` -> `a`"),
    ]


def test_the_calls_of_all_loops_are_bounded_too(tmp_path: Path) -> None:
    """65536 calls in all: a description from a device cannot make the checker write out
    millions of them, one interface of 4096 at a time."""
    body = "".join(f"interface i{k}() {{ for v in 0..4095 {{ torque(v % 256, True) }} }}\n" for k in range(17))
    _, result = check_text(tmp_path, HEAD + body)
    errors = [line.strip() for line in result.stderr.splitlines() if line.startswith(("error[", "  -->"))]
    assert errors == ["error[E212]: the description's interfaces unroll into more than 65536 calls",
                      f"--> {tmp_path / 'd.rdis'}:23:19"]


def test_the_budget_costs_each_interface_once(tmp_path: Path) -> None:
    """Loops of calls of interfaces of loops: 4096 ** 3 primitive calls a tick, costed from
    4096 * 3 written out (counting them one by one would not end), and reported as too much."""
    source = tmp_path / "deep.rdis"
    source.write_text(HEAD + """\
interface c() { for i in 0..4095 { torque(i % 256, True) } }
interface b() { for i in 0..4095 { c() } }
interface a() periodic { for i in 0..4095 { b() }  idle() delay 5 ms }
interface idle() { }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None
    (link,) = budget(compilation.model, compilation.diagnostics)
    (a,) = link.periodic
    assert (a.interface, a.bytes, a.delay_ms) == ("a", 3 * 4096 ** 3, 5.0)  # idle() waits though it sends nothing
    assert [d.code for d in compilation.diagnostics.items] == ["W402", "W401"]
