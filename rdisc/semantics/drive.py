"""A differential drive's body against the input that drives it (issue 26): no URDF tool can
check this, since it takes both halves. A Twist (`DifferentialSpeed`) is mapped by the input to
interface and primitive arguments, which the transmissions' conversions turn into wheel speeds;
the wheels' axes, places and radii then say how the base would move. A forward command must
move it forward and a counter-clockwise one turn it counter-clockwise (E612), at the speeds
commanded (E613: the conversions' wheel radius and track are the body's). Every step is the
description's own expressions evaluated once per command, with the checker's interpreter; nothing
is simulated. A drive this cannot follow (a condition on state, a third wheel, a wheel of no
round shape) is not judged.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from rdisc.diagnostics import Diagnostics, Label
from rdisc.engine.operations import EvalError
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import evaluate
from rdisc.semantics.resolve import Symbols
from rdisc.syntax import ast

LINEAR = 0.1  # m/s: the forward command tried, small enough for any drive's range
ANGULAR = 0.5  # rad/s: the counter-clockwise command tried
TOLERANCE = 0.05  # a relative difference of speeds the device's steps (mm/s rounded) cannot explain
ADAPTERS = ("DifferentialSpeed", "Twist")
Command = dict[tuple[bool, str, str], m.Value]  # (interface?, target, parameter) -> the value it is given
Vector = tuple[float, float, float]


@dataclass(frozen=True)
class Wheel:
    joint: m.Joint
    centre: Vector  # in the base's frame
    axis: Vector  # unit, in the base's frame
    radius: float
    shape: m.Shape

    def forward(self, turning: float) -> float:
        """The speed along the base's x axis that turning at `turning` rad/s gives the wheel's
        centre, rolling without slip on the floor below it."""
        a = self.axis
        down = (a[2] * a[0], a[2] * a[1], a[2] * a[2] - 1.0)  # -z without its part along the axis
        size = math.sqrt(sum(c * c for c in down))
        lever = tuple(-self.radius * c / size for c in down)  # from the contact point to the centre
        return turning * (a[1] * lever[2] - a[2] * lever[1])


def check_drives(model: m.Model, d: Diagnostics, symbols: Symbols) -> None:
    """Each input of a Twist against the two wheels it turns."""
    for name, inp in model.inputs.items():
        adapter = model.adapters.get(inp.adapter)
        if adapter is None or not adapter.standard or adapter.name not in ADAPTERS:
            continue
        wheels = find_wheels(model, commanded)
        if wheels is None:
            continue
        forward = _turning(model, inp, wheels, {"linear": LINEAR, "angular": 0.0})
        turning = _turning(model, inp, wheels, {"linear": 0.0, "angular": ANGULAR})
        if forward is None or turning is None:
            continue
        _judge(model, d, symbols, symbols.inputs[name], wheels, forward, turning)


def _judge(model: m.Model, d: Diagnostics, s: Symbols, decl: ast.InputDecl, wheels: list[Wheel],
           forward: list[float], turning: list[float]) -> None:
    name = decl.name.text
    command = Label(decl.name.span, "the command")
    rolled = [w.forward(t) for w, t in zip(wheels, forward, strict=True)]
    backward = [(w, v) for w, v in zip(wheels, rolled, strict=True) if v <= 0]
    for wheel, speed in backward:
        joint = s.joints[wheel.joint.name]
        axis = next((i for i in joint.items if isinstance(i, ast.BodyValue) and i.key == "axis"), None)
        d.report("E612", (axis or joint.name).span,
                 f"a forward command of {LINEAR:g} m/s to input `{name}` turns joint `{wheel.joint.name}` so that "
                 f"its wheel rolls {'backward' if speed < 0 else 'not at all'} ({_speed(speed)} m/s)",
                 labels=(command,),
                 help="a forward command turns both wheels forward: turn this axis round, or correct the "
                      "conversion or the input")
    if backward:
        return
    (y1, y2) = (wheels[0].centre[1], wheels[1].centre[1])
    radius = sum(w.radius for w in wheels) / 2
    track = abs(y1 - y2)
    linear, veer = base_motion(rolled, y1, y2)
    spun = [w.forward(t) for w, t in zip(wheels, turning, strict=True)]
    _, angular = base_motion(spun, y1, y2)
    if angular <= 0:
        d.report("E612", decl.name.span,
                 f"a counter-clockwise command of {ANGULAR:g} rad/s to input `{name}` turns the base "
                 f"{'clockwise' if angular < 0 else 'not at all'} ({_speed(angular)} rad/s)",
                 help="a positive angular speed turns the base to the left: the input gives the wheels' speeds "
                      "the other way round")
        return
    shape = Label(wheels[0].shape.span, f"the body's wheel, radius {radius:.6g} m") \
        if wheels[0].shape.span is not None else None
    if abs(veer) * track / 2 > TOLERANCE * linear:
        d.report("E613", decl.name.span,
                 f"a forward command of {LINEAR:g} m/s to input `{name}` also turns the body's base, at {veer:.4g} "
                 f"rad/s: its wheels roll at " + " and ".join(f"{v:.4g}" for v in rolled) + " m/s",
                 labels=tuple(Label(w.shape.span, f"radius {w.radius:.6g} m") for w in wheels
                              if w.shape.span is not None),
                 help="the two wheels and their conversions are alike: the same radius, the same conversion")
        return
    if abs(linear / LINEAR - 1) > TOLERANCE:
        d.report("E613", decl.name.span,
                 f"a forward command of {LINEAR:g} m/s to input `{name}` moves the body's base at {linear:.4g} m/s: "
                 f"the conversions turn the wheels as if their radius were {radius * LINEAR / linear:.4g} m, "
                 f"the body's wheels are {radius:.4g} m",
                 labels=() if shape is None else (shape,),
                 help="the conversions' wheel radius and the wheels' shapes are one number: a constant both use")
        return
    if abs(angular / ANGULAR - 1) > TOLERANCE:
        joints = tuple(Label(s.joints[w.joint.name].name.span, f"at y = {w.centre[1]:.6g} m") for w in wheels)
        d.report("E613", decl.name.span,
                 f"a counter-clockwise command of {ANGULAR:g} rad/s to input `{name}` turns the body's base at "
                 f"{angular:.4g} rad/s: the input gives the wheels' speeds as if they were "
                 f"{track * angular / ANGULAR:.4g} m apart, the body's wheel joints are {track:.4g} m apart",
                 labels=joints,
                 help="the input's wheel base and the wheel joints' places are one number: a constant both use")


def base_motion(speeds: list[float], y1: float, y2: float) -> tuple[float, float]:
    """The base's forward and angular speed from its wheels' forward speeds at y1 and y2."""
    angular = (speeds[1] - speeds[0]) / (y1 - y2)
    return speeds[0] + angular * y1, angular


def _speed(value: float) -> str:
    return f"{value:.4g}"


def commanded(t: m.Transmission) -> bool:
    """A wheel's transmission that commands its speed."""
    return any(b.quantity is m.Quantity.VELOCITY for b in t.commands)


def find_wheels(model: m.Model, turned: Callable[[m.Transmission], bool]) -> list[Wheel] | None:
    """The two wheels of the transmissions `turned` picks (`commanded`: a velocity command turns
    them), each on a joint whose parents are fixed to the base and with a round shape; None when
    the body is not such a drive."""
    wheels: list[Wheel] = []
    for t in model.transmissions.values():
        if not turned(t):
            continue
        joint = model.joints[t.joint]
        if joint.kind not in (m.JointKind.CONTINUOUS, m.JointKind.REVOLUTE):
            continue
        placed = _placed(model, joint)
        link = model.links[joint.child]
        shape = next((s for s in (*link.collisions, *link.visuals)
                      if s.kind in (m.ShapeKind.CYLINDER, m.ShapeKind.SPHERE)), None)
        if placed is None or shape is None:
            continue
        rotation, origin = placed
        axis = _apply(rotation, _unit(joint.axis))
        if abs(axis[2]) > 0.99:  # about the vertical: it steers, it does not roll
            continue
        centre = tuple(o + c for o, c in zip(origin, _apply(rotation, shape.origin.xyz), strict=True))
        wheels.append(Wheel(joint, (centre[0], centre[1], centre[2]), axis, shape.size[0], shape))
    if len(wheels) != 2 or abs(wheels[0].centre[1] - wheels[1].centre[1]) < 1e-9:
        return None
    return wheels


def _placed(model: m.Model, joint: m.Joint) -> tuple[list[list[float]], Vector] | None:
    """The joint's frame in the root's (rotation, origin), when every joint above it is fixed."""
    parents = {j.child: j for j in model.joints.values()}
    chain = [joint]
    while chain[-1].parent in parents:
        above = parents[chain[-1].parent]
        if above.moves():
            return None
        chain.append(above)
    rotation = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    origin: Vector = (0.0, 0.0, 0.0)
    for j in reversed(chain):
        moved = _apply(rotation, j.origin.xyz)
        origin = (origin[0] + moved[0], origin[1] + moved[1], origin[2] + moved[2])
        rotation = _product(rotation, _rotation(j.origin.rpy))
    return rotation, origin


def _turning(model: m.Model, inp: m.DomainInput, wheels: list[Wheel], fields: dict[str, float]) -> list[float] | None:
    """Each wheel's commanded rad/s for the adapter's `fields`, or None when it cannot be told."""
    names: dict[str, m.Value] = {n: s.initial for n, s in model.states.items()}
    names.update({n: s.default for n, s in model.settings.items()})
    adapter = model.adapters[inp.adapter]
    names.update({f.name: fields.get(f.name, 0.0) for f in adapter.fields if f.type is m.Type.FLOAT})
    given: Command = {}
    try:
        args = tuple(evaluate(a, names) for a in inp.args)
        _call(model, True, inp.interface, args, names, given, 0)
        turning: list[float] = []
        for wheel in wheels:
            t = next(t for t in model.transmissions.values() if t.joint == wheel.joint.name)
            b = next(b for b in t.commands if b.quantity is m.Quantity.VELOCITY)
            assert b.parameter is not None
            raw = given.get((b.interface, b.target, b.parameter))
            if raw is None:
                return None
            if b.index is not None:
                raw = raw[b.index]  # type: ignore[index]
            value = evaluate(b.to_joint, {"raw": raw})
            if type(value) not in (int, float):
                return None
            turning.append(float(value))  # type: ignore[arg-type]
        return turning
    except (EvalError, ArithmeticError, ValueError, TypeError, KeyError, IndexError, RecursionError):
        return None


def _call(model: m.Model, interface: bool, target: str, args: tuple[m.Value, ...],
          names: dict[str, m.Value], given: Command, depth: int) -> None:
    """What a call gives each parameter, through the interfaces it calls (each at most 8 deep)."""
    if depth > 8:
        raise RecursionError(target)
    owner = model.interfaces[target] if interface else model.primitives[target]
    values = dict(names)
    for i, p in enumerate(owner.params):
        value = args[i] if i < len(args) else p.default
        if value is None:
            raise ValueError(p.name)
        given[interface, target, p.name] = value
        values[p.name] = value
    if not isinstance(owner, m.Interface):
        return
    for call in owner.run_order():
        if call.when is not None and not evaluate(call.when, values):
            continue
        _call(model, call.interface, call.primitive, tuple(evaluate(a, values) for a in call.args), names,
              given, depth + 1)


def _unit(v: Vector) -> Vector:
    size = math.sqrt(sum(c * c for c in v))
    return (v[0] / size, v[1] / size, v[2] / size)


def _rotation(rpy: Vector) -> list[list[float]]:
    """URDF's roll, pitch, yaw as a matrix: about x, then y, then z, fixed axes."""
    (cr, sr), (cp, sp), (cy, sy) = ((math.cos(a), math.sin(a)) for a in rpy)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def _apply(r: list[list[float]], v: Vector) -> Vector:
    return (sum(r[0][k] * v[k] for k in range(3)), sum(r[1][k] * v[k] for k in range(3)),
            sum(r[2][k] * v[k] for k in range(3)))


def _product(a: list[list[float]], b: list[list[float]]) -> list[list[float]]:
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
