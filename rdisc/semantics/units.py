"""The units a parameter may declare (`unit "mm/s"`), and which of a joint's quantities each carries.

A unit is only checked against its dimension, never converted: the conversions a transmission
writes do that, so the table needs no scale factors, only what each unit measures.
"""

from __future__ import annotations

import enum

from rdisc.semantics import model as m


class Dimension(enum.Enum):
    LENGTH = "a length"
    ANGLE = "an angle"
    TIME = "a time"
    LINEAR_VELOCITY = "a linear velocity"
    ANGULAR_VELOCITY = "an angular velocity"
    FORCE = "a force"
    TORQUE = "a torque"
    CURRENT = "a current"
    VOLTAGE = "a voltage"
    NONE = "dimensionless"


UNITS = {
    "m": Dimension.LENGTH, "cm": Dimension.LENGTH, "mm": Dimension.LENGTH,
    "rad": Dimension.ANGLE, "deg": Dimension.ANGLE,
    "s": Dimension.TIME, "ms": Dimension.TIME,
    "m/s": Dimension.LINEAR_VELOCITY, "mm/s": Dimension.LINEAR_VELOCITY,
    "rad/s": Dimension.ANGULAR_VELOCITY, "deg/s": Dimension.ANGULAR_VELOCITY, "rpm": Dimension.ANGULAR_VELOCITY,
    "N": Dimension.FORCE,
    "N m": Dimension.TORQUE, "mN m": Dimension.TORQUE,
    "A": Dimension.CURRENT, "mA": Dimension.CURRENT,
    "V": Dimension.VOLTAGE, "mV": Dimension.VOLTAGE,
    "%": Dimension.NONE, "count": Dimension.NONE,
}

# What a joint's quantity is, by how the joint moves: turning (revolute, continuous) or sliding.
_TURNING = {
    m.Quantity.POSITION: Dimension.ANGLE,
    m.Quantity.VELOCITY: Dimension.ANGULAR_VELOCITY,
    m.Quantity.EFFORT: Dimension.TORQUE,
}
_SLIDING = {
    m.Quantity.POSITION: Dimension.LENGTH,
    m.Quantity.VELOCITY: Dimension.LINEAR_VELOCITY,
    m.Quantity.EFFORT: Dimension.FORCE,
}
# The dimensions a device value may have and still carry the quantity: a transmission's conversion
# may turn an angle into a length (a wheel's radius, a screw's pitch), and a motor's torque is its
# current times its torque constant.
CARRIERS = {
    m.Quantity.POSITION: (Dimension.ANGLE, Dimension.LENGTH),
    m.Quantity.VELOCITY: (Dimension.ANGULAR_VELOCITY, Dimension.LINEAR_VELOCITY),
    m.Quantity.EFFORT: (Dimension.TORQUE, Dimension.FORCE, Dimension.CURRENT),
}


def dimension_of(quantity: m.Quantity, kind: m.JointKind) -> Dimension:
    """What the joint's quantity is: a revolute joint's position an angle, a prismatic joint's a length."""
    return (_SLIDING if kind is m.JointKind.PRISMATIC else _TURNING)[quantity]


def carries(unit: str, quantity: m.Quantity) -> bool:
    """Whether a device value in `unit` can carry the quantity: a dimensionless unit carries any."""
    dimension = UNITS[unit]
    return dimension is Dimension.NONE or dimension in CARRIERS[quantity]
