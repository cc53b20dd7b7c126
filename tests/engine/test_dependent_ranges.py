"""A parameter's range that reads the parameters before it (`channel: int in 0..count - 1`,
issue 23, construct 8): the checker allows sums of constants and earlier int parameters with
ranges (E214 otherwise) and keeps the widest range they give; the runtime and a generated
driver check the value at each call with the same `RdisValueError` as a constant range, and
nothing is written; JSON carries the bounds both ways."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc.diagnostics import Diagnostics
from rdisc.json_import.document import read
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.conftest import run_rdisc
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

# A mux of up to 8 channels, a buffer read from an offset, a window around a centre and an
# interface that passes its own dependent range on.
MUX = """\
robot mux { author "tests" }
const SIZE = 16
connection link: serial { baud 9600 }
frame boxed(count: int in 1..8, channel: int in 0..count - 1) { header "\\xAA"  field count "B" = count  field channel "B" = channel  payload }
primitive select(count: int in 1..8, channel: int in 0..count - 1) on link pack "BB" (count, channel)
primitive read(offset: int in 0..15, length: int in 1..SIZE - offset) on link pack "BB" (offset, length)
primitive window(limit: int in 0..100, gains: int[2] in -limit..limit) on link pack "Bbb" (limit, gains[0], gains[1])
primitive boxed_select(count: int in 1..8, channel: int in 0..7) on link frame boxed(count, channel) pack "B" (1)
interface pick(count: int in 1..8, channel: int in count - 8..count - 1 + 0) { select(count, channel) }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_value_within_the_range_its_earlier_parameters_give_is_written(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"")
    with implementation_of(kind, MUX, tmp_path, "mux").connect(port, threads=False) as robot:
        robot.call_primitive("select", 4, 3)
        robot.call_primitive("select", 1, 0)
        robot.call_primitive("read", 15, 1)
        robot.call_primitive("read", 0, 16)
        robot.call_primitive("window", 5, (-5, 5))
        robot.call_primitive("boxed_select", 2, 1)
        robot.call_interface("pick", 8, 0)
        assert bytes(port.written).hex(" ") == "04 03 01 00 0f 01 00 10 05 fb 05 aa 02 01 01 08 00"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
@pytest.mark.parametrize(("name", "args", "message"), [
    ("select", (4, 4), "select: parameter channel is 4, outside 0..3"),
    ("select", (1, 1), "select: parameter channel is 1, outside 0..0"),
    ("select", (4, -1), "select: parameter channel is -1, outside 0..3"),
    ("read", (15, 2), "read: parameter length is 2, outside 1..1"),
    ("window", (5, (0, 6)), "window: parameter gains[1] is 6, outside -5..5"),
    ("boxed_select", (2, 2), "boxed_select: frame boxed: parameter channel is 2, outside 0..1"),
])
def test_a_value_outside_it_is_refused_and_nothing_is_written(kind: str, name: str, args: tuple[object, ...],
                                                              message: str, tmp_path: Path) -> None:
    port = ScriptedPort(b"")
    with implementation_of(kind, MUX, tmp_path, "mux").connect(port, threads=False) as robot:
        with pytest.raises(Exception) as raised:
            robot.call_primitive(name, *args)
        assert (type(raised.value).__name__, str(raised.value)) == ("RdisValueError", message)
        with pytest.raises(Exception) as raised:
            robot.call_interface("pick", 2, 2)
        assert (type(raised.value).__name__, str(raised.value)) == ("RdisValueError",
                                                                    "pick: parameter channel is 2, outside -6..1")
        assert bytes(port.written) == b""


def test_json_carries_the_bounds_both_ways_and_the_printer_writes_them(tmp_path: Path) -> None:
    _, built = through_json(MUX, tmp_path, "mux")  # the JSON read back gives the same JSON
    ranges = {p["name"]: p["parameterRanges"] for p in json.loads(built)["primitives"]}
    assert ranges["select"] == [[1, 8], [0, "<count - 1>"]]
    assert ranges["read"] == [[0, 15], [1, "<16 - offset>"]]
    assert ranges["window"] == [[0, 100], ["<-limit>", "<limit>"]]
    imported = read("mux.json", built, Diagnostics())  # `rdisc import`
    assert imported is not None
    printed = print_module(imported)
    assert "primitive select(count: int in 1..8, channel: int in 0..count - 1)\n" in printed
    assert "primitive read(offset: int in 0..15, length: int in 1..16 - offset)" in printed
    assert "primitive window(limit: int in 0..100, gains: int[2] in -limit..limit)" in printed
    module = parse("mux.rdis", MUX, Diagnostics())
    assert parse("mux.rdis", print_module(module), Diagnostics()) == module


def test_the_widest_range_is_what_the_checks_use(tmp_path: Path) -> None:
    """A constant argument is checked against the widest range (E403 outside it); the model
    keeps both the bounds as written and the widest range."""
    compilation, _ = through_json(MUX, tmp_path, "mux")
    assert compilation.model is not None
    select = compilation.model.primitives["select"].params[1]
    assert (select.low, select.high, select.range_text()) == (0, 7, "0..7")
    source = tmp_path / "bad.rdis"
    source.write_text(MUX + "interface far() { select(8, 8) }\ninterface near() { select(2, 7) }\n",
                      encoding="utf-8")
    result = run_rdisc("check", str(source))
    assert result.returncode == 1
    assert "error[E403]: 8 is outside the range of parameter `channel`" in result.stderr
    assert result.stderr.count("error[") == 1  # `select(2, 7)` is refused when it runs, not here


def test_the_driver_and_dump_show_the_bounds_as_written(tmp_path: Path) -> None:
    driver = implementation_of("driver", MUX, tmp_path, "mux")
    method = next(getattr(driver, name) for name in dir(driver)
                  if isinstance(getattr(driver, name), type) and hasattr(getattr(driver, name), "select"))
    assert "    count: 1..8\n            channel: 0..count - 1\n" in method.select.__doc__
    result = run_rdisc("dump", str(tmp_path / "mux.rdis"))
    assert result.returncode == 0
    assert "primitive read(offset: int in 0..15, length: int in 1..16 - offset) on link\n" in result.stdout
