"""The engine's `Flag` (what a delay waits on to be cut short by closing, a connection's thread
to be stopped, a sensor's reader for the read in flight) against an exception raised at each
step of its `wait` and `set`, as a signal's handler raises it on the main thread.

`threading.Event` failed this: its Condition code, in Python, left its lock held (the next
`set` waited for ever: `rdisc run` hung on closing) or released it twice ("release unlocked
lock"), when a SIGINT came during the start-up delay."""

from __future__ import annotations

import functools
import sys
import threading
from collections.abc import Callable

from rdisc.engine.signals import Flag


def _interrupted_at(step: int, call: Callable[[], object]) -> bool:
    """Run `call` with KeyboardInterrupt raised at its `step`-th bytecode step (none if it has
    fewer); whether it was."""
    count = [0]

    def tracer(frame: object, event: str, arg: object) -> object:
        frame.f_trace_opcodes = True  # type: ignore[attr-defined]
        if event == "opcode":
            count[0] += 1
            if count[0] == step:
                raise KeyboardInterrupt
        return tracer

    sys.settrace(tracer)  # type: ignore[arg-type]
    try:
        call()
    except KeyboardInterrupt:
        return True
    finally:
        sys.settrace(None)
    return False


def _woken(flag: Flag, timeout: float, woke: threading.Event) -> None:
    if flag.wait(timeout):
        woke.set()


def _set_elsewhere(flag: Flag) -> None:
    setter = threading.Thread(target=flag.set, daemon=True)
    setter.start()
    setter.join(timeout=30)
    assert not setter.is_alive(), "set() waited for ever"


def test_a_wait_cut_short_at_any_step_leaves_the_flag_working() -> None:
    steps = 0
    for step in range(1, 500):
        flag = Flag()
        if not _interrupted_at(step, functools.partial(flag.wait, 0.001)):
            break
        steps += 1
        _set_elsewhere(flag)
        assert flag.wait(30) is True and flag.is_set()
    assert steps >= 5  # every step of the wait was tried, until it ended untouched


def test_a_set_cut_short_at_any_step_leaves_the_flag_working() -> None:
    steps = 0
    for step in range(1, 500):
        flag = Flag()
        waiter_woke = threading.Event()
        # (a set cut short after the flag is set and before its lock is let go wakes a thread
        # already waiting only at that wait's timeout: short here)
        waiter = threading.Thread(target=_woken, args=(flag, 0.2, waiter_woke), daemon=True)
        waiter.start()
        if not _interrupted_at(step, flag.set):
            waiter.join(timeout=30)
            assert waiter_woke.is_set()
            break
        steps += 1
        flag.set()  # again, uninterrupted: never "release unlocked lock"
        assert flag.wait(30) is True
        waiter.join(timeout=30)
        assert waiter_woke.is_set()
    assert steps >= 3


def test_a_set_wakes_every_waiter_and_later_waits_return_at_once() -> None:
    flag = Flag()
    woke: list[bool] = []
    waiters = [threading.Thread(target=lambda: woke.append(flag.wait(30))) for _ in range(4)]
    for waiter in waiters:
        waiter.start()
    assert flag.wait(0.01) is False
    flag.set()
    for waiter in waiters:
        waiter.join(timeout=30)
    assert woke == [True] * 4
    assert flag.wait(0) is True and flag.wait() is True


def test_a_wait_of_no_time_only_looks_and_one_of_infinite_time_waits_for_the_set() -> None:
    flag = Flag()
    assert flag.wait(0) is False and flag.wait(-1.0) is False  # as threading.Event's
    setter = threading.Timer(0.05, flag.set)
    setter.start()
    assert flag.wait(float("inf")) is True  # (threading.Event's raises OverflowError)
    setter.join()
