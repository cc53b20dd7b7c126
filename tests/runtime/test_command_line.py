"""The command line `rdisc run` and every generated driver share (the engine's): --call's
values read as each parameter's type says, a near name suggested, --trace's times, and
--duration counted from the end of the startup hooks. Each run both ways, over loop://
(what is written shows in the trace)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from conftest import run_command_here, untimed

from tests.engine.test_one_engine import implementation_of

TERM = """\
robot term { author "tests" }
connection link: serial { baud 9600 }
primitive say(line: string) on link format "S{}\\r\\n" (line)
primitive blob(data: bytes) on link pack "B*" (0xF0, data)
primitive goals(goal: int[3]) on link pack "<B3H" (0x84, goal)
primitive label(names: string[2]) on link format "N{},{}\\n" (names[0], names[1])
interface set_velocity(linear: float) { goals([round(linear * 1000), 0, 0]) }
"""

SLOW = """\
robot slow { author "tests" }
connection link: serial { baud 9600 threading single at 20 Hz startup warm_up() }
primitive wake() on link pack "B" (0x80)
primitive poll() on link pack "B" (0x8E)
interface warm_up() { wake() delay 500 ms }
interface poll() periodic { poll() }
"""


def _command(kind: str, text: str, folder: Path, name: str) -> list[str]:
    """The command line of `rdisc run` on the description, or of its generated driver."""
    if kind == "rdisc run":
        source = folder / f"{name}.rdis"
        source.write_text(text, encoding="utf-8")
        return [sys.executable, "-m", "rdisc", "run", str(source)]
    implementation_of("driver", text, folder, name)
    return [sys.executable, str(folder / f"{name}_driver.py")]


def _run(command: list[str], *args: str) -> subprocess.CompletedProcess[str]:
    return run_command_here([*command, "--port", "loop://", *args])


@pytest.mark.parametrize("kind", ["rdisc run", "driver"])
def test_call_values_are_read_as_their_parameters_types(kind: str, tmp_path: Path) -> None:
    command = _command(kind, TERM, tmp_path, "term")
    result = _run(command, "--trace", "--call", "say", "line=1234", "--call", "blob", "data=00080000",
                  "--call", "goals", "goal=[1,2,3]", "--call", "label", "names=[12, ab]",
                  "--call", "set_velocity", "linear=0.5")
    assert result.returncode == 0, result.stderr
    assert untimed(result.stderr) == [
        "link > 53 31 32 33 34 0d 0a",  # "S1234\r\n": digits are a string's text
        "link > f0 00 08 00 00",  # bytes as hex
        "link > 84 01 00 02 00 03 00",
        "link > 4e 31 32 2c 61 62 0a",  # "N12,ab\n": a string array's elements as written
        "link > 84 f4 01 00 00 00 00",
    ]
    prog = "rdisc run" if kind == "rdisc run" else "term_driver.py"
    for args, message in [
        (("blob", "data=0g"), ("primitive blob: parameter data must be bytes, as hex such as 3c20 (two digits a byte), "
                              "not '0g'")),
        (("goals", "goal=[1,x,3]"), "primitive goals: parameter goal[1] must be int, not str 'x'"),
        (("set_velocity", "linear=fast"), "interface set_velocity: parameter linear must be float, not str 'fast'"),
    ]:
        result = _run(command, "--call", *args)
        assert (result.returncode, result.stderr) == (2, f"{prog}: {message}\n")


@pytest.mark.parametrize("kind", ["rdisc run", "driver"])
def test_an_unknown_name_is_answered_with_the_near_one(kind: str, tmp_path: Path) -> None:
    command = _command(kind, TERM, tmp_path, "term")
    prog = "rdisc run" if kind == "rdisc run" else "term_driver.py"
    result = _run(command, "--call", "set_velocty", "linear=1")
    assert (result.returncode, result.stderr) == (
        2, f"{prog}: term has no input, interface or primitive `set_velocty`; did you mean `set_velocity`?\n")
    result = _run(command, "--call", "xyzzy")
    assert (result.returncode, result.stderr) == (
        2, (f"{prog}: term has no input, interface or primitive `xyzzy`; "
           "there are: set_velocity, say, blob, goals, label\n"))


@pytest.mark.parametrize("kind", ["rdisc run", "driver"])
def test_duration_counts_from_the_end_of_the_startup_hooks(kind: str, tmp_path: Path) -> None:
    result = _run(_command(kind, SLOW, tmp_path, "slow"), "--trace", "--duration", "0.3")
    assert result.returncode == 0, result.stderr
    trace = untimed(result.stderr)
    assert trace[0] == "link > 80"  # the startup hook, then its 500 ms delay
    assert set(trace[1:]) == {"link > 8e"}
    # 20 Hz for 0.3 s after the startup: six polls. Counted from the start of the run, the
    # startup's delay would have used up the duration, leaving at most one.
    assert len(trace[1:]) >= 3
    started = float(result.stderr.splitlines()[1].split()[0])
    assert started >= 0.5  # the trace's times count from the start of the run, the startup's delay included
