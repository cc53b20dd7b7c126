"""One reading of a call's values given from outside Python (`engine.read_value`, `call_values`):
one table of inputs, each run through every surface that reads values as text or JSON (the
engine's command-line parser in process, a generated driver's `--call`, the console's call path
in process, a replay of a recording holding the call), with the same outcome everywhere: the same
bytes written, or the same refusal with the same text. A number is written as a description writes
one, in ASCII and finite; a parameter left out, or given as an empty text, takes its default."""

from __future__ import annotations

import json
import struct
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from conftest import run_driver_here, untimed

from rdisc import engine
from rdisc.console.server import Console
from rdisc.runtime.replay import Recording, replay
from tests.engine.test_one_engine import ScriptedPort, implementation_of

pytest.importorskip("mcap_ros2")  # a replay records what it runs

DESCRIPTION = r"""
robot values { author "tests" }
connection link: serial { baud 9600 }
primitive move(speed: int in -100..100) on link pack "<b" (speed)
primitive level(x: float) on link pack "<d" (x)
primitive goals(goal: int[3] in 0..255) on link pack "3B" (goal)
primitive zoom(speed: int in 0..7 = 5, tele: bool = True) on link pack "<BB?" (0x81, speed, tele)
primitive say(text: string) on link format "S{}\n" (text)
primitive blob(data: bytes in 0..8) on link pack "B*" (len(data), data)
interface go(speed: int in 0..7 = 5, fast: bool = False) { move(speed * 2 if fast else speed) }
input set_velocity: DifferentialSpeed -> go(round(linear * 7), angular > 0)
"""

MANY = "9" * 5000


@dataclass(frozen=True)
class Refused:
    """A refusal: its error type and text; `form`, the console's words for a form's field that is
    not of its scalar type (its page's, kept as they were); `made`, refused when the call is made
    (a range) rather than when its values are read."""

    error: str
    message: str
    form: str | None = None
    made: bool = False


def _double(value: float) -> str:
    return struct.pack("<d", value).hex()


def _mistyped(what: str, form: str) -> Refused:
    return Refused("TypeError", what, form)


CASES: list[tuple[str, dict[str, str], str | Refused]] = [
    # numbers as a description writes them
    ("move", {"speed": "-3"}, "fd"),
    ("move", {"speed": "+5"}, "05"),
    ("move", {"speed": " 7 "}, "07"),
    ("move", {"speed": "0x10"}, "10"),
    ("move", {"speed": "0b11"}, "03"),
    ("move", {"speed": "0o17"}, "0f"),
    ("move", {"speed": "1_0"}, "0a"),
    ("level", {"x": "1.5"}, _double(1.5)),
    ("level", {"x": "2"}, _double(2.0)),
    ("level", {"x": "0x10"}, _double(16.0)),
    ("level", {"x": "-1e3"}, _double(-1000.0)),
    ("level", {"x": ".5"}, _double(0.5)),
    ("level", {"x": "1e308"}, _double(1e308)),
    # arrays, strings, bytes, bools, defaults
    ("goals", {"goal": "[1, 2, 255]"}, "0102ff"),
    ("goals", {"goal": "4,5,6"}, "040506"),
    ("say", {"text": "1234"}, b"S1234\n".hex()),
    ("blob", {"data": "0a0b"}, "020a0b"),
    ("zoom", {}, "810501"),
    ("zoom", {"speed": ""}, "810501"),
    ("zoom", {"tele": "false"}, "810500"),
    ("zoom", {"speed": "3", "tele": "True"}, "810301"),
    ("go", {}, "05"),
    ("go", {"fast": "true"}, "0a"),
    ("set_velocity", {"linear": "1", "angular": "-0.5"}, "07"),
    # numbers that are not ASCII, not finite or too wide: refused naming the parameter
    ("move", {"speed": "٣٣"}, Refused("RdisValueError", "primitive move: parameter speed is '٣٣': a number is "
                                                         "written in ASCII")),
    ("level", {"x": "１.５"}, Refused("RdisValueError", "primitive level: parameter x is '１.５': a number is "
                                                       "written in ASCII")),
    ("level", {"x": "inf"}, Refused("RdisValueError", "primitive level: parameter x is 'inf': a number must be finite")),
    ("level", {"x": "-Infinity"}, Refused("RdisValueError",
                                          "primitive level: parameter x is '-Infinity': a number must be finite")),
    ("level", {"x": "nan"}, Refused("RdisValueError", "primitive level: parameter x is 'nan': a number must be finite")),
    ("level", {"x": "1e400"}, Refused("RdisValueError",
                                      "primitive level: parameter x is '1e400': a number must be finite")),
    ("level", {"x": MANY}, Refused("RdisValueError", f"primitive level: parameter x is {MANY[:30]!r}... "
                                                    "(5000 characters): a number must be finite")),
    ("move", {"speed": "1e400"}, Refused("RdisValueError",
                                         "primitive move: parameter speed is '1e400': a number must be finite")),
    ("move", {"speed": MANY}, Refused("RdisValueError", f"primitive move: parameter speed is {MANY[:30]!r}... "
                                                       "(5000 characters): integers are limited to 64 bits and a sign")),
    ("move", {"speed": str(2**70)}, Refused("RdisValueError", "primitive move: parameter speed is a 71-bit integer; "
                                                              "integers are limited to 64 bits and a sign")),
    ("goals", {"goal": "[1, inf, 3]"}, Refused("RdisValueError",
                                               "primitive goals: parameter goal[1] is 'inf': a number must be finite")),
    ("set_velocity", {"linear": "inf", "angular": "0"},
     Refused("RdisValueError", "input set_velocity: field linear is 'inf': a number must be finite")),
    # outside the declared range: refused when the call is made
    ("move", {"speed": "200"}, Refused("RdisValueError", "move: parameter speed is 200, outside -100..100", made=True)),
    ("goals", {"goal": "[1, 2, 256]"}, Refused("RdisValueError", "goals: parameter goal[2] is 256, outside 0..255",
                                               made=True)),
    # not of the parameter's type
    ("move", {"speed": "1.5"}, _mistyped("primitive move: parameter speed must be int, not float 1.5",
                                         "move: speed must be an int, not '1.5'")),
    ("move", {"speed": "010"}, _mistyped("primitive move: parameter speed must be int, not str '010'",
                                         "move: speed must be an int, not '010'")),
    ("level", {"x": "fast"}, _mistyped("primitive level: parameter x must be float, not str 'fast'",
                                       "level: x must be a number, not 'fast'")),
    ("zoom", {"tele": "yes"}, _mistyped("primitive zoom: parameter tele must be bool, not str 'yes'",
                                        "zoom: tele must be true or false, not 'yes'")),
    ("goals", {"goal": "[1, x, 3]"}, Refused("TypeError", "primitive goals: parameter goal[1] must be int, not str 'x'")),
    ("goals", {"goal": "[1, 2]"}, Refused("TypeError", "primitive goals: parameter goal must have 3 values, not 2")),
    ("blob", {"data": "0g"}, Refused("TypeError", "primitive blob: parameter data must be bytes, as hex such as 3c20 "
                                                  "(two digits a byte), not '0g'")),
]


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("values")


@pytest.fixture(scope="module")
def description(folder: Path) -> Any:
    return implementation_of("runtime", DESCRIPTION, folder, "values")


@pytest.fixture(scope="module")
def driver(folder: Path) -> Path:
    implementation_of("driver", DESCRIPTION, folder, "values")
    return folder / "values_driver.py"


def _kind(device: engine.Device, name: str) -> str:
    return "input" if name in device.inputs else "interface" if name in device.interfaces else "primitive"


def _command_line(description: Any, name: str, values: dict[str, str]) -> tuple[str, str]:
    """`parse_call` then the call, as `rdisc run` makes it: ("written", hex) or (error type, text)."""
    port = ScriptedPort()
    robot = description.connect(port, threads=False)
    try:
        _, kind, typed = engine.parse_call([name, *(f"{k}={v}" for k, v in values.items())], robot.device)
        engine.make_call(robot, kind, name, typed)
    except (TypeError, ValueError) as err:
        return type(err).__name__, str(err)
    finally:
        robot.close()
    return "written", bytes(port.written).hex()


def _console(description: Any, name: str, values: dict[str, str]) -> tuple[str, str]:
    port = ScriptedPort()
    robot = description.connect(port, threads=False)
    try:
        console = Console(robot, "<p>page</p>")
        console._push = lambda event: None  # no page is open
        kind = _kind(robot.device, name)
        result = console.call(json.dumps({"id": 1, "kind": kind, "name": name, "values": values}))
    finally:
        robot.close()
    if not result["ok"]:
        return result["error"], result["message"]
    return "written", bytes(port.written).hex()


def _replay(description: Any, name: str, values: dict[str, Any]) -> tuple[str, str]:
    """A recording whose one run is the call, its values JSON's strings: the replay's writes or error."""
    kind = _kind(description.device, name)
    replayed = replay(Recording(runs=[{"call": kind, "name": name, "values": values}]), description.device)
    if replayed.errors:
        (error,) = replayed.errors
        kind_of, _, message = error.partition(": ")
        return kind_of, message
    return "written", b"".join(replayed.writes.get("link", [])).hex()


@pytest.mark.parametrize(("name", "values", "outcome"), CASES, ids=[f"{n}-{i}" for i, (n, _, _) in enumerate(CASES)])
def test_each_value_is_read_alike_in_process(description: Any, name: str, values: dict[str, str],
                                             outcome: str | Refused) -> None:
    command_line, console, replayed = (read(description, name, values) for read in (_command_line, _console, _replay))
    if isinstance(outcome, str):
        assert command_line == console == replayed == ("written", outcome)
        return
    assert command_line == (outcome.error, outcome.message)
    assert console == (("ValueError", outcome.form) if outcome.form else (outcome.error, outcome.message))
    kind = _kind(description.device, name)
    wrapped = outcome.error == "RdisValueError"  # a replay's other errors say which recorded call
    assert replayed == ("RdisValueError", outcome.message if wrapped
                        else f"the recorded call of {kind} {name}: {outcome.message}")


def test_a_drivers_command_line_reads_each_value_alike(driver: Path) -> None:
    """The accepted values in one run (each call's bytes a line of the trace); each refused one alone:
    refused when read, a usage error (2) before anything is opened; refused when made, the device's (1)."""
    calls = [["--call", name, *(f"{k}={v}" for k, v in values.items())] for name, values, _ in CASES]
    accepted = [(call, outcome) for call, (_, _, outcome) in zip(calls, CASES) if isinstance(outcome, str)]
    done = _run_driver(driver, "--trace", *(word for call, _ in accepted for word in call))
    assert done.returncode == 0, done.stderr
    assert [line.replace(" ", "") for line in untimed(done.stderr)] == [f"link>{hex_}" for _, hex_ in accepted]
    for call, (_, _, outcome) in zip(calls, CASES):
        if isinstance(outcome, Refused):
            done = _run_driver(driver, *call)
            expected = ((1, f"rdisc run: {outcome.error}: {outcome.message}\n") if outcome.made
                        else (2, f"values_driver.py: {outcome.message}\n"))
            assert (done.returncode, done.stderr) == expected, call


def _run_driver(driver: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return run_driver_here(driver, "--port", "loop://", *args)


@pytest.mark.parametrize(("name", "values", "outcome"), [
    ("move", {"speed": 16}, ("written", "10")),
    ("level", {"x": 2}, ("written", _double(2.0))),
    ("goals", {"goal": [1, 2, 255]}, ("written", "0102ff")),
    ("zoom", {"tele": False}, ("written", "810500")),
    ("blob", {"data": "0a0b"}, ("written", "020a0b")),  # bytes as a recording writes them: hex
    ("level", {"x": float("inf")}, ("RdisValueError", "primitive level: parameter x is inf: a number must be finite")),
    ("goals", {"goal": [1, float("nan"), 3]},
     ("RdisValueError", "primitive goals: parameter goal[1] is nan: a number must be finite")),
    ("move", {"speed": 2**70}, ("RdisValueError", ("primitive move: parameter speed is a 71-bit integer; "
                                                   "integers are limited to 64 bits and a sign"))),
    ("move", {"speed": True}, ("RdisValueError", ("the recorded call of primitive move: primitive move: parameter "
                                                  "speed must be int, not bool True"))),
])
def test_a_recordings_json_values_are_read_by_the_same_rule(description: Any, name: str, values: dict[str, Any],
                                                            outcome: tuple[str, str]) -> None:
    """A recording holds JSON: its numbers, lists and bools are taken as the typed API takes them, and a
    number JSON cannot hold (Python's json writes inf as `Infinity`) or too wide is refused as a text's is."""
    assert _replay(description, name, values) == outcome


# ---- binding by name: the same values bound, each surface's words for what does not bind -----------------


@pytest.mark.parametrize(("name", "values", "command_line", "console", "typed"), [
    ("move", {}, "--call move takes speed=...", "TypeError: move: speed is missing",
     "primitive move: missing argument 'speed'"),
    ("zoom", {"fast": "1"}, "--call zoom takes [speed=5] [tele=True]",
     "TypeError: zoom has no parameter or field named 'fast'", "primitive zoom: unexpected argument 'fast'"),
])
def test_what_does_not_bind_is_refused_everywhere(description: Any, name: str, values: dict[str, str],
                                                  command_line: str, console: str, typed: str) -> None:
    assert _command_line(description, name, values) == ("ValueError", command_line)
    assert ": ".join(_console(description, name, values)) == console
    assert _replay(description, name, values) == ("RdisValueError", f"the recorded call of primitive {name}: {typed}")
    with description.connect(ScriptedPort(), threads=False) as robot, pytest.raises(TypeError) as raised:
        getattr(robot.primitives, name)(**values)
    assert str(raised.value) == typed


SETTINGS = """
robot tuned { author "tests" }
setting BAUD: int in 1200..115200 = 9600
setting gain: float = 1.0
connection link: serial { baud BAUD }
primitive nudge() on link pack "<d" (gain)
"""


def test_a_setting_is_read_as_a_value_is(folder: Path) -> None:
    """`--set` reads its text by the same rule, then `bind_settings` checks the range."""
    device = implementation_of("runtime", SETTINGS, folder, "tuned").device
    assert engine.parse_settings(["BAUD=0x2580", "gain=-1.5e-1"], device) == {"BAUD": 9600, "gain": -0.15}
    assert engine.parse_settings(["gain="], device) == {"gain": 1.0}  # empty: the default
    for pair, message in [
        ("gain=inf", "tuned: setting gain is 'inf': a number must be finite"),
        ("BAUD=٩٦٠٠", "tuned: setting BAUD is '٩٦٠٠': a number is written in ASCII"),
        ("BAUD=fast", "tuned: setting BAUD must be int, not str 'fast'"),
    ]:
        with pytest.raises(engine.RdisValueError) as raised:
            engine.parse_settings([pair], device)
        assert str(raised.value) == message
    with pytest.raises(engine.RdisValueError, match="^tuned: setting BAUD is 300, outside 1200..115200$"):
        engine.bind_settings(device, engine.parse_settings(["BAUD=300"], device))
