"""The command line `rdisc run` and every driver share: its options and the calls they make
(its signals and exit statuses: rdisc.engine.signals).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from collections.abc import Callable, Iterable, Iterator, Mapping
from contextlib import contextmanager
from typing import Any

from rdisc.engine.arguments import Unbound, bind_settings, call_values, read_value
from rdisc.engine.errors import RdisError, RdisValueError, nearest
from rdisc.engine.plans import Device, Input, Interface, Primitive
from rdisc.engine.ports import Simulator
from rdisc.engine.recording import Recorder, Session
from rdisc.engine.robot import Robot
from rdisc.engine.signals import (
    EXIT_ERROR,
    EXIT_OK,
    EXIT_SIGINT,
    EXIT_SIGTERM,
    EXIT_USAGE,
    _install_signal_handlers,
    _restore_handlers,
    _shutting_down,
    _Terminated,
    raise_dropped,
)
from rdisc.engine.values import Value


@contextmanager
def ports_held(robot: Robot) -> Iterator[None]:
    """A host's call is recorded while it holds its robot's ports: a tick that holds a port
    (`threading single`) then runs wholly before or after it, so a recording's order of runs is
    the wire's, which `rdisc replay` follows (`--call`, and the console's calls). Each port once,
    in the order of connection names."""
    locks = list({id(port): port.lock for _, port in sorted(robot._ports.items())}.values())
    for lock in locks:
        lock.acquire()
    try:
        yield
    finally:
        for lock in reversed(locks):
            lock.release()

def add_arguments(parser: argparse.ArgumentParser, device: Device | None = None, *, ports: bool = True) -> None:
    """The options of `rdisc run` (and of a driver's command line), on `parser`; without
    `--port` for a simulated device (`rdisc sim`)."""
    connections = f" (connections: {', '.join(device.connections)})" if device is not None else ""
    inputs = f" (inputs: {', '.join(device.inputs)})" if device is not None and device.inputs else ""
    if ports:
        parser.add_argument("--port", action="append", default=[], metavar="[CONN=]PORT",
                            help="a pyserial port or URL (/dev/ttyUSB0, COM3, socket://host:port); "
                                 f"CONN=PORT for one connection of several{connections}")
    parser.add_argument("--call", action="append", nargs="+", default=[], metavar="NAME [K=V ...]",
                        help="call an input (or an interface, or a primitive) with named values; repeat for "
                             f"several calls, in order{inputs}")
    settings = f" (settings: {', '.join(p.name for p in device.settings)})" if device and device.settings else ""
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help=f"give a setting of the description its value; repeat for several{settings}")
    parser.add_argument("--watch", action="store_true", help="print each output as a JSON line as it arrives")
    parser.add_argument("--trace", action="store_true",
                        help="print every byte written and read, in hex, on stderr, after the seconds since the "
                             "run started: `0.1234 CONN > 89 00 c8 80 00`")
    parser.add_argument("--duration", type=float, metavar="S",
                        help="run for S seconds, counted from the end of the startup hooks (default: until the "
                             "calls are done; with --watch, until Ctrl-C)")
    parser.add_argument("--timeout", type=float, default=1.0, metavar="S",
                        help="reply timeout in seconds (default 1)")
    parser.add_argument("--record", metavar="FILE.mcap",
                        help="record the session in MCAP: inputs and outputs as ROS 2 messages, the bytes "
                             "each way, errors (needs the mcap and mcap-ros2-support packages); a file that "
                             "exists is refused unless --force")
    parser.add_argument("--force", action="store_true",
                        help="let --record replace a file that exists (never the description or its imports)")


def run_command(args: argparse.Namespace, robot: Robot, prog: str, sim: Simulator | None = None,
                inputs: Iterable[str] = (), opened: Callable[[], object] | None = None,
                session: Session | None = None) -> int:
    """What `rdisc run` does with its options: connect, make the --call calls in order, then
    run until --duration seconds after the startup hooks ended (or, with --watch, until
    Ctrl-C; else end when the calls are done). It always ends by closing the robot, which
    runs the terminate hooks. Exit status: 0 done; 1 the device failed; 2 a usage error;
    130 after SIGINT; 143 after SIGTERM. With `sim` (`rdisc sim`) the robot runs against
    the simulated device; in simulated time the seconds, the trace's included, are its.
    `inputs` are the files the description was read from, which --record never writes over.
    `opened` is called once the startup hooks are done (a ROS 2 node subscribes then); `--duration
    inf` runs until a signal. `session`: the robot's, when something besides --record observes it
    (`rdisc run --foxglove`): the calls are told to it, and --record records it."""
    simulated = sim is not None and not sim.realtime
    clock = sim.now if sim is not None and simulated else time.monotonic
    began = clock()
    try:
        port = None if sim is not None else parse_ports(args.port, robot.device)
        settings = bind_settings(robot.device, parse_settings(args.set, robot.device))
        calls = [parse_call(words, robot.device) for words in args.call]
    except (TypeError, ValueError) as err:
        print(f"{prog}: {err}", file=sys.stderr)
        return EXIT_USAGE
    recorder = (start_recording(robot, args.record, settings, prog, force=args.force, inputs=inputs,
                                session=session) if args.record else None)
    if args.record and recorder is None:
        return EXIT_USAGE
    session = recorder.session if recorder is not None else session
    robot.on_error(_print_error)
    if args.watch:
        robot.on_output(_watcher(robot))
    if args.trace:
        robot.on_trace(lambda when, kind, connection, data: _print_io(when - began, kind, connection, data))
    previous = _install_signal_handlers()
    status = EXIT_OK
    try:
        robot.open(port, settings=settings, sim=sim)
        started = clock()  # the startup hooks are done: --duration counts from here
        if opened is not None:
            opened()
        for name, kind, values in calls:
            raise_dropped()
            with ports_held(robot):
                if session is not None:
                    session.call(kind, name, values)
                make_call(robot, kind, name, values)
        if simulated and (args.duration is not None or args.watch):
            robot.run_for(None if args.duration is None else args.duration - (clock() - started))
        elif args.duration is not None:
            _sleep(args.duration - (time.monotonic() - started))
        elif args.watch:
            _sleep(None)
    except RdisError as err:
        _print_error(err)
        if session is not None:
            session.error(err)
        status = EXIT_ERROR
    except (TypeError, ValueError) as err:  # values of the wrong type for a call, or a bad port
        print(f"{prog}: {err}", file=sys.stderr)
        status = EXIT_USAGE
    except KeyboardInterrupt:
        _shutting_down[0] = True  # marked here, where a later signal is still ignored as on its way
        status = EXIT_SIGINT
    except _Terminated:
        _shutting_down[0] = True
        status = EXIT_SIGTERM
    finally:
        _shutting_down[0] = True  # first, by no call (see `_shutting_down`): the terminate hooks run in peace
        try:
            robot.close()
            if recorder is not None:
                recorder.finish()
        finally:
            _restore_handlers(previous, status)
    return status


def start_recording(robot: Robot, path: str, settings: Mapping[str, Any], prog: str, *, force: bool = False,
                    inputs: Iterable[str] = (), session: Session | None = None) -> Recorder | None:
    """`--record PATH` (of `rdisc run`, `rdisc sim`, a driver and `rdisc console`): a Recorder
    attached to `robot`, or None once stderr says in a line why there is none, which is a usage
    error: the mcap packages are missing, PATH is one of `inputs` (the description and its
    imports, even with `force`), PATH exists and `force` is not given, or it cannot be written.
    `session`: the robot's, when something else observes it too."""
    source = made_from(path, inputs)
    if source is not None:
        print(f"{prog}: will not record to {path}: it is {source}, which this runs", file=sys.stderr)
        return None
    try:
        return Recorder(robot, path, settings, replace=force, session=session)
    except ImportError:
        print(f"{prog}: --record needs the mcap and mcap-ros2-support packages "
              "(pip install mcap mcap-ros2-support)", file=sys.stderr)
    except FileExistsError:
        print(f"{prog}: will not record to {path}: it exists (--force replaces it)", file=sys.stderr)
    except OSError as err:
        print(f"{prog}: cannot write {path}: {err.strerror or err}", file=sys.stderr)
    return None


def made_from(path: str, inputs: Iterable[str]) -> str | None:
    """The one of `inputs` (the files a description was read from) that `path` is, if any: a
    file written is never one of those (`-o` of every verb, `--record`)."""
    for source in inputs:
        try:
            if os.path.samefile(path, source):
                return source
        except (OSError, ValueError):  # one of them does not exist (yet): not the same file
            pass
    return None


def parse_ports(given: list[str], device: Device) -> str | dict[str, str] | None:
    """`--port P` for every connection, `--port CONN=P` for one; a plain port is the default for
    the others, and a connection given none opens its `address`."""
    connections = device.connections
    addresses = {name: c.address for name, c in connections.items() if c.address is not None}
    if not given:
        if len(addresses) == len(connections):
            return None
        raise ValueError("give the device's port: --port /dev/ttyUSB0 (or CONN=PORT for each connection)")
    default: str | None = None
    named: dict[str, str] = {}
    for value in given:
        name, sep, port = value.partition("=")
        if sep and name in connections:
            if name in named:
                raise ValueError(f"two ports for connection `{name}`")
            named[name] = port
        elif sep and name.isidentifier():
            raise ValueError(f"`{name}` is not a connection of {device.name} "
                             f"(its connections: {', '.join(connections) or 'none'})")
        elif default is not None:
            raise ValueError(f"two ports without a connection name: `{default}` and `{value}`")
        else:
            default = value
    if not named:
        assert default is not None
        return default
    for name in connections:
        if name not in named:
            fallback = default if default is not None else addresses.get(name)
            if fallback is None:
                raise ValueError(f"no port for connection `{name}`: add --port {name}=PORT")
            named[name] = fallback
    return named


def parse_settings(given: list[str], device: Device) -> dict[str, Any]:
    """--set NAME=VALUE ...: each value read as its setting's type says (`read_value`), for
    `bind_settings` to check; one that does not fit is an RdisValueError naming the setting."""
    declared = {p.name: p for p in device.settings}
    values: dict[str, Any] = {}
    for name, text in named_pairs(given, "--set ", "NAME", "{}").items():
        param = declared.get(name)
        try:
            values[name] = text if param is None else read_value(text, param, f"{device.name}: setting {name}")
        except TypeError as err:
            raise RdisValueError(str(err)) from None
    return values


def named_pairs(words: list[str], said: str, key: str, shown: str) -> dict[str, str]:
    """`K=V` words as a dict in their order: `said` starts a refusal, `key` names the K of a
    word without one, `shown` writes a K given twice."""
    given: dict[str, str] = {}
    for pair in words:
        name, sep, text = pair.partition("=")
        if not sep or not name:
            raise ValueError(f"{said}`{pair}` is not {key}=VALUE")
        if name in given:
            raise ValueError(f"{said}{shown.format(name)} given twice")
        given[name] = text
    return given


def parse_call(words: list[str], device: Device) -> tuple[str, str, dict[str, Value]]:
    """--call NAME K=V ...: (name, "input" | "interface" | "primitive", values in declaration
    order, each read as its parameter's or field's type says, `read_value`; those left out take
    their defaults); an input is preferred to an interface of the same name, an interface to a
    primitive. An unknown name is answered with the nearest known one. A value that does not fit
    is refused here, before anything is opened (TypeError, or RdisValueError naming it)."""
    name, *pairs = words
    plan: Input | Interface | Primitive | None = None
    for kind, plan in (("input", device.inputs.get(name)), ("interface", device.interfaces.get(name)),
                       ("primitive", device.primitives.get(name))):
        if plan is not None:
            break
    else:
        known = list(dict.fromkeys([*device.inputs, *device.interfaces, *device.primitives]))
        near = nearest(name, known)
        hint = f"did you mean `{near}`?" if near else f"there are: {', '.join(known) or 'none'}"
        raise ValueError(f"{device.name} has no input, interface or primitive `{name}`; {hint}")
    given = named_pairs(pairs, f"--call {name}: ", "KEY", "`{}`")
    try:
        return name, kind, call_values(device, kind, name, given)
    except Unbound:
        params = plan.fields if isinstance(plan, Input) else plan.params
        wanted = " ".join(f"{p.name}=..." if p.default is None else f"[{p.name}={p.default!r}]" for p in params)
        raise ValueError(f"--call {name} takes {wanted or 'no values'}") from None


def make_call(robot: Robot, kind: str, name: str, values: Mapping[str, Value]) -> None:
    """A call of an input, interface or primitive with its values by name, in declaration order
    (`call_values`'): how `--call`, the console and a replay make theirs."""
    if kind == "input":
        robot.call_input(name, **values)
    elif kind == "interface":
        robot.call_interface(name, *values.values())
    else:
        robot.call_primitive(name, *values.values())


def _watcher(robot: Robot) -> Callable[[dict[str, Any]], None]:
    """`--watch`'s printer: an output that reads sensors also says how old each one's value is
    (`"sensor_ages"`, seconds by the robot's clock), the rest as they are."""
    read = {o.name: o.sensors for i in robot.device.interfaces.values() for o in i.outputs if o.sensors}
    if not read:
        return _print_output

    def watched(message: dict[str, Any]) -> None:
        sensors = read.get(message["name"], ())
        if sensors:
            ages = {name: robot.sensor_age(name) for name in sensors}
            message = {**message, "sensor_ages": {n: None if a is None else round(a, 6) for n, a in ages.items()}}
        _print_output(message)

    return watched


def _print_output(message: dict[str, Any]) -> None:
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def _print_error(error: BaseException) -> None:
    print(f"rdisc run: {type(error).__name__}: {error}", file=sys.stderr, flush=True)


def _print_io(elapsed: float, kind: str, connection: str, data: bytes) -> None:
    """One --trace line: the seconds since the run began when it happened, the connection, then
    `>` and the bytes written, `<` and the bytes read, `lines` and the modem lines set, or `skip`
    and why a reply was read past."""
    if kind in ("lines", "skip"):
        shown = f"{kind} {data.decode('utf-8', 'replace')}"
    else:
        shown = f"{'>' if kind == 'write' else '<'} {data.hex(' ')}"
    print(f"{elapsed:.4f} {connection} {shown}", file=sys.stderr, flush=True)


def _sleep(seconds: float | None) -> None:
    """Sleep (forever if None or infinite); a signal ends it through its handler, and one whose
    exception Python dropped before is raised first."""
    raise_dropped()
    if seconds is None or seconds == math.inf:
        while True:
            time.sleep(3600)
    elif seconds > 0:
        time.sleep(seconds)
