"""The plans a description is lowered to (`rdisc.lower`): the engine's plans (Primitive, Call,
Interface, Input, Output, Hook, Connection, Device, Frame, FrameUse) as data, each function the
engine takes a `Code`, and each way of reading a reply one variant of the closed union `Reply`.

A plan's fields after `KW_ONLY` are options, written by keyword when they are not at
their default."""

from __future__ import annotations

import dataclasses
import enum
from collections.abc import Mapping
from dataclasses import KW_ONLY, dataclass, field
from typing import Any

from rdisc import engine
from rdisc.lowering.constructs import Construct
from rdisc.lowering.whole_frame import WholeFrame
from rdisc.semantics import model as m

LOWERED_ONLY = "lowered only"
"""The metadata key of a plan's field that its engine counterpart does not take."""

Item = tuple[str, m.Expr, m.AnyType | None]
"""What a Code returns, one item: its key (a dict's key; in a list, "*" for an array given
element by element, else ""), the expression, the type its value is bound to (None: as it is)."""


class Gives(enum.Enum):
    """What a Code returns."""

    LIST = "list"  # its items' values, in order
    DICT = "dict"  # its items' values by key
    BOOL = "bool"  # its one item's truth


@dataclass(frozen=True, slots=True, eq=False)
class Code:
    """A function of a plan, as data: given `takes` (of "state", "args", "reply", in this
    order), `args` unpacked into `params`, it returns its items as `gives` says."""

    takes: tuple[str, ...]
    gives: Gives
    params: tuple[m.Parameter, ...]
    items: tuple[Item, ...]


_NO_STATE: Mapping[str, m.Value] = {}
_OVER_ARGS = ("state", "args")
_OVER_REPLY = ("state", "args", "reply")


def _values(params: tuple[m.Parameter, ...], exprs: tuple[m.Expr, ...], takes: tuple[str, ...] = _OVER_ARGS) -> Code:
    return Code(takes, Gives.LIST, params, tuple(("", e, None) for e in exprs))


def _condition(takes: tuple[str, ...], params: tuple[m.Parameter, ...], e: m.Expr) -> Code:
    return Code(takes, Gives.BOOL, params, (("", e, None),))


@dataclass(frozen=True, slots=True, eq=False)
class Frame:
    """engine.Frame: its parts each way as constructs, its fields' values a Code over the args."""

    name: str
    request: list[Construct[Any]]
    reply: list[Construct[Any]]
    _: KW_ONLY
    stuffing: Construct[engine.Stuffing] | None = None
    params: tuple[Construct[engine.Param], ...] = ()
    fields: Code | None = None  # takes the args only
    more_requests: list[list[Construct[Any]]] = dataclasses.field(default_factory=list)
    more_replies: list[list[Construct[Any]]] = dataclasses.field(default_factory=list)
    escaping: Construct[engine.Escaping] | None = None
    choose: Code | None = None  # `either when`: each request layout's condition over the args
    answer: Code | None = None  # and each reply layout's


@dataclass(frozen=True, slots=True, eq=False)
class FrameUse:
    """engine.FrameUse: a frame, and its arguments over the primitive's parameters."""

    frame: Frame
    args: Code


@dataclass(frozen=True, slots=True, eq=False)
class Written:
    """A primitive's request in one step, when it is only written (the engine's `Primitive.request`)
    or a plain exchange's (`Primitive.asked`, no frame): its parameters
    each of its own type and in its range, its format values packed with `format`, between the
    frame's constant bytes (its arguments constants, the payload's size fixed): `head`, the
    checksum after the payload (if any) over `covered` (the head's bytes it covers) and the
    payload, then `tail`. Anything else, and the general way decides (and says what is wrong)."""

    params: tuple[m.Parameter, ...]
    values: Code
    format: str
    _: KW_ONLY
    head: bytes = b""
    checksum: Construct[engine.Checksum] | None = None
    check_format: str = ""  # how the checksum is packed
    check_size: int = 0  # the bytes it packs into
    covered: bytes = b""
    partial: int | None = None  # a "sum" checksum: the sum of `covered`, to which the payload's is added
    tail: bytes = b""
    constant: bytes | None = None  # no parameters and constant values: the whole request, always
    whole: WholeFrame | None = None  # head, payload, checksum and tail packed by one struct, where they can be


# ---- the shapes of a reply: the engine's (`rdisc.engine.plans`), a table's entries each with its values

@dataclass(frozen=True, slots=True)
class NoReply:
    """engine.NoReply: nothing is read."""


NO_REPLY = NoReply()


@dataclass(frozen=True, slots=True, eq=False)
class LineReply:
    """engine.LineReply: a line, matched."""

    decoder: Construct[engine.Match]


@dataclass(frozen=True, slots=True, eq=False)
class ErrorReply:
    """engine.ErrorReply: the reply that may come instead, raised with its code's name; or,
    `when`, the reply itself when the condition over it holds."""

    decoder: Construct[engine.Unpack]
    marker: bytes = b""
    frame: FrameUse | None = None
    codes: str = ""
    names: dict[int, str] = dataclasses.field(default_factory=dict)
    when: Code | None = None


@dataclass(frozen=True, slots=True, eq=False)
class FixedReply:
    """engine.FixedReply: the bytes the decoder takes, no frame."""

    decoder: Construct[engine.Unpack]
    _: KW_ONLY
    error: ErrorReply | None = None


@dataclass(frozen=True, slots=True, eq=False)
class FramedReply:
    """engine.FramedReply: a reply frame's payload decoded (or the frame only read)."""

    decoder: Construct[engine.Unpack] | Construct[engine.Match] | None = None
    _: KW_ONLY
    skip: bool = False
    error: ErrorReply | None = None


@dataclass(frozen=True, slots=True, eq=False)
class TaggedReply:
    """engine.TaggedReply: a reply frame's tag, then its entry's bytes."""

    tag: str
    table: tuple[Entry, ...]
    _: KW_ONLY
    skip: bool = False


@dataclass(frozen=True, slots=True, eq=False)
class TaggedStream:
    """engine.TaggedStream: a tag, then its entry's bytes, no frame; after a tag of `nested`, a
    second tag (its struct format) first."""

    tag: str
    table: tuple[Entry, ...]
    _: KW_ONLY
    skip: bool = False
    nested: dict[int, str] = field(default_factory=dict)


@dataclass(frozen=True, slots=True, eq=False)
class SubPayloads:
    """engine.SubPayloads: a reply frame's payload of tagged sub-payloads."""

    tag: str
    table: tuple[Entry, ...]
    length: str | None = None
    _: KW_ONLY
    skip: bool = False


@dataclass(frozen=True, slots=True, eq=False)
class Records:
    """engine.Records: a reply frame's payload of records, each ended by the marker."""

    marker: bytes
    decoder: Construct[engine.Unpack]
    _: KW_ONLY
    skip: bool = False


@dataclass(frozen=True, slots=True, eq=False)
class KeyedReply:
    """engine.KeyedReply: a reply table chosen by the parameter at `key`."""

    key: int
    table: tuple[Entry, ...]


@dataclass(frozen=True, slots=True, eq=False)
class SeveralReplies:
    """engine.SeveralReplies: `replies N`, each reply read as `each`."""

    count: int
    each: Reply
    frames: tuple[FrameUse, ...] = ()
    over: int = -1  # `replies id in ids`: the array parameter's position, a reply for each element


@dataclass(frozen=True, slots=True, eq=False)
class ListedReplies:
    """engine.ListedReplies: `replies { }`, a plan each."""

    answers: tuple[Primitive, ...]


Reply = (NoReply | LineReply | FixedReply | FramedReply | TaggedReply | TaggedStream | SubPayloads | Records
         | KeyedReply | SeveralReplies | ListedReplies)
"""How a primitive's reply is read, decided once here (`_Lowering.read_as`)."""

TABLED = (TaggedReply, TaggedStream, SubPayloads, KeyedReply)
"""The shapes with a reply table."""


@dataclass(frozen=True, slots=True, eq=False)
class Entry:
    """A reply table's entry: the key or tag values it is for, and its plan."""

    case: m.ReplyCase
    plan: Primitive


@dataclass(frozen=True, slots=True, eq=False)
class Primitive:
    """engine.Primitive; `reply`, how its reply is read (a reply table's entries each with the
    values it is for)."""

    name: str
    connection: str
    params: tuple[Construct[engine.Param], ...]
    values: Code
    encoder: Construct[engine.Pack] | Construct[engine.Format] | None
    _: KW_ONLY
    reply: Reply = NO_REPLY
    actions: Code | None = None
    frame: FrameUse | None = None
    timeout: float | None = None
    retries: int = 0
    checked: tuple[str, ...] = ()
    expect: Code | None = None
    lines: Code | None = None
    request: Written | None = None
    looks_up: bool = False
    actuators: tuple[Construct[engine.ActuatorLimit], ...] = ()  # the actuators' limits on its parameters
    # A plain exchange's request in one step (`engine.asked_at_once`): the engine makes its own,
    # and a driver's typed method compiles this one (`LOWERED_ONLY`: no argument of engine.Primitive).
    asked: Written | None = field(default=None, metadata={LOWERED_ONLY: True})


@dataclass(frozen=True, slots=True, eq=False)
class Output:
    """engine.Output."""

    name: str
    fields: Code
    adapter: str = ""
    frame: str = ""
    child_frame: str = ""
    filters: tuple[Construct[engine.FilterPlan], ...] = ()
    sensors: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True, eq=False)
class Call:
    """engine.Call: `direct`, the arguments are the primitive's format values."""

    target: Primitive | Interface
    args: Code
    delay: float = 0.0
    _: KW_ONLY
    direct: bool = False
    when: Code | None = None
    until: Code | None = None
    every: float = 0.0
    within: float = 0.0


@dataclass(frozen=True, slots=True, eq=False)
class Interface:
    """engine.Interface."""

    name: str
    params: tuple[Construct[engine.Param], ...]
    calls: tuple[Call, ...]
    _: KW_ONLY
    outputs: tuple[Output, ...] = ()
    sensors: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True, eq=False)
class Input:
    """engine.Input; `request`: the engine writes it at once, so a driver compiles that."""

    name: str
    adapter: str
    fields: tuple[Construct[engine.Param], ...]
    interface: Interface
    args: Code
    _: KW_ONLY
    request: bool = False
    sensors: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True, eq=False)
class Hook:
    """engine.Hook."""

    interface: Interface
    args: Code  # takes the state only


@dataclass(frozen=True, slots=True, eq=False)
class Connection:
    """engine.Connection."""

    name: str
    baud: int
    _: KW_ONLY
    address: str | None = None
    terminator: bytes = b"\n"
    frequency: float = 0.0
    periodic: tuple[Interface, ...] = ()
    startup: Hook | None = None
    terminate: Hook | None = None
    keepalive: Hook | None = None
    interval: float = 0.0
    baud_setting: str | None = None
    data_bits: int = 8
    parity: str = "none"
    stop_bits: float = 1
    threading: str = "single"
    rates: tuple[float, ...] = ()


@dataclass(frozen=True, slots=True, eq=False)
class Sensor:
    """engine.Sensor: its primitive's plan stores its value (`_Lowering.sensed`)."""

    name: str
    primitive: Primitive
    cache: float


@dataclass(frozen=True, slots=True, eq=False)
class Device:
    """engine.Device."""

    name: str
    state: Mapping[str, m.Value]
    connections: Mapping[str, Connection]
    primitives: Mapping[str, Primitive]
    interfaces: Mapping[str, Interface]
    inputs: Mapping[str, Input]
    _: KW_ONLY
    settings: tuple[Construct[engine.Param], ...] = ()
    messages: Mapping[str, engine.Message] = dataclasses.field(default_factory=dict)
    sensors: Mapping[str, Sensor] = dataclasses.field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class Plans:
    """A description lowered: the device, and the frames and outputs its plans use, by name."""

    device: Device
    frames: Mapping[str, Frame]
    outputs: Mapping[str, Output]
