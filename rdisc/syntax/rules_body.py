"""The Builder's methods for the body's rules: links, shapes, joints, transmissions and actuators
(rdisc.syntax.build.Rules)."""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.syntax import ast

if TYPE_CHECKING:
    from typing import Any

    from lark.tree import Meta

    from rdisc.syntax.builder import Builder


class BodyRules:
    """The body's nodes, made of their children."""

    b: Builder

    def link_decl(self, meta: Meta, c: list[Any]) -> ast.LinkDecl:
        return ast.LinkDecl(self.b.ident(c[0]), tuple(c[1:]), self.b.span(meta), self.b.doc(meta))

    def visual(self, meta: Meta, c: list[Any]) -> ast.ShapeUse:
        at, rpy = c[1]
        return ast.ShapeUse("visual", c[0], at, rpy, self.b.span(meta), c[2])

    def collision(self, meta: Meta, c: list[Any]) -> ast.ShapeUse:
        at, rpy = c[1]
        return ast.ShapeUse("collision", c[0], at, rpy, self.b.span(meta))

    def spawn(self, meta: Meta, c: list[Any]) -> ast.LinkSpawn:
        at, rpy = c[1]
        return ast.LinkSpawn(self.b.ident(c[0]), at, rpy, self.b.span(meta))

    def shape(self, meta: Meta, c: list[Any]) -> ast.Shape:
        return ast.Shape(self.b.ident(c[0]), c[1] or (), self.b.span(meta))

    def pose(self, meta: Meta, c: list[Any]) -> tuple[ast.Expr | None, ast.Expr | None]:
        return c[0], c[1]

    def joint_decl(self, meta: Meta, c: list[Any]) -> ast.JointDecl:
        name, kind, parent, child, *items = c
        return ast.JointDecl(self.b.ident(name), self.b.ident(kind), self.b.ident(parent), self.b.ident(child),
                             tuple(items), self.b.span(meta), self.b.doc(meta))

    def mass(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("mass", c[0], self.b.span(meta))

    def centre(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("centre", c[0], self.b.span(meta))

    def inertia(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("inertia", c[0], self.b.span(meta))

    def joint_at(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("at", c[0], self.b.span(meta))

    def joint_rpy(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("rpy", c[0], self.b.span(meta))

    def axis(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("axis", c[0], self.b.span(meta))

    def max_velocity(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("velocity", c[0], self.b.span(meta))

    def max_effort(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("effort", c[0], self.b.span(meta))

    def damping(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("damping", c[0], self.b.span(meta))

    def friction(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue("friction", c[0], self.b.span(meta))

    def limit(self, meta: Meta, c: list[Any]) -> ast.JointLimit:
        return ast.JointLimit(c[0], c[1], self.b.span(meta))

    def mimic(self, meta: Meta, c: list[Any]) -> ast.JointMimic:
        return ast.JointMimic(self.b.ident(c[0]), c[1], c[2], self.b.span(meta))

    def transmission_decl(self, meta: Meta, c: list[Any]) -> ast.TransmissionDecl:
        actuator = None if c[2] is None else self.b.ident(c[2])
        return ast.TransmissionDecl(self.b.ident(c[0]), self.b.ident(c[1]), tuple(c[3:]), self.b.span(meta),
                                    self.b.doc(meta), actuator)

    def actuator_decl(self, meta: Meta, c: list[Any]) -> ast.ActuatorDecl:
        return ast.ActuatorDecl(self.b.ident(c[0]), self.b.ident(c[1]), tuple(c[2:]), self.b.span(meta),
                                self.b.doc(meta))

    def actuator_item(self, meta: Meta, c: list[Any]) -> ast.BodyValue:
        return ast.BodyValue(str(c[0]), c[1], self.b.span(meta))

    def command(self, meta: Meta, c: list[Any]) -> ast.Binding:
        quantity, target, member, index, *conversions = c
        return ast.Binding("command", self.b.ident(quantity), self.b.ident(target), self.b.ident(member), index,
                           tuple(conversions), self.b.span(meta))

    def measure(self, meta: Meta, c: list[Any]) -> ast.Binding:
        quantity, target, index, *conversions = c
        return ast.Binding("measure", self.b.ident(quantity), self.b.ident(target), None, index,
                           tuple(conversions), self.b.span(meta))
