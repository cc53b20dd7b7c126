"""Interfaces, their calls, and the domain adapters, inputs and outputs: an interface parameter
passed bare to a primitive parameter takes that parameter's type (else float); an input or output
without an adapter gets the standard adapter with exactly its fields, or one made for it."""

from __future__ import annotations

import dataclasses

from rdisc.json_import.expressions import Expressions
from rdisc.json_import.noise import ErrorModels
from rdisc.json_import.reader import Members, present, str_lit, type_text
from rdisc.json_import.values import JArray, JNumber, JObject, JString, JValue
from rdisc.semantics.operators import FLOAT_FUNCTIONS
from rdisc.syntax import ast
from rdisc.syntax.printer import print_expr

_INTERFACE = (
    "name", "type", "rateHz", "parameters", "parameterTypes", "parameterRanges", "parameterDefaults", "parameterUnits",
    "primitiveCalls", "triggers", "doc",
)  # fmt: skip
_CALL = ("name", "arguments", "delay", "priority", "when", "until", "every", "within")
_ADAPTER = ("name", "ros", "fields", "doc")
_FIELD = ("name", "type", "unit", "ros", "doc")
_INPUT = ("name", "adapter", "parameters", "calls", "doc")
_OUTPUT = ("name", "adapter", "frame", "returns", "noise", "filters", "doc")


class Interfaces(Expressions, ErrorModels):
    """The reading of interfaces, adapters, inputs and outputs."""

    def interface(self, obj: JObject) -> ast.InterfaceDecl | None:
        m = self.members(obj, "an interface", _INTERFACE)
        name = self.name(obj, m, "an interface")
        clauses: list[ast.InterfaceClause] = []
        kind = self.string(m.get("type"), "`type`")
        if kind is not None and kind.value not in ("adhoc", "periodic"):
            self.error(kind.span, f"an interface's `type` is `adhoc` or `periodic`, not {kind.raw}")
        elif kind is not None and kind.value == "periodic":  # adhoc is the default, left unsaid
            rate = self.expr(m["rateHz"], "float") if "rateHz" in m else None
            clauses.append(ast.Kind("periodic", kind.span, rate))
        if "rateHz" in m and (kind is None or kind.value != "periodic"):
            self.error(m["rateHz"].span, "`rateHz` is a periodic interface's own rate: its `type` is `periodic`")
        if "triggers" in m:  # an output's name, as in the thesis, or a list of them
            value = m["triggers"]
            items = self.array(value, "`triggers`") if isinstance(value, JArray) else [value]
            outputs = present([self.ident(item, "`triggers`") for item in items])
            if outputs:
                clauses.append(ast.Triggers(tuple(outputs), value.span))
        calls = [
            self.object(item, "a primitive call")
            for item in self.array(m.get("primitiveCalls"), "`primitiveCalls`")
        ]
        body = present([None if c is None else self.call_stmt(c) for c in calls])

        def infer(param: ast.Ident) -> str:
            for stmt in body:
                for arg, type_ in zip(stmt.call.args, self.primitive_types.get(stmt.call.target.text, ())):
                    if isinstance(arg, ast.Ref) and arg.name == param.text:
                        return type_
            return "float"

        params = self.params(m, infer)
        if "parameterTypes" not in m:  # thesis JSON, which ran on Python 2
            floats = {p.name.text for p in params if type_text(p.type) == "float"}
            body = tuple(self.truncated(stmt, floats) for stmt in body)
        if name is None:
            return None
        self.interface_types[name.text] = tuple(type_text(p.type) for p in params)
        return ast.InterfaceDecl(name, params, tuple(clauses), tuple(body), obj.span, self.doc(m))

    def truncated(self, stmt: ast.CallStmt, floats: set[str]) -> ast.CallStmt:
        """A call as the thesis ran it: Python 2's `struct` truncated a float packed with an
        integer code towards zero, so an argument that may be a float going into an int
        parameter is imported as `int(...)`, with a warning that shows it."""
        types = self.primitive_types.get(stmt.call.target.text, ())
        args = list(stmt.call.args)
        for i, (arg, type_) in enumerate(zip(args, types)):
            if type_ == "int" and _may_be_float(arg, floats):
                args[i] = ast.CallExpr(ast.Ident("int", arg.span), (arg,), arg.span)
                self.d.report("W403", arg.span, f"a float going into an int: imported as `{print_expr(args[i])}`, "
                              "towards zero, as Python 2's struct packed it for the thesis",
                              help="write `round(...)` instead if the device wants the nearest integer")
        if args == list(stmt.call.args):
            return stmt
        return dataclasses.replace(stmt, call=dataclasses.replace(stmt.call, args=tuple(args)))

    def call_stmt(self, obj: JObject) -> ast.CallStmt | None:
        m = self.members(obj, "a primitive call", _CALL)
        target = self.name(obj, m, "a primitive call")
        if target is None:
            return None
        args = self.args(m.get("arguments"), self.primitive_types.get(target.text, ()))
        delay = priority = None
        if "delay" in m and not _is_zero(m["delay"]):  # 0 is the default, left unsaid
            delay = self.expr(m["delay"], "float")
        if "priority" in m and not _is_zero(m["priority"]):
            priority = self.expr(m["priority"], "int")
        when = self.expr(m["when"], "bool") if "when" in m else None
        delays = present([None if delay is None else ast.Duration(delay, "ms", delay.span)])
        return ast.CallStmt(ast.Call(target, args, obj.span), delays, present([priority]), obj.span,
                            present([when]), present([self.poll(obj, m)]))

    def poll(self, obj: JObject, m: Members) -> ast.Poll | None:
        """`"until"`, `"every"` and `"within"` (ms), together: the call's `until COND every P within T`."""
        if "until" not in m:
            return None
        until = self.expr(m["until"], "bool")
        every = self.expr(m["every"], "float") if "every" in m else None
        within = self.expr(m["within"], "float") if "within" in m else None
        if every is None or within is None:
            self.d.report("E008", obj.span, "a call with `until` gives `every` and `within` (ms)")
            return None
        if until is None:
            return None
        return ast.Poll(until, ast.Duration(every, "ms", every.span), ast.Duration(within, "ms", within.span), obj.span)

    def adapter(self, obj: JObject) -> ast.AdapterDecl | None:
        m = self.members(obj, "an adapter", _ADAPTER)
        name = self.name(obj, m, "an adapter")
        ros = self.string(m.get("ros"), "`ros`")
        objects = [self.object(item, "an adapter field") for item in self.array(m.get("fields"), "`fields`")]
        built = present([None if f is None else self.field(f) for f in objects])
        if name is None:
            return None
        self.adapter_fields[name.text] = {f.name.text: type_text(f.type) for f in built}
        return ast.AdapterDecl(name, str_lit(ros), built, obj.span, self.doc(m))

    def field(self, obj: JObject) -> ast.FieldDecl | None:
        m = self.members(obj, "an adapter field", _FIELD)
        name = self.name(obj, m, "an adapter field")
        type_ = self.required(obj, m, "type", "an adapter field", self.type_ref)
        unit, ros = self.string(m.get("unit"), "`unit`"), self.string(m.get("ros"), "`ros`")
        if name is None or type_ is None:
            return None
        return ast.FieldDecl(name, type_, _text(unit), str_lit(ros), obj.span, self.doc(m))

    def input(self, obj: JObject) -> ast.InputDecl | None:
        m = self.members(obj, "a domain interface", _INPUT)
        name = self.name(obj, m, "a domain interface")
        params = [
            i for v in self.array(m.get("parameters"), "`parameters`") if (i := self.ident(v, "a parameter"))
        ]
        calls = self.required(obj, m, "calls", "a domain interface", self.object)
        if name is None or calls is None:
            return None
        c = self.members(calls, "`calls`", ("name", "arguments"))
        target = self.name(calls, c, "`calls`")
        if target is None:
            return None
        args = self.args(c.get("arguments"), self.interface_types.get(target.text, ()))
        adapter = self.adapter_of(obj, m, name, params, ordered=True)
        call = ast.Call(target, args, calls.span)
        return ast.InputDecl(name, adapter, call, obj.span, self.doc(m))

    def output(self, obj: JObject) -> ast.OutputDecl | None:
        m = self.members(obj, "a domain output", _OUTPUT)
        name = self.name(obj, m, "a domain output")
        returns = self.required(obj, m, "returns", "a domain output", self.object)
        if name is None or returns is None:
            return None
        written = [
            (field_, value) for key, value in returns.members if (field_ := self.ident(key, "a field"))
        ]
        adapter = self.adapter_of(obj, m, name, [field_ for field_, _ in written])
        types = self.adapter_fields.get(adapter.text, {})
        assigns = []
        for field_, value in written:
            expr = self.expr(value, types.get(field_.text))
            assigns.append(None if expr is None else ast.Assign(field_, expr, value.span))
        frame = None if "frame" not in m else self.ident(m["frame"], "`frame`")
        return ast.OutputDecl(name, adapter, present(assigns), obj.span, self.doc(m), frame, self.noises(m),
                              self.filters(m))

    def adapter_of(self, obj: JObject, m: Members, element: ast.Ident, names: list[ast.Ident],
                   ordered: bool = False) -> ast.Ident:
        """The adapter named, else the standard one with exactly these fields, else a new one.
        Where the order of the fields is the element's (an input's parameters), a standard
        adapter with them in another order is copied in this order: its units and ROS paths
        kept, and the parameters' order kept through `rdisc build`."""
        if "adapter" in m:
            return self.ident(m["adapter"], "`adapter`") or ast.Ident("", m["adapter"].span)
        wanted = [n.text for n in names]
        standard = next((a for a in self.standard.values() if {f.name.text for f in a.fields} == set(wanted)), None)
        if standard is not None and (not ordered or [f.name.text for f in standard.fields] == wanted):
            return ast.Ident(standard.name.text, self.opening(obj))
        base = "".join(part[:1].upper() + part[1:] for part in element.text.split("_")) + "Message"
        made, n = base, 2
        while made in self.adapter_fields:
            made, n = f"{base}{n}", n + 1
        if standard is not None:
            by_name = {f.name.text: f for f in standard.fields}
            decl_fields = tuple(dataclasses.replace(by_name[f.text], span=f.span) for f in names)
            doc = f"{standard.name.text}, with its fields in the order of `{element.text}`."
            decl = ast.AdapterDecl(ast.Ident(made, element.span), standard.ros, decl_fields, obj.span, doc)
        else:
            decl_fields = tuple(ast.FieldDecl(f, ast.Ident("float", f.span), None, None, f.span) for f in names)
            decl = ast.AdapterDecl(ast.Ident(made, element.span), None, decl_fields, obj.span)
        self.made_adapters.append(decl)
        self.adapter_fields[made] = {f.name.text: type_text(f.type) for f in decl_fields}
        return ast.Ident(made, element.span)


def _may_be_float(e: ast.Expr, floats: set[str]) -> bool:
    """Whether an expression of thesis JSON, whose float names are `floats`, may be a float
    (the checker decides for sure; this front end only decides what to convert)."""
    match e:
        case ast.FloatLit():
            return True
        case ast.Ref(name=name):
            return name in floats
        case ast.Unary(op=op, operand=operand):
            return op in "+-" and _may_be_float(operand, floats)
        case ast.BinOp(op="/"):
            return True
        case ast.BinOp(op=op, left=left, right=right) if op in ("+", "-", "*", "//", "%", "**"):
            return _may_be_float(left, floats) or _may_be_float(right, floats)
        case ast.Conditional(then=then, orelse=orelse):
            return _may_be_float(then, floats) or _may_be_float(orelse, floats)
        case ast.CallExpr(func=func, args=args):
            if func.text in FLOAT_FUNCTIONS or (func.text == "round" and len(args) == 2):
                return True
            return func.text in ("abs", "min", "max", "clamp") and any(_may_be_float(a, floats) for a in args)
    return False


def _is_zero(v: JValue) -> bool:
    return isinstance(v, JNumber) and v.value == 0


def _text(s: JString | None) -> str | None:
    return None if s is None else s.value
