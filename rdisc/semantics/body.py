"""The body's rules (thesis ch. 6): links, joints and transmissions, checked into the Model.

Robot formats check a tree of links; what none of them checks is that the body and the
device agree. Here a joint's limits, mapped through its transmission's conversion, must
fall in the range the device accepts, and the two conversions must undo each other, so a
URDF, a simulation and the serial device cannot silently disagree.
"""

from __future__ import annotations

import math

from rdisc.diagnostics import Label
from rdisc.engine.operations import EvalError
from rdisc.semantics import model as m
from rdisc.semantics.body_joints import BodyJoints
from rdisc.semantics.body_values import (
    _QUANTITIES,
    MAX_CONVERSION_NODES,
    SAMPLES,
    _close,
    _shown,
    joint_range,
    sample,
    size,
)
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.resolve import suggest
from rdisc.semantics.types import Env, describe
from rdisc.semantics.units import CARRIERS, UNITS, carries, dimension_of
from rdisc.source import Span
from rdisc.syntax import ast


class BodyRules(BodyJoints):
    """Checks the body's declarations. Its numbers are constants, or read the description's
    `settings` (a wheel base given when connecting): each has its default, or the value the
    description is compiled with (`compile_path(..., settings=...)`, `--set` of the verbs that
    write or simulate the body)."""

    # -- transmissions -----------------------------------------------------------------

    def transmission(self, decl: ast.TransmissionDecl, joints: dict[str, m.Joint],
                     primitives: dict[str, m.Primitive], interfaces: dict[str, tuple[m.Parameter, ...]],
                     states: dict[str, m.StateVariable]) -> m.Transmission | None:
        joint = joints.get(decl.joint.text)
        if joint is None:  # unknown (reported) or refused
            return None
        if not joint.moves():
            self.d.report("E605", decl.joint.span, f"joint `{joint.name}` is fixed: there is nothing to transmit")
            return None
        if not decl.bindings:
            self.d.report("E605", decl.name.span, f"transmission `{decl.name.text}` neither commands nor measures "
                          f"joint `{joint.name}`", help="add `command QUANTITY to ...` or `measure QUANTITY from ...`")
        commands: list[m.Binding] = []
        measures: list[m.Binding] = []
        for binding in decl.bindings:
            checked = self.binding(binding, joint, primitives, interfaces, states)
            if checked is not None:
                (commands if binding.role == "command" else measures).append(checked)
        actuator = decl.actuator.text if decl.actuator is not None and decl.actuator.text in self.s.actuators else None
        return m.Transmission(decl.name.text, joint.name, tuple(commands), tuple(measures), decl.doc, decl.span,
                              actuator)

    def binding(self, b: ast.Binding, joint: m.Joint, primitives: dict[str, m.Primitive],
                interfaces: dict[str, tuple[m.Parameter, ...]],
                states: dict[str, m.StateVariable]) -> m.Binding | None:
        quantity = _QUANTITIES.get(b.quantity.text)
        if quantity is None:
            self.d.report("E605", b.quantity.span, f"unknown joint quantity `{b.quantity.text}`",
                          help=suggest(b.quantity.text, _QUANTITIES) or "a joint has a position, velocity and effort")
            return None
        target = b.target.text
        param: m.Parameter | None = None
        device: m.AnyType | None
        is_interface = False
        if b.role == "command":
            primitive = primitives.get(target)
            params = primitive.params if primitive is not None else interfaces.get(target)
            is_interface = primitive is None
            if params is None:  # unknown: reported
                return None
            assert b.member is not None  # a command names its parameter (the parser and the importer see to it)
            member = b.member.text
            param = next((p for p in params if p.name == member), None)
            if param is None:
                kind = "interface" if is_interface else "primitive"
                self.d.report("E605", b.member.span, f"{kind} `{target}` has no parameter `{member}`",
                              help=suggest(member, [p.name for p in params]))
                return None
            device = param.type
            where = f"parameter `{target}.{member}`"
            if param.unit is not None and not carries(param.unit, quantity):
                decl = self.s.primitives.get(target) or self.s.interfaces.get(target)
                unit = next((p.unit for p in decl.params if p.name.text == member), None) if decl else None
                self.d.report("E605", b.member.span,
                              f"`{target}.{member}` is in {param.unit}, {UNITS[param.unit].value}, but the "
                              f"transmission commands joint `{joint.name}`'s {quantity.value}, "
                              f"{dimension_of(quantity, joint.kind).value}",
                              labels=() if unit is None else (Label(unit.span, "the parameter's unit"),),
                              help=f"a {quantity.value} is carried by "
                              f"{' or '.join(d.value for d in CARRIERS[quantity])}, or a dimensionless count or %")
                return None
        else:
            if target in self.s.settings:
                self.d.report("E605", b.target.span, f"`{target}` is a setting: a joint is measured by a state "
                              "variable its replies set")
                return None
            variable = states.get(target)
            if variable is None:
                return None
            self.typer.reads.add(target)
            device = variable.type
            where = f"state variable `{target}`"
        if device is None:  # its type is in error, reported where it is declared
            return None
        index = self.index(b, device, where)
        if index is False:
            return None
        scalar = device.element if isinstance(device, m.Array) else device
        if scalar not in (Type.INT, Type.FLOAT):
            self.d.report("E605", (b.member or b.target).span, f"{where} is {describe(device)}, not a number",
                          help="a joint's quantity is carried by an int or float")
            return None
        conversions = self.conversions(b, quantity, scalar)
        if conversions is None:
            return None
        binding = m.Binding(quantity, target, param.name if param is not None else None, index, *conversions,
                            interface=is_interface, span=b.span, expressions=self.written(index=b.index))
        self.agree(b, binding, joint, scalar, param)
        return binding

    def index(self, b: ast.Binding, device: m.AnyType | None, where: str) -> int | None | bool:
        """The element of an array a binding names (False when refused, None for a scalar)."""
        if isinstance(device, m.Array):
            if b.index is None:
                self.d.report("E605", (b.member or b.target).span, f"{where} is {describe(device)}: name one "
                              "element, `[i]`")
                return False
            value = self.number(b.index, "an element's index")
            if value is None:
                return False
            if value != int(value) or not 0 <= value < device.size:
                self.d.report("E605", b.index.span, f"{where} has elements 0..{device.size - 1}, not {value:g}")
                return False
            return int(value)
        if b.index is not None:
            self.d.report("E605", b.index.span, f"{where} is not an array")
            return False
        return None

    def conversions(self, b: ast.Binding, quantity: m.Quantity, device: Type) -> tuple[m.Expr, m.Expr] | None:
        """`raw = ...` (the device's value, from the quantity) and `QUANTITY = ...` (back)."""
        name = quantity.value
        found: dict[str, ast.Assign] = {}
        for a in b.conversions:
            if a.target.text not in ("raw", name) or a.index is not None:
                self.d.report("E605", a.target.span, f"a {b.role} converts `raw` and `{name}`, not "
                              f"`{a.target.text}`", help=f"`raw = ...` from `{name}`, and `{name} = ...` from `raw`")
                return None
            if a.target.text in found:
                self.d.report("E203", a.span, f"`{a.target.text}` is given twice",
                              labels=(Label(found[a.target.text].span, "first given here"),))
                return None
            found[a.target.text] = a
        for missing in ("raw", name):
            if missing not in found:
                reads = f"`{name}`" if missing == "raw" else "`raw`"
                self.d.report("E605", b.span, f"this {b.role} does not say `{missing} = ...` (from {reads})",
                              help="a transmission converts both ways: the checks and the simulation need both")
                return None
        raw_env = Env({name: (Scope.PARAM, Type.FLOAT)}, "in a conversion to the device", f"`{name}` and constants")
        joint_env = Env({"raw": (Scope.PARAM, device)}, "in a conversion to the joint", "`raw` and constants")
        errors = self.d.error_count
        to_device = self.typer.expr(found["raw"].value, raw_env)
        to_joint = self.typer.expr(found[name].value, joint_env)
        if self.d.error_count > errors:
            return None
        if (to_device.type, device) == (Type.FLOAT, Type.INT):
            self.d.report("E402", found["raw"].value.span, "the device's value is an int, but this is a float",
                          help="convert it: `round(...)` to the nearest integer")
            return None
        for expr, assign in ((to_device, found["raw"]), (to_joint, found[name])):
            if expr.type is None:  # a value of unknown type, reported where it comes from
                return None
            if expr.type not in (Type.INT, Type.FLOAT):
                self.d.report("E401", assign.value.span, f"a conversion gives a number, not {describe(expr.type)}")
                return None
        return to_device, to_joint

    def agree(self, b: ast.Binding, binding: m.Binding, joint: m.Joint, device: Type,
              param: m.Parameter | None) -> None:
        """The joint's range, mapped to the device, lies in what the device accepts; and the device's
        value, converted to the joint and back, is itself (to one step of an int)."""
        low, high, text = joint_range(joint, binding.quantity)
        decl = self.s.joints[joint.name]
        span = next((i.span for i in decl.items if isinstance(i, ast.JointLimit) and text == "limit"
                     or isinstance(i, ast.BodyValue) and i.key == text), decl.span)
        if low is None or high is None:
            return
        from rdisc.semantics.evaluate import prepare  # the runtime's own interpreter: the check is what runs

        self.work += 2 * size(binding.to_device) + size(binding.to_joint)
        if self.work > MAX_CONVERSION_NODES:
            if self.work - MAX_CONVERSION_NODES <= 2 * size(binding.to_device) + size(binding.to_joint):
                self.d.report("E005", b.span, f"the body's conversions have more than {MAX_CONVERSION_NODES} "
                              "operations in all: too many to check against the device",
                              help="a conversion is a scale and an offset: `raw = round(position * 195.3) + 512`")
            return
        name = binding.quantity.value
        step = 1.0 if device is Type.INT else 0.0
        to_device, to_joint = prepare(binding.to_device), prepare(binding.to_joint)

        def given(value: m.Value, type_: Type) -> m.Value:
            """A value as the runtime binds it: an int where a float is declared made a float."""
            return float(value) if type_ is Type.FLOAT and type(value) is int else value

        for x in sample(low, high):
            try:
                raw = given(to_device({}, {name: x}, ()), device)
                back = given(to_joint({}, {"raw": raw}, ()), Type.FLOAT)
                again = given(to_device({}, {name: back}, ()), device)
            except (EvalError, ArithmeticError, ValueError, OverflowError) as err:
                self.d.report("E606", b.span, f"converting {name} {x:g} of joint `{joint.name}` fails: {err}",
                              labels=(Label(span, f"its {text}"),))
                return
            if any(isinstance(v, float) and not math.isfinite(v) for v in (raw, back, again)):
                self.d.report("E606", b.span, f"converting {name} {x:g} of joint `{joint.name}` gives raw "
                              f"{_shown(raw)}, which comes back as {name} {_shown(back)}: not a finite number",
                              labels=(Label(span, f"its {text}"),))
                return
            if param is not None and param.low is not None and param.high is not None \
                    and not param.low <= raw <= param.high:  # type: ignore[operator]
                self.d.report("E606", b.span, f"joint `{joint.name}`'s {name} {x:g} becomes {_shown(raw)} at "
                              f"{binding.place()}, outside its range {param.range_text()}",
                              labels=(Label(span, f"the joint's {text}"), *self.range_label(binding)),
                              help="narrow the joint's limits, or correct the conversion")
                return
            if not _close(again, raw, step):  # type: ignore[arg-type]
                self.d.report("E606", b.span, f"the conversions do not undo each other: {name} {x:g} becomes "
                              f"raw {_shown(raw)}, which comes back as {name} {_shown(back)}, which becomes raw "
                              f"{_shown(again)}",
                              help=f"`{name} = ...` must invert `raw = ...`")
                return
        if param is not None and param.low is not None and param.high is not None:
            self.between(b, binding, joint, (low, high), (float(param.low), float(param.high)), span, text)

    def between(self, b: ast.Binding, binding: m.Binding, joint: m.Joint, joint_range: tuple[float, float],
                accepted: tuple[float, float], span: Span, text: str) -> None:
        """The whole range, not only its samples: where the conversion's bounds (rdisc.semantics.intervals)
        leave the device's range, a value of the joint that truly converts outside it is looked for."""
        from rdisc.semantics.evaluate import prepare
        from rdisc.semantics.intervals import witness

        name = binding.quantity.value
        to_device = prepare(binding.to_device)

        def value(x: float) -> float:
            try:
                raw = to_device({}, {name: x}, ())
            except (EvalError, ArithmeticError, ValueError, OverflowError):
                return math.nan
            return float(raw) if type(raw) in (int, float) else math.nan  # type: ignore[arg-type]

        x = witness(binding.to_device, name, joint_range[0], joint_range[1], accepted, value)
        if x is not None:
            self.d.report("E606", b.span, f"joint `{joint.name}`'s {name} {x:.6g} becomes {value(x):.10g} at "
                          f"{binding.place()}, outside its range {accepted[0]:g}..{accepted[1]:g}, between the "
                          f"{SAMPLES} values sampled",
                          labels=(Label(span, f"the joint's {text}"), *self.range_label(binding)),
                          help="every value of the joint's range is converted, not only its samples: correct the "
                               "conversion")

    def range_label(self, binding: m.Binding) -> tuple[Label, ...]:
        decl = self.s.primitives.get(binding.target) or self.s.interfaces.get(binding.target)
        if decl is None:
            return ()
        p = next((p for p in decl.params if p.name.text == binding.parameter), None)
        if p is None or p.low is None or p.high is None:
            return ()
        return (Label(p.low.span.to(p.high.span), "the range the device accepts"),)
