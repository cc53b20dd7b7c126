"""Struct layouts are parsed once, by the checker, and stored on the Model beside their format:
each value's struct code and size, the struct module's format, the sizes a message is counted
in. The lowering hands them to the engine as they are; nothing after the checker reads a
format's text again."""

from __future__ import annotations

import functools
import re
import struct
from pathlib import Path

import rdisc
from rdisc.compile import compile_text
from rdisc.lower import FramedReply, lower
from rdisc.runtime import load
from rdisc.semantics import model as m
from tests.support.ports import ScriptedPort

DESCRIPTION = """\
robot layouts { description "struct layouts of every kind" }

state seen: int = 0
state name: string = ""

frame framed(id: int in 0..200) {
    request {
        header "\\xFF"  field id ">H" = id  length "<H" = payload + 1  payload  checksum "crc16-xmodem" ">H"
    }
    reply {
        header "\\xFF"  bits "<H" { length: 12 = payload  field id: 4 = id & 15 }  payload  checksum "xor" hex
    }
}

connection link: serial { baud 115200 }

primitive named(level: int, label: string) on link frame framed(1)
    pack ">BhH5s10pc" (1, level, 7, label, "ab", "z") unpack "<H#B2(bb)#(BH)I" { seen = out[0] }
primitive flags(low: int in 0..1, high: int in 0..127) on link frame framed(3) pack "<B{1,7}xq" (low, high, 9)
    unpack "<h3s*" { name = out[1] }
primitive sensors() on link format "" () frame framed(4) reply each tag "B" length ">H" {
    1: unpack "<H" { seen = out[0] }
}
"""


@functools.cache
def _model() -> m.Model:
    compiled = compile_text("layouts.rdis", DESCRIPTION)
    assert compiled.model is not None, [d.message for d in compiled.diagnostics.sorted()]
    return compiled.model


def _code_sizes(layout: m.StructLayout) -> list[int]:
    """Each slot's size as the struct module counts one value of its code."""
    return [0 if s.code == "*" else struct.calcsize(layout.order + s.code.split("{")[0])
            for s in layout.slots]


def test_a_primitive_holds_the_layouts_of_its_formats() -> None:
    named = _model().primitives["named"]
    assert isinstance(named.encoding, m.Pack) and isinstance(named.decoding, m.Unpack)
    request = named.encoding.layout
    assert (request.order, request.fixed, request.size) == (">", ">BhH5s10pc", struct.calcsize(">BhH5s10pc"))
    assert [s.size for s in request.slots] == _code_sizes(request) == [1, 2, 2, 5, 10, 1]
    assert request.rooms == ((3, 5), (4, 9))  # `10p` holds a length byte and 9 of text
    reply = named.decoding.layout
    assert reply.varying is not None
    assert reply.size == struct.calcsize(reply.varying.head + reply.varying.tail) == 11  # without a round
    assert (reply.varying.unit_size, reply.varying.tail_size, reply.varying.count_size) == (
        struct.calcsize("<BH"), struct.calcsize("<I"), struct.calcsize("<B"))
    assert reply.most(2) == struct.calcsize("<HBbbbbBHBHI")
    flags = _model().primitives["flags"]
    assert isinstance(flags.encoding, m.Pack) and isinstance(flags.decoding, m.Unpack)
    split = flags.encoding.layout
    assert (split.fixed, split.size, split.bits) == ("<Bxq", struct.calcsize("<Bxq"), ((0, "<B", (1, 7)),))
    assert [s.size for s in split.slots] == [1, 1, 8]
    rest = flags.decoding.layout
    assert (rest.fixed, rest.size, rest.rest, rest.rooms) == ("<h3s", 5, True, ((1, 3),))


def test_frame_parts_and_reply_tags_hold_their_layouts() -> None:
    model = _model()
    frame = model.frames["framed"]
    field, length, check = (p for p in frame.request
                            if isinstance(p, (m.FrameField, m.FrameLength, m.FrameChecksum)))
    assert isinstance(field, m.FrameField) and isinstance(length, m.FrameLength)
    assert isinstance(check, m.FrameChecksum)
    assert (field.layout.order, field.layout.slots[0].code, field.layout.size) == (">", "H", 2)
    assert (length.layout.order, length.layout.slots[0].high) == ("<", 0xFFFF)
    assert check.layout is not None and check.layout.size == 2
    bits = next(p for p in frame.reply if isinstance(p, m.FrameBits))
    assert bits.layout.size == 2
    hex_check = next(p for p in frame.reply if isinstance(p, m.FrameChecksum))
    assert hex_check.layout is None  # ASCII hex digits: no struct format
    table = model.primitives["sensors"].table
    assert table is not None and table.tag_layout is not None and table.length_layout is not None
    assert (table.tag_layout.size, table.length_layout.size, table.length_layout.order) == (1, 2, ">")


def test_the_engine_gets_the_stored_layouts() -> None:
    """The engine's objects take the sizes the checker worked out (the lowering reads nothing else)."""
    model = _model()
    device = lower(model).device
    named = device.primitives["named"]
    reply = named.reply
    assert named.encoder is not None and isinstance(reply, FramedReply) and reply.decoder is not None
    assert isinstance(named.encoder.value, rdisc.engine.Pack)
    assert named.encoder.value.sizes == {3: 5, 4: 9}
    assert isinstance(reply.decoder.value, rdisc.engine.Unpack)
    assert reply.decoder.value.varying_sizes == (3, 4)
    framed = lower(model).frames["framed"]
    field, length = framed.request[1].value, framed.request[2].value
    assert isinstance(field, rdisc.engine.Field) and isinstance(length, rdisc.engine.Length)
    assert (field.order, field.code, length.order, length.code) == (">", "H", "<", "H")
    assert length.most == 0xFFFF - 1  # what `"<H"` holds, less the adjust


def test_a_padded_part_keeps_its_pad_bytes() -> None:
    """A one-integer part's format may pad (`xB`, `<xH`): the engine is given all its codes."""
    compiled = compile_text("padded.rdis", """\
robot padded { description "padded frame parts" }
frame padded(id: int in 0..200) { header "\\xFF"  field id "xB" = id  length "<xH" = payload  payload }
connection link: serial { baud 115200 }
primitive go(v: int in 0..9) on link frame padded(5) pack "B" (v)
""")
    assert compiled.model is not None
    port = ScriptedPort()
    with load(compiled.model).connect(port, threads=False) as robot:
        robot.primitives.go(7)
    assert bytes(port.written).hex(" ") == "ff 00 05 00 01 00 07"


def test_the_layout_is_derived_data() -> None:
    """Not in the JSON, nor in the Model's equality: a layout follows from its format."""
    named = _model().primitives["named"]
    assert isinstance(named.encoding, m.Pack)
    assert named.encoding == m.Pack(named.encoding.format, m.REFUSED, named.encoding.grouped)
    assert "layout" not in repr(named.encoding)


PACKAGE = Path(rdisc.__file__).parent
PARSES = re.compile(r"\bstruct_layout\(|\bcalcsize\(|\bsplit_rest\(")
CHECKER = {"semantics/formats.py", "semantics/check/layouts.py", "semantics/check/replies.py",  # where the Model is made
           "semantics/checksums.py"}  # a frame's one-integer formats (FrameRules takes them from ChecksumRules)
IMPORTER = "json_import/primitives.py"  # infers the types of thesis JSON's arguments, before there is a Model


def test_no_module_after_the_checker_parses_a_format() -> None:
    found = sorted(str(path.relative_to(PACKAGE)) for path in PACKAGE.rglob("*.py")
                   if PARSES.search(path.read_text(encoding="utf-8")))
    assert found == sorted([*CHECKER, IMPORTER])
    engine = "\n".join(path.read_text(encoding="utf-8") for path in (PACKAGE / "engine").glob("*.py"))
    assert not re.search(r"re\.findall|islower\(\)|\.format\[|fmt\[", engine)
