"""Syntax tree of an RDIS description: what was written, not yet what it means.

Every node carries the span it came from. Spans are excluded from equality so
that round-trip tests (print, parse again) compare structure only. Clauses are
kept as written, repeats included: the checker reports what is missing or doubled.

This module is the syntax tree's one namespace (`ast.PrimitiveDecl`, as its readers write it): it
declares the declarations that stand alone and the Module, and re-exports the nodes of the
modules that declare the rest, each with one concern: names, expressions and the pieces
declarations share (`ast_expressions`), a primitive and its clauses (`ast_primitives`), frames
(`ast_frames`) and the body (`ast_body`).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.syntax.ast_methods import dataclass, field

from rdisc.frozen import Frozen
from rdisc.source import Span
from rdisc.syntax.ast_body import (
    ActuatorDecl,
    Binding,
    BodyValue,
    JointDecl,
    JointLimit,
    JointMimic,
    LinkDecl,
    LinkSpawn,
    Shape,
    ShapeUse,
    TransmissionDecl,
)
from rdisc.syntax.ast_expressions import (
    ArrayLit,
    ArrayOf,
    Assign,
    BinOp,
    BoolLit,
    BytesLit,
    Call,
    CallExpr,
    Conditional,
    Duration,
    Expr,
    FloatLit,
    Ident,
    Index,
    IntLit,
    Member,
    MethodCall,
    Param,
    Ref,
    StrLit,
    TypeRef,
    Unary,
)
from rdisc.syntax.ast_frames import (
    ChecksumOption,
    FrameBitField,
    FrameBits,
    FrameBytes,
    FrameChecksum,
    FrameDecl,
    FrameEither,
    FrameEscape,
    FrameField,
    FrameLength,
    FrameOptional,
    FramePart,
    FramePayload,
    FrameSide,
    FrameStuff,
)
from rdisc.syntax.ast_primitives import (
    Actions,
    Decoding,
    Encoding,
    ErrorReply,
    Expect,
    Framed,
    LineBreak,
    Lines,
    ListedReply,
    On,
    PrimitiveClause,
    PrimitiveDecl,
    Records,
    Replies,
    ReplyEntry,
    ReplyList,
    ReplyTable,
    ReplyTimeout,
    Retry,
    SkipUnmatched,
)

__all__ = [
    "Actions",
    "ActuatorDecl",
    "AdapterDecl",
    "Address",
    "ArrayLit",
    "ArrayOf",
    "Assign",
    "Baud",
    "BinOp",
    "Binding",
    "BodyStmt",
    "BodyValue",
    "BoolLit",
    "BytesLit",
    "Call",
    "CallExpr",
    "CallStmt",
    "ChecksumOption",
    "Conditional",
    "ConnectionAttr",
    "ConnectionDecl",
    "ConstDecl",
    "Damaged",
    "DataBits",
    "Decl",
    "Decoding",
    "Duration",
    "Encoding",
    "EnumDecl",
    "EnumMember",
    "ErrorReply",
    "Expect",
    "Expr",
    "FieldDecl",
    "FieldFilter",
    "FieldNoise",
    "FloatLit",
    "ForStmt",
    "FrameBitField",
    "FrameBits",
    "FrameBytes",
    "FrameChecksum",
    "FrameDecl",
    "FrameEither",
    "FrameEscape",
    "FrameField",
    "FrameLength",
    "FrameOptional",
    "FramePart",
    "FramePayload",
    "FrameSide",
    "FrameStuff",
    "Framed",
    "Hook",
    "Ident",
    "ImportDecl",
    "Index",
    "InputDecl",
    "IntLit",
    "InterfaceClause",
    "InterfaceDecl",
    "JointDecl",
    "JointLimit",
    "JointMimic",
    "Kind",
    "LineBreak",
    "Lines",
    "LinkDecl",
    "LinkSpawn",
    "ListedReply",
    "Member",
    "MethodCall",
    "Module",
    "NumberRows",
    "On",
    "OutputDecl",
    "Param",
    "Parity",
    "Poll",
    "PrimitiveClause",
    "PrimitiveDecl",
    "Records",
    "Ref",
    "Replies",
    "ReplyEntry",
    "ReplyList",
    "ReplyTable",
    "ReplyTimeout",
    "Retry",
    "RobotAttr",
    "RobotDecl",
    "SensorDecl",
    "SettingDecl",
    "Shape",
    "ShapeUse",
    "SkipUnmatched",
    "StateDecl",
    "StopBits",
    "StrLit",
    "TableLit",
    "Terminator",
    "Threading",
    "TransmissionDecl",
    "Triggers",
    "TypeRef",
    "Unary",
]

_span: Span = field(compare=False, repr=False, default=None)  # type: ignore[assignment]



# ---- declarations -------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class ImportDecl(metaclass=Frozen):
    path: str
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class RobotAttr(metaclass=Frozen):
    key: str  # "author" | "description" | "version"
    value: str
    span: Span = _span


@dataclass(frozen=True, slots=True)
class RobotDecl(metaclass=Frozen):
    name: Ident
    attrs: tuple[RobotAttr, ...]
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class StateDecl(metaclass=Frozen):
    name: Ident
    type: TypeRef
    init: Expr | None
    span: Span = _span
    doc: str | None = None
    noise: FieldNoise | None = None  # `noise 0.01 "m"`: the error of the values a device reports into it


@dataclass(frozen=True, slots=True)
class SensorDecl(metaclass=Frozen):
    """`sensor NAME: TYPE from PRIMITIVE() cache DURATION`: the primitive's reply value, kept
    for the cache time (thesis §7.2.4)."""

    name: Ident
    type: TypeRef
    primitive: Ident
    cache: Duration
    span: Span = _span
    doc: str | None = None
    noise: FieldNoise | None = None  # `noise 0.01 "m"`: the error of the value it reads


@dataclass(frozen=True, slots=True)
class SettingDecl(metaclass=Frozen):
    """`setting NAME: TYPE in LOW..HIGH = DEFAULT`: a value the user gives when connecting."""

    name: Ident
    type: TypeRef
    default: Expr | None
    span: Span = _span
    doc: str | None = None
    low: Expr | None = None
    high: Expr | None = None


@dataclass(frozen=True, slots=True)
class Baud(metaclass=Frozen):
    value: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Threading(metaclass=Frozen):
    model: Ident  # "single"
    frequency: Expr  # Hz
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Hook(metaclass=Frozen):
    event: str  # "startup" | "terminate" | "keepalive"
    call: Call
    every: Duration | None  # keepalive only
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Terminator(metaclass=Frozen):
    """The end of a reply line, for `regex` replies."""

    value: StrLit
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Address(metaclass=Frozen):
    """The port a connection opens when none is given: a device path or a URL."""

    value: StrLit
    span: Span = _span


@dataclass(frozen=True, slots=True)
class DataBits(metaclass=Frozen):
    """A serial line's data bits a character (`databits 7`): 8 unless said."""

    value: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Parity(metaclass=Frozen):
    """A serial line's parity bit (`parity even`): `none` unless said."""

    value: Ident
    span: Span = _span


@dataclass(frozen=True, slots=True)
class StopBits(metaclass=Frozen):
    """A serial line's stop bits a character (`stopbits 2`): 1 unless said."""

    value: Expr
    span: Span = _span


ConnectionAttr = Baud | Threading | Hook | Terminator | Address | DataBits | Parity | StopBits


@dataclass(frozen=True, slots=True)
class ConnectionDecl(metaclass=Frozen):
    name: Ident
    kind: Ident  # "serial"
    attrs: tuple[ConnectionAttr, ...]
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class Kind(metaclass=Frozen):
    word: str  # "periodic" | "adhoc"
    span: Span = _span
    rate: Expr | None = None  # `periodic 10 Hz`: its own rate (Hz), under `threading multiple`


@dataclass(frozen=True, slots=True)
class Triggers(metaclass=Frozen):
    outputs: tuple[Ident, ...]
    span: Span = _span


InterfaceClause = Kind | Triggers


@dataclass(frozen=True, slots=True)
class CallStmt(metaclass=Frozen):
    """One primitive call in an interface body, with its options as written."""

    call: Call
    delays: tuple[Duration, ...]
    priorities: tuple[Expr, ...]
    span: Span = _span
    conditions: tuple[Expr, ...] = ()  # `when COND`: the call is made only when COND holds
    polls: tuple[Poll, ...] = ()  # `until COND every P within T`: made again until COND holds


@dataclass(frozen=True, slots=True)
class Poll(metaclass=Frozen):
    """`until COND every P within T`: the call made again every P until COND holds after it,
    at most T/P more times."""

    condition: Expr
    every: Duration
    within: Duration
    span: Span = _span


@dataclass(frozen=True, slots=True)
class ForStmt(metaclass=Frozen):
    """`for NAME in LOW..HIGH { ... }` or `for NAME in ARRAY { ... }`: the body once per
    value, both ends of a range included; the checker writes the loop out as its calls."""

    var: Ident
    low: Expr  # the array, when there is no `high`
    high: Expr | None
    body: tuple[BodyStmt, ...]
    span: Span = _span


BodyStmt = CallStmt | ForStmt


def call_stmts(body: tuple[BodyStmt, ...]) -> list[CallStmt]:
    """The calls written in a body, those inside loops included, each once."""
    return [c for stmt in body for c in ([stmt] if isinstance(stmt, CallStmt) else call_stmts(stmt.body))]


@dataclass(frozen=True, slots=True)
class InterfaceDecl(metaclass=Frozen):
    name: Ident
    params: tuple[Param, ...]
    clauses: tuple[InterfaceClause, ...]
    body: tuple[BodyStmt, ...]
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class FieldDecl(metaclass=Frozen):
    name: Ident
    type: TypeRef
    unit: str | None
    ros: StrLit | None  # a field path in the adapter's ROS message
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class AdapterDecl(metaclass=Frozen):
    name: Ident
    ros: StrLit | None  # a ROS message type, "package/Message"
    fields: tuple[FieldDecl, ...]
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class InputDecl(metaclass=Frozen):
    name: Ident
    adapter: Ident
    call: Call
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class NumberRows(metaclass=Frozen):
    """`[1, 0; 0, 1]`: constant numbers in rows apart by `;` (a vector is one row)."""

    rows: tuple[tuple[float, ...], ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FieldNoise(metaclass=Frozen):
    """`noise FIELD 0.01 "m"`: a field's standard deviation in a unit, or `noise FIELD [a, b; c, d]`,
    its covariance (error models, thesis §7.2.3); `noise (F, G) [a, b; c, d]` one covariance over
    several number fields, `others` those after the first."""

    field: Ident
    value: float | NumberRows
    unit: StrLit | None
    span: Span = _span
    others: tuple[Ident, ...] = ()


@dataclass(frozen=True, slots=True)
class FieldFilter(metaclass=Frozen):
    """`filter FIELD kalman { state [..] transition [..] ... }`: the field published as a Kalman
    filter's estimate, each matrix under its word."""

    field: Ident
    items: tuple[tuple[Ident, float | NumberRows], ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class OutputDecl(metaclass=Frozen):
    """`output NAME: ADAPTER [frame LINK] { field = expr ... noise ... filter ... }`."""

    name: Ident
    adapter: Ident
    fields: tuple[Assign, ...]
    span: Span = _span
    doc: str | None = None
    frame: Ident | None = None  # the body's link its data belongs to (its base when not given)
    noises: tuple[FieldNoise, ...] = ()  # its fields' error models
    filters: tuple[FieldFilter, ...] = ()  # fields published as a Kalman filter's estimate


@dataclass(frozen=True, slots=True)
class TableLit(metaclass=Frozen):
    """`{key: value, ...}`: a lookup table, read as `NAME[key]`."""

    entries: tuple[tuple[Expr, Expr], ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class ConstDecl(metaclass=Frozen):
    name: Ident
    value: Expr | TableLit
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class EnumMember(metaclass=Frozen):
    name: Ident
    value: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class EnumDecl(metaclass=Frozen):
    name: Ident
    members: tuple[EnumMember, ...]
    span: Span = _span
    doc: str | None = None


Decl = (
    ImportDecl | RobotDecl | StateDecl | SensorDecl | SettingDecl | ConnectionDecl | PrimitiveDecl | InterfaceDecl | AdapterDecl | InputDecl
    | OutputDecl | ConstDecl | EnumDecl | FrameDecl | LinkDecl | JointDecl | TransmissionDecl
    | ActuatorDecl
)


@dataclass(frozen=True, slots=True)
class Damaged(metaclass=Frozen):
    """A declaration lost to a syntax error: its keyword and name, when they could
    be read, so that references to it are not reported again as unknown."""

    keyword: str
    name: Ident


@dataclass(frozen=True, slots=True)
class Module(metaclass=Frozen):
    """One parsed file."""

    path: str
    decls: tuple[Decl, ...]
    damaged: tuple[Damaged, ...] = ()
    refused: bool = False  # refused before parsing (E005): nothing is known of it, so nothing is missing
