"""Parameters with default values (VISCA's zoom speed, a driver's `retries=3`): a call in a
description or from the host may leave them out, in the runtime and a generated driver
alike; the defaults are checked where they are declared and travel through JSON."""

from __future__ import annotations

import inspect
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path
from rdisc.emit.python import import_driver
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

CAMERA = """\
robot camera { author "tests" }
connection link: serial { baud 9600 }
primitive zoom(speed: int in 0..7 = 5, tele: bool = True) on link pack "<BBB?" (0x81, 0x07, speed, tele)
primitive ping(id: int, retries: int = 3) on link pack "BB" (id, retries)
interface zoom_in(speed: int in 0..7 = 2) { zoom(speed)  ping(1) }
interface wide() { zoom(7, False)  zoom() }
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, CAMERA, tmp_path_factory.mktemp("defaults"), "camera")


def test_calls_leave_out_what_has_a_default(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.call_interface("wide")  # in the description: zoom(7, False) then zoom()
        robot.call_interface("zoom_in")  # from the host: speed 2
        robot.call_primitive("ping", 9)
        robot.primitives.zoom(tele=False)  # by name, the other left out
        assert bytes(port.written).hex(" ") == (
            "81 07 07 00 81 07 05 01"
            " 81 07 02 01 01 03"
            " 09 03"
            " 81 07 05 00")
        with pytest.raises(TypeError, match=r"^primitive ping takes 1 to 2 arguments, 0 given$"):
            robot.call_primitive("ping")


def test_a_driver_method_shows_the_defaults(tmp_path: Path) -> None:
    source = tmp_path / "camera.rdis"
    source.write_text(CAMERA, encoding="utf-8")
    driver = import_driver(source, tmp_path, "camera_signatures")
    with driver.connect(ScriptedPort(), threads=False) as robot:
        assert str(inspect.signature(robot.primitives.zoom)) == "(speed: 'int' = 5, tele: 'bool' = True) -> 'None'"


def test_defaults_go_through_json_and_back(tmp_path: Path) -> None:
    compilation, built = through_json(CAMERA, tmp_path, "camera")
    assert not compilation.diagnostics.items
    assert '"parameterDefaults": [\n        "<5>",\n        "<True>"\n      ]' in built


def test_what_the_checker_refuses(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
connection link: serial { baud 9600 }
primitive a(x: int = 1, y: int) on link pack "BB" (x, y)
primitive b(x: int in 0..3 = 9) on link pack "B" (x)
primitive c(x: int = 1.5) on link pack "B" (x)
primitive d(x: float = 2) on link pack "<f" (x)
interface i() { d(1, 2) }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E204", "parameter `y` needs a default: it follows one that has one"),
        ("E403", "9 is outside the range of parameter `x`"),
        ("E402", "the default of parameter `x` takes an int, but this is a float"),
        ("E201", "primitive `d` takes 0 to 1 arguments, but 2 given"),
    ]
