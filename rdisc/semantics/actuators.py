"""The actuator's rules (thesis §7.2.6): what drives a joint between the device's command and the
joint, checked into the Model. An actuator is one motor: a transmission names it (`transmission
T: JOINT actuator A { ... }`), at most one transmission each, so that every model written from
the body (URDF's `<actuator>`, MJCF's) has one actuator of that name. A servo is commanded a
position, a wheel a velocity; the limits are positive numbers; the gain a description states is
held against the inertia its joint carries (W621), as the simulation will integrate it.
"""

from __future__ import annotations

from rdisc.diagnostics import Diagnostics, Label
from rdisc.semantics import model as m
from rdisc.semantics.body import BodyRules
from rdisc.semantics.linear import limited
from rdisc.semantics.reflected import STABLE_STEP, TIMESTEP, joint_inertia, steps_per_period
from rdisc.syntax import ast

_KINDS = {k.value: k for k in m.ActuatorKind}
KEYS = ("velocity", "acceleration", "effort", "gain", "damping")
LIMITS = ("shape", "refuse")  # `limit shape` (the default) or `limit refuse`: what a command beyond a limit meets
_COMMANDED = {m.ActuatorKind.SERVO: m.Quantity.POSITION, m.ActuatorKind.WHEEL: m.Quantity.VELOCITY}


def actuator(d: Diagnostics, body: BodyRules, decl: ast.ActuatorDecl) -> m.Actuator | None:
    """One `actuator NAME: KIND { ... }`: a known kind, known keys each at most once, positive numbers."""
    from rdisc.semantics.resolve import suggest

    kind = _KINDS.get(decl.kind.text)
    if kind is None:
        d.report("E620", decl.kind.span, f"unknown actuator kind `{decl.kind.text}`",
                 help=suggest(decl.kind.text, _KINDS) or "actuators are " + ", ".join(_KINDS))
    for item in decl.items:
        if item.key not in KEYS and item.key != "limit":
            d.report("E620", item.span, f"an actuator has no `{item.key}`",
                     help=suggest(item.key, (*KEYS, "limit")) or "its items are " + ", ".join((*KEYS, "limit")))
    refuse = limit(d, body, decl) == "refuse"
    values: dict[str, float | None] = {}
    clauses: dict[str, ast.Expr | None] = {}
    for key in KEYS:
        expr = clauses[key] = body.once(decl.items, key, decl.name)
        value = None if expr is None else body.number(expr, f"an actuator's {key}")
        if value is not None and value <= 0:
            d.report("E620", expr.span if expr is not None else decl.name.span,
                     f"an actuator's {key} is more than 0, not {value:g}")
            value = None
        values[key] = value
    if kind is m.ActuatorKind.WHEEL:
        for item in decl.items:
            if item.key in ("gain", "damping"):
                key = item.key
                d.report("E620", item.span, f"a wheel has no `{key}`: it holds a speed, not a position",
                         help="its simulated motor pushes with its whole effort when its speed is off by 1% "
                              "of its `velocity`")
    if kind is None:
        return None
    return m.Actuator(decl.name.text, kind, values["velocity"], values["acceleration"], values["effort"],
                      values["gain"], values["damping"], decl.doc, decl.span, refuse, body.written(**clauses))


def _unlimited(d: Diagnostics, decl: ast.TransmissionDecl, motor: m.Actuator, transmission: m.Transmission) -> None:
    """W622: a command of the transmission the engine cannot hold to its actuator's limits."""
    for binding in transmission.commands:
        if binding.quantity is not _COMMANDED[motor.kind] or limited(binding):
            continue  # another quantity is E620
        why = ("it gives an interface's parameter" if binding.interface
               else "its conversion is not a ratio (`raw = round(position * K) + C`)")
        d.report("W622", binding.span or decl.span,
                 f"actuator `{motor.name}`'s limits do not hold transmission `{transmission.name}`'s command of "
                 f"`{binding.place()}`: {why}", help="commands beyond its `velocity` or `acceleration` are written "
                 "as they are: command a primitive's parameter, through a ratio")


def limit(d: Diagnostics, body: BodyRules, decl: ast.ActuatorDecl) -> str:
    """`limit shape` or `limit refuse`, a word, not a value: what a command beyond the limits meets."""
    from rdisc.semantics.resolve import suggest

    expr = body.once(decl.items, "limit", decl.name)
    if expr is None:
        return "shape"
    word = expr.name if isinstance(expr, ast.Ref) else None
    if word not in LIMITS:
        shown = f"`{word}`" if word is not None else "a value"
        d.report("E620", expr.span, f"an actuator's limit is `shape` or `refuse`, not {shown}",
                 help=(suggest(word, LIMITS) if word is not None else None)
                 or "`limit shape` slows a command to the limits, `limit refuse` refuses it")
        return "shape"
    return word


def bind(d: Diagnostics, decls: dict[str, ast.TransmissionDecl], actuators: dict[str, m.Actuator],
         transmissions: dict[str, m.Transmission], links: dict[str, m.Link], joints: dict[str, m.Joint]) -> None:
    """Each actuator named by at most one transmission, whose command is the actuator's quantity;
    a stated servo gain the joint's inertia can follow within a simulated step (W621)."""
    named: dict[str, ast.TransmissionDecl] = {}
    inertia: dict[str, float] | None = None
    for name, decl in decls.items():
        if decl.actuator is None or decl.actuator.text not in actuators:
            continue
        motor = actuators[decl.actuator.text]
        first = named.setdefault(motor.name, decl)
        if first is not decl:
            d.report("E620", decl.actuator.span, f"actuator `{motor.name}` already drives transmission "
                     f"`{first.name.text}`", labels=(Label(first.actuator.span if first.actuator else first.span,
                                                           "named here first"),),
                     help="an actuator is one motor: declare one for each joint it drives")
            continue
        transmission = transmissions.get(name)
        if transmission is None:
            continue
        want = _COMMANDED[motor.kind]
        wrong = next((b for b in transmission.commands if b.quantity is not want), None)
        if wrong is not None:
            d.report("E620", decl.actuator.span, f"a {motor.kind.value} is commanded a {want.value}, but "
                     f"transmission `{name}` commands its {wrong.quantity.value}",
                     help=f"`command {want.value} to ...`, or an actuator of another kind")
        if motor.velocity is not None or motor.acceleration is not None:
            _unlimited(d, decl, motor, transmission)
        if motor.kind is m.ActuatorKind.SERVO and motor.gain is not None:
            if inertia is None:
                inertia = joint_inertia(links, joints)
            carried = inertia.get(transmission.joint, 0.0)
            steps = steps_per_period(motor.gain, carried, TIMESTEP)
            if steps > STABLE_STEP:
                d.report("W621", decl.actuator.span,
                         f"actuator `{motor.name}`'s gain of {motor.gain:g} N m/rad on joint `{transmission.joint}`, "
                         f"which carries {carried:.3g} kg m², rings at {steps:.3g} rad a simulated step: the "
                         "simulation will be unstable", help="leave `gain` out (it is then derived from the effort "
                         f"and the inertia), or give at most {carried * (STABLE_STEP / TIMESTEP) ** 2:.3g}")
