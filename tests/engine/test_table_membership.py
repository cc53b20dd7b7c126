"""`key in TABLE` and `TABLE.get(key, default)` (issue 23, construct 7): a device's status code
named, or "unknown" for one the table does not list, in the runtime and a generated driver
alike; folded by the checker, refused where no table or a key of another type is given;
through canonical JSON and the printer unchanged."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.json_import.document import read
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

HEALTH = """\
robot health { author "tests" }
const HEALTH = { 0: "ok", 1: "hot", 2: "overload" }
const SCALE = { "fast": 2.5 }
const KNOWN = 1 in HEALTH
const NAMED = HEALTH.get(7, "unknown")
state status: string
state known: bool
state scale: float
connection link: serial { baud 9600 }
primitive read(mode: string) on link pack "B" (0x01) unpack "B" {
    known = out[0] in HEALTH
    status = HEALTH.get(out[0], "unknown")
    scale = SCALE.get(mode, 1)
}
primitive named_only() on link pack "B" (0x02) unpack "B" expect out[0] in HEALTH { status = HEALTH[out[0]] }
interface check() { read("fast") when KNOWN and NAMED == "unknown" }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_code_is_named_or_unknown(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"\x01\x07\x02\x09")
    with implementation_of(kind, HEALTH, tmp_path, "health").connect(port, threads=False) as robot:
        robot.call_interface("check")
        assert dict(robot.state) == {"status": "hot", "known": True, "scale": 2.5}
        robot.call_primitive("read", "slow")
        assert dict(robot.state) == {"status": "unknown", "known": False, "scale": 1.0}
        robot.call_primitive("named_only")
        assert robot.state["status"] == "overload"
        with pytest.raises(Exception) as caught:  # a code the table lacks fails the `expect`
            robot.call_primitive("named_only")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "named_only: reply (9,) does not meet its `expect`")
        assert bytes(port.written) == b"\x01\x01\x02\x02"


def test_constants_fold_and_what_is_refused(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
const HEALTH = { 0: "ok", 1: "hot" }
const IDS = [1, 2]
const A = "x" in HEALTH
const B = 1 in IDS
const C = 1 in [1, 2]
const D = HEALTH.get(1)
const E = HEALTH.get(1, 2)
const F = HEALTH.keys()
const G = IDS.get(1, 2)
const H = HEALTH.get("a", "b")
const I = 1 in NOPE
const J = HEALTH.get(5, "none") + str(0 in HEALTH)
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E401", "table `HEALTH` is keyed by int, but this is a string"),
        ("E404", "`in` needs a lookup table, and `IDS` is not one"),
        ("E404", "`in` needs a lookup table on its right"),
        ("E201", "`get` takes 2 arguments (a key and a default), but 1 given"),
        ("E401", "the default of `HEALTH.get` is a string, as the table's values are, not an int"),
        ("E106", "unknown method `keys`"),
        ("E404", "`.get` needs a lookup table, and `IDS` is not one"),
        ("E401", "table `HEALTH` is keyed by int, but this is a string"),
        ("E404", "`in` needs a lookup table, and `NOPE` is not one"),
    ]
    source.write_text("""\
robot good { author "tests" }
const HEALTH = { 0: "ok", 1: "hot" }
const J = HEALTH.get(5, "none") + str(0 in HEALTH) + HEALTH.get(1, "none")
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None and compilation.model.constants["J"] == "noneTruehot"


def test_it_goes_through_json_and_the_printer(tmp_path: Path) -> None:
    compilation, built = through_json(HEALTH, tmp_path, "health")
    assert not compilation.diagnostics.items
    assert '"known = __out__[0] in HEALTH"' in built and '"status = HEALTH.get(__out__[0], \\"unknown\\")"' in built
    assert '"expect": "<__out__[0] in HEALTH>"' in built
    module = parse("t.rdis", HEALTH, Diagnostics())
    printed = print_module(module)
    assert "known = out[0] in HEALTH" in printed and 'const NAMED = HEALTH.get(7, "unknown")' in printed
    assert module == parse("t.rdis", printed, Diagnostics())
    imported = read("health.json", built, Diagnostics())  # `rdisc import`: the JSON back as a description
    assert imported is not None and 'status = HEALTH.get(out[0], "unknown")' in print_module(imported)
    assert print_module(parse("t.rdis", "const A = (1 in T) == (2 in T)\n", Diagnostics())) == \
        "const A = (1 in T) == (2 in T)\n"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_request_value_looked_up_with_a_default_reads_back_from_json(kind: str, tmp_path: Path) -> None:
    text = """\
robot gears { author "tests" }
const SPEED = { 1: 10, 2: 20 }
connection link: serial { baud 9600 }
primitive go(gear: int) on link pack "B?" (SPEED.get(gear, 0), gear in SPEED)
"""
    compilation, built = through_json(text, tmp_path, "gears")  # a whole JSON value that is a `.get` call
    assert not compilation.diagnostics.items and '"<SPEED.get(gear, 0)>"' in built and '"<gear in SPEED>"' in built
    port = ScriptedPort()
    with implementation_of(kind, text, tmp_path, "gears").connect(port, threads=False) as robot:
        robot.call_primitive("go", 2)
        robot.call_primitive("go", 3)
        assert bytes(port.written) == b"\x14\x01\x00\x00"
