"""What an actuator does with a command beyond its limits (thesis §7.2.6): `limit shape` (the
default) or `limit refuse`, read from text and JSON alike, printed back, checked (E620, E203), and
lowered onto the primitive its transmission commands as the engine applies it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc import engine
from rdisc.compile import compile_path, compile_text
from rdisc.diagnostics import Diagnostics
from rdisc.emit.canonical import to_json
from rdisc.lower import lower
from rdisc.semantics import model as m
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module

BODY = """robot lift { author "tests" }
connection link: serial { baud 115200 }
primitive servo(goal: int in 0..1023) on link pack ">BH" (2, goal)
primitive slide(goal: int in 0..1023) on link pack ">BH" (3, goal)
link base { mass 1  inertia [0.001, 0.001, 0.001] }
link arm { mass 0.2  centre [0.1, 0, 0]  inertia [0.0001, 0.0007, 0.0007] }
link carriage { mass 0.2  inertia [0.0001, 0.0001, 0.0001] }
joint lift: revolute base -> arm { limit -1.5..1.5 velocity 2 effort 1 axis [0, 0, 1] }
joint rail: prismatic base -> carriage { limit 0..0.2 velocity 0.1 effort 10 axis [1, 0, 0] }
actuator lift_motor: servo { velocity 1.5  acceleration 10  LIMIT }
actuator rail_motor: servo { velocity 0.05 }
transmission lifter: lift actuator lift_motor {
    command position to servo.goal { raw = round(position * 195.3) + 512  position = (raw - 512) / 195.3 }
}
transmission railer: rail actuator rail_motor {
    command position to slide.goal { raw = round(position * 5000)  position = raw / 5000 }
}
"""


def _compiled(limit: str) -> tuple[m.Model | None, list[tuple[str, str]]]:
    compilation = compile_text("lift.rdis", BODY.replace("LIMIT", limit))
    return compilation.model, [(d.code, d.message) for d in compilation.diagnostics.items]


@pytest.mark.parametrize(("limit", "refuse"), [("", False), ("limit shape", False), ("limit refuse", True)])
def test_an_actuator_shapes_unless_it_says_refuse(limit: str, refuse: bool) -> None:
    model, said = _compiled(limit)
    assert said == []
    assert model is not None
    assert model.actuators["lift_motor"].refuse is refuse


@pytest.mark.parametrize(("limit", "expected"), [
    ("limit sprint", [("E620", "an actuator's limit is `shape` or `refuse`, not `sprint`")]),
    ("limit 3", [("E620", "an actuator's limit is `shape` or `refuse`, not a value")]),
    ("limit shape  limit refuse", [("E203", "`limit` is given twice in `lift_motor`")]),
])
def test_a_limit_that_is_not_shape_or_refuse_is_refused(limit: str, expected: list[tuple[str, str]]) -> None:
    assert _compiled(limit)[1] == expected


def test_json_says_limit_refuse_and_reads_back_to_the_same_model(tmp_path: Path) -> None:
    model, _ = _compiled("limit refuse")
    assert model is not None
    text = to_json(model)
    assert json.loads(text)["actuators"] == [
        {"name": "lift_motor", "kind": "servo", "velocity": 1.5, "acceleration": 10.0, "limit": "refuse"},
        {"name": "rail_motor", "kind": "servo", "velocity": 0.05},  # shaping, the default, is not written
    ]
    copy = tmp_path / "lift.json"
    copy.write_text(text, encoding="utf-8")
    again = compile_path(str(copy))
    assert again.model == model, again.diagnostics.items
    assert to_json(again.model) == text


def test_json_with_another_limit_is_refused_as_text_is(tmp_path: Path) -> None:
    model, _ = _compiled("limit refuse")
    assert model is not None
    document = json.loads(to_json(model))
    document["actuators"][0]["limit"] = "sprint"
    copy = tmp_path / "lift.json"
    copy.write_text(json.dumps(document), encoding="utf-8")
    compilation = compile_path(str(copy))
    assert compilation.model is None
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E620", "an actuator's limit is `shape` or `refuse`, not `sprint`")]


def test_the_printer_writes_the_limit_back() -> None:
    module = parse("lift.rdis", BODY.replace("LIMIT", "limit refuse"), Diagnostics())
    printed = print_module(module)
    assert "actuator lift_motor: servo {\n    velocity 1.5\n    acceleration 10\n    limit refuse\n}" in printed
    assert parse("lift.rdis", printed, Diagnostics()) == module


def test_the_lowering_puts_each_limit_on_the_primitive_its_transmission_commands() -> None:
    """In the joint's units and the device's ratio; a primitive held to limits is never written in
    one step (its request is made the general way, where the limits are applied)."""
    model, _ = _compiled("limit refuse")
    assert model is not None
    primitives = lower(model).device.primitives
    assert [c.value for c in primitives["servo"].actuators] == [
        engine.ActuatorLimit("lift_motor", 0, None, "position", 195.3, offset=-512 / 195.3, velocity=1.5,
                             acceleration=10.0, refuse=True)]
    assert [c.value for c in primitives["slide"].actuators] == [
        engine.ActuatorLimit("rail_motor", 0, None, "position", 5000.0, velocity=0.05, unit="m")]
    assert primitives["servo"].request is None and primitives["slide"].request is None
