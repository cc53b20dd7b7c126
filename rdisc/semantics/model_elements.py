"""The Model's elements: robot, states, connections, primitives, interfaces, adapters, inputs, outputs."""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import replace
from rdisc.semantics.model_expressions import (
    AdapterRef,
    AnyType,
    Array,
    ConnectionRef,
    Const,
    Expr,
    InterfaceRef,
    OutputRef,
    Parameter,
    PrimitiveRef,
    Scope,
    Type,
    Value,
    Var,
    spread,
)
from rdisc.semantics.model_frames import (
    INDEX,
    TAG,
    ErrorReply,
    Frame,
    FramePayload,
    FrameUse,
    ListedReply,
    RepliesEach,
    ReplyCase,
    ReplyTable,
)
from rdisc.semantics.model_layouts import Format, LineLevel, Pack, PostAction, Regex, Unpack
from rdisc.source import Span

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.model_elements_methods import dataclass, field

from rdisc.frozen import Frozen

_span = field(compare=False, repr=False, default=None)


# ---- elements --------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Robot(metaclass=Frozen):
    name: str
    author: str | None = None
    description: str | None = None
    version: str | None = None
    doc: str | None = None
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class StateVariable(metaclass=Frozen):
    name: str
    type: AnyType
    initial: Value
    doc: str | None = None
    span: Span | None = _span
    noise: Noise | None = None  # the error of the values a device reports into it (thesis §7.2.3)


@dataclass(frozen=True, slots=True)
class Sensor(metaclass=Frozen):
    """`sensor NAME: TYPE from PRIMITIVE() cache N ms`: the primitive's one reply value, read
    when a reader finds it older than the cache time and kept until then (thesis §7.2.4)."""

    name: str
    type: AnyType
    primitive: PrimitiveRef
    cache_ms: float
    doc: str | None = None
    span: Span | None = _span
    noise: Noise | None = None  # the error of the value it reads (thesis §7.2.3)


@dataclass(frozen=True, slots=True)
class Setting(metaclass=Frozen):
    """A value given when connecting (a baud rate, a servo's ID, a wheel base): read-only,
    read by expressions as state is; `default` when none is given, and what the checks use."""

    name: str
    type: AnyType
    default: Value
    low: int | float | None = None  # the range a given value must be in, when declared
    high: int | float | None = None
    doc: str | None = None
    span: Span | None = _span

    def range_text(self) -> str:
        return f"{self.low!r}..{self.high!r}"


@dataclass(frozen=True, slots=True)
class HookCall(metaclass=Frozen):
    """A connection event calling an interface; arguments see state only."""

    interface: InterfaceRef
    args: tuple[Expr, ...]
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class Keepalive(metaclass=Frozen):
    call: HookCall
    interval_ms: float


@dataclass(frozen=True, slots=True)
class Connection(metaclass=Frozen):
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
    address: str | None = None  # the port opened when none is given (path or URL)
    baud_setting: str | None = None  # the setting that gives the baud rate (`baud` is then its default)
    data_bits: int = 8  # a serial line's character: data bits, parity, stop bits (8N1 unless said)
    parity: str = "none"  # none, even, odd, mark or space
    stop_bits: float = 1  # 1, 1.5 or 2
    threading: str = "single"  # single, dual or multiple (rdisc.engine.schedule)

    def terminator_bytes(self) -> bytes:
        return self.terminator.encode("latin-1")

    def rate_of(self, interface: Interface) -> float:
        """Runs a second of a periodic interface of this connection: its own rate under
        `threading multiple` when it states one, else the connection's frequency."""
        own = interface.rate_hz if self.threading == "multiple" else None
        return own or self.frequency_hz

    def line_text(self) -> str:
        """The serial line's character as it is usually written: `8N1`, `8E2`, `5N1.5`."""
        return f"{self.data_bits}{self.parity[0].upper()}{self.stop_bits:g}"

    def bits_per_byte(self) -> float:
        """A byte's bits on the wire: a start bit, the data bits, a parity bit, the stop bits."""
        return 1 + self.data_bits + (self.parity != "none") + self.stop_bits


@dataclass(frozen=True, slots=True)
class Primitive(metaclass=Frozen):
    name: str
    params: tuple[Parameter, ...]
    connection: ConnectionRef
    encoding: Pack | Format | None  # None: it writes no request, and only sets `lines`
    args: tuple[Expr, ...]
    decoding: Unpack | Regex | None = None
    actions: tuple[PostAction, ...] = ()
    doc: str | None = None
    span: Span | None = _span
    frame: FrameUse | None = None
    skip_unmatched: bool = False  # reads frames until one decodes, within the timeout
    table: ReplyTable | None = None  # the reply chosen by a parameter (then no `decoding`)
    timeout_ms: float | None = None  # how long its reply may take, instead of the robot's timeout
    expect: Expr | None = None  # a condition on the decoded reply that it must meet
    lines: tuple[LineLevel, ...] = ()  # modem lines set before the request, in this order
    replies: int = 0  # `replies N`: N replies to its request, each value of them an array of N (0: one reply)
    reply_frames: tuple[FrameUse, ...] = ()  # each reply's own frame, when `replies` gives them
    records: str | None = None  # `reply each until`: the marker ending each record of the payload (latin-1)
    listed: tuple[ListedReply, ...] = ()  # `replies { ... }`: replies of different shapes, in order
    retries: int = 0  # `retry N`: resends after a timeout or a reply that does not match (0: none)
    error: ErrorReply | None = None  # `error ...`: the exception the device may send instead of its reply
    each: RepliesEach | None = None  # `replies id in ids`: a reply for each element of an array parameter

    def listed_reply(self, r: ListedReply) -> Primitive:
        """This primitive as it is for one of its listed replies: that reply's frame, decoding,
        `expect` and post-actions, as if it were its only one."""
        return replace(self, decoding=r.decoding, frame=r.frame or self.frame, expect=r.expect,
                                   actions=r.actions, listed=())

    def post_actions(self) -> tuple[PostAction, ...]:
        """Every post-action it may run: its own, its table's entries' and its listed replies'."""
        return (*self.actions, *(a for c in (self.table.cases if self.table else ()) for a in c.actions),
                *(a for r in self.listed for a in r.actions))

    def case(self, c: ReplyCase) -> Primitive:
        """This primitive as it is when its table's key (or its reply's tag) has c.value: one decoding."""
        return replace(self, decoding=c.decoding, actions=c.actions, table=None)

    def reply_locals(self) -> tuple[Parameter, ...]:
        """What its post-actions read besides state and `out`: its parameters, and after
        them, when a tag chooses the reply, the tag's value as `tag`, or, when the reply is
        records, the record's position as `index`."""
        if self.records is not None:
            return (*self.params, Parameter(INDEX, Type.INT))
        if self.table is None or self.table.tag is None:
            return self.params
        return (*self.params, Parameter(TAG, Type.INT))

    def formats_its_params(self) -> bool:
        """Whether a call's arguments can be its format values as they are: no post-actions,
        frame, table, modem lines or ranges, and format arguments that are constants and its parameters,
        each once and in order (both planners then skip binding the parameters)."""
        used = [a.name for a in self.args if isinstance(a, Var) and a.scope is Scope.PARAM]
        simple = all(isinstance(a, Const) or (isinstance(a, Var) and a.scope is Scope.PARAM) for a in self.args)
        return (simple and not self.spreads()
                and not (self.actions or self.frame or self.table or self.expect or self.lines)
                and all(p.low is None for p in self.params) and used == [p.name for p in self.params])

    def format_values(self) -> tuple[Expr, ...]:
        """The format's values, one per slot: an array argument as its elements, except in a
        repeated group, which takes it whole."""
        spreads = self.spreads()
        return tuple(v for i, a in enumerate(self.args) for v in (spread((a,)) if i in spreads else (a,)))

    def spreads(self) -> tuple[int, ...]:
        """The format arguments that are arrays outside a repeated group: each gives its elements
        as that many values."""
        grouped = self.encoding.grouped if isinstance(self.encoding, Pack) else ()
        return tuple(i for i, a in enumerate(self.args) if isinstance(a.type, Array) and i not in grouped)

    def expects_reply(self, frames: dict[str, Frame]) -> bool:
        """A reply is read when there is one to decode, or when the frame's reply
        is an acknowledgement (constant parts only, no payload)."""
        if self.decoding is not None or self.table is not None or self.listed:
            return True
        if self.frame is None:
            return False
        reply = frames[self.frame.frame].reply
        return bool(reply) and not any(isinstance(p, FramePayload) for p in reply)


@dataclass(frozen=True, slots=True)
class PrimitiveCall(metaclass=Frozen):
    """A call in an interface's body: of a primitive, or (`interface`, when no primitive has
    the name) of another interface; the checker keeps the calls between interfaces acyclic."""

    primitive: PrimitiveRef
    args: tuple[Expr, ...]
    delay_ms: float = 0
    priority: int = 0
    span: Span | None = _span
    interface: bool = False
    when: Expr | None = None  # made only when this holds, over state and the interface's parameters
    until: Expr | None = None  # made again every `every_ms` until this holds, at most within_ms / every_ms more times
    every_ms: float = 0
    within_ms: float = 0


@dataclass(frozen=True, slots=True)
class Interface(metaclass=Frozen):
    name: str
    params: tuple[Parameter, ...]
    periodic: bool
    calls: tuple[PrimitiveCall, ...]  # as written
    triggers: tuple[OutputRef, ...] = ()  # delivered in this order after the calls
    doc: str | None = None
    span: Span | None = _span
    rate_hz: float | None = None  # its own rate (`periodic 10 Hz`), under `threading multiple`

    def run_order(self) -> tuple[PrimitiveCall, ...]:
        """Calls by priority, then as written (a stable sort)."""
        return tuple(sorted(self.calls, key=lambda c: c.priority))


@dataclass(frozen=True, slots=True)
class AdapterField(metaclass=Frozen):
    name: str
    type: AnyType
    unit: str | None = None
    ros: str | None = None
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class FrameworkMapping(metaclass=Frozen):
    """What an adapter is in one framework (thesis §7.2.5; rdisc.semantics.frameworks): the
    framework (`ros2`) and its title (`ROS 2`), the adapter's message or schema type there, each
    field's path in it in the adapter's field order (None: no `ros` path given), and the encodings
    of the framework's schemas and messages (None: the framework's own)."""

    framework: str
    title: str
    type: str
    paths: tuple[str | None, ...]
    schema_encoding: str | None = None
    message_encoding: str | None = None


@dataclass(frozen=True, slots=True)
class Adapter(metaclass=Frozen):
    name: str
    fields: tuple[AdapterField, ...]
    ros: str | None = None  # the `ros` shorthand as written; what it is in each framework: `frameworks`
    standard: bool = False  # declared in stdlib/adapters.rdis
    doc: str | None = None
    span: Span | None = _span
    frameworks: tuple[FrameworkMapping, ...] = ()  # in the table's order of frameworks

    def field(self, name: str) -> AdapterField | None:
        return next((f for f in self.fields if f.name == name), None)

    def mapping(self, framework: str) -> FrameworkMapping | None:
        """What the adapter is in `framework` (`ros1`, `ros2`, `foxglove`), or None: nothing."""
        return next((f for f in self.frameworks if f.framework == framework), None)


@dataclass(frozen=True, slots=True)
class DomainInput(metaclass=Frozen):
    name: str
    adapter: AdapterRef
    interface: InterfaceRef
    args: tuple[Expr, ...]
    doc: str | None = None
    span: Span | None = _span


Rows = tuple[tuple[float, ...], ...]
"""A matrix as its rows."""


@dataclass(frozen=True, slots=True)
class Noise(metaclass=Frozen):
    """A field's error model (thesis §7.2.3): its covariance, a deviation's square when it was
    written as one (`deviation`, in `unit`)."""

    field: str
    covariance: Rows
    deviation: float | None = None
    unit: str | None = None
    span: Span | None = _span
    others: tuple[str, ...] = ()  # the fields after `field` one covariance spans (`noise (x, y) [...]`)

    @property
    def fields(self) -> tuple[str, ...]:
        """The fields the covariance is over, in its order."""
        return (self.field, *self.others)


@dataclass(frozen=True, slots=True)
class Kalman(metaclass=Frozen):
    """A field published as a linear Kalman filter's estimate (H x): the filter's start state and
    covariance, its transition and process noise, its measurement and measurement noise."""

    field: str
    state: tuple[float, ...]
    covariance: Rows
    transition: Rows
    process: Rows
    measurement: Rows
    noise: Rows
    span: Span | None = _span


@dataclass(frozen=True, slots=True)
class DomainOutput(metaclass=Frozen):
    name: str
    adapter: AdapterRef
    fields: tuple[tuple[str, Expr], ...]  # in the adapter's field order
    doc: str | None = None
    span: Span | None = _span
    frame: str | None = None  # the link its data belongs to, as written (`Model.frame_id` when not)
    noise: tuple[Noise, ...] = ()  # its fields' error models, as written
    filters: tuple[Kalman, ...] = ()
