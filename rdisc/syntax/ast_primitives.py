"""The syntax tree of a `primitive` declaration and its clauses (rdisc.syntax.ast)."""

from __future__ import annotations

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.syntax.ast_primitives_methods import dataclass, field

from rdisc.frozen import Frozen
from rdisc.source import Span
from rdisc.syntax.ast_expressions import (
    Assign,
    Duration,
    Expr,
    Ident,
    Param,
    StrLit,
)

_span: Span = field(compare=False, repr=False, default=None)  # type: ignore[assignment]


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
