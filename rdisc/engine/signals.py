"""SIGINT and SIGTERM over a command line's whole run, and its exit statuses: what `rdisc`'s
every verb needs from its first instant, apart from the rest of the command line
(rdisc.engine.command), so that `rdisc check` starts without importing the engine.
"""

from __future__ import annotations

import _thread
import signal
import sys
from collections.abc import Callable

TYPE_CHECKING = False  # typing's, without importing typing: `rdisc check` imports this module
if TYPE_CHECKING:
    from typing import Any, TypeVar

    _Started = TypeVar("_Started")

EXIT_OK, EXIT_ERROR, EXIT_USAGE, EXIT_SIGINT, EXIT_SIGTERM = 0, 1, 2, 130, 143


class _Terminated(BaseException):
    """SIGTERM, turned into an exception so that the terminate hooks run on the way out."""


# The shutdown began: later signals are ignored. Marked by a plain store as the first statement of
# each `except` and `finally` that ends a run: the interpreter runs a signal's handler only at a
# call, a function's start or a loop's turn, so none can come between the `finally` and the mark
# (a call to mark it would let one raise at the callee's start, out of the `finally`, before the
# robot is closed: found by benchmarks/signal_sweep.py).
_shutting_down = [False]
_raised: list[BaseException | None] = [None]  # the exception the last signal raised, until then


def _on_signal(signum: int, frame: object) -> None:
    """The first signal raises KeyboardInterrupt (SIGINT) or _Terminated (SIGTERM), which ends the
    run through its `except` and `finally`. A later one is ignored while that exception is on
    its way (a burst would cut its cleanup short) and once the shutdown began (the terminate
    hooks run in peace). Python drops an exception raised where it cannot propagate (in a
    `__del__`, a weakref callback; silently in some of its C paths): then the next signal
    raises again, and one dropped where Python reports it is raised again by the run's next
    wait (`_dropped`, `raise_dropped`)."""
    if _shutting_down[0]:
        return
    raised = _raised[0]
    if raised is not None and _on_its_way(raised):
        return
    error = KeyboardInterrupt() if signum == signal.SIGINT else _Terminated()
    _raised[0] = error
    raise error


def _on_its_way(error: BaseException) -> bool:
    """Whether `error` is being handled or propagated on this thread: the exception of an
    `except` or `finally` running, or what such an exception was raised in the handling of."""
    seen: BaseException | None = sys.exc_info()[1]
    for _ in range(64):  # a chain of contexts is short; a cycle is possible, so bounded
        if seen is None:
            return False
        if seen is error:
            return True
        seen = seen.__context__
    return False


_dropped_signal: list[int | None] = [None]  # a signal whose exception Python dropped, to raise again


def _dropped(unraisable: Any) -> None:
    """`sys.unraisablehook` while signals are handled: a signal's exception raised where Python
    could only report it (a `__del__`, a weakref callback such as an import lock's) is not
    printed but kept, for the run's next wait to raise (`raise_dropped`): raised again from
    here it would be dropped again. Anything else is reported as Python would."""
    error = unraisable.exc_value
    if error is not None and error is _raised[0]:
        _raised[0] = None
        _dropped_signal[0] = signal.SIGINT if isinstance(error, KeyboardInterrupt) else signal.SIGTERM
        return
    sys.__unraisablehook__(unraisable)


def raise_dropped() -> None:
    """Raise the exception of a signal that Python dropped (`_dropped`), if one was: a command
    line's waits call this before each, so that the signal still ends the run."""
    signum = _dropped_signal[0]
    if signum is not None:
        _dropped_signal[0] = None
        _on_signal(signum, None)


class _Handlers:
    """What `_install_signal_handlers` replaced, for `_restore_handlers` to put back."""

    __slots__ = ("signals", "unraisable")

    def __init__(self, signals: dict[int, Any], unraisable: Any) -> None:
        self.signals = signals
        self.unraisable = unraisable


def _install_signal_handlers() -> _Handlers:
    _shutting_down[0] = False
    _raised[0] = _dropped_signal[0] = None
    previous: dict[int, Any] = {}
    for signum in (signal.SIGINT, signal.SIGTERM):
        try:
            previous[signum] = signal.signal(signum, _on_signal)
        except ValueError:  # not the main thread: leave the handlers alone
            return _Handlers({}, sys.unraisablehook)
    hook = sys.unraisablehook
    sys.unraisablehook = _dropped
    return _Handlers(previous, hook)


def command_line(run: Callable[[], int]) -> int:
    """`run()`, a command line's whole run (`rdisc`'s, a driver's main), with SIGINT and SIGTERM
    handled from its first instant: the first ends it with 130 or 143 and no traceback, even
    before there is a robot (`run_command` handles them from then on, stopping the robot
    first), later ones are ignored until it has returned. Signals the entry point held back
    (blocked, until these handlers were in place) are handled at once. The handlers and signal
    mask found are restored after; after a signal, later ones stay ignored to the exit."""
    previous = _install_signal_handlers()
    mask: set[int | signal.Signals] | None = None
    status = EXIT_SIGINT
    try:
        mask = _unblock_signals()  # a signal held back is handled here, as KeyboardInterrupt or _Terminated
        status = run()
    except KeyboardInterrupt:
        _shutting_down[0] = True  # marked here, where a later signal is still ignored as on its way
        status = EXIT_SIGINT
    except _Terminated:
        _shutting_down[0] = True
        status = EXIT_SIGTERM
    finally:
        _shutting_down[0] = True  # (see `_shutting_down`) a signal from here on is too late: it is ignored
        if not _restore_handlers(previous, status) and mask is not None:
            signal.pthread_sigmask(signal.SIG_SETMASK, mask)
    return status


def _restore_handlers(previous: _Handlers, status: int) -> bool:
    """The handlers found put back, unless a signal ended the run (then later ones are ignored to
    the exit); whether one did."""
    interrupted = status in (EXIT_SIGINT, EXIT_SIGTERM)
    for signum, handler in previous.signals.items():
        signal.signal(signum, signal.SIG_IGN if interrupted else handler)
    if previous.signals:
        sys.unraisablehook = previous.unraisable
    return interrupted


class Flag:
    """A `threading.Event` that a signal's exception can interrupt at any instant without breaking
    it. Event's `wait` and `set` run Condition code written in Python: an exception raised by a
    signal's handler there (after its lock is taken and before its `try`, or between a release
    and the next) leaves the lock held, and the next `set` waits for ever, or releases it twice
    ("release unlocked lock"); both were found by raising a SIGINT at each step of `rdisc run`'s
    start-up delay. Here a wait is one C call of a lock held until the flag is set: interrupted,
    it takes nothing; taken just before the exception, the flag stays set and later waits
    return at once (a thread already waiting then waits out its timeout, no longer)."""

    __slots__ = ("_gate", "_set")

    def __init__(self) -> None:
        self._gate = _thread.allocate_lock()
        self._gate.acquire()  # held until `set`: a wait is a wait to take it
        self._set = False

    def is_set(self) -> bool:
        return self._set

    def set(self) -> None:
        if self._set:
            return
        self._set = True
        try:
            self._gate.release()  # the first waiter takes it and hands it on
        except RuntimeError:  # two threads set it at once: the other released it
            pass

    def wait(self, timeout: float | None = None) -> bool:
        """Whether the flag is set, waiting up to `timeout` seconds for it: None or beyond what
        a lock can wait (infinity), for ever; none at all, as Event's, for 0 or less."""
        if self._set:
            return True
        if timeout is not None and timeout <= 0:
            return False
        seconds = -1.0 if timeout is None or not timeout < _thread.TIMEOUT_MAX else timeout  # -1: for ever
        if self._gate.acquire(True, seconds):
            self._gate.release()
            return True
        return self._set


def without_signals(start: Callable[[], _Started]) -> _Started:
    """`start()` with SIGINT and SIGTERM blocked on this thread, so that every thread it starts
    (Python's, or a library's in C, as Cyclone DDS's) inherits the block and the kernel gives
    them to the main thread. A signal given to another thread only marks Python's handler as
    due: the main thread, asleep in a system call (`--watch` waits in `time.sleep`), is not
    woken, and the robot runs on as if nothing had come (seen once in 400 interrupted runs)."""
    if not hasattr(signal, "pthread_sigmask"):  # Windows: signals go to the main thread anyway
        return start()
    mask = signal.pthread_sigmask(signal.SIG_BLOCK, (signal.SIGINT, signal.SIGTERM))
    try:
        return start()
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)  # one that came meanwhile is handled here


def _unblock_signals() -> set[int | signal.Signals] | None:
    """SIGINT and SIGTERM let through to this thread (a signal held back comes now); the mask it
    had, or None where there are no masks (Windows)."""
    if not hasattr(signal, "pthread_sigmask"):
        return None
    return signal.pthread_sigmask(signal.SIG_UNBLOCK, (signal.SIGINT, signal.SIGTERM))
