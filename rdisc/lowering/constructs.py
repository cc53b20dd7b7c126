"""A primitive's bytes as the engine takes them: its encoder, its decoder, its frame's parts.

These are data built once from the Model, each a `Construct`: the engine object and the
constructor call that made it. The runtime hands the objects to the engine; `rdisc
emit-python` writes the calls, so both encode and decode alike. A struct format comes as
the layout the checker stored beside it (`model.StructLayout`): its struct module format,
sizes and indexes are handed on as they are, never worked out again from its text.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Generic, TypeVar

from rdisc import engine
from rdisc.semantics import bounds
from rdisc.semantics import model as m

__all__ = ["Construct", "Hex", "built", "checksum", "decoder", "decoding", "encoder", "encoding", "escaping",
           "frame_fields", "param", "parts", "stuffing"]

T = TypeVar("T")

_KINDS: dict[m.Type, type] = {m.Type.INT: int, m.Type.FLOAT: float, m.Type.BOOL: bool, m.Type.STRING: str,
                              m.Type.BYTES: bytes}


class Hex(int):
    """An integer best read in hexadecimal (a CRC's polynomial): its repr says so."""

    def __repr__(self) -> str:
        return f"{self:#x}"


@dataclass(frozen=True, slots=True, eq=False)
class Construct(Generic[T]):
    """An engine object and its constructor call: `kind(*args, **options)`, constructs among
    them made first. The runtime takes `value`; a driver is written the call."""

    kind: type[T]
    args: tuple[Any, ...] = ()
    options: tuple[tuple[str, Any], ...] = ()
    value: T = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "value", self.kind(*map(built, self.args),
                                                    **{key: built(value) for key, value in self.options}))


def built(value: Any) -> Any:
    """`value` with the constructs in it (in lists and tuples too) as the objects they made."""
    if isinstance(value, Construct):
        return value.value
    if isinstance(value, (list, tuple)):
        return type(value)(map(built, value))
    return value


def _call(kind: type[T], *args: Any, **options: Any) -> Construct[T]:
    """The construct of `kind(*args, **options)`, the options left out that are at their
    defaults (None, False, empty)."""
    given = tuple((key, value) for key, value in options.items()
                  if value is not None and value is not False and value != () and value != [])
    return Construct(kind, args, given)


def encoding(encoding: m.Pack | m.Format) -> Construct[engine.Pack] | Construct[engine.Format]:
    match encoding:
        case m.Pack(layout=layout):
            return _struct_codec(engine.Pack, layout)
        case m.Format(template=template):
            return _call(engine.Format, template)


def decoding(decoding: m.Unpack | m.Regex | None) -> Construct[engine.Unpack] | Construct[engine.Match] | None:
    match decoding:
        case m.Unpack(layout=layout, until=until):
            end = None if until is None else until.encode("latin-1")
            return _struct_codec(engine.Unpack, layout, until=end)
        case m.Regex(pattern=pattern):
            return _call(engine.Match, pattern)
    return None


def encoder(encoding_: m.Pack | m.Format) -> engine.Pack | engine.Format:
    """The engine's encoder of a request."""
    return encoding(encoding_).value


def decoder(decoding_: m.Unpack | m.Regex | None) -> engine.Unpack | engine.Match | None:
    """The engine's decoder of a reply, if it has one."""
    made = decoding(decoding_)
    return None if made is None else made.value


def param(name: str, type_: m.AnyType, low: float | None = None, high: float | None = None,
          default: m.Value | None = None, earlier: tuple[m.Parameter, ...] = (),
          limits: tuple[m.Expr, m.Expr] | None = None) -> Construct[engine.Param]:
    """A parameter, field or setting as the engine takes it; its default of its declared type;
    a range that reads `earlier` parameters as constants and terms (`rdisc.semantics.bounds`)."""
    options: tuple[tuple[str, Any], ...] = () if default is None else (("default", m.coerce(default, type_)),)
    if limits is not None:  # the checker made each bound a sum of constants and earlier parameters
        (low, low_terms), (high, high_terms) = (_linear(bound, earlier) for bound in limits)
        options += tuple((key, terms) for key, terms in (("low_terms", low_terms), ("high_terms", high_terms))
                         if terms)
    given = (low, high) if low is not None else ()
    if isinstance(type_, m.Array):
        return Construct(engine.Param, (name, _KINDS[type_.element], *given), (*options, ("size", type_.size)))
    return Construct(engine.Param, (name, _KINDS[type_], *given), options)


def _linear(bound: m.Expr, earlier: tuple[m.Parameter, ...]) -> tuple[int, bounds.Terms]:
    form = bounds.linear(bound, earlier)
    assert form is not None  # the checker refuses any other bound (E214)
    return form


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


def parts(frame: m.Frame, layout: tuple[m.FramePart, ...]) -> list[Construct[Any]]:
    """One layout of a frame's side as the engine's parts."""
    index = {key: i for i, key in enumerate(frame_fields(frame))}
    return [_part(part, index, layout) for part in layout]


def _field_key(part: m.FramePart) -> tuple[str, m.Expr]:
    """A `field` part's key among the frame's fields (the checker made sure a seed's is one)."""
    assert isinstance(part, m.FrameField)
    return part.name, part.value


def stuffing(frame: m.Frame) -> Construct[engine.Stuffing] | None:
    if frame.stuffing is None:
        return None
    reserved, escape = frame.stuffing
    return _call(engine.Stuffing, reserved.encode("latin-1"), escape.encode("latin-1"))


def escaping(frame: m.Frame) -> Construct[engine.Escaping] | None:
    """An `escape` rule as the engine's `Escaping`: the escape, and its (byte, code) pairs."""
    if frame.escaping is None:
        return None
    table = [(byte.encode("latin-1"), code.encode("latin-1")) for byte, code in frame.escaping.table]
    return _call(engine.Escaping, frame.escaping.escape.encode("latin-1"), table)


def checksum(a: m.ChecksumAlgorithm) -> engine.Checksum:
    """The engine's checksum of an algorithm."""
    return _checksum(a).value


def _checksum(a: m.ChecksumAlgorithm) -> Construct[engine.Checksum]:
    def hexadecimal(value: int) -> Hex | None:
        return Hex(value) if value else None

    return _call(engine.Checksum, a.kind, a.width, poly=hexadecimal(a.poly), init=hexadecimal(a.init),
                 reflect_in=a.reflect_in, reflect_out=a.reflect_out, xorout=hexadecimal(a.xorout),
                 inverted=a.inverted, mask=a.mask)


def _part(part: m.FramePart, index: Mapping[tuple[str, m.Expr], int],
          side: tuple[m.FramePart, ...]) -> Construct[Any]:
    match part:
        case m.FrameBytes(role=role, data=data):
            return _call(engine.Bytes, role, data.encode("latin-1"))
        case m.FrameField(name=name, value=value, layout=layout):
            return _call(engine.Field, name, layout.order, layout.codes, index[(name, value)])
        case m.FrameLength(adjust=adjust, layout=layout):
            return _call(engine.Length, layout.order, layout.codes, adjust, layout.slots[0].high)
        case m.FramePayload(trimmed=trimmed):
            return _call(engine.Payload, trimmed=trimmed)
        case m.FrameChecksum():
            seed = None if part.seed is None else (index[_field_key(side[part.seed.part])], part.seed.entries,
                                                   part.seed.table, part.seed.field)
            if part.layout is not None and part.layout.bits:  # bytes holding one integer (`>3s{24}`)
                order = "big" if part.layout.order in (">", "!") else "little"
                return _call(engine.Check, _checksum(part.algorithm), part.layout.fixed, part.first, part.last,
                             with_request=part.with_request, seed=seed, byte_order=order)
            return _call(engine.Check, _checksum(part.algorithm), part.format, part.first, part.last,
                         with_request=part.with_request, seed=seed)
        case m.FrameOptional(count=count):
            return _call(engine.OptionalParts, count)
        case m.FrameBits(format=fmt, fields=bits):
            # (name, width, field index or -1 for the length) from the lowest bits up, and the length's adjust
            entries = [(bit.name, bit.width, -1 if bit.value is None else index[(bit.name, bit.value)]) for bit in bits]
            return _call(engine.Bits, fmt, entries, part.length.adjust if part.length is not None else 0)
    raise AssertionError(part)


def _struct_codec(kind: type[T], layout: m.StructLayout, until: bytes | None = None) -> Construct[T]:
    """A struct format as the engine's `Pack` and `Unpack` take it: the struct module's format
    (with a group repeated as the message says, the format before it), the indexes of its
    strings and its groups among the struct module's values (an integer split into bit fields
    one value), whether it ends in the rest, that group, the integers split into bits; a
    request's, the most bytes each `Ns` and `Np` holds and its width field with the `%` codes it sizes; a reply's, the sizes of that group's
    round and of what follows it."""
    v = layout.varying
    fixed, varying = (layout.fixed, None) if v is None else (v.head, (v.unit, v.tail, v.count_at))
    strings = tuple(layout.joined(i) for i, slot in enumerate(layout.slots) if slot.type is m.Type.STRING)
    groups = tuple((layout.joined(first), codes, count) for first, codes, count in layout.groups)
    if kind is engine.Pack:
        widths = tuple(layout.joined(i) for i, slot in enumerate(layout.slots) if slot.code == "%")
        return _call(kind, fixed, strings=strings, rest=layout.rest, groups=groups, varying=varying,
                     bits=layout.bits, rooms=layout.rooms,
                     width=None if layout.width < 0 else (layout.joined(layout.width), widths))
    padded = tuple(layout.joined(i) for i, slot in enumerate(layout.slots) if slot.code.endswith("Z"))
    return _call(kind, fixed, strings=strings, rest=layout.rest, groups=groups, varying=varying, bits=layout.bits,
                 until=until, varying_sizes=None if v is None else (v.unit_size, v.tail_size), padded=padded)
