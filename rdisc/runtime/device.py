"""A description planned for the engine: `load` → `Description` → `connect` → `Robot`.

The Model is turned once into the engine's plans (`rdisc.engine`): encoders,
decoders and frames as data, and each expression of the checked IR prepared by
`rdisc.runtime.evaluate.prepare` into a closure, so a call walks prepared objects
and parses nothing. Everything that happens at run time is the engine's, the same
code a generated driver carries.
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import Any

from rdisc import engine
from rdisc.runtime.codec import decoder, encoder, frame_fields, wire_frame
from rdisc.runtime.errors import RdisLoadError
from rdisc.runtime.evaluate import Prepared, coerce, prepare
from rdisc.runtime.messages import recorded_messages
from rdisc.semantics import model as m

__all__ = ["Description", "load"]

_KINDS: dict[m.Type, type] = {m.Type.INT: int, m.Type.FLOAT: float, m.Type.BOOL: bool, m.Type.STRING: str,
                              m.Type.BYTES: bytes}
_EMPTY: Mapping[str, m.Value] = MappingProxyType({})


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
        raise RdisLoadError.from_compilation(path, compilation)
    return Description(compilation.model)


class Description:
    """A checked description, planned once; `connect` runs it against ports."""

    def __init__(self, model: m.Model) -> None:
        self.model = model
        self.name = model.robot.name
        self._frames = {f.name: self._frame(f) for f in model.frames.values()}
        primitives = {p.name: self._primitive(p) for p in model.primitives.values()}
        outputs = {o.name: self._output(o) for o in model.outputs.values()}
        planned: dict[str, engine.Interface] = {}
        for iface in model.callees_first():
            planned[iface.name] = self._interface(iface, primitives, outputs, planned)
        interfaces = {name: planned[name] for name in model.interfaces}
        inputs = {i.name: self._input(i, interfaces) for i in model.inputs.values()}
        connections = {c.name: self._connection(c, interfaces) for c in model.connections.values()}
        state = {s.name: s.default for s in model.settings.values()} | {s.name: s.initial for s in model.states.values()}
        settings = tuple(_param(s.name, s.type, s.low, s.high, s.default) for s in model.settings.values())
        self.device = engine.Device(self.name, state, connections, primitives, interfaces, inputs, settings,
                                    recorded_messages(model))

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

    # ---- plans ----------------------------------------------------------------------------------

    def _primitive(self, p: m.Primitive, local: tuple[m.Parameter, ...] | None = None) -> engine.Primitive:
        """The plan of a primitive; `local`, what its post-actions read besides state and the
        reply, when that is more than its parameters and its own (a tag's entry reads the tag)."""
        if p.table is not None:  # one plan for each key or tag, chosen when it is called or read
            plain = self._primitive(dataclasses.replace(p, table=None))
            table: dict[int, engine.Primitive] = {}
            for c in p.table.cases:  # a range entry's plan once, for each of its values
                table.update(dict.fromkeys(c.values(), self._primitive(p.case(c), p.reply_locals())))
            if p.table.tag is not None:
                return dataclasses.replace(plain, table=table, tag=p.table.tag, each=p.table.each,
                                           length=p.table.length)
            key = next(i for i, param in enumerate(p.params) if param.name == p.table.key)
            return dataclasses.replace(plain, table=table, key=key)
        slots = _slots(local or p.reply_locals())
        actions = None
        if p.actions:
            prepared = [(a.target, prepare(a.value, slots), self.model.states[a.target].type) for a in p.actions]
            actions = lambda s, loc, r: {t: coerce(f(s, loc, r), type_) for t, f, type_ in prepared}
        checked = tuple(a.target for a in p.actions
                        if self.model.states[a.target].type is m.Type.INT and m.may_outgrow(a.value))
        frame = None
        if p.frame is not None:
            frame = engine.FrameUse(self._frames[p.frame.frame], _values([prepare(a, slots) for a in p.frame.args]))
        expect = None if p.expect is None else prepare(p.expect, slots)
        answers = tuple(engine.FrameUse(self._frames[use.frame], _values([prepare(a, slots) for a in use.args]))
                        for use in p.reply_frames)
        return engine.Primitive(
            p.name, p.connection, _params(p.params), _spread(_values([prepare(a, slots) for a in p.args]), p.spreads()),
            None if p.encoding is None else encoder(p.encoding), decoder(p.decoding), actions, frame,
            p.skip_unmatched, None if p.timeout_ms is None else p.timeout_ms / 1000.0, checked=checked,
            expect=expect, lines=_levels(p.lines, slots), replies=p.replies, reply_frames=answers,
            answers=tuple(self._primitive(p.listed_reply(r)) for r in p.listed),
            records=None if p.records is None else p.records.encode("latin-1"),
        )

    def _frame(self, frame: m.Frame) -> engine.Frame:
        fields = _values([prepare(e, _slots(frame.params)) for _, e in frame_fields(frame)])
        return wire_frame(frame, _params(frame.params), lambda args: fields(_EMPTY, args))

    def _output(self, o: m.DomainOutput) -> engine.Output:
        adapter = self.model.adapters[o.adapter]
        fields = [(name, prepare(e), _field_type(adapter, name, e)) for name, e in o.fields]
        return engine.Output(o.name, lambda s: {name: coerce(f(s, _EMPTY, ()), t) for name, f, t in fields}, o.adapter)

    def _interface(self, iface: m.Interface, primitives: Mapping[str, engine.Primitive],
                   outputs: Mapping[str, engine.Output], callees: Mapping[str, engine.Interface]) -> engine.Interface:
        """The interface's plan; `callees`, the plans of the interfaces it calls."""
        slots = _slots(iface.params)
        calls = []
        for c in iface.run_order():
            if c.interface:
                args = _values([prepare(a, slots) for a in c.args])
                call = engine.Call(callees[c.primitive], args, c.delay_ms / 1000.0)
            else:
                call = self._call(c, slots, primitives[c.primitive])
            if c.when is not None:
                call = dataclasses.replace(call, when=_condition(prepare(c.when, slots)))
            calls.append(call)
        triggered = tuple(outputs[o] for o in iface.triggers)
        return engine.Interface(iface.name, _params(iface.params), tuple(calls), triggered)

    def _call(self, call: m.PrimitiveCall, slots: dict[str, int], plan: engine.Primitive) -> engine.Call:
        """A call of a primitive, with its format arguments substituted where that changes
        nothing (`formats_its_params`): its format values are computed straight from the
        call's arguments, the same expressions evaluated in the same order."""
        primitive = self.model.primitives[call.primitive]
        delay = call.delay_ms / 1000.0
        if not primitive.formats_its_params():
            return engine.Call(plan, _values([prepare(a, slots) for a in call.args]), delay)
        by_param = {p.name: (p, arg) for p, arg in zip(primitive.params, call.args)}
        direct: list[Prepared | m.Const] = []
        for arg in primitive.args:
            if isinstance(arg, m.Var):
                param, expr = by_param[arg.name]
                widen = param.type is m.Type.FLOAT and expr.type is m.Type.INT
                direct.append(_widened(prepare(expr, slots)) if widen else prepare(expr, slots))
            else:
                assert isinstance(arg, m.Const)  # `simple`
                direct.append(arg)  # a constant, such as an opcode
        return engine.Call(plan, _values(direct), delay, direct=True)

    def _input(self, i: m.DomainInput, interfaces: Mapping[str, engine.Interface]) -> engine.Input:
        adapter = self.model.adapters[i.adapter]
        fields = tuple(_param(f.name, f.type) for f in adapter.fields)
        slots = {f.name: n for n, f in enumerate(adapter.fields)}
        return engine.Input(i.name, i.adapter, fields, interfaces[i.interface],
                            _values([prepare(a, slots) for a in i.args]))

    def _connection(self, c: m.Connection, interfaces: Mapping[str, engine.Interface]) -> engine.Connection:
        def hook(call: m.HookCall | None) -> engine.Hook | None:
            if call is None:
                return None
            args = _values([prepare(a) for a in call.args])
            return engine.Hook(interfaces[call.interface], lambda s: args(s, _EMPTY))

        periodic = tuple(interfaces[i.name] for i in self.model.interfaces.values()
                         if i.periodic and self.model.owner(i) == c.name)
        keepalive = c.keepalive
        return engine.Connection(
            c.name, c.baud, c.address, c.terminator_bytes(), c.frequency_hz, periodic, hook(c.startup),
            hook(c.terminate), hook(keepalive.call if keepalive else None),
            keepalive.interval_ms / 1000.0 if keepalive else 0.0, c.baud_setting,
        )


def _params(params: tuple[m.Parameter, ...]) -> tuple[engine.Param, ...]:
    return tuple(_param(p.name, p.type, p.low, p.high, p.default) for p in params)


def _param(name: str, type_: m.AnyType, low: float | None = None, high: float | None = None,
           default: m.Value | None = None) -> engine.Param:
    if isinstance(type_, m.Array):
        return engine.Param(name, _KINDS[type_.element], low, high, default, type_.size)
    return engine.Param(name, _KINDS[type_], low, high, default)


def _levels(lines: tuple[m.LineLevel, ...],
            slots: dict[str, int]) -> Callable[[Mapping[str, m.Value], Any], dict[str, m.Value]] | None:
    """A primitive's modem lines, over state and its parameters: each line's level, in order."""
    if not lines:
        return None
    prepared = [(level.line, prepare(level.value, slots)) for level in lines]
    return lambda state, local: {line: f(state, local, ()) for line, f in prepared}


def _condition(holds: Prepared) -> Callable[[Mapping[str, m.Value], Any], m.Value]:
    """A call's `when`, over state and the interface's parameters."""
    return lambda state, local: holds(state, local, ())


def _slots(params: tuple[m.Parameter, ...]) -> dict[str, int]:
    return {p.name: i for i, p in enumerate(params)}


def _field_type(adapter: m.Adapter, name: str, expr: m.Expr) -> m.Type:
    field = adapter.field(name)
    return field.type if field is not None else expr.type


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
