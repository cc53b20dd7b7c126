"""The Model's values and typed expressions: references, types, parameters and expression nodes."""

from __future__ import annotations

import enum
from collections.abc import Iterator

from rdisc import TYPE_CHECKING
from rdisc.source import Span

if TYPE_CHECKING:
    from dataclasses import dataclass, field
    from typing import Any, NewType
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.model_expressions_methods import dataclass, field

from rdisc.frozen import Frozen

_span = field(compare=False, repr=False, default=None)


if TYPE_CHECKING:
    ConnectionRef = NewType("ConnectionRef", str)
    PrimitiveRef = NewType("PrimitiveRef", str)
    InterfaceRef = NewType("InterfaceRef", str)
    OutputRef = NewType("OutputRef", str)
    AdapterRef = NewType("AdapterRef", str)
    StateRef = NewType("StateRef", str)
    FrameRef = NewType("FrameRef", str)
else:  # what a NewType's call gives back: the name itself (without importing typing)
    ConnectionRef = PrimitiveRef = InterfaceRef = OutputRef = AdapterRef = StateRef = FrameRef = str


class Type(enum.Enum):
    INT = "int"
    FLOAT = "float"
    BOOL = "bool"
    STRING = "string"
    BYTES = "bytes"  # parameters and replies only: variable-length binary data

    # Hashed as any object, by identity, where Enum's hash is a Python call that hashes the name:
    # types are the keys of the checker's tables, and a member is equal only to itself either way.
    __hash__ = object.__hash__

    def default(self) -> Value:
        """The value `""` stands for in thesis JSON (section 4.3.3)."""
        return _DEFAULTS[self]


@dataclass(frozen=True, slots=True)
class Array(metaclass=Frozen):
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


_DEFAULTS: dict[Type, Value] = {Type.INT: 0, Type.FLOAT: 0.0, Type.BOOL: False, Type.STRING: "", Type.BYTES: b""}
AnyType = Type | Array
Value = int | float | bool | str | bytes | tuple["Any", ...]  # an array's value is a tuple of its elements


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

    __hash__ = object.__hash__  # as Type's


@dataclass(frozen=True, slots=True)
class Const(metaclass=Frozen):
    value: Value
    type: AnyType
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Var(metaclass=Frozen):
    name: str
    scope: Scope
    type: AnyType
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class ReplyValue(metaclass=Frozen):
    """`out[index]`: one value of the primitive's reply."""

    index: int
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class UnaryOp(metaclass=Frozen):
    op: str  # "-", "+", "~", "not"
    operand: Expr
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class BinaryOp(metaclass=Frozen):
    op: str
    left: Expr
    right: Expr
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class IfElse(metaclass=Frozen):
    cond: Expr
    then: Expr
    orelse: Expr
    type: AnyType
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class FuncCall(metaclass=Frozen):
    func: str  # one of rdisc.engine.operations.FUNCTIONS
    args: tuple[Expr, ...]
    type: AnyType
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Table(metaclass=Frozen):
    """A lookup table constant: its keys (ints or strings) and values, each of one type."""

    name: str
    key_type: Type
    value_type: Type
    entries: tuple[tuple[Value, Value], ...]
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class Lookup(metaclass=Frozen):
    """`TABLE[key]`: the value a lookup table holds for the key; a key it lacks is an error,
    unless a `default` is given (`TABLE.get(key, default)`)."""

    table: str
    entries: tuple[tuple[Value, Value], ...]
    key: Expr
    type: Type
    span: Span | None = _span
    default: Expr | None = None


@dataclass(frozen=True, slots=True)
class InTable(metaclass=Frozen):
    """`key in TABLE`: whether a lookup table has an entry for the key."""

    table: str
    keys: tuple[Value, ...]
    key: Expr
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class ArrayValue(metaclass=Frozen):
    """`[a, b, c]`: an array of the items' values."""

    items: tuple[Expr, ...]
    type: Array
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Element(metaclass=Frozen):
    """`array[index]`: one element; an index outside the array is an error, never wrapped."""

    array: Expr
    index: Expr
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Replaced(metaclass=Frozen):
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


# ---- parameters ------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Parameter(metaclass=Frozen):
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
