"""The actuators' limits on the primitives their transmissions command (thesis §7.2.6), as the
engine applies them (`engine.ActuatorLimit`): each command a ratio (`rdisc.semantics.linear`) from
the joint's units to the device's value, so the limits stated in rad/s (m/s) hold the device's.
A command that is not a ratio, or one of an interface's parameters, is not limited (W622 says so).
"""

from __future__ import annotations

from rdisc import engine
from rdisc.lowering.constructs import Construct
from rdisc.semantics import model as m
from rdisc.semantics.linear import limited, ratio


def actuator_limits(model: m.Model) -> dict[str, tuple[Construct[engine.ActuatorLimit], ...]]:
    """Each commanded primitive's limits, by its name, in the order of the transmissions."""
    found: dict[str, list[Construct[engine.ActuatorLimit]]] = {}
    for transmission in model.transmissions.values():
        motor = model.actuators.get(transmission.actuator) if transmission.actuator is not None else None
        if motor is None or (motor.velocity is None and motor.acceleration is None):
            continue
        joint = model.joints.get(transmission.joint)
        unit = "m" if joint is not None and joint.kind is m.JointKind.PRISMATIC else "rad"
        for binding in transmission.commands:
            line = ratio(binding)
            if line is None or not limited(binding):
                continue
            params = [p.name for p in model.primitives[binding.target].params]
            param = params.index(binding.parameter) if binding.parameter in params else 0
            options = (("offset", line.offset), ("velocity", motor.velocity), ("acceleration", motor.acceleration),
                       ("refuse", motor.refuse), ("unit", unit))
            given = tuple((key, value) for key, value in options if value not in (None, False, 0.0, "rad"))
            found.setdefault(binding.target, []).append(Construct(
                engine.ActuatorLimit, (motor.name, param, binding.index, binding.quantity.value, line.reduction), given))
    return {name: tuple(limits) for name, limits in found.items()}
