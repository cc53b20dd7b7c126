"""Model → plans (`lower`): every decision about how a description is run, made once.

The plans mirror the engine's (`rdisc.engine`: Primitive, Call, Interface, Input,
Output, Hook, Connection, Device, Frame, FrameUse). Where the engine takes a function, a
plan holds a `Code`: what the function computes, as data. The engine's data objects
(encoders, decoders, frame parts, parameters) are built here, once, as `Construct`s. Two
back ends walk the same plans: the runtime (`rdisc.runtime.device`) makes each Code a
closure over `rdisc.semantics.evaluate.prepare`; the emitter (`rdisc.emit.python`) writes
each Code as a function and each plan as its constructor call. Neither decides anything
about the description's structure.

A plan's fields after `KW_ONLY` are options, written by keyword when they are not at
their default.
"""

from __future__ import annotations

import dataclasses
import enum
import struct
from collections.abc import Mapping
from dataclasses import KW_ONLY, dataclass, field
from typing import Any

from rdisc import engine
from rdisc.engine.operations import EVAL_ERRORS
from rdisc.lowering.actuators import actuator_limits
from rdisc.lowering.constructs import (
    Construct,
    decoding,
    encoding,
    escaping,
    frame_fields,
    param,
    parts,
    stuffing,
)
from rdisc.lowering.messages import recorded_messages
from rdisc.lowering.whole_frame import WholeFrame, whole_frame
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import prepare
from rdisc.semantics.ros import header_frames

__all__ = ["Call", "Code", "Connection", "Device", "ErrorReply", "Frame", "FrameUse", "Gives", "Hook", "Input", "Interface",
           "Output", "Plans", "Primitive", "Written", "frame", "lower", "written_at_once"]

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


def lower(model: m.Model) -> Plans:
    """The plans of a checked description."""
    return _Lowering(model).plans


class _Lowering:
    def __init__(self, model: m.Model) -> None:
        self.model = model
        self.frames = {f.name: frame(f) for f in model.frames.values()}
        self.own_frames: dict[str, tuple[FrameUse, ...]] = {}
        self.limits = actuator_limits(model)
        primitives = {p.name: self.primitive(self.sensed(p)) for p in model.primitives.values()}
        outputs = {o.name: self.output(o) for o in model.outputs.values()}
        planned: dict[str, Interface] = {}
        for iface in model.callees_first():
            planned[iface.name] = self.interface(iface, primitives, outputs, planned)
        interfaces = {name: planned[name] for name in model.interfaces}
        inputs = {i.name: self.input(i, interfaces) for i in model.inputs.values()}
        connections = {c.name: self.connection(c, interfaces) for c in model.connections.values()}
        state = ({s.name: m.coerce(s.default, s.type) for s in model.settings.values()}
                 | {s.name: m.coerce(s.initial, s.type) for s in model.states.values()})
        settings = tuple(param(s.name, s.type, s.low, s.high, s.default) for s in model.settings.values())
        sensors = {s.name: Sensor(s.name, primitives[s.primitive], s.cache_ms / 1000.0) for s in model.sensors.values()}
        device = Device(model.robot.name, state, connections, primitives, interfaces, inputs, settings=settings,
                        messages=recorded_messages(model), sensors=sensors)
        self.plans = Plans(device, self.frames, outputs)

    # ---- primitives -----------------------------------------------------------------------------

    def sensed(self, p: m.Primitive) -> m.Primitive:
        """`p`, and when sensors read it, a post-action storing its one reply value as each
        sensor's (`rdisc.semantics.check.sensors`): reading the sensor runs this plan."""
        decoding = p.decoding
        stores = tuple(m.PostAction(m.StateRef(s.name), m.ReplyValue(0, decoding.layout.slots[0].type))
                       for s in self.model.sensors.values() if s.primitive == p.name and isinstance(decoding, m.Unpack))
        return dataclasses.replace(p, actions=p.actions + stores) if stores else p

    def sensors(self, *exprs: m.Expr | None) -> tuple[str, ...]:
        """The sensors the expressions read, each once, in order."""
        sensors = self.model.sensors
        read = (v.name for e in exprs if e is not None for v in m.variables(e) if v.scope is m.Scope.STATE)
        return tuple(dict.fromkeys(name for name in read if name in sensors))

    def primitive(self, p: m.Primitive) -> Primitive:
        """A primitive's plan; with a reply table, one plan for each entry besides (a range
        entry's once, for each of its values), chosen by a parameter or by the reply's tag."""
        limits = self.limits.get(p.name, ())
        if p.table is None:
            plan = dataclasses.replace(self.single(p, p.reply_locals()), actuators=limits)
            return dataclasses.replace(plan, request=_written(plan, p.params, p.encoding),
                                       asked=_asked(plan, p.params))
        plain = dataclasses.replace(self.single(dataclasses.replace(p, table=None), p.reply_locals()), actuators=limits)
        table = tuple(Entry(c, self.reply(plain, p.case(c), p.reply_locals())) for c in p.table.cases)
        if p.table.tag is None:
            key = next(i for i, prm in enumerate(p.params) if prm.name == p.table.key)
            return dataclasses.replace(plain, reply=KeyedReply(key, table))
        frames = self.reply_frames(p)
        tagged = _tagged(p.table, frames[0] if frames else plain.frame, p.skip_unmatched, table)
        return dataclasses.replace(plain, reply=self.several(p, tagged) if p.replies else tagged)

    def single(self, p: m.Primitive, local: tuple[m.Parameter, ...]) -> Primitive:
        """The plan of a primitive without a reply table, its listed replies each its own plan;
        `local`, what its `expect` and post-actions read besides state and the reply."""
        spreads = p.spreads()
        values = Code(_OVER_ARGS, Gives.LIST, p.params,
                      tuple(("*" if i in spreads else "", a, None) for i, a in enumerate(p.args)))
        lines = None
        if p.lines:
            lines = Code(_OVER_ARGS, Gives.DICT, p.params, tuple((level.line, level.value, None) for level in p.lines))
        plan = Primitive(
            p.name, p.connection, _params(p.params), values, None if p.encoding is None else encoding(p.encoding),
            frame=self.frame_use(p.frame, p.params), timeout=None if p.timeout_ms is None else p.timeout_ms / 1000.0,
            retries=p.retries,
            expect=None if p.expect is None else _condition(_OVER_REPLY, local, p.expect), lines=lines,
        )
        plan = self.reply(plan, p, local)
        if not p.listed:
            return plan
        return dataclasses.replace(plan, reply=ListedReplies(tuple(self.listed(plan, p.listed_reply(r))
                                                                     for r in p.listed)))

    def listed(self, plan: Primitive, p: m.Primitive) -> Primitive:
        """One of `replies { }`: the primitive's plan with that reply's frame, decoder, expect
        and post-actions."""
        expect = None if p.expect is None else _condition(_OVER_REPLY, p.reply_locals(), p.expect)
        own = dataclasses.replace(plan, frame=self.frame_use(p.frame, p.params), expect=expect)
        return self.reply(own, p, p.reply_locals())

    def reply(self, plan: Primitive, p: m.Primitive, local: tuple[m.Parameter, ...]) -> Primitive:
        """`plan` reading `p`'s reply (`read_as`): and its post-actions over `local` (besides
        state and the reply), with the state variables they may make too wide."""
        states: Mapping[str, m.StateVariable | m.Sensor] = {**self.model.states, **self.model.sensors}
        actions = None
        if p.actions:
            actions = Code(_OVER_REPLY, Gives.DICT, local,
                           tuple((a.target, a.stored(), states[a.target].type) for a in p.actions))
        checked = tuple(a.target for a in p.actions
                        if states[a.target].type is m.Type.INT and m.may_outgrow(a.stored()))
        return dataclasses.replace(plan, reply=self.read_as(p, plan.frame), actions=actions, checked=checked,
                                   looks_up=any(m.looks_up(a.value) for a in p.actions))

    def read_as(self, p: m.Primitive, use: FrameUse | None) -> Reply:
        """How `p`'s reply is read through `use` (a primitive without a reply table or listed
        replies, or one of its entries or listed replies): several replies, each as one is; one
        reply to decode; a frame of constant parts that acknowledges; or nothing."""
        decoder = decoding(p.decoding)
        if p.replies:
            frames = self.reply_frames(p)
            return self.several(p, _one(decoder, frames[0] if frames else use, p.skip_unmatched, p.records))
        error = None if p.error is None else self.error(p.error, p.reply_locals())
        if decoder is not None:
            return _one(decoder, use, p.skip_unmatched, p.records, error)
        if use is not None and _acknowledges(use.frame):
            return FramedReply(skip=p.skip_unmatched, error=error)
        return NO_REPLY

    def error(self, e: m.ErrorReply, params: tuple[m.Parameter, ...]) -> ErrorReply:
        """The reply that may come instead (`error ...`): its enum's members by value."""
        decoder = decoding(e.decoding)
        assert decoder is not None and decoder.kind is engine.Unpack  # the checker's
        names = {} if e.codes is None else {value: member for member, value in self.model.enums[e.codes].items()}
        when = None if e.when is None else _condition(_OVER_REPLY, params, e.when)
        return ErrorReply(decoder, e.marker.encode("latin-1"), self.frame_use(e.frame, params), e.codes or "", names,
                          when)

    def several(self, p: m.Primitive, each: Reply) -> SeveralReplies:
        """`replies N`, each reply read as `each`: N of them, or one for each element of an
        array parameter (`replies id in ids`)."""
        frames = self.reply_frames(p)
        if p.each is None:
            return SeveralReplies(len(frames) or p.replies, each, frames)
        over = next(i for i, prm in enumerate(p.params) if prm.name == p.each.over)
        return SeveralReplies(0, each, frames, over)

    def reply_frames(self, p: m.Primitive) -> tuple[FrameUse, ...]:
        """`replies N`'s own frames, made once a primitive (its table's entries share them); over
        an array parameter, the one frame whose arguments read the element after the parameters."""
        if p.name not in self.own_frames:
            local = p.params if p.each is None else p.each.local(p.params)
            self.own_frames[p.name] = tuple(FrameUse(self.frames[use.frame], _values(local, use.args))
                                            for use in p.reply_frames)
        return self.own_frames[p.name]

    def frame_use(self, use: m.FrameUse | None, params: tuple[m.Parameter, ...]) -> FrameUse | None:
        return None if use is None else FrameUse(self.frames[use.frame], _values(params, use.args))

    # ---- interfaces, inputs, outputs, connections ---------------------------------------------------

    def output(self, o: m.DomainOutput) -> Output:
        adapter = self.model.adapters[o.adapter]
        fields = tuple((name, e, _field_type(adapter, name, e)) for name, e in o.fields)
        filters = tuple(Construct(engine.FilterPlan, (k.field, k.state, k.covariance, k.transition, k.process,
                                                       k.measurement, k.noise)) for k in o.filters)
        return Output(o.name, Code(("state",), Gives.DICT, (), fields), o.adapter, *header_frames(self.model, o),
                      filters, self.sensors(*(e for _, e in o.fields)))

    def interface(self, iface: m.Interface, primitives: Mapping[str, Primitive], outputs: Mapping[str, Output],
                  callees: Mapping[str, Interface]) -> Interface:
        """The interface's plan; `callees`, the plans of the interfaces it calls."""
        calls = []
        for c in iface.run_order():
            if c.interface:
                call = Call(callees[c.primitive], _values(iface.params, c.args), c.delay_ms / 1000.0)
            else:
                call = self.call(c, iface.params, primitives[c.primitive])
            if c.when is not None:
                call = dataclasses.replace(call, when=_condition(_OVER_ARGS, iface.params, c.when))
            if c.until is not None:
                call = dataclasses.replace(call, until=_condition(_OVER_ARGS, iface.params, c.until),
                                           every=c.every_ms / 1000.0, within=c.within_ms / 1000.0)
            calls.append(call)
        read = self.sensors(*(e for c in iface.run_order() for e in (*c.args, c.when, c.until)))
        return Interface(iface.name, _params(iface.params), tuple(calls),
                         outputs=tuple(outputs[o] for o in iface.triggers), sensors=read)

    def call(self, call: m.PrimitiveCall, params: tuple[m.Parameter, ...], plan: Primitive) -> Call:
        """A call of a primitive, with its format arguments substituted where that changes
        nothing (`formats_its_params`): its format values are computed straight from the
        call's arguments, the same expressions evaluated in the same order, each bound to
        its parameter's type."""
        primitive = self.model.primitives[call.primitive]
        delay = call.delay_ms / 1000.0
        if not primitive.formats_its_params() or plan.actuators:  # an actuator's limits hold its parameters
            return Call(plan, _values(params, call.args), delay)
        by_param = {prm.name: (prm, arg) for prm, arg in zip(primitive.params, call.args)}
        direct: list[Item] = []
        for arg in primitive.args:
            if isinstance(arg, m.Var):
                prm, expr = by_param[arg.name]
                direct.append(("", expr, prm.type))
            else:
                direct.append(("", arg, None))  # a constant, such as an opcode
        return Call(plan, Code(_OVER_ARGS, Gives.LIST, params, tuple(direct)), delay, direct=True)

    def input(self, i: m.DomainInput, interfaces: Mapping[str, Interface]) -> Input:
        adapter = self.model.adapters[i.adapter]
        fields = tuple(m.Parameter(f.name, f.type) for f in adapter.fields)
        interface = interfaces[i.interface]
        read = self.sensors(*i.args)  # read first, the general way: no one-step request
        plan = Input(i.name, i.adapter, _params(fields), interface, _values(fields, i.args), sensors=read)
        return dataclasses.replace(plan, request=written_at_once(interface) and not read)

    def connection(self, c: m.Connection, interfaces: Mapping[str, Interface]) -> Connection:
        def hook(call: m.HookCall | None) -> Hook | None:
            return None if call is None else Hook(interfaces[call.interface], _values((), call.args, ("state",)))

        owned = [i for i in self.model.interfaces.values() if i.periodic and self.model.owner(i) == c.name]
        periodic = tuple(interfaces[i.name] for i in owned)
        rates = tuple(i.rate_hz or 0.0 for i in owned) if c.threading == "multiple" else ()
        keepalive = c.keepalive
        return Connection(
            c.name, c.baud, address=c.address, terminator=c.terminator_bytes(), frequency=float(c.frequency_hz or 0),
            periodic=periodic, startup=hook(c.startup), terminate=hook(c.terminate),
            keepalive=hook(keepalive.call if keepalive else None),
            interval=keepalive.interval_ms / 1000.0 if keepalive else 0.0, baud_setting=c.baud_setting,
            data_bits=c.data_bits, parity=c.parity, stop_bits=c.stop_bits, threading=c.threading,
            rates=rates if any(rates) else (),
        )


def frame(f: m.Frame) -> Frame:
    """A frame's plan: its parts each way, and its fields' values over its parameters."""
    values = frame_fields(f)
    fields = _values(f.params, tuple(e for _, e in values), ("args",)) if values else None
    return Frame(f.name, parts(f, f.request), parts(f, f.reply), stuffing=stuffing(f), params=_params(f.params),
                 fields=fields, more_requests=[parts(f, layout) for layout in f.more_requests],
                 more_replies=[parts(f, layout) for layout in f.more_replies], escaping=escaping(f),
                 choose=_conditions(f.params, f.request_when), answer=_conditions(f.params, f.reply_when))


def _conditions(params: tuple[m.Parameter, ...], when: tuple[m.Expr | None, ...]) -> Code | None:
    """The conditions of a side's `either when` over the frame's arguments (a plain last layout has none)."""
    return _values(params, tuple(e for e in when if e is not None), ("args",)) if when else None


def _written(plan: Primitive, params: tuple[m.Parameter, ...], encoding: m.Pack | m.Format | None) -> Written | None:
    """A primitive's request in one step, when it is only written (`engine.sent_at_once`)
    and its frame, if any, folds into constant bytes around a payload of a fixed size (then packed
    by one struct with them, `whole_frame`, where it can be)."""
    encoder = None if plan.encoder is None else plan.encoder.value
    sent = engine.sent_at_once(encoder=encoder, replies=not isinstance(plan.reply, NoReply),
                               acts=plan.actions is not None or plan.lines is not None,
                               dependent=any(prm.limits is not None for prm in params),
                               actuated=bool(plan.actuators))
    if not sent:
        return None
    written = _packed(plan, params)
    assert isinstance(encoder, engine.Pack)  # `sent`
    folded = written if plan.frame is None or written is None else _folded(written, plan.frame, encoder.struct.size)
    if folded is None:
        return None
    return _constant(dataclasses.replace(folded, whole=whole_frame(encoding, folded)), encoder)


def _asked(plan: Primitive, params: tuple[m.Parameter, ...]) -> Written | None:
    """A plain exchange's request in one step (`engine.asked_at_once`), when its values are packed
    as they are, its parameters' ranges not reading each other."""
    encoder = None if plan.encoder is None else plan.encoder.value
    reply = plan.reply
    decoder = reply.decoder.value if isinstance(reply, FixedReply) and reply.error is None else None
    asked = engine.asked_at_once(encoder=encoder, framed=plan.frame is not None, lines=plan.lines is not None,
                                 retries=plan.retries, decoder=decoder, actuated=bool(plan.actuators))
    written = _packed(plan, params) if asked and not any(prm.limits is not None for prm in params) else None
    return None if written is None or encoder is None else _constant(written, encoder)


def _packed(plan: Primitive, params: tuple[m.Parameter, ...]) -> Written | None:
    """A request whose values one struct packs as they are (no groups, varying counts, arrays)."""
    encoder = None if plan.encoder is None else plan.encoder.value
    if not isinstance(encoder, engine.Pack) or encoder.groups or encoder.varying \
            or any(key == "*" for key, _, _ in plan.values.items) or any(isinstance(prm.type, m.Array) for prm in params):
        return None
    return Written(params, plan.values, encoder.struct.format)


def _constant(folded: Written, encoder: engine.Pack | engine.Format) -> Written:
    """`folded` with its whole request, when that is always the same bytes (no parameters, constant values)."""
    assert isinstance(encoder, engine.Pack)
    if folded.params or not all(isinstance(e, m.Const) for _, e, _ in folded.values.items):
        return folded
    try:
        payload = encoder.struct.pack(*(e.value for _, e, _ in folded.values.items if isinstance(e, m.Const)))
    except struct.error:
        return folded  # the general way says what is wrong, each time
    check = b""
    if folded.checksum is not None:
        check = struct.pack(folded.check_format, folded.checksum.value(folded.covered + payload))
    return dataclasses.replace(folded, constant=folded.head + payload + check + folded.tail)


def _folded(written: Written, use: FrameUse, size: int) -> Written | None:
    """`written` with its frame's parts folded around its payload: the frame's arguments
    constants, nothing escaped or stuffed, one layout, no reply read; before the payload
    constant bytes, fields and the length only; after it a checksum of parts up to it, then
    constant bytes."""
    f = use.frame
    if f.stuffing is not None or f.escaping is not None or f.more_requests or _acknowledges(f) \
            or not all(isinstance(e, m.Const) for _, e, _ in use.args.items):
        return None
    args = [e.value for _, e, _ in use.args.items if isinstance(e, m.Const)]
    made = engine.Frame(f.name, [part.value for part in f.request], [], params=tuple(prm.value for prm in f.params),
                        fields=None if f.fields is None else _evaluated(f.fields))
    side = made.requests[0]
    payload_at = side.payload
    if payload_at < 0 or size > side.most or made.trim:  # a trimmed payload's size is not fixed
        return None
    try:
        fields = made.values("", args)
    except (engine.RdisValueError, *EVAL_ERRORS):
        return None
    before, after = side.parts[:payload_at], side.parts[payload_at + 1:]
    if not all(isinstance(part, (engine.Bytes, engine.Field, engine.Length)) for part in before):
        return None
    head_size = sum(side.sizes[:payload_at])
    try:
        framed = made.wrap(bytes(size), fields)
    except (ValueError, struct.error):
        return None
    head = framed[:head_size]
    check = after[0] if after and isinstance(after[0], engine.Check) else None
    if not all(isinstance(part, engine.Bytes) for part in after[1 if check else 0:]):
        return None
    tail = b"".join(part.data for part in after[1 if check else 0:] if isinstance(part, engine.Bytes))
    if check is None:
        return dataclasses.replace(written, head=head, tail=tail)
    if check.last != payload_at or check.struct is None or check.order is not None or check.with_request \
            or check.seed >= 0:
        return None
    construct = f.request[payload_at + 1].args[0]
    covered = head[sum(side.sizes[:check.first]):]
    partial = sum(covered) if check.checksum.kind == "sum" else None
    return dataclasses.replace(written, head=head, checksum=construct, check_format=check.struct.format,
                               check_size=check.struct.size, covered=covered, partial=partial, tail=tail)


def _one(decoder: Construct[engine.Unpack] | Construct[engine.Match] | None, use: FrameUse | None, skip: bool,
         records: str | None, error: ErrorReply | None = None) -> Reply:
    """How one reply is read: through a frame whose reply has parts, its payload (as records,
    or decoded); with no frame, a line matched or the bytes an `unpack` takes. `error`: the
    reply that may come instead (the checker allows it only where one reply is decoded)."""
    if use is not None and use.frame.reply:
        if records is not None:
            assert decoder is not None and decoder.kind is engine.Unpack  # the checker's
            return Records(records.encode("latin-1"), decoder, skip=skip)
        return FramedReply(decoder, skip=skip, error=error)
    if decoder is None:
        return NO_REPLY
    if decoder.kind is engine.Match:
        return LineReply(decoder)
    assert decoder.kind is engine.Unpack
    return FixedReply(decoder, error=error)


def _tagged(table: m.ReplyTable, use: FrameUse | None, skip: bool, entries: tuple[Entry, ...]) -> Reply:
    """How a reply whose tag chooses its entry is read: through a frame whose reply has parts,
    its payload's tag (or its sub-payloads, each with its tag); with no frame, a tag and its bytes."""
    assert table.tag is not None
    if use is None or not use.frame.reply:
        nested = {c.under: c.under_tag for c in table.cases if c.under is not None and c.under_tag is not None}
        return TaggedStream(table.tag, entries, skip=skip, nested=nested)
    if table.each:
        return SubPayloads(table.tag, entries, table.length, skip=skip)
    return TaggedReply(table.tag, entries, skip=skip)


def _acknowledges(f: Frame) -> bool:
    """Whether a frame's reply is an acknowledgement: constant parts only, no payload (the
    engine reads it, and there is nothing to decode)."""
    reply = engine.Side([part.value for part in f.reply])
    return bool(reply.parts) and reply.payload < 0


def _evaluated(code: Code) -> Any:
    """A frame's fields' values over its arguments (the runtime's closure of the Code)."""
    slots = {prm.name: i for i, prm in enumerate(code.params)}
    fs = [prepare(e, slots) for _, e, _ in code.items]
    return lambda args: [f(_NO_STATE, args, ()) for f in fs]


def written_at_once(interface: Interface) -> bool:
    """Whether running the interface is one plain write: the engine's rule
    (`engine.written_at_once`), of this plan."""
    call = interface.calls[0] if len(interface.calls) == 1 else None
    prim = call.target if call is not None else None
    if call is None or not isinstance(prim, Primitive):
        return False
    return engine.written_at_once(
        calls=len(interface.calls), outputs=len(interface.outputs), ranged=_ranged(interface.params + prim.params),
        direct=call.direct, waits=bool(call.delay or call.when is not None or call.until is not None),
        encoder=None if prim.encoder is None else prim.encoder.value, replies=not isinstance(prim.reply, NoReply),
        framed=prim.frame is not None, acts=prim.actions is not None or prim.lines is not None)


def _ranged(params: tuple[Construct[engine.Param], ...]) -> bool:
    return any(prm.value.low is not None for prm in params)


def _params(params: tuple[m.Parameter, ...]) -> tuple[Construct[engine.Param], ...]:
    return tuple(param(p.name, p.type, p.low, p.high, p.default, params[:i], p.limits) for i, p in enumerate(params))


def _field_type(adapter: m.Adapter, name: str, expr: m.Expr) -> m.AnyType:
    field = adapter.field(name)
    return field.type if field is not None else expr.type
