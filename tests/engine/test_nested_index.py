"""An element of a reply's value that is an array (`out[1][i]`, a repeated group's) and of a
table's array entry (`TABLE[key][i]`), in the runtime and a generated driver alike; refused by
the checker where the value is no array or a constant index is outside a group of fixed size;
through canonical JSON and the printer unchanged (issue 23, construct 6)."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.json_import.document import read
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

GROUPS = """\
robot groups { author "tests" }
state first: int
state picked: int
state last: int
state count: int
state gain: float
const GAINS = { 1: [0.5, 1.5], 2: [2.0, 2.5] }
connection link: serial { baud 9600 }
frame sized { header "\\xaa" length "B" = payload  payload }
primitive read3(which: int in 0..2) on link pack "B" (0x01) unpack "<B3(Hb)" {
    first = out[1][0]
    picked = out[2][which]
    gain = GAINS[out[0]][1]
}
primitive readn() on link frame sized pack "B" (0x02) unpack "<#B#(H)" {
    count = len(out[0])
    last = out[0][len(out[0]) - 1]
}
"""

REPLIES = (b"\x02" + b"\x01\x00\xff\x02\x00\xfe\x03\x00\x05"  # read3: a mode, then three (H, b)
           + b"\xaa\x05\x02\x10\x00\x20\x00")  # readn: two H counted by a B


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_element_of_a_group_is_read(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(REPLIES + b"\xaa\x01\x00")
    with implementation_of(kind, GROUPS, tmp_path, "groups").connect(port, threads=False) as robot:
        robot.call_primitive("read3", 2)
        robot.call_primitive("readn")
        assert bytes(port.written) == b"\x01\xaa\x01\x02"  # the second through its frame
        assert dict(robot.state) == {"first": 1, "picked": 5, "last": 0x20, "count": 2, "gain": 2.5}
        with pytest.raises(ValueError) as caught:  # a group of no rounds has no last element
            robot.call_primitive("readn")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisValueError", "readn: index -1 is outside out[0], which has 0 values")
        assert robot.state["count"] == 2


def test_what_is_not_an_array_or_outside_it_is_refused(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
const IDS = [1, 2, 3]
state first: int
state other: int
state flag: bool
connection link: serial { baud 9600 }
primitive read3() on link pack "B" (0x01) unpack "<B3(Hb)" {
    first = out[0][1]
    other = out[1][3]
    flag = out[2][1.5] == 1
}
interface i() { read3() when IDS[0][1] == 2 }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E404", "`out[0]` is an int, not an array, and cannot be indexed"),
        ("E403", "index 3 is outside `out[1]`, which has 3 values"),
        ("E404", "an index is an int, not a float"),
        ("E404", "`IDS[0]` is an int, not an array, and cannot be indexed"),
    ]
    first = compilation.diagnostics.items[0]
    assert source.read_text()[first.span.start:first.span.end] == "out[0][1]"


def test_it_goes_through_json_and_the_printer(tmp_path: Path) -> None:
    compilation, built = through_json(GROUPS, tmp_path, "groups")
    assert not compilation.diagnostics.items
    assert '"first = __out__[1][0]"' in built and '"gain = GAINS[__out__[0]][1]"' in built
    assert '"last = __out__[0][len(__out__[0]) - 1]"' in built
    module = parse("t.rdis", GROUPS, Diagnostics())
    printed = print_module(module)
    assert "picked = out[2][which]" in printed and "gain = GAINS[out[0]][1]" in printed
    assert module == parse("t.rdis", printed, Diagnostics())
    imported = read("groups.json", built, Diagnostics())  # `rdisc import`: the JSON back as a description
    assert imported is not None and "last = out[0][len(out[0]) - 1]" in print_module(imported)
