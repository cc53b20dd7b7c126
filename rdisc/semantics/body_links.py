"""The body's links (rdisc.semantics.body): their shapes, meshes, colours, poses, spawn and inertia."""

from __future__ import annotations

import dataclasses
import os

from rdisc.diagnostics import Label
from rdisc.semantics import model as m
from rdisc.semantics.body_values import (
    MAX_INERTIA,
    MAX_LENGTH,
    MAX_MASS,
    SHAPES,
    BodyValues,
    principal_moments,
)
from rdisc.semantics.meshes import located
from rdisc.semantics.resolve import suggest
from rdisc.syntax import ast


class BodyLinks(BodyValues):
    """The rules of `link` declarations."""

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
