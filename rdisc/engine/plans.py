"""The plans: what a description specialises (per primitive, interface, input and connection), as
data and small functions. The runtime builds them with its interpreter and a driver writes them
as source; both hand the engine the same types.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Mapping, Sequence
from dataclasses import KW_ONLY, dataclass, field
from math import isfinite
from typing import Any

from rdisc.engine.actuation import ActuatorLimit
from rdisc.engine.codec import Format, Match, Pack, Unpack
from rdisc.engine.frames import Frame
from rdisc.engine.kalman import FilterPlan
from rdisc.engine.values import Args, Param, StateValues, Value, _ranged, one_step_bounds


@dataclass(frozen=True, slots=True)
class FrameUse:
    """A primitive's frame, and the frame's arguments over the primitive's parameters."""

    frame: Frame
    args: Callable[[StateValues, Args], Args]


Request = Callable[[StateValues, Args], bytes | None]
"""An input's fields' or a primitive's parameters' values to its request bytes in one step;
None where the general way must decide."""


# ---- the shapes of a reply: one of these is how a primitive's reply is read ---------------------


@dataclass(frozen=True, slots=True)
class NoReply:
    """Nothing is read: the request is only written (its post-actions read its parameters alone)."""


NO_REPLY = NoReply()


@dataclass(frozen=True, slots=True)
class LineReply:
    """A line up to the connection's terminator, matched by `decoder` (no frame)."""

    decoder: Match


@dataclass(frozen=True, slots=True)
class ErrorReply:
    """The reply a device may send instead (`error`: Modbus's exception, a NACK), raised as an
    RdisDeviceError: known by its own frame (`frame`; None: the reply's, or none) or by the bytes
    it starts with (`marker`), the rest decoded by `decoder`, whose first value is the device's
    code when `codes` (an enum's name) names it by `names`. With `when` (`error when COND`), it
    is the reply itself, decoded as ever, when the condition over it holds."""

    decoder: Unpack
    marker: bytes = b""
    frame: FrameUse | None = None
    codes: str = ""
    names: Mapping[int, str] = field(default_factory=dict)
    when: Callable[[StateValues, Args, Sequence[Any]], object] | None = None


@dataclass(frozen=True, slots=True)
class FixedReply:
    """The bytes `decoder` takes, as they come (no frame). `error`: the reply that may come
    instead, known by its first bytes."""

    decoder: Unpack
    _: KW_ONLY
    error: ErrorReply | None = None


@dataclass(frozen=True, slots=True)
class FramedReply:
    """A reply frame, its payload decoded by `decoder` (None: the frame is only read, as a frame
    of constant parts acknowledges). `skip`: frames that do not decode are read past. `error`:
    the reply that may come instead, in a frame of its own or this one's."""

    decoder: Unpack | Match | None = None
    _: KW_ONLY
    skip: bool = False
    error: ErrorReply | None = None


@dataclass(frozen=True, slots=True)
class TaggedReply:
    """A reply frame whose payload starts with a tag (struct format `tag`): the rest is decoded
    by the entry of `table` the tag chooses, whose post-actions take it."""

    tag: str
    table: Mapping[int, Primitive]
    _: KW_ONLY
    skip: bool = False
    tag_struct: struct.Struct = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "tag_struct", struct.Struct(self.tag))


@dataclass(frozen=True, slots=True)
class TaggedStream:
    """A tag, then exactly the bytes its entry decodes, with no frame (Firmata's stream). `skip`:
    a tag without an entry is read past. `nested`: the tags after which a second tag (its struct
    format) chooses the entry, keyed in `table` by the pair (Firmata's sysex sub-commands)."""

    tag: str
    table: Mapping[int | tuple[int, int], Primitive]
    _: KW_ONLY
    skip: bool = False
    nested: Mapping[int, str] = field(default_factory=dict)
    tag_struct: struct.Struct = field(init=False)
    nested_structs: Mapping[int, struct.Struct] = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "tag_struct", struct.Struct(self.tag))
        object.__setattr__(self, "nested_structs", {value: struct.Struct(fmt) for value, fmt in self.nested.items()})


@dataclass(frozen=True, slots=True)
class SubPayloads:
    """A reply frame whose payload is sub-payloads until it ends (Kobuki's feedback): each a tag,
    its length (struct format `length`, when given) and the bytes its entry decodes."""

    tag: str
    table: Mapping[int, Primitive]
    length: str | None = None
    _: KW_ONLY
    skip: bool = False
    tag_struct: struct.Struct = field(init=False)
    length_struct: struct.Struct | None = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "tag_struct", struct.Struct(self.tag))
        object.__setattr__(self, "length_struct", None if self.length is None else struct.Struct(self.length))


@dataclass(frozen=True, slots=True)
class Records:
    """A reply frame whose payload is records, each ended by `marker`, each decoded by `decoder`
    (Firmata's capability report)."""

    marker: bytes
    decoder: Unpack | Match
    _: KW_ONLY
    skip: bool = False


@dataclass(frozen=True, slots=True)
class KeyedReply:
    """A reply table chosen by a parameter (at position `key`): the entry its value chooses is
    what runs, chosen before anything is written (`entry`)."""

    key: int
    table: Mapping[int, Primitive]

    def entry(self, args: Args) -> Primitive:
        return self.table[args[self.key]]  # the key's range holds every key of the table


@dataclass(frozen=True, slots=True)
class SeveralReplies:
    """`replies N`: `count` replies to one request, each read as `each`, through its own frame
    where `frames` gives one (else the primitive's); their values collected value by value into
    arrays for the primitive's post-actions. `replies id in ids` over an array parameter (at
    position `over`): a reply for each of its elements, through the one frame of `frames`,
    whose arguments read the element after the parameters."""

    count: int
    each: Reply
    frames: tuple[FrameUse, ...] = ()
    over: int = -1


@dataclass(frozen=True, slots=True)
class ListedReplies:
    """`replies { }`: the replies read in turn, a plan each (its own frame, reply, `expect` and
    post-actions)."""

    answers: tuple[Primitive, ...]


Reply = (NoReply | LineReply | FixedReply | FramedReply | TaggedReply | TaggedStream | SubPayloads | Records
         | KeyedReply | SeveralReplies | ListedReplies)
"""How a primitive's reply is read: one shape each, decided by the lowering (`rdisc.lower`) and
read by one `match` (`Exchange._read`)."""


@dataclass(frozen=True, slots=True)
class Primitive:
    """One device command: its format values (over state and its parameters), how they are
    encoded and framed (no encoder: no request, only modem lines), how its reply is read and
    decoded (`reply`, one of the shapes of `Reply`), and its post-actions (the new values of
    state variables, over state, its parameters and the reply)."""

    name: str
    connection: str
    params: tuple[Param, ...]
    values: Callable[[StateValues, Args], Args]
    encoder: Pack | Format | None
    _: KW_ONLY
    reply: Reply = NO_REPLY  # how its reply is read
    actions: Callable[[StateValues, Args, Sequence[Any]], dict[str, Value]] | None = None
    frame: FrameUse | None = None
    timeout: float | None = None  # seconds its reply may take, instead of the robot's
    retries: int = 0  # resends after a reply that timed out or did not match (`retry N`)
    checked: tuple[str, ...] = ()  # state variables its post-actions may make too wide (checked as they are set)
    request: Request | None = None  # its parameters' values to the bytes, when it is only written (`_sent_at_once`)
    expect: Callable[[StateValues, Args, Sequence[Any]], object] | None = None  # a condition its decoded reply meets
    lines: Callable[[StateValues, Args], dict[str, Value]] | None = None  # "dtr"/"rts": levels, set before the request
    looks_up: bool = False  # its post-actions look a key up in a table: a miss is a reply it cannot read
    renews: bool = False  # its post-actions give every state variable in the state's order: the new state, published whole
    actuators: tuple[ActuatorLimit, ...] = ()  # actuators' limits on its parameters: shaped or refused first
    floats: tuple[int, ...] = field(init=False)
    ranged: tuple[int, ...] = field(init=False)
    asked: Request | None = field(init=False)  # the request of a plain exchange (`_asked_at_once`), in one step

    def __post_init__(self) -> None:
        object.__setattr__(self, "floats", _floats(self.params))
        object.__setattr__(self, "ranged", _ranged(self.params))
        if not _sent_at_once(self):
            object.__setattr__(self, "request", None)
        elif self.request is None:
            object.__setattr__(self, "request", _composed_write(self))
        object.__setattr__(self, "asked", _composed_write(self) if _asked_at_once(self) else None)


def _plain(encoder: Pack | Format | None) -> bool:
    """Whether an encoder is one struct module's `pack` of its values as they are: no string,
    rest or bit fields to prepare first."""
    return isinstance(encoder, Pack) and not encoder.strings and not encoder.rest and not encoder.bits


def _sent_at_once(plan: Primitive) -> bool:
    """`sent_at_once`, of this plan."""
    return sent_at_once(encoder=plan.encoder, replies=not isinstance(plan.reply, NoReply),
                        acts=plan.actions is not None or plan.lines is not None, dependent=_dependent(plan.params),
                        actuated=bool(plan.actuators))


def _dependent(params: tuple[Param, ...]) -> bool:
    return any(p.low_terms or p.high_terms for p in params)


def sent_at_once(*, encoder: Pack | Format | None, replies: bool, acts: bool, dependent: bool = False,
                 actuated: bool = False) -> bool:
    """Whether running a primitive is only packing its values, framing them and writing them
    (`Primitive.request`): one plain struct pack (`encoder`), and no reply, reply table,
    post-action, modem line (`acts`), range that reads another parameter (`dependent`, checked
    the general way) or actuator's limit (`actuated`, applied the general way) in the way. The
    one rule: the engine applies it to its plans, the lowering (`rdisc.lower`) to its own."""
    return _plain(encoder) and not replies and not acts and not dependent and not actuated


def _asked_at_once(plan: Primitive) -> bool:
    """`asked_at_once`, of this plan."""
    reply = plan.reply
    return asked_at_once(encoder=plan.encoder, framed=plan.frame is not None, lines=plan.lines is not None,
                         retries=plan.retries, actuated=bool(plan.actuators),
                         decoder=reply.decoder if isinstance(reply, FixedReply) and reply.error is None else None)


def asked_at_once(*, encoder: Pack | Format | None, framed: bool, lines: bool, retries: int,
                  decoder: Unpack | None, actuated: bool = False) -> bool:
    """Whether a primitive is a plain exchange (`Exchange._ask`): its request one plain struct pack
    of some bytes (a listener writes none, and keeps what has arrived) with no frame and no modem
    line, its reply a fixed number of bytes (`decoder`: a reply's with no error reply in its
    place, else None), read in one try (no `retry`). Such a reply is read from the port in one
    read, and no actuator's limit on its parameters (`actuated`). The one rule: the engine applies it
    to its plans, the lowering (`rdisc.lower`) to its own."""
    return (_plain(encoder) and isinstance(encoder, Pack) and encoder.struct.size > 0 and not framed
            and not lines and not retries and decoder is not None and decoder.size > 0 and decoder.until is None
            and not actuated)


def plainly_given(args: Args, kinds: tuple[type, ...], bounds: tuple[tuple[int, Any, Any], ...]) -> bool:
    """Whether a one-step request may take these values: one of each parameter's own type, those
    with a range within it, bytes by their length (anything else goes the general way, which says
    what is wrong)."""
    if len(args) != len(kinds):
        return False
    for value, kind in zip(args, kinds):
        if type(value) is not kind:
            return False
    for i, low, high in bounds:
        value = args[i]
        if not low <= (len(value) if type(value) is bytes else value) <= high:
            return False
    return True


def _composed_write(plan: Primitive) -> Request:
    """The general way of a primitive only written (`Robot._primitive`), or of a plain exchange's
    request (`Primitive.asked`), as one function of its parameters' values. Like `Input.request` it returns None for anything but the parameters'
    own types in their ranges, and on any error: the general way then says what is wrong."""
    kinds = tuple(p.kind for p in plan.params)
    bounds = one_step_bounds(plan.params)
    values_of = plan.values
    assert isinstance(plan.encoder, Pack)
    pack = plan.encoder.struct.pack
    use = plan.frame

    def request(state: StateValues, args: Args) -> bytes | None:
        if not plainly_given(args, kinds, bounds):
            return None
        try:
            payload = pack(*values_of(state, args))
            if use is None:
                return payload
            given = use.args(state, args)
            return use.frame.wrap(payload, use.frame.values("", given), use.frame.layout("", given))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    def parameterless(state: StateValues, args: Args) -> bytes | None:  # no parameter to test
        if args:
            return None
        try:
            return pack(*values_of(state, args))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    return parameterless if not kinds and use is None else request


@dataclass(frozen=True, slots=True)
class Output:
    """A domain output: its fields over state, in its adapter's order."""

    name: str
    fields: Callable[[StateValues], dict[str, Value]]
    adapter: str = ""
    frame: str = ""  # its stamped messages' frame id and child frame id (`semantics.ros.header_frames`)
    child_frame: str = ""
    filters: tuple[FilterPlan, ...] = ()  # fields published as a Kalman filter's estimate
    sensors: tuple[str, ...] = ()  # the sensors its fields read: each read first, when stale


@dataclass(frozen=True, slots=True)
class Call:
    """A call of an interface: of a primitive or of another interface, its arguments over
    state and the interface's parameters, and the delay after it. `direct`: the arguments
    are the primitive's format values (it has no frame, table, ranges or post-actions)."""

    target: Primitive | Interface
    args: Callable[[StateValues, Args], Args]
    delay: float = 0.0  # seconds
    direct: bool = False
    when: Callable[[StateValues, Args], object] | None = None  # the call is made only when this holds
    until: Callable[[StateValues, Args], object] | None = None  # made again every `every` s until this holds
    every: float = 0.0
    within: float = 0.0  # seconds: at most within / every more calls, else an RdisTimeout


@dataclass(frozen=True, slots=True)
class Interface:
    """A host-side operation: its calls in run order, then the outputs it triggers."""

    name: str
    params: tuple[Param, ...]
    calls: tuple[Call, ...]
    outputs: tuple[Output, ...] = ()
    sensors: tuple[str, ...] = ()  # the sensors its calls read: each read first, when stale
    floats: tuple[int, ...] = field(init=False)
    ranged: tuple[int, ...] = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "floats", _floats(self.params))
        object.__setattr__(self, "ranged", _ranged(self.params))


@dataclass(frozen=True, slots=True)
class Input:
    """A domain input: its adapter's fields, and the interface's arguments over them.

    When its interface is one plain write (`_written_at_once`), `request` goes from the
    fields' values straight to the bytes: a generated driver gives one compiled from the
    expressions, else the general way is composed into one here. It returns None for
    anything but the fields' own types and on any error, and the general way then runs
    and says what is wrong, so both ways behave alike."""

    name: str
    adapter: str
    fields: tuple[Param, ...]
    interface: Interface
    args: Callable[[StateValues, Args], Args]
    request: Request | None = None
    sensors: tuple[str, ...] = ()  # the sensors its arguments read: each read first, when stale
    primitive: Primitive | None = field(init=False)  # where `request` goes, when there is one
    kinds: tuple[type, ...] = field(init=False)
    taken: Callable[[Mapping[str, Any]], Args] = field(init=False)  # the fields' values from a call's keywords

    def __post_init__(self) -> None:
        object.__setattr__(self, "kinds", tuple(f.kind for f in self.fields))
        object.__setattr__(self, "taken", _taking(tuple(f.name for f in self.fields)))
        call = None if self.sensors else _written_at_once(self.interface)  # a sensor is read the general way
        object.__setattr__(self, "primitive", call.target if call is not None else None)
        request = None if call is None else self.request or _composed(self, call)
        object.__setattr__(self, "request", request)


def _written_at_once(interface: Interface) -> Call | None:
    """The interface's one call, when running it is only packing its values and writing them
    (`written_at_once`, of this plan)."""
    call = interface.calls[0] if len(interface.calls) == 1 else None
    prim = call.target if call is not None else None
    if call is None or not isinstance(prim, Primitive):
        return None
    plain = written_at_once(
        calls=len(interface.calls), outputs=len(interface.outputs), ranged=bool(interface.ranged or prim.ranged),
        direct=call.direct, waits=bool(call.delay or call.when or call.until), encoder=prim.encoder,
        replies=not isinstance(prim.reply, NoReply), framed=prim.frame is not None,
        acts=prim.actions is not None or prim.lines is not None)
    return call if plain else None


def written_at_once(*, calls: int, outputs: int, ranged: bool, direct: bool, waits: bool,
                    encoder: Pack | Format | None, replies: bool, framed: bool, acts: bool) -> bool:
    """Whether running an interface is one plain write, so that an input of it may go from its
    fields' values straight to the bytes (`Input.request`): its one call (of `calls`) a direct
    call of a primitive packed with one plain struct pack (`encoder`), and no delay, condition or
    poll (`waits`), range (the interface's or the primitive's), output, reply, frame, post-action
    or modem line (`acts`) in the way. The one rule: the engine applies it to its plans, the
    lowering (`rdisc.lower`) to its own, so a driver is written with the function this asks for."""
    return (calls == 1 and not outputs and not ranged and direct and not waits and not framed
            and sent_at_once(encoder=encoder, replies=replies, acts=acts))


def _taking(names: tuple[str, ...]) -> Callable[[Mapping[str, Any]], Args]:
    """The values of `names` from keywords, in order (a KeyError for one missing): up to three
    unrolled, the commonest inputs' (`Robot.call_input`) with no loop."""
    match names:
        case (one,):
            return lambda given: [given[one]]
        case (one, two):
            return lambda given: [given[one], given[two]]
        case (one, two, three):
            return lambda given: [given[one], given[two], given[three]]
    return lambda given: [given[name] for name in names]


def _composed(plan: Input, call: Call) -> Request:
    """The general way of an input written at once (`Robot._input`), as one function."""
    args_of, floats, values_of = plan.args, plan.interface.floats, call.args
    kinds: tuple[Any, ...] = plan.kinds  # (not `type`: a value tested against one is not narrowed to `object`)
    assert isinstance(call.target, Primitive)  # `_written_at_once`
    encoder = call.target.encoder
    assert isinstance(encoder, Pack)
    pack = encoder.struct.pack

    def request(state: StateValues, values: Args) -> bytes | None:
        for value, kind in zip(values, kinds):  # (inline: every input's path)
            if type(value) is not kind or kind is float and not isfinite(value):
                return None
        try:
            args = args_of(state, values)
            for i in floats:
                if type(args[i]) is int:
                    args[i] = float(args[i])
            return pack(*values_of(state, args))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    return request


@dataclass(frozen=True, slots=True)
class Hook:
    """A connection's startup, terminate or keepalive call: an interface, arguments over state."""

    interface: Interface
    args: Callable[[StateValues], Args]


@dataclass(frozen=True, slots=True)
class Connection:
    """A transport and what runs on it: hooks, periodic interfaces, its thread's frequency."""

    name: str
    baud: int
    address: str | None = None  # opened when no port is given
    terminator: bytes = b"\n"  # ends a reply line
    frequency: float = 0.0  # ticks a second
    periodic: tuple[Interface, ...] = ()
    startup: Hook | None = None
    terminate: Hook | None = None
    keepalive: Hook | None = None
    interval: float = 0.0  # seconds between keepalives
    baud_setting: str | None = None  # the setting that gives the baud rate (`baud` is its default)
    data_bits: int = 8  # the serial line's character: 8N1 unless the description says otherwise
    parity: str = "none"  # none, even, odd, mark or space
    stop_bits: float = 1  # 1, 1.5 or 2
    threading: str = "single"  # single: a tick holds the port; dual: each exchange does; multiple: a thread each
    rates: tuple[float, ...] = ()  # under `multiple`, each periodic interface's ticks a second (0: `frequency`)


@dataclass(frozen=True, slots=True)
class Sensor:
    """A sensor (`rdisc.engine.sensing`): the primitive whose post-actions store its value as
    state, and how long a value read is kept (seconds)."""

    name: str
    primitive: Primitive
    cache: float


@dataclass(frozen=True, slots=True)
class Device:
    """A whole description, planned: what a Robot runs."""

    name: str
    state: Mapping[str, Value]  # the initial values, and the settings' defaults
    connections: Mapping[str, Connection]
    primitives: Mapping[str, Primitive]
    interfaces: Mapping[str, Interface]
    inputs: Mapping[str, Input]
    settings: tuple[Param, ...] = ()  # given when connecting; read as state is, never written
    messages: Mapping[str, Message] = field(default_factory=dict)  # by adapter: how a recording carries it
    sensors: Mapping[str, Sensor] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class Message:
    """The ROS 2 message a recording (`--record`) carries an adapter's values as: its type
    (`geometry_msgs/msg/Twist`), its definition with those of the messages it uses (the
    `ros2msg` schema text), the adapter's fields and where each goes (`linear.x`, `position[0]`,
    `pose.pose.orientation:yaw` for a quaternion given by its yaw)."""

    type: str
    definition: str
    fields: tuple[str, ...]
    paths: tuple[str, ...]


def _floats(params: tuple[Param, ...]) -> tuple[int, ...]:
    return tuple(i for i, p in enumerate(params) if p.kind is float)
