"""A generated driver's typed method writes a plain command itself, through its connection's lane
(the port's lock and write, bound once: `Exchange._lanes`), one call fewer than the engine's
write. It keeps every protection of the engine's write: the port's lock against the other
threads (no frame cut by another's, none written into an exchange in flight), its release
whatever interrupts the write, a signal before its `try` leaving the lock to the interrupted
thread (re-entrant: the terminate hook's stop is still written), the refusal of a write that
gets the port after the stop, and the general way (which the callbacks see) while a callback
watches the writes.

Ports in memory that stop in the middle of a write or before a reply until another thread has
had its chance: each test's bytes are exact, and each fails without the protection it names.
"""

from __future__ import annotations

import signal
import threading
from pathlib import Path
from typing import Any

import pytest

from rdisc.emit.python import import_driver
from tests.support.ports import ScriptedPort

ROOT = Path(__file__).resolve().parents[2]
FAST_CREATE = ROOT / "tests" / "runtime" / "data" / "fast_create.rdis"  # its terminate hook writes the stop
STOP = bytes.fromhex("89 0000 0000")
FORWARD, BACKWARD = bytes.fromhex("89 00c8 7fff"), bytes.fromhex("89 ff38 7fff")  # set_velocity(±0.2, 0.0)
CHARGE = b"\x8e\x19"  # the sensor read of packet 25, two bytes answered
CHANCE = 0.2  # seconds a port stopped midway gives the other thread to write (it cannot: the port is locked)


@pytest.fixture(scope="module")
def driver(tmp_path_factory: pytest.TempPathFactory) -> Any:
    return import_driver(FAST_CREATE, tmp_path_factory.mktemp("typed_lane"), "fast_create_lane_driver")


def _connect(driver: Any, port: ScriptedPort) -> Any:
    """The robot on `port`, no thread of its own, its startup hook's bytes forgotten."""
    robot = driver.connect({"btserial": port}, threads=False)
    del port.written[:]
    return robot


def _drive(robot: Any, linear: float) -> Any:
    """The typed method, to be run on a thread."""
    return lambda: robot.set_velocity(linear=linear, angular=0.0)


class HalvingPort(ScriptedPort):
    """Writes its first frame's first half, then lets another thread try its write (`tried`, set
    by the test) and waits for that write to land (`landed`) or CHANCE to pass, then the rest."""

    def __init__(self) -> None:
        super().__init__()
        self.tried = threading.Event()
        self.landed = threading.Event()
        self.halving = False

    def halve_next(self) -> None:
        self.halving = True
        self.landed.clear()  # (the startup hook's writes landed)

    def write(self, data: bytes, /) -> int:
        if not self.halving:
            self.landed.set()
            return super().write(data)
        self.halving = False
        super().write(data[:2])
        self.tried.wait(timeout=30)
        self.landed.wait(timeout=CHANCE)
        super().write(data[2:])
        return len(data)


def test_a_typed_write_on_another_thread_waits_for_the_frame_being_written(driver: Any) -> None:
    port = HalvingPort()
    with _connect(driver, port) as robot:
        port.halve_next()
        first = threading.Thread(target=_drive(robot, 0.2), daemon=True)
        first.start()
        second = _drive(robot, -0.2)
        other = threading.Thread(target=lambda: (port.tried.set(), second()), daemon=True)
        other.start()
        first.join(timeout=30)
        other.join(timeout=30)
        assert bytes(port.written) == FORWARD + BACKWARD
        del port.written[:]
    assert bytes(port.written) == STOP


class SlowCharge:
    """Answers the charge's read (1234 mAh) only once another thread has tried its write and that
    write landed, or CHANCE passed; what had been written by then is kept (`before`)."""

    def __init__(self, port: ScriptedPort) -> None:
        self.port = port
        self.tried = threading.Event()
        self.landed = threading.Event()
        self.before = b""
        self.asked = False

    def answer(self, request: bytes) -> bytes:
        self.asked = self.asked or request == CHARGE
        if request != CHARGE:
            self.landed.set()
        return b""

    def listen(self) -> bytes:
        if not self.asked:
            return b""
        self.asked = False
        self.tried.wait(timeout=30)
        self.landed.wait(timeout=CHANCE)
        self.before = bytes(self.port.written)
        return (1234).to_bytes(2, "big")


def test_a_typed_write_waits_for_the_exchange_in_flight(driver: Any) -> None:
    """A command written while a reply comes would collide with it on a half-duplex bus: a typed
    write from another thread waits until the exchange has read its reply."""
    port = ScriptedPort(timeout=30)
    device = port.device = SlowCharge(port)
    with _connect(driver, port) as robot:
        device.landed.clear()  # (the startup hook's writes landed)
        exchange = threading.Thread(target=robot.primitives.charge, daemon=True)
        exchange.start()
        second = _drive(robot, 0.2)
        other = threading.Thread(target=lambda: (device.tried.set(), second()), daemon=True)
        other.start()
        exchange.join(timeout=30)
        other.join(timeout=30)
        assert device.before == CHARGE  # nothing written into the exchange
        assert bytes(port.written) == CHARGE + FORWARD
        assert robot.state["charge"] == 1234


class Interrupted(BaseException):
    """What the test's SIGINT handler raises (as Python's raises KeyboardInterrupt)."""


def _interrupt(signum: int, frame: object) -> None:
    raise Interrupted


class SignalledPort(ScriptedPort):
    """A port whose next write is cut short by SIGINT after its first byte (`signalled`)."""

    signalled = False

    def write(self, data: bytes, /) -> int:
        if self.signalled:
            self.signalled = False
            super().write(data[:1])
            signal.raise_signal(signal.SIGINT)  # the handler runs here, raising Interrupted
        return super().write(data)


def test_a_signal_during_a_typed_write_leaves_the_port_free(driver: Any) -> None:
    if threading.current_thread() is not threading.main_thread():
        pytest.skip("signal handlers are set on the main thread only")
    port = SignalledPort()
    previous = signal.signal(signal.SIGINT, _interrupt)
    try:
        with _connect(driver, port) as robot:
            port.signalled = True
            with pytest.raises(Interrupted):
                robot.set_velocity(linear=0.2, angular=0.0)
            other = threading.Thread(target=_drive(robot, -0.2), daemon=True)  # the port is free for it
            other.start()
            other.join(timeout=30)
            assert not other.is_alive()
    finally:
        signal.signal(signal.SIGINT, previous)
    assert bytes(port.written) == FORWARD[:1] + BACKWARD + STOP


def test_a_signal_right_after_a_typed_write_takes_the_lock_still_lets_the_stop_be_written(driver: Any) -> None:
    """A signal can land between `acquire()` and the method's `try`: the interrupted thread keeps
    the lock, and closing (its terminate hook's stop, on the same thread) must not wait for it."""
    port = ScriptedPort()
    robot = _connect(driver, port)
    done = threading.Event()

    def interrupted_then_closed() -> None:
        acquire, release, write = robot._lanes[0]

        def acquire_interrupted() -> bool:
            acquire()
            raise Interrupted

        robot._lanes = ((acquire_interrupted, release, write),)
        try:
            robot.set_velocity(linear=0.2, angular=0.0)
        except Interrupted:
            robot.close()
            done.set()

    worker = threading.Thread(target=interrupted_then_closed, daemon=True)
    worker.start()
    worker.join(timeout=30)  # deadlocked for ever if the lock were not re-entrant
    assert done.is_set()
    assert bytes(port.written) == STOP


class StopWatchingPort(ScriptedPort):
    """Tells when the stop has been written."""

    def __init__(self) -> None:
        super().__init__()
        self.stopped = threading.Event()

    def write(self, data: bytes, /) -> int:
        written = super().write(data)
        if bytes(self.written).endswith(STOP):
            self.stopped.set()
        return written


def test_a_typed_write_that_gets_the_port_after_the_stop_is_refused(driver: Any) -> None:
    """A typed method that found its lane before closing began but takes the port only after the
    terminate hook's stop: refused under the lock (`_closed`), so the stop stays the last command."""
    port = StopWatchingPort()
    robot = _connect(driver, port)
    acquire, release, write = robot._lanes[0]
    entered = threading.Event()

    def acquire_after_the_stop() -> bool:
        entered.set()
        port.stopped.wait(timeout=30)
        return acquire()

    robot._lanes = ((acquire_after_the_stop, release, write),)
    refused: list[BaseException] = []

    def late() -> None:
        try:
            robot.set_velocity(linear=0.2, angular=0.0)
        except driver.RdisConnectionError as err:
            refused.append(err)

    worker = threading.Thread(target=late, daemon=True)
    worker.start()
    entered.wait(timeout=30)  # the lane found: closing begins after
    robot.close()
    worker.join(timeout=30)
    assert [str(err) for err in refused] == ["fast_create: drive not sent: the robot is closed"]
    assert bytes(port.written) == STOP


def test_a_watched_typed_write_goes_the_general_way_the_callbacks_see(driver: Any) -> None:
    port = ScriptedPort()
    seen: list[tuple[str, str, bytes]] = []
    with _connect(driver, port) as robot:
        robot.set_velocity(linear=0.2, angular=0.0)
        robot.on_io(lambda direction, connection, data: seen.append((direction, connection, bytes(data))))
        assert robot._lanes == (None,)
        robot.set_velocity(linear=-0.2, angular=0.0)
    assert seen == [("write", "btserial", BACKWARD), ("write", "btserial", STOP)]
    assert bytes(port.written) == FORWARD + BACKWARD + STOP
