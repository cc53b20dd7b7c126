"""The description as a whole: `read` (JSON text -> an AST module), its top-level members in an
order where every type a default needs is known, the robot, constants, tables, enums, settings,
state variables and connections (defaults as in thesis Appendix A)."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from functools import partial
from typing import Any, TypeVar

from rdisc.diagnostics import Diagnostics
from rdisc.json_import.body import Body
from rdisc.json_import.interfaces import Interfaces
from rdisc.json_import.primitives import Primitives
from rdisc.json_import.reader import NAME, Members, present, type_text
from rdisc.json_import.values import JObject, JString, JValue, kind_of, read_json
from rdisc.syntax import ast

Declared = TypeVar("Declared", ast.ConstDecl, ast.EnumDecl)


def read(path: str, text: str, diagnostics: Diagnostics) -> ast.Module | None:
    """The declarations of a JSON description; None if it is not a JSON object."""
    root = read_json(path, text, diagnostics)
    if root is None:
        return None
    if not isinstance(root, JObject):
        diagnostics.report("E008", root.span, f"a description is a JSON object, found {kind_of(root)}")
        return None
    return Importer(path, diagnostics).module(root)


_TOP = (
    "name", "author", "description", "version", "doc", "constants", "enums", "tables", "constantDocs", "enumDocs",
    "settings",
    "stateVariables", "sensors", "connections", "frames", "primitives", "interfaces", "domainAdapters", "domainInterfaces", "domainOutputs",
    "links", "joints", "transmissions", "actuators",
)  # fmt: skip
_SECTIONS = {  # list member: (its elements in words, the RDIS keyword declaring one)
    "settings": ("a setting", "setting"),
    "stateVariables": ("a state variable", "state"),
    "sensors": ("a sensor", "sensor"),
    "spp": ("a connection", "connection"),
    "tcp": ("a connection", "connection"),
    "frames": ("a frame", "frame"),
    "primitives": ("a primitive", "primitive"),
    "interfaces": ("an interface", "interface"),
    "domainAdapters": ("an adapter", "adapter"),
    "domainInterfaces": ("a domain interface", "input"),
    "domainOutputs": ("a domain output", "output"),
    "links": ("a link", "link"),
    "joints": ("a joint", "joint"),
    "transmissions": ("a transmission", "transmission"),
    "actuators": ("an actuator", "actuator"),
}
_STATE = ("name", "type", "value", "noise", "doc")
_SENSOR = ("name", "type", "primitive", "cache", "noise", "doc")
_SETTING = ("name", "type", "range", "value", "doc")
THREADINGS = ("singleThreading", "dualThreading", "multipleThreading")  # the threading models, one a connection
_CONNECTION = (
    "name", "baud", "dataBits", "parity", "stopBits", *THREADINGS, "startup", "terminate", "keepalive",
    "terminator", "address", "doc",
)  # fmt: skip
DEFAULT_BAUD = 9600  # thesis Appendix A; written out, so the .rdis says what the robot gets
DEFAULT_FREQUENCY_HZ = 10


class Importer(Primitives, Interfaces, Body):
    """Every kind of element, read in the order of the document."""

    def module(self, root: JObject) -> ast.Module:
        top = self.members(root, "the description", _TOP)
        robot = self.robot(root, top)
        constants = self.documented(self.constants(top.get("constants")) + self.tables(top.get("tables")),
                                    top.get("constantDocs"), "`constantDocs`",
                                    _keys(top.get("constants")) | _keys(top.get("tables")))
        enums = self.documented(self.enums(top.get("enums")), top.get("enumDocs"), "`enumDocs`",
                                _keys(top.get("enums")))
        frames = self.each(top, "frames", self.frame)
        settings = self.each(top, "settings", self.setting)
        states = self.each(top, "stateVariables", self.state)
        sensors = self.each(top, "sensors", self.sensor)
        primitives = self.each(top, "primitives", self.primitive)
        interfaces = self.each(top, "interfaces", self.interface)
        connections = self.connections(top.get("connections"))
        adapters = self.each(top, "domainAdapters", self.adapter)
        inputs = self.each(top, "domainInterfaces", self.input)
        outputs = self.each(top, "domainOutputs", self.output)
        links = self.each(top, "links", self.link)
        joints = self.each(top, "joints", self.joint)
        transmissions = self.each(top, "transmissions", self.transmission)
        actuators = self.each(top, "actuators", self.actuator)
        decls: list[ast.Decl] = [] if robot is None else [robot]
        decls += [
            *constants,
            *enums,
            *settings,
            *states,
            *sensors,
            *connections,
            *frames,
            *primitives,
            *interfaces,
            *adapters,
            *self.made_adapters,
            *inputs,
            *outputs,
            *links,
            *joints,
            *transmissions,
            *actuators,
        ]
        return ast.Module(self.path, tuple(decls), tuple(self.damaged))

    def each(self, top: Members, key: str, build: Callable[[JObject], Any]) -> list[Any]:
        """The elements of a list member. An element with an error is left out, and
        its name kept as damaged, so that references to it are not reported again."""
        what, keyword = _SECTIONS[key]
        built = []
        for item in self.array(top.get(key), f"`{key}`"):
            obj = self.object(item, what)
            if obj is None:
                continue
            errors = self.d.error_count
            element = build(obj)
            if element is not None and self.d.error_count == errors:
                built.append(element)
                continue
            name = next((v for k, v in obj.members if k.value == "name"), None)
            if isinstance(name, JString) and NAME.fullmatch(name.value):
                self.damaged.append(ast.Damaged(keyword, ast.Ident(name.value, self.inner(name))))
        return built

    def robot(self, root: JObject, top: Members) -> ast.RobotDecl | None:
        name = self.name(root, top, "the description")
        attrs = []
        for key in ("author", "description", "version"):
            s = self.string(top.get(key), f"`{key}`")
            if s is not None:
                attrs.append(ast.RobotAttr(key, s.value, s.span))
        doc = self.doc(top)
        return None if name is None else ast.RobotDecl(name, tuple(attrs), root.span, doc)

    def tables(self, value: JValue | None) -> list[ast.ConstDecl]:
        """`tables`: each a list of `[key, value]` pairs."""
        obj = self.object(value, "`tables`") if value is not None else None
        built = []
        for key, item in obj.members if obj else ():
            name = self.ident(key, "a table")
            entries = []
            for pair in self.array(item, "a table"):
                both = self.array(pair, "a table entry")
                if len(both) != 2:
                    self.error(pair.span, "a table entry is `[key, value]`")
                    continue
                k, v = self.expr(both[0], None), self.expr(both[1], None)
                if k is not None and v is not None:
                    entries.append((k, v))
            if name is not None:
                built.append(ast.ConstDecl(name, ast.TableLit(tuple(entries), item.span), key.span))
        return built

    def constants(self, value: JValue | None) -> list[ast.ConstDecl]:
        obj = self.object(value, "`constants`") if value is not None else None
        built = []
        for key, item in obj.members if obj else ():
            name, expr = self.ident(key, "a constant"), self.expr(item, None)
            if name is not None and expr is not None:
                built.append(ast.ConstDecl(name, expr, key.span))
        return built

    def documented(self, decls: list[Declared], value: JValue | None, what: str, named: set[str]) -> list[Declared]:
        """The constants or enums with their doc comments from `constantDocs` or `enumDocs`
        (name: text), which their plain JSON values have no place for; `named`: the names the
        JSON declares (one in error among them is reported once, as itself)."""
        docs = self.object(value, what) if value is not None else None
        texts = {key.value: text.value for key, item in docs.members
                 if (text := self.string(item, "a doc comment")) is not None} if docs else {}
        for key, _ in docs.members if docs else ():
            if key.value not in named:
                self.error(key.span, f"{what} names `{key.value}`, which the description does not declare")
        return [dataclasses.replace(d, doc=texts[d.name.text]) if d.name.text in texts else d for d in decls]

    def enums(self, value: JValue | None) -> list[ast.EnumDecl]:
        obj = self.object(value, "`enums`") if value is not None else None
        built = []
        for key, item in obj.members if obj else ():
            name, members = self.ident(key, "an enum"), self.object(item, "an enum")
            if name is None or members is None:
                continue
            made = []
            for member, number in members.members:
                ident, expr = self.ident(member, "an enum member"), self.expr(number, "int")
                if ident is not None and expr is not None:
                    made.append(ast.EnumMember(ident, expr, member.span))
            built.append(ast.EnumDecl(name, tuple(made), key.span))
        return built

    def state(self, obj: JObject) -> ast.StateDecl | None:
        m = self.members(obj, "a state variable", _STATE)
        name = self.name(obj, m, "a state variable")
        type_ = self.required(obj, m, "type", "a state variable", self.type_ref)
        init = None if "value" not in m else self.expr(m["value"], type_text(type_) if type_ else None)
        if name is None or type_ is None:
            return None
        return ast.StateDecl(name, type_, init, obj.span, self.doc(m), self.state_noise(m.get("noise"), name))

    def sensor(self, obj: JObject) -> ast.SensorDecl | None:
        """`{"name", "type", "primitive", "cache"}`: the cache time in ms."""
        m = self.members(obj, "a sensor", _SENSOR)
        name = self.name(obj, m, "a sensor")
        type_ = self.required(obj, m, "type", "a sensor", self.type_ref)
        primitive = self.required(obj, m, "primitive", "a sensor", self.ident)
        cache = self.required(obj, m, "cache", "a sensor", lambda v, _: self.expr(v, "float"))
        if name is None or type_ is None or primitive is None or cache is None:
            return None
        return ast.SensorDecl(name, type_, primitive, ast.Duration(cache, "ms", cache.span), obj.span, self.doc(m),
                              self.state_noise(m.get("noise"), name))

    def setting(self, obj: JObject) -> ast.SettingDecl | None:
        m = self.members(obj, "a setting", _SETTING)
        name = self.name(obj, m, "a setting")
        type_ = self.required(obj, m, "type", "a setting", self.type_ref)
        default = None if "value" not in m else self.expr(m["value"], type_text(type_) if type_ else None)
        low = high = None
        if "range" in m:
            bounds = self.array(m["range"], "a setting's range")
            if len(bounds) != 2:
                self.error(m["range"].span, "a setting's range is `[low, high]`")
                return None
            low, high = self.expr(bounds[0], None), self.expr(bounds[1], None)
        if name is None or type_ is None:
            return None
        return ast.SettingDecl(name, type_, default, obj.span, self.doc(m), low, high)

    def connections(self, value: JValue | None) -> list[ast.ConnectionDecl]:
        groups = self.object(value, "`connections`") if value is not None else None
        built = []
        for key, group in groups.members if groups else ():
            if key.value not in ("spp", "tcp"):
                self.error(
                    key.span,
                    f"unknown connection kind `{key.value}`",
                    help="serial connections are listed under `spp`, TCP ones under `tcp`",
                )
                continue
            kind = ast.Ident("serial" if key.value == "spp" else "tcp", key.span)
            built += self.each({key.value: group}, key.value, partial(self.connection, kind=kind))
        return built

    def connection(self, obj: JObject, kind: ast.Ident) -> ast.ConnectionDecl | None:
        m = self.members(obj, "a connection", _CONNECTION)
        name = self.name(obj, m, "a connection")
        brace = self.opening(obj)
        baud = ast.IntLit(DEFAULT_BAUD, brace) if "baud" not in m else self.expr(m["baud"], "int")
        attrs: list[ast.ConnectionAttr | None] = [None if baud is None else ast.Baud(baud, baud.span)]
        if "dataBits" in m:
            bits = self.expr(m["dataBits"], "int")
            attrs.append(None if bits is None else ast.DataBits(bits, bits.span))
        if "parity" in m:
            parity = self.ident(m["parity"], "`parity`")
            attrs.append(None if parity is None else ast.Parity(parity, parity.span))
        if "stopBits" in m:
            bits = self.expr(m["stopBits"], "float")
            attrs.append(None if bits is None else ast.StopBits(bits, bits.span))
        given = [key for key in THREADINGS if key in m]
        for extra in given[1:]:
            self.error(m[extra].span, f"a connection has one threading model: `{given[0]}` or `{extra}`")
        key = given[0] if given else "singleThreading"
        threading = self.object(m.get(key), f"`{key}`")
        model = key.removesuffix("Threading")
        if threading is None:
            attrs.append(
                ast.Threading(ast.Ident("single", brace), ast.IntLit(DEFAULT_FREQUENCY_HZ, brace), brace)
            )
        else:
            t = self.members(threading, f"`{key}`", ("freqHz",))
            hz = self.required(
                threading, t, "freqHz", f"`{key}`", lambda v, _: self.expr(v, "float")
            )
            attrs.append(
                None if hz is None else ast.Threading(ast.Ident(model, threading.span), hz, threading.span)
            )
        for event in ("startup", "terminate", "keepalive"):
            hook = self.object(m.get(event), f"`{event}`")
            attrs.append(None if hook is None else self.hook(hook, event))
        terminator = self.string(m.get("terminator"), "`terminator`")
        if terminator is not None:
            attrs.append(ast.Terminator(ast.StrLit(terminator.value, terminator.span), terminator.span))
        address = self.string(m.get("address"), "`address`")
        if address is not None:
            attrs.append(ast.Address(ast.StrLit(address.value, address.span), address.span))
        if name is None:
            return None
        return ast.ConnectionDecl(name, kind, present(attrs), obj.span, self.doc(m))

    def hook(self, obj: JObject, event: str) -> ast.Hook | None:
        keepalive = event == "keepalive"
        what = f"the `{event}` hook"
        m = self.members(obj, what, ("name", "interval", "arguments") if keepalive else ("name", "arguments"))
        target = self.name(obj, m, what)
        every = None
        if keepalive:
            interval = self.required(obj, m, "interval", what, lambda v, _: self.expr(v, "float"))
            every = None if interval is None else ast.Duration(interval, "ms", interval.span)
        if target is None:
            return None
        args = self.args(m.get("arguments"), self.interface_types.get(target.text, ()))
        return ast.Hook(event, ast.Call(target, args, obj.span), every, obj.span)


def _keys(value: JValue | None) -> set[str]:
    """The member names of a JSON object; none of anything else."""
    return {key.value for key, _ in value.members} if isinstance(value, JObject) else set()
