"""The body's numbers (rdisc.semantics.body): its constants and settings valued, the limits of
what a simulator takes, and `BodyValues`, the base of the body's rules, which values a clause's
expression and keeps what it read for the Model."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from typing import Protocol, TypeVar

from rdisc.diagnostics import Diagnostics, Label, abbreviate
from rdisc.engine.operations import EvalError
from rdisc.semantics import model as m
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.resolve import Symbols
from rdisc.semantics.types import Env, Typer, describe
from rdisc.source import Span
from rdisc.syntax import ast

# Sizes a shape takes, in order, and what they are called in diagnostics.
SHAPES = {
    m.ShapeKind.BOX: ("x", "y", "z"),
    m.ShapeKind.CYLINDER: ("radius", "length"),
    m.ShapeKind.SPHERE: ("radius",),
}
_KINDS = {k.value: k for k in m.JointKind}
_QUANTITIES = {q.value: q for q in m.Quantity}
_LIMITED = (m.JointKind.REVOLUTE, m.JointKind.PRISMATIC)
SAMPLES = 33  # points of a joint's range at which a conversion is checked, both ends included
# Operations of all conversions checked against the device: under a second of sampling, many times
# what a real body has; beyond it, a description's conversions would cost more to check than to read.
MAX_CONVERSION_NODES = 50_000
MAX_MASS = 1e6  # kg: a link heavier is out of what a simulator integrates (a mass of 1e308 makes MuJoCo's NaN)
MAX_INERTIA = 1e6  # kg m², each element of an inertia
MAX_LENGTH = 1e4  # m, each size of a shape

class _Spanned(Protocol):
    @property
    def span(self) -> Span: ...


_Clause = TypeVar("_Clause", bound=_Spanned)


class BodyValues:
    """The body's rules' state and their reading of values: each number, vector and clause checked once."""

    def __init__(self, d: Diagnostics, typer: Typer, symbols: Symbols,
                 settings: Mapping[str, m.Setting] | None = None) -> None:
        self.d = d
        self.typer = typer
        self.s = symbols
        self.settings = dict(settings or {})
        self.env = Env({n: (Scope.STATE, s.type) for n, s in self.settings.items()}, "in the body",
                       "constants and settings")
        self.work = 0  # operations of the conversions sampled so far
        self.typed: dict[int, tuple[ast.Expr, m.Expr]] = {}  # by id: each expression valued, typed

    def written(self, **clauses: ast.Expr | Sequence[ast.Expr] | None) -> m.Written:
        """The clauses given that read settings, each as written (typed), for the Model's
        `expressions`: a list of separate values (a shape's sizes, a joint's limits) as an array."""
        found: list[tuple[str, m.Expr]] = []
        for word, given in clauses.items():
            items = [] if given is None else [given] if isinstance(given, ast.Expr) else list(given)
            nodes = [node for e in items if (kept := self.typed.get(id(e))) is not None and kept[0] is e
                     for node in (kept[1],)]
            if not items or len(nodes) != len(items) or not any(next(m.variables(node), None) for node in nodes):
                continue
            if isinstance(given, ast.Expr):
                found.append((word, nodes[0]))
            else:
                found.append((word, m.ArrayValue(tuple(nodes), m.Array(Type.FLOAT, len(nodes)))))
        return tuple(found)

    # -- constants of the body ---------------------------------------------------------

    def value(self, expr: ast.Expr, what: str) -> m.Value | None:
        """The value of a body's expression: folded from constants, or computed from the
        settings it reads at their values (none of a bool or string: reported, E213); None once
        reported, here or where what it reads is declared."""
        errors = self.d.error_count
        node = self.typer.expr(expr, self.env)
        if self.d.error_count > errors or node.type is None:
            return None
        self.typed[id(expr)] = (expr, node)
        value = self.typer.constant(node)
        if value is not None:
            return value
        read = sorted({v.name for v in m.variables(node)})
        for name in read:
            setting = self.settings[name]
            scalar = setting.type.element if isinstance(setting.type, m.Array) else setting.type
            if scalar not in (Type.INT, Type.FLOAT):
                self.d.report("E213", expr.span, f"setting `{name}` is {describe(setting.type)}: {what} is a number",
                              labels=() if setting.span is None else (Label(setting.span, "declared here"),),
                              help="a body's sizes, places and masses may read number settings")
                return None
        if any(self.settings[name].default is None for name in read):
            return None  # a setting without a default, reported where it is declared (E213)
        from rdisc.semantics.evaluate import evaluate

        try:
            return evaluate(node, {name: self.settings[name].default for name in read})
        except (EvalError, ArithmeticError, ValueError) as err:
            given = ", ".join(f"`{n}` = {self.settings[n].default!r}" for n in read)
            self.d.report("E204", expr.span, f"{what} cannot be computed with {given}: {err}")
            return None

    def number(self, expr: ast.Expr, what: str) -> float | None:
        """A number as a finite float (`2 ** 1100` is an int no float holds)."""
        value = self.value(expr, what)
        if value is None:
            return None
        if type(value) not in (int, float):
            self.d.report("E204", expr.span, f"{what} must be a constant number")
            return None
        finite = _finite(value)  # type: ignore[arg-type]
        if finite is None:
            self.d.report("E204", expr.span, f"{what} must be a finite number")
        return finite

    def vector(self, expr: ast.Expr, what: str) -> m.Vector | None:
        """Three constant finite numbers written as an array: `[0, 0, 0.05]`."""
        values = self.numbers(expr, what)
        if values is None:
            return None
        if len(values) != 3:
            self.d.report("E602", expr.span, f"{what} is three numbers, `[x, y, z]`, not {len(values)}")
            return None
        return values[0], values[1], values[2]

    def numbers(self, expr: ast.Expr, what: str) -> tuple[float, ...] | None:
        value = self.value(expr, what)
        if value is None:  # reported
            return None
        items = value if isinstance(value, tuple) else None
        floats = [_finite(v) if type(v) in (int, float) else None for v in items or ()]
        finite = tuple(f for f in floats if f is not None)
        if items is None or len(finite) != len(floats):
            self.d.report("E602", expr.span, f"{what} must be constant finite numbers, written `[x, y, z]`")
            return None
        return finite

    def positive(self, expr: ast.Expr, what: str, code: str, zero: bool = False,
                 most: float = math.inf, unit: str = "") -> float | None:
        """A constant more than 0 (or 0 too), and at most `most` (in `unit`): what a simulator can integrate."""
        value = self.number(expr, what)
        if value is None:
            return None
        if value < 0 or (value == 0 and not zero):
            self.d.report(code, expr.span, f"{what} must be {'0 or more' if zero else 'more than 0'}, not {value:g}")
            return None
        if value > most:
            self.d.report(code, expr.span, f"{what} of {value:g} {unit} is more than a simulator can integrate",
                          help=f"at most {most:g} {unit}")
            return None
        return float(value)

    def once(self, items: Iterable[ast.BodyValue | ast.JointLimit | ast.JointMimic], key: str,
             owner: ast.Ident) -> ast.Expr | None:
        """The value of a clause given at most once; a repeat is reported where it is."""
        found = self.first([i for i in items if isinstance(i, ast.BodyValue) and i.key == key], key, owner)
        return found.value if found is not None else None

    def first(self, found: Sequence[_Clause], word: str, owner: ast.Ident) -> _Clause | None:
        """The first of the clauses `word` a declaration gives (a link's `spawn`, a joint's `limit`),
        each repeat reported where it is (E203)."""
        for extra in found[1:]:
            self.d.report("E203", extra.span, f"`{word}` is given twice in `{owner.text}`",
                          labels=(Label(found[0].span, "first given here"),))
        return found[0] if found else None


def reserved_name(name: str) -> bool:
    """A name SDF keeps for itself (`__...__` ones too, which RDIS names cannot be)."""
    return name == "world"


def joint_range(joint: m.Joint, quantity: m.Quantity) -> tuple[float | None, float | None, str]:
    """The range of a quantity the body allows, and what states it."""
    if quantity is m.Quantity.POSITION:
        return joint.lower, joint.upper, "limit"
    bound = joint.velocity if quantity is m.Quantity.VELOCITY else joint.effort
    return (None, None, "") if bound is None else (-bound, bound, quantity.value)


def size(expr: m.Expr) -> int:
    """The number of operations (nodes) of an expression."""
    count, pending = 0, [expr]
    while pending:
        count += 1
        pending.extend(m.operands(pending.pop()))
    return count


def sample(low: float, high: float) -> list[float]:
    """SAMPLES points from low to high, both included; weighted so that no step overflows when
    high - low is beyond the largest float."""
    return [low * (1 - i / (SAMPLES - 1)) + high * (i / (SAMPLES - 1)) for i in range(SAMPLES)]


def _shown(value: object) -> str:
    return abbreviate(repr(value))


def _close(a: float, b: float, step: float) -> bool:
    """Equal to one step (of an int), or to a relative 1e-9; exact for ints beyond a float's range."""
    difference = abs(a - b)
    if difference <= step:
        return True
    try:
        return difference <= 1e-9 * max(abs(a), abs(b), 1.0)
    except OverflowError:  # ints too large for a float that differ by more than a step
        return False


def principal_moments(t: tuple[float, float, float, float, float, float]) -> tuple[float, float, float]:
    """The eigenvalues of the symmetric inertia tensor (ixx, iyy, izz, ixy, ixz, iyz), by the
    closed form for a symmetric 3x3 matrix."""
    xx, yy, zz, xy, xz, yz = t
    off = xy * xy + xz * xz + yz * yz
    if off == 0:
        return xx, yy, zz
    q = (xx + yy + zz) / 3
    p = math.sqrt(((xx - q) ** 2 + (yy - q) ** 2 + (zz - q) ** 2 + 2 * off) / 6)
    b = [[(xx - q) / p, xy / p, xz / p], [xy / p, (yy - q) / p, yz / p], [xz / p, yz / p, (zz - q) / p]]
    det = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0])
           + b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]))
    phi = math.acos(max(-1.0, min(1.0, det / 2))) / 3
    one = q + 2 * p * math.cos(phi)
    three = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return one, 3 * q - one - three, three


def _finite(value: float) -> float | None:
    """`value` as a float, when it is a finite one."""
    try:
        number = float(value)
    except OverflowError:
        return None
    return number if math.isfinite(number) else None
