"""Periodic rates, keepalive intervals, delays and independent connections, over ptys.

The machine running the tests may be small and busy: a thread may wake late, and a
late tick is skipped rather than run in a burst. So these tests assert order and
counts: at most one poll per period (never more, whatever the load), enough polls
to show the schedule runs, so many polls per keepalive, no burst of polls after a
stall. Times are taken from the device's clock (when each command arrived), and
only lower bounds (a delay is never cut short) or loose upper bounds are asserted
on them.
"""

from __future__ import annotations

import itertools
import time

from devices import CreateEmulator
from devices.create import DRIVE, SENSORS
from runtime_support import DATA, Recorder

from rdisc.runtime import RdisTimeout, load

PERIOD = 0.05  # schedule.rdis and two_links.rdis's `fast`: 20 Hz
KEEPALIVE = 0.3  # schedule.rdis: `keepalive ping() every 300 ms`


def polls(dev, packet: int) -> list[float]:
    """Arrival times of the Sensors queries for one packet."""
    with dev._cond:
        return [t for t, c in dev.commands if c[0] == SENSORS and c[1] == packet]


def at_most_one_per_period(times: list[float], period: float) -> bool:
    """No more polls than periods between the first and the last, and one: a tick is never run
    twice, nor in a burst. One more for a first poll read late by the busy device's thread."""
    return len(times) <= (times[-1] - times[0]) / period + 3


def test_periodic_rate_and_keepalive_interval() -> None:
    with CreateEmulator() as dev:
        robot = load(DATA / "schedule.rdis").connect(dev.port)
        try:
            dev.wait_until(lambda: len(polls(dev, 25)) >= 3, 10.0, "three keepalives")
        finally:
            robot.close()
        bumper_polls = polls(dev, 7)
        keepalives = polls(dev, 25)
    assert bumper_polls and bumper_polls[0] < keepalives[0]  # the periodic work starts at once
    assert at_most_one_per_period(bumper_polls, PERIOD), bumper_polls
    assert at_most_one_per_period(keepalives, KEEPALIVE), keepalives
    # Both run on the connection's thread, the keepalive after the tick's poll: about
    # KEEPALIVE / PERIOD = 6 polls between two keepalives, 7 before the first (due one
    # interval after start); fewer if ticks were skipped, never many more.
    before_first = sum(1 for t in bumper_polls if t <= keepalives[0])
    assert 2 <= before_first <= 9, (before_first, bumper_polls, keepalives)
    for a, b in itertools.pairwise(keepalives):
        between = sum(1 for t in bumper_polls if a < t <= b)
        assert 2 <= between <= 8, (between, bumper_polls, keepalives)
    # 20 Hz: at least a third of the ticks ran, over the whole run (about 0.9 s)
    span = bumper_polls[-1] - bumper_polls[0]
    assert len(bumper_polls) >= span / PERIOD / 3, (len(bumper_polls), span)


class StallingCreate(CreateEmulator):
    """A Create whose `stall_at`-th reply comes `stall` seconds late (and every other at once)."""

    def __init__(self, stall_at: int, stall: float) -> None:
        super().__init__()
        self.stall_at, self.stall = stall_at, stall
        self.replies = 0
        self.stalled: float | None = None  # when the command answered late arrived

    def send(self, data: bytes) -> None:  # on the device's thread, answering its last command
        self.replies += 1
        if self.replies == self.stall_at:
            with self._cond:
                self.stalled = self.commands[-1][0]
            time.sleep(self.stall)
        super().send(data)


def test_no_tick_runs_in_a_burst_after_a_stall() -> None:
    with StallingCreate(stall_at=5, stall=0.5) as dev:  # the 5th reply holds the thread for 10 ticks
        robot = load(DATA / "schedule.rdis").connect(dev.port, timeout=2.0)
        try:
            dev.wait_until(lambda: dev.stalled is not None and polls(dev, 7)[-1] > dev.stalled + 0.8, 10.0,
                           "polls 0.3 s after the stall")
        finally:
            robot.close()
        times = polls(dev, 7)
    stalled = dev.stalled
    assert stalled is not None
    after = [t for t in times if t > stalled]
    assert after[0] - stalled >= 0.45  # the thread was held up for the whole stall
    # The ten ticks the stall overran are skipped: in the quarter of a second after it, the
    # polls of that quarter's ticks only (6 at most, and 2 for the device's clock); a burst
    # that caught up would add ten more, a few milliseconds apart.
    window = [t for t in after if t <= after[0] + 0.25]
    assert len(window) <= 0.25 / PERIOD + 3, window
    assert at_most_one_per_period(after, PERIOD), after


def test_delays_and_priorities() -> None:
    with CreateEmulator() as dev:
        robot = load(DATA / "schedule.rdis").connect(dev.port, threads=False)
        try:
            started = time.monotonic()
            robot.call_interface("wiggle")
            took = time.monotonic() - started
            drives = dev.wait_for_commands(4, opcode=DRIVE)
        finally:
            robot.close()
    assert [c for _, c in drives] == [bytes([DRIVE, 0, v, 0, 0]) for v in (1, 2, 3, 4)]
    times = [t for t, _ in drives]
    assert times[1] - times[0] >= 0.19  # `drive(1, 0) delay 200 ms`
    assert times[2] - times[1] >= 0.09  # `drive(2, 0) delay 100 ms`
    assert times[3] - times[2] < 0.15  # `drive(3, 0)` has no delay: well under drive(1, 0)'s
    assert 0.3 <= took < 2.0  # the delays, and not a reply timeout's wait


def test_tick_runs_the_periodic_work_on_the_callers_thread() -> None:
    with CreateEmulator(bumpers=1) as dev:
        outputs = Recorder()
        robot = load(DATA / "schedule.rdis").connect(dev.port, threads=False, on_output=outputs)
        connected = time.monotonic()
        try:
            time.sleep(0.1)
            assert polls(dev, 7) == []  # no thread of its own
            robot.tick()
            robot.tick()
            assert len(polls(dev, 7)) == 2
            assert outputs.snapshot() == [{"name": "detect_bump", "contents": {"distance": 0.0}}] * 2
            if time.monotonic() - connected < 0.29:
                assert polls(dev, 25) == []  # the keepalive is not due yet
            time.sleep(0.35)
            robot.tick()  # the keepalive is due now
            assert len(polls(dev, 25)) >= 1
        finally:
            robot.close()


def test_two_connections_run_independently() -> None:
    with CreateEmulator(mode="silent") as slow, CreateEmulator(bumpers=1) as fast:
        outputs, errors = Recorder(), Recorder()
        robot = load(DATA / "two_links.rdis").connect(
            {"slow": slow.port, "fast": fast.port}, timeout=0.4, on_output=outputs, on_error=errors)
        try:
            slow.wait_until(lambda: len(polls(slow, 7)) >= 2, 10.0, "the second slow poll")
            # `slow` has just started a 0.4 s wait for a reply that never comes: a call on
            # `fast` that waited for it (a lock of the robot's, say) would take most of it
            call_started = time.monotonic()
            robot.call_input("set_velocity", linear=0.1, angular=0.0)
            call_took = time.monotonic() - call_started
            slow.wait_until(lambda: len(polls(slow, 7)) >= 3, 10.0, "the third slow poll")
        finally:
            robot.close()
        fast_polls = polls(fast, 7)
        slow_polls = polls(slow, 7)
    assert call_took < 0.2, call_took  # half of `slow`'s timeout
    assert fast.drives() == [(100, 32767)]
    # one slow poll per 0.4 s timeout, and meanwhile `fast` polls at 20 Hz as if `slow` were not
    # there: 8 polls a timeout, at least 3 of them whatever the load, and never more than 20 Hz
    for a, b in itertools.pairwise(slow_polls):
        assert b - a >= 0.35, slow_polls
        assert sum(1 for t in fast_polls if a < t <= b) >= 3, (a, b, fast_polls)
    assert at_most_one_per_period(fast_polls, PERIOD), fast_polls
    timeouts = [e for e in errors.snapshot() if isinstance(e, RdisTimeout)]
    assert len(timeouts) >= 2
    assert all(str(e).startswith("slow_query: ") for e in timeouts)
    assert all(o["name"] == "fast_bump" for o in outputs.snapshot())
    assert len(outputs) >= 0.6 * len(fast_polls)
