"""The syntax tree of a `frame` declaration: the bytes around a payload (rdisc.syntax.ast)."""

from __future__ import annotations

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.syntax.ast_frames_methods import dataclass, field

from rdisc.frozen import Frozen
from rdisc.source import Span
from rdisc.syntax.ast_expressions import (
    Expr,
    Ident,
    Param,
    StrLit,
)

_span: Span = field(compare=False, repr=False, default=None)  # type: ignore[assignment]


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
