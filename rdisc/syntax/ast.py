"""Syntax tree of an RDIS description: what was written, not yet what it means.

Every node carries the span it came from. Spans are excluded from equality so
that round-trip tests (print, parse again) compare structure only. Clauses are
kept as written, repeats included: the checker reports what is missing or doubled.
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.syntax.ast_methods import dataclass, field

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
class On(metaclass=Frozen):
    connection: Ident
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Encoding(metaclass=Frozen):
    kind: str  # "pack" | "format"
    template: StrLit
    args: tuple[Expr, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Decoding(metaclass=Frozen):
    kind: str  # "unpack" | "regex"
    template: StrLit
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Actions(metaclass=Frozen):
    assigns: tuple[Assign, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Framed(metaclass=Frozen):
    """`frame NAME(args)`: the frame around the primitive's request and reply."""

    frame: Ident
    args: tuple[Expr, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class SkipUnmatched(metaclass=Frozen):
    """`skip unmatched`: frames that do not decode are other traffic, read past."""

    span: Span = _span


@dataclass(frozen=True, slots=True)
class ReplyEntry(metaclass=Frozen):
    """`VALUE: unpack "fmt" { post-actions }`: the reply when the key is VALUE; or
    `LOW..HIGH: ...`: when it is any of them (Firmata's 0xE0..0xEF, a channel in the tag); or
    `VALUE: tag "fmt" { ... }`: a table of its own, chosen by the tag after this one (Firmata's
    sysex sub-commands), then without a decoding of its own."""

    value: Expr
    decoding: Decoding | None
    actions: Actions | None
    span: Span = _span
    last: Expr | None = None  # HIGH of a range entry
    until: StrLit | None = None  # `until "\xF7"`: read to these bytes (an unframed tagged reply's entry)
    table: ReplyTable | None = None  # `tag "fmt" { ... }`: the next tag chooses among its entries


@dataclass(frozen=True, slots=True)
class ReplyTable(metaclass=Frozen):
    """`reply KEY { ... }`: the reply's decoding chosen by a parameter's value; or
    `reply tag "fmt" { ... }`: by the tag at the start of the reply's payload; or
    `reply each tag "fmt" length "fmt" { ... }`: the payload a sequence of sub-payloads, each
    an entry chosen by its own tag (Kobuki's feedback), with or without its own length."""

    key: Ident
    entries: tuple[ReplyEntry, ...]
    span: Span = _span
    tag: StrLit | None = None
    each: bool = False  # `reply each tag`: entries repeat over the payload
    length: StrLit | None = None  # each sub-payload's length field after its tag (`each` only)


@dataclass(frozen=True, slots=True)
class Retry(metaclass=Frozen):
    """`retry N`: the request sent again, up to N more times, after a timeout or a reply that
    does not match (as published drivers resend)."""

    count: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class ReplyTimeout(metaclass=Frozen):
    """`timeout D`: how long this primitive's reply may take, instead of the connection's."""

    duration: Duration
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Replies(metaclass=Frozen):
    """`replies N`: N replies to one request (a sync read's status packets), each read and
    decoded as one reply is; the post-actions read each value of them as an array of N. Or
    `replies id in IDS frame status(id)` (`over` a constant array, or a range `over..high`):
    a reply a value of the variable, each read through its own frame."""

    over: Expr  # N, or what the variable goes over
    span: Span = _span
    var: Ident | None = None
    high: Expr | None = None
    frame: Framed | None = None


@dataclass(frozen=True, slots=True)
class ListedReply(metaclass=Frozen):
    """One reply of `replies { ... }`: `frame status(2) unpack "<BB" expect out[0] == 0 { ... }`,
    its frame (None: the primitive's), decoding, condition and post-actions its own."""

    decoding: Decoding
    span: Span = _span
    frame: Framed | None = None
    expect: Expr | None = None
    actions: Actions | None = None


@dataclass(frozen=True, slots=True)
class ReplyList(metaclass=Frozen):
    """`replies { ... }`: a fixed sequence of replies to one request, each of its own shape (a
    Dynamixel bulk read's status packets, each servo's own data)."""

    replies: tuple[ListedReply, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Expect(metaclass=Frozen):
    """`expect COND`: a condition on the decoded reply (`out`) that a reply must meet."""

    condition: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Records(metaclass=Frozen):
    """`reply each until "\x7F"`: the reply's payload is records, each ended by the marker,
    each decoded by the primitive's `unpack` and its post-actions run for it with `index`
    (Firmata's capability report: a pin's modes, then 7F)."""

    marker: StrLit
    span: Span = _span


@dataclass(frozen=True, slots=True)
class LineBreak(metaclass=Frozen):
    """`break 10 ms` among a primitive's `lines`: a serial break (TX held low) for that long."""

    duration: Duration
    span: Span = _span


@dataclass(frozen=True, slots=True)
class Lines(metaclass=Frozen):
    """`lines dtr = COND, rts = COND, break 10 ms`: the serial port's modem lines, set before the
    request, and a break sent, in the order given."""

    settings: tuple[Assign | LineBreak, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class ErrorReply(metaclass=Frozen):
    """`error frame rtu(UNIT, 0x83) unpack "B" code Exception`: the reply the device may send
    instead (Modbus's exception, a NACK), known by its own frame or its first bytes (`marker`),
    decoded, its first value the device's code, named by an enum (`codes`). `error when COND
    code Status` (no decoding of its own): the reply itself, decoded as ever, is the device's
    error when COND holds (a TMCL status below 100), its first value the code."""

    decoding: Decoding | None
    span: Span = _span
    frame: Framed | None = None
    marker: StrLit | None = None
    codes: Ident | None = None
    when: Expr | None = None


PrimitiveClause = (
    On | Encoding | Decoding | Actions | Framed | SkipUnmatched | ReplyTable | ReplyTimeout | Expect | Lines
    | Replies | Retry | ReplyList | Records | ErrorReply
)


@dataclass(frozen=True, slots=True)
class PrimitiveDecl(metaclass=Frozen):
    name: Ident
    params: tuple[Param, ...]
    clauses: tuple[PrimitiveClause, ...]
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


# ---- frames: the bytes around a payload ----


@dataclass(frozen=True, slots=True)
class FrameBytes(metaclass=Frozen):
    """Constant bytes: `header`, `literal` or `terminator`."""

    role: str  # "header" | "literal" | "terminator"
    value: StrLit
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameField(metaclass=Frozen):
    """`field NAME "fmt" = expr`: a value of the frame's parameters."""

    name: Ident
    format: StrLit
    value: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameLength(metaclass=Frozen):
    """`length "fmt" = payload + N`."""

    format: StrLit
    adjust: int
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FramePayload(metaclass=Frozen):
    """`payload`, or `payload trimmed`: its trailing zero bytes dropped when written and put back
    when read (MAVLink 2's payload truncation)."""

    span: Span = _span
    trimmed: bool = False


@dataclass(frozen=True, slots=True)
class ChecksumOption(metaclass=Frozen):
    """`inverted`, `reflect` (`reflect in`, `reflect out`: one way only), `mask/poly/init/xorout/width EXPR`,
    `over A .. B` or `seed TABLE[FIELD]` (`over` holds the table's name and the field's)."""

    word: str
    value: Expr | None = None
    over: tuple[Ident, ...] = ()
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameChecksum(metaclass=Frozen):
    algorithm: StrLit
    format: StrLit | None  # None: ASCII hex digits
    options: tuple[ChecksumOption, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameOptional(metaclass=Frozen):
    """`optional { ... }`: parts a reply may lack, all together; a request writes them."""

    parts: tuple[FramePart, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameEither(metaclass=Frozen):
    """`either { ... } or { ... }`: alternative runs of parts. A request is written with the
    first whose length field can state its payload; a reply is read by the one whose header came.
    `either when COND { ... } or ... or { ... }`: a request's alternative chosen by a condition over
    the frame's parameters, the first that holds (a plain last one when none does)."""

    alternatives: tuple[tuple[FramePart, ...], ...]
    span: Span = _span
    conditions: tuple[Expr | None, ...] = ()  # one per alternative (None: plain) when any has `when`


@dataclass(frozen=True, slots=True)
class FrameBitField(metaclass=Frozen):
    """`field NAME: WIDTH = expr`, or (no name) `length: WIDTH = payload + N`, in a `bits`."""

    name: Ident | None  # None: the length
    width: int
    value: Expr | None  # None: the length
    adjust: int = 0
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameBits(metaclass=Frozen):
    """`bits "<I" { ... }`: one integer of a struct format, split into fields from its lowest bit up."""

    format: StrLit
    fields: tuple[FrameBitField, ...]
    span: Span = _span


FramePart = (FrameBytes | FrameField | FrameLength | FramePayload | FrameChecksum | FrameOptional | FrameEither
             | FrameBits)


@dataclass(frozen=True, slots=True)
class FrameSide(metaclass=Frozen):
    """`request { ... }` or `reply { ... }`."""

    side: str  # "request" | "reply"
    parts: tuple[FramePart, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameStuff(metaclass=Frozen):
    """`stuff ESCAPE after RESERVED`: byte stuffing of the payloads, both ways."""

    escape: StrLit
    reserved: StrLit
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameEscape(metaclass=Frozen):
    """`escape "\\x7D" xor 0x20 for "\\x7E\\x7D"` (HDLC, PPP) or `escape "\\xDB" { "\\xC0": "\\xDC",
    "\\xDB": "\\xDD" }` (SLIP): each listed byte between the frame's flags sent as ESCAPE and a code,
    its own XOR the mask or the one the table gives."""

    escape: StrLit
    table: tuple[tuple[StrLit, StrLit], ...]  # (byte, code); () in the xor form
    xor: int | None = None  # the xor form's mask, and the bytes it escapes
    escaped: StrLit | None = None
    span: Span = _span


@dataclass(frozen=True, slots=True)
class FrameDecl(metaclass=Frozen):
    name: Ident
    params: tuple[Param, ...]
    items: tuple[FramePart | FrameSide | FrameStuff | FrameEscape, ...]
    span: Span = _span
    doc: str | None = None


# ---- the body (thesis ch. 6) ----------------------------------------------------


@dataclass(frozen=True, slots=True)
class Shape(metaclass=Frozen):
    """`box(x, y, z)`, `cylinder(radius, length)`, `sphere(radius)`, `mesh("file.stl", scale)`."""

    kind: Ident
    args: tuple[Expr, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class ShapeUse(metaclass=Frozen):
    """`visual SHAPE at XYZ rpy RPY color RGBA` or `collision ...`: a shape placed in its link's frame."""

    role: str  # "visual" | "collision"
    shape: Shape
    at: Expr | None
    rpy: Expr | None
    span: Span = _span
    color: Expr | None = None  # a visual's `[r, g, b]` or `[r, g, b, a]`, each 0 to 1


@dataclass(frozen=True, slots=True)
class LinkSpawn(metaclass=Frozen):
    """`spawn floating at XYZ rpy RPY` (or `fixed`): how and where the root link meets the world."""

    kind: Ident
    at: Expr | None
    rpy: Expr | None
    span: Span = _span


@dataclass(frozen=True, slots=True)
class BodyValue(metaclass=Frozen):
    """One `KEY value` clause of a link or joint: `mass 3.6`, `axis [0, 1, 0]`, `at [...]`."""

    key: str
    value: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class JointLimit(metaclass=Frozen):
    """`limit LOW..HIGH`: the joint's position range (rad, or m for a prismatic joint)."""

    low: Expr
    high: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class JointMimic(metaclass=Frozen):
    """`mimic JOINT multiplier M offset O`: this joint's position is M times JOINT's, plus O."""

    joint: Ident
    multiplier: Expr | None
    offset: Expr | None
    span: Span = _span


@dataclass(frozen=True, slots=True)
class LinkDecl(metaclass=Frozen):
    name: Ident
    items: tuple[ShapeUse | BodyValue | LinkSpawn, ...]
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class JointDecl(metaclass=Frozen):
    """`joint NAME: KIND PARENT -> CHILD { ... }`."""

    name: Ident
    kind: Ident
    parent: Ident
    child: Ident
    items: tuple[BodyValue | JointLimit | JointMimic, ...]
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class Binding(metaclass=Frozen):
    """`command QUANTITY to TARGET.PARAM[i] { raw = ...  QUANTITY = ... }` or
    `measure QUANTITY from STATE[i] { ... }`: a joint quantity and a device value, both ways."""

    role: str  # "command" | "measure"
    quantity: Ident
    target: Ident  # a primitive or interface (command), a state variable (measure)
    member: Ident | None  # the parameter commanded
    index: Expr | None  # its element, for an array
    conversions: tuple[Assign, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class TransmissionDecl(metaclass=Frozen):
    """`transmission NAME: JOINT { command ... measure ... }`."""

    name: Ident
    joint: Ident
    bindings: tuple[Binding, ...]
    span: Span = _span
    doc: str | None = None
    actuator: Ident | None = None  # `transmission NAME: JOINT actuator ACTUATOR { ... }`


@dataclass(frozen=True, slots=True)
class ActuatorDecl(metaclass=Frozen):
    """`actuator NAME: KIND { velocity ...  acceleration ...  effort ...  gain ...  damping ... }`."""

    name: Ident
    kind: Ident
    items: tuple[BodyValue, ...]
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
