"""The Model: the checked, resolved, typed description that every emitter and the
runtime consume. Built only after checking succeeded, so every reference in it
names an element that exists (references are typed keys into per-kind maps).
"""

from __future__ import annotations

import enum
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any, NewType

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.model_methods import dataclass, field

from rdisc.frozen import field_names, replace
from rdisc.source import Span

_span = field(compare=False, repr=False, default=None)

ConnectionRef = NewType("ConnectionRef", str)
PrimitiveRef = NewType("PrimitiveRef", str)
InterfaceRef = NewType("InterfaceRef", str)
OutputRef = NewType("OutputRef", str)
AdapterRef = NewType("AdapterRef", str)
StateRef = NewType("StateRef", str)
FrameRef = NewType("FrameRef", str)


class Type(enum.Enum):
    INT = "int"
    FLOAT = "float"
    BOOL = "bool"
    STRING = "string"
    BYTES = "bytes"  # parameters and replies only: variable-length binary data

    def default(self) -> Value:
        """The value `""` stands for in thesis JSON (section 4.3.3)."""
        defaults: dict[Type, Value] = {Type.INT: 0, Type.FLOAT: 0.0, Type.BOOL: False, Type.STRING: "", Type.BYTES: b""}
        return defaults[self]


@dataclass(frozen=True, slots=True)
class Array:
    """A fixed number of values of one scalar type (`int[6]`), held as a tuple. An adapter's
    field leaves the size open (`float[]`, size 0): the description that uses it fixes it."""

    element: Type
    size: int  # 0: open

    @property
    def value(self) -> str:
        """As written: `int[6]`, `float[]`."""
        return f"{self.element.value}[{self.size or ''}]"

    def default(self) -> tuple[Value, ...]:
        return (self.element.default(),) * self.size


AnyType = Type | Array
Value = int | float | bool | str | bytes | tuple[Any, ...]  # an array's value is a tuple of its elements


def coerce(value: Value, type_: AnyType) -> Value:
    """A value as the type it is declared with: ints widen to floats, nothing else changes."""
    if isinstance(type_, Array):
        if type_.element is Type.FLOAT and isinstance(value, tuple):
            return tuple(coerce(v, Type.FLOAT) for v in value)
        return value
    if type_ is Type.FLOAT and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    return value


# ---- typed expressions ----------------------------------------------------------


class Scope(enum.Enum):
    """Where a name read by an expression lives."""

    STATE = "state"
    PARAM = "param"
    FIELD = "field"


@dataclass(frozen=True, slots=True)
class Const:
    value: Value
    type: AnyType
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Var:
    name: str
    scope: Scope
    type: AnyType
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class ReplyValue:
    """`out[index]`: one value of the primitive's reply."""

    index: int
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class UnaryOp:
    op: str  # "-", "+", "~", "not"
    operand: Expr
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class BinaryOp:
    op: str
    left: Expr
    right: Expr
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class IfElse:
    cond: Expr
    then: Expr
    orelse: Expr
    type: AnyType
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class FuncCall:
    func: str  # one of rdisc.engine.operations.FUNCTIONS
    args: tuple[Expr, ...]
    type: AnyType
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Table:
    """A lookup table constant: its keys (ints or strings) and values, each of one type."""

    name: str
    key_type: Type
    value_type: Type
    entries: tuple[tuple[Value, Value], ...]
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class Lookup:
    """`TABLE[key]`: the value a lookup table holds for the key; a key it lacks is an error,
    unless a `default` is given (`TABLE.get(key, default)`)."""

    table: str
    entries: tuple[tuple[Value, Value], ...]
    key: Expr
    type: Type
    span: Span | None = _span
    default: Expr | None = None


@dataclass(frozen=True, slots=True)
class InTable:
    """`key in TABLE`: whether a lookup table has an entry for the key."""

    table: str
    keys: tuple[Value, ...]
    key: Expr
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class ArrayValue:
    """`[a, b, c]`: an array of the items' values."""

    items: tuple[Expr, ...]
    type: Array
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Element:
    """`array[index]`: one element; an index outside the array is an error, never wrapped."""

    array: Expr
    index: Expr
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Replaced:
    """The array with one element replaced: what `array[index] = value` in a post-action stores."""

    array: Expr
    index: Expr
    value: Expr
    type: Array
    span: Span | None = _span
    when: Expr | None = None  # `array[index] = value when COND`: the element kept unless COND holds


def array_name(array: Expr) -> str:
    """How a run-time error names an array: the variable's name, `out[1]` for a reply's value,
    or `array` for a computed one."""
    if isinstance(array, ReplyValue):
        return f"out[{array.index}]"
    return array.name if isinstance(array, Var) else "array"


def spread(args: tuple[Expr, ...]) -> tuple[Expr, ...]:
    """Format arguments as the values they give, one per code: an array as its elements."""
    values: list[Expr] = []
    for a in args:
        if isinstance(a, Const) and isinstance(a.value, tuple) and isinstance(a.type, Array):
            values.extend(Const(v, a.type.element, a.span) for v in a.value)
        elif isinstance(a.type, Array):
            values.extend(Element(a, Const(i, Type.INT), a.type.element, a.span) for i in range(a.type.size))
        else:
            values.append(a)
    return tuple(values)


def operands(e: Expr) -> tuple[Expr, ...]:
    """The expressions `e` is made of, one level down (none for a name, a constant, `out[i]`)."""
    match e:
        case Lookup(key=a, default=b) if b is not None:
            return (a, b)
        case UnaryOp(operand=a) | Lookup(key=a) | InTable(key=a):
            return (a,)
        case BinaryOp(left=a, right=b) | Element(array=a, index=b):
            return (a, b)
        case IfElse(cond=a, then=b, orelse=c) | Replaced(array=a, index=b, value=c):
            return (a, b, c)
        case FuncCall(args=items) | ArrayValue(items=items):
            return items
    return ()


def variables(e: Expr) -> Iterator[Var]:
    """Every name `e` reads (state, parameters, fields), in order, repeats included."""
    if isinstance(e, Var):
        yield e
    for operand in operands(e):
        yield from variables(operand)


Expr = (Const | Var | ReplyValue | UnaryOp | BinaryOp | IfElse | FuncCall | Lookup | InTable | ArrayValue | Element
        | Replaced)


# ---- elements --------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Parameter:
    name: str
    type: AnyType
    low: int | float | None = None  # the range a value must be in, when declared
    high: int | float | None = None
    default: Value | None = None  # the value when a call leaves it out (the parameters after it have one too)
    unit: str | None = None  # one of rdisc.semantics.units.UNITS, when declared
    limits: tuple[Expr, Expr] | None = None  # bounds that read earlier parameters (`0..count - 1`),
    # checked at each call (rdisc.semantics.bounds); `low` and `high` are then the widest range they give

    def range_text(self) -> str:
        return f"{self.low!r}..{self.high!r}"


@dataclass(frozen=True, slots=True)
class Robot:
    name: str
    author: str | None = None
    description: str | None = None
    version: str | None = None
    doc: str | None = None
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class StateVariable:
    name: str
    type: AnyType
    initial: Value
    doc: str | None = None
    span: Span | None = _span
    noise: Noise | None = None  # the error of the values a device reports into it (thesis §7.2.3)


@dataclass(frozen=True, slots=True)
class Sensor:
    """`sensor NAME: TYPE from PRIMITIVE() cache N ms`: the primitive's one reply value, read
    when a reader finds it older than the cache time and kept until then (thesis §7.2.4)."""

    name: str
    type: AnyType
    primitive: PrimitiveRef
    cache_ms: float
    doc: str | None = None
    span: Span | None = _span
    noise: Noise | None = None  # the error of the value it reads (thesis §7.2.3)


@dataclass(frozen=True, slots=True)
class Setting:
    """A value given when connecting (a baud rate, a servo's ID, a wheel base): read-only,
    read by expressions as state is; `default` when none is given, and what the checks use."""

    name: str
    type: AnyType
    default: Value
    low: int | float | None = None  # the range a given value must be in, when declared
    high: int | float | None = None
    doc: str | None = None
    span: Span | None = _span

    def range_text(self) -> str:
        return f"{self.low!r}..{self.high!r}"


@dataclass(frozen=True, slots=True)
class HookCall:
    """A connection event calling an interface; arguments see state only."""

    interface: InterfaceRef
    args: tuple[Expr, ...]
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Keepalive:
    call: HookCall
    interval_ms: float


@dataclass(frozen=True, slots=True)
class Connection:
    name: str
    kind: str  # "serial"
    baud: int
    frequency_hz: float
    startup: HookCall | None = None
    terminate: HookCall | None = None
    keepalive: Keepalive | None = None
    doc: str | None = None
    span: Span | None = _span
    terminator: str = "\n"  # ends a reply line; "\n" also takes a "\r" before it
    address: str | None = None  # the port opened when none is given (path or URL)
    baud_setting: str | None = None  # the setting that gives the baud rate (`baud` is then its default)
    data_bits: int = 8  # a serial line's character: data bits, parity, stop bits (8N1 unless said)
    parity: str = "none"  # none, even, odd, mark or space
    stop_bits: float = 1  # 1, 1.5 or 2
    threading: str = "single"  # single, dual or multiple (rdisc.engine.schedule)

    def terminator_bytes(self) -> bytes:
        return self.terminator.encode("latin-1")

    def rate_of(self, interface: Interface) -> float:
        """Runs a second of a periodic interface of this connection: its own rate under
        `threading multiple` when it states one, else the connection's frequency."""
        own = interface.rate_hz if self.threading == "multiple" else None
        return own or self.frequency_hz

    def line_text(self) -> str:
        """The serial line's character as it is usually written: `8N1`, `8E2`, `5N1.5`."""
        return f"{self.data_bits}{self.parity[0].upper()}{self.stop_bits:g}"

    def bits_per_byte(self) -> float:
        """A byte's bits on the wire: a start bit, the data bits, a parity bit, the stop bits."""
        return 1 + self.data_bits + (self.parity != "none") + self.stop_bits


# ---- struct layouts: a struct format parsed once, by the checker (rdisc.semantics.formats) -------------


@dataclass(frozen=True, slots=True)
class Slot:
    """One value a struct format takes or yields."""

    code: str  # the struct code as written: `B`, `3s`, `B{1,1,6}` for a bit field, `*` for the rest
    type: Type
    low: int | None = None  # integer range, when the code has one
    high: int | None = None
    repeat: int = 0  # in a repeated group `6(BH)`: the group's count (the value is an array of it); -1 in a
    # group repeated as the message says (`#(BH)`, `*(BH)`), whose value is an array of any size
    bits: tuple[int, int] | None = None  # a bit field of an integer code (`B{1,1,6}`): its lowest bit, its width
    size: int = field(default=0, compare=False)  # bytes of one value of its code (a bit field: of its integer)

    @property
    def shown(self) -> str:
        """The code as a message names it: `B`, or `B{1,1,6}` bits 2..7 for a bit field."""
        if self.bits is None:
            return f"`{self.code}`"
        return f"`{self.code}` {bit_span(*self.bits)}"


def bit_span(low: int, width: int) -> str:
    """The bits a field takes in its integer: `bit 0`, `bits 2..7`."""
    return f"bit {low}" if width == 1 else f"bits {low}..{low + width - 1}"


@dataclass(frozen=True, slots=True)
class Varying:
    """A group repeated as many times as the message says, after `head` (a struct format
    with its byte order) and before `tail`: `#(BH)` as many times as the count field `#B`
    in the head says (its index among the head's values: `count_at`), `*(BH)` until the
    message ends (`count_at` -1). The count field takes and gives no value: a request
    computes it from the arrays' length, a reply's arrays have its length."""

    head: str
    unit: str  # the group's codes, once
    tail: str
    count_at: int
    count_high: int = 0  # the largest count the count field holds, at most MAX_ARRAY (0: no count field)
    count_code: str = ""
    count_slot: int = -1  # the slot the count field comes before (its place among the values)
    unit_size: int = field(default=0, compare=False)  # bytes of one round
    tail_size: int = field(default=0, compare=False)  # bytes of the tail
    count_size: int = field(default=0, compare=False)  # bytes of the count field (0: none)


@dataclass(frozen=True, slots=True)
class StructLayout:
    """A struct format as every stage after the checker reads it: its values, the struct
    module's format and the sizes, worked out once."""

    slots: tuple[Slot, ...]
    size: int  # bytes on the wire (before the rest, when it ends in `*`; without a round of its varying group)
    native: bool  # no byte-order prefix: host order and alignment
    rest: bool = False  # ends in `*`: the rest of the message, as bytes
    fixed: str = ""  # the format without its `*` and with its groups written out, for the struct module
    groups: tuple[tuple[int, int, int], ...] = ()  # each repeated group: (its first slot, its codes, its count)
    varying: Varying | None = None  # a group repeated as the message says (its count 0 in `groups`)
    bits: tuple[tuple[int, str, tuple[int, ...]], ...] = ()  # each integer split into bit fields: its first
    # field's slot, its code with the byte order, its fields' widths from its lowest bit up
    order: str = ""  # the byte-order prefix as written (`<`, `>`, `!`, `=`, `@`), "" when none
    rooms: tuple[tuple[int, int], ...] = ()  # each `Ns` or `Np` value: its index among the struct module's
    # values, the most bytes of text it holds
    width: int = -1  # the slot of the width field `%H` that states the bytes of its groups' `%` codes (-1: none);
    # `size` counts each `%` code at its widest, 8 bytes

    @property
    def codes(self) -> str:
        """The struct module's format without its byte order: what a one-integer part packs (`xB` too)."""
        return self.fixed[len(self.order) :]

    def joined(self, slot: int) -> int:
        """The index among the struct module's values of a slot's value (not a bit field's): what
        the engine counts groups and strings in."""
        return slot - sum(len(widths) - 1 for first, _, widths in self.bits if first < slot)

    @property
    def open_end(self) -> bool:
        """Whether the message's size is not the format's: something must say where it ends."""
        return self.rest or self.varying is not None or self.width >= 0

    def most(self, count: int) -> int:
        """The size of the message with `count` rounds of its varying group (its size without one)."""
        return self.size + (self.varying.unit_size * count if self.varying is not None else 0)


REFUSED = StructLayout((), 0, False)
"""The layout of a format the checker refused (reported: no Model is made of it)."""


@dataclass(frozen=True, slots=True)
class Pack:
    """Raw-encoded request: a struct format."""

    format: str
    layout: StructLayout = field(compare=False, repr=False)  # the format parsed (derived: not in the JSON)
    grouped: tuple[int, ...] = ()  # the arguments that fill a repeated group's codes, each an array


@dataclass(frozen=True, slots=True)
class Format:
    """ASCII request: a PEP 3101 format with positional fields."""

    template: str


@dataclass(frozen=True, slots=True)
class Unpack:
    """Fixed-width raw reply: a struct format. With `until`, an unframed tagged reply's entry
    reads to those bytes (Firmata's sysex, ended by 0xF7) and its `*` rest takes what is before."""

    format: str
    layout: StructLayout = field(compare=False, repr=False)
    until: str | None = None  # latin-1 text, as a connection's terminator


@dataclass(frozen=True, slots=True)
class Regex:
    """ASCII reply line, matched by a regular expression; groups are the values."""

    pattern: str


@dataclass(frozen=True, slots=True)
class PostAction:
    target: StateRef
    value: Expr
    span: Span | None = _span
    when: Expr | None = None  # `target = value when COND`: the state variable kept unless COND holds

    def stored(self) -> Expr:
        """What the action stores, its conditions spelled out: `value if COND else target`, and
        for each element `array[index] = value when COND`, the element as it was unless COND holds."""
        return _kept_unless(self.when, _elements_kept(self.value), Var(self.target, Scope.STATE, self.value.type))


def _elements_kept(value: Expr) -> Expr:
    """`value` with each conditional element replacement spelled out (see PostAction.stored)."""
    if not isinstance(value, Replaced):
        return value
    array = _elements_kept(value.array)
    element = _kept_unless(value.when, value.value, Element(array, value.index, value.type.element))
    return Replaced(array, value.index, element, value.type, value.span)


def _kept_unless(when: Expr | None, value: Expr, kept: Expr) -> Expr:
    return value if when is None else IfElse(when, value, kept, value.type, value.span)


MODEM_LINES = ("dtr", "rts")
BREAK = "break"  # a LineLevel's line for a serial break: its value the duration in ms (a float constant)
"""The serial port's modem lines a primitive may set (pyserial's `dtr` and `rts`)."""


@dataclass(frozen=True, slots=True)
class LineLevel:
    """A modem line and its level (a bool over state and the primitive's parameters)."""

    line: str  # one of MODEM_LINES, or BREAK
    value: Expr
    span: Span | None = _span


_KEEPING_WIDTH = frozenset({"&", "|", "^", ">>", "==", "!=", "<", "<=", ">", ">=", "and", "or"})


def may_outgrow(e: Expr) -> bool:
    """Whether an int expression may pass the 64 bits (and a sign) that state keeps: not when
    it is made of reply values, constants and state by operators that keep the width (`&`,
    `>>`, comparisons, ...), so the run-time check is left out where it cannot fail."""
    match e:
        case Const() | ReplyValue():
            return False
        case Var(scope=scope):
            return scope is not Scope.STATE  # a parameter is what the host gave: any int
        case UnaryOp(operand=operand):
            return may_outgrow(operand)
        case BinaryOp(op=op, left=left, right=right) if op in _KEEPING_WIDTH:
            return may_outgrow(left) or may_outgrow(right)
        case IfElse(then=then, orelse=orelse):
            return may_outgrow(then) or may_outgrow(orelse)
        case FuncCall(func="abs" | "min" | "max" | "clamp", args=args):
            return any(may_outgrow(a) for a in args)
        case FuncCall(func="len" | "byte" | "bool") | Replaced():
            return False  # a replaced element is checked as it is stored
    return True


def looks_up(e: object) -> bool:
    """Whether an expression looks a key up in a table without a default (`HEALTH[out[0]]`),
    which a key the table lacks makes fail."""
    if isinstance(e, Lookup) and e.default is None:
        return True
    if isinstance(e, tuple):
        return any(looks_up(item) for item in e)
    return any(looks_up(getattr(e, name)) for name in field_names(e) if name != "span")


# ---- frames: the bytes around a payload ---------------------------------------------


@dataclass(frozen=True, slots=True)
class ChecksumAlgorithm:
    """An additive sum, an XOR or a CRC (Rocksoft parameters), then optionally
    inverted (`~value`) and masked, all within `width` bits."""

    kind: str  # "sum" | "xor" | "crc"
    width: int  # bits
    poly: int = 0
    init: int = 0
    reflect_in: bool = False
    reflect_out: bool = False
    xorout: int = 0
    inverted: bool = False
    mask: int | None = None
    name: str = ""  # as written: "sum", "crc16-xmodem", ...


@dataclass(frozen=True, slots=True)
class FrameBytes:
    """Constant bytes (latin-1 text): the header, a literal between parts, or the terminator."""

    role: str  # "header" | "literal" | "terminator"
    data: str


@dataclass(frozen=True, slots=True)
class FrameField:
    """A value computed from the frame's parameters, in a one-integer struct format.
    In a reply it is read and must equal the value the request was framed with."""

    name: str
    format: str
    value: Expr
    layout: StructLayout = field(compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class FrameLength:
    """The payload's size plus `adjust`, in a one-integer struct format."""

    format: str
    adjust: int
    layout: StructLayout = field(compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class FramePayload:
    """Where the primitive's own bytes go; `trimmed`: without their trailing zero bytes (a first
    byte kept), which a reader puts back up to the size its decoding takes (MAVLink 2)."""

    trimmed: bool = False


@dataclass(frozen=True, slots=True)
class FrameSeed:
    """`seed TABLE[FIELD]`: the byte the lookup table holds for the value of the field (the part
    `part` of the checksum's side), summed after the bytes covered and never sent (MAVLink 2's
    CRC_EXTRA); `entries`, the table's (key, byte) pairs."""

    table: str
    field: str
    part: int
    entries: tuple[tuple[int, int], ...]


@dataclass(frozen=True, slots=True)
class FrameChecksum:
    """A checksum over the parts `first` to `last` of its side (indexes); in a reply,
    `with_request` puts the request's bytes, as sent, before them; `seed`, a byte summed after them."""

    algorithm: ChecksumAlgorithm
    format: str | None  # a one-integer struct format; None: ASCII hex digits
    first: int
    last: int
    with_request: bool = False
    layout: StructLayout | None = field(default=None, compare=False, repr=False)  # of `format`
    seed: FrameSeed | None = None


@dataclass(frozen=True, slots=True)
class FrameOptional:
    """The `count` parts after it, which a reply may lack, all together: they are there when
    their first bytes (constant) are. A request writes them."""

    count: int


@dataclass(frozen=True, slots=True)
class BitField:
    """`width` bits of a `FrameBits`: a field's value over the frame's parameters (in a reply
    read and checked like a `FrameField`), or, `value` None, the payload's size plus `adjust`."""

    name: str  # "length" for the length
    width: int
    value: Expr | None = None
    adjust: int = 0


@dataclass(frozen=True, slots=True)
class FrameBits:
    """One unsigned integer in a one-integer struct format, holding `fields` from its lowest
    bit up (their widths add up to the format's bits)."""

    format: str
    fields: tuple[BitField, ...]
    layout: StructLayout = field(compare=False, repr=False)

    @property
    def length(self) -> BitField | None:
        return next((f for f in self.fields if f.value is None), None)


FramePart = FrameBytes | FrameField | FrameLength | FramePayload | FrameChecksum | FrameOptional | FrameBits


@dataclass(frozen=True, slots=True)
class Escaping:
    """Escaping between a frame's flags (SLIP, HDLC, PPP): each byte of `table` is sent as
    `escape` and its code (one character up to \\xff each), so no flag comes between them."""

    escape: str
    table: tuple[tuple[str, str], ...]  # (byte, code)


@dataclass(frozen=True, slots=True)
class Frame:
    """A frame's parts each way; with `either`, more than one layout of a side: a request is
    written with the first that can state its payload's size, a reply read by its header."""

    name: str
    params: tuple[Parameter, ...]
    request: tuple[FramePart, ...]  # the first (or only) layout
    reply: tuple[FramePart, ...]  # () when the device answers nothing framed
    doc: str | None = None
    span: Span | None = _span
    stuffing: tuple[str, str] | None = None  # (reserved, escape): escape inserted after reserved
    more_requests: tuple[tuple[FramePart, ...], ...] = ()  # the other layouts, in order
    more_replies: tuple[tuple[FramePart, ...], ...] = ()
    escaping: Escaping | None = None
    request_when: tuple[Expr | None, ...] = ()  # `either when`: each request layout's condition (None: plain)
    reply_when: tuple[Expr | None, ...] = ()  # each reply layout's, over parameters given settings only

    @property
    def requests(self) -> tuple[tuple[FramePart, ...], ...]:
        return (self.request, *self.more_requests)

    @property
    def replies(self) -> tuple[tuple[FramePart, ...], ...]:
        """Every layout of the reply; none when the device answers nothing framed."""
        return (self.reply, *self.more_replies) if self.reply else ()


@dataclass(frozen=True, slots=True)
class FrameUse:
    frame: FrameRef
    args: tuple[Expr, ...]  # over the primitive's parameters


@dataclass(frozen=True, slots=True)
class ReplyCase:
    """The reply of a primitive when its table's key (or its reply's tag) has `value`, or
    any value from `value` to `last`."""

    value: int
    decoding: Unpack | Regex
    actions: tuple[PostAction, ...] = ()
    last: int | None = None  # the end of a range entry's values
    under: int | None = None  # an entry of a nested table: the tag before (Firmata's F0), read first
    under_tag: str | None = None  # then the nested table's tag (a one-integer struct format)
    under_layout: StructLayout | None = field(default=None, compare=False, repr=False)  # of `under_tag`

    def values(self) -> range:
        """The key or tag values this entry is the reply for (a few thousand at most: checked)."""
        return range(self.value, (self.value if self.last is None else self.last) + 1)

    def table_keys(self) -> list[int | tuple[int, int]]:
        """Its keys in the engine's table: its values, or under a nested table (tag, its tag) pairs."""
        under = self.under
        return list(self.values()) if under is None else [(under, v) for v in self.values()]

    def values_text(self) -> str:
        """`7`, or `224..239` for a range entry."""
        return str(self.value) if self.last is None else f"{self.value}..{self.last}"


@dataclass(frozen=True, slots=True)
class ListedReply:
    """One reply of `replies { ... }`, read in its place among the others: through its own
    frame (None: the primitive's), decoded, held by its own `expect`, then its post-actions."""

    decoding: Unpack | Regex
    frame: FrameUse | None = None
    expect: Expr | None = None
    actions: tuple[PostAction, ...] = ()


@dataclass(frozen=True, slots=True)
class RepliesEach:
    """`replies id in ids frame status(id)` over an array parameter `ids`: a reply for each of
    its elements, as many as the caller gives, each read through the one reply frame (`reply_frames`)
    whose arguments read that element as `var`."""

    var: str
    over: str  # the array parameter

    def array(self, params: tuple[Parameter, ...]) -> Array:
        """The type of the array parameter (of size 0 when open: as many replies as it has)."""
        array = next(p.type for p in params if p.name == self.over)
        assert isinstance(array, Array)  # the checker's
        return array

    def local(self, params: tuple[Parameter, ...]) -> tuple[Parameter, ...]:
        """What the reply frame's arguments read: the parameters, then the element as `var`."""
        return (*params, Parameter(self.var, self.array(params).element))


@dataclass(frozen=True, slots=True)
class ErrorReply:
    """The reply a device may send instead of the one asked for (Modbus's exception, a NACK):
    known by its own frame (None: the primitive's, or none) or by its first bytes (`marker`,
    latin-1), decoded, its first value the device's code, named by the enum `codes`. It is
    raised, never stored: an RdisDeviceError. With `when` (`error when COND`), it is the reply
    itself, decoded by the primitive's `decoding`, when the condition over `out` holds."""

    decoding: Unpack
    frame: FrameUse | None = None
    marker: str = ""
    codes: str | None = None
    when: Expr | None = None


TAG = "tag"  # the name of a tagged reply's tag in its entries' post-actions
INDEX = "index"  # the name of a record's position in the post-actions of `reply each until`


@dataclass(frozen=True, slots=True)
class ReplyTable:
    key: str  # the parameter whose value chooses the reply ("" when a tag does)
    cases: tuple[ReplyCase, ...]
    tag: str | None = None  # a one-integer struct format: the tag starting the payload chooses
    each: bool = False  # the payload is sub-payloads, each tagged and decoded by its entry, until it ends
    length: str | None = None  # each sub-payload's length field after its tag (`each`): an unknown tag is skipped
    tag_layout: StructLayout | None = field(default=None, compare=False, repr=False)  # of `tag`
    length_layout: StructLayout | None = field(default=None, compare=False, repr=False)  # of `length`


@dataclass(frozen=True, slots=True)
class Primitive:
    name: str
    params: tuple[Parameter, ...]
    connection: ConnectionRef
    encoding: Pack | Format | None  # None: it writes no request, and only sets `lines`
    args: tuple[Expr, ...]
    decoding: Unpack | Regex | None = None
    actions: tuple[PostAction, ...] = ()
    doc: str | None = None
    span: Span | None = _span
    frame: FrameUse | None = None
    skip_unmatched: bool = False  # reads frames until one decodes, within the timeout
    table: ReplyTable | None = None  # the reply chosen by a parameter (then no `decoding`)
    timeout_ms: float | None = None  # how long its reply may take, instead of the robot's timeout
    expect: Expr | None = None  # a condition on the decoded reply that it must meet
    lines: tuple[LineLevel, ...] = ()  # modem lines set before the request, in this order
    replies: int = 0  # `replies N`: N replies to its request, each value of them an array of N (0: one reply)
    reply_frames: tuple[FrameUse, ...] = ()  # each reply's own frame, when `replies` gives them
    records: str | None = None  # `reply each until`: the marker ending each record of the payload (latin-1)
    listed: tuple[ListedReply, ...] = ()  # `replies { ... }`: replies of different shapes, in order
    retries: int = 0  # `retry N`: resends after a timeout or a reply that does not match (0: none)
    error: ErrorReply | None = None  # `error ...`: the exception the device may send instead of its reply
    each: RepliesEach | None = None  # `replies id in ids`: a reply for each element of an array parameter

    def listed_reply(self, r: ListedReply) -> Primitive:
        """This primitive as it is for one of its listed replies: that reply's frame, decoding,
        `expect` and post-actions, as if it were its only one."""
        return replace(self, decoding=r.decoding, frame=r.frame or self.frame, expect=r.expect,
                                   actions=r.actions, listed=())

    def post_actions(self) -> tuple[PostAction, ...]:
        """Every post-action it may run: its own, its table's entries' and its listed replies'."""
        return (*self.actions, *(a for c in (self.table.cases if self.table else ()) for a in c.actions),
                *(a for r in self.listed for a in r.actions))

    def case(self, c: ReplyCase) -> Primitive:
        """This primitive as it is when its table's key (or its reply's tag) has c.value: one decoding."""
        return replace(self, decoding=c.decoding, actions=c.actions, table=None)

    def reply_locals(self) -> tuple[Parameter, ...]:
        """What its post-actions read besides state and `out`: its parameters, and after
        them, when a tag chooses the reply, the tag's value as `tag`, or, when the reply is
        records, the record's position as `index`."""
        if self.records is not None:
            return (*self.params, Parameter(INDEX, Type.INT))
        if self.table is None or self.table.tag is None:
            return self.params
        return (*self.params, Parameter(TAG, Type.INT))

    def formats_its_params(self) -> bool:
        """Whether a call's arguments can be its format values as they are: no post-actions,
        frame, table, modem lines or ranges, and format arguments that are constants and its parameters,
        each once and in order (both planners then skip binding the parameters)."""
        used = [a.name for a in self.args if isinstance(a, Var) and a.scope is Scope.PARAM]
        simple = all(isinstance(a, Const) or (isinstance(a, Var) and a.scope is Scope.PARAM) for a in self.args)
        return (simple and not self.spreads()
                and not (self.actions or self.frame or self.table or self.expect or self.lines)
                and all(p.low is None for p in self.params) and used == [p.name for p in self.params])

    def format_values(self) -> tuple[Expr, ...]:
        """The format's values, one per slot: an array argument as its elements, except in a
        repeated group, which takes it whole."""
        spreads = self.spreads()
        return tuple(v for i, a in enumerate(self.args) for v in (spread((a,)) if i in spreads else (a,)))

    def spreads(self) -> tuple[int, ...]:
        """The format arguments that are arrays outside a repeated group: each gives its elements
        as that many values."""
        grouped = self.encoding.grouped if isinstance(self.encoding, Pack) else ()
        return tuple(i for i, a in enumerate(self.args) if isinstance(a.type, Array) and i not in grouped)

    def expects_reply(self, frames: dict[str, Frame]) -> bool:
        """A reply is read when there is one to decode, or when the frame's reply
        is an acknowledgement (constant parts only, no payload)."""
        if self.decoding is not None or self.table is not None or self.listed:
            return True
        if self.frame is None:
            return False
        reply = frames[self.frame.frame].reply
        return bool(reply) and not any(isinstance(p, FramePayload) for p in reply)


@dataclass(frozen=True, slots=True)
class PrimitiveCall:
    """A call in an interface's body: of a primitive, or (`interface`, when no primitive has
    the name) of another interface; the checker keeps the calls between interfaces acyclic."""

    primitive: PrimitiveRef
    args: tuple[Expr, ...]
    delay_ms: float = 0
    priority: int = 0
    span: Span | None = _span
    interface: bool = False
    when: Expr | None = None  # made only when this holds, over state and the interface's parameters
    until: Expr | None = None  # made again every `every_ms` until this holds, at most within_ms / every_ms more times
    every_ms: float = 0
    within_ms: float = 0


@dataclass(frozen=True, slots=True)
class Interface:
    name: str
    params: tuple[Parameter, ...]
    periodic: bool
    calls: tuple[PrimitiveCall, ...]  # as written
    triggers: tuple[OutputRef, ...] = ()  # delivered in this order after the calls
    doc: str | None = None
    span: Span | None = _span
    rate_hz: float | None = None  # its own rate (`periodic 10 Hz`), under `threading multiple`

    def run_order(self) -> tuple[PrimitiveCall, ...]:
        """Calls by priority, then as written (a stable sort)."""
        return tuple(sorted(self.calls, key=lambda c: c.priority))


@dataclass(frozen=True, slots=True)
class AdapterField:
    name: str
    type: AnyType
    unit: str | None = None
    ros: str | None = None
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class FrameworkMapping:
    """What an adapter is in one framework (thesis §7.2.5; rdisc.semantics.frameworks): the
    framework (`ros2`) and its title (`ROS 2`), the adapter's message or schema type there, each
    field's path in it in the adapter's field order (None: no `ros` path given), and the encodings
    of the framework's schemas and messages (None: the framework's own)."""

    framework: str
    title: str
    type: str
    paths: tuple[str | None, ...]
    schema_encoding: str | None = None
    message_encoding: str | None = None


@dataclass(frozen=True, slots=True)
class Adapter:
    name: str
    fields: tuple[AdapterField, ...]
    ros: str | None = None  # the `ros` shorthand as written; what it is in each framework: `frameworks`
    standard: bool = False  # declared in stdlib/adapters.rdis
    doc: str | None = None
    span: Span | None = _span
    frameworks: tuple[FrameworkMapping, ...] = ()  # in the table's order of frameworks

    def field(self, name: str) -> AdapterField | None:
        return next((f for f in self.fields if f.name == name), None)

    def mapping(self, framework: str) -> FrameworkMapping | None:
        """What the adapter is in `framework` (`ros1`, `ros2`, `foxglove`), or None: nothing."""
        return next((f for f in self.frameworks if f.framework == framework), None)


@dataclass(frozen=True, slots=True)
class DomainInput:
    name: str
    adapter: AdapterRef
    interface: InterfaceRef
    args: tuple[Expr, ...]
    doc: str | None = None
    span: Span | None = _span


Rows = tuple[tuple[float, ...], ...]
"""A matrix as its rows."""


@dataclass(frozen=True, slots=True)
class Noise:
    """A field's error model (thesis §7.2.3): its covariance, a deviation's square when it was
    written as one (`deviation`, in `unit`)."""

    field: str
    covariance: Rows
    deviation: float | None = None
    unit: str | None = None
    span: Span | None = _span
    others: tuple[str, ...] = ()  # the fields after `field` one covariance spans (`noise (x, y) [...]`)

    @property
    def fields(self) -> tuple[str, ...]:
        """The fields the covariance is over, in its order."""
        return (self.field, *self.others)


@dataclass(frozen=True, slots=True)
class Kalman:
    """A field published as a linear Kalman filter's estimate (H x): the filter's start state and
    covariance, its transition and process noise, its measurement and measurement noise."""

    field: str
    state: tuple[float, ...]
    covariance: Rows
    transition: Rows
    process: Rows
    measurement: Rows
    noise: Rows
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class DomainOutput:
    name: str
    adapter: AdapterRef
    fields: tuple[tuple[str, Expr], ...]  # in the adapter's field order
    doc: str | None = None
    span: Span | None = _span
    frame: str | None = None  # the link its data belongs to, as written (`Model.frame_id` when not)
    noise: tuple[Noise, ...] = ()  # its fields' error models, as written
    filters: tuple[Kalman, ...] = ()


# ---- the body (thesis ch. 6) -------------------------------------------------------

Vector = tuple[float, float, float]
ORIGIN: Vector = (0.0, 0.0, 0.0)


Written = tuple[tuple[str, Expr], ...]
"""A body element's clauses that read settings, by their word (`at`, `size`, `mass`, `limit`, ...): each
as written, typed (a list of separate values, a shape's sizes or a joint's limits, an array of them).
The element's numbers are at the settings' values; these let canonical JSON carry what they follow."""


@dataclass(frozen=True, slots=True)
class Pose:
    """A frame relative to its parent's: a translation (m), then roll, pitch, yaw (rad) about
    the parent's fixed x, y, z axes, as URDF's `origin`."""

    xyz: Vector = ORIGIN
    rpy: Vector = ORIGIN

    def is_identity(self) -> bool:
        return self.xyz == ORIGIN and self.rpy == ORIGIN


class ShapeKind(enum.Enum):
    BOX = "box"  # size: x, y, z (full lengths, m)
    CYLINDER = "cylinder"  # size: radius, length (along its z axis, m)
    SPHERE = "sphere"  # size: radius (m)
    MESH = "mesh"  # size: scale x, y, z; path: the mesh file, as written


@dataclass(frozen=True, slots=True)
class Shape:
    """A visual or collision shape placed in its link's frame."""

    kind: ShapeKind
    size: tuple[float, ...]
    origin: Pose = Pose()
    path: str | None = None
    span: Span | None = _span
    color: tuple[float, float, float, float] | None = None  # red, green, blue, alpha: each 0 to 1
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)


@dataclass(frozen=True, slots=True)
class Inertial:
    """Mass (kg) at `centre` (m, in the link's frame), and the inertia tensor about the centre,
    in the link's axes (kg m²): ixx, iyy, izz, ixy, ixz, iyz."""

    mass: float
    centre: Vector
    inertia: tuple[float, float, float, float, float, float]
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)


@dataclass(frozen=True, slots=True)
class Link:
    name: str
    visuals: tuple[Shape, ...] = ()
    collisions: tuple[Shape, ...] = ()
    inertial: Inertial | None = None
    doc: str | None = None
    span: Span | None = _span
    spawn: Spawn | None = None  # the root link's: how and where it meets the world


def world_joint(root: str) -> str:
    """The fixed joint the URDF and SDF add between the world and a root link spawned `fixed`."""
    return f"world_to_{root}"


@dataclass(frozen=True, slots=True)
class Spawn:
    """The root link `floating` (free on the floor: a mobile base) or `fixed` to the world (an arm
    bolted down), its frame at `pose` in the world's when the simulation starts."""

    floating: bool
    pose: Pose = Pose()
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)


class JointKind(enum.Enum):
    FIXED = "fixed"
    REVOLUTE = "revolute"  # about `axis`, within `limit` (rad)
    CONTINUOUS = "continuous"  # about `axis`, without a position limit
    PRISMATIC = "prismatic"  # along `axis`, within `limit` (m)


@dataclass(frozen=True, slots=True)
class Mimic:
    """A joint that follows another: its position is `multiplier` times `joint`'s, plus `offset`
    (URDF's `<mimic>`, MuJoCo's joint equality)."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True, slots=True)
class Joint:
    """`child`'s frame is `origin` in `parent`'s, then moved about or along the unit `axis`."""

    name: str
    kind: JointKind
    parent: str
    child: str
    origin: Pose = Pose()
    axis: Vector = (1.0, 0.0, 0.0)
    lower: float | None = None  # the position limit (revolute, prismatic)
    upper: float | None = None
    velocity: float | None = None  # the largest speed (rad/s, m/s)
    effort: float | None = None  # the largest torque (N m) or force (N)
    damping: float = 0.0
    friction: float = 0.0
    doc: str | None = None
    span: Span | None = _span
    mimic: Mimic | None = None  # another joint this one follows
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)

    def moves(self) -> bool:
        return self.kind is not JointKind.FIXED


class Quantity(enum.Enum):
    POSITION = "position"  # rad or m
    VELOCITY = "velocity"  # rad/s or m/s
    EFFORT = "effort"  # N m or N


@dataclass(frozen=True, slots=True)
class Binding:
    """A joint quantity and a device value, converted both ways. A command drives a parameter
    of a primitive or interface (`target.parameter[index]`); a measure reads a state variable
    (`target[index]`). `to_device` reads the quantity by its name (`position`, ...) and gives the
    device's value; `to_joint` reads that value as `raw` and gives the quantity back."""

    quantity: Quantity
    target: str
    parameter: str | None
    index: int | None
    to_device: Expr
    to_joint: Expr
    interface: bool = False  # the target is an interface, not a primitive
    span: Span | None = _span
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)

    def place(self) -> str:
        where = self.target if self.parameter is None else f"{self.target}.{self.parameter}"
        return where if self.index is None else f"{where}[{self.index}]"


@dataclass(frozen=True, slots=True)
class Transmission:
    """How the device moves and senses one joint."""

    name: str
    joint: str
    commands: tuple[Binding, ...] = ()
    measures: tuple[Binding, ...] = ()
    doc: str | None = None
    span: Span | None = _span
    actuator: str | None = None  # the actuator between its command and the joint


class ActuatorKind(enum.Enum):
    SERVO = "servo"  # a position servo: the command is a position it moves to
    WHEEL = "wheel"  # a velocity-controlled motor: the command is a speed it holds


@dataclass(frozen=True, slots=True)
class Actuator:
    """What drives a joint (thesis §7.2.6): its limits, which shape (or, `refuse`, refuse) the commands
    a joint is given (a position moves at most `velocity`, a speed changes by at most `acceleration` a second), and
    the gains the simulation gives it (`gain` N m/rad, `damping` N m s/rad; None: derived)."""

    name: str
    kind: ActuatorKind
    velocity: float | None = None  # rad/s (m/s)
    acceleration: float | None = None  # rad/s² (m/s²)
    effort: float | None = None  # N m (N)
    gain: float | None = None
    damping: float | None = None
    doc: str | None = None
    span: Span | None = _span
    refuse: bool = False  # `limit refuse`: a command beyond a limit is refused, not shaped (`limit shape`)
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)


@dataclass(frozen=True, slots=True)
class Model:
    robot: Robot
    states: dict[str, StateVariable]
    connections: dict[str, Connection]
    primitives: dict[str, Primitive]
    interfaces: dict[str, Interface]
    adapters: dict[str, Adapter]
    inputs: dict[str, DomainInput]
    outputs: dict[str, DomainOutput]
    frames: dict[str, Frame] = field(default_factory=dict)
    constants: dict[str, Value] = field(default_factory=dict)
    enums: dict[str, dict[str, int]] = field(default_factory=dict)
    tables: dict[str, Table] = field(default_factory=dict)
    # The doc comments of constants and enums, by name: their values are plain, with no place for one.
    constant_docs: dict[str, str] = field(default_factory=dict)
    enum_docs: dict[str, str] = field(default_factory=dict)
    settings: dict[str, Setting] = field(default_factory=dict)
    links: dict[str, Link] = field(default_factory=dict)
    joints: dict[str, Joint] = field(default_factory=dict)  # parents before children
    transmissions: dict[str, Transmission] = field(default_factory=dict)
    sensors: dict[str, Sensor] = field(default_factory=dict)
    actuators: dict[str, Actuator] = field(default_factory=dict)

    def root_link(self) -> Link | None:
        """The link no joint moves: the checker allows exactly one when there are links."""
        children = {j.child for j in self.joints.values()}
        return next((link for link in self.links.values() if link.name not in children), None)

    def frame_id(self, output: DomainOutput) -> str:
        """The frame a framework's stamped message of `output` names (ROS's `header.frame_id`):
        its `frame` link, else the body's base, else "" (no body: no frame to name). Every
        emitter asks here."""
        if output.frame is not None:
            return output.frame
        root = self.root_link()
        return "" if root is None else root.name

    def owner(self, iface: Interface) -> str | None:
        """The connection whose thread runs a periodic interface: its first primitive's."""
        first = self._first_primitive(iface, set())
        if first is not None:
            return self.primitives[first].connection
        return next(iter(self.connections), None)

    def _first_primitive(self, iface: Interface, seen: set[str]) -> PrimitiveRef | None:
        """The primitive an interface calls first, through the interfaces it calls, each looked
        into once (one that led to no primitive leads to none again: loops repeat calls)."""
        seen.add(iface.name)
        for call in iface.run_order():
            if not call.interface:
                return call.primitive
            if call.primitive not in seen:
                found = self._first_primitive(self.interfaces[call.primitive], seen)
                if found is not None:
                    return found
        return None

    def callees_first(self) -> list[Interface]:
        """The interfaces, each after the interfaces it calls (the checker keeps the calls
        between interfaces acyclic), else as declared."""
        ordered: dict[str, Interface] = {}

        def place(iface: Interface) -> None:
            if iface.name in ordered:
                return
            for call in iface.calls:
                if call.interface:
                    place(self.interfaces[call.primitive])
            ordered[iface.name] = iface

        for iface in self.interfaces.values():
            place(iface)
        return list(ordered.values())

