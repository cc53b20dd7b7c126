"""examples/create.rdis through the runtime, over a pty, against the emulated Create.

One connection serves the whole module: connecting runs the startup hook, which
takes two seconds (the thesis's delays), so it is paid once.
"""

from __future__ import annotations

import struct
import time

import pytest
from devices import CreateEmulator
from devices.create import DRIVE, FULL, SENSORS, START, STOP, TABLE_4_3
from runtime_support import CREATE, Recorder

from rdisc.runtime import load


@pytest.fixture(scope="module")
def create():
    """(device, robot, outputs, errors, connect time) with the robot connected."""
    with CreateEmulator() as dev:
        outputs, errors = Recorder(), Recorder()
        started = time.monotonic()
        robot = load(CREATE).connect(dev.port, on_output=outputs, on_error=errors)
        try:
            yield dev, robot, outputs, errors, started
        finally:
            robot.close()


@pytest.mark.parametrize(("given", "expected"), TABLE_4_3, ids=[str(row[0]) for row in TABLE_4_3])
def test_set_velocity_writes_the_expected_column(create, given, expected) -> None:
    dev, robot, _, errors, _ = create
    before = len(dev.drives())
    linear, angular = given
    robot.call_input("set_velocity", linear=linear, angular=angular)
    commands = dev.wait_for_commands(before + 1, opcode=DRIVE)
    assert commands[-1][1] == struct.pack(">Bhh", *expected)
    assert errors.snapshot() == []


def test_startup_sends_start_then_full_a_second_apart(create) -> None:
    dev, _, _, _, started = create
    commands = dev.wait_for_commands(3)
    (t_start, start), (t_full, full) = commands[0], commands[1]
    assert (start, full) == (bytes([START]), bytes([FULL]))
    assert t_start - started < 1.0  # at once, not after a delay (loose: the machine may be busy)
    assert 0.9 <= t_full - t_start < 2.0  # `start() delay 1000 ms` (loose: less than two delays)
    first_poll = next(t for t, c in commands if c[0] == SENSORS)
    assert first_poll - t_full >= 0.9  # `full() delay 1000 ms`, then the thread starts


def test_bumpers_are_polled_and_reported(create) -> None:
    dev, _, outputs, _, _ = create
    dev.bumpers = 0
    outputs.wait(lambda items: items and items[-1] == {"name": "detect_bump", "contents": {"distance": 1.0}})
    dev.bumpers = 1
    outputs.wait(lambda items: items[-1] == {"name": "detect_bump", "contents": {"distance": 0.0}})
    dev.bumpers = 4  # a wheel drop is not an obstacle
    outputs.wait(lambda items: items[-1]["contents"]["distance"] == 1.0)


def test_state_is_a_read_only_snapshot(create) -> None:
    dev, robot, outputs, _, _ = create
    dev.bumpers = 2
    outputs.wait(lambda items: items[-1]["contents"]["distance"] == 0.0)
    state = robot.state
    assert state["bumperStates"] == 2
    with pytest.raises(TypeError):
        state["bumperStates"] = 0  # type: ignore[index]
    dev.bumpers = 0


def test_closing_runs_the_terminate_hook() -> None:
    with CreateEmulator() as dev:
        robot = load(CREATE).connect(dev.port, threads=False)
        robot.close()
        assert dev.wait_for_commands(3)[-1][1] == STOP
        assert dev.opcodes() == [START, FULL, DRIVE]
        robot.close()  # idempotent
        assert dev.opcodes() == [START, FULL, DRIVE]
