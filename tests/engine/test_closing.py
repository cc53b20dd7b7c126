"""Closing leaves the robot stopped: `close()` from another thread, at any point of an interface
a host call is running (after each of its writes, during each of its delays), stops that call
from writing (it ends with an RdisConnectionError at its next write, its delays cut short),
runs the terminate hook, and then refuses every write: the hook's stop is the last command
written. Through the runtime and a generated driver, with the exact bytes written."""

from __future__ import annotations

import sys
import threading
from pathlib import Path
from typing import Any

import pytest

from tests.engine.test_one_engine import implementation_of
from tests.support.ports import ScriptedPort

DANCE = """
robot dancer { author "rdisc tests" description "several commands and delays, then a stop" }

state level: int = 0

connection c: serial {
    baud 9600
    terminate halt()
}

primitive step(n: int) on c pack "BB" (0x10, n)
primitive ask() on c pack "B" (0x20) unpack "B" { level = out[0] }
primitive stop() on c pack "BB" (0x89, 0)

interface halt() { stop() }

interface dance() {
    step(1) delay 20 s
    step(2)
    ask() delay 20 s
    step(3)
}
"""

WRITES = [b"\x10\x01", b"\x10\x02", b"\x20", b"\x10\x03"]
STOP = b"\x89\x00"
DELAYS = [1, 3]  # the writes a delay follows
BOUND = 10.0  # seconds a thread is waited for: far more than it takes, far less than a delay


class Answering:
    """The device: a level for each `ask`."""

    def answer(self, request: bytes) -> bytes:
        return b"\x07" if request == b"\x20" else b""

    def listen(self) -> bytes:
        return b""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def dancer(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, DANCE, tmp_path_factory.mktemp(request.param), "dancer")


def _error(robot: Any) -> type[Exception]:
    """RdisConnectionError as the robot knows it (a driver carries its own)."""
    return sys.modules[type(robot).__module__].RdisConnectionError  # type: ignore[no-any-return]


def _dance(robot: Any) -> BaseException | None:
    try:
        robot.interfaces.dance()
    except _error(robot) as err:
        return err
    return None


def _closing(robot: Any) -> threading.Thread:
    closer = threading.Thread(target=robot.close, daemon=True)
    closer.start()
    return closer


def _wait_until_closing(robot: Any) -> None:
    for _ in range(10_000):
        if robot.closed:
            return
        threading.Event().wait(0.001)
    raise AssertionError("close() never began")


def _check(port: ScriptedPort, done: int, error: BaseException | None, closer: threading.Thread) -> None:
    closer.join(BOUND)
    assert not closer.is_alive()
    assert port.writes == [*WRITES[:done], STOP]
    if done < len(WRITES):
        assert error is not None and "clos" in str(error), error
    assert port.closed is False  # a port object given is never closed by the robot


@pytest.mark.parametrize("k", range(1, len(WRITES) + 1))
def test_a_close_after_each_write_of_a_host_call_leaves_the_stop_last(dancer: Any, k: int) -> None:
    port = ScriptedPort(device=Answering())
    robot = dancer.connect(port, threads=False)
    seen: list[bytes] = []
    closers: list[threading.Thread] = []

    def on_io(direction: str, connection: str, data: bytes) -> None:
        if direction == "write" and threading.current_thread() is threading.main_thread():
            seen.append(data)
            if len(seen) == k:  # the call goes on only once the close has begun
                closers.append(_closing(robot))
                _wait_until_closing(robot)

    robot.on_io(on_io)
    delay = robot._sleep
    robot._sleep = lambda seconds: delay(seconds) if robot.closed else None  # whole once closing began
    error = _dance(robot)
    _check(port, k, error, closers[0])


@pytest.mark.parametrize("k", DELAYS)
def test_a_close_during_each_delay_of_a_host_call_cuts_it_short(dancer: Any, k: int) -> None:
    port = ScriptedPort(device=Answering())
    robot = dancer.connect(port, threads=False)
    delays = 0
    closers: list[threading.Thread] = []
    sleep = robot._sleep

    def delay(seconds: float) -> None:
        nonlocal delays
        delays += 1
        if delays == DELAYS.index(k) + 1:  # the k-th delay begins once the close has begun
            closers.append(_closing(robot))
            _wait_until_closing(robot)
            sleep(seconds)

    robot._sleep = delay  # the delays before the k-th pass at once
    outcome: list[BaseException | None] = []
    host = threading.Thread(target=lambda: outcome.append(_dance(robot)), daemon=True)
    host.start()
    host.join(BOUND)  # a delay not cut short would keep it 20 s
    assert not host.is_alive()
    _check(port, k, outcome[0], closers[0])


def test_a_closed_robot_writes_nothing_more(dancer: Any) -> None:
    port = ScriptedPort(device=Answering())
    robot = dancer.connect(port, threads=False)
    robot.close()
    for call in (robot.interfaces.dance, robot.primitives.stop, lambda: robot._interface(
            robot.device.interfaces["dance"], [])):
        with pytest.raises(_error(robot), match="closed"):
            call()
    assert port.writes == [STOP]


def test_the_terminate_hooks_delays_are_kept(tmp_path: Path) -> None:
    """The closing thread runs the hooks whole, delays and the commands after them included."""
    text = DANCE.replace("interface halt() { stop() }", "interface halt() {\n    stop() delay 30 ms\n    step(9)\n}")
    port = ScriptedPort()
    robot = implementation_of("runtime", text, tmp_path, "slow_halt").connect(port, threads=False)
    robot.close()
    assert port.writes == [STOP, b"\x10\x09"]
