"""The syntax tree's names, expressions and the pieces declarations share (rdisc.syntax.ast)."""

from __future__ import annotations

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.syntax.ast_expressions_methods import dataclass, field

from rdisc.frozen import Frozen
from rdisc.source import Span

_span: Span = field(compare=False, repr=False, default=None)  # type: ignore[assignment]


@dataclass(frozen=True, slots=True)
class Ident(metaclass=Frozen):
    """A name as written, with its place."""

    text: str
    span: Span = _span


# ---- expressions -----------------------------------------------------------


@dataclass(frozen=True, slots=True)
class IntLit(metaclass=Frozen):
    value: int
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FloatLit(metaclass=Frozen):
    value: float
    span: Span = _span


@dataclass(frozen=True, slots=True)
class StrLit(metaclass=Frozen):
    value: str
    span: Span = _span


@dataclass(frozen=True, slots=True)
class BytesLit(metaclass=Frozen):
    """`b"\\x01\\x02"`: constant bytes, written with ASCII characters and escapes."""

    value: bytes
    span: Span = _span


@dataclass(frozen=True, slots=True)
class BoolLit(metaclass=Frozen):
    value: bool
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Ref(metaclass=Frozen):
    """A name read in an expression: a parameter, field, state variable or `out`."""

    name: str
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Index(metaclass=Frozen):
    """`base[index]`: `out[constant]`, an array's element or a lookup table's entry; `out[1][i]`
    an element of an array that a reply value or a table's entry is."""

    base: Ref | ArrayLit | Index
    index: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class ArrayLit(metaclass=Frozen):
    """`[a, b, c]`: the values of an array, in order."""

    items: tuple[Expr, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Unary(metaclass=Frozen):
    op: str  # "-", "+", "~", "not"
    operand: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class BinOp(metaclass=Frozen):
    op: str  # arithmetic, bitwise, comparison, "and", "or"
    left: Expr
    right: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Conditional(metaclass=Frozen):
    """`then if cond else orelse`."""

    then: Expr
    cond: Expr
    orelse: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class CallExpr(metaclass=Frozen):
    """A call of a built-in function inside an expression."""

    func: Ident
    args: tuple[Expr, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Member(metaclass=Frozen):
    """`Enum.member`: a member of an enumeration."""

    enum: Ident
    member: Ident
    span: Span = _span


@dataclass(frozen=True, slots=True)
class MethodCall(metaclass=Frozen):
    """`TABLE.get(key, default)`: a lookup table's value for a key, or the default."""

    base: Ident
    method: Ident
    args: tuple[Expr, ...]
    span: Span = _span


Expr = (IntLit | FloatLit | StrLit | BytesLit | BoolLit | Ref | Index | ArrayLit | Unary | BinOp | Conditional
        | CallExpr | Member | MethodCall)


# ---- pieces shared by declarations ------------------------------------------


@dataclass(frozen=True, slots=True)
class ArrayOf(metaclass=Frozen):
    """`int[6]`: a fixed number of values of one type. The size is a constant expression;
    an adapter's field leaves it out (`float[]`), for the description that uses it to fix."""

    element: Ident
    size: Expr | None
    span: Span = _span


TypeRef = Ident | ArrayOf


@dataclass(frozen=True, slots=True)
class Param(metaclass=Frozen):
    name: Ident
    type: TypeRef
    span: Span = _span
    low: Expr | None = None  # `in low..high`
    high: Expr | None = None
    default: Expr | None = None  # `= value`: the value when a call leaves it out
    unit: StrLit | None = None  # `unit "mm/s"`


@dataclass(frozen=True, slots=True)
class Call(metaclass=Frozen):
    """A call of a declared element: `name(args)` in a hook, interface body or input."""

    target: Ident
    args: tuple[Expr, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Duration(metaclass=Frozen):
    """`value ms` or `value s`."""

    value: Expr
    unit: str  # "ms" | "s"
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Assign(metaclass=Frozen):
    target: Ident
    value: Expr
    span: Span = _span
    index: Expr | None = None  # `target[index] = value`: one element of an array
    when: Expr | None = None  # `target = value when COND`: a post-action made only if COND holds
