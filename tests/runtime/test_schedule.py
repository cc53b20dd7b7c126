"""Periodic rates, keepalive intervals, delays and independent connections, over ptys.

The machine running the tests may be small and busy, so rates are checked within
generous bounds, and order and counts rather than exact times.
"""

from __future__ import annotations

import itertools
import time

from devices import CreateEmulator
from devices.create import DRIVE, SENSORS
from runtime_support import DATA, Recorder

from rdisc.runtime import RdisTimeout, load


def polls(dev, packet: int) -> list[float]:
    """Arrival times of the Sensors queries for one packet."""
    with dev._cond:
        return [t for t, c in dev.commands if c[0] == SENSORS and c[1] == packet]


def test_periodic_rate_and_keepalive_interval() -> None:
    with CreateEmulator() as dev:
        robot = load(DATA / "schedule.rdis").connect(dev.port)
        try:
            started = time.monotonic()
            time.sleep(1.25)
            elapsed = time.monotonic() - started
        finally:
            robot.close()
        bumper_polls = polls(dev, 7)
        keepalives = polls(dev, 25)
    rate = len(bumper_polls) / elapsed
    assert 12 <= rate <= 28, rate  # 20 Hz, within 40 %
    gaps = [b - a for a, b in itertools.pairwise(bumper_polls)]
    assert max(gaps) < 0.25  # never stalled for long
    assert 3 <= len(keepalives) <= 5, keepalives  # every 300 ms, the first 300 ms after start
    intervals = [b - a for a, b in itertools.pairwise(keepalives)]
    assert all(0.2 <= i <= 0.5 for i in intervals), intervals
    assert keepalives[0] - bumper_polls[0] >= 0.2


def test_no_tick_runs_in_a_burst_after_a_stall() -> None:
    with CreateEmulator(reply_delay=0.2) as dev:  # each poll takes 4 ticks
        robot = load(DATA / "schedule.rdis").connect(dev.port, timeout=1.0)
        try:
            time.sleep(1.1)
        finally:
            robot.close()
        times = polls(dev, 7) + polls(dev, 25)
    times.sort()
    gaps = [b - a for a, b in itertools.pairwise(times)]
    assert len(times) <= 7  # at most one exchange per 200 ms, not 20 a second
    assert all(g >= 0.15 for g in gaps), gaps


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
    assert times[3] - times[2] < 0.09
    assert 0.3 <= took < 1.0


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
            started = time.monotonic()
            time.sleep(0.3)
            call_started = time.monotonic()
            robot.call_input("set_velocity", linear=0.1, angular=0.0)  # on `fast`, while `slow` waits
            call_took = time.monotonic() - call_started
            time.sleep(1.0)
            elapsed = time.monotonic() - started
        finally:
            robot.close()
        fast_polls = polls(fast, 7)
        slow_polls = polls(slow, 7)
    assert call_took < 0.3  # not held up by `slow`'s 0.4 s timeouts
    assert fast.drives() == [(100, 32767)]
    assert 12 <= len(fast_polls) / elapsed <= 28  # 20 Hz, as if `slow` were not there
    assert 2 <= len(slow_polls) <= 5  # one per 0.4 s timeout
    timeouts = [e for e in errors.snapshot() if isinstance(e, RdisTimeout)]
    assert len(timeouts) >= 2
    assert all(str(e).startswith("slow_query: ") for e in timeouts)
    assert all(o["name"] == "fast_bump" for o in outputs.snapshot())
    assert len(outputs) >= 0.6 * len(fast_polls)
