"""The shapes of a reply: the lowering decides, once for each primitive, which way its reply is
read (`rdisc.engine.Reply`, a closed union), and the engine reads it by one `match` over the
shape. One description needs every shape; each primitive of it is lowered to its shape, which the
runtime and the generated driver (the engine carried) both hold, and each reads its exact bytes
into the same values."""

from __future__ import annotations

import typing
from pathlib import Path
from typing import Any

import pytest

from rdisc import engine
from rdisc import lower as lowering
from rdisc.compile import compile_path
from tests.engine.test_one_engine import ScriptedPort, implementation_of

SHAPES = r"""robot shapes { author "tests" }
connection port: serial { baud 115200 }
frame f { header "\xFF"  length "B" = payload  payload }
frame ack { request { payload }  reply { header "\x06" } }
frame status(id: int in 0..9) { request { payload }  reply { header "\xFE"  field id "B" = id  payload } }
state a: int
state b: int
state n: int
state c: int[2]
primitive write(x: int in 0..255) on port pack "BB" (0x01, x)
primitive line() on port format "L\n" () regex "v([0-9]+)" { a = int(out[0]) }
primitive fixed() on port pack "B" (0x02) unpack "<h" { a = out[0] }
primitive framed() on port frame f() pack "B" (0x03) unpack "<H" { a = out[0] }
primitive acknowledged() on port frame ack pack "B" (0x04)
primitive tagged() on port frame f() pack "B" (0x05) reply tag "B" {
    1: unpack "B" { a = out[0] }
    2: unpack "<H" { b = out[0] + tag }
}
primitive stream() on port format "" () reply tag "B" { 0x90..0x9F: unpack "B" { a = out[0] + (tag & 0x0F) } }
primitive parts() on port frame f() pack "B" (0x06) reply each tag "B" length "B" {
    1: unpack "B" { a = out[0] }
    2: unpack "<H" { b = out[0] }
}
primitive records() on port frame f() pack "B" (0x07) reply each until "\x7F" unpack "B" { n = n * 10 + out[0] + index }
primitive keyed(k: int in 0..1) on port pack "BB" (0x08, k) reply k {
    0: unpack "B" { a = out[0] }
    1: unpack "<H" { b = out[0] }
}
primitive several() on port pack "B" (0x09) replies 2 unpack "B" { c = out[0] }
primitive listed() on port frame f() pack "B" (0x0A) replies {
    frame status(1) unpack "B" { a = out[0] }
    frame status(2) unpack "<H" { b = out[0] }
}
"""

# Each primitive: its shape, its call, the bytes the device answers, the bytes written and the
# state variables after it.
EXCHANGES: list[tuple[str, str, tuple[Any, ...], str, str, dict[str, Any]]] = [
    ("write", "NoReply", (7,), "", "01 07", {}),
    ("line", "LineReply", (), "76 34 32 0d 0a", "4c 0a", {"a": 42}),
    ("fixed", "FixedReply", (), "fe ff", "02", {"a": -2}),
    ("framed", "FramedReply", (), "ff 02 34 12", "ff 01 03", {"a": 0x1234}),
    ("acknowledged", "FramedReply", (), "06", "04", {}),
    ("tagged", "TaggedReply", (), "ff 03 02 cd ab", "ff 01 05", {"b": 0xABCD + 2}),
    ("stream", "TaggedStream", (), "93 05", "", {"a": 5 + 3}),
    ("parts", "SubPayloads", (), "ff 07 01 01 07 02 02 34 12", "ff 01 06", {"a": 7, "b": 0x1234}),
    ("records", "Records", (), "ff 04 03 7f 04 7f", "ff 01 07", {"n": (0 * 10 + 3 + 0) * 10 + 4 + 1}),
    ("keyed", "KeyedReply", (1,), "78 56", "08 01", {"b": 0x5678}),
    ("several", "SeveralReplies", (), "0b 0c", "09", {"c": (11, 12)}),
    ("listed", "ListedReplies", (), "fe 01 21 fe 02 22 11", "ff 01 0a", {"a": 0x21, "b": 0x1122}),
]


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("shapes")


def test_the_lowering_gives_each_primitive_the_shape_it_needs_and_every_shape_is_needed(folder: Path) -> None:
    source = folder / "shapes.rdis"
    source.write_text(SHAPES, encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None and not compilation.diagnostics.has_errors()
    plans = lowering.lower(compilation.model).device.primitives
    assert {name: type(plans[name].reply).__name__ for name, *_ in EXCHANGES} == {
        name: shape for name, shape, *_ in EXCHANGES}
    every = {shape.__name__ for shape in typing.get_args(engine.Reply)}
    assert every == {shape for _, shape, *_ in EXCHANGES}  # a shape no description needs would be dead
    # The shapes within shapes: `replies N` reads each reply as one; a listed reply is read through
    # its own frame; a tag's entries and a key's are plans, their replies read as their own.
    several, listed, keyed = plans["several"].reply, plans["listed"].reply, plans["keyed"].reply
    assert isinstance(several, lowering.SeveralReplies) and isinstance(several.each, lowering.FixedReply)
    assert (several.count, several.frames) == (2, ())
    assert isinstance(listed, lowering.ListedReplies)
    assert [type(answer.reply).__name__ for answer in listed.answers] == ["FramedReply"] * 2
    assert isinstance(keyed, lowering.KeyedReply) and keyed.key == 0
    assert [type(entry.plan.reply).__name__ for entry in keyed.table] == ["FixedReply"] * 2
    acknowledged = plans["acknowledged"].reply
    assert isinstance(acknowledged, lowering.FramedReply) and acknowledged.decoder is None  # only the frame is read


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_each_shape_reads_its_bytes_into_the_same_values(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, SHAPES, tmp_path, "shapes")
    said = bytes.fromhex(" ".join(answer for *_, answer, _, _ in EXCHANGES))
    port = ScriptedPort(said)
    with implementation.connect(port, threads=False) as robot:
        for name, shape, args, _, written, changed in EXCHANGES:
            assert type(robot.device.primitives[name].reply).__name__ == shape  # the engine holds the shape
            before = dict(robot.state)
            port.written.clear()
            robot.call_primitive(name, *args)
            assert (name, bytes(port.written).hex(" ")) == (name, written)
            assert {key: value for key, value in robot.state.items() if before[key] != value} == changed, name
        assert (port.script, bytes(port.given)) == (b"", said)  # every byte read, in order


def test_a_reply_table_chosen_by_a_key_runs_the_entry_of_its_value(tmp_path: Path) -> None:
    port = ScriptedPort(bytes.fromhex("09"))
    with implementation_of("runtime", SHAPES, tmp_path, "shapes").connect(port, threads=False) as robot:
        robot.call_primitive("keyed", 0)
        assert (bytes(port.written).hex(" "), robot.state["a"], robot.state["b"]) == ("08 00", 9, 0)
