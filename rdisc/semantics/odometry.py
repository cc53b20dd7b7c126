"""A differential drive's odometry against its body (issue 26, E613): an `Odometry` output whose
pose a primitive's post-actions integrate from the two wheels' encoder counts must move as the
body's wheels roll for those counts. Its metres per count and its wheel base are numbers of the
description's own, which no URDF tool sees: a wheel radius of 0.036 m in the odometry and 0.044 m
in the body has the odometry say 0.396 m where the base went 0.485 m.

Decided from the expressions, not by simulating: the post-actions are run twice, as two replies
would run them (a first reading, then one step of counts later), with the checker's interpreter;
the body's side is each wheel's `measure position` conversion of those counts, rolled at the
wheel's radius about its joint's axis (rdisc.semantics.drive). Both are exact for the linear
conversions odometry uses (a scale, a wrap of the counter), so one step says it. A step each
way: both wheels forward (the radius), and one forward, one back (the wheel base).

An odometry whose step reads state the device sets elsewhere (a calibration), a parameter, or
encoders not stored as `ENCODER = out[i]`, is not judged: its values are the device's, known only
when it runs (`rdisc sim` still holds it against the physics).
"""

from __future__ import annotations

import math
from collections.abc import Iterable

from rdisc.diagnostics import Diagnostics, Label
from rdisc.engine.operations import EvalError
from rdisc.semantics import model as m
from rdisc.semantics.drive import TOLERANCE, Wheel, base_motion, find_wheels
from rdisc.semantics.evaluate import evaluate
from rdisc.semantics.resolve import Symbols

COUNTS = 100  # encoder counts of the step tried: small beside any counter's wrap, large beside its rounding
HELP = "the odometry's metres per count and wheel base are the body's wheel radius and track: constants both use"


def check_odometry(model: m.Model, d: Diagnostics, symbols: Symbols) -> None:
    """Each `Odometry` output integrated from the encoders of the body's two wheels."""
    wheels = find_wheels(model, _measured)
    if wheels is None:
        return
    wheels.sort(key=lambda w: -w.centre[1])  # the left wheel first
    encoders = [_encoder(model, w) for w in wheels]
    if any(e is None for e in encoders):
        return
    for name, output in model.outputs.items():
        adapter = model.adapters.get(output.adapter)
        if adapter is None or not adapter.standard or adapter.name != "Odometry":
            continue
        fields = dict(output.fields)
        if not {"x", "y", "theta"} <= set(fields):
            continue
        step = _Step.find(model, [fields["x"], fields["y"], fields["theta"]], [e for e in encoders if e])
        if step is not None:
            _judge(model, d, symbols, name, wheels, [e for e in encoders if e], step)


def _measured(t: m.Transmission) -> bool:
    """A wheel's transmission that measures its angle from a state variable (an encoder)."""
    return any(_is_encoder(b) for b in t.measures)


def _encoder(model: m.Model, wheel: Wheel) -> m.Binding | None:
    found = [b for t in model.transmissions.values() if t.joint == wheel.joint.name for b in t.measures
             if _is_encoder(b)]
    return found[0] if len(found) == 1 else None


def _is_encoder(binding: m.Binding) -> bool:
    """A measure of a joint's angle from one state variable, not an array's item."""
    return binding.quantity is m.Quantity.POSITION and binding.index is None


class _Step:
    """A primitive's post-actions that store both encoders from its reply and the pose the
    odometry's fields read, reading nothing but what they store and settings."""

    def __init__(self, model: m.Model, primitive: m.Primitive, pose: list[m.Expr], places: list[int]) -> None:
        self.model = model
        self.primitive = primitive
        self.pose = pose
        self.places = places  # the reply's value each encoder is stored from
        self.size = 1 + max(_reply_values(a.stored() for a in primitive.actions))

    @classmethod
    def find(cls, model: m.Model, pose: list[m.Expr], encoders: list[m.Binding]) -> _Step | None:
        read = set().union(*(_names(e) for e in pose)) - set(model.settings)
        for p in model.primitives.values():
            if p.table is not None or p.listed or p.records is not None:
                continue
            stored: dict[str, m.PostAction] = {a.target: a for a in p.actions}
            if not read <= set(stored) or any(a.when is not None for a in p.actions):
                continue
            places = [_stored_from(stored.get(e.target)) for e in encoders]
            reads = set().union(*(_names(a.stored()) for a in p.actions))
            if any(i is None for i in places) or not reads <= set(stored) | set(model.settings):
                continue
            return cls(model, p, pose, [i for i in places if i is not None])
        return None

    def after(self, counts: list[int]) -> tuple[float, float, float]:
        """The pose the odometry says after a first reading of 0 counts and a second of `counts`,
        in the frame of the pose after the first: (forward, sideways, turned)."""
        state: dict[str, m.Value] = {n: s.initial for n, s in self.model.states.items()}
        settings = {n: s.default for n, s in self.model.settings.items()}
        poses = []
        for reading in ([0] * len(counts), counts):
            reply: list[m.Value] = [0] * self.size
            for place, count in zip(self.places, reading, strict=True):
                reply[place] = count
            names = {**state, **settings}
            state = {**state, **{a.target: m.coerce(evaluate(a.stored(), names, reply), self.model.states[a.target].type)
                                 for a in self.primitive.actions}}
            x, y, theta = (evaluate(e, {**state, **settings}) for e in self.pose)
            poses.append((float(x), float(y), float(theta)))  # type: ignore[arg-type]
        (x0, y0, t0), (x1, y1, t1) = poses
        dx, dy = x1 - x0, y1 - y0
        return dx * math.cos(t0) + dy * math.sin(t0), dy * math.cos(t0) - dx * math.sin(t0), t1 - t0


def _judge(model: m.Model, d: Diagnostics, s: Symbols, name: str, wheels: list[Wheel], encoders: list[m.Binding],
           step: _Step) -> None:
    """Both wheels' encoders a step forward (the radius), then the right's forward and the left's
    back (the wheel base): where the odometry's step and the body's differ by more than TOLERANCE
    of the wheels' roll, the first is reported."""
    decl = s.outputs[name]
    written = next((a for a in step.primitive.actions if a.target in _names(step.pose[0])), None)
    step_label = (Label(written.span, f"the odometry's step, in `{step.primitive.name}`"),) \
        if written is not None and written.span is not None else ()
    track = abs(wheels[0].centre[1] - wheels[1].centre[1])
    radius = sum(w.radius for w in wheels) / 2
    shape = wheels[0].shape
    wheel_label = (Label(shape.span, f"the body's wheel, radius {radius:.6g} m"),) if shape.span is not None else ()
    joints = tuple(Label(s.joints[w.joint.name].name.span, f"at y = {w.centre[1]:.6g} m") for w in wheels)
    trials = (("of each wheel's encoder", [COUNTS, COUNTS], wheel_label),
              ("forward of the right wheel's encoder and back of the left's", [-COUNTS, COUNTS], joints))
    for counted, counts, labels in trials:
        try:
            said, _, said_turn = step.after(counts)
            rolled = _rolled(wheels, encoders, counts)
        except (EvalError, ArithmeticError, ValueError, TypeError, KeyError, IndexError):
            return  # a step the interpreter cannot take is not judged (the runtime would say why)
        roll = sum(abs(r) for r in rolled) / 2
        if roll == 0 or not all(math.isfinite(v) for v in (said, said_turn, roll)):
            return  # wheels that do not roll, or a step to no number: nothing to hold it to
        went, turned = base_motion(rolled, wheels[0].centre[1], wheels[1].centre[1])
        if abs(said - went) <= TOLERANCE * roll and abs(said_turn - turned) * track / 2 <= TOLERANCE * roll:
            continue
        message = f"output `{name}` says {COUNTS} counts {counted} "
        if counts[0] == counts[1] and abs(said_turn - turned) * track / 2 <= TOLERANCE * roll and said * went > 0:
            message += (f"move the base {said:.4g} m, but the body's wheels roll it {went:.4g} m: the odometry's "
                        f"wheel radius is {radius * said / went:.4g} m, the body's wheels are {radius:.4g} m")
        elif counts[0] != counts[1] and abs(said - went) <= TOLERANCE * roll and said_turn * turned > 0:
            message += (f"turn the base {said_turn:.4g} rad, but the body turns {turned:.4g} rad: the odometry's "
                        f"wheels are {track * turned / said_turn:.4g} m apart, the body's wheel joints are "
                        f"{track:.4g} m apart")
        else:
            message += (f"move the base {said:.4g} m and turn it {said_turn:.4g} rad, but the body's wheels move it "
                        f"{went:.4g} m and turn it {turned:.4g} rad")
        d.report("E613", decl.name.span, message, labels=(*step_label, *labels), help=HELP)
        return


def _rolled(wheels: list[Wheel], encoders: list[m.Binding], counts: list[int]) -> list[float]:
    """How far each of the body's wheels rolls forward when its encoder counts `counts` from 0."""
    rolled = []
    for wheel, encoder, count in zip(wheels, encoders, counts, strict=True):
        turned = _number(evaluate(encoder.to_joint, {"raw": count})) - _number(evaluate(encoder.to_joint, {"raw": 0}))
        rolled.append(wheel.forward(turned))
    return rolled


def _number(value: m.Value) -> float:
    if type(value) not in (int, float):
        raise TypeError(value)
    return float(value)  # type: ignore[arg-type]


def _stored_from(action: m.PostAction | None) -> int | None:
    """i, for an action `ENCODER = out[i]`."""
    if action is None or action.when is not None or not isinstance(action.value, m.ReplyValue):
        return None
    return action.value.index


def _names(expr: m.Expr) -> set[str]:
    return {v.name for v in m.variables(expr)}


def _reply_values(exprs: Iterable[m.Expr]) -> set[int]:
    found: set[int] = {0}
    pending = list(exprs)
    while pending:
        node = pending.pop()
        if isinstance(node, m.ReplyValue):
            found.add(node.index)
        pending.extend(m.operands(node))
    return found
