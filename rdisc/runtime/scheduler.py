"""The schedule of one connection: its periodic interfaces and its keepalive.

A `Worker` holds what a connection does on its own (the periodic interfaces it
owns, the keepalive and its interval) and when it is due. `tick()` runs one
iteration on the calling thread; `start()` runs iterations on a thread of the
connection's own at its frequency until `stop()`. The thread waits on an Event
between ticks, so it never spins, and wakes at once when stopped.

Timing (the runtime contract): tick k is due at start + k / frequency; a tick
already past when the previous one ends is skipped, not run in a burst. The
keepalive is due one interval after start, then every interval after the time it
was due (or one interval after now, if that is past too).
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any

Job = Callable[[], Any]


class Worker:
    def __init__(
        self,
        name: str,
        frequency_hz: float,
        periodic: Sequence[Job],
        keepalive: Job | None,
        keepalive_interval_ms: float | None,
        report: Callable[[BaseException], None],
        errors: tuple[type[BaseException], ...],
    ) -> None:
        self.name = name
        self.period = 1.0 / frequency_hz if frequency_hz > 0 else math.inf
        self.periodic = tuple(periodic)
        self.keepalive = keepalive
        self.interval = (keepalive_interval_ms or 0) / 1000.0
        self._report = report
        self._errors = errors
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._start = time.monotonic()
        self._keepalive_due = self._start + self.interval

    @property
    def has_work(self) -> bool:
        return bool(self.periodic) or (self.keepalive is not None and self.interval > 0)

    def restart_clock(self) -> None:
        """Make now the start of the schedule."""
        with self._lock:
            self._start = time.monotonic()
            self._keepalive_due = self._start + self.interval

    def tick(self) -> None:
        """One iteration: each periodic interface, then the keepalive if it is due."""
        for job in self.periodic:
            if self._stop.is_set():
                return
            self._run(job)
        if self.keepalive is None or not self.interval:
            return
        with self._lock:
            now = time.monotonic()
            if now < self._keepalive_due:
                return
            due = self._keepalive_due + self.interval
            self._keepalive_due = due if due > now else now + self.interval
        self._run(self.keepalive)

    def _run(self, job: Job) -> None:
        try:
            job()
        except self._errors as err:
            self._report(err)

    # ---- the thread ----------------------------------------------------------------

    def start(self) -> None:
        self.restart_clock()
        self._thread = threading.Thread(target=self._loop, name=f"rdisc {self.name}", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop the thread; it finishes the interface it is running first."""
        self._stop.set()
        thread = self._thread
        if thread is not None and thread is not threading.current_thread():
            thread.join()

    def _loop(self) -> None:
        if not self.has_work:
            self._stop.wait()
            return
        k = 0
        while not self._stop.is_set():
            if self.periodic:
                self.tick()
                now = time.monotonic()
                k = max(k + 1, math.ceil((now - self._start) / self.period))
                wake = self._start + k * self.period
            else:  # only a keepalive: wake when it is due
                self.tick()
                wake = self._keepalive_due
            delay = wake - time.monotonic()
            if delay > 0 and self._stop.wait(delay):
                return
