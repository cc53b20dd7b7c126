"""The body: links (shapes, inertials), joints and transmissions (the RDIS clauses their members
stand for, checked by the checker)."""

from __future__ import annotations

from rdisc.json_import.expressions import Expressions
from rdisc.json_import.reader import Members, present
from rdisc.json_import.values import JArray, JBool, JObject
from rdisc.syntax import ast

_LINK = ("name", "visuals", "collisions", "inertial", "spawn", "doc")
_SPAWN = ("floating", "xyz", "rpy")
_SHAPE = ("shape", "path", "size", "scale", "xyz", "rpy", "color")
_INERTIAL = ("mass", "centre", "inertia")
_JOINT = ("name", "type", "parent", "child", "xyz", "rpy", "axis", "limit", "velocity", "effort", "damping",
          "friction", "mimic", "doc")
_MIMIC = ("joint", "multiplier", "offset")
_TRANSMISSION = ("name", "joint", "commands", "measures", "actuator", "doc")
_ACTUATOR = ("name", "kind", "velocity", "acceleration", "effort", "gain", "damping", "limit", "doc")
_COMMAND = ("quantity", "primitive", "interface", "parameter", "index", "toDevice", "toJoint")
_MEASURE = ("quantity", "state", "index", "toDevice", "toJoint")


class Body(Expressions):
    """The reading of links, joints and transmissions."""

    def link(self, obj: JObject) -> ast.LinkDecl | None:
        m = self.members(obj, "a link", _LINK)
        name = self.name(obj, m, "a link")
        items: list[ast.ShapeUse | ast.BodyValue | ast.LinkSpawn | None] = []
        for role, key in (("visual", "visuals"), ("collision", "collisions")):
            shapes = [self.object(item, f"a {role} shape") for item in self.array(m.get(key), f"`{key}`")]
            items += [None if o is None else self.shape_use(o, role) for o in shapes]
        inertial = self.object(m.get("inertial"), "`inertial`")
        if inertial is not None:
            i = self.members(inertial, "`inertial`", _INERTIAL)
            items += [self.body_value(i, key, key) for key in _INERTIAL]
        spawn = self.object(m.get("spawn"), "`spawn`")
        if spawn is not None:
            s = self.members(spawn, "`spawn`", _SPAWN)
            floating = self.required(spawn, s, "floating", "`spawn`",
                                     lambda v, what: self.expect(v, JBool, what, "true or false"))
            at = self.expr(s["xyz"], "float") if "xyz" in s else None
            rpy = self.expr(s["rpy"], "float") if "rpy" in s else None
            kind = None if floating is None else ast.Ident("floating" if floating.value else "fixed", spawn.span)
            items.append(None if kind is None else ast.LinkSpawn(kind, at, rpy, spawn.span))
        if name is None:
            return None
        return ast.LinkDecl(name, present(items), obj.span, self.doc(m))

    def shape_use(self, obj: JObject, role: str) -> ast.ShapeUse | None:
        """`{"shape": "box", "size": [x, y, z]}` is `box(x, y, z)`; `{"shape": "mesh", "path": "f.stl",
        "scale": [1, 1, 1]}` is `mesh("f.stl", [1, 1, 1])`."""
        what = f"a {role} shape"
        s = self.members(obj, what, _SHAPE)
        kind = self.required(obj, s, "shape", what, self.ident)
        path = self.string(s.get("path"), "`path`")
        args: list[ast.Expr | None] = [] if path is None else [ast.StrLit(path.value, path.span)]
        args += [self.expr(v, "float") for v in self.array(s.get("size"), "`size`")]
        if "scale" in s:
            args.append(self.expr(s["scale"], "float"))
        at = self.expr(s["xyz"], "float") if "xyz" in s else None
        rpy = self.expr(s["rpy"], "float") if "rpy" in s else None
        color = self.expr(s["color"], "float") if "color" in s else None
        if kind is None:
            return None
        return ast.ShapeUse(role, ast.Shape(kind, present(args), obj.span), at, rpy, obj.span, color)

    def body_value(self, m: Members, key: str, word: str) -> ast.BodyValue | None:
        """The member `key`, when given, as the clause `word VALUE`."""
        value = self.expr(m[key], "float") if key in m else None
        return None if value is None else ast.BodyValue(word, value, m[key].span)

    def joint(self, obj: JObject) -> ast.JointDecl | None:
        m = self.members(obj, "a joint", _JOINT)
        name = self.name(obj, m, "a joint")
        kind = self.required(obj, m, "type", "a joint", self.ident)
        parent = self.required(obj, m, "parent", "a joint", self.ident)
        child = self.required(obj, m, "child", "a joint", self.ident)
        items: list[ast.BodyValue | ast.JointLimit | ast.JointMimic | None] = [
            self.body_value(m, "xyz", "at"), self.body_value(m, "rpy", "rpy"), self.body_value(m, "axis", "axis")]
        if "limit" in m:
            bounds = self.array(m["limit"], "a joint's limit")
            if len(bounds) == 2:
                low, high = self.expr(bounds[0], "float"), self.expr(bounds[1], "float")
                items.append(None if low is None or high is None else ast.JointLimit(low, high, m["limit"].span))
            elif isinstance(m["limit"], JArray):
                self.error(m["limit"].span, "a joint's limit is `[low, high]`")
        items += [self.body_value(m, key, key) for key in ("velocity", "effort", "damping", "friction")]
        mimic = self.object(m.get("mimic"), "`mimic`")
        if mimic is not None:
            follows = self.members(mimic, "`mimic`", _MIMIC)
            leader = self.required(mimic, follows, "joint", "`mimic`", self.ident)
            multiplier, offset = (self.expr(follows[key], "float") if key in follows else None
                                  for key in ("multiplier", "offset"))
            items.append(None if leader is None else ast.JointMimic(leader, multiplier, offset, mimic.span))
        if name is None or kind is None or parent is None or child is None:
            return None
        return ast.JointDecl(name, kind, parent, child, present(items), obj.span, self.doc(m))

    def transmission(self, obj: JObject) -> ast.TransmissionDecl | None:
        m = self.members(obj, "a transmission", _TRANSMISSION)
        name = self.name(obj, m, "a transmission")
        joint = self.required(obj, m, "joint", "a transmission", self.ident)
        bindings: list[ast.Binding | None] = []
        for role, key in (("command", "commands"), ("measure", "measures")):
            objects = [self.object(item, f"a {role}") for item in self.array(m.get(key), f"`{key}`")]
            bindings += [None if o is None else self.binding(o, role) for o in objects]
        actuator = self.ident(m["actuator"], "`actuator`") if "actuator" in m else None
        if name is None or joint is None or ("actuator" in m and actuator is None):
            return None
        return ast.TransmissionDecl(name, joint, present(bindings), obj.span, self.doc(m), actuator)

    def actuator(self, obj: JObject) -> ast.ActuatorDecl | None:
        """`{"name": "horn", "kind": "servo", "velocity": 4.8, ...}`: the clauses of `actuator horn: servo { }`."""
        m = self.members(obj, "an actuator", _ACTUATOR)
        name = self.name(obj, m, "an actuator")
        kind = self.required(obj, m, "kind", "an actuator", self.ident)
        items = [self.body_value(m, key, key) for key in _ACTUATOR[2:-2]]
        limit = self.ident(m["limit"], "`limit`") if "limit" in m else None  # "shape" or "refuse": a word
        items.append(None if limit is None else ast.BodyValue("limit", ast.Ref(limit.text, limit.span), limit.span))
        if name is None or kind is None:
            return None
        return ast.ActuatorDecl(name, kind, present(items), obj.span, self.doc(m))

    def binding(self, obj: JObject, role: str) -> ast.Binding | None:
        """A command names its `primitive` or its `interface` and the `parameter`; a measure its `state`.
        `toDevice` and `toJoint` are the conversions `raw = ...` and `QUANTITY = ...`."""
        what = f"a {role}"
        b = self.members(obj, what, _COMMAND if role == "command" else _MEASURE)
        quantity = self.required(obj, b, "quantity", what, self.ident)
        member = None
        if role == "command":
            kinds = [k for k in ("primitive", "interface") if k in b]
            if len(kinds) != 1:
                self.error(self.opening(obj), "a command names one `primitive` or one `interface`")
                return None
            target = self.ident(b[kinds[0]], f"`{kinds[0]}`")
            other = "interface" if kinds[0] == "primitive" else "primitive"
            known = self.primitive_types if other == "primitive" else self.interface_types
            mine = self.interface_types if other == "primitive" else self.primitive_types
            if target is not None and target.text in known and target.text not in mine:
                self.error(b[kinds[0]].span, f"`{target.text}` is {'an' if other == 'interface' else 'a'} {other}",
                           help=f"write `\"{other}\": \"{target.text}\"`")
                return None
            member = self.required(obj, b, "parameter", what, self.ident)
        else:
            target = self.required(obj, b, "state", what, self.ident)
        index = self.expr(b["index"], "int") if "index" in b else None
        to_device = self.required(obj, b, "toDevice", what, lambda v, _: self.expr(v, None))
        to_joint = self.required(obj, b, "toJoint", what, lambda v, _: self.expr(v, None))
        if quantity is None or target is None or to_device is None or to_joint is None \
                or (role == "command" and member is None) or ("index" in b and index is None):
            return None
        conversions = (ast.Assign(ast.Ident("raw", to_device.span), to_device, b["toDevice"].span),
                       ast.Assign(ast.Ident(quantity.text, to_joint.span), to_joint, b["toJoint"].span))
        return ast.Binding(role, quantity, target, member, index, conversions, obj.span)
