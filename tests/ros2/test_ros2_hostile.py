"""The generated ROS 2 node against hostile publishers on its command topic: an independent
participant (participant.py) publishes Twists whose numbers are NaN or infinite, then one that
is right, and leaves. Each hostile one is refused on `/NODE/errors` with the field and why,
nothing is written to the device (a pseudo-terminal) for it (a Twist of inf drove the Create at
500 mm/s, one of angular NaN spun it), the right one is written as Table 4.3's bytes; the
publisher leaving (Cyclone hands the reader a sample without data) costs nothing, and the next
publisher is served (the node's reading thread ended with a traceback there); stderr has no
traceback."""

from __future__ import annotations

import signal
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import run_rdisc

from tests.devices import CreateEmulator
from tests.devices.dynamixel import XBus, sync_goals
from tests.ros2.test_ros2_node import (  # noqa: F401 - dds_env and node_file are fixtures
    ARM_JOINTS,
    REPO,
    Participant,
    _start_node,
    _stop,
    dds_env,
    node_file,
)

pytest.importorskip("cyclonedds")

DRIVE = 137
HOSTILE = {"nan 0": "linear is nan", "inf 0": "linear is inf", "-inf 0": "linear is -inf",
           "0 nan": "angular is nan"}
AHEAD = bytes.fromhex("89 00 c8 7f ff")  # Table 4.3: 0.2 m/s straight ahead


def _drives(device: CreateEmulator) -> list[bytes]:
    return [command for _, command in device.commands if command[0] == DRIVE]


def _refused(hostile: Participant, line: str) -> None:
    """Send a Twist until the node says why it refused it: a writer may match the node's reader
    before that reader has matched the writer, and a sample written then reaches no one (seen
    once, on a loaded machine); a refused Twist sent again is refused again, and writes nothing."""
    for _ in range(3):
        hostile.send_line(line)
        try:
            hostile.wait(lambda e: "error" in e, f"the error of {line}", timeout=10)
            return
        except AssertionError:
            continue
    hostile.wait(lambda e: "error" in e, f"the error of {line}")


def test_a_twist_of_nan_or_inf_is_refused_naming_its_field_and_writes_nothing(
        node_file: Path, dds_env: dict[str, str]) -> None:  # noqa: F811 - the fixtures imported above
    with CreateEmulator() as device:
        node = _start_node(node_file, dds_env, device)
        try:
            hostile = Participant(dds_env)
            try:
                hostile.wait(lambda e: "matched" in e or "unmatched" in e, "subscription to set_velocity")
                assert hostile.seen[-1] == {"matched": True}
                for line in HOSTILE:
                    _refused(hostile, line)
                hostile.send_line("0.2 0")
                device.wait_for_commands(1, timeout=15, opcode=DRIVE)
                errors = hostile.so_far("error")  # and, as it comes, its reader of /detect_bump refused
                drives = _drives(device)
            finally:
                hostile.stop()  # its writer leaves: the node reads a sample without data
            later = Participant(dds_env)
            try:
                later.wait(lambda e: "matched" in e or "unmatched" in e, "subscription to set_velocity")
                later.send_line("0.2 0")
                device.wait_for_commands(2, timeout=15, opcode=DRIVE)
                served = _drives(device)
            finally:
                later.stop()
        finally:
            _, stderr = _stop(node, signal.SIGINT)
    said = [e for e in errors if not e.startswith("/detect_bump")]
    assert [e for i, e in enumerate(said) if i == 0 or e != said[i - 1]] == [  # each once, or again if sent again
        f"RdisValueError: input set_velocity: field {field}: a number must be finite" for field in HOSTILE.values()]
    assert drives == [AHEAD]  # no drive before the right Twist's
    assert served == [AHEAD, AHEAD]
    assert "Traceback" not in stderr, stderr


def test_a_publisher_leaving_the_arm_s_joint_command_leaves_the_node_serving(
        dds_env: dict[str, str], tmp_path: Path) -> None:  # noqa: F811 - the fixture imported above
    """Cyclone hands a reader a sample without data when a writer leaves: the arm's joint_command
    read its names and the node's reading thread ended, with a traceback, serving no one after."""
    path = tmp_path / "arm_node.py"
    assert run_rdisc("emit-ros2", REPO / "examples" / "arm.rdis", "-o", path).returncode == 0
    goal = {"name": ARM_JOINTS, "position": [0.0] * 6}
    with XBus() as bus:
        bus.present = {1: 2048, 2: 1024, 3: 3072, 4: 2560, 5: 0, 6: 4095}
        node = subprocess.Popen([sys.executable, str(path), "--ros-args", "-p", f"port:={bus.port}"], env=dds_env,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            for count in (1, 2):  # the second publisher, after the first left
                arm = Participant(dds_env, "arm")
                try:
                    arm.wait(lambda e: "matched" in e or "unmatched" in e, "subscription to joint_command")
                    arm.wait(lambda e: "joint_states" in e, "the servos' positions")  # the node is serving it
                    arm.send(goal)
                    bus.wait_until(lambda n=count: len(sync_goals(bus.received)) == n, 15, f"sync write {count}")
                finally:
                    arm.stop()
        finally:
            _, stderr = _stop(node, signal.SIGINT)
    assert sync_goals(bus.received) == [[2048] * 6] * 2
    assert node.returncode == 130, stderr
    assert "Traceback" not in stderr, stderr
