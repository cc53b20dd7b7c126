"""The syntax tree of the body: links, joints, transmissions, actuators (rdisc.syntax.ast, thesis ch. 6)."""

from __future__ import annotations

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.syntax.ast_body_methods import dataclass, field

from rdisc.frozen import Frozen
from rdisc.source import Span
from rdisc.syntax.ast_expressions import (
    Assign,
    Expr,
    Ident,
)

_span: Span = field(compare=False, repr=False, default=None)  # type: ignore[assignment]


# ---- the body (thesis ch. 6) ----------------------------------------------------


@dataclass(frozen=True, slots=True)
class Shape(metaclass=Frozen):
    """`box(x, y, z)`, `cylinder(radius, length)`, `sphere(radius)`, `mesh("file.stl", scale)`."""

    kind: Ident
    args: tuple[Expr, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class ShapeUse(metaclass=Frozen):
    """`visual SHAPE at XYZ rpy RPY color RGBA` or `collision ...`: a shape placed in its link's frame."""

    role: str  # "visual" | "collision"
    shape: Shape
    at: Expr | None
    rpy: Expr | None
    span: Span = _span
    color: Expr | None = None  # a visual's `[r, g, b]` or `[r, g, b, a]`, each 0 to 1


@dataclass(frozen=True, slots=True)
class LinkSpawn(metaclass=Frozen):
    """`spawn floating at XYZ rpy RPY` (or `fixed`): how and where the root link meets the world."""

    kind: Ident
    at: Expr | None
    rpy: Expr | None
    span: Span = _span


@dataclass(frozen=True, slots=True)
class BodyValue(metaclass=Frozen):
    """One `KEY value` clause of a link or joint: `mass 3.6`, `axis [0, 1, 0]`, `at [...]`."""

    key: str
    value: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class JointLimit(metaclass=Frozen):
    """`limit LOW..HIGH`: the joint's position range (rad, or m for a prismatic joint)."""

    low: Expr
    high: Expr
    span: Span = _span


@dataclass(frozen=True, slots=True)
class JointMimic(metaclass=Frozen):
    """`mimic JOINT multiplier M offset O`: this joint's position is M times JOINT's, plus O."""

    joint: Ident
    multiplier: Expr | None
    offset: Expr | None
    span: Span = _span


@dataclass(frozen=True, slots=True)
class LinkDecl(metaclass=Frozen):
    name: Ident
    items: tuple[ShapeUse | BodyValue | LinkSpawn, ...]
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class JointDecl(metaclass=Frozen):
    """`joint NAME: KIND PARENT -> CHILD { ... }`."""

    name: Ident
    kind: Ident
    parent: Ident
    child: Ident
    items: tuple[BodyValue | JointLimit | JointMimic, ...]
    span: Span = _span
    doc: str | None = None


@dataclass(frozen=True, slots=True)
class Binding(metaclass=Frozen):
    """`command QUANTITY to TARGET.PARAM[i] { raw = ...  QUANTITY = ... }` or
    `measure QUANTITY from STATE[i] { ... }`: a joint quantity and a device value, both ways."""

    role: str  # "command" | "measure"
    quantity: Ident
    target: Ident  # a primitive or interface (command), a state variable (measure)
    member: Ident | None  # the parameter commanded
    index: Expr | None  # its element, for an array
    conversions: tuple[Assign, ...]
    span: Span = _span


@dataclass(frozen=True, slots=True)
class TransmissionDecl(metaclass=Frozen):
    """`transmission NAME: JOINT { command ... measure ... }`."""

    name: Ident
    joint: Ident
    bindings: tuple[Binding, ...]
    span: Span = _span
    doc: str | None = None
    actuator: Ident | None = None  # `transmission NAME: JOINT actuator ACTUATOR { ... }`


@dataclass(frozen=True, slots=True)
class ActuatorDecl(metaclass=Frozen):
    """`actuator NAME: KIND { velocity ...  acceleration ...  effort ...  gain ...  damping ... }`."""

    name: Ident
    kind: Ident
    items: tuple[BodyValue, ...]
    span: Span = _span
    doc: str | None = None
