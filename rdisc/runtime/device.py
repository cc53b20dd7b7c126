"""A description running against devices: `load` → `Description` → `connect` → `Robot`.

The Model is turned once into plans (codecs, run orders, delays in seconds, and
each expression of the checked IR prepared by `rdisc.runtime.evaluate.prepare`),
so a call walks prepared objects and parses nothing. The semantics are the
contract in the docstring of `rdisc.runtime`.

State lives in a dict that is never changed in place: post-actions build a new
one under the state lock and publish it with one assignment, so any reader sees
a consistent snapshot without locking.
"""

from __future__ import annotations

import dataclasses
import logging
import numbers
import os
import struct
import threading
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from rdisc.runtime import framing
from rdisc.runtime.codec import MAX_LINE, Codec, frame_fields, wire_frame
from rdisc.runtime.errors import (
    RdisCallbackError,
    RdisConnectionError,
    RdisError,
    RdisLoadError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)
from rdisc.runtime.evaluate import EvalError, Prepared, always_float, coerce, prepare
from rdisc.runtime.scheduler import Worker
from rdisc.semantics import model as m

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["Description", "Robot", "load"]

log = logging.getLogger("rdisc")

OutputCallback = Callable[[dict[str, Any]], Any]
ErrorCallback = Callable[[BaseException], Any]
IoCallback = Callable[[str, str, bytes], Any]

# Everything evaluating an expression can raise besides EvalError: a bad operand
# type or a huge number cannot come from a checked model, but a value read from a
# device can still make a function refuse it.
_EVAL_ERRORS = (EvalError, ArithmeticError, ValueError, TypeError, OverflowError, IndexError)


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


# ---- plans: the Model prepared for running ----------------------------------------------


# Parameters are bound by position: a primitive's or an interface's values are a
# list, widened in place (`float_slots`), and its expressions read them by index.
Values = Callable[[Mapping[str, m.Value], Any], list[m.Value]]
"""Prepared expressions evaluated in turn: `values(state, local)` is the list of their values."""


Ranges = tuple[tuple[int, str, float, float], ...]
"""The declared ranges of parameters: (position, name, low, high)."""


@dataclass(frozen=True, slots=True)
class _PrimitivePlan:
    name: str
    connection: str
    params: tuple[tuple[str, m.Type], ...]
    float_slots: tuple[int, ...]  # positions of the float parameters, where an int is widened
    args: Values
    codec: Codec
    actions: tuple[tuple[str, Prepared, m.Type], ...]
    frame: _FramePlan | None = None
    expects_reply: bool = False
    ranges: Ranges = ()
    skip: bool = False  # frames that do not decode are skipped (within the timeout)
    cases: dict[int, _PrimitivePlan] | None = None  # a reply table: the plan for each value of the key
    key: int = 0  # the key parameter's position
    timeout: float | None = None  # seconds its reply may take, instead of the robot's
    tag: struct.Struct | None = None  # a reply chosen by its tag: the tag's format (`cases` by tag)


@dataclass(frozen=True, slots=True)
class _FramePlan:
    """A primitive's frame: the frame's arguments (over the primitive's parameters),
    its field values (over the frame's arguments) and the wire frame."""

    args: Values
    fields: Values
    wire: framing.Frame
    reads: bool  # the reply is framed (else it is read as the primitive's decoding says)


@dataclass(frozen=True, slots=True)
class _CallPlan:
    primitive: _PrimitivePlan
    args: Values  # the call's arguments; if `direct`, the primitive's format values
    delay: float  # seconds
    direct: bool = False


@dataclass(frozen=True, slots=True)
class _OutputPlan:
    name: str
    fields: tuple[tuple[str, Prepared, m.Type], ...]


@dataclass(frozen=True, slots=True)
class _InterfacePlan:
    name: str
    params: tuple[tuple[str, m.Type], ...]
    float_slots: tuple[int, ...]
    calls: tuple[_CallPlan, ...]  # in run order
    output: _OutputPlan | None
    connection: str | None  # the owner, for a periodic interface
    ranges: Ranges = ()


@dataclass(frozen=True, slots=True)
class _InputPlan:
    name: str
    adapter: str
    fields: tuple[tuple[str, m.Type, type[Any]], ...]  # name, declared type, its Python type
    args: Values  # over the fields, by name
    interface: _InterfacePlan
    widen: tuple[int, ...]  # the interface's float parameters whose argument may be an int
    call: _CallPlan | None  # the interface's one call, when it is direct and has no delay


@dataclass(frozen=True, slots=True)
class _HookPlan:
    interface: _InterfacePlan
    args: Values  # over state only


class Description:
    """A checked description, prepared once; `connect` runs it against ports."""

    def __init__(self, model: m.Model) -> None:
        self.model = model
        self.name = model.robot.name
        self.primitives = {p.name: self._primitive(p) for p in model.primitives.values()}
        self.outputs = {o.name: self._output(o) for o in model.outputs.values()}
        self.interfaces = {i.name: self._interface(i) for i in model.interfaces.values()}
        self.inputs = {i.name: self._input(i) for i in model.inputs.values()}
        self.initial_state: dict[str, m.Value] = {s.name: s.initial for s in model.states.values()}
        self.periodic: dict[str, list[_InterfacePlan]] = {}  # connection -> its periodic interfaces
        for iface in model.interfaces.values():
            plan = self.interfaces[iface.name]
            if iface.periodic and plan.connection is not None:
                self.periodic.setdefault(plan.connection, []).append(plan)

    def _primitive(self, p: m.Primitive) -> _PrimitivePlan:
        if p.table is not None:  # one plan for each value of the key, chosen when it is called
            plain = self._primitive(dataclasses.replace(p, table=None))
            cases = {c.value: self._primitive(p.case(c)) for c in p.table.cases}
            if p.table.tag is not None:
                return dataclasses.replace(plain, cases=cases, tag=struct.Struct(p.table.tag), expects_reply=True)
            key = next(i for i, param in enumerate(p.params) if param.name == p.table.key)
            return dataclasses.replace(plain, cases=cases, key=key)
        slots = _slots(p.params)
        actions = tuple((a.target, prepare(a.value, slots), self.model.states[a.target].type) for a in p.actions)
        frame = None
        if p.frame is not None:
            model_frame = self.model.frames[p.frame.frame]
            fields = [prepare(e, _slots(model_frame.params)) for e in frame_fields(model_frame).values()]
            frame = _FramePlan(_values([prepare(a, slots) for a in p.frame.args]), _values(fields),
                               wire_frame(model_frame), bool(model_frame.reply))
        return _PrimitivePlan(p.name, p.connection, _params(p.params), _float_slots(p.params),
                              _values([prepare(a, slots) for a in p.args]),
                              Codec(p, self.model.connections[p.connection].terminator_bytes()), actions,
                              frame, p.expects_reply(self.model.frames), _ranges(p.params), p.skip_unmatched,
                              timeout=None if p.timeout_ms is None else p.timeout_ms / 1000.0)

    def _output(self, o: m.DomainOutput) -> _OutputPlan:
        adapter = self.model.adapters[o.adapter]
        return _OutputPlan(o.name, tuple((name, prepare(e), _field_type(adapter, name, e)) for name, e in o.fields))

    def _interface(self, iface: m.Interface) -> _InterfacePlan:
        slots = _slots(iface.params)
        calls = tuple(self._call(c, slots) for c in iface.run_order())
        owner = calls[0].primitive.connection if calls else next(iter(self.model.connections), None)
        output = self.outputs[iface.triggers] if iface.triggers else None
        return _InterfacePlan(iface.name, _params(iface.params), _float_slots(iface.params), calls, output, owner,
                              _ranges(iface.params))

    def _call(self, call: m.PrimitiveCall, slots: dict[str, int]) -> _CallPlan:
        """A call, with the primitive's format arguments substituted where that changes nothing.

        When the primitive has no post-actions and its format arguments are
        constants and its parameters, each once and in order, its format values
        are computed straight from the call's arguments (no binding in between):
        the same expressions are evaluated, in the same order.
        """
        primitive = self.model.primitives[call.primitive]
        plan = self.primitives[call.primitive]
        delay = call.delay_ms / 1000.0
        params = [p.name for p in primitive.params]
        used = [a.name for a in primitive.args if isinstance(a, m.Var) and a.scope is m.Scope.PARAM]
        simple = all(isinstance(a, m.Const) or (isinstance(a, m.Var) and a.scope is m.Scope.PARAM)
                     for a in primitive.args)
        if (primitive.actions or primitive.frame or primitive.table or _ranges(primitive.params) or not simple
                or used != params):
            return _CallPlan(plan, _values([prepare(a, slots) for a in call.args]), delay)
        by_param = dict(zip(params, zip(primitive.params, call.args)))
        direct: list[Prepared | m.Const] = []
        for arg in primitive.args:
            if isinstance(arg, m.Var):
                param, expr = by_param[arg.name]
                direct.append(_widened(prepare(expr, slots)) if param.type is m.Type.FLOAT
                              and expr.type is m.Type.INT else prepare(expr, slots))
            else:
                assert isinstance(arg, m.Const)  # `simple`
                direct.append(arg)  # a constant, such as an opcode
        return _CallPlan(plan, _values(direct), delay, direct=True)

    def _input(self, i: m.DomainInput) -> _InputPlan:
        fields = tuple((f.name, f.type, _PYTHON_TYPES[f.type]) for f in self.model.adapters[i.adapter].fields)
        interface = self.interfaces[i.interface]
        widen = tuple(slot for slot in interface.float_slots if not always_float(i.args[slot]))
        calls = interface.calls
        direct = len(calls) == 1 and calls[0].direct and not calls[0].delay and not interface.ranges
        call = calls[0] if direct else None
        return _InputPlan(i.name, i.adapter, fields, _values([prepare(a) for a in i.args]), interface, widen, call)

    def hook(self, hook: m.HookCall) -> _HookPlan:
        return _HookPlan(self.interfaces[hook.interface], _values([prepare(a) for a in hook.args]))

    def connect(
        self,
        port: str | Any | Mapping[str, str | Any] | None = None,
        timeout: float = 1.0,
        threads: bool = True,
        *,
        on_output: OutputCallback | None = None,
        on_error: ErrorCallback | None = None,
        on_io: IoCallback | None = None,
    ) -> Robot:
        """Open the ports, run the startup hooks, start the connections' threads.

        `port` is one port (a pyserial port name or URL, or an open pyserial-like
        object) for every connection, or a dict from connection name to port; a
        connection given none opens its `address`.
        Callbacks given here are registered before anything is opened, so they
        also see what the startup hooks do.
        """
        return Robot(self, port, timeout, threads, on_output=on_output, on_error=on_error, on_io=on_io)


def _widened(f: Prepared) -> Prepared:
    def widened(s: Mapping[str, m.Value], loc: Mapping[str, m.Value], r: Any) -> m.Value:
        value = f(s, loc, r)
        return float(value) if type(value) is int else value

    return widened


def _tagged(plan: _PrimitivePlan, payload: bytes) -> tuple[_PrimitivePlan, tuple[m.Value, ...]]:
    """The entry a reply's tag chooses, and the rest of the payload decoded by it."""
    assert plan.tag is not None and plan.cases is not None
    if len(payload) < plan.tag.size:
        raise RdisProtocolError(f"{plan.name}: expected {plan.tag.size} bytes or more, got {len(payload)}")
    tag = plan.tag.unpack_from(payload)[0]
    case = plan.cases.get(tag)
    if case is None:
        raise RdisProtocolError(f"{plan.name}: no reply entry for tag {tag}")
    rest = payload[plan.tag.size :]
    return case, case.codec.match_payload(rest) if case.codec.reads_line else case.codec.decode(rest)


def _ranges(params: tuple[m.Parameter, ...]) -> Ranges:
    return tuple((i, p.name, p.low, p.high) for i, p in enumerate(params) if p.low is not None)  # type: ignore[misc]


def _in_ranges(owner: str, ranges: Ranges, values: list[m.Value]) -> None:
    """A value outside its parameter's declared range is refused before anything is sent."""
    for i, name, low, high in ranges:
        value = values[i]
        if isinstance(value, bytes):
            if not low <= len(value) <= high:
                raise RdisValueError(f"{owner}: parameter {name} has {len(value)} bytes, outside {low!r}..{high!r}")
        elif not low <= value <= high:  # type: ignore[operator]
            raise RdisValueError(f"{owner}: parameter {name} is {value!r}, outside {low!r}..{high!r}")


def _params(params: tuple[m.Parameter, ...]) -> tuple[tuple[str, m.Type], ...]:
    return tuple((p.name, p.type) for p in params)


def _slots(params: tuple[m.Parameter, ...]) -> dict[str, int]:
    return {p.name: i for i, p in enumerate(params)}


def _float_slots(params: tuple[m.Parameter, ...]) -> tuple[int, ...]:
    return tuple(i for i, p in enumerate(params) if p.type is m.Type.FLOAT)


def _values(fs: list[Prepared | m.Const]) -> Values:
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


def _field_type(adapter: m.Adapter, name: str, expr: m.Expr) -> m.Type:
    field = adapter.field(name)
    return field.type if field is not None else expr.type


# ---- ports --------------------------------------------------------------------------------


class _Port:
    """One open port, shared by the connections given the same one, with its exchange lock."""

    __slots__ = ("input", "io", "label", "lock", "owned")

    def __init__(self, io: Any, owned: bool, label: str) -> None:
        self.io = io
        self.input = framing.Input(io)  # for frames: the port's input, with bytes a bad frame gave back
        self.owned = owned
        self.label = label
        self.lock = threading.Lock()


def _open(connection: m.Connection, port: str, timeout: float) -> Any:
    import serial  # type: ignore[import-untyped]

    try:
        return serial.serial_for_url(
            port, baudrate=connection.baud, bytesize=8, parity="N", stopbits=1,
            timeout=timeout, write_timeout=timeout,
        )
    except (serial.SerialException, OSError, ValueError) as err:
        raise RdisConnectionError(f"{connection.name}: cannot open {port}: {err}") from err


def _write_timeout_types() -> tuple[type[BaseException], ...]:
    try:
        from serial import SerialTimeoutException  # type: ignore[import-untyped]
    except ImportError:  # pragma: no cover - pyserial is a dependency
        return ()
    return (SerialTimeoutException,)


_WRITE_TIMEOUTS = _write_timeout_types()


# ---- the running robot ---------------------------------------------------------------------


class Robot:
    """A description connected to its devices. Use it as a context manager, or call close()."""

    def __init__(
        self,
        description: Description,
        port: str | Any | Mapping[str, str | Any] | None = None,
        timeout: float = 1.0,
        threads: bool = True,
        *,
        on_output: OutputCallback | None = None,
        on_error: ErrorCallback | None = None,
        on_io: IoCallback | None = None,
    ) -> None:
        self.description = description
        self.model = description.model
        self.name = description.name
        self.timeout = timeout
        self._inputs = description.inputs
        self._state: dict[str, m.Value] = dict(description.initial_state)
        self._state_lock = threading.Lock()
        self._callback_lock = threading.RLock()
        self._output_callbacks: list[OutputCallback] = []
        self._error_callbacks: list[ErrorCallback] = []
        self._io_callbacks: list[IoCallback] = []
        self._ports: dict[str, _Port] = {}
        self._workers: list[Worker] = []
        self._closed = False
        self._close_lock = threading.Lock()
        if on_output is not None:
            self.on_output(on_output)
        if on_error is not None:
            self.on_error(on_error)
        if on_io is not None:
            self.on_io(on_io)
        try:
            self._open_ports(port)
            for connection in self.model.connections.values():
                if connection.startup is not None:
                    self._run_hook(description.hook(connection.startup))
            self._workers = [self._worker(c) for c in self.model.connections.values()]
            if threads:
                for worker in self._workers:
                    worker.start()
            else:
                for worker in self._workers:
                    worker.restart_clock()
        except BaseException:
            self.close()
            raise

    # ---- callbacks --------------------------------------------------------------------------

    def on_output(self, callback: OutputCallback) -> OutputCallback:
        """Call `callback({"name": ..., "contents": {...}})` for every output triggered."""
        with self._callback_lock:
            self._output_callbacks.append(callback)
        return callback

    def on_error(self, callback: ErrorCallback) -> ErrorCallback:
        """Call `callback(error)` for every error of periodic work, keepalives, hooks and callbacks."""
        with self._callback_lock:
            self._error_callbacks.append(callback)
        return callback

    def on_io(self, callback: IoCallback) -> IoCallback:
        """Call `callback("write" | "read", connection, data)` for every write and every read with data."""
        with self._callback_lock:
            self._io_callbacks.append(callback)
        return callback

    # ---- calls ------------------------------------------------------------------------------

    @property
    def state(self) -> Mapping[str, m.Value]:
        """A read-only snapshot of the state variables."""
        return MappingProxyType(self._state)

    @property
    def closed(self) -> bool:
        return self._closed

    def call_input(self, name: str, /, **fields: Any) -> None:
        """Run a domain input with its adapter's fields, on this thread; errors are raised."""
        plan = self._inputs.get(name)
        if plan is None:
            raise KeyError(f"{self.name} has no input named {name!r}")
        if self._closed:
            self._check_open()
        local = _accept_fields(plan, fields)
        try:
            args = plan.args(self._state, local)
        except _EVAL_ERRORS as err:
            raise RdisValueError(f"{name}: {err}") from None
        interface = plan.interface
        call = plan.call
        if call is None:
            self._run_interface(interface, args)
            return
        # For speed, an interface of one direct call without delay is run here, as
        # `_run_interface` runs it, and only the arguments that may be ints are widened.
        if plan.widen:
            _widen(interface.name, plan.widen, args)
        try:
            values = call.args(self._state, args)
        except _EVAL_ERRORS as err:
            raise RdisValueError(f"{interface.name}: {err}") from None
        self._exchange(call.primitive, values, values)
        if interface.output is not None:
            self._deliver(interface.output)

    def call_interface(self, name: str, /, *args: Any) -> None:
        """Run an interface with positional arguments, on this thread; errors are raised."""
        plan = self.description.interfaces.get(name)
        self._run_interface(plan, self._arguments("interface", name, plan, args))  # type: ignore[arg-type]

    def call_primitive(self, name: str, /, *args: Any) -> None:
        """Send one device command (a primitive) with positional arguments, read its
        reply and run its post-actions, on this thread; errors are raised."""
        plan = self.description.primitives.get(name)
        self._run_primitive(plan, self._arguments("primitive", name, plan, args))  # type: ignore[arg-type]

    def _arguments(self, kind: str, name: str, plan: _PrimitivePlan | _InterfacePlan | None,
                   args: tuple[Any, ...]) -> list[m.Value]:
        """Positional arguments of a call, made their parameters' types; KeyError, TypeError."""
        if plan is None:
            raise KeyError(f"{self.name} has no {kind} named {name!r}")
        self._check_open()
        if len(args) != len(plan.params):
            raise TypeError(f"{kind} {name} takes {len(plan.params)} arguments, {len(args)} given")
        return [_accept(v, t, f"{kind} {name}: parameter {p}") for v, (p, t) in zip(args, plan.params)]

    def tick(self) -> None:
        """One iteration of every connection's periodic work and due keepalive, on this thread."""
        self._check_open()
        for worker in self._workers:
            worker.tick()

    # ---- lifecycle -----------------------------------------------------------------------------

    def close(self) -> None:
        """Stop the threads, run the terminate hooks (errors reported), close the ports. Idempotent."""
        with self._close_lock:
            if self._closed:
                return
            self._closed = True
        for worker in self._workers:
            worker.stop()
        for connection in self.model.connections.values():
            if connection.terminate is not None and connection.name in self._ports:
                try:
                    self._run_hook(self.description.hook(connection.terminate))
                except RdisError as err:
                    self._report(err)
        for port in {id(p): p for p in self._ports.values()}.values():
            if port.owned:
                try:
                    port.io.close()
                except Exception:  # noqa: BLE001, S110 - a port that fails to close is closed enough
                    pass

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _check_open(self) -> None:
        if self._closed:
            raise RdisConnectionError(f"{self.name}: closed")

    # ---- running the description ------------------------------------------------------------------

    def _open_ports(self, port: str | Any | Mapping[str, str | Any] | None) -> None:
        connections = self.model.connections
        if isinstance(port, Mapping):
            unknown = [name for name in port if name not in connections]
            if unknown:
                raise ValueError(f"{self.name} has no connection named {unknown[0]!r} "
                                 f"(its connections: {', '.join(connections) or 'none'})")
            given = dict(port)
        else:
            given = dict.fromkeys(connections, port) if port is not None else {}
        for name, connection in connections.items():
            if name not in given:
                if connection.address is None:
                    raise ValueError(f"no port given for connection {name!r}, which has no `address`")
                given[name] = connection.address
        opened: dict[object, _Port] = {}
        for name, where in given.items():
            key: object = where if isinstance(where, (str, os.PathLike)) else id(where)
            if key not in opened:
                if isinstance(where, (str, os.PathLike)):
                    opened[key] = _Port(_open(connections[name], os.fspath(where), self.timeout), True, name)
                else:
                    opened[key] = _Port(where, False, name)
            self._ports[name] = opened[key]

    def _run_hook(self, hook: _HookPlan) -> None:
        try:
            args = hook.args(self._state, _EMPTY)
        except _EVAL_ERRORS as err:
            raise RdisValueError(f"{hook.interface.name}: {err}") from None
        self._run_interface(hook.interface, args)

    def _worker(self, connection: m.Connection) -> Worker:
        periodic = [
            (lambda plan=plan: self._run_interface(plan, []))
            for plan in self.description.periodic.get(connection.name, ())
        ]
        keepalive = None
        if connection.keepalive is not None:
            hook = self.description.hook(connection.keepalive.call)
            keepalive = lambda: self._run_hook(hook)
        return Worker(
            connection.name, connection.frequency_hz, periodic, keepalive,
            connection.keepalive.interval_ms if connection.keepalive else None,
            self._report, (Exception,),
        )

    def _run_interface(self, plan: _InterfacePlan, args: list[m.Value]) -> None:
        """Run an interface with its parameters' values (the list is bound in place)."""
        if plan.float_slots:
            _widen(plan.name, plan.float_slots, args)
        if plan.ranges:
            _in_ranges(plan.name, plan.ranges, args)
        for call in plan.calls:
            try:
                values = call.args(self._state, args)
            except _EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
            if call.direct:  # the call's values are the primitive's format values
                self._exchange(call.primitive, values, values)
            else:
                self._run_primitive(call.primitive, values)
            if call.delay:
                time.sleep(call.delay)
        if plan.output is not None:
            self._deliver(plan.output)

    def _run_primitive(self, plan: _PrimitivePlan, args: list[m.Value]) -> None:
        if plan.float_slots:
            _widen(plan.name, plan.float_slots, args)
        if plan.ranges:
            _in_ranges(plan.name, plan.ranges, args)
        if plan.cases is not None and plan.tag is None:  # its range holds every key of its table (load checked)
            plan = plan.cases[args[plan.key]]  # type: ignore[index]
        try:
            values = plan.args(self._state, args)
        except _EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        self._exchange(plan, values, args)

    def _exchange(self, plan: _PrimitivePlan, values: list[m.Value], local: list[m.Value]) -> None:
        """Encode, write, read the reply (under the port's lock), then run the post-actions.

        `local` is the primitive's parameters, for its post-actions (a direct
        call, which has none, passes anything).
        """
        codec = plan.codec
        try:
            request = codec.encode(*values)
        except struct.error as err:
            raise codec.refused(err) from None
        frame = plan.frame
        fields: list[m.Value] = []
        if frame is not None:
            try:
                fields = frame.fields(self._state, frame.args(self._state, local))
                request = frame.wire.wrap(request, fields)  # type: ignore[arg-type]
            except _EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
            except struct.error as err:
                raise codec.refused(err) from None
        port = self._ports.get(plan.connection)
        if port is None:
            raise RdisConnectionError(f"{plan.connection}: not open")
        io = port.io
        expects_reply = plan.expects_reply
        wait = plan.timeout or self.timeout
        data = b""
        payload = b""
        reply: tuple[m.Value, ...] = ()
        decoded = False  # the reply was decoded while it was read (a tag's entry, or `skip unmatched`)
        failed: framing.FrameError | RdisProtocolError | None = None
        lock = port.lock
        lock.acquire()  # acquire/release rather than `with`: cheaper, and this runs on every call
        try:
            try:
                if request:  # a listener (no request) keeps what has arrived: its reply is the next frame
                    if expects_reply:
                        io.reset_input_buffer()
                        port.input.clear()
                    io.write(request)
            except _WRITE_TIMEOUTS:
                raise RdisTimeout(f"{plan.name}: write not completed within {self.timeout:g} s") from None
            except Exception as err:
                raise RdisConnectionError(f"{plan.connection}: {err}") from err
            if expects_reply:
                if plan.timeout is not None:
                    io.timeout = plan.timeout
                try:
                    if frame is not None and frame.reads:
                        size = codec.reply_size if codec.reply_size > 0 or not codec.expects_reply else -1
                        deadline = time.monotonic() + wait
                        while True:  # once, or until a frame decodes when the primitive skips others
                            try:
                                chunk, payload = frame.wire.read(port.input, fields, request, size)  # type: ignore[arg-type]
                                data += chunk
                                if plan.tag is not None:  # the tag chooses the entry: its decoding, its actions
                                    plan, reply = _tagged(plan, payload)
                                    decoded = True
                                elif plan.skip:
                                    reply = codec.match_payload(payload) if codec.reads_line else codec.decode(payload)
                                    decoded = True
                                break
                            except (framing.FrameError, RdisProtocolError) as err:
                                if (not plan.skip or getattr(err, "timeout", False)
                                        or time.monotonic() >= deadline):
                                    failed = err
                                    break
                    else:
                        data = bytes(io.read_until(codec.terminator, MAX_LINE) if codec.reads_line
                                     else io.read(codec.reply_size))
                except Exception as err:
                    raise RdisConnectionError(f"{plan.connection}: {err}") from err
                finally:
                    if plan.timeout is not None:
                        io.timeout = self.timeout
        finally:
            lock.release()
        # I/O callbacks run once the port is free again: one that calls the robot
        # (or waits for a thread that does) cannot deadlock against this exchange.
        if self._io_callbacks:
            if request:
                self._notify_io("write", plan.connection, request)
            if data:
                self._notify_io("read", plan.connection, data)
        if failed is not None:
            if getattr(failed, "timeout", False) or plan.skip:
                what = "matching reply" if plan.skip else "reply"
                raise RdisTimeout(f"{plan.name}: no {what} within {wait:g} s")
            if isinstance(failed, RdisProtocolError):
                raise failed
            raise RdisProtocolError(f"{plan.name}: {failed}")
        if decoded or not expects_reply or not codec.expects_reply:
            pass
        elif frame is not None and frame.reads:
            reply = codec.match_payload(payload) if codec.reads_line else codec.decode(payload)
        elif not data:
            raise RdisTimeout(f"{plan.name}: no reply within {wait:g} s")
        else:
            reply = codec.match(data) if codec.reads_line else codec.decode(data)
        if plan.actions:
            self._assign(plan, local, reply)

    def _assign(self, plan: _PrimitivePlan, local: list[m.Value], reply: tuple[m.Value, ...]) -> None:
        """The post-actions: all values computed from one snapshot, then published together."""
        with self._state_lock:
            state = self._state
            try:
                values = [(target, coerce(f(state, local, reply), type_)) for target, f, type_ in plan.actions]
            except _EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
            new = dict(state)
            new.update(values)
            self._state = new

    # ---- callbacks ------------------------------------------------------------------------------------

    def _deliver(self, plan: _OutputPlan) -> None:
        state = self._state
        try:
            contents = {name: coerce(f(state, _EMPTY, ()), type_) for name, f, type_ in plan.fields}
        except _EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        message = {"name": plan.name, "contents": contents}
        with self._callback_lock:
            for callback in list(self._output_callbacks):
                try:
                    callback(message)
                except Exception as err:  # noqa: BLE001 - a user's callback must not stop delivery
                    error = RdisCallbackError(f"{plan.name}: output callback raised {type(err).__name__}: {err}")
                    error.__cause__ = err
                    self._report(error)

    def _notify_io(self, direction: str, connection: str, data: bytes) -> None:
        with self._callback_lock:
            for callback in list(self._io_callbacks):
                try:
                    callback(direction, connection, data)
                except Exception as err:  # noqa: BLE001 - a user's callback must not stop the I/O
                    error = RdisCallbackError(f"{connection}: I/O callback raised {type(err).__name__}: {err}")
                    error.__cause__ = err
                    self._report(error)

    def _report(self, error: BaseException) -> None:
        with self._callback_lock:
            callbacks = list(self._error_callbacks)
            if not callbacks:
                log.warning("%s: %s: %s", self.name, type(error).__name__, error)
            for callback in callbacks:
                try:
                    callback(error)
                except Exception:  # noqa: BLE001, S110 - the contract: an error callback's exception is ignored
                    pass


_EMPTY: Mapping[str, m.Value] = MappingProxyType({})
_PYTHON_TYPES: dict[m.Type, type[Any]] = {m.Type.INT: int, m.Type.FLOAT: float, m.Type.BOOL: bool, m.Type.STRING: str}


def _widen(owner: str, float_slots: tuple[int, ...], values: list[m.Value]) -> None:
    """Parameters bound to computed values (of their types already, but for int -> float), in place."""
    for i in float_slots:
        if type(values[i]) is int:
            try:
                values[i] = float(values[i])
            except OverflowError as err:  # an int too large for a float
                raise RdisValueError(f"{owner}: {err}") from None


def _accept_fields(plan: _InputPlan, fields: dict[str, Any]) -> dict[str, m.Value]:
    """An input's fields, checked and made their types; TypeError unless exactly the adapter's.

    `fields` is the call's own keyword dict: it is made the adapter's types in
    place and returned (no copy, for speed).
    """
    if len(fields) == len(plan.fields):
        for name, type_, python_type in plan.fields:
            if name not in fields:
                break
            value: Any = fields[name]
            if type(value) is not python_type:
                fields[name] = _accept(value, type_, f"input {plan.name}: field {name}")
        else:
            return fields
    expected = ", ".join(name for name, _, _ in plan.fields)
    raise TypeError(f"input {plan.name} takes the fields {expected} ({plan.adapter}); "
                    f"given: {', '.join(fields) or 'none'}")


def _bytes(value: Any, what: str) -> bytes:
    """Bytes given as bytes, a bytearray, a list of ints 0..255 or hex text ("3c20")."""
    try:
        if isinstance(value, str):
            return bytes.fromhex(value)
        if isinstance(value, (bytes, bytearray, memoryview, list, tuple)):
            return bytes(value)
    except (ValueError, TypeError) as err:
        raise TypeError(f"{what} must be bytes: {err}") from None
    raise TypeError(f"{what} must be bytes, not {type(value).__name__} {value!r}")


def _accept(value: Any, type_: m.Type, what: str) -> m.Value:
    """A value given for a parameter or field of this type, made that type; else TypeError."""
    kind = type(value)
    if type_ is m.Type.FLOAT:
        if kind is float:
            return value
        if isinstance(value, numbers.Real) and kind is not bool:
            return float(value)
    elif type_ is m.Type.INT:
        if kind is int:
            return value
        if isinstance(value, numbers.Integral) and kind is not bool:
            return int(value)
    elif type_ is m.Type.BOOL:
        if kind is bool:
            return value
    elif type_ is m.Type.BYTES:
        return _bytes(value, what)
    elif isinstance(value, str):
        return value
    raise TypeError(f"{what} must be {type_.value}, not {kind.__name__} {value!r}")
