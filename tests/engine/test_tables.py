"""Lookup tables: `const BAUD_CODE = {9600: 1, ...}` read as `BAUD_CODE[baud]`. A key the table
lacks is refused, at check time for a constant key (E403) and at run time otherwise (an
RdisValueError, nothing written), in the runtime and a generated driver alike; tables travel
through JSON and the printer."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

TABLES = """\
robot tables { author "tests" }
/// The codes of the baud rates the device takes.
const BAUD_CODE = { 9600: 1, 19200: 2, 115200: 4 }
const NOTE = { "c": 261.63, "a": 440 }
connection link: serial { baud 9600 }
primitive set_baud(baud: int) on link pack "BB" (0x04, BAUD_CODE[baud])
primitive beep(note: string) on link pack "<Bf" (0x05, NOTE[note])
interface fast() { set_baud(115200) }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_table_gives_the_value_of_a_key_and_refuses_another(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, TABLES, tmp_path, "tables").connect(port, threads=False) as robot:
        robot.call_interface("fast")
        robot.call_primitive("set_baud", 19200)
        robot.call_primitive("beep", "a")  # 440 in a table of floats is 440.0
        assert bytes(port.written).hex(" ") == "04 04 04 02 05 00 00 dc 43"
        port.written.clear()
        with pytest.raises(ValueError) as caught:
            robot.call_primitive("set_baud", 4800)
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisValueError", "set_baud: table BAUD_CODE has no entry for 4800")
        assert bytes(port.written) == b""


def test_tables_go_through_json_and_the_printer(tmp_path: Path) -> None:
    compilation, _ = through_json(TABLES, tmp_path, "tables")
    assert not compilation.diagnostics.items
    module = parse("t.rdis", TABLES, Diagnostics())
    printed = print_module(module)
    assert "const BAUD_CODE = {\n    9600: 1,\n    19200: 2,\n    115200: 4,\n}\n" in printed
    assert print_module(parse("t.rdis", printed, Diagnostics())) == printed


def test_what_the_checker_refuses(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
const T = { 1: 2, 1: 3, "x": 4 }
const U = { 1: 2, 2: "two" }
const V = { 1: 2 }
connection link: serial { baud 9600 }
primitive p() on link pack "B" (V[5])
primitive q(s: string) on link pack "B" (V[s])
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E101", "key 1 is in table `T` twice"),
        ("E401", "the keys of table `T` are of one type"),
        ("E401", "a table's values are of one type: this is a string, the ones before are an int"),
        ("E403", "table `V` has no entry for 5"),
        ("E401", "table `V` is keyed by int, but this is a string"),
    ]


def test_a_driver_keeps_a_table_as_a_dict(tmp_path: Path) -> None:
    driver = implementation_of("driver", TABLES, tmp_path, "tables_source")
    text = Path(driver.__file__).read_text(encoding="utf-8")
    assert "_TABLE_BAUD_CODE: dict[Any, Any] = {9600: 1, 19200: 2, 115200: 4}" in text
    assert 'return [4, lookup("BAUD_CODE", _TABLE_BAUD_CODE, baud)]' in text


def test_an_empty_table_is_one_error_and_its_lookups_none(tmp_path: Path) -> None:
    source = tmp_path / "empty.rdis"
    source.write_text('robot r { author "tests" }\nconst T = {}\nconst U = { 2: T[1] }\n', encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [("E204", "table `T` is empty")]
