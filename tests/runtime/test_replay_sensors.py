"""A replay measures a sensor's age on the recording's clock (`rdisc.runtime.replay.RecordedClock`):
a session recorded with host calls 0, 50 and 150 ms apart read its sensor (cache 100 ms) at the
first and the third; replayed in a few milliseconds it reads it at the same two, serves the kept
value at the second, and `rdisc replay` finds no difference. A call at 200 ms whose output reads
the sensor after a delay of 120 ms reads it again: the delay passes on the replay's clock too."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from rdisc import engine
from rdisc.runtime import load
from rdisc.runtime.replay import read_recording, replay
from tests.support.ports import ScriptedPort

pytest.importorskip("mcap_ros2")  # a recording's library

DESCRIPTION = """robot sensed { author "tests" }
connection link: serial { baud 9600 }
primitive level() on link pack "B" (1) unpack "B"
/// Kept for 100 ms: a reader within that time sends nothing.
sensor height: int from level() cache 100 ms
primitive show(value: int in 0..255) on link pack "BB" (2, value)
interface report() { show(height) delay 20 ms }
interface watch() triggers seen { show(1) delay 120 ms }
output seen: Range { distance = height / 100.0 }
"""

# Seconds after the first: the second within the cache time, the third past it; the last one's output
# reads the sensor 120 ms after it began, 170 ms after the last read.
CALLS = ((0.0, "report"), (0.05, "report"), (0.15, "report"), (0.2, "watch"))


class Levels:
    """The device: each `level` request answered with the next height."""

    def __init__(self) -> None:
        self.heights = iter(range(5, 100))

    def answer(self, request: bytes) -> bytes:
        return bytes([next(self.heights)]) if request == b"\x01" else b""

    def listen(self) -> bytes:
        return b""


@pytest.fixture
def recorded(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[Path, Path]:
    """The description and its session recorded on a clock the test moves (the robot's and the
    recording's timestamps alike), as `rdisc run --call` records host calls."""
    path = tmp_path / "sensed.rdis"
    path.write_text(DESCRIPTION, encoding="utf-8")
    now = [1_000.0]
    monkeypatch.setattr(time, "monotonic", lambda: now[0])
    monkeypatch.setattr(time, "time_ns", lambda: round(now[0] * 1e9))
    robot = engine.Robot(load(path).device)
    robot._sleep = lambda seconds: now.__setitem__(0, now[0] + seconds)  # on the test's clock, not the machine's
    recording = tmp_path / "sensed.mcap"
    recorder = engine.Recorder(robot, str(recording))
    port = ScriptedPort(device=Levels())
    robot.open({"link": port}, threads=False)
    for at, interface in CALLS:
        now[0] = 1_000.0 + at
        recorder.call("interface", interface, {})
        engine.make_call(robot, "interface", interface, {})
    robot.close()
    recorder.finish()
    monkeypatch.undo()
    assert bytes(port.written) == bytes.fromhex("01 0205 0205 01 0206 0201 01")
    return path, recording


def test_a_replay_reads_a_sensor_where_the_recording_did(recorded: tuple[Path, Path]) -> None:
    path, recording = recorded
    session = read_recording(recording)
    replayed = replay(session, load(path).device)
    assert replayed.writes["link"] == [b"\x01", b"\x02\x05", b"\x02\x05", b"\x01", b"\x02\x06", b"\x02\x01", b"\x01"]
    assert replayed.writes == session.writes and not replayed.errors


def test_rdisc_replay_finds_no_difference(rdisc, recorded: tuple[Path, Path]) -> None:
    path, recording = recorded
    result = rdisc("replay", recording, path)
    assert (result.returncode, result.stdout, result.stderr) == (0, "", "")


def test_a_replay_in_real_time_reads_where_the_recording_did_too(recorded: tuple[Path, Path]) -> None:
    """`--realtime` sleeps the delays (200 ms in all here) and measures ages on the recording's clock as well."""
    path, recording = recorded
    session = read_recording(recording)
    replayed = replay(session, load(path).device, realtime=True)
    assert replayed.writes == session.writes and not replayed.errors
