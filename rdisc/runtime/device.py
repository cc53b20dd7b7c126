"""A description planned for the engine: `load` → `Description` → `connect` → `Robot`.

The Model's plans (`rdisc.lower`) are made the engine's (`rdisc.engine`): each
`Code` a closure over the expressions prepared by `rdisc.semantics.evaluate.prepare`, so a
call walks prepared objects and parses nothing. Everything that happens at run time is
the engine's, the same code a generated driver carries; what the plans are is the
lowering's, the same plans a generated driver is written from.
"""

from __future__ import annotations

import os
import struct
from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import Any, TypeVar, assert_never

from rdisc import engine
from rdisc import lower as plans
from rdisc.diagnostics.load_error import RdisLoadError
from rdisc.engine.plans import plainly_given
from rdisc.lowering.constructs import built
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import Prepared, coerce, prepare

__all__ = ["Description", "load", "wire_frame"]

_EMPTY: Mapping[str, m.Value] = MappingProxyType({})
T = TypeVar("T")


def load(source: str | os.PathLike[str] | m.Model) -> Description:
    """A description ready to connect: a checked Model, or a .rdis / thesis-style .json file.

    A file with errors raises RdisLoadError carrying its diagnostics; nothing of it
    is evaluated.
    """
    if isinstance(source, m.Model):
        return Description(source)
    from rdisc.compile import compile_path

    path = os.fspath(source)
    compilation = compile_path(path)
    if compilation.model is None or compilation.diagnostics.has_errors():
        raise RdisLoadError.of(path, compilation.diagnostics, compilation.sources)
    return Description(compilation.model)


class Description:
    """A checked description, planned once; `connect` runs it against ports."""

    def __init__(self, model: m.Model) -> None:
        self.model = model
        self.name = model.robot.name
        self.device = _Engine().device(plans.lower(model).device)

    def connect(
        self,
        port: engine.PortSpec | None = None,
        timeout: float = 1.0,
        threads: bool = True,
        *,
        on_output: engine.OutputCallback | None = None,
        on_error: engine.ErrorCallback | None = None,
        on_io: engine.IoCallback | None = None,
        settings: Mapping[str, Any] | None = None,
        sim: bool | engine.Simulator = False,
    ) -> engine.Robot:
        """The robot, running: its ports open, its startup hooks run, its threads started.

        `port` is one port (a pyserial port name or URL, or an open pyserial-like
        object) for every connection, or a dict from connection name to port; a
        connection given none opens its `address`. `settings` gives the description's
        settings by name (the others keep their defaults); a value that does not fit its
        type or range is an RdisValueError, before any port is opened. Callbacks given
        here are registered before anything is opened, so they also see what the
        startup hooks do. `sim=True` runs the description against a MuJoCo simulation of its
        body in simulated time (`rdisc.sim.Simulation`, or give one), opening no port:
        `robot.run_for(seconds)` runs its schedule.
        """
        simulator: engine.Simulator | None = None
        if sim is True:
            from rdisc.sim import Simulation

            simulator = Simulation(self.model)
        elif sim is not False:
            simulator = sim
        robot = engine.Robot(self.device, timeout=timeout)
        if on_output is not None:
            robot.on_output(on_output)
        if on_error is not None:
            robot.on_error(on_error)
        if on_io is not None:
            robot.on_io(on_io)
        robot.open(port, threads=threads, settings=settings, sim=simulator)
        return robot



def wire_frame(frame: m.Frame) -> engine.Frame:
    """One frame of the Model as the engine reads and writes it."""
    return _Engine().frame(plans.frame(frame))


class _Engine:
    """The plans as the engine's, each built once (plans are shared: a primitive called by
    many interfaces, an interface by hooks), each Code a closure."""

    def __init__(self) -> None:
        self.done: dict[object, Any] = {}

    def once(self, plan: object, make: Callable[[], T]) -> T:
        if plan not in self.done:
            self.done[plan] = make()
        made: T = self.done[plan]
        return made

    def closure(self, code: plans.Code | None) -> Any:
        """The function a Code says, made once however many plans share it."""
        if code is None:
            return None
        made = {plans.Gives.LIST: _list, plans.Gives.DICT: _dict, plans.Gives.BOOL: _predicate}[code.gives]
        return self.once(code, lambda: made(code))

    def device(self, d: plans.Device) -> engine.Device:
        return engine.Device(
            d.name, dict(d.state), {name: self.connection(c) for name, c in d.connections.items()},
            {name: self.primitive(p) for name, p in d.primitives.items()},
            {name: self.interface(i) for name, i in d.interfaces.items()},
            {name: self.input(i) for name, i in d.inputs.items()}, built(d.settings), dict(d.messages),
        )

    def frame(self, f: plans.Frame) -> engine.Frame:
        return self.once(f, lambda: engine.Frame(
            f.name, built(f.request), built(f.reply), built(f.stuffing), built(f.params), self.closure(f.fields),
            built(f.more_requests), built(f.more_replies), built(f.escaping)))

    def use(self, use: plans.FrameUse) -> engine.FrameUse:
        return engine.FrameUse(self.frame(use.frame), self.closure(use.args))

    def primitive(self, p: plans.Primitive) -> engine.Primitive:
        return self.once(p, lambda: self._primitive(p))

    def _primitive(self, p: plans.Primitive) -> engine.Primitive:
        return engine.Primitive(
            p.name, p.connection, built(p.params), self.closure(p.values), built(p.encoder), reply=self.reply(p.reply),
            actions=self.closure(p.actions), frame=None if p.frame is None else self.use(p.frame), timeout=p.timeout,
            retries=p.retries,
            checked=p.checked, expect=self.closure(p.expect), lines=self.closure(p.lines),
            request=None if p.request is None else self.written(p.request, built(p.params)),
        )

    def reply(self, r: plans.Reply) -> engine.Reply:
        """How the reply is read, as the lowering decided it."""
        match r:
            case plans.NoReply():
                return engine.NO_REPLY
            case plans.LineReply(decoder=decoder):
                return engine.LineReply(decoder.value)
            case plans.FixedReply(decoder=decoder, error=error):
                return engine.FixedReply(decoder.value, error=self.error(error))
            case plans.FramedReply(decoder=decoder, skip=skip, error=error):
                return engine.FramedReply(built(decoder), skip=skip, error=self.error(error))
            case plans.TaggedReply(tag=tag, table=table, skip=skip):
                return engine.TaggedReply(tag, self.table(table), skip=skip)
            case plans.TaggedStream(tag=tag, table=table, skip=skip):
                return engine.TaggedStream(tag, self.table(table), skip=skip)
            case plans.SubPayloads(tag=tag, table=table, length=length, skip=skip):
                return engine.SubPayloads(tag, self.table(table), length, skip=skip)
            case plans.Records(marker=marker, decoder=decoder, skip=skip):
                return engine.Records(marker, decoder.value, skip=skip)
            case plans.KeyedReply(key=key, table=table):
                return engine.KeyedReply(key, self.table(table))
            case plans.SeveralReplies(count=count, each=each, frames=frames):
                return engine.SeveralReplies(count, self.reply(each), tuple(self.use(u) for u in frames))
            case plans.ListedReplies(answers=answers):
                return engine.ListedReplies(tuple(self.primitive(answer) for answer in answers))
            case _:
                assert_never(r)

    def error(self, e: plans.ErrorReply | None) -> engine.ErrorReply | None:
        """The reply that may come instead, as the lowering decided it."""
        if e is None:
            return None
        return engine.ErrorReply(e.decoder.value, e.marker, None if e.frame is None else self.use(e.frame), e.codes,
                                 dict(e.names))

    def table(self, entries: tuple[plans.Entry, ...]) -> dict[int, engine.Primitive]:
        """A reply table: each entry's plan for each of its values (a range entry's plan once)."""
        return {value: self.primitive(entry.plan) for entry in entries for value in entry.case.values()}

    def written(self, w: plans.Written, params: tuple[engine.Param, ...]) -> engine.Request:
        """A primitive's request in one step, as its description says (`plans.Written`); what
        a driver writes as one function."""
        if w.constant is not None:
            constant = w.constant
            return lambda state, args: None if args else constant
        kinds = tuple(prm.kind for prm in params)
        bounds = tuple((i, prm.low, prm.high) for i, prm in enumerate(params) if prm.low is not None)
        leading = _leading_constants(w.values)  # the values: these, then the parameters' in order
        constants = leading or ()
        values = None if leading is not None else self.closure(w.values)
        pack = struct.Struct(w.format).pack
        head, tail, covered, partial = w.head, w.tail, w.covered, w.partial
        checksum: engine.Checksum | None = built(w.checksum)
        pack_check = struct.Struct(w.check_format or "B").pack
        full, flip, mask = _sum_finish(checksum)

        def request(state: Mapping[str, m.Value], args: Any) -> bytes | None:
            if not plainly_given(args, kinds, bounds):
                return None
            try:
                payload = pack(*constants, *args) if values is None else pack(*values(state, args))
            except Exception:  # noqa: BLE001 - the general way says what is wrong
                return None
            if checksum is None:
                return head + payload + tail
            if partial is not None:  # a sum: the covered bytes' summed once
                return head + payload + pack_check((((partial + sum(payload)) & full) ^ flip) & mask) + tail
            return head + payload + pack_check(checksum(covered + payload)) + tail

        return request

    def output(self, o: plans.Output) -> engine.Output:
        return self.once(o, lambda: engine.Output(o.name, self.closure(o.fields), o.adapter, o.frame,
                                                               o.child_frame))

    def interface(self, i: plans.Interface) -> engine.Interface:
        return self.once(i, lambda: engine.Interface(i.name, built(i.params), tuple(self.call(c) for c in i.calls),
                                                     tuple(self.output(o) for o in i.outputs)))

    def call(self, c: plans.Call) -> engine.Call:
        target = self.primitive(c.target) if isinstance(c.target, plans.Primitive) else self.interface(c.target)
        return engine.Call(target, self.closure(c.args), c.delay, c.direct, self.closure(c.when),
                           self.closure(c.until), c.every, c.within)

    def input(self, i: plans.Input) -> engine.Input:
        made = engine.Input(i.name, i.adapter, built(i.fields), self.interface(i.interface), self.closure(i.args))
        assert (made.request is not None) == i.request, f"{i.name}: the lowering and the engine disagree"
        return made

    def connection(self, c: plans.Connection) -> engine.Connection:
        def hook(h: plans.Hook | None) -> engine.Hook | None:
            return None if h is None else engine.Hook(self.interface(h.interface), self.closure(h.args))

        return engine.Connection(
            c.name, c.baud, c.address, c.terminator, c.frequency, tuple(self.interface(i) for i in c.periodic),
            hook(c.startup), hook(c.terminate), hook(c.keepalive), c.interval, c.baud_setting,
        )


def _leading_constants(code: plans.Code) -> tuple[m.Value, ...] | None:
    """The constants a primitive's format values start with, when the parameters' values follow
    them as they are, in order (an opcode and the parameters: `pack(*constants, *args)`)."""
    count = len(code.items) - len(code.params)
    if count < 0 or any(not isinstance(e, m.Const) or type_ is not None for _, e, type_ in code.items[:count]):
        return None
    for (_, e, type_), prm in zip(code.items[count:], code.params):
        if not isinstance(e, m.Var) or e.scope is not m.Scope.PARAM or e.name != prm.name or type_ is not None:
            return None
    return tuple(e.value for _, e, _ in code.items[:count] if isinstance(e, m.Const))


def _sum_finish(checksum: engine.Checksum | None) -> tuple[int, int, int]:
    """A "sum" checksum's last steps, as masks: kept to its width, inverted (XOR), masked."""
    if checksum is None:
        return 0, 0, 0
    full = (1 << checksum.width) - 1
    return full, full if checksum.inverted else 0, full if checksum.mask is None else checksum.mask


def _slots(code: plans.Code) -> dict[str, int]:
    return {p.name: i for i, p in enumerate(code.params)}


def _list(code: plans.Code) -> Any:
    """A LIST code as a closure taking what it takes: its items' values, bound to their
    types, arrays marked "*" given element by element."""
    slots = _slots(code)
    values = _values([_bound(e, type_, slots) for _, e, type_ in code.items])
    values = _spread(values, tuple(i for i, (key, _, _) in enumerate(code.items) if key == "*"))
    match code.takes:
        case ("state", "args"):
            return values
        case ("args",):
            return lambda args: values(_EMPTY, args)
        case ("state",):
            return lambda state: values(state, _EMPTY)
    raise AssertionError(code.takes)


def _dict(code: plans.Code) -> Any:
    """A DICT code as a closure: its items' values by key, each coerced to its type if it has one
    (all have or none has)."""
    slots = _slots(code)
    typed = [(key, prepare(e, slots), type_) for key, e, type_ in code.items if type_ is not None]
    if not typed:
        plain = [(key, prepare(e, slots)) for key, e, _ in code.items]
        match code.takes:
            case ("state", "args"):
                return lambda s, loc: {key: f(s, loc, ()) for key, f in plain}
    assert len(typed) == len(code.items), "all typed or none"
    match code.takes:
        case ("state", "args", "reply"):
            return lambda s, loc, r: {key: coerce(f(s, loc, r), t) for key, f, t in typed}
        case ("state",):
            return lambda s: {key: coerce(f(s, _EMPTY, ()), t) for key, f, t in typed}
    raise AssertionError(code.takes)


def _predicate(code: plans.Code) -> Any:
    """A BOOL code as a closure: its one item's value (the engine tests its truth)."""
    ((_, e, _),) = code.items
    holds = prepare(e, _slots(code))
    match code.takes:
        case ("state", "args", "reply"):
            return holds
        case ("state", "args"):
            return lambda state, local: holds(state, local, ())
    raise AssertionError(code.takes)


def _bound(e: m.Expr, type_: m.AnyType | None, slots: dict[str, int]) -> Prepared | m.Const:
    """`e` prepared, bound to `type_` as the contract binds values (an int made a float where a
    float is declared); a constant given as it is, which `_values` puts in as it is."""
    if type_ is None and isinstance(e, m.Const):
        return e
    f = prepare(e, slots)
    if type_ is m.Type.FLOAT and e.type is m.Type.INT:
        return _widened(f)
    if isinstance(type_, m.Array) and type_.element is m.Type.FLOAT and isinstance(e.type, m.Array) \
            and e.type.element is m.Type.INT:
        return lambda s, loc, r: coerce(f(s, loc, r), type_)
    return f


def _widened(f: Prepared) -> Prepared:
    def widened(s: Mapping[str, m.Value], loc: Any, r: Any) -> m.Value:
        value = f(s, loc, r)
        return float(value) if type(value) is int else value

    return widened


def _spread(values: Callable[[Mapping[str, m.Value], Any], list[m.Value]],
            arrays: tuple[int, ...]) -> Callable[[Mapping[str, m.Value], Any], list[m.Value]]:
    """Format values with the arrays among them (at `arrays`) given element by element."""
    if not arrays:
        return values

    def spread(s: Mapping[str, m.Value], loc: Any) -> list[m.Value]:
        flat: list[m.Value] = []
        for i, v in enumerate(values(s, loc)):
            flat.extend(v) if i in arrays else flat.append(v)  # type: ignore[arg-type]
        return flat

    return spread


def _values(fs: list[Prepared | m.Const]) -> Callable[[Mapping[str, m.Value], Any], list[m.Value]]:
    """The prepared expressions (or constants) `fs` evaluated in turn, as a list.

    For speed, up to three are unrolled (a list comprehension costs more than
    the calls themselves), and a leading constant (an opcode) is put in as it is.
    """
    prepared: list[Prepared] = [prepare(f) if isinstance(f, m.Const) else f for f in fs]
    if fs and isinstance(fs[0], m.Const):
        c = fs[0].value
        match prepared:
            case [_, f]:
                return lambda s, loc: [c, f(s, loc, ())]
            case [_, f, g]:
                return lambda s, loc: [c, f(s, loc, ()), g(s, loc, ())]
    match prepared:
        case []:
            return lambda s, loc: []
        case [f]:
            return lambda s, loc: [f(s, loc, ())]
        case [f, g]:
            return lambda s, loc: [f(s, loc, ()), g(s, loc, ())]
        case [f, g, h]:
            return lambda s, loc: [f(s, loc, ()), g(s, loc, ()), h(s, loc, ())]
    return lambda s, loc: [f(s, loc, ()) for f in prepared]
