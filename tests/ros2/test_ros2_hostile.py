"""The generated ROS 2 node against a hostile publisher on its command topic: an independent
participant (participant.py) publishes Twists whose numbers are NaN, infinite or past what the
drive can be asked, then one that is right. Each hostile one is refused on `/NODE/errors` with
the field and why, nothing is written to the device (a pseudo-terminal) for it, the right one
is written as Table 4.3's bytes, and the node's stderr has no traceback."""

from __future__ import annotations

import signal
from pathlib import Path

import pytest

from tests.devices import CreateEmulator
from tests.ros2.test_ros2_node import Participant, _start_node, _stop, dds_env, node_file  # noqa: F401 - fixtures

pytest.importorskip("cyclonedds")

DRIVE = 137
HOSTILE = {"nan 0": "linear is nan", "inf 0": "linear is inf", "-inf 0": "linear is -inf",
           "0 nan": "angular is nan"}


def test_a_twist_of_nan_or_inf_is_refused_naming_its_field_and_writes_nothing(
        node_file: Path, dds_env: dict[str, str]) -> None:  # noqa: F811 - the fixtures imported above
    participant = Participant(dds_env)
    try:
        with CreateEmulator() as device:
            node = _start_node(node_file, dds_env, device)
            try:
                participant.wait(lambda e: "matched" in e or "unmatched" in e, "subscription to set_velocity")
                assert participant.seen[-1] == {"matched": True}
                for line in HOSTILE:
                    participant.send_line(line)
                    participant.wait(lambda e: "error" in e, f"the error of {line}")
                participant.send_line("0.2 0")
                device.wait_for_commands(1, timeout=15, opcode=DRIVE)
                errors = participant.so_far("error")
                drives = [command for _, command in device.commands if command[0] == DRIVE]
            finally:
                _, stderr = _stop(node, signal.SIGINT)
    finally:
        participant.stop()
    assert errors == [f"RdisValueError: input set_velocity: field {said}: a number must be finite"
                      for said in HOSTILE.values()]
    assert drives == [bytes.fromhex("89 00 c8 7f ff")]  # Table 4.3's 0.2 m/s straight ahead, no drive before it
    assert "Traceback" not in stderr, stderr
