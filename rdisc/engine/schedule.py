"""The schedule of a connection: its periodic interfaces and keepalive, each run on the
connection's own thread when due, never in a burst.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from typing import Protocol

from rdisc.engine.errors import RdisConnectionError
from rdisc.engine.plans import Connection, Hook, Interface
from rdisc.engine.values import Args


class _Owner(Protocol):
    """What a connection's thread uses of its robot (a `Robot`, whose module comes after this one)."""

    name: str
    _clock: Callable[[], float]
    _closed: bool
    _run_callbacks: list[Callable[[str, str, str], object]]

    def _interface(self, plan: Interface, args: Args) -> None: ...
    def _hook(self, hook: Hook) -> None: ...
    def _notify_run(self, connection: str, kind: str, name: str) -> None: ...
    def _report(self, error: BaseException) -> None: ...


class _Worker:
    """One connection's own work (its periodic interfaces, its keepalive) and when it is due.

    Tick k is due at start + k / frequency; a tick already past when the previous one
    ends is skipped, not run in a burst. The keepalive is due one interval after start,
    then every interval after the time it was due (or one interval after now, if that is
    past too). The thread waits on an Event between ticks, so it never spins, and wakes
    at once when stopped.
    """

    def __init__(self, robot: _Owner, connection: Connection) -> None:
        self.robot = robot
        self.connection = connection
        self.period = 1.0 / connection.frequency if connection.frequency > 0 else math.inf
        self.interval = connection.interval if connection.keepalive is not None else 0.0
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self.restart_clock()

    def restart_clock(self) -> None:
        """Make now the start of the schedule."""
        with self._lock:
            self._start = self.robot._clock()
            self._keepalive_due = self._start + self.interval

    def tick(self) -> None:
        """One iteration: each periodic interface, then the keepalive if it is due. Errors go
        to the error callbacks, and the schedule goes on."""
        robot = self.robot
        for interface in self.connection.periodic:
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
        self._thread = threading.Thread(target=self._loop, name=f"{self.robot.name} {self.connection.name}",
                                        daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop the thread; it finishes the interface it is running first."""
        self._stop.set()
        thread = self._thread
        if thread is not None and thread is not threading.current_thread():
            try:
                thread.join()
            except RuntimeError:  # its start was interrupted before it ran: it will see the stop and end
                pass

    def _loop(self) -> None:
        periodic = bool(self.connection.periodic)
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
