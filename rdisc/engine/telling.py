"""The exchange's telling: outputs delivered, events shown and errors reported to the callbacks, one at a time."""

from __future__ import annotations

import logging
import threading
import time
from collections import deque
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from rdisc.engine.errors import (
    RdisCallbackError,
    RdisValueError,
)
from rdisc.engine.kalman import KalmanFilter
from rdisc.engine.operations import EVAL_ERRORS
from rdisc.engine.plans import (
    Device,
    Output,
)
from rdisc.engine.ports import Simulator, _Link, _Port
from rdisc.engine.values import (
    ErrorCallback,
    IoCallback,
    OutputCallback,
    OutputMessage,
    TraceCallback,
    Value,
)

_log = logging.getLogger("rdisc")


class Telling:
    """The part of an Exchange that tells the callbacks what happened; it declares what a Robot sets."""

    device: Device
    name: str
    timeout: float
    _state: dict[str, Value]
    _read_ns: int | None  # when a reply last changed the state (ns since the epoch); None: none has
    _state_lock: threading.Lock
    _callback_lock: threading.RLock
    _ticking: threading.local  # `.port`: the port this thread's tick holds whole (`threading single`), else None
    _filters: dict[tuple[str, str], KalmanFilter]  # (output, field): its running filter, made when first delivered
    _output_callbacks: list[OutputCallback]
    _error_callbacks: list[ErrorCallback]
    _io_callbacks: list[IoCallback]
    _trace_callbacks: list[TraceCallback]
    _watched: bool  # an I/O or trace callback is registered: the events are queued and shown
    # What crossed the wire (and each reply skipped), stamped and queued as it happens, under the
    # port's lock: the callbacks are shown it in that order, once the port is free (`_show`).
    _events: deque[tuple[float, str, str, bytes]]
    _events_lock: threading.Lock
    _clock: Callable[[], float]
    _run_callbacks: list[Callable[[str, str, str], object]]
    _links: dict[str, _Link]
    _ports: dict[str, _Port]  # each connection's port, for a plain write to find at once
    # Closing (`Robot.close`): from the moment it begins nothing is written but by the thread that
    # closes (`_closer`: the terminate hooks), and once they are done nothing at all (`_closer` None).
    _closed: bool
    _closer: int | None
    _sim: Simulator | None  # a simulated device in place of the ports (`_simulated`)

    # ---- delivering to callbacks: one at a time, a failing one reported -----------------------------

    def _sense(self, names: tuple[str, ...]) -> None:
        """Make each named sensor fresh before it is read (the Robot's: `rdisc.engine.sensing`)."""
        raise NotImplementedError

    def _deliver(self, plan: Output) -> None:
        if plan.sensors:
            self._sense(plan.sensors)
        with self._state_lock:  # the snapshot and when it was read, together
            state, read_ns = self._state, self._read_ns
        try:
            contents = plan.fields(state)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        message = OutputMessage(plan.name, contents, time.time_ns() if read_ns is None else read_ns)
        port = self._take_turn()
        try:
            if plan.filters:
                message = OutputMessage(plan.name, self._filtered(plan, contents), message.read_ns)
            for callback in list(self._output_callbacks):
                try:
                    callback(message)
                except Exception as err:  # noqa: BLE001 - a user's callback must not stop delivery
                    error = RdisCallbackError(f"{plan.name}: output callback raised {type(err).__name__}: {err}")
                    error.__cause__ = err
                    self._report(error)
        finally:
            self._end_turn(port)

    def _take_turn(self) -> _Port | None:
        """The callbacks' turn (they run one at a time, under the callback lock). A tick that holds
        its port whole (`threading single`) and finds the turn taken lets the port go while it
        waits and runs the callbacks: the turn may be a callback's on another thread that is
        commanding the robot, which waits for the port. Returns that port, to take back after."""
        lock = self._callback_lock
        if lock.acquire(blocking=False):
            return None
        port: _Port | None = getattr(self._ticking, "port", None)
        if port is None:
            lock.acquire()
            return None
        port.lock.release()
        try:
            lock.acquire()
        except BaseException:  # a signal's exception while waiting: the tick holds its port again
            port.lock.acquire()
            raise
        return port

    def _end_turn(self, port: _Port | None) -> None:
        """The turn's end: the callback lock let go, then the tick's port taken back (never the
        port while holding the turn: a host's call holding its port may wait for the turn)."""
        self._callback_lock.release()
        if port is not None:
            port.lock.acquire()

    def _filtered(self, plan: Output, contents: dict[str, Value]) -> dict[str, Value]:
        """The fields a Kalman filter estimates, each filter stepped once by the value delivered
        (a number, or an array's values); under the callback lock, so deliveries step in turn."""
        for given in plan.filters:
            running = self._filters.get((plan.name, given.field))
            if running is None:
                running = self._filters[(plan.name, given.field)] = given.start()
            value = contents[given.field]
            if isinstance(value, (tuple, list)):
                contents = {**contents, given.field: type(value)(running.step(value))}
            else:
                contents = {**contents, given.field: running.step((float(value),))[0]}
        return contents

    def _happened(self, kind: str, connection: str, data: bytes) -> None:
        """An event as it happens, under the port's lock: stamped by the robot's clock and queued
        in the order of the wire, across threads and connections, for `_show`. "write" or "read"
        and the bytes, "lines" and the modem lines set (`_lines_text`), "skip" and why a reply
        was read past."""
        with self._events_lock:
            self._events.append((self._clock(), kind, connection, data))

    def _show(self) -> None:
        """The events queued, in order, to the callbacks, one at a time: the I/O callbacks every
        one but "skip", the trace callbacks every one with its stamp. A thread shows another's
        events that came before its own and are not shown yet (so a line never jumps the queue)."""
        port = self._take_turn()
        try:
            while True:
                with self._events_lock:
                    if not self._events:
                        return
                    when, kind, connection, data = self._events.popleft()
                if kind != "skip":
                    self._notify(self._io_callbacks, connection, kind, connection, data)
                self._notify(self._trace_callbacks, connection, when, kind, connection, data)
        finally:
            self._end_turn(port)

    def _notify(self, callbacks: Sequence[Callable[..., object]], connection: str, *event: Any) -> None:
        for callback in list(callbacks):
            try:
                callback(*event)
            except Exception as err:  # noqa: BLE001 - a user's callback must not stop the I/O
                error = RdisCallbackError(f"{connection}: I/O callback raised {type(err).__name__}: {err}")
                error.__cause__ = err
                self._report(error)

    def _notify_run(self, connection: str, kind: str, name: str) -> None:
        """Tell a recorder that a connection's thread starts a periodic interface or its keepalive."""
        port = self._take_turn()
        try:
            for callback in list(self._run_callbacks):
                callback(connection, kind, name)
        finally:
            self._end_turn(port)

    def _report(self, error: BaseException) -> None:
        port = self._take_turn()
        try:
            callbacks = list(self._error_callbacks)
            if not callbacks:
                _log.warning("%s: %s: %s", self.name, type(error).__name__, error)
            for callback in callbacks:
                try:
                    callback(error)
                except Exception:  # noqa: BLE001, S110 - the contract: an error callback's failure is ignored
                    pass
        finally:
            self._end_turn(port)


def _lines_text(levels: Mapping[str, Value]) -> bytes:
    """The modem lines a primitive set and its break, as the I/O callbacks see them:
    b"dtr=False rts=True", b"break=10ms"."""
    return " ".join(f"break={_ms(level).replace(' ', '')}" if line == "break" else f"{line}={bool(level)}"
                    for line, level in levels.items()).encode("ascii")


def _ms(level: Value) -> str:
    """A break's duration as said: "10 ms"."""
    return f"{level:g} ms" if isinstance(level, (int, float)) else repr(level)
