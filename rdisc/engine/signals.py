"""SIGINT and SIGTERM over a command line's whole run, and its exit statuses: what `rdisc`'s
every verb needs from its first instant, apart from the rest of the command line
(rdisc.engine.command), so that `rdisc check` starts without importing the engine.
"""

from __future__ import annotations

import signal
from collections.abc import Callable

TYPE_CHECKING = False  # typing's, without importing typing: `rdisc check` imports this module
if TYPE_CHECKING:
    from typing import Any, TypeVar

    _Started = TypeVar("_Started")

EXIT_OK, EXIT_ERROR, EXIT_USAGE, EXIT_SIGINT, EXIT_SIGTERM = 0, 1, 2, 130, 143


class _Terminated(BaseException):
    """SIGTERM, turned into an exception so that the terminate hooks run on the way out."""


_shutting_down = [False]


def _on_signal(signum: int, frame: object) -> None:
    if _shutting_down[0]:
        return  # the first signal already started the shutdown: the terminate hooks run in peace
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
        status = EXIT_SIGINT
    except _Terminated:
        status = EXIT_SIGTERM
    finally:
        status = _shutting_down_with(status)  # a signal from here on is too late to end it: it is ignored
        if not _restore_handlers(previous, status) and mask is not None:
            signal.pthread_sigmask(signal.SIG_SETMASK, mask)
    return status


def _shutting_down_with(status: int) -> int:
    """Mark the shutdown begun, so that later signals are ignored, and the status to end with: a
    signal that lands before the mark is taken decides it (hence the loop)."""
    while not _shutting_down[0]:
        try:
            _shutting_down[0] = True
        except KeyboardInterrupt:
            status = EXIT_SIGINT
        except _Terminated:
            status = EXIT_SIGTERM
    return status


def _restore_handlers(previous: dict[int, Any], status: int) -> bool:
    """The handlers found put back, unless a signal ended the run (then later ones are ignored to
    the exit); whether one did."""
    interrupted = status in (EXIT_SIGINT, EXIT_SIGTERM)
    for signum, handler in previous.items():
        signal.signal(signum, signal.SIG_IGN if interrupted else handler)
    return interrupted


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
