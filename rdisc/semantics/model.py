"""The Model: the checked, resolved, typed description that every emitter and the
runtime consume. Built only after checking succeeded, so every reference in it
names an element that exists (references are typed keys into per-kind maps).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import NewType

from rdisc.source import Span

_span = field(compare=False, repr=False, default=None)

ConnectionRef = NewType("ConnectionRef", str)
PrimitiveRef = NewType("PrimitiveRef", str)
InterfaceRef = NewType("InterfaceRef", str)
OutputRef = NewType("OutputRef", str)
AdapterRef = NewType("AdapterRef", str)
StateRef = NewType("StateRef", str)


class Type(enum.Enum):
    INT = "int"
    FLOAT = "float"
    BOOL = "bool"
    STRING = "string"

    def default(self) -> Value:
        """The value `""` stands for in thesis JSON (section 4.3.3)."""
        return {Type.INT: 0, Type.FLOAT: 0.0, Type.BOOL: False, Type.STRING: ""}[self]


Value = int | float | bool | str


# ---- typed expressions ----------------------------------------------------------


class Scope(enum.Enum):
    """Where a name read by an expression lives."""

    STATE = "state"
    PARAM = "param"
    FIELD = "field"


@dataclass(frozen=True, slots=True)
class Const:
    value: Value
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Var:
    name: str
    scope: Scope
    type: Type
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
    type: Type
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class FuncCall:
    func: str  # one of rdisc.semantics.operators.FUNCTIONS
    args: tuple[Expr, ...]
    type: Type
    span: Span | None = _span


Expr = Const | Var | ReplyValue | UnaryOp | BinaryOp | IfElse | FuncCall


# ---- elements --------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Parameter:
    name: str
    type: Type


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
    type: Type
    initial: Value
    doc: str | None = None
    span: Span | None = _span


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

    def terminator_bytes(self) -> bytes:
        return self.terminator.encode("latin-1")


@dataclass(frozen=True, slots=True)
class Pack:
    """Raw-encoded request: a struct format."""

    format: str


@dataclass(frozen=True, slots=True)
class Format:
    """ASCII request: a PEP 3101 format with positional fields."""

    template: str


@dataclass(frozen=True, slots=True)
class Unpack:
    """Fixed-width raw reply: a struct format."""

    format: str


@dataclass(frozen=True, slots=True)
class Regex:
    """ASCII reply line, matched by a regular expression; groups are the values."""

    pattern: str


@dataclass(frozen=True, slots=True)
class PostAction:
    target: StateRef
    value: Expr
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Primitive:
    name: str
    params: tuple[Parameter, ...]
    connection: ConnectionRef
    encoding: Pack | Format
    args: tuple[Expr, ...]
    decoding: Unpack | Regex | None = None
    actions: tuple[PostAction, ...] = ()
    doc: str | None = None
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class PrimitiveCall:
    primitive: PrimitiveRef
    args: tuple[Expr, ...]
    delay_ms: float = 0
    priority: int = 0
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Interface:
    name: str
    params: tuple[Parameter, ...]
    periodic: bool
    calls: tuple[PrimitiveCall, ...]  # as written
    triggers: OutputRef | None = None
    doc: str | None = None
    span: Span | None = _span

    def run_order(self) -> tuple[PrimitiveCall, ...]:
        """Calls by priority, then as written (a stable sort)."""
        return tuple(sorted(self.calls, key=lambda c: c.priority))


@dataclass(frozen=True, slots=True)
class AdapterField:
    name: str
    type: Type
    unit: str | None = None
    ros: str | None = None
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class Adapter:
    name: str
    fields: tuple[AdapterField, ...]
    ros: str | None = None
    standard: bool = False  # declared in stdlib/adapters.rdis
    doc: str | None = None
    span: Span | None = _span

    def field(self, name: str) -> AdapterField | None:
        return next((f for f in self.fields if f.name == name), None)


@dataclass(frozen=True, slots=True)
class DomainInput:
    name: str
    adapter: AdapterRef
    interface: InterfaceRef
    args: tuple[Expr, ...]
    doc: str | None = None
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class DomainOutput:
    name: str
    adapter: AdapterRef
    fields: tuple[tuple[str, Expr], ...]  # in the adapter's field order
    doc: str | None = None
    span: Span | None = _span


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
