"""`rdisc run` as a subprocess against emulated devices on ptys."""

from __future__ import annotations

import json
import signal
import struct
import subprocess
import sys
import time

import pytest
from conftest import cli_env, untimed
from devices import CreateEmulator, KoalaEmulator
from devices.create import DRIVE, SENSORS, STOP, TABLE_4_3
from runtime_support import CREATE, DATA, KOALA, REPO, typed_thesis_create


def test_table_4_3_through_rdisc_run(rdisc) -> None:
    calls = [arg for (linear, angular), _ in TABLE_4_3
             for arg in ("--call", "set_velocity", f"linear={linear}", f"angular={angular}")]
    with CreateEmulator() as dev:
        result = rdisc("run", CREATE, "--port", dev.port, "--trace", *calls)
        assert result.returncode == 0, result.stderr
        dev.wait_for_commands(len(TABLE_4_3) + 1, opcode=DRIVE)
        assert dev.drives() == [expected[1:] for _, expected in TABLE_4_3] + [(0, 0)]
        assert dev.commands[-1][1] == STOP
    trace = untimed(result.stderr)
    assert trace[:2] == ["btserial > 80", "btserial > 84"]
    assert "btserial > 89 ff 38 01 f4" in trace  # (137, -200, 500)
    assert trace[-1] == "btserial > 89 00 00 00 00"  # the terminate hook
    assert result.stdout == ""


def test_watch_prints_outputs_as_json_lines(rdisc) -> None:
    with CreateEmulator(bumpers=1) as dev:
        result = rdisc("run", DATA / "fast_create.rdis", "--port", dev.port, "--watch", "--duration", "0.5")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert 3 <= len(lines) <= 20  # 20 Hz for half a second
    assert {line for line in lines} == {json.dumps({"name": "detect_bump", "contents": {"distance": 0.0}})}


def test_calls_an_interface_by_parameter_names(rdisc) -> None:
    with CreateEmulator() as dev:
        dev.sensors[25] = 1234
        result = rdisc("run", DATA / "fast_create.rdis", "--port", dev.port, "--watch",
                       "--call", "drive", "velocity=0.1", "radius=-1",
                       "--call", "read_charge", "--duration", "0")
    assert result.returncode == 0, result.stderr
    assert dev.drives()[0] == (100, -1000)  # written before `read_charge` was answered
    assert json.dumps({"name": "battery_charge", "contents": {"distance": 1234.0}}) in result.stdout.splitlines()


def test_koala_one_port_per_connection_by_name(rdisc) -> None:
    with KoalaEmulator() as dev:
        result = rdisc("run", KOALA, "--port", f"rs232={dev.port}",
                       "--call", "set_velocity", "linear=0.2", "angular=0")
        assert result.returncode == 0, result.stderr
        dev.wait_for_lines(2, prefix="D,0,0")
        assert dev.lines[:2] == ["D,0,0", "G,0,0"]
        assert "D,44,44" in dev.lines
        assert dev.lines[-1] == "D,0,0"


def test_a_device_error_exits_1_with_its_message(rdisc) -> None:
    with CreateEmulator(mode="silent") as dev:
        result = rdisc("run", DATA / "fast_create.rdis", "--port", dev.port, "--timeout", "0.2",
                       "--call", "read_charge")
        assert result.returncode == 1
        assert "RdisTimeout: charge: no reply within 0.2 s" in result.stderr
        assert "Traceback" not in result.stderr
        assert dev.wait_for_commands(1, opcode=DRIVE)[-1][1] == STOP  # the terminate hook still ran


def test_a_port_that_cannot_be_opened(rdisc, tmp_path) -> None:
    result = rdisc("run", DATA / "fast_create.rdis", "--port", str(tmp_path / "no-such-tty"))
    assert result.returncode == 1
    assert "RdisConnectionError: btserial: cannot open" in result.stderr
    assert "Traceback" not in result.stderr


def test_a_description_with_errors_shows_its_diagnostics(rdisc, tmp_path) -> None:
    result = rdisc("run", typed_thesis_create(tmp_path), "--port", "loop://")
    assert result.returncode == 1
    assert "error[E402]" in result.stderr
    assert "2 errors emitted" in result.stderr


@pytest.mark.parametrize(("args", "message"), [
    ((), "give the device's port"),
    (("--port", "loop://", "--call", "fly"), "has no input, interface or primitive `fly`"),
    (("--port", "loop://", "--call", "set_velocity", "linear=1"), "takes linear=... angular=..."),
    (("--port", "loop://", "--call", "set_velocity", "linear"), "is not KEY=VALUE"),
    (("--port", "btserail=loop://"), "`btserail` is not a connection"),
    (("--port", "loop://", "--call", "set_velocity", "linear=fast", "angular=0"), "field linear must be float"),
])
def test_usage_errors(rdisc, args, message) -> None:
    result = rdisc("run", DATA / "fast_create.rdis", *args)
    assert result.returncode == 2, result.stderr
    assert message in result.stderr
    assert "Traceback" not in result.stderr


def test_duration_inf_runs_until_a_signal() -> None:
    """`--duration inf` (how the ROS 2 node runs): polling goes on, printing nothing, until SIGINT."""
    with CreateEmulator() as dev:
        process = subprocess.Popen(
            [sys.executable, "-m", "rdisc", "run", str(DATA / "fast_create.rdis"), "--port", dev.port, "--duration",
             "inf"], cwd=REPO, env=cli_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            polls = len(dev.wait_for_commands(1, timeout=15, opcode=SENSORS))
            dev.wait_for_commands(polls + 3, timeout=5, opcode=SENSORS)
            assert process.poll() is None
            process.send_signal(signal.SIGINT)
            stdout, stderr = process.communicate(timeout=10)
            assert (process.returncode, stdout, stderr) == (130, "", "")
            dev.wait_until(lambda: bool(dev.commands) and dev.commands[-1][1] == STOP, 5, "the stop command")
        finally:
            if process.poll() is None:
                process.kill()


@pytest.mark.parametrize(("signum", "status"), [(signal.SIGINT, 130), (signal.SIGTERM, 143)],
                         ids=["SIGINT", "SIGTERM"])
def test_a_signal_still_stops_the_robot(signum, status) -> None:
    with CreateEmulator() as dev:  # fast_create.rdis: the Create's startup without its two seconds of delays
        process = subprocess.Popen(
            [sys.executable, "-m", "rdisc", "run", str(DATA / "fast_create.rdis"), "--port", dev.port, "--watch",
             "--call", "set_velocity", "linear=0.2", "angular=0"],
            cwd=REPO, env=cli_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        )
        try:
            dev.wait_for_commands(1, timeout=15, opcode=DRIVE)  # started, and driving
            polls = len(dev.wait_for_commands(1, timeout=5, opcode=SENSORS))
            dev.wait_for_commands(polls + 2, timeout=5, opcode=SENSORS)  # the periodic thread runs
            assert dev.drives() == [(200, 32767)]
            sent = time.monotonic()
            process.send_signal(signum)
            _, stderr = process.communicate(timeout=10)
            assert process.returncode == status, stderr
            assert "Traceback" not in stderr
            dev.wait_for_commands(2, opcode=DRIVE)
            assert dev.drives() == [(200, 32767), (0, 0)]
            assert dev.commands[-1][1] == STOP
            assert time.monotonic() - sent < 5
        finally:
            if process.poll() is None:
                process.kill()
                process.communicate()


def test_sigterm_during_startup_still_runs_the_terminate_hook() -> None:
    with CreateEmulator() as dev:
        process = subprocess.Popen(
            [sys.executable, "-m", "rdisc", "run", str(CREATE), "--port", dev.port, "--watch"],
            cwd=REPO, env=cli_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        )
        try:
            dev.wait_for_commands(1, timeout=15)  # `start` written; `full` is a second away
            process.send_signal(signal.SIGTERM)
            _, stderr = process.communicate(timeout=10)
            assert process.returncode == 143, stderr
            assert dev.wait_for_commands(1, opcode=DRIVE)[-1][1] == STOP
            assert struct.pack(">Bhh", 137, 0, 0) == STOP
        finally:
            if process.poll() is None:
                process.kill()
                process.communicate()
