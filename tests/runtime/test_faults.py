"""Faults over real ptys: each yields its typed error, and the robot goes on."""

from __future__ import annotations

import time

import pytest
from devices import CreateEmulator, KoalaEmulator
from devices.create import DRIVE, SENSORS, STOP
from runtime_support import DATA, KOALA, Recorder

from rdisc.runtime import (
    RdisCallbackError,
    RdisConnectionError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
    load,
)
from tests.support.ports import ScriptedPort

FAST_CREATE = DATA / "fast_create.rdis"


def test_silent_device_times_out_for_the_caller_and_the_schedule() -> None:
    with CreateEmulator(mode="silent") as dev:
        errors = Recorder()
        robot = load(FAST_CREATE).connect(dev.port, timeout=0.2, on_error=errors)
        try:
            started = time.monotonic()
            with pytest.raises(RdisTimeout, match=r"^charge: no reply within 0.2 s$"):
                robot.call_interface("read_charge")
            assert 0.15 <= time.monotonic() - started < 1.0
            errors.wait_count(3)  # periodic polls time out, and the schedule goes on
            dev.mode = "normal"
            dev.bumpers = 1
            robot.call_interface("read_charge")  # the device is back
        finally:
            robot.close()
    reported = errors.snapshot()
    assert all(isinstance(e, RdisTimeout) and str(e).startswith("bumpers: ") for e in reported[:3])
    assert robot.state["charge"] == dev.sensors[25]


def test_short_reply_is_a_protocol_error() -> None:
    with CreateEmulator(mode="short") as dev:
        robot = load(FAST_CREATE).connect(dev.port, timeout=0.2, threads=False)
        try:
            with pytest.raises(RdisProtocolError, match=r"^charge: expected 2 bytes, got 1$"):
                robot.call_interface("read_charge")
            assert robot.state["charge"] == 0  # no post-action ran
        finally:
            robot.close()


def test_garbage_reply_is_a_protocol_error() -> None:
    with KoalaEmulator() as dev:
        errors = Recorder()
        robot = load(KOALA).connect(dev.port, timeout=0.3, on_error=errors)
        try:
            dev.mode = "garbage"
            with pytest.raises(RdisProtocolError, match=r"^set_speed: reply '#\?garbage!' does not match"):
                robot.call_input("set_velocity", linear=0.1, angular=0.0)
            reported = errors.wait_count(2)
            assert all(isinstance(e, RdisProtocolError) for e in reported)
            dev.mode = "normal"
            robot.call_input("set_velocity", linear=0.1, angular=0.0)
        finally:
            robot.close()


def test_unterminated_reply_is_a_protocol_error() -> None:
    with KoalaEmulator() as dev:
        robot = load(KOALA).connect(dev.port, timeout=0.2, threads=False)
        try:
            dev.mode = "unterminated"
            with pytest.raises(RdisProtocolError, match=r"^set_speed: reply line not terminated: 'd'$"):
                robot.call_input("set_velocity", linear=0.1, angular=0.0)
            dev.mode = "normal"
        finally:
            robot.close()


def test_a_vanished_device_is_a_connection_error() -> None:
    with CreateEmulator() as dev:
        errors = Recorder()
        robot = load(FAST_CREATE).connect(dev.port, timeout=0.3, on_error=errors)
        try:
            dev.wait_for_commands(2, opcode=SENSORS)
            dev.close_master()
            with pytest.raises(RdisConnectionError, match=r"^btserial: "):
                robot.call_input("set_velocity", linear=0.1, angular=0.0)
            errors.wait(lambda items: any(isinstance(e, RdisConnectionError) for e in items))
        finally:
            robot.close()  # the terminate hook fails too: reported, not raised
    assert isinstance(errors.snapshot()[-1], RdisConnectionError)


def test_a_raising_callback_is_reported_and_delivery_goes_on() -> None:
    with CreateEmulator(bumpers=1) as dev:
        errors, delivered = Recorder(), Recorder()

        def broken(message: dict) -> None:
            raise ValueError("boom")

        robot = load(FAST_CREATE).connect(dev.port, on_error=errors)
        try:
            robot.on_output(broken)
            robot.on_output(delivered)
            errors.wait_count(3)
            delivered.wait_count(3)
        finally:
            robot.close()
    error = errors.snapshot()[0]
    assert isinstance(error, RdisCallbackError)
    assert isinstance(error.__cause__, ValueError)
    assert str(error) == "detect_bump: output callback raised ValueError: boom"
    assert delivered.snapshot()[0] == {"name": "detect_bump", "contents": {"distance": 0.0}}


def test_an_error_callback_that_raises_is_ignored() -> None:
    with CreateEmulator(mode="silent") as dev:
        seen = Recorder()

        def broken(error: BaseException) -> None:
            seen(error)
            raise RuntimeError("not this one too")

        robot = load(FAST_CREATE).connect(dev.port, timeout=0.1, on_error=broken)
        try:
            seen.wait_count(3)
        finally:
            robot.close()


def test_a_value_out_of_range_for_its_code() -> None:
    with CreateEmulator() as dev:
        robot = load(FAST_CREATE).connect(dev.port, threads=False)
        try:
            with pytest.raises(RdisValueError, match=r"^drive: "):
                robot.call_interface("drive", 100.0, 0)  # 100000 mm/s does not fit `h`
            assert dev.drives() == []
        finally:
            robot.close()


@pytest.mark.parametrize(("fields", "message"), [
    ({"linear": 0.1}, "takes the fields linear, angular"),
    ({"linear": 0.1, "angular": 0, "z": 1}, "takes the fields linear, angular"),
    ({"linear": "fast", "angular": 0}, "field linear must be float, not str"),
    ({"linear": True, "angular": 0}, "field linear must be float, not bool"),
])
def test_wrong_fields_are_a_type_error_and_nothing_is_written(fields, message) -> None:
    with CreateEmulator() as dev:
        robot = load(FAST_CREATE).connect(dev.port, threads=False)
        try:
            with pytest.raises(TypeError, match=message):
                robot.call_input("set_velocity", **fields)
            with pytest.raises(KeyError, match="no input named 'fly'"):
                robot.call_input("fly")
            with pytest.raises(TypeError, match="takes 2 arguments, 1 given"):
                robot.call_interface("drive", 0.1)
            assert dev.drives() == []
        finally:
            robot.close()
        dev.wait_for_commands(1, opcode=DRIVE)
        assert dev.drives() == [(0, 0)]


def test_ints_are_accepted_for_floats() -> None:
    with CreateEmulator() as dev:
        robot = load(FAST_CREATE).connect(dev.port, threads=False)
        try:
            robot.call_input("set_velocity", linear=0, angular=0)
            robot.call_interface("drive", 0, 1)
        finally:
            robot.close()
        dev.wait_for_commands(3, opcode=DRIVE)
        assert dev.drives() == [(0, 0), (0, 1000), (0, 0)]


def test_calls_after_close_are_connection_errors() -> None:
    with CreateEmulator() as dev:
        robot = load(FAST_CREATE).connect(dev.port)
        robot.close()
        assert dev.wait_for_commands(1, opcode=DRIVE)[-1][1] == STOP
        with pytest.raises(RdisConnectionError, match="closed"):
            robot.call_input("set_velocity", linear=0.1, angular=0.0)


def test_a_port_object_is_used_as_it_is_and_left_open() -> None:
    port = ScriptedPort()
    with load(FAST_CREATE).connect(port, threads=False) as robot:
        robot.call_input("set_velocity", linear=0.2, angular=0.0)
    assert port.writes == [b"\x80", b"\x84", b"\x89\x00\xc8\x7f\xff", STOP]
    assert not port.closed


def test_unknown_or_missing_connections_in_a_port_dict() -> None:
    description = load(FAST_CREATE)
    with pytest.raises(ValueError, match="no connection named 'bt'"):
        description.connect({"bt": "loop://"})
    with pytest.raises(ValueError, match="no port given for connection 'btserial'"):
        description.connect({})
    with pytest.raises(RdisConnectionError, match="^btserial: cannot open /nonexistent/tty"):
        description.connect("/nonexistent/tty")


def test_an_output_callback_that_calls_an_input_does_not_deadlock_with_io_callbacks() -> None:
    """An output callback calls an input while I/O callbacks are registered and another
    thread calls inputs: the port's lock and the callbacks' lock must not cross."""
    import threading

    with CreateEmulator(bumpers=1) as dev:
        io, errors, reflexes = Recorder(), Recorder(), Recorder()

        def reflex(output: object) -> None:
            robot.call_input("set_velocity", linear=0.0, angular=0.0)
            reflexes(output)

        def keep_driving() -> None:  # until several reflexes crossed these calls (or 10 s)
            deadline = time.monotonic() + 10
            while len(reflexes) < 5 and time.monotonic() < deadline:
                robot.call_input("set_velocity", linear=0.1, angular=0.0)

        robot = load(FAST_CREATE).connect(dev.port, on_io=io, on_error=errors)
        robot.on_output(reflex)
        try:
            caller = threading.Thread(target=keep_driving, daemon=True)
            caller.start()
            caller.join(timeout=20)
            assert not caller.is_alive(), "deadlocked"
            assert len(reflexes) >= 5
            assert errors.snapshot() == []
        finally:
            robot.close()
    assert (0, 0) in dev.drives() and (100, 32767) in dev.drives()
