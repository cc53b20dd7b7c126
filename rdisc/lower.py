"""Model → plans (`lower`): every decision about how a description is run, made once.

The plans mirror the engine's (`rdisc.engine`: Primitive, Call, Interface, Input,
Output, Hook, Connection, Device, Frame, FrameUse). Where the engine takes a function, a
plan holds a `Code`: what the function computes, as data. The engine's data objects
(encoders, decoders, frame parts, parameters) are built here, once, as `Construct`s. Two
back ends walk the same plans: the runtime (`rdisc.runtime.device`) makes each Code a
closure over `rdisc.semantics.evaluate.prepare`; the emitter (`rdisc.emit.python`) writes
each Code as a function and each plan as its constructor call. Neither decides anything
about the description's structure.

The plans themselves are declared in `rdisc.lowering.plans` and a primitive's request in one
step is worked out in `rdisc.lowering.one_step`; this module walks the Model and is the
namespace both back ends read the plans from (`plans.Primitive`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

from rdisc import engine
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
from rdisc.lowering.one_step import _acknowledges, _asked, _written, written_at_once
from rdisc.lowering.plans import (
    _OVER_ARGS,
    _OVER_REPLY,
    LOWERED_ONLY,
    NO_REPLY,
    TABLED,
    Call,
    Code,
    Connection,
    Device,
    Entry,
    ErrorReply,
    FixedReply,
    Frame,
    FramedReply,
    FrameUse,
    Gives,
    Hook,
    Input,
    Interface,
    Item,
    KeyedReply,
    LineReply,
    ListedReplies,
    NoReply,
    Output,
    Plans,
    Primitive,
    Records,
    Reply,
    Sensor,
    SeveralReplies,
    SubPayloads,
    TaggedReply,
    TaggedStream,
    Written,
    _condition,
    _values,
)
from rdisc.semantics import model as m
from rdisc.semantics.ros import header_frames

__all__ = [
    "LOWERED_ONLY",
    "NO_REPLY",
    "TABLED",
    "Call",
    "Code",
    "Connection",
    "Device",
    "Entry",
    "ErrorReply",
    "FixedReply",
    "Frame",
    "FrameUse",
    "FramedReply",
    "Gives",
    "Hook",
    "Input",
    "Interface",
    "Item",
    "KeyedReply",
    "LineReply",
    "ListedReplies",
    "NoReply",
    "Output",
    "Plans",
    "Primitive",
    "Records",
    "Reply",
    "Sensor",
    "SeveralReplies",
    "SubPayloads",
    "TaggedReply",
    "TaggedStream",
    "Written",
    "frame",
    "lower",
    "written_at_once",
]



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




def _params(params: tuple[m.Parameter, ...]) -> tuple[Construct[engine.Param], ...]:
    return tuple(param(p.name, p.type, p.low, p.high, p.default, params[:i], p.limits) for i, p in enumerate(params))


def _field_type(adapter: m.Adapter, name: str, expr: m.Expr) -> m.AnyType:
    field = adapter.field(name)
    return field.type if field is not None else expr.type
