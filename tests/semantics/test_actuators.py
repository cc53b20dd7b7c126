"""The actuator element (thesis §7.2.6): what drives a joint between the device's command and the
joint, read from text and JSON alike, printed back, and carried into the models of the body (the
MJCF servo's gain, the URDF transmission's actuator)."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

from rdisc.compile import compile_path, compile_text
from rdisc.diagnostics import Diagnostics
from rdisc.emit.canonical import to_json
from rdisc.emit.mjcf import to_mjcf
from rdisc.emit.urdf import to_urdf
from rdisc.semantics import model as m
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module

BODY = """robot lift { author "tests" }
connection link: serial { baud 115200 }
primitive servo(goal: int in 0..1023) on link pack ">BH" (2, goal)
link base { mass 1  inertia [0.001, 0.001, 0.001] }
link arm { mass 0.2  centre [0.1, 0, 0]  inertia [0.0001, 0.0007, 0.0007] }
link tilt_arm { mass 0.2  centre [0.1, 0, 0]  inertia [0.0001, 0.0007, 0.0007] }
joint lift: revolute base -> arm { limit -1.5..1.5 velocity 2 effort 1 axis [0, 0, 1] }
joint tilt: revolute base -> tilt_arm { limit -1.5..1.5 velocity 2 effort 1 axis [0, 1, 0] at [0, 0, 0.1] }
/// The lifting servo.
actuator lift_motor: servo { velocity 1.5  acceleration 10  effort 0.8  gain 30  damping 0.2 }
actuator tilt_motor: servo { effort 0.5 }
transmission lifter: lift actuator lift_motor {
    command position to servo.goal { raw = round(position * 195.3) + 512  position = (raw - 512) / 195.3 }
}
transmission tilter: tilt actuator tilt_motor {
    command position to servo.goal { raw = round(position * 195.3) + 512  position = (raw - 512) / 195.3 }
}
"""


def _model(text: str = BODY) -> m.Model:
    compilation = compile_text("lift.rdis", text)
    assert compilation.model is not None, compilation.diagnostics.items
    assert compilation.diagnostics.items == []
    return compilation.model


def test_an_actuator_is_in_the_model_and_its_transmission_names_it() -> None:
    model = _model()
    assert model.actuators["lift_motor"] == m.Actuator("lift_motor", m.ActuatorKind.SERVO, velocity=1.5,
                                                       acceleration=10.0, effort=0.8, gain=30.0, damping=0.2,
                                                       doc="The lifting servo.")
    assert model.actuators["tilt_motor"].gain is None
    assert [t.actuator for t in model.transmissions.values()] == ["lift_motor", "tilt_motor"]


def test_json_has_the_actuators_and_reads_back_to_the_same_model(tmp_path: Path) -> None:
    model = _model()
    text = to_json(model)
    document = json.loads(text)
    assert document["actuators"] == [
        {"name": "lift_motor", "kind": "servo", "velocity": 1.5, "acceleration": 10.0, "effort": 0.8, "gain": 30.0,
         "damping": 0.2, "doc": "The lifting servo."},
        {"name": "tilt_motor", "kind": "servo", "effort": 0.5},
    ]
    assert [t["actuator"] for t in document["transmissions"]] == ["lift_motor", "tilt_motor"]
    copy = tmp_path / "lift.json"
    copy.write_text(text, encoding="utf-8")
    again = compile_path(str(copy))
    assert again.model == model, again.diagnostics.items
    assert to_json(again.model) == text


def test_an_actuator_in_json_with_an_unknown_member_is_refused(tmp_path: Path) -> None:
    document = json.loads(to_json(_model()))
    document["actuators"][1]["spin"] = 3
    copy = tmp_path / "lift.json"
    copy.write_text(json.dumps(document), encoding="utf-8")
    compilation = compile_path(str(copy))
    assert compilation.model is None
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E008", "unknown member `spin` in an actuator")]


def test_the_printer_writes_actuators_back() -> None:
    module = parse("lift.rdis", BODY, Diagnostics())
    printed = print_module(module)
    assert "actuator lift_motor: servo {\n    velocity 1.5\n    acceleration 10\n    effort 0.8\n    gain 30\n" \
           "    damping 0.2\n}" in printed
    assert "transmission lifter: lift actuator lift_motor {" in printed
    assert parse("lift.rdis", printed, Diagnostics()) == module


def test_mjcf_takes_a_stated_gain_and_damping_and_derives_the_others() -> None:
    root = ET.fromstring(to_mjcf(_model()))
    lift = root.find("actuator/position[@name='lifter_position']")
    tilt = root.find("actuator/position[@name='tilter_position']")
    assert lift is not None and tilt is not None
    assert lift.attrib == {"name": "lifter_position", "joint": "lift", "kp": "30", "kv": "0.2",
                           "ctrlrange": "-1.5 1.5", "forcerange": "-0.8 0.8"}
    assert tilt.attrib == {"name": "tilter_position", "joint": "tilt", "kp": "10", "dampratio": "1",
                           "ctrlrange": "-1.5 1.5", "forcerange": "-0.5 0.5"}


def test_two_transmissions_on_one_parameter_name_two_urdf_actuators() -> None:
    """Before, both were named after the parameter they command, `servo.goal`; without actuators
    each is named after its transmission."""
    robot = ET.fromstring(to_urdf(_model(), "lift.rdis"))
    assert [a.get("name") for a in robot.iter("actuator")] == ["lift_motor", "tilt_motor"]
    plain = _model(BODY.replace(" actuator lift_motor", "").replace(" actuator tilt_motor", ""))
    robot = ET.fromstring(to_urdf(plain, "lift.rdis"))
    assert [a.get("name") for a in robot.iter("actuator")] == ["lifter_actuator", "tilter_actuator"]
