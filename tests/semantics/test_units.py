"""Units on parameters (`unit "mm/s"`): the table's units only (E109), and a transmission's
command only to a parameter whose unit can carry the joint's quantity (E605), each with its
exact diagnostic; the unit kept in the Model, canonical JSON both ways and a driver's docstrings."""

from __future__ import annotations

import inspect
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.emit.python import import_driver
from rdisc.semantics.units import UNITS, Dimension
from tests.engine.test_one_engine import ScriptedPort, through_json
from tests.semantics.test_body import check

ROOT = Path(__file__).resolve().parents[2]
# A wheel, a lift and a slide, and a device whose parameters say their units.
BODY = (
    "link base {}\nlink wheel {}\nlink arm {}\nlink carriage {}\n"
    "joint spin: continuous base -> wheel { axis [0, 1, 0] velocity 10 effort 1 }\n"
    "joint lift: revolute base -> arm { limit -1.5..1.5 velocity 2 effort 1 axis [0, 0, 1] }\n"
    "joint slide: prismatic base -> carriage { limit 0..0.2 velocity 0.1 effort 50 axis [1, 0, 0] }\n"
    'primitive wheel(speed: int in -500..500 unit "mm/s") on c pack ">Bh" (1, speed)\n'
    'primitive servo(goal: int in 0..1023 unit "count", torque: int in 0..1000 unit "mA") on c pack ">BHH" (2, goal, torque)\n'
    'primitive motor(duty: float in -100..100 unit "%", volts: float in -12..12 unit "V") on c pack ">Bff" (3, duty, volts)\n'
    'primitive screw(at: int in 0..200 unit "mm") on c pack ">BH" (4, at)\n'
    'interface wait_for(time: float unit "s") { wheel(0) }\n'
)


def command(joint: str, quantity: str, target: str) -> str:
    """A transmission of `joint` commanding its quantity to `target`, the device's value the quantity itself."""
    return BODY + f"transmission t: {joint} {{ command {quantity} to {target} {{ raw = {quantity}  {quantity} = raw }} }}\n"


ALL_UNITS = ", ".join(UNITS)


@pytest.mark.parametrize(("params", "expected"), [
    ('speed: int unit "mm/sec"', [("E109", '"mm/sec"', "unknown unit `mm/sec`", "did you mean `mm/s`?", [])]),
    ('torque: float unit "Nm"', [("E109", '"Nm"', "unknown unit `Nm`", "did you mean `N m`?", [])]),
    ('distance: float unit "furlong"',
     [("E109", '"furlong"', "unknown unit `furlong`", f"the units are {ALL_UNITS}", [])]),
    ('label: string unit "m", on: bool[2] unit "count"',
     [("E109", '"m"', "parameter `label` is a string: only a number has a unit", None, []),
      ("E109", '"count"', "parameter `on` is an array bool[2]: only a number has a unit", None, [])]),
])
def test_only_the_table_s_units_on_numbers(tmp_path: Path, params: str, expected: list[object]) -> None:
    assert check(tmp_path, f"primitive p({params}) on c pack \"B\" (1)\ninterface i() {{ }}\n") == expected


def test_a_unit_that_cannot_carry_the_quantity_shows_both_sides(tmp_path: Path) -> None:
    text = BODY + ("transmission t: lift { command position to wheel.speed { raw = round(position * 300)"
                   "  position = raw / 300 } }\n")
    assert check(tmp_path, text) == [(
        "E605", "speed",
        "`wheel.speed` is in mm/s, a linear velocity, but the transmission commands joint `lift`'s position, an angle",
        "a position is carried by an angle or a length, or a dimensionless count or %",
        [('"mm/s"', "the parameter's unit")],
    )]


@pytest.mark.parametrize(("joint", "quantity", "target", "message"), [
    ("slide", "effort", "motor.volts",
     "`motor.volts` is in V, a voltage, but the transmission commands joint `slide`'s effort, a force"),
    ("spin", "position", "wheel.speed",
     "`wheel.speed` is in mm/s, a linear velocity, but the transmission commands joint `spin`'s position, an angle"),
    ("slide", "velocity", "screw.at",
     "`screw.at` is in mm, a length, but the transmission commands joint `slide`'s velocity, a linear velocity"),
    ("lift", "velocity", "wait_for.time",
     "`wait_for.time` is in s, a time, but the transmission commands joint `lift`'s velocity, an angular velocity"),
])
def test_what_no_unit_of_that_dimension_carries(tmp_path: Path, joint: str, quantity: str, target: str,
                                                message: str) -> None:
    (found,) = check(tmp_path, command(joint, quantity, target))
    assert found[:3] == ("E605", target.split(".")[1], message)


@pytest.mark.parametrize(("joint", "quantity", "target"), [
    ("spin", "velocity", "wheel.speed"),  # a wheel's rad/s into mm/s: the conversion has the radius
    ("slide", "position", "screw.at"),  # a length carries a length
    ("lift", "position", "servo.goal"),  # a count carries anything
    ("lift", "effort", "servo.torque"),  # a current carries a torque
    ("slide", "effort", "motor.duty"),  # so does a duty cycle, without a dimension
])
def test_what_carries_the_quantity(tmp_path: Path, joint: str, quantity: str, target: str) -> None:
    text = command(joint, quantity, target).replace("velocity 10", "velocity 500").replace("effort 50", "effort 1")
    assert [found for found in check(tmp_path, text) if found[0] == "E605"] == []


def test_every_unit_has_its_dimension() -> None:
    assert {unit: dimension.name for unit, dimension in UNITS.items() if dimension is Dimension.NONE} == {
        "%": "NONE", "count": "NONE"}
    assert len(UNITS) == 21


UNITS_TEXT = """\
robot wheels { author "tests" }
connection link: serial { baud 9600 }
/// Both wheels.
primitive drive(right: int in -500..500 unit "mm/s", left: int in -500..500 unit "mm/s", pwm: bool = False)
    on link pack ">Bhh?" (145, right, left, pwm)
interface move(angle: float[2] unit "rad", id: int) { drive(round(angle[0] * 10), round(angle[1] * 10)) }
"""


def test_units_go_through_json_and_back(tmp_path: Path) -> None:
    compilation, built = through_json(UNITS_TEXT, tmp_path, "wheels")
    assert not compilation.diagnostics.items and compilation.model is not None
    assert [p.unit for p in compilation.model.primitives["drive"].params] == ["mm/s", "mm/s", None]
    assert '"parameterUnits": [\n        "mm/s",\n        "mm/s",\n        null\n      ]' in built
    assert '"parameterUnits": [\n        "rad",\n        null\n      ]' in built


def test_a_unit_in_json_is_checked_too(tmp_path: Path) -> None:
    _, built = through_json(UNITS_TEXT, tmp_path, "wheels")
    (tmp_path / "bad.json").write_text(built.replace('"rad"', '"radian"'), encoding="utf-8")
    compilation = compile_path(str(tmp_path / "bad.json"))
    assert [(d.code, d.message, d.help) for d in compilation.diagnostics.items] == [
        ("E109", "unknown unit `radian`", "did you mean `rad`?")]


def test_a_driver_method_lists_the_units(tmp_path: Path) -> None:
    source = tmp_path / "wheels.rdis"
    source.write_text(UNITS_TEXT, encoding="utf-8")
    driver = import_driver(source, tmp_path, "wheels_units")
    with driver.connect(ScriptedPort(), threads=False) as robot:
        assert inspect.getdoc(robot.primitives.drive) == (
            "Both wheels.\n\n"
            "Ranges (a value outside is refused before anything is written):\n"
            "    right: -500..500\n    left: -500..500\n\n"
            "Units (as the device takes them):\n"
            "    right: mm/s\n    left: mm/s")
        assert inspect.getdoc(robot.interfaces.move) == "The interface `move`.\n\nUnits (as the device takes them):\n    angle: rad"


def test_the_examples_say_their_units(tmp_path: Path) -> None:
    create2 = compile_path(str(ROOT / "examples" / "create2.rdis")).model
    arm = compile_path(str(ROOT / "examples" / "arm.rdis")).model
    assert create2 is not None and arm is not None
    assert [p.unit for p in create2.primitives["drive_direct"].params] == ["mm/s", "mm/s"]
    assert [p.unit for p in arm.primitives["sync_goal"].params] == ["count"]
    assert [p.unit for p in arm.interfaces["move"].params] == ["rad"]
