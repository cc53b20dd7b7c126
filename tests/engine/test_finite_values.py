"""A float given from Python (the typed API, `call_*`) that is NaN or infinite is refused by the
engine, naming it, before any byte is written: by the runtime and by a generated driver alike. A
clamp or a comparison in a description would otherwise make such a value a valid command (an
infinite speed clamped to full speed; a NaN turn rate read as "not positive")."""

from __future__ import annotations

import math
from typing import Any

import pytest

from tests.engine.test_one_engine import ScriptedPort, implementation_of

DESCRIPTION = r"""
robot finite { author "tests" }
connection link: serial { baud 9600 }
primitive level(x: float) on link pack "<d" (x)
primitive levels(xs: float[2]) on link pack "<2d" (xs)
primitive near(x: float in -1.0..1.0) on link pack "<f" (x)
primitive both(x: float, y: float) on link pack "<ff" (x, y)
primitive move(speed: int in -100..100) on link pack "<b" (speed)
interface drive(speed: float) { move(round(clamp(speed, -1.0, 1.0) * 100)) }
interface turn(rate: float) { move(50 if rate > 0 else -50) }
input set_velocity: DifferentialSpeed -> drive(linear)
"""

NOT_FINITE = [math.inf, -math.inf, math.nan]


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, DESCRIPTION, tmp_path_factory.mktemp("finite"), "finite")


def _refused(implementation: Any, call: Any) -> tuple[str, str, bytes]:
    """The error a call raises, and what the robot wrote."""
    port = ScriptedPort()
    robot = implementation.connect(port, threads=False)
    try:
        call(robot)
    except Exception as err:  # noqa: BLE001 - the error's type and text are the test's
        return type(err).__name__, str(err), bytes(port.written)
    finally:
        robot.close()
    return "written", "", bytes(port.written)


@pytest.mark.parametrize("value", NOT_FINITE, ids=repr)
@pytest.mark.parametrize(("what", "call"), [
    ("primitive level: parameter x is {}", lambda robot, v: robot.primitives.level(v)),
    ("primitive level: parameter x is {}", lambda robot, v: robot.call_primitive("level", v)),
    ("primitive near: parameter x is {}", lambda robot, v: robot.primitives.near(v)),
    ("primitive both: parameter y is {}", lambda robot, v: robot.primitives.both(0.5, v)),
    ("primitive both: parameter y is {}", lambda robot, v: robot.call_primitive("both", 0.5, v)),
    ("primitive levels: parameter xs[1] is {}", lambda robot, v: robot.primitives.levels([0.5, v])),
    ("primitive levels: parameter xs[1] is {}", lambda robot, v: robot.call_primitive("levels", (0.5, v))),
    ("interface drive: parameter speed is {}", lambda robot, v: robot.interfaces.drive(v)),
    ("interface drive: parameter speed is {}", lambda robot, v: robot.call_interface("drive", v)),
    ("interface turn: parameter rate is {}", lambda robot, v: robot.interfaces.turn(v)),
    ("input set_velocity: field linear is {}", lambda robot, v: robot.inputs.set_velocity(linear=v, angular=0.0)),
    ("input set_velocity: field angular is {}", lambda robot, v: robot.call_input("set_velocity", linear=0.0,
                                                                                   angular=v)),
], ids=lambda x: x if isinstance(x, str) else "")
def test_a_value_that_is_not_finite_is_refused_before_a_byte(implementation: Any, what: str, call: Any,
                                                             value: float) -> None:
    assert _refused(implementation, lambda robot: call(robot, value)) == (
        "RdisValueError", f"{what.format(repr(value))}: a number must be finite", b"")


def test_finite_values_are_written(implementation: Any) -> None:
    """The same calls with finite values (the largest float among them) write their bytes."""
    def calls(robot: Any) -> None:
        robot.primitives.level(1.7976931348623157e308)
        robot.call_primitive("both", 0.5, -0.25)
        robot.primitives.levels([0.5, -1e300])
        robot.interfaces.drive(2.5)
        robot.inputs.set_velocity(linear=-0.5, angular=0.0)
    assert _refused(implementation, calls) == (
        "written", "", bytes.fromhex("ffffffffffffef7f" "0000003f000080be" "000000000000e03f" "9c7500883ce437fe")
        + bytes([100, 206]))
