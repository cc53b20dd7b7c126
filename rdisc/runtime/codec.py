"""A primitive's bytes as the engine takes them: its encoder, its decoder, its frame.

These are data built once from the Model. The runtime hands the objects to the
engine; `rdisc emit-python` writes their constructors (`repr` of an encoder or a
decoder is its constructor call), so both encode and decode alike.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from rdisc import engine
from rdisc.semantics import formats
from rdisc.semantics import model as m

__all__ = ["bit_fields", "checksum", "decoder", "encoder", "frame_fields", "wire_frame"]


def encoder(encoding: m.Pack | m.Format) -> engine.Pack | engine.Format:
    match encoding:
        case m.Pack(format=fmt):
            return engine.Pack(*_struct_codec(formats.struct_layout(fmt)))
        case m.Format(template=template):
            return engine.Format(template)


def decoder(decoding: m.Unpack | m.Regex | None) -> engine.Unpack | engine.Match | None:
    match decoding:
        case m.Unpack(format=fmt, until=until):
            return engine.Unpack(*_struct_codec(formats.struct_layout(fmt)),
                                 until=None if until is None else until.encode("latin-1"))
        case m.Regex(pattern=pattern):
            return engine.Match(pattern)
    return None


def frame_fields(frame: m.Frame) -> tuple[tuple[str, m.Expr], ...]:
    """The frame's distinct fields, in the order their values are passed: a field of the
    reply with the name of one of the request but another value is a field of its own."""
    fields: dict[tuple[str, m.Expr], None] = {}
    for part in (part for layout in (*frame.requests, *frame.replies) for part in layout):
        if isinstance(part, m.FrameField):
            fields[(part.name, part.value)] = None
        elif isinstance(part, m.FrameBits):
            fields.update(((bit.name, bit.value), None) for bit in part.fields if bit.value is not None)
    return tuple(fields)


def bit_fields(part: m.FrameBits, index: dict[tuple[str, m.Expr], int]) -> tuple[list[tuple[str, int, int]], int]:
    """A `bits` part as the engine's `Bits` takes it: (name, width, field index or -1 for the
    length) from the lowest bits up, and the length's adjust."""
    entries = [(bit.name, bit.width, -1 if bit.value is None else index[(bit.name, bit.value)]) for bit in part.fields]
    return entries, part.length.adjust if part.length is not None else 0


def wire_frame(frame: m.Frame, params: tuple[engine.Param, ...] = (),
               fields: Callable[[engine.Args], list[Any]] | None = None) -> engine.Frame:
    """The Model's frame as the engine reads and writes it; `params` and `fields` (the field
    values over the parameters' values) where frames are used, not only read and written."""
    index = {key: i for i, key in enumerate(frame_fields(frame))}
    stuffing = None
    if frame.stuffing is not None:
        reserved, escape = frame.stuffing
        stuffing = engine.Stuffing(reserved.encode("latin-1"), escape.encode("latin-1"))
    escaping = None
    if frame.escaping is not None:
        escaping = engine.Escaping(frame.escaping.escape.encode("latin-1"), escape_table(frame.escaping))
    return engine.Frame(frame.name, [_part(p, index) for p in frame.request], [_part(p, index) for p in frame.reply],
                        stuffing, params, fields, [[_part(p, index) for p in layout] for layout in frame.more_requests],
                        [[_part(p, index) for p in layout] for layout in frame.more_replies], escaping)


def escape_table(escaping: m.Escaping) -> list[tuple[bytes, bytes]]:
    """An `escape` rule's (byte, code) pairs as the engine's `Escaping` takes them."""
    return [(byte.encode("latin-1"), code.encode("latin-1")) for byte, code in escaping.table]


def checksum(a: m.ChecksumAlgorithm) -> engine.Checksum:
    return engine.Checksum(a.kind, a.width, a.poly, a.init, a.reflect_in, a.reflect_out, a.xorout, a.inverted, a.mask)


def _part(part: m.FramePart, index: dict[tuple[str, m.Expr], int]) -> engine.Part:
    match part:
        case m.FrameBytes(role=role, data=data):
            return engine.Bytes(role, data.encode("latin-1"))
        case m.FrameField(name=name, format=fmt, value=value):
            return engine.Field(name, fmt, index[(name, value)])
        case m.FrameLength(format=fmt, adjust=adjust):
            return engine.Length(fmt, adjust)
        case m.FramePayload():
            return engine.Payload()
        case m.FrameChecksum():
            return engine.Check(checksum(part.algorithm), part.format, part.first, part.last, part.with_request)
        case m.FrameOptional(count=count):
            return engine.OptionalParts(count)
        case m.FrameBits(format=fmt):
            return engine.Bits(fmt, *bit_fields(part, index))
    raise AssertionError(part)


StructCodec = tuple[str, tuple[int, ...], bool, tuple[engine.Group, ...], engine.Varying | None,
                    tuple[engine.Split, ...]]


def _struct_codec(layout: formats.StructLayout) -> StructCodec:
    """A struct format as the engine's `Pack` and `Unpack` take it: the struct module's format
    (with a group repeated as the message says, the format before it), the indexes of its
    strings and its groups among the struct module's values (an integer split into bit fields
    one value), whether it ends in the rest, that group, the integers split into bits."""
    v = layout.varying
    fixed, varying = (layout.fixed, None) if v is None else (v.head, (v.unit, v.tail, v.count_at))
    strings = tuple(layout.joined(i) for i, slot in enumerate(layout.slots) if slot.type is m.Type.STRING)
    groups = tuple((layout.joined(first), codes, count) for first, codes, count in layout.groups)
    return fixed, strings, layout.rest, groups, varying, layout.bits
