"""The Model's struct layouts (a format parsed once, by the checker) and what a reply does."""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import field_names
from rdisc.semantics.model_expressions import (
    BinaryOp,
    Const,
    Element,
    Expr,
    FuncCall,
    IfElse,
    Lookup,
    Replaced,
    ReplyValue,
    Scope,
    StateRef,
    Type,
    UnaryOp,
    Var,
)
from rdisc.source import Span

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.model_layouts_methods import dataclass, field

from rdisc.frozen import Frozen

_span = field(compare=False, repr=False, default=None)


# ---- struct layouts: a struct format parsed once, by the checker (rdisc.semantics.formats) -------------


@dataclass(frozen=True, slots=True)
class Slot(metaclass=Frozen):
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
class Varying(metaclass=Frozen):
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
class StructLayout(metaclass=Frozen):
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
class Pack(metaclass=Frozen):
    """Raw-encoded request: a struct format."""

    format: str
    layout: StructLayout = field(compare=False, repr=False)  # the format parsed (derived: not in the JSON)
    grouped: tuple[int, ...] = ()  # the arguments that fill a repeated group's codes, each an array


@dataclass(frozen=True, slots=True)
class Format(metaclass=Frozen):
    """ASCII request: a PEP 3101 format with positional fields."""

    template: str


@dataclass(frozen=True, slots=True)
class Unpack(metaclass=Frozen):
    """Fixed-width raw reply: a struct format. With `until`, an unframed tagged reply's entry
    reads to those bytes (Firmata's sysex, ended by 0xF7) and its `*` rest takes what is before."""

    format: str
    layout: StructLayout = field(compare=False, repr=False)
    until: str | None = None  # latin-1 text, as a connection's terminator


@dataclass(frozen=True, slots=True)
class Regex(metaclass=Frozen):
    """ASCII reply line, matched by a regular expression; groups are the values."""

    pattern: str


@dataclass(frozen=True, slots=True)
class PostAction(metaclass=Frozen):
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
class LineLevel(metaclass=Frozen):
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
