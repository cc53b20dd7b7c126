"""The body's rules (thesis ch. 6): links, joints and transmissions, checked into the Model.

Robot formats check a tree of links; what none of them checks is that the body and the
device agree. Here a joint's limits, mapped through its transmission's conversion, must
fall in the range the device accepts, and the two conversions must undo each other, so a
URDF, a simulation and the serial device cannot silently disagree.
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections import deque
from collections.abc import Iterable, Mapping, Sequence
from typing import Protocol, TypeVar

from rdisc.diagnostics import Diagnostics, Label, abbreviate
from rdisc.engine.operations import EvalError
from rdisc.semantics import model as m
from rdisc.semantics.meshes import located
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.resolve import Symbols, suggest
from rdisc.semantics.types import Env, Typer, describe
from rdisc.semantics.units import CARRIERS, UNITS, carries, dimension_of
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

class BodyRules:
    """Checks the body's declarations. Its numbers are constants, or read the description's
    `settings` (a wheel base given when connecting): each has its default, or the value the
    description is compiled with (`compile_path(..., settings=...)`, `--set` of the verbs that
    write or simulate the body)."""

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

    # -- links ---------------------------------------------------------------------------

    def link(self, decl: ast.LinkDecl) -> m.Link:
        uses = [i for i in decl.items if isinstance(i, ast.ShapeUse)]
        visuals = tuple(s for s in (self.shape(u) for u in uses if u.role == "visual") if s is not None)
        collisions = tuple(s for s in (self.shape(u) for u in uses if u.role == "collision") if s is not None)
        return m.Link(decl.name.text, visuals, collisions, self.inertial(decl), decl.doc, decl.span, self.spawn(decl))

    def spawn(self, decl: ast.LinkDecl) -> m.Spawn | None:
        """`spawn floating|fixed at XYZ rpy RPY`, given once (that it is the root's: `spawned`)."""
        given = self.first([i for i in decl.items if isinstance(i, ast.LinkSpawn)], "spawn", decl.name)
        if given is None:
            return None
        kind = given.kind.text
        if kind not in ("floating", "fixed"):
            self.d.report("E601", given.kind.span, f"a link is spawned `floating` or `fixed`, not `{kind}`",
                          help=suggest(kind, ("floating", "fixed")) or "`floating` for a mobile base, `fixed` for an "
                          "arm bolted to the world")
            return None
        pose = self.pose(given.at, given.rpy)
        return None if pose is None else m.Spawn(kind == "floating", pose, self.written(at=given.at, rpy=given.rpy))

    def spawned(self, links: dict[str, m.Link], joints: dict[str, m.Joint]) -> None:
        """Only the root link meets the world: every other hangs from its joint."""
        children = {j.child: j for j in joints.values()}
        for link in links.values():
            welded = m.world_joint(link.name)
            if link.spawn is not None and not link.spawn.floating and welded in self.s.joints:
                self.d.report("E607", self.s.joints[welded].name.span, f"joint `{welded}` takes the name of the "
                              f"joint that fixes `{link.name}` to the world in the URDF and SDF",
                              help=f"name it otherwise, e.g. `{welded}_2`")
        for name, decl in self.s.links.items():
            spawn = next((i for i in decl.items if isinstance(i, ast.LinkSpawn)), None)
            joint = children.get(name)
            if spawn is not None and joint is not None:
                self.d.report("E601", spawn.span, f"link `{name}` hangs from joint `{joint.name}`: only the root "
                              "link is spawned", labels=(Label(self.s.joints[joint.name].child.span,
                                                               f"joint `{joint.name}`"),),
                              help="give `spawn` to the link no joint moves")

    def shape(self, use: ast.ShapeUse) -> m.Shape | None:
        shape = self.sized_shape(use)
        if shape is None or use.color is None:
            return shape
        color = self.color(use.color)
        return None if color is None else dataclasses.replace(
            shape, color=color, expressions=shape.expressions + self.written(color=use.color))

    def color(self, expr: ast.Expr) -> tuple[float, float, float, float] | None:
        """`[r, g, b]` or `[r, g, b, a]`, each 0 to 1 (alpha 1 when not given), as URDF, SDF and
        MuJoCo write colours."""
        values = self.numbers(expr, "a colour")
        if values is None:
            return None
        if len(values) not in (3, 4) or not all(0 <= v <= 1 for v in values):
            self.d.report("E602", expr.span, "a colour is `[red, green, blue]` or `[red, green, blue, alpha]`, "
                          "each from 0 to 1", help="`color [0.8, 0.1, 0.1]` is red; `[0, 0, 1, 0.5]` a see-through blue")
            return None
        red, green, blue, *alpha = values
        return (red, green, blue, alpha[0] if alpha else 1.0)

    def sized_shape(self, use: ast.ShapeUse) -> m.Shape | None:
        origin = self.pose(use.at, use.rpy)
        kind_name = use.shape.kind.text
        kind = next((k for k in m.ShapeKind if k.value == kind_name), None)
        if kind is None:
            self.d.report("E602", use.shape.kind.span, f"unknown shape `{kind_name}`",
                          help=suggest(kind_name, [k.value for k in m.ShapeKind])
                          or "shapes are box(x, y, z), cylinder(radius, length), sphere(radius), mesh(\"file\")")
            return None
        args = use.shape.args
        if kind is m.ShapeKind.MESH:
            return self.mesh(use, origin)
        names = SHAPES[kind]
        if len(args) != len(names):
            self.d.report("E602", use.shape.span, f"{kind_name} takes {len(names)} size"
                          f"{'s' if len(names) > 1 else ''} ({', '.join(names)}), not {len(args)}",
                          help=f"write `{kind_name}({', '.join(names)})` in metres")
            return None
        size = [self.positive(a, f"a {kind_name}'s {n}", "E602", most=MAX_LENGTH, unit="m")
                for a, n in zip(args, names, strict=True)]
        sizes = tuple(v for v in size if v is not None)
        if origin is None or len(sizes) != len(size):
            return None
        return m.Shape(kind, sizes, origin, None, use.span, expressions=self.written(size=args, at=use.at, rpy=use.rpy))

    def mesh(self, use: ast.ShapeUse, origin: m.Pose | None) -> m.Shape | None:
        """`mesh("file.stl")` or `mesh("file.stl", scale)`, the scale one number or three."""
        args = use.shape.args
        path = args[0] if args else None
        if not 1 <= len(args) <= 2 or not isinstance(path, ast.StrLit) or not path.value:
            self.d.report("E602", use.shape.span, "a mesh is `mesh(\"file\")` or `mesh(\"file\", scale)`",
                          help="the file is a path as the tools reading the output will see it")
            return None
        if not path.value.isprintable():
            self.d.report("E602", path.span, f"a mesh's path has a character no URDF or SDF file can carry: "
                          f"{next(c for c in path.value if not c.isprintable())!r}",
                          help="a mesh's path is printable text, as the tools reading the output will see it")
            return None
        scale: tuple[float, ...] | None = (1.0, 1.0, 1.0)
        if len(args) == 2:
            if isinstance(args[1], ast.ArrayLit):
                scale = self.vector(args[1], "a mesh's scale")
            else:
                one = self.positive(args[1], "a mesh's scale", "E602")
                scale = None if one is None else (one, one, one)
        if scale is None or origin is None:
            return None
        if not all(v > 0 for v in scale):
            self.d.report("E602", args[1].span, "a mesh's scale must be more than 0")
            return None
        described = path.span.path
        if os.path.isfile(described):  # a description read from a file: its meshes are beside it
            found, why = located(path.value, described)
            if found is None or not os.path.isfile(found):
                self.d.report("E614", path.span, f"mesh `{path.value}` is not found: {why}",
                              help="a relative path starts at the description's folder; `package://NAME/PATH` at "
                              "the folder NAME that holds the description, or NAME in ROS_PACKAGE_PATH")
                return None
        return m.Shape(m.ShapeKind.MESH, scale, origin, path.value, use.span, expressions=self.written(
            scale=args[1] if len(args) == 2 else None, at=use.at, rpy=use.rpy))

    def pose(self, at: ast.Expr | None, rpy: ast.Expr | None) -> m.Pose | None:
        xyz = m.ORIGIN if at is None else self.vector(at, "a position")
        angles = m.ORIGIN if rpy is None else self.vector(rpy, "roll, pitch and yaw")
        return None if xyz is None or angles is None else m.Pose(xyz, angles)

    def inertial(self, decl: ast.LinkDecl) -> m.Inertial | None:
        """Mass, centre and inertia: a link has all (the centre defaults to its origin) or none."""
        values = [i for i in decl.items if isinstance(i, ast.BodyValue)]
        mass_expr = self.once(values, "mass", decl.name)
        centre_expr = self.once(values, "centre", decl.name)
        inertia_expr = self.once(values, "inertia", decl.name)
        if mass_expr is None or inertia_expr is None:
            given = mass_expr or inertia_expr
            if given is None:
                if centre_expr is not None:
                    self.d.report("E604", centre_expr.span, f"link `{decl.name.text}` has a centre of mass but no "
                                  "mass", help="give its `mass` (kg) and `inertia` too")
                return None
            missing = "inertia" if inertia_expr is None else "mass"
            self.d.report("E604", given.span, f"link `{decl.name.text}` has no {missing}",
                          help="a link's inertial is its `mass` (kg) and `inertia` (kg m²) together")
            return None
        mass = self.positive(mass_expr, "a link's mass", "E604", most=MAX_MASS, unit="kg")
        centre = m.ORIGIN if centre_expr is None else self.vector(centre_expr, "a centre of mass")
        inertia = self.inertia(inertia_expr)
        if mass is None or centre is None or inertia is None:
            return None
        return m.Inertial(mass, centre, inertia, self.written(mass=mass_expr, centre=centre_expr, inertia=inertia_expr))

    def inertia(self, expr: ast.Expr) -> tuple[float, float, float, float, float, float] | None:
        """`[ixx, iyy, izz]` or `[ixx, iyy, izz, ixy, ixz, iyz]`: a physical tensor is positive
        definite and its principal moments meet the triangle inequality."""
        values = self.numbers(expr, "an inertia")
        if values is None:
            return None
        if len(values) not in (3, 6):
            self.d.report("E604", expr.span, f"an inertia is [ixx, iyy, izz] or [ixx, iyy, izz, ixy, ixz, iyz], "
                          f"not {len(values)} numbers")
            return None
        if max(abs(v) for v in values) > MAX_INERTIA:
            self.d.report("E604", expr.span, f"an inertia of {max(abs(v) for v in values):g} kg m² is more than a "
                          "simulator can integrate", help=f"each element at most {MAX_INERTIA:g} kg m²")
            return None
        full = values + (0.0, 0.0, 0.0) if len(values) == 3 else values
        tensor = (full[0], full[1], full[2], full[3], full[4], full[5])
        moments = principal_moments(tensor)
        if min(moments) <= 0:
            self.d.report("E604", expr.span, "the inertia is not positive definite: its principal moments are "
                          + ", ".join(f"{v:.6g}" for v in moments), help="every principal moment is more than 0")
            return None
        a, b, c = sorted(moments)
        if a + b < c * (1 - 1e-9):
            self.d.report("E604", expr.span, f"the inertia breaks the triangle inequality: its principal moments "
                          f"{a:.6g} + {b:.6g} < {c:.6g}",
                          help="no body has one moment larger than the other two together")
            return None
        return tensor

    # -- joints and the tree ---------------------------------------------------------------

    def joint(self, decl: ast.JointDecl) -> m.Joint | None:
        kind = _KINDS.get(decl.kind.text)
        if kind is None:
            self.d.report("E603", decl.kind.span, f"unknown joint kind `{decl.kind.text}`",
                          help=suggest(decl.kind.text, _KINDS) or "joints are " + ", ".join(_KINDS))
            return None
        items = decl.items
        at, rpy = self.once(items, "at", decl.name), self.once(items, "rpy", decl.name)
        origin = self.pose(at, rpy)
        limit = self.first([i for i in items if isinstance(i, ast.JointLimit)], "limit", decl.name)
        moving = {"axis", "velocity", "effort", "damping", "friction"}
        if kind is m.JointKind.FIXED:
            for item in items:
                if not isinstance(item, ast.BodyValue) or item.key in moving:
                    key = item.key if isinstance(item, ast.BodyValue) else \
                        "limit" if isinstance(item, ast.JointLimit) else "mimic"
                    self.d.report("E603", item.span, f"a fixed joint does not move: it has no `{key}`")
            return None if origin is None else m.Joint(decl.name.text, kind, decl.parent.text, decl.child.text,
                                                       origin, doc=decl.doc, span=decl.span,
                                                       expressions=self.written(at=at, rpy=rpy))
        axis = (1.0, 0.0, 0.0)
        axis_expr = self.once(items, "axis", decl.name)
        if axis_expr is not None:
            given = self.vector(axis_expr, "an axis")
            if given is not None and not any(given):
                self.d.report("E603", axis_expr.span, "an axis must not be zero",
                              help="the unit vector the joint turns about or slides along: `axis [0, 0, 1]`")
                given = None
            axis = given or axis
        lower = upper = None
        if limit is not None:
            if kind not in _LIMITED:
                self.d.report("E603", limit.span, f"a {kind.value} joint has no position limit",
                              help="a joint that turns within limits is `revolute`" if kind is m.JointKind.CONTINUOUS
                              else None)
            else:
                lower, upper = self.number(limit.low, "a joint's limit"), self.number(limit.high, "a joint's limit")
                if lower is not None and upper is not None and not lower < upper:
                    self.d.report("E603", limit.span, f"a joint's limits are ordered, low < high, not "
                                  f"{lower:g}..{upper:g}")
                    lower = upper = None
        elif kind in _LIMITED:
            self.d.report("E603", decl.name.span, f"{kind.value} joint `{decl.name.text}` has no `limit LOW..HIGH`",
                          help="a continuous joint turns without limits" if kind is m.JointKind.REVOLUTE
                          else "the range it slides over, in metres")
        bounds: dict[str, float | None] = {}
        clauses: dict[str, ast.Expr | None] = {}
        for key, zero in (("velocity", False), ("effort", False), ("damping", True), ("friction", True)):
            expr = clauses[key] = self.once(items, key, decl.name)
            bounds[key] = None if expr is None else self.positive(expr, f"a joint's {key}", "E603", zero)
            if expr is None and key in ("velocity", "effort") and kind in _LIMITED:
                self.d.report("E603", decl.name.span, f"{kind.value} joint `{decl.name.text}` has no `{key}`",
                              help="URDF needs a moving joint's largest velocity and effort")
        mimic = self.mimic(decl)
        if origin is None or isinstance(mimic, bool):
            return None
        follows = next((i for i in items if isinstance(i, ast.JointMimic)), None) if mimic else None
        written = self.written(at=at, rpy=rpy, axis=axis_expr, limit=None if limit is None or lower is None
                               else (limit.low, limit.high), **clauses,
                               multiplier=None if follows is None else follows.multiplier,
                               offset=None if follows is None else follows.offset)
        return m.Joint(decl.name.text, kind, decl.parent.text, decl.child.text, origin, axis, lower, upper,
                       bounds["velocity"], bounds["effort"], bounds["damping"] or 0.0, bounds["friction"] or 0.0,
                       decl.doc, decl.span, mimic, written)

    def mimic(self, decl: ast.JointDecl) -> m.Mimic | None | bool:  # False: refused
        """`mimic JOINT multiplier M offset O` (1 and 0 when left out): None without one, False when
        refused (reported). The joint it names is checked with the tree (`mimics`)."""
        given = self.first([i for i in decl.items if isinstance(i, ast.JointMimic)], "mimic", decl.name)
        if given is None:
            return None
        multiplier = 1.0 if given.multiplier is None else self.number(given.multiplier, "a mimic's multiplier")
        offset = 0.0 if given.offset is None else self.number(given.offset, "a mimic's offset")
        if multiplier is None or offset is None:
            return False
        if multiplier == 0:
            self.d.report("E603", given.multiplier.span if given.multiplier else given.span,
                          "a mimic's multiplier is not 0", help="a joint that does not follow is a `fixed` one")
            return False
        return m.Mimic(given.joint.text, multiplier, offset)

    def mimics(self, joints: dict[str, m.Joint]) -> None:
        """Each mimic follows a moving joint of the body that is not itself a mimic: URDF's tools
        and MuJoCo's equalities follow one leader, never a chain or a loop."""
        for joint in joints.values():
            if joint.mimic is None:
                continue
            span = next(i.joint.span for i in self.s.joints[joint.name].items if isinstance(i, ast.JointMimic))
            leader = joints.get(joint.mimic.joint)
            if joint.mimic.joint == joint.name:
                self.d.report("E603", span, f"joint `{joint.name}` cannot mimic itself")
            elif leader is None:
                continue  # unknown (E102) or refused: reported where it is
            elif not leader.moves():
                self.d.report("E603", span, f"joint `{leader.name}` is fixed: there is nothing to mimic")
            elif leader.mimic is not None:
                self.d.report("E603", span, f"joint `{leader.name}` mimics `{leader.mimic.joint}` itself",
                              help=f"mimic `{leader.mimic.joint}` (with the multipliers multiplied)")

    def portable_names(self) -> None:
        """Names every model format can carry as written, so URDF, SDF, MJCF, ros2_control and a
        JointState name a joint alike: SDF gives links and joints one namespace, where a joint named
        like a link is refused (`ign sdf -k`), and reserves `world`."""
        for kind, decls in (("link", self.s.links), ("joint", self.s.joints)):
            for name, decl in decls.items():
                if reserved_name(name):
                    self.d.report("E607", decl.name.span, f"`{name}` is reserved by SDF: a {kind} cannot take it",
                                  help=f"name the {kind} `{name}_{kind}`")
        for name, decl in self.s.joints.items():
            link = self.s.links.get(name)
            if link is not None and not reserved_name(name):
                self.d.report("E607", decl.name.span, f"joint `{name}` is named like a link",
                              labels=(Label(link.name.span, f"link `{name}`"),),
                              help=f"SDF and Gazebo give links and joints one namespace: name the joint "
                              f"`{name}_joint`, or the link `{name}_link`")

    def tree(self, links: dict[str, m.Link], joints: dict[str, m.Joint]) -> dict[str, m.Joint]:
        """One tree with one root: every link moved by at most one joint, reachable from the root,
        no cycle. The joints come back parents first. A link is reported detached only when every
        joint was understood: a joint refused or naming an unknown link may be the one missing."""
        decls = self.s.joints
        moved_by: dict[str, m.Joint] = {}
        for joint in joints.values():
            decl = decls[joint.name]
            if joint.parent == joint.child:
                self.d.report("E601", decl.child.span, f"joint `{joint.name}` joins link `{joint.child}` to itself")
                continue
            first = moved_by.get(joint.child)
            if first is not None:
                self.d.report("E601", decl.child.span, f"link `{joint.child}` is the child of two joints",
                              labels=(Label(decls[first.name].child.span, f"also of joint `{first.name}`"),),
                              help="a link hangs from one parent; join the other with a link of its own")
                continue
            moved_by[joint.child] = joint
        if not links:
            return {}
        roots = [name for name in links if name not in moved_by]
        if not roots:
            name = next(iter(links))
            self.d.report("E601", self.s.links[name].name.span, "the links form a cycle with no root",
                          help="one link, the base, is the child of no joint")
            return {}
        complete = len(joints) == len(decls) and all(j.parent in links and j.child in links for j in joints.values())
        for extra in roots[1:] if complete else ():
            self.d.report("E601", self.s.links[extra].name.span, f"link `{extra}` is not joined to the tree of "
                          f"`{roots[0]}`", labels=(Label(self.s.links[roots[0]].name.span, "the root"),),
                          help="join it with a joint (`fixed` if it does not move): a robot is one tree")
        children: dict[str, list[m.Joint]] = {}
        for joint in moved_by.values():
            children.setdefault(joint.parent, []).append(joint)
        order: dict[str, m.Joint] = {}
        reached: set[str] = set()
        for root in roots:  # the root's tree first: its joints are the body's; then the detached trees
            frontier = deque([root])
            while frontier:
                for joint in children.get(frontier.popleft(), ()):
                    if root == roots[0]:
                        order[joint.name] = joint
                    reached.add(joint.child)
                    frontier.append(joint.child)
        self.cycles({link: joint for link, joint in moved_by.items() if link not in reached and link in links},
                    roots[0])
        return order

    def carried(self, links: dict[str, m.Link], joints: dict[str, m.Joint]) -> None:
        """Every link a moving joint carries has a mass and an inertia: libsdformat gives a link
        without them 1 kg, and `ign sdf -p` drops it, so the simulated body is not this one."""
        for joint in joints.values():
            link = links.get(joint.child)
            if not joint.moves() or link is None or link.inertial is not None:
                continue
            decl = self.s.links[link.name]
            if any(isinstance(i, ast.BodyValue) and i.key in ("mass", "inertia") for i in decl.items):
                continue  # given but refused: reported where it is
            self.d.report("E611", decl.name.span, f"link `{link.name}` is moved by joint `{joint.name}` but has no "
                          "mass and inertia", labels=(Label(self.s.joints[joint.name].child.span, "moved here"),),
                          help="give it `mass` (kg) and `inertia` (kg m²): a simulator needs them to move it, "
                          "and libsdformat silently gives a link without them 1 kg")

    def cycles(self, unreached: dict[str, m.Joint], root: str) -> None:
        """Report each cycle among links no root reaches, once, at its first joint declared: each such
        link hangs from its parent, so following parents ends on a cycle or on an unknown link."""
        state: dict[str, int] = {}  # 1: on the path being followed, 2: done
        declared = {name: i for i, name in enumerate(self.s.joints)}
        for start in unreached:
            path: list[str] = []
            link: str | None = start
            while link is not None and link in unreached and link not in state:
                state[link] = 1
                path.append(link)
                link = unreached[link].parent
            if link is not None and state.get(link) == 1:
                ring = path[path.index(link):]
                names = [unreached[x].name for x in ring]
                first = min(names, key=declared.__getitem__)
                self.d.report("E601", self.s.joints[first].name.span,
                              f"joint `{first}` closes a cycle: links " + ", ".join(f"`{x}`" for x in ring)
                              + f" hang from each other, not from the root `{root}`",
                              help="a robot is one tree: every link hangs from the root through one joint")
            for x in path:
                state[x] = 2

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
