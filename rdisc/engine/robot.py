"""The robot: its lifecycle (ports opened, hooks, threads, closing) and its public face (state,
inputs, interfaces, primitives); what it runs is written and read by the exchange it inherits.
"""

from __future__ import annotations

import functools
import math
import os
import threading
import time
from collections import deque
from collections.abc import Callable, Iterator, Mapping
from typing import Any

from rdisc.engine.actuation import Actuated
from rdisc.engine.arguments import _accepted, _bind, bind_settings
from rdisc.engine.errors import RdisConnectionError, RdisError, RdisTimeout
from rdisc.engine.plans import Device, Input, Interface, Primitive, Request
from rdisc.engine.ports import PortSpec, Simulator, _Link, _open_port, _Port, _write_timed_out
from rdisc.engine.running import Running
from rdisc.engine.schedule import _connection_workers, _Worker
from rdisc.engine.sensing import SensorCache, Sensors
from rdisc.engine.signals import Flag
from rdisc.engine.values import (
    Args,
    ErrorCallback,
    IoCallback,
    OutputCallback,
    StateValues,
    TraceCallback,
    Value,
)
from rdisc.engine.wire import MAX_FRAME

_RAW_QUIET = 0.05  # seconds without a byte that end a raw answer (`Robot.send_raw`)
_RAW_CHUNK = 256  # bytes asked of the port at a time while a raw answer comes


class State(Mapping[str, Value]):
    """The state variables at one moment: `state["name"]` or `state.name`. Immutable: the
    robot publishes a new snapshot after each primitive's post-actions."""

    __slots__ = ("_values",)

    def __init__(self, values: StateValues) -> None:
        self._values = values

    def __getitem__(self, name: str) -> Value:
        value: Value = self._values[name]
        return value

    def __getattr__(self, name: str) -> Value:
        try:
            value: Value = self._values[name]
            return value
        except KeyError:
            raise AttributeError(f"no state variable {name!r}") from None

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __repr__(self) -> str:
        return f"State({dict(self._values)!r})"


class Calls:
    """`robot.inputs`, `robot.interfaces` or `robot.primitives`: each element of that kind
    as a method of its name (an input takes its fields by name, the others their
    parameters by position or name)."""

    def __init__(self, robot: Robot, kind: str) -> None:
        self._robot = robot
        self._kind = kind  # each method made is kept as an attribute: `__getattr__` makes it once

    def _plans(self) -> Mapping[str, Input | Interface | Primitive]:
        device = self._robot.device
        if self._kind == "input":
            return device.inputs
        return device.interfaces if self._kind == "interface" else device.primitives

    def __getattr__(self, name: str) -> Callable[..., None]:
        plan = self._plans().get(name)
        if plan is None:
            raise AttributeError(f"{self._robot.name} has no {self._kind} named {name!r}")
        robot = self._robot
        method: Callable[..., None]
        if isinstance(plan, Input):
            method = functools.partial(robot.call_input, name)
        elif isinstance(plan, Interface):
            interface, what = plan, f"interface {name}"
            method = lambda *args, **kwargs: robot._call_interface(interface, _bind(what, interface.params, args, kwargs))
        else:
            method = _primitive_method(robot, plan)
        setattr(self, name, method)
        return method

    def __dir__(self) -> list[str]:
        return sorted(self._plans())


def _primitive_method(robot: Robot, plan: Primitive) -> Callable[..., None]:
    """`robot.primitives.NAME`: its one plain write made here when it can be (`Robot.call_primitive`'s
    path, inline: every command's), else the general way, with its arguments bound."""
    request, what = plan.request, f"primitive {plan.name}"

    def method(*args: Any, **kwargs: Any) -> None:
        if request is not None and not kwargs and robot._direct:
            data = request(robot._state, args)  # type: ignore[arg-type]  # a request takes any sequence of values
            if data is not None:
                robot._write(plan, data)
                return
        robot._call_primitive(plan, _bind(what, plan.params, args, kwargs))

    return method


class Robot(Running):
    """A description's devices, driven: `open()` opens the ports, runs the startup hooks
    and starts one thread per connection; `close()` (or leaving a `with` block) stops
    them, runs the terminate hooks and closes the ports.

    State lives in a dict that is never changed in place: post-actions build a new one
    under the state lock and publish it with one assignment, so any reader sees a
    consistent snapshot without locking.
    """

    def __init__(self, device: Device, *, timeout: float = 1.0) -> None:
        """A robot not connected yet; `timeout`: seconds a reply may take."""
        self.device = device
        self.name = device.name
        self.timeout = timeout
        self._state: dict[str, Value] = dict(device.state)
        self._state_lock = threading.Lock()
        self._callback_lock = threading.RLock()  # callbacks run one at a time
        self._ticking = threading.local()  # `.port`: what this thread's tick holds whole (`threading single`)
        self._output_callbacks: list[OutputCallback] = []
        self._filters = {}
        self._read_ns: int | None = None  # when a reply last changed the state
        self._error_callbacks: list[ErrorCallback] = []
        self._io_callbacks: list[IoCallback] = []
        self._trace_callbacks: list[TraceCallback] = []
        self._watched = False  # an I/O or trace callback is registered (they are never removed)
        self._events: deque[tuple[float, str, str, bytes]] = deque()
        self._events_lock = threading.Lock()
        self._run_callbacks: list[Callable[[str, str, str], object]] = []  # a Recorder's: what a thread runs
        self._links: dict[str, _Link] = {}
        self._ports: dict[str, _Port] = {}
        self._workers: list[_Worker] = []
        self._close_lock = threading.Lock()
        self._calls = {kind: Calls(self, kind) for kind in ("input", "interface", "primitive")}
        self._running = False
        self._direct = False  # running on ports: a plain write may skip the general way
        # While `_direct`, the primitives only written, by name, with their one-step requests: what
        # `call_primitive` looks up first (empty otherwise, so that one look-up decides both).
        self._written: dict[str, tuple[Primitive, Request]] = {}
        # A generated driver's typed methods that make their primitive's request in one step, by
        # name, with their parameters' count (set by the driver's robot): what `call_primitive`
        # looks up first, the same specialised function as `robot.primitives.NAME`.
        self._one_step: dict[str, tuple[Callable[..., None], int]] = {}
        # Each input by name with what `call_input` reads of it on every call, read once here: its
        # fields' count, how they are taken from keywords, its one-step request and where that goes.
        self._inputs: dict[str, tuple[Input, int, Callable[[Mapping[str, Any]], Args], Request | None,
                                      Primitive | None]] = {
            name: (plan, len(plan.fields), plan.taken, plan.request, plan.primitive)
            for name, plan in device.inputs.items()}
        self._closed = False  # closing or closed: writes are refused (`_refuse`) but by the `_closer`
        self._closer: int | None = None
        self._closing = Flag()  # set when closing begins: it ends the other threads' delays
        self._sim: Simulator | None = None
        self._clock: Callable[[], float] = time.monotonic  # the schedule's time, and the delays'
        self._sleep: Callable[[float], None] = self._delay
        self._sensed = SensorCache()
        self._actuated = Actuated()  # what each actuator was last given, by the robot's clock
        self._choose_write()

    # ---- callbacks --------------------------------------------------------------------------------

    def on_output(self, callback: OutputCallback) -> OutputCallback:
        """Call `callback({"name": ..., "contents": {...}})` for every output triggered: an
        `OutputMessage`, whose `read_ns` says when its data was read."""
        with self._callback_lock:
            self._output_callbacks.append(callback)
        return callback

    def on_error(self, callback: ErrorCallback) -> ErrorCallback:
        """Call `callback(error)` for every error of periodic work, keepalives, terminate hooks
        and callbacks (with none registered, errors are logged to the "rdisc" logger)."""
        with self._callback_lock:
            self._error_callbacks.append(callback)
        return callback

    def on_io(self, callback: IoCallback) -> IoCallback:
        """Call `callback("write" | "read", connection, data)` for every write, and for every
        byte read, whatever became of it; `callback("lines", connection, b"dtr=False")` for the
        modem lines a primitive set, before its write."""
        with self._callback_lock:
            self._io_callbacks.append(callback)
            self._watched = True
            self._choose_write()
        return callback

    def on_trace(self, callback: TraceCallback) -> TraceCallback:
        """Call `callback(time, kind, connection, data)` for what an I/O callback sees, stamped
        when it happened (a request when it was written, a reply when its last byte came), and
        for each reply `skip unmatched` read past: `kind` "skip", `data` why (UTF-8 text). In
        the order it happened, across threads; `time` is the robot's clock (`time.monotonic`,
        or a simulation's time). `rdisc run --trace` prints these."""
        with self._callback_lock:
            self._trace_callbacks.append(callback)
            self._watched = True
            self._choose_write()
        return callback

    # ---- what the host can see and call -------------------------------------------------------------

    @property
    def state(self) -> State:
        """The state variables now: an immutable snapshot, `robot.state["name"]` or `.name`."""
        return State(self._state)

    @functools.cached_property
    def sensors(self) -> Any:  # a Sensors, or a driver's typed properties
        """The sensors, by name: `robot.sensors.NAME` is its value, read first when older than its cache time."""
        return Sensors(self.device.sensors, self.read_sensor)

    def read_sensor(self, name: str, /) -> Value:
        """A sensor's value, read through its primitive first when older than its cache time."""
        self._sense((name,))
        return self._state[name]

    def sensor_age(self, name: str, /) -> float | None:
        """Seconds since the sensor's value was read, by the robot's clock; None: never read."""
        return self._sensed.age(name, self._clock())

    def _sense(self, names: tuple[str, ...]) -> None:
        sensors = self.device.sensors
        for name in names:
            sensor = sensors.get(name)
            if sensor is None:
                raise KeyError(f"{self.name} has no sensor named {name!r}")
            self._sensed.refresh(sensor, self._clock(), self._read_sensor)

    def _read_sensor(self, plan: Primitive) -> None:
        if not self._running and self._closer != threading.get_ident():  # a terminate hook reads too
            raise self._not_running()
        self._primitive(plan, [])

    @property
    def closed(self) -> bool:
        return self._closed

    @functools.cached_property  # kept on the instance: a typed method's call looks it up as an attribute
    def inputs(self) -> Any:  # a Calls; a generated driver gives a class of typed methods
        """The domain inputs, by name: `robot.inputs.NAME(field=value, ...)`."""
        return self._calls["input"]

    @functools.cached_property  # kept on the instance: a typed method's call looks it up as an attribute
    def interfaces(self) -> Any:  # a Calls, or a driver's typed methods
        """The interfaces, by name: `robot.interfaces.NAME(param, ...)`."""
        return self._calls["interface"]

    @functools.cached_property  # kept on the instance: a typed method's call looks it up as an attribute
    def primitives(self) -> Any:  # a Calls, or a driver's typed methods
        """The primitives (device commands), by name: `robot.primitives.NAME(param, ...)`."""
        return self._calls["primitive"]

    def call_input(self, name: str, /, **fields: Any) -> None:
        """Run a domain input with its adapter's fields by name, on this thread; errors are raised."""
        found = self._inputs.get(name)
        if found is None:
            raise KeyError(f"{self.name} has no input named {name!r}")
        plan, count, taken, request, primitive = found
        try:
            if len(fields) != count:
                raise KeyError(name)
            values = taken(fields)
        except KeyError:
            expected = ", ".join(f.name for f in plan.fields)
            raise TypeError(f"input {name} takes the fields {expected} ({plan.adapter}); "
                            f"given: {', '.join(fields) or 'none'}") from None
        if request is not None and self._direct:  # `_input`'s one plain write, inline: every command's path
            data = request(self._state, values)
            if data is not None:
                assert primitive is not None  # set with `request`
                self._write(primitive, data)
                return
            self._input_in_full(plan, values)
            return
        self._input(plan, values)

    def call_interface(self, name: str, /, *args: Any) -> None:
        """Run an interface with positional arguments, on this thread; errors are raised."""
        plan = self.device.interfaces.get(name)
        if plan is None:
            raise KeyError(f"{self.name} has no interface named {name!r}")
        self._call_interface(plan, list(args))

    def call_primitive(self, name: str, /, *args: Any) -> None:
        """Send one device command (a primitive) with positional arguments, read its reply and
        run its post-actions, on this thread; errors are raised."""
        typed = self._one_step.get(name)
        if typed is not None and len(args) == typed[1]:  # a driver's typed method: every command's path
            typed[0](*args)
            return
        written = self._written.get(name)
        if written is not None:  # `_call_primitive`'s one plain write, inline: every command's path
            plan, request = written
            data = request(self._state, args)  # type: ignore[arg-type]  # a request takes any sequence of values
            if data is not None:
                self._write(plan, data)
                return
        else:
            found = self.device.primitives.get(name)
            if found is None:
                raise KeyError(f"{self.name} has no primitive named {name!r}")
            plan = found
        self._call_primitive(plan, list(args))

    def request(self, name: str, /, *args: Any) -> bytes:
        """The bytes primitive `name` would write for these arguments (framed, after every check
        a call makes), neither written nor needing a port: what `rdisc dump --args` shows. b""
        for a primitive that writes nothing (a listener). Errors are raised as a call's. Its
        actuators' limits hold it as the first command they are given (a wheel's speed within its
        velocity), and the commands after it are held to the ones written, not to it."""
        plan = self.device.primitives.get(name)
        if plan is None:
            raise KeyError(f"{self.name} has no primitive named {name!r}")
        given = _accepted(f"primitive {plan.name}", plan.params, list(args))
        plan, values, local = self._planned(plan, given, Actuated())  # as a first command: no actuator moved
        return self._request(plan, values, local)[0]

    def send_raw(self, connection: str, data: bytes, /, *, quiet: float = _RAW_QUIET) -> bytes:
        """Write `data` as it is on `connection`'s port and return what the device answers, as a
        terminal (pyserial's miniterm) shows it: under the port's lock, as a call's request, so no
        call's bytes come between; input waiting before it is discarded; the answer's first byte
        waited for up to the robot's timeout, then more until none has come for `quiet` seconds,
        the whole answer within the timeout and at most MAX_FRAME bytes. b"": no answer. The I/O
        and trace callbacks see both as a call's bytes."""
        link = self._links.get(connection)
        if link is None:
            if connection not in self.device.connections:
                raise KeyError(f"{self.name} has no connection named {connection!r}")
            why = "the device is simulated: there is no port" if self._sim is not None else "not open"
            raise RdisConnectionError(f"{connection}: {why}")
        port = link.port
        io = port.io
        answer = bytearray()
        watched = self._watched
        timeout = io.timeout  # the port's own: the first byte's wait, as a reply's (`Incoming`)
        port.lock.acquire()
        try:
            if self._closed:
                raise RdisConnectionError(f"{self.name}: raw bytes not sent: the robot is "
                                          f"{'closing' if self._closer is not None else 'closed'}")
            io.reset_input_buffer()
            port.input.clear()
            if data:
                io.write(data)
                if watched:
                    self._happened("write", connection, data)
            deadline = time.monotonic() + (self.timeout if timeout is None else timeout)
            chunk = io.read(1)
            while chunk:
                answer += chunk
                left = deadline - time.monotonic()
                if left <= 0 or len(answer) >= MAX_FRAME:
                    break
                io.timeout = min(quiet, left)
                chunk = io.read(min(_RAW_CHUNK, MAX_FRAME - len(answer)))
        except RdisError:
            raise
        except Exception as err:  # whatever the port raises, it failed
            if _write_timed_out(err):
                raise RdisTimeout(f"{connection}: raw bytes: write not completed within {self.timeout:g} s") from err
            raise RdisConnectionError(f"{connection}: {err}") from err
        finally:
            try:
                if io.timeout != timeout:
                    io.timeout = timeout
            except Exception:  # noqa: BLE001, S110 - a port gone mid-answer: its read's failure is the one to tell
                pass
            if answer and watched:
                self._happened("read", connection, bytes(answer))
            port.lock.release()
            if watched:
                self._show()
        return bytes(answer)

    # ---- lifecycle ----------------------------------------------------------------------------------

    def open(self, port: PortSpec | None = None, *, threads: bool = True,
             settings: Mapping[str, Any] | None = None, sim: Simulator | None = None) -> None:
        """Bind the settings, open the ports, run the startup hooks, then start the connections' threads.

        `port`: a pyserial port name or URL ("/dev/ttyUSB0", "COM3", "socket://host:4000")
        or an open port object, for every connection; or a dict {connection: port}; a
        connection given none opens its address from the description. `settings`: values
        of the description's settings by name (the others keep their defaults); one that
        does not fit is an RdisValueError, before anything is opened. With
        `threads=False` no thread is started: call `tick()` from your own loop. If any of
        it fails, what was opened is closed again (terminate hooks included) and the
        error is raised. `sim`: a simulated device in place of the ports (no port is
        opened); in simulated time no thread is started either: `run_for` runs the schedule.
        """
        if self._running or self._closed:
            raise RdisConnectionError(f"{self.name}: already opened")
        self._state = {**self._state, **bind_settings(self.device, settings)}
        try:
            if sim is None:
                self._open_links(port)
            else:
                self._simulate(sim)
                threads = threads and sim.realtime
            self._running = True
            self._direct = sim is None
            self._choose_write()  # the lanes, now that a plain write may skip the general way
            if self._direct:
                self._written = {name: (plan, plan.request) for name, plan in self.device.primitives.items()
                                 if plan.request is not None}
            self.startup()
            self._workers = [w for c in self.device.connections.values() for w in _connection_workers(self, c)]
            for worker in self._workers:
                if threads:
                    worker.start()
        except BaseException:
            self.close()
            raise

    def startup(self) -> None:
        """Run the startup hooks, in declaration order (`open()` does); errors are raised."""
        for connection in self.device.connections.values():
            if connection.startup is not None:
                self._hook(connection.startup)

    def terminate(self) -> None:
        """Run the terminate hooks of the connections that are open, in declaration order
        (`close()` does): they leave the robot stopped. Errors are reported, not raised."""
        for connection in self.device.connections.values():
            if connection.terminate is not None and (connection.name in self._links or self._sim is not None):
                try:
                    self._hook(connection.terminate)
                except Exception as err:  # noqa: BLE001 - reported, and the others run
                    self._report(err)

    def tick(self) -> None:
        """One iteration of every connection's work on this thread, in declaration order: its
        periodic interfaces, then its keepalive if due. Errors are reported, as the threads' are."""
        if not self._running:
            raise self._not_running()
        for worker in self._workers:
            worker.tick()

    def run_for(self, seconds: float | None) -> None:
        """Run the connections' schedules for `seconds` of simulated time (None: for ever), on
        this thread: each connection's tick when it is due, as its thread would run it, the
        simulation advanced up to it (and by the delays within it)."""
        sim = self._sim
        if sim is None or sim.realtime or not self._running:
            raise RdisConnectionError(f"{self.name}: not running in simulated time")
        end = math.inf if seconds is None else sim.now() + seconds
        ticks = dict.fromkeys(self._workers, 0)  # each periodic connection's next tick
        while True:
            due = {w: w._start + k * w.period if w.periodic else w._keepalive_due if w.interval else math.inf
                   for w, k in ticks.items()}
            wake = min(due.values(), default=math.inf)
            if wake > end:
                sim.advance(end - sim.now())
                return
            sim.advance(max(wake - sim.now(), 0.0))
            for worker, when in due.items():
                if when <= wake:
                    worker.tick()  # as the thread's loop: a tick already past is skipped
                    if worker.periodic:
                        late = math.ceil((sim.now() - worker._start) / worker.period - 1e-9)
                        ticks[worker] = max(ticks[worker] + 1, late)

    def close(self) -> None:
        """Stop every other thread from writing (a host call or periodic interface in progress
        ends with an RdisConnectionError at its next write, its delays cut short), stop the
        threads, run the terminate hooks on this thread (errors reported, not raised), then
        refuse every write and close the ports `open` opened: the terminate hooks' commands
        are the last written. Idempotent; the robot does nothing more afterwards."""
        with self._close_lock:
            if self._closed:
                return
            self._closer = threading.get_ident()
            self._closed = True
            self._running = False
            self._direct = False
            self._lanes = (None,) * len(self._lanes)  # a typed method's write goes the general way, refused
            self._written = {}
        self._closing.set()
        try:
            for worker in self._workers:
                worker.stop()
            self.terminate()
        finally:
            self._closer = None
        for port in {id(link.port): link.port for link in self._links.values()}.values():
            if port.owned:
                try:
                    port.io.close()
                except Exception:  # noqa: BLE001, S110 - a port that fails to close is closed enough
                    pass

    def __enter__(self) -> Robot:  # noqa: PYI034 - typing.Self needs Python 3.11
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _delay(self, seconds: float) -> None:
        """A call's delay: the closing thread's (its terminate hooks') is whole; any other
        thread's ends when closing begins, for its next write to be refused at once."""
        if self._closer == threading.get_ident():
            time.sleep(seconds)
        else:
            self._closing.wait(seconds)

    def _open_links(self, port: PortSpec | None) -> None:
        """A port for each connection: one name or URL is opened once and shared, with one
        lock; an open port object is used as it is and never closed here; a connection
        given no port opens its address."""
        connections = self.device.connections
        given: dict[str, Any]
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
        fair = {os.fspath(where) if isinstance(where, (str, os.PathLike)) else id(where)  # ports handed over in turn
                for name, where in given.items() if connections[name].threading != "single"}
        opened: dict[object, _Port] = {}
        for name, where in given.items():
            by_name = isinstance(where, (str, os.PathLike))
            key: object = os.fspath(where) if by_name else id(where)
            if key not in opened:
                connection = connections[name]
                setting = connection.baud_setting  # an int setting: the checker holds it to that type
                baud: Any = self._state[setting] if setting is not None else connection.baud
                io = _open_port(connection, os.fspath(where), self.timeout, baud) if by_name else where
                opened[key] = _Port(io, owned=by_name, fair=key in fair)
            self._links[name] = _Link(connections[name], opened[key])
            self._ports[name] = opened[key]
        self._choose_write()

    # ---- a simulated device: `open(sim=...)` puts these in place of the ports' ways ------------------

    def _simulate(self, sim: Simulator) -> None:
        """Run against `sim`: every primitive the general way (the simulator takes parameters'
        values, which a plain write's shortcut never has), and in simulated time the schedule's
        clock and the delays the simulation's. Instance attributes, so that a robot on ports runs
        exactly the code it runs without them. Each exchange is the simulator's (`Exchange._simulated`)."""
        self._sim = sim
        self._input = self._input_in_full  # type: ignore[method-assign]
        self._primitive = self._primitive_in_full  # type: ignore[method-assign]
        self._interface = self._simulated_interface  # type: ignore[method-assign]
        if not sim.realtime:
            self._clock = sim.now
            self._sleep = sim.advance

    def _simulated_interface(self, plan: Interface, args: Args) -> None:
        """An interface: the simulator sees its parameters' values first (a transmission may
        command one), then it runs as it always does."""
        assert self._sim is not None
        self._sim.interface(plan, args)
        Robot._interface(self, plan, args)
