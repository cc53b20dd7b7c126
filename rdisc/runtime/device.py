"""A description planned for the engine: `load` → `Description` → `connect` → `Robot`.

The Model's plans (`rdisc.lower`) are made the engine's (`rdisc.engine`): each
`Code` a closure over the expressions prepared by `rdisc.semantics.evaluate.prepare`, so a
call walks prepared objects and parses nothing. Everything that happens at run time is
the engine's, the same code a generated driver carries; what the plans are is the
lowering's, the same plans a generated driver is written from.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from typing import Any, TypeVar, assert_never

from rdisc import engine
from rdisc import lower as plans
from rdisc.diagnostics.load_error import RdisLoadError
from rdisc.lowering.constructs import built
from rdisc.runtime.at_once import input_request, primitive_request
from rdisc.runtime.closures import closure
from rdisc.semantics import model as m

__all__ = ["Description", "load", "wire_frame"]

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
        return self.once(code, lambda: closure(code))

    def device(self, d: plans.Device) -> engine.Device:
        return engine.Device(
            d.name, dict(d.state), {name: self.connection(c) for name, c in d.connections.items()},
            {name: self.primitive(p) for name, p in d.primitives.items()},
            {name: self.interface(i) for name, i in d.interfaces.items()},
            {name: self.input(i) for name, i in d.inputs.items()}, built(d.settings), dict(d.messages),
            {name: engine.Sensor(name, self.primitive(s.primitive), s.cache) for name, s in d.sensors.items()},
        )

    def frame(self, f: plans.Frame) -> engine.Frame:
        return self.once(f, lambda: engine.Frame(
            f.name, built(f.request), built(f.reply), built(f.stuffing), built(f.params), self.closure(f.fields),
            built(f.more_requests), built(f.more_replies), built(f.escaping), self.closure(f.choose),
            self.closure(f.answer)))

    def use(self, use: plans.FrameUse) -> engine.FrameUse:
        return engine.FrameUse(self.frame(use.frame), self.closure(use.args))

    def primitive(self, p: plans.Primitive) -> engine.Primitive:
        return self.once(p, lambda: self._primitive(p))

    def _primitive(self, p: plans.Primitive) -> engine.Primitive:
        return engine.Primitive(
            p.name, p.connection, built(p.params), self.closure(p.values), built(p.encoder), reply=self.reply(p.reply),
            actions=self.closure(p.actions), frame=None if p.frame is None else self.use(p.frame), timeout=p.timeout,
            retries=p.retries,
            checked=p.checked, expect=self.closure(p.expect), lines=self.closure(p.lines), looks_up=p.looks_up,
            actuators=built(p.actuators),
            request=None if p.request is None else primitive_request(p.request, built(p.params), self.closure),
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
            case plans.TaggedStream(tag=tag, table=table, skip=skip, nested=nested):
                return engine.TaggedStream(tag, self.table(table), skip=skip, nested=nested)
            case plans.SubPayloads(tag=tag, table=table, length=length, skip=skip):
                return engine.SubPayloads(tag, self.table(table), length, skip=skip)
            case plans.Records(marker=marker, decoder=decoder, skip=skip):
                return engine.Records(marker, decoder.value, skip=skip)
            case plans.KeyedReply(key=key, table=table):
                return engine.KeyedReply(key, self.table(table))
            case plans.SeveralReplies(count=count, each=each, frames=frames, over=over):
                return engine.SeveralReplies(count, self.reply(each), tuple(self.use(u) for u in frames), over)
            case plans.ListedReplies(answers=answers):
                return engine.ListedReplies(tuple(self.primitive(answer) for answer in answers))
            case _:
                assert_never(r)

    def error(self, e: plans.ErrorReply | None) -> engine.ErrorReply | None:
        """The reply that may come instead, as the lowering decided it."""
        if e is None:
            return None
        return engine.ErrorReply(e.decoder.value, e.marker, None if e.frame is None else self.use(e.frame), e.codes,
                                 dict(e.names), self.closure(e.when))

    def table(self, entries: tuple[plans.Entry, ...]) -> dict[Any, engine.Primitive]:
        """A reply table: each entry's plan for each of its keys (a range entry's plan once)."""
        return {key: self.primitive(entry.plan) for entry in entries for key in entry.case.table_keys()}

    def output(self, o: plans.Output) -> engine.Output:
        return self.once(o, lambda: engine.Output(o.name, self.closure(o.fields), o.adapter, o.frame,
                                                               o.child_frame, built(o.filters), o.sensors))

    def interface(self, i: plans.Interface) -> engine.Interface:
        return self.once(i, lambda: engine.Interface(i.name, built(i.params), tuple(self.call(c) for c in i.calls),
                                                     tuple(self.output(o) for o in i.outputs), i.sensors))

    def call(self, c: plans.Call) -> engine.Call:
        target = self.primitive(c.target) if isinstance(c.target, plans.Primitive) else self.interface(c.target)
        return engine.Call(target, self.closure(c.args), c.delay, c.direct, self.closure(c.when),
                           self.closure(c.until), c.every, c.within)

    def input(self, i: plans.Input) -> engine.Input:
        interface = self.interface(i.interface)
        request = input_request(i, built(i.fields), interface.params) if i.request else None
        made = engine.Input(i.name, i.adapter, built(i.fields), interface, self.closure(i.args), request=request,
                            sensors=i.sensors)
        assert (made.request is not None) == i.request, f"{i.name}: the lowering and the engine disagree"
        return made

    def connection(self, c: plans.Connection) -> engine.Connection:
        def hook(h: plans.Hook | None) -> engine.Hook | None:
            return None if h is None else engine.Hook(self.interface(h.interface), self.closure(h.args))

        return engine.Connection(
            c.name, c.baud, c.address, c.terminator, c.frequency, tuple(self.interface(i) for i in c.periodic),
            hook(c.startup), hook(c.terminate), hook(c.keepalive), c.interval, c.baud_setting,
            c.data_bits, c.parity, c.stop_bits, c.threading, c.rates,
        )
