"""The schedule of a connection: its periodic interfaces and keepalive, each run on a
thread of the connection when due, never in a burst, by its threading model.

`single`: one thread, and a tick holds the port, so a host's command waits for the whole
tick. `dual`: one thread for the periodic work, which takes the port for each exchange
only, so a command waits for at most the exchange in flight. `multiple`: a thread for each
periodic interface at its own rate (and one for the keepalive), each taking the port for
each exchange.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable, Mapping
from typing import Protocol

from rdisc.engine.errors import RdisConnectionError
from rdisc.engine.plans import Connection, Hook, Interface
from rdisc.engine.ports import _Port
from rdisc.engine.signals import Flag, without_signals
from rdisc.engine.values import Args


class _Owner(Protocol):
    """What a connection's thread uses of its robot (a `Robot`, whose module comes after this one)."""

    name: str
    _clock: Callable[[], float]
    _closed: bool
    _run_callbacks: list[Callable[[str, str, str], object]]
    _ticking: threading.local

    @property
    def _ports(self) -> Mapping[str, _Port]: ...

    def _interface(self, plan: Interface, args: Args) -> None: ...
    def _hook(self, hook: Hook) -> None: ...
    def _notify_run(self, connection: str, kind: str, name: str) -> None: ...
    def _report(self, error: BaseException) -> None: ...


def _connection_workers(robot: _Owner, connection: Connection) -> list[_Worker]:
    """The threads' work of a connection by its threading model: one worker under `single` and
    `dual`; under `multiple` one for each periodic interface, at its rate (0: the connection's),
    and one for the keepalive. Under `dual` and `multiple` the port's lock is a fair one (`ports._FairLock`)."""
    if connection.threading != "multiple":
        return [_Worker(robot, connection)]
    rates = connection.rates or (0.0,) * len(connection.periodic)
    made = [_Worker(robot, connection, (interface,), rate or connection.frequency, keepalive=False)
            for interface, rate in zip(connection.periodic, rates)]
    if connection.keepalive is not None and connection.interval:
        made.append(_Worker(robot, connection, (), 0.0))
    return made or [_Worker(robot, connection, (), 0.0)]


class _Worker:
    """A thread's work on a connection (periodic interfaces, the keepalive) and when it is due.

    Tick k is due at start + k / frequency; a tick already past when the previous one
    ends is skipped, not run in a burst. The keepalive is due one interval after start,
    then every interval after the time it was due (or one interval after now, if that is
    past too). The thread waits on an Event between ticks, so it never spins, and wakes
    at once when stopped.
    """

    def __init__(self, robot: _Owner, connection: Connection, periodic: tuple[Interface, ...] | None = None,
                 frequency: float | None = None, *, keepalive: bool = True) -> None:
        self.robot = robot
        self.connection = connection
        self.periodic = connection.periodic if periodic is None else periodic
        frequency = connection.frequency if frequency is None else frequency
        self.period = 1.0 / frequency if frequency > 0 else math.inf
        self.interval = connection.interval if keepalive and connection.keepalive is not None else 0.0
        self.whole = connection.threading == "single"  # a tick holds the port
        self._lock = threading.Lock()
        self._stop = Flag()
        self._thread: threading.Thread | None = None
        self.restart_clock()

    def restart_clock(self) -> None:
        """Make now the start of the schedule."""
        with self._lock:
            self._start = self.robot._clock()
            self._keepalive_due = self._start + self.interval

    def tick(self) -> None:
        """One iteration: each periodic interface, then the keepalive if it is due. Errors go
        to the error callbacks, and the schedule goes on. Under `single` the tick holds the
        port (re-entrant: its exchanges take it again), so another thread's command waits for
        the whole tick; one made by a callback on this thread goes in between. Only while it
        waits for the callbacks' turn, which a callback on another thread may hold while it
        commands the robot, does the tick let the port go."""
        port = self.robot._ports.get(self.connection.name) if self.whole else None
        if port is None:  # dual, multiple, or a simulated device: no port to hold
            self._tick()
            return
        port.lock.acquire()
        ticking = self.robot._ticking
        ticking.port = port  # the callbacks' turn lets it go while it waits (`Exchange._take_turn`)
        try:
            self._tick()
        finally:
            ticking.port = None
            port.lock.release()

    def _tick(self) -> None:
        robot = self.robot
        for interface in self.periodic:
            if self._stop.is_set():
                return
            if robot._run_callbacks:
                robot._notify_run(self.connection.name, "periodic", interface.name)
            try:
                robot._interface(interface, [])
            except Exception as err:  # noqa: BLE001 - reported; the schedule goes on
                self._report(err)
        keepalive = self.connection.keepalive
        if keepalive is None or not self.interval:
            return
        with self._lock:
            now = robot._clock()
            if now < self._keepalive_due:
                return
            due = self._keepalive_due + self.interval
            self._keepalive_due = due if due > now else now + self.interval
        if robot._run_callbacks:
            robot._notify_run(self.connection.name, "keepalive", keepalive.interface.name)
        try:
            robot._hook(keepalive)
        except Exception as err:  # noqa: BLE001 - reported; the schedule goes on
            self._report(err)

    def _report(self, err: Exception) -> None:
        """Report an error of the work, but not the refusal that ends it when the robot closes."""
        if not (self.robot._closed and isinstance(err, RdisConnectionError)):
            self.robot._report(err)

    def start(self) -> None:
        self.restart_clock()
        # Kept before it starts: a signal may interrupt `start()` once the thread exists.
        name = f"{self.robot.name} {self.connection.name}"
        if self.connection.threading == "multiple":
            name += f" {self.periodic[0].name if self.periodic else 'keepalive'}"
        self._thread = threading.Thread(target=self._loop, name=name, daemon=True)
        without_signals(self._thread.start)

    def stop(self) -> None:
        """Stop the thread; it finishes the interface it is running first. Not waited for when
        this thread holds the connection's port: a signal that landed between a command's taking
        of the port and its `try` left it held, and the thread's next tick waits for it for ever
        (the port's lock and the robot's closed test keep the terminate hooks' stop last)."""
        self._stop.set()
        thread = self._thread
        port = self.robot._ports.get(self.connection.name)
        if port is not None and port.held_here():
            return
        if thread is not None and thread is not threading.current_thread():
            try:
                thread.join()
            except RuntimeError:  # its start was interrupted before it ran: it will see the stop and end
                pass

    def _loop(self) -> None:
        periodic = bool(self.periodic)
        if not periodic and not self.interval:
            self._stop.wait()
            return
        k = 0
        while not self._stop.is_set():
            self.tick()
            if periodic:
                k = max(k + 1, math.ceil((time.monotonic() - self._start) / self.period))
                wake = self._start + k * self.period
            else:  # only a keepalive: wake when it is due
                wake = self._keepalive_due
            delay = wake - time.monotonic()
            if delay > 0 and self._stop.wait(delay):
                return
