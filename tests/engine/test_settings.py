"""Settings given when connecting (`setting BAUD: int in 9600..1000000 = 57600`): the runtime's
`connect(settings=...)`, a driver's keyword per setting and `rdisc run --set` all bind them
through the engine (`bind_settings`), before any port opens; expressions read them as state,
nothing writes them; the baud rate may be one. Exact bytes, errors, diagnostics and JSON."""

from __future__ import annotations

import os
import select
import subprocess
import sys
import termios
from pathlib import Path
from typing import Any

import pytest
from conftest import run_command_here, untimed

from rdisc import engine
from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.runtime import RdisValueError
from rdisc.semantics.budget import budget
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json
from tests.syntax.test_printer import parsed

SERVOS = """\
robot servos { author "tests" }

/// The bus's rate.
setting BAUD: int in 9600..1000000 = 57600
/// The servo's ID on its bus.
setting ID: int in 0..253 = 1
/// Between the wheels, in metres.
setting wheel_base: float in 0.1..1.0 = 0.25
setting label: string = "arm"

state position: int

connection bus: serial { baud BAUD startup hello(ID) }

primitive ping(id: int) on bus pack "BB" (0xFF, id)
primitive read_position() on bus pack "BB" (ID, 0x24) unpack "<H" { position = out[0] + ID }
primitive turn(rate: float) on bus format "T{},{:.3f},{}\\n" (ID, rate * wheel_base, label)

interface hello(id: int) { ping(id) }
interface poll() triggers at { read_position() }
interface spin(rate: float) { turn(rate) when wheel_base > 0.2 }

output at: Range { distance = position * wheel_base }
"""


def _connect(kind: str, implementation: Any, port: ScriptedPort, outputs: list[Any], **settings: Any) -> Any:
    """Connected as each implementation takes settings: a mapping, or a keyword each."""
    if kind == "runtime":
        return implementation.connect(port, threads=False, on_output=outputs.append, settings=settings)
    return implementation.connect(port, threads=False, on_output=outputs.append, **settings)


def _value_error(kind: str, implementation: Any) -> type[Exception]:
    """RdisValueError as each implementation raises it: a driver carries the engine's own."""
    return RdisValueError if kind == "runtime" else implementation.RdisValueError  # type: ignore[no-any-return]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_the_defaults_hold_until_settings_are_given(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, SERVOS, tmp_path, "servos")
    outputs: list[Any] = []
    port = ScriptedPort(b"\x10\x00")
    with _connect(kind, implementation, port, outputs) as robot:
        robot.call_interface("poll")
        robot.call_interface("spin", 2.0)
        assert robot.state["position"] == 17 and robot.state["ID"] == 1
    assert bytes(port.written) == b"\xff\x01" + b"\x01\x24" + b"T1,0.500,arm\n"
    assert outputs == [{"name": "at", "contents": {"distance": 4.25}}]

    outputs.clear()
    port = ScriptedPort(b"\x10\x00")
    with _connect(kind, implementation, port, outputs, ID=7, wheel_base=1, label="left") as robot:
        robot.call_interface("poll")
        robot.call_interface("spin", 2.0)
        assert robot.state["position"] == 23  # 16 + ID
        assert (robot.state["ID"], robot.state["wheel_base"], robot.state["BAUD"]) == (7, 1.0, 57600)
    # the startup hook's argument, a format value, a post-action and an output read them
    assert bytes(port.written) == b"\xff\x07" + b"\x07\x24" + b"T7,2.000,left\n"
    assert outputs == [{"name": "at", "contents": {"distance": 23.0}}]

    port = ScriptedPort()
    with _connect(kind, implementation, port, outputs, wheel_base=0.15) as robot:
        robot.call_interface("spin", 2.0)  # `when wheel_base > 0.2` no longer holds
    assert bytes(port.written) == b"\xff\x01"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
@pytest.mark.parametrize(("settings", "message"), [
    ({"ID": 300}, "servos: setting ID is 300, outside 0..253"),
    ({"ID": True}, "servos: setting ID must be int, not bool True"),
    ({"wheel_base": "wide"}, "servos: setting wheel_base must be float, not str 'wide'"),
    ({"wheel_base": 1.5}, "servos: setting wheel_base is 1.5, outside 0.1..1.0"),
    ({"label": 3}, "servos: setting label must be string, not int 3"),
    ({"BAUD": 1 << 70}, "servos: setting BAUD is a 71-bit integer; integers are limited to 64 bits and a sign"),
])
def test_a_setting_that_does_not_fit_is_refused_before_anything_is_written(
        kind: str, settings: dict[str, Any], message: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, SERVOS, tmp_path, "servos")
    port = ScriptedPort()
    with pytest.raises(_value_error(kind, implementation)) as caught:
        _connect(kind, implementation, port, [], **settings)
    assert str(caught.value) == message
    assert bytes(port.written) == b""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_unknown_setting_names_the_known_ones(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, SERVOS, tmp_path, "servos")
    port = ScriptedPort()
    robot = engine.Robot(implementation.device) if kind == "runtime" else implementation.Servos()
    with pytest.raises(_value_error(kind, implementation)) as caught:
        robot.open(port, threads=False, settings={"id": 2})
    assert str(caught.value) == "servos: no setting named 'id' (its settings: BAUD, ID, wheel_base, label)"
    assert bytes(port.written) == b""


def test_the_driver_s_connect_takes_each_setting_typed_with_its_doc(tmp_path: Path) -> None:
    driver = implementation_of("driver", SERVOS, tmp_path, "servos")
    text = (tmp_path / "servos_driver.py").read_text(encoding="utf-8")
    assert ("    on_io: IoCallback | None = None,\n    sim: Simulator | None = None,\n    BAUD: int = 57600,\n    ID: int = 1,\n"
            "    wheel_base: float = 0.25,\n    label: str = \"arm\",\n) -> Servos:\n") in text
    assert ("    Settings (a value outside its type or range is refused before anything is opened):\n"
            "        BAUD in 9600..1000000: The bus's rate.\n"
            "        ID in 0..253: The servo's ID on its bus.\n"
            "        wheel_base in 0.1..1.0: Between the wheels, in metres.\n"
            "        label\n") in text
    assert 'baud_setting="BAUD"' in text
    assert driver.connect.__kwdefaults__["wheel_base"] == 0.25


def _run(command: list[str], tmp_path: Path) -> tuple[subprocess.CompletedProcess[str], bytes, int]:
    """A command run against a real pty: its result, the bytes the device got, the port's speed."""
    master, slave = os.openpty()
    try:
        result = run_command_here([*command, "--port", os.ttyname(slave)], cwd=tmp_path)
        received = b""  # all the run wrote: a pty hands it over a write at a time
        while select.select([master], [], [], 0.2)[0]:
            try:
                chunk = os.read(master, 4096)
            except OSError:  # no writer left: everything was read
                break
            if not chunk:
                break
            received += chunk
        speed = termios.tcgetattr(slave)[5]  # ospeed
    finally:
        os.close(master)
        os.close(slave)
    return result, received, speed


@pytest.mark.parametrize("kind", ["rdisc run", "driver"])
def test_set_on_the_command_line_over_a_pty(kind: str, tmp_path: Path) -> None:
    source = tmp_path / "servos.rdis"
    source.write_text(SERVOS, encoding="utf-8")
    if kind == "rdisc run":
        command = [sys.executable, "-m", "rdisc", "run", str(source)]
    else:
        implementation_of("driver", SERVOS, tmp_path, "servos")
        command = [sys.executable, str(tmp_path / "servos_driver.py")]
    result, received, speed = _run([*command, "--set", "BAUD=115200", "--set", "ID=9", "--set", "label=12",
                                    "--call", "hello", "id=3", "--call", "spin", "rate=1", "--trace"], tmp_path)
    assert result.returncode == 0, result.stderr
    assert received == b"\xff\x09\xff\x03T9,0.250,12\n"  # `label=12` is the text of a string setting
    assert speed == termios.B115200  # the port opened at the baud rate given
    assert untimed(result.stderr)[:2] == ["bus > ff 09", "bus > ff 03"]

    result, received, _ = _run([*command, "--set", "ID=900", "--call", "hello", "id=3"], tmp_path)
    prog = "rdisc run" if kind == "rdisc run" else "servos_driver.py"
    assert (result.returncode, result.stderr, received) == (2, f"{prog}: servos: setting ID is 900, outside 0..253\n",
                                                            b"")
    result, _, _ = _run([*command, "--set", "BAUD=fast", "--set", "Id=3"], tmp_path)
    assert (result.returncode, result.stderr) == (2, f"{prog}: servos: setting BAUD must be int, not str 'fast'\n")
    result, _, _ = _run([*command, "--set", "Id=3"], tmp_path)
    assert result.stderr == f"{prog}: servos: no setting named 'Id' (its settings: BAUD, ID, wheel_base, label)\n"
    result, _, _ = _run([*command, "--set", "ID=3", "--set", "ID=4"], tmp_path)
    assert result.stderr == f"{prog}: --set ID given twice\n"


def test_the_checker_s_texts(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
setting ID: int in 0..253
setting RATE: float = 57600.0
setting LOW: int = 0
setting WAIT: int = 20
setting position: int = 1
setting OUT: int in 0..9 = 12
state position: int
connection bus: serial { baud RATE }
connection spare: serial { baud LOW }
primitive read(id: int) on bus pack "B" (id) unpack "B" { ID = out[0]  position = out[0] }
primitive other() on spare pack "B" (OUT)
interface poll() { read(ID) delay WAIT ms }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E213", "setting `ID` has no default"),
        ("E101", "`position` is declared as a state variable and as a setting"),
        ("E403", "12 is outside the range of setting `OUT`"),
        ("E207", "cannot assign `ID`: it is a setting, given when connecting"),
        ("E213", "the baud rate is an int, but setting `RATE` is a float"),
        ("E204", "the baud rate must be a positive integer at most 100000000, but the default of setting `LOW` is 0"),
        ("E213", "setting `WAIT` is given only when connecting, so it cannot stand where a constant is needed"),
    ]


def test_json_both_ways_the_printer_and_the_budget(tmp_path: Path) -> None:
    compilation, built = through_json(SERVOS, tmp_path, "servos")
    assert not compilation.diagnostics.items
    assert '"baud": "<BAUD>"' in built
    assert """\
  "settings": [
    {
      "name": "BAUD",
      "type": "int",
      "range": [
        9600,
        1000000
      ],
      "value": "<57600>",
      "doc": "The bus's rate."
    },""" in built
    assert """\
    {
      "name": "label",
      "type": "string",
      "value": "<\\"arm\\">"
    }
  ],""" in built
    module = parsed(SERVOS)
    assert parsed(print_module(module)) == module
    assert "setting wheel_base: float in 0.1..1.0 = 0.25\n" in print_module(module)
    assert compilation.model is not None
    (bus,) = budget(compilation.model, Diagnostics())
    assert bus.lines()[0] == "connection `bus`: 57600 baud (the default of setting `BAUD`), 5760 bytes/s"
