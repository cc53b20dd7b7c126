"""A transmission's conversion as a gear ratio, when it is one: what URDF's `SimpleTransmission`
says with `mechanicalReduction` and a joint `offset`.

ros_control's SimpleTransmission turns a joint's value into the actuator's as
`actuator = (joint - offset) * reduction` for a position, `joint * reduction` for a velocity and
`joint / reduction` for an effort. A conversion `raw = round(position * 651.9) + 2048` is that
with reduction 651.9 and offset -2048 / 651.9: rounding (`round`, `int`, `float`) is the device's
step, not part of the ratio. Anything else (a wrap with `%`, a condition, another name) is not a
ratio, and None says so.
"""

from __future__ import annotations

from dataclasses import dataclass

from rdisc.semantics import model as m

_STEPS = frozenset({"round", "int", "float"})  # a value made whole or made a float: the ratio is the same


@dataclass(frozen=True, slots=True)
class Ratio:
    """`actuator = (joint - offset) * reduction` (a position), `joint * reduction` (a velocity),
    `joint / reduction` (an effort)."""

    reduction: float
    offset: float = 0.0


def ratio(binding: m.Binding) -> Ratio | None:
    """The binding's `raw = ...` as a SimpleTransmission's ratio, or None when it is not one."""
    line = _affine(binding.to_device, binding.quantity.value)
    if line is None:
        return None
    scale, shift = line
    if scale == 0:
        return None
    match binding.quantity:
        case m.Quantity.POSITION:
            return Ratio(scale, -shift / scale if shift else 0.0)
        case m.Quantity.VELOCITY:
            return Ratio(scale) if shift == 0 else None
        case m.Quantity.EFFORT:
            return Ratio(1 / scale) if shift == 0 else None


def limited(binding: m.Binding) -> bool:
    """Whether the engine can hold this command to its actuator's limits (`rdisc.engine.actuation`):
    a position or velocity given a primitive's parameter through a ratio, so that the limits in the
    joint's units are the device value's."""
    quantity = binding.quantity in (m.Quantity.POSITION, m.Quantity.VELOCITY)
    return quantity and not binding.interface and ratio(binding) is not None


def _affine(expr: m.Expr, name: str) -> tuple[float, float] | None:
    """`expr` as `scale * name + shift`, each a number; None when it is not of that form."""
    match expr:
        case m.Const(value=value) if isinstance(value, (int, float)) and not isinstance(value, bool):
            return 0.0, value
        case m.Var(name=var) if var == name:
            return 1.0, 0.0
        case m.UnaryOp(op="-", operand=operand):
            line = _affine(operand, name)
            return None if line is None else (-line[0], -line[1])
        case m.UnaryOp(op="+", operand=operand):
            return _affine(operand, name)
        case m.FuncCall(func=func, args=(argument,)) if func in _STEPS:
            return _affine(argument, name)
        case m.BinaryOp(op=op, left=left, right=right) if op in ("+", "-", "*", "/"):
            a, b = _affine(left, name), _affine(right, name)
            if a is None or b is None:
                return None
            return _combined(op, a, b)
    return None


def _combined(op: str, a: tuple[float, float], b: tuple[float, float]) -> tuple[float, float] | None:
    """Two affine forms joined by `op`, when the result is affine (a product with one side constant,
    a quotient by a constant that is not 0)."""
    if op == "+":
        return a[0] + b[0], a[1] + b[1]
    if op == "-":
        return a[0] - b[0], a[1] - b[1]
    if op == "*":
        if a[0] == 0:
            return a[1] * b[0], a[1] * b[1]
        if b[0] == 0:
            return a[0] * b[1], a[1] * b[1]
        return None
    if b[0] != 0 or b[1] == 0:  # "/": only by a constant
        return None
    return a[0] / b[1], a[1] / b[1]
