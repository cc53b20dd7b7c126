"""A driver's own names never take the engine's: a robot whose class would be named as an
engine class (`incoming` → Incoming), an input whose plan function would be named as an
engine function (`ranges` → _in_ranges), still gets a driver that runs as `rdisc run` and
the runtime do, byte for byte, over a real pty. The engine's names are its modules' own
(`rdisc.engine.carry.names`), not a list kept by hand."""

from __future__ import annotations

import ast
import importlib
import re
import sys

import pytest
from conftest import run_command_here, run_rdisc, untimed

from rdisc.compile import compile_path
from rdisc.emit.python import import_driver, to_python
from rdisc.emit.python_names import class_name
from rdisc.engine import carry
from rdisc.runtime import load
from tests.devices import pty_device
from tests.engine.test_one_engine import ROOT

DESCRIPTION = """\
robot {name} {{ author "tests" }}
state v: int = 0
connection link: serial {{ baud 9600 }}
primitive ask(x: int in 0..200) on link pack "BB" (0x41, x) unpack "B" {{ v = out[0] }}
interface ask(x: int) {{ ask(x) }}
input ranges: Range -> ask(round(distance))
"""

GENERATED = re.compile(r"_(p|i|in|f|o|request)_|_(P|O|I|IN|C|FRAME|PACK|TABLE)_")
"""The forms of the names a driver makes from a description's (`_p_drive_values`, `_P_DRIVE`)."""


def _answer(data: bytes) -> bytes | None:
    return bytes([data[1] + 1]) if data[:1] == b"A" else None  # one reply byte for each request


@pytest.mark.parametrize("name", ["incoming", "robot", "frame", "port", "port_spec", "state", "calls"])
def test_a_robot_named_as_an_engine_class_gets_a_driver_that_runs(name, tmp_path) -> None:
    source = tmp_path / f"{name}.rdis"
    source.write_text(DESCRIPTION.format(name=name), encoding="utf-8")
    cls = class_name(name)
    assert cls == "".join(part.capitalize() for part in name.split("_")) + "Robot"
    driver = import_driver(source, tmp_path, f"{name}_driver")
    assert isinstance(getattr(driver, cls), type) and issubclass(getattr(driver, cls), driver.Robot)
    written = {}
    for kind, implementation in (("driver", driver), ("runtime", load(source))):
        with pty_device(_answer) as device, implementation.connect(device.port, threads=False) as robot:
            robot.inputs.ranges(distance=5.0)
            robot.interfaces.ask(9)
            assert robot.state["v"] == 10
            with pytest.raises(ValueError, match=r"^ask: parameter x is 250, outside 0\.\.200$"):
                robot.interfaces.ask(250)
            device.wait_for(4, timeout=5.0)
            written[kind] = device.received
    assert written["driver"] == written["runtime"] == bytes.fromhex("41 05 41 09")
    calls = ["--call", "ranges", "distance=5", "--call", "ask", "x=9", "--trace"]
    for command in ([sys.executable, str(tmp_path / f"{name}_driver.py")], None):
        with pty_device(_answer) as device:
            if command is None:
                done = run_rdisc("run", source, "--port", device.port, *calls)
            else:
                done = run_command_here([*command, "--port", device.port, *calls])
            assert done.returncode == 0, done.stderr
            assert untimed(done.stderr) == ["link > 41 05", "link < 06", "link > 41 09", "link < 0a"]
            assert device.received == bytes.fromhex("41 05 41 09")


def _top_level(text: str) -> list[str]:
    return carry.bound(ast.parse(text).body)


@pytest.mark.parametrize("example", sorted(path.name for path in (ROOT / "examples").glob("*.rdis")))
def test_a_driver_binds_each_top_level_name_once(example) -> None:
    """The expression operations are carried whole, as the ROS node's conversions may ask."""
    compilation = compile_path(str(ROOT / "examples" / example))
    assert compilation.model is not None
    names = _top_level(to_python(compilation.model, example))
    assert sorted({name for name in names if names.count(name) > 1}) == []


def test_an_element_named_as_an_engine_function_leaves_it_alone(tmp_path) -> None:
    source = tmp_path / "ranges.rdis"
    source.write_text(DESCRIPTION.format(name="ranges"), encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None
    names = _top_level(to_python(compilation.model, "ranges.rdis"))
    assert sorted({name for name in names if names.count(name) > 1}) == []


def test_no_engine_name_has_the_form_of_a_name_a_driver_makes() -> None:
    assert sorted(name for name in carry.names() if GENERATED.match(name)) == []
    fixed = {"ROBOT", "connect", "main", "_DEVICE", "_SETTINGS", "_MESSAGES"}  # a driver's own, whatever it describes
    assert sorted(fixed & carry.names()) == []


def test_the_names_are_the_engine_modules_own() -> None:
    import rdisc.engine as package

    for section in carry.sections():
        module = vars(importlib.import_module(f"{package.__name__}.{section.module}"))  # the engine imports lazily
        type_variables = {node.targets[0].id for node in ast.parse(section.body).body  # the module's for type checking
                          if isinstance(node, ast.Assign) and ast.unparse(node.value).startswith("TypeVar(")}
        assert set(_top_level(section.body)) - type_variables <= set(module)
    assert {"Incoming", "Robot", "Frame", "Port", "_Worker", "_check_ranges", "annotations"} <= carry.names()


SHADOWS = """\
robot shadow { author "tests" }
const T = { 1: 10, 2: 20 }
connection link: serial { baud 9600 }
primitive ask(lookup: int in 1..2, element: int) on link pack "BBB" (0x41, T[lookup], element)
interface ask(lookup: int, element: int) { ask(lookup, element) }
input run_for: Range -> ask(1, round(distance))
"""


def test_a_parameter_or_an_input_named_as_an_engine_name_hides_nothing(tmp_path) -> None:
    """A parameter `lookup` would hide the engine's `lookup` in the plan function that reads a
    table; an input `run_for`, as a typed method, would hide `Robot.run_for`."""
    source = tmp_path / "shadow.rdis"
    source.write_text(SHADOWS, encoding="utf-8")
    driver = import_driver(source, tmp_path, "shadow_driver")
    assert driver.Shadow.run_for is driver.Robot.run_for
    written = {}
    for kind, implementation in (("driver", driver), ("runtime", load(source))):
        with pty_device(lambda data: None) as device, implementation.connect(device.port, threads=False) as robot:
            robot.interfaces.ask(2, 3)
            robot.primitives.ask(lookup=1, element=4)
            robot.inputs.run_for(distance=5.0)
            if kind == "driver":
                robot.run_for_(6.0)
            device.wait_for(9 if kind == "runtime" else 12, timeout=5.0)
            written[kind] = device.received
    assert written["driver"] == written["runtime"] + bytes.fromhex("41 0a 06")
    assert written["runtime"] == bytes.fromhex("41 14 03  41 0a 04  41 0a 05")
