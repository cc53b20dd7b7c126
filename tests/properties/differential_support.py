"""Running one description in both implementations and comparing what each does.

Both the runtime (`rdisc.runtime.load(...).connect`) and the generated driver
(`rdisc.emit.python.import_driver(...).connect`) are driven through their public
API only, with the same `Script` against a `PlannedDevice` behind a `ScriptedPort`
(tests/support/ports.py): a device that answers each exchange when its request is written (a
listener's when it reads with nothing pending) with the reply its `ReplyPlan`
says, computed from the request, the robot's state at that moment and the
primitive's parameters. Everything observable goes into one ordered log: every
write and input reset the device sees, every on_io, on_output and on_error
callback, each call's outcome (the error's type and the element its message
names first) and the state after it. The two logs must be equal.

Each run is also held against rules of the contract that both could break alike,
which a comparison alone would miss: every byte the port gave is shown to on_io;
a call answered with a reply the device model knows to be valid decodes it; calls
raise only the contract's error types; a value outside its range is refused; an
interface that completes delivers its output; the terminate hooks run while the robot
closes (a sensor they read too). Time is the wire's (`Clock`), so no deadline and no
sensor's age depends on how fast the machine runs the test; a `wait` moves it on.
"""

from __future__ import annotations

import difflib
import hashlib
import math
import os
import pprint
import re
import sys
import time
from collections import deque
from collections.abc import Callable, Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from types import ModuleType
from typing import Any

from descriptions import (
    CallStmt,
    Description,
    Interface,
    Operation,
    Primitive,
    ReplyPlan,
    Script,
    Sensor,
    Unknown,
    reply_for,
)
from renaming import Renamed

from rdisc.emit.python import import_driver
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

Log = list[tuple[Any, ...]]


# ---- the device --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Exchange:
    """An exchange the device expects: which primitive, its parameters' values (computed from the
    state when the request arrives), and how to answer."""

    primitive: Primitive
    values: Callable[[dict[str, Any]], dict[str, Any]]
    plan: ReplyPlan
    sensor: Sensor | None = None  # a sensor's read: made only when its value is older than its cache time


class Clock:
    """Time as the wire sees it: it passes only while a read waits for bytes that never come (the
    port's timeout, which the robot sets to what is left of a reply's deadline). So deadlines fall
    where they would against a real device, and never because the machine running the test is slow."""

    def __init__(self) -> None:
        self.now = 1000.0

    def monotonic(self) -> float:
        return self.now


@contextmanager
def wire_time(clock: Clock) -> Iterator[Clock]:
    """`time.monotonic` is the clock's while both implementations run (they read it as `time.monotonic()`)."""
    real = time.monotonic
    time.monotonic = clock.monotonic
    try:
        yield clock
    finally:
        time.monotonic = real


class PlannedDevice:
    """The device behind the port (a `ScriptedPort`): it answers each exchange as planned."""

    def __init__(self, description: Description) -> None:
        self.description = description
        self.queue: deque[Exchange] = deque()
        self.answers: list[bool] = []  # per exchange answered: whether its reply was valid
        self.failures = 0  # times the port raised
        self.state: Callable[[], dict[str, Any]] = lambda: {n: v for n, _, v in description.states}
        # A sensor's age as the robot tells it (`robot.sensor_age`): which of the reads an operation may
        # make it makes. A read in flight has no age yet or one past the cache time (the clock stands
        # still but while a read waits), so a sensor younger than its cache time is one not read now.
        self.age: Callable[[str], float | None] = lambda name: None

    def expect(self, exchanges: Iterable[Exchange]) -> None:
        """The exchanges of the next operation, in the order they are expected."""
        self.queue = deque(exchanges)

    def answer(self, request: bytes, listening: bool = False) -> bytes:
        """The next exchange's reply, made now; a listener's is not checked for validity, since bytes
        the robot put back after an earlier reply come before it."""
        self._pass_fresh()
        if not self.queue:
            return b""
        exchange = self.queue.popleft()
        if exchange.plan.kind == "broken":
            self.failures += 1
            raise OSError(5, "the device is gone")
        state = self.state()
        try:
            values = exchange.values(state)
        except Unknown:
            values = dict(state)
        wire = reply_for(self.description, exchange.primitive, values, request, exchange.plan)
        self.answers.append(wire.valid and not listening)
        return wire.data

    def _pass_fresh(self) -> None:
        """Drop the reads of sensors still fresh: the robot makes none of them."""
        while self.queue and self.queue[0].sensor is not None:
            sensor = self.queue[0].sensor
            age = self.age(sensor.name)
            if age is None or age >= sensor.cache_ms / 1000.0:
                return
            self.queue.popleft()

    def listen(self) -> bytes:
        """A listener's reply, when the robot reads with nothing waiting."""
        self._pass_fresh()
        if self.queue and self.queue[0].primitive.listens:
            return self.answer(b"", listening=True)
        return b""


# ---- what each operation is expected to exchange -------------------------------------------------------


def _evaluate(args: tuple[Any, ...], names: Iterable[str], env: dict[str, Any]) -> dict[str, Any]:
    values = dict(env)
    for name, arg in zip(names, args):
        try:
            values[name] = arg.value(env)
        except (Unknown, ArithmeticError, ValueError, TypeError, KeyError):
            values.pop(name, None)
    return values


def _sensed(sensor: Sensor, plan: ReplyPlan) -> Exchange:
    return Exchange(sensor.primitive, lambda live: live, plan, sensor)


def _calls(description: Description, iface: Interface, arguments: Callable[[dict[str, Any]], dict[str, Any]],
           plans: Iterable[ReplyPlan]) -> list[Exchange]:
    """The exchanges of an interface, in the order it makes them: its sensors' reads, its calls, the
    reads of the sensors its output reads."""
    out = []
    for run, plan in zip(description.runs(iface), plans):
        if not isinstance(run, CallStmt):
            out.append(_sensed(run, plan))
            continue

        def values(state: dict[str, Any], call: CallStmt = run) -> dict[str, Any]:
            env = {**state, **arguments(state)}
            return _evaluate(call.args, [p.name for p in call.primitive.params], env)
        out.append(Exchange(run.primitive, values, plan))
    return out


def exchanges(description: Description, op: Operation, state: dict[str, Any]) -> list[Exchange]:
    """The exchanges an operation is expected to make (fewer happen when one fails)."""
    plans = iter(op.plans)
    if op.kind == "primitive":
        prim = description.primitive(op.name)
        given = dict(zip((p.name for p in prim.params), op.args))
        return [Exchange(prim, lambda live: {**live, **given}, plan) for plan in plans]
    if op.kind == "interface":
        iface = description.interface(op.name)
        given = {p.name: (float(v) if p.type == "float" and isinstance(v, int) else v)
                 for p, v in zip(iface.params, op.args)}
        return _calls(description, iface, lambda live: given, plans)
    if op.kind == "input":
        spec = description.input(op.name)
        read = [_sensed(sensor, plan) for sensor, plan in zip(description.sensors_read(spec.read_names()), plans)]

        def given_by(live: dict[str, Any]) -> dict[str, Any]:  # its arguments read the sensors just read
            fixed = _evaluate(spec.args, [p.name for p in spec.interface.params], {**live, **dict(op.args)})
            return {p.name: fixed[p.name] for p in spec.interface.params if p.name in fixed}
        if not read:  # its arguments as they are when it is called
            fixed_now = given_by(state)
            return _calls(description, spec.interface, lambda live: fixed_now, plans)
        return read + _calls(description, spec.interface, given_by, plans)
    if op.kind == "sensor":
        return [_sensed(description.sensor(op.name), plan) for plan in plans]
    out: list[Exchange] = []
    for iface in description.periodic():
        out += _calls(description, iface, lambda live: {}, plans)
    return out


def hook_exchanges(description: Description, hook: str, plans: Iterable[ReplyPlan],
                   state: dict[str, Any]) -> list[Exchange]:
    """The exchanges of every connection's startup or terminate hook, in declaration order."""
    plans = iter(plans)
    out: list[Exchange] = []
    for connection in description.connections:
        h = getattr(connection, hook)
        if h is not None:
            given = _evaluate(h.args, [p.name for p in h.interface.params], state)
            out += _calls(description, h.interface, lambda live, given=given: given, plans)
    return out


# ---- running ------------------------------------------------------------------------------------------


def normal(value: Any) -> Any:
    """A value made comparable: bools and floats tagged (True is not 1, 1.0 is not 1) and floats by repr
    (nan equals nan, -0.0 is not 0.0), containers inside out."""
    if isinstance(value, bool):
        return ("bool", value)
    if isinstance(value, float):
        return ("float", repr(value))
    if isinstance(value, dict):
        return tuple((k, normal(v)) for k, v in value.items())
    if isinstance(value, (list, tuple)):
        return tuple(normal(v) for v in value)
    if isinstance(value, (bytes, bytearray)):
        return bytes(value)
    return value


def snapshot(robot: Any) -> Any:
    """The robot's state, by name (the contract fixes no order), and each sensor's age (a sensor is state too)."""
    ages = {name: robot.sensor_age(name) for name in sorted(robot.device.sensors)}
    return normal(dict(sorted(dict(robot.state).items()))), normal(ages)


def error_key(err: BaseException) -> tuple[str, str]:
    """What the contract fixes of an error: its type, and the element its message names first."""
    return type(err).__name__, str(err).split(":")[0]


def _plainly(param: Any, value: Any) -> bool:
    """Whether a value is plainly of its parameter's type (no conversion the contract allows)."""
    kinds = {"int": (int,), "float": (int, float), "bool": (bool,), "string": (str,), "bytes": (bytes, bytearray),
             "int[]": (list, tuple)}
    return isinstance(value, kinds[param.type]) and (param.type == "bool" or not isinstance(value, bool))


def _refusing(description: Description, op: Operation) -> str:
    """The element that must refuse this call for a value outside a range ("" if none must), as
    its error names it first."""
    if op.kind not in ("primitive", "interface"):
        return ""
    element = description.primitive(op.name) if op.kind == "primitive" else description.interface(op.name)
    if len(op.args) != len(element.params) or not all(_plainly(p, v) for p, v in zip(element.params, op.args)):
        return ""
    if any(isinstance(v, float) and not math.isfinite(v) for v in op.args):  # refused as it is taken, before
        return f"{op.kind} {element.name}"  # any range is tested: "primitive p0: parameter a0 is nan: ..."
    for p, v in zip(element.params, op.args):
        if p.low is not None and p.high is not None:
            size = len(v) if p.type == "bytes" else v
            if not p.low <= size <= p.high:
                return element.name
    return ""


def _triggered(description: Description, op: Operation) -> str:
    """The output an interface call that completes must deliver ("" if none)."""
    if op.kind == "interface":
        return description.interface(op.name).triggers or ""
    if op.kind == "input":
        return description.input(op.name).interface.triggers or ""
    return ""


def _perform(robot: Any, op: Operation, clock: Clock) -> Any:
    """Do what the operation says; a sensor's value is returned."""
    if op.kind == "wait":
        clock.now += op.args[0] / 1000.0
    elif op.kind == "sensor":
        return getattr(robot.sensors, op.name)
    elif op.kind == "tick":
        robot.tick()
    elif op.kind == "input":
        robot.call_input(op.name, **dict(op.args))
    elif op.kind == "interface":
        robot.call_interface(op.name, *op.args)
    else:
        robot.call_primitive(op.name, *op.args)


Connect = Callable[..., Any]
"""connect(port, threads=False, on_output=..., on_error=..., on_io=...) of either implementation."""

IO_RULE = "every byte read is shown to on_io"
ERROR_RULE = "calls raise the contract's error types"
REPLY_RULE = "a valid reply is decoded"
RANGE_RULE = "a value outside its parameter's range is refused"
OUTPUT_RULE = "an interface that completes delivers the output it triggers"
LOAD_RULE = "a checked description loads"
TERMINATE_RULE = "a terminate hook runs while the robot closes"
CALL_ERRORS = ("RdisTimeout", "RdisProtocolError", "RdisValueError", "RdisDeviceError", "TypeError", "KeyError")


@dataclass(frozen=True)
class Violation:
    """A rule of the contract broken by one implementation, which a comparison cannot see when
    both break it alike."""

    who: str  # runtime | driver
    rule: str
    where: str  # the call, or "session"
    detail: str

    def __str__(self) -> str:
        return f"{self.who}: {self.where}: {self.rule}, but {self.detail}"


@dataclass
class Run:
    """What one implementation did: the log that is compared, the full text of each error in it
    (by entry; only the type and the element named first are compared) and the contract's rules
    it broke."""

    who: str
    log: Log = field(default_factory=list)
    messages: dict[int, str] = field(default_factory=dict)
    violations: list[Violation] = field(default_factory=list)

    def error(self, head: tuple[Any, ...], err: BaseException, tail: tuple[Any, ...] = ()) -> None:
        self.messages[len(self.log)] = f"{type(err).__name__}: {err}"
        self.log.append((*head, *error_key(err), *tail))

    def broke(self, rule: str, where: str, detail: str) -> None:
        self.violations.append(Violation(self.who, rule, where, detail))


def run(who: str, connect: Connect, description: Description, script: Script) -> Run:
    """Everything observable when `script` runs against one implementation."""
    with wire_time(Clock()) as clock:
        return _run(Run(who), connect, description, script, clock)


def _run(result: Run, connect: Connect, description: Description, script: Script, clock: Clock) -> Run:
    log = result.log
    device = PlannedDevice(description)

    def waited(seconds: float) -> None:
        clock.now += seconds

    port = ScriptedPort(device=device, events=log, record_resets=True, timeout=1.0, on_timeout=waited)
    shown = bytearray()

    def on_io(direction: str, connection: str, data: bytes) -> None:
        log.append(("io", direction, connection, bytes(data)))
        if direction == "read":
            shown.extend(data)

    device.expect(hook_exchanges(description, "startup", script.startup, device.state()))
    try:
        robot = connect(port, threads=False, on_output=lambda o: log.append(("output", normal(o))),
                        on_error=lambda e: result.error(("reported",), e), on_io=on_io)
    except Exception as err:  # noqa: BLE001 - a failing startup is compared too
        result.error(("connect",), err)
    else:
        device.state = lambda: dict(robot.state)
        device.age = robot.sensor_age
        log.append(("connected", snapshot(robot)))
        for op in script.operations:
            device.expect(exchanges(description, op, dict(robot.state)))
            answered, failures, start = len(device.answers), device.failures, len(log)
            refused = _refusing(description, op)
            try:
                value = _perform(robot, op, clock)
                log.append((op.label(), "ok", normal(value), snapshot(robot)))
                if refused:
                    result.broke(RANGE_RULE, op.label(), f"{refused} accepted it")
                triggers = _triggered(description, op)
                if triggers and not any(e[0] == "output" and e[1][0] == ("name", triggers) for e in log[start:]):
                    result.broke(OUTPUT_RULE, op.label(), f"{triggers} was not delivered")
            except Exception as err:  # noqa: BLE001 - the error is what is compared
                if refused and error_key(err) != ("RdisValueError", refused):
                    result.broke(RANGE_RULE, op.label(), f"it raised {type(err).__name__}: {err}")
                result.error((op.label(),), err, (snapshot(robot),))
                kind = type(err).__name__  # a driver has error types of its own: compared by name
                if kind not in CALL_ERRORS + ("RdisConnectionError",) * (device.failures > failures):
                    result.broke(ERROR_RULE, op.label(), f"it raised {kind}: {err}")
                if kind in ("RdisProtocolError", "RdisTimeout") and op.kind == "primitive" \
                        and device.answers[answered:] == [True]:
                    result.broke(REPLY_RULE, op.label(), f"it raised {kind}: {err}")
        device.expect(hook_exchanges(description, "terminate", script.terminate, dict(robot.state)))
        closing, failures = len(log), device.failures
        robot.close()
        log.append(("closed", snapshot(robot)))
        refused = [result.messages[i] for i in range(closing, len(log)) if i in result.messages
                   and result.messages[i] == f"RdisConnectionError: {robot.name}: closed"]
        if refused and device.failures == failures:
            result.broke(TERMINATE_RULE, "close", f"it reported {refused[0]}")
        if script.after_close is not None:
            try:
                _perform(robot, script.after_close, clock)
                log.append((script.after_close.label(), "ok"))
            except Exception as err:  # noqa: BLE001 - compared
                result.error((script.after_close.label(),), err)
    if bytes(shown) != bytes(port.given):
        failed = " (the port had failed)" if device.failures else ""
        result.broke(IO_RULE, "session", f"it showed {bytes(shown)!r} where the port gave {bytes(port.given)!r}{failed}")
    return result


# ---- both implementations of one description ---------------------------------------------------------


class Pair:
    """The runtime and the generated driver of one description text (the driver imported once)."""

    def __init__(self, description: Description, folder: str, renaming: Mapping[str, str] | None = None) -> None:
        """`renaming`: the description's names as the text renames them (`renaming.renamed`); the
        robots take calls by the names as drawn."""
        digest = hashlib.sha1(description.text.encode()).hexdigest()[:16]
        self.description = description
        self.renaming = renaming
        self.module_name = f"generated_{digest}"
        path = os.path.join(folder, f"{self.module_name}.rdis")
        with open(path, "w", encoding="utf-8") as out:
            out.write(description.text)
        self.failure: list[Violation] = []  # an implementation that could not even load the description
        try:
            self.runtime = load(path)
        except Exception as err:  # noqa: BLE001 - reported, not raised
            self.failure.append(Violation("runtime", LOAD_RULE, "load", f"it raised {type(err).__name__}: {err}"))
        try:
            self.driver: ModuleType = import_driver(path, folder, self.module_name)
        except Exception as err:  # noqa: BLE001 - reported, not raised
            self.failure.append(Violation("driver", LOAD_RULE, "import_driver", f"it raised {type(err).__name__}: {err}"))

    def forget(self) -> None:
        """Drop the driver module (a long search imports thousands)."""
        sys.modules.pop(self.module_name, None)

    def runtime_connect(self, port: Any, **kwargs: Any) -> Any:
        return self._named(self.runtime.connect(port, **kwargs))

    def driver_connect(self, port: Any, **kwargs: Any) -> Any:
        return self._named(self.driver.connect(port, **kwargs))

    def _named(self, robot: Any) -> Any:
        return robot if self.renaming is None else Renamed(robot, self.renaming)


@dataclass(frozen=True)
class Known:
    """An open bug both implementations share, found by these tests: the random tests pass over it
    (a test of its own, marked xfail, keeps it in view) and the benchmark labels it."""

    name: str
    matches: Callable[[Violation, Description], bool]


KNOWN: tuple[Known, ...] = ()
"""None open now. An entry names a bug and matches its violations, e.g. `Known("an XOR narrower than 8 bits
is not reduced to its width", lambda v, d: v.rule == REPLY_RULE and ...)`; remove it with the fix."""


def known(v: Violation, d: Description) -> Known | None:
    return next((k for k in KNOWN if k.matches(v, d)), None)


@dataclass(frozen=True)
class Outcome:
    """Both runs of one script, and what is wrong with them (nothing, when they agree and keep the contract)."""

    description: Description
    runtime: Run
    driver: Run

    @property
    def violations(self) -> list[Violation]:
        return self.runtime.violations + self.driver.violations

    @property
    def new_violations(self) -> list[Violation]:
        """The violations that no known bug explains."""
        return [v for v in self.violations if known(v, self.description) is None]

    @property
    def agree(self) -> bool:
        return self.runtime.log == self.driver.log

    @property
    def ok(self) -> bool:
        """They agree, and keep the contract but for known bugs."""
        return self.agree and not self.new_violations

    def signatures(self) -> list[tuple[Any, ...]]:
        """A short name for each thing that went wrong, to tell one problem from another: the kinds
        of the first entries that differ (with the shape of their errors), the rules broken and how."""
        names = []
        if not self.agree:
            a, b = self.runtime.log, self.driver.log
            at = next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
            names.append(("disagree", _kind(self.runtime, at), _kind(self.driver, at)))
        for v in self.violations:
            bug = known(v, self.description)
            names.append(("known", bug.name) if bug is not None else ("contract", v.rule, _shape(v.detail)))
        return list(dict.fromkeys(names))

    def report(self) -> str:
        lines = []
        for v in self.violations:
            bug = known(v, self.description)
            lines.append(f"- {v}" + (f"  [known: {bug.name}]" if bug is not None else ""))
        if not self.agree:
            a = pprint.pformat(self.runtime.log, width=110).splitlines()
            b = pprint.pformat(self.driver.log, width=110).splitlines()
            lines += difflib.unified_diff(a, b, "runtime", "generated driver", lineterm="", n=4)
            a_at, b_at = self.runtime.messages, self.driver.messages
            for i in sorted(set(a_at) | set(b_at)):
                if a_at.get(i) != b_at.get(i):
                    lines.append(f"  entry {i}: runtime {a_at.get(i, '-')!r}; driver {b_at.get(i, '-')!r}")
        return "\n".join(lines)


def _shape(message: str) -> str:
    """A message without its particulars (numbers, quoted values), cut short."""
    message = re.sub(r"b?'[^']*'|\"[^\"]*\"", "Q", message)
    return re.sub(r"\d+(\.\d+)?(e[+-]?\d+)?", "N", message)[:80]


def _kind(run: Run, at: int) -> tuple[Any, ...]:
    """The log entry at `at` reduced to its kind: a call and its outcome type, an event, a write."""
    if at >= len(run.log):
        return ("(nothing)",)
    entry = run.log[at]
    head = entry[0]
    if head in ("write", "reset input", "connected", "closed", "output"):
        return (head,)
    kind = (head.split("(")[0], entry[1]) if head not in ("io", "reported", "connect") else (head, entry[1])
    return (*kind, _shape(run.messages[at])) if at in run.messages else kind


def compare(pair: Pair, script: Script) -> Outcome:
    """Both implementations through the same session."""
    if pair.failure:
        failed = Run("runtime")
        failed.violations += pair.failure
        return Outcome(pair.description, failed, Run("driver"))
    return Outcome(pair.description, run("runtime", pair.runtime_connect, pair.description, script),
                   run("driver", pair.driver_connect, pair.description, script))


class Pairs:
    """The last few descriptions' pairs: shrinking a script reruns one description many times."""

    def __init__(self, folder: str, size: int = 8) -> None:
        self.folder = folder
        self.size = size
        self.pairs: dict[str, Pair] = {}

    def __call__(self, description: Description, renaming: Mapping[str, str] | None = None) -> Pair:
        """`renaming`: as `Pair`'s (the description's text renamed by it)."""
        pair = self.pairs.pop(description.text, None) or Pair(description, self.folder, renaming)
        self.pairs[description.text] = pair  # now the most recent
        while len(self.pairs) > self.size:
            oldest = next(iter(self.pairs))
            self.pairs.pop(oldest).forget()
        return pair
