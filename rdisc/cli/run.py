"""`rdisc run FILE --port P [--call NAME k=v ...]...`: drive a device from the command line.

Loads the description, connects (startup hooks), performs the calls in order,
then runs for `--duration` seconds, or until Ctrl-C with `--watch`, or ends when
the calls are done. Whatever happens (the end, a device error, Ctrl-C, SIGTERM),
it ends by running the terminate hooks, so a robot is left stopped.

Exit status: 0 done; 1 the description has errors or the device failed; 2 a
usage error (a bad --port or --call); 130 after SIGINT, 143 after SIGTERM.
"""

from __future__ import annotations

import argparse
import json
import signal
import sys
import time
from typing import Any

from rdisc.cli.output import EXIT_ERRORS, EXIT_OK, EXIT_USAGE, exit_code, show
from rdisc.compile import compile_path
from rdisc.semantics import model as m

EXIT_SIGINT, EXIT_SIGTERM = 130, 143


def add_parser(verbs) -> None:
    p = verbs.add_parser(
        "run", help="run a description against a device: calls, outputs, I/O trace",
        description="Connect to a device, perform calls and show outputs. The terminate hooks always run at the end.",
    )
    p.add_argument("file", metavar="FILE", help=".rdis or thesis-style .json description")
    p.add_argument("--port", action="append", default=[], metavar="[CONN=]PORT",
                   help="a pyserial port or URL (/dev/ttyUSB0, COM3, socket://host:port); "
                        "CONN=PORT for one connection of several (repeat the option)")
    p.add_argument("--call", action="append", nargs="+", default=[], metavar="NAME [K=V ...]",
                   help="call an input (or an interface, or a primitive) with named values; repeat for several "
                        "calls, in order")
    p.add_argument("--watch", action="store_true", help="print each output as a JSON line as it arrives")
    p.add_argument("--trace", action="store_true", help="print every byte written and read, in hex, on stderr")
    p.add_argument("--duration", type=float, metavar="S",
                   help="run for S seconds (default: until the calls are done; with --watch, until Ctrl-C)")
    p.add_argument("--timeout", type=float, default=1.0, metavar="S", help="reply timeout in seconds (default 1)")
    p.set_defaults(run=run)


class _Terminated(BaseException):
    """SIGTERM, turned into an exception so that the terminate hooks run on the way out."""


def run(args: argparse.Namespace) -> int:
    compilation = compile_path(args.file)
    show([compilation])
    if compilation.model is None or compilation.diagnostics.has_errors():
        return exit_code([compilation]) or EXIT_ERRORS
    model = compilation.model
    try:
        ports = parse_ports(args.port, model)
        calls = [parse_call(call, model) for call in args.call]
    except ValueError as err:
        print(f"rdisc run: {err}", file=sys.stderr)
        return EXIT_USAGE

    from rdisc.runtime import RdisError
    from rdisc.runtime.device import Description

    handlers = _install_signal_handlers()
    robot = None
    status = EXIT_OK
    try:
        start = time.monotonic()
        robot = Description(model).connect(
            ports, timeout=args.timeout,
            on_output=_print_output if args.watch else None,
            on_error=_print_error,
            on_io=_print_io if args.trace else None,
        )
        for name, kind, values in calls:
            if kind == "input":
                robot.call_input(name, **values)
            elif kind == "interface":
                robot.call_interface(name, *values)
            else:
                robot.call_primitive(name, *values)
        if args.duration is not None:
            _sleep(args.duration - (time.monotonic() - start))
        elif args.watch:
            _sleep(None)
    except RdisError as err:
        print(f"rdisc run: {type(err).__name__}: {err}", file=sys.stderr)
        status = EXIT_ERRORS
    except TypeError as err:  # values of the wrong type for a call
        print(f"rdisc run: {err}", file=sys.stderr)
        status = EXIT_USAGE
    except KeyboardInterrupt:
        status = EXIT_SIGINT
    except _Terminated:
        status = EXIT_SIGTERM
    finally:
        _shutting_down[0] = True  # a second signal must not cut the terminate hooks short
        try:
            if robot is not None:
                robot.close()
        finally:
            _restore_signal_handlers(handlers)
    return status


# ---- arguments ----------------------------------------------------------------------------------------


def parse_ports(given: list[str], model: m.Model) -> str | dict[str, str] | None:
    """`--port P` for every connection, `--port CONN=P` for one; a plain port is the default for the rest,
    and a connection given none opens its `address`."""
    addresses = {name: c.address for name, c in model.connections.items() if c.address is not None}
    if not given and len(addresses) == len(model.connections):
        return None
    if not given:
        raise ValueError("give the device's port: --port /dev/ttyUSB0 (or CONN=PORT for each connection)")
    default: str | None = None
    named: dict[str, str] = {}
    for value in given:
        name, sep, port = value.partition("=")
        if sep and name in model.connections:
            if name in named:
                raise ValueError(f"two ports for connection `{name}`")
            named[name] = port
        elif sep and name.isidentifier():
            raise ValueError(f"`{name}` is not a connection of {model.robot.name} "
                             f"(its connections: {', '.join(model.connections) or 'none'})")
        elif default is not None:
            raise ValueError(f"two ports without a connection name: `{default}` and `{value}`")
        else:
            default = value
    if not named:
        assert default is not None
        return default
    missing = [c for c in model.connections if c not in named and c not in addresses]
    if missing and default is None:
        raise ValueError(f"no port for connection `{missing[0]}`: add --port {missing[0]}=PORT")
    return {c: named.get(c, default if default is not None else addresses.get(c)) for c in model.connections}  # type: ignore[misc]


def parse_value(text: str) -> int | float | bool | str:
    """A command-line value: an int, a float, True/False, else the string itself."""
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    if text in ("True", "False"):
        return text == "True"
    return text


def parse_call(words: list[str], model: m.Model) -> tuple[str, str, Any]:
    """(name, "input" | "interface" | "primitive", values) for `NAME k=v ...`; an input is preferred
    to an interface, an interface to a primitive."""
    name, *pairs = words
    values: dict[str, Any] = {}
    for pair in pairs:
        key, sep, text = pair.partition("=")
        if not sep or not key:
            raise ValueError(f"--call {name}: `{pair}` is not KEY=VALUE")
        if key in values:
            raise ValueError(f"--call {name}: `{key}` given twice")
        values[key] = parse_value(text)
    if name in model.inputs:
        adapter = model.adapters[model.inputs[name].adapter]
        _check_names(name, list(values), [f.name for f in adapter.fields], "fields")
        return name, "input", values
    if name in model.interfaces:
        params = [p.name for p in model.interfaces[name].params]
        _check_names(name, list(values), params, "parameters")
        return name, "interface", [values[p] for p in params]
    if name in model.primitives:
        params = [p.name for p in model.primitives[name].params]
        _check_names(name, list(values), params, "parameters")
        return name, "primitive", [values[p] for p in params]
    known = ", ".join(dict.fromkeys([*model.inputs, *model.interfaces, *model.primitives]))
    raise ValueError(f"{model.robot.name} has no input, interface or primitive `{name}` "
                     f"(there are: {known or 'none'})")


def _check_names(name: str, given: list[str], expected: list[str], what: str) -> None:
    if sorted(given) != sorted(expected):
        wanted = " ".join(f"{e}=..." for e in expected) or f"no {what}"
        raise ValueError(f"--call {name} takes {wanted}")


# ---- printing ------------------------------------------------------------------------------------------


def _print_output(message: dict[str, Any]) -> None:
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def _print_error(error: BaseException) -> None:
    print(f"rdisc run: {type(error).__name__}: {error}", file=sys.stderr, flush=True)


def _print_io(direction: str, connection: str, data: bytes) -> None:
    arrow = ">" if direction == "write" else "<"
    print(f"{connection} {arrow} {data.hex(' ')}", file=sys.stderr, flush=True)


# ---- signals -------------------------------------------------------------------------------------------

_shutting_down = [False]


def _on_signal(signum: int, frame: object) -> None:
    if _shutting_down[0]:
        return  # the first signal already started the shutdown
    _shutting_down[0] = True
    raise KeyboardInterrupt if signum == signal.SIGINT else _Terminated()


def _install_signal_handlers() -> dict[int, Any]:
    _shutting_down[0] = False
    previous: dict[int, Any] = {}
    for signum in (signal.SIGINT, signal.SIGTERM):
        try:
            previous[signum] = signal.signal(signum, _on_signal)
        except ValueError:  # not the main thread: leave the handlers alone
            pass
    return previous


def _restore_signal_handlers(previous: dict[int, Any]) -> None:
    for signum, handler in previous.items():
        signal.signal(signum, handler)


def _sleep(seconds: float | None) -> None:
    """Sleep (forever if None); signals interrupt it through their handlers."""
    if seconds is None:
        while True:
            time.sleep(3600)
    elif seconds > 0:
        time.sleep(seconds)
