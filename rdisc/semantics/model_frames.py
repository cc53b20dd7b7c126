"""The Model's frames and reply shapes: the bytes around a payload and the ways a reply is read."""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.semantics.model_expressions import Array, Expr, FrameRef, Parameter
from rdisc.semantics.model_layouts import PostAction, Regex, StructLayout, Unpack
from rdisc.source import Span

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.model_frames_methods import dataclass, field

from rdisc.frozen import Frozen

_span = field(compare=False, repr=False, default=None)


# ---- frames: the bytes around a payload ---------------------------------------------


@dataclass(frozen=True, slots=True)
class ChecksumAlgorithm(metaclass=Frozen):
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
class FrameBytes(metaclass=Frozen):
    """Constant bytes (latin-1 text): the header, a literal between parts, or the terminator."""

    role: str  # "header" | "literal" | "terminator"
    data: str


@dataclass(frozen=True, slots=True)
class FrameField(metaclass=Frozen):
    """A value computed from the frame's parameters, in a one-integer struct format.
    In a reply it is read and must equal the value the request was framed with."""

    name: str
    format: str
    value: Expr
    layout: StructLayout = field(compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class FrameLength(metaclass=Frozen):
    """The payload's size plus `adjust`, in a one-integer struct format."""

    format: str
    adjust: int
    layout: StructLayout = field(compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class FramePayload(metaclass=Frozen):
    """Where the primitive's own bytes go; `trimmed`: without their trailing zero bytes (a first
    byte kept), which a reader puts back up to the size its decoding takes (MAVLink 2)."""

    trimmed: bool = False


@dataclass(frozen=True, slots=True)
class FrameSeed(metaclass=Frozen):
    """`seed TABLE[FIELD]`: the byte the lookup table holds for the value of the field (the part
    `part` of the checksum's side), summed after the bytes covered and never sent (MAVLink 2's
    CRC_EXTRA); `entries`, the table's (key, byte) pairs."""

    table: str
    field: str
    part: int
    entries: tuple[tuple[int, int], ...]


@dataclass(frozen=True, slots=True)
class FrameChecksum(metaclass=Frozen):
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
class FrameOptional(metaclass=Frozen):
    """The `count` parts after it, which a reply may lack, all together: they are there when
    their first bytes (constant) are. A request writes them."""

    count: int


@dataclass(frozen=True, slots=True)
class BitField(metaclass=Frozen):
    """`width` bits of a `FrameBits`: a field's value over the frame's parameters (in a reply
    read and checked like a `FrameField`), or, `value` None, the payload's size plus `adjust`."""

    name: str  # "length" for the length
    width: int
    value: Expr | None = None
    adjust: int = 0


@dataclass(frozen=True, slots=True)
class FrameBits(metaclass=Frozen):
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
class Escaping(metaclass=Frozen):
    """Escaping between a frame's flags (SLIP, HDLC, PPP): each byte of `table` is sent as
    `escape` and its code (one character up to \\xff each), so no flag comes between them."""

    escape: str
    table: tuple[tuple[str, str], ...]  # (byte, code)


@dataclass(frozen=True, slots=True)
class Frame(metaclass=Frozen):
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
class FrameUse(metaclass=Frozen):
    frame: FrameRef
    args: tuple[Expr, ...]  # over the primitive's parameters


@dataclass(frozen=True, slots=True)
class ReplyCase(metaclass=Frozen):
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
class ListedReply(metaclass=Frozen):
    """One reply of `replies { ... }`, read in its place among the others: through its own
    frame (None: the primitive's), decoded, held by its own `expect`, then its post-actions."""

    decoding: Unpack | Regex
    frame: FrameUse | None = None
    expect: Expr | None = None
    actions: tuple[PostAction, ...] = ()


@dataclass(frozen=True, slots=True)
class RepliesEach(metaclass=Frozen):
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
class ErrorReply(metaclass=Frozen):
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
class ReplyTable(metaclass=Frozen):
    key: str  # the parameter whose value chooses the reply ("" when a tag does)
    cases: tuple[ReplyCase, ...]
    tag: str | None = None  # a one-integer struct format: the tag starting the payload chooses
    each: bool = False  # the payload is sub-payloads, each tagged and decoded by its entry, until it ends
    length: str | None = None  # each sub-payload's length field after its tag (`each`): an unknown tag is skipped
    tag_layout: StructLayout | None = field(default=None, compare=False, repr=False)  # of `tag`
    length_layout: StructLayout | None = field(default=None, compare=False, repr=False)  # of `length`
