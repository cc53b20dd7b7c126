"""Expressions, parameters and post-actions: an expression written `"<...>"` parsed by the RDIS
grammar with spans on the characters inside the string (nothing is evaluated), `""` the
default of the type expected there, a post-action `"state = expr"` with the reply `__out__`."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import fields, is_dataclass, replace
from typing import Any

from rdisc.diagnostics import Diagnostics, Label
from rdisc.json_import.reader import NAME, Members, Reader, present, str_lit
from rdisc.json_import.values import JArray, JBool, JNull, JNumber, JString, JValue, kind_of
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.parse import parse_expression

_DEFAULTS: dict[str, Any] = {"int": 0, "float": 0.0, "bool": False, "string": "", "bytes": b""}
# One character of a JSON string body: a surrogate pair escape decodes to one character.
_JSON_CHAR = re.compile(
    r"\\u[dD][89abAB][0-9a-fA-F]{2}\\u[dD][c-fC-F][0-9a-fA-F]{2}|\\u[0-9a-fA-F]{4}|\\.|.", re.DOTALL
)
_ASSIGNMENT = re.compile(r"\s*([A-Za-z_]\w*)\s*=(?!=)")
_ELEMENT_ASSIGNMENT = re.compile(r"\s*([A-Za-z_]\w*)\[([^=]*)\]\s*=(?!=)")  # `position[id] = ...`
# `__out__` as an identifier; string literals are matched (and skipped) so that their text is left alone.
_OUT = re.compile(r'r?"(?:[^"\\\n]|\\.)*"|(?<![A-Za-z0-9_])(__out__)(?![A-Za-z0-9_])')
_WHEN = re.compile(r"\s+when\s+(?!.*\swhen\s)", re.DOTALL)


class Expressions(Reader):
    """The reading of expressions, parameters and post-actions."""

    def params(self, m: Members, infer: Callable[[ast.Ident], str]) -> tuple[ast.Param, ...]:
        names = [
            i for v in self.array(m.get("parameters"), "`parameters`") if (i := self.ident(v, "a parameter"))
        ]
        ranges = self.ranges(m, len(names))
        defaults = self.defaults(m, len(names))
        units = self.units(m, len(names))
        if "parameterTypes" not in m:
            return tuple(ast.Param(n, ast.Ident(infer(n), n.span), n.span, *r, d, u)
                         for n, r, d, u in zip(names, ranges, defaults, units))
        types = [
            t for v in self.array(m["parameterTypes"], "`parameterTypes`") if (t := self.type_ref(v, "a type"))
        ]
        if len(types) != len(names):
            self.error(
                m["parameterTypes"].span,
                f"`parameterTypes` has {len(types)} entries for {len(names)} parameters",
            )
            return ()
        return tuple(ast.Param(n, t, n.span, *r, d, u) for n, t, r, d, u in zip(names, types, ranges, defaults, units))

    def per_parameter(self, m: Members, key: str, count: int) -> tuple[JValue, ...] | None:
        """A member with an entry for each parameter (`parameterUnits`, ...); None when it is
        left out, or has another number of entries (reported)."""
        if key not in m:
            return None
        items = self.array(m[key], f"`{key}`")
        if len(items) != count:
            self.error(m[key].span, f"`{key}` has {len(items)} entries for {count} parameters")
            return None
        return items

    def units(self, m: Members, count: int) -> list[ast.StrLit | None]:
        """`parameterUnits`: a unit or null for each parameter."""
        items = self.per_parameter(m, "parameterUnits", count)
        if items is None:
            return [None] * count
        return [None if isinstance(item, JNull) else str_lit(self.string(item, "a parameter's unit")) for item in items]

    def defaults(self, m: Members, count: int) -> list[ast.Expr | None]:
        """`parameterDefaults`: a value or null for each parameter."""
        items = self.per_parameter(m, "parameterDefaults", count)
        if items is None:
            return [None] * count
        return [None if isinstance(item, JNull) else self.expr(item, None) for item in items]

    def ranges(self, m: Members, count: int) -> list[tuple[ast.Expr | None, ast.Expr | None]]:
        """`parameterRanges`: `[low, high]` or null for each parameter."""
        none: tuple[ast.Expr | None, ast.Expr | None] = (None, None)
        items = self.per_parameter(m, "parameterRanges", count)
        if items is None:
            return [none] * count
        built = []
        for item in items:
            bounds = () if isinstance(item, JNull) else self.array(item, "a parameter's range")
            if len(bounds) == 2:
                built.append((self.expr(bounds[0], None), self.expr(bounds[1], None)))
            else:
                if not isinstance(item, JNull):
                    self.error(item.span, "a parameter's range is `[low, high]` or null")
                built.append(none)
        return built

    def args(self, value: JValue | None, types: tuple[str, ...]) -> tuple[ast.Expr, ...]:
        items = self.array(value, "`arguments`")
        return present([self.expr(a, types[i] if i < len(types) else None) for i, a in enumerate(items)])

    def expr(self, v: JValue, type_: str | None) -> ast.Expr | None:
        """An expression: a JSON literal, `""` (the default of `type_`), `"<expr>"`, or a string."""
        match v:
            case JBool(value, span):
                return ast.BoolLit(value, span)
            case JNumber(value, span):
                return _number(value, span)
            case JString("", _, span):
                return _literal(_DEFAULTS.get(type_ or "", ""), span)
            case JString(value, _, span) if not _embedded(value):
                return ast.StrLit(value, span)
            case JString():
                offsets = self.offsets(v)
                return self.parse(v.value[1:-1], offsets[1 : len(v.value)])
            case JArray(items, span) if items:  # a constant array: `"IDS": [1, 2, 3]`
                values = [self.expr(item, None) for item in items]
                built = tuple(value for value in values if value is not None)
                return ast.ArrayLit(built, span) if len(built) == len(values) else None
        self.error(v.span, f"expected an expression (a number, true/false, a string or an array), found {kind_of(v)}")
        return None

    def reply_expr(self, v: JValue, what: str) -> ast.Expr | None:
        """`"<expr>"` over the reply, called `__out__` as in post-actions."""
        s = self.string(v, what)
        if s is None:
            return None
        text, offsets = s.value, self.offsets(s)
        if _embedded(text):
            text, offsets = text[1:-1], offsets[1 : len(text)]
        text, offsets = _reply_as_out(text, offsets)
        return self.parse(text, offsets)

    def post_action(self, v: JValue) -> ast.Assign | None:
        """`"state = expr"` or `"state[index] = expr"` (or inside `<...>`), with the reply as `__out__`."""
        s = self.string(v, "a post-action")
        if s is None:
            return None
        text, offsets = s.value, self.offsets(s)
        if _embedded(text):
            text, offsets = text[1:-1], offsets[1 : len(text)]
        m = _ASSIGNMENT.match(text) or _ELEMENT_ASSIGNMENT.match(text)
        if m is None or not NAME.fullmatch(m.group(1)):
            self.error(
                s.span,
                "a post-action is written `state = expression`",
                help='e.g. "bumperStates = __out__[0]"',
            )
            return None
        target = ast.Ident(m.group(1), Span(self.path, offsets[m.start(1)], offsets[m.end(1)]))
        index = None
        if m.re is _ELEMENT_ASSIGNMENT:
            at, end = m.start(2), m.end(2)
            index = self.parse(*_reply_as_out(text[at:end], offsets[at : end + 1]))
            if index is None:
                return None
        text, offsets = _reply_as_out(text[m.end() :], offsets[m.end() :])
        when = None
        split = _WHEN.search(text)  # `value when COND`: the last `when` of the text
        if split is not None:
            when = self.parse(text[split.end():], offsets[split.end():])
            if when is None:
                return None
            text, offsets = text[: split.start()], offsets[: split.start() + 1]
        value = self.parse(text, offsets)
        return None if value is None else ast.Assign(target, value, s.span, index, when)

    def offsets(self, s: JString) -> list[int]:
        """The file offset of each character of a decoded string, then of its closing quote."""
        if "\\" not in s.raw:
            return list(range(s.span.start + 1, s.span.end))
        return [s.span.start + m.start() for m in _JSON_CHAR.finditer(s.raw, 1, len(s.raw) - 1)] + [
            s.span.end - 1
        ]

    def parse(self, text: str, offsets: list[int]) -> ast.Expr | None:
        """Parse `text`, whose character i is at file offset offsets[i]."""
        if offsets[-1] - offsets[0] == len(text):  # written as is: spans are a plain shift
            return parse_expression(self.path, text, offsets[0], self.d)
        local = Diagnostics()
        expr = parse_expression(self.path, text, 0, local)

        def place(span: Span) -> Span:
            return Span(self.path, offsets[span.start], offsets[span.end])

        for d in local.items:
            labels = tuple(Label(place(label.span), label.message) for label in d.labels)
            span = None if d.span is None else place(d.span)
            self.d.report(d.code, span, d.message, label=d.label, labels=labels, help=d.help)
        return None if expr is None else _respan(expr, place)


def _embedded(value: str) -> bool:
    return len(value) >= 3 and value[0] == "<" and value[-1] == ">"


def _number(value: float, span: Span) -> ast.Expr:
    """A JSON number as the parser would read it: a negative one is a unary minus."""
    if value < 0 or str(value).startswith("-"):
        return ast.Unary("-", _literal(-value, Span(span.path, span.start + 1, span.end)), span)
    return _literal(value, span)


def _literal(value: Any, span: Span) -> ast.Expr:
    if isinstance(value, bool):
        return ast.BoolLit(value, span)
    if isinstance(value, int):
        return ast.IntLit(value, span)
    if isinstance(value, float):
        return ast.FloatLit(value, span)
    if isinstance(value, bytes):
        return ast.BytesLit(value, span)
    return ast.StrLit(value, span)


def _reply_as_out(text: str, offsets: list[int]) -> tuple[str, list[int]]:
    """Replace the identifier `__out__` by `out`, keeping each character's file offset."""
    pieces, places, last = [], [], 0
    for m in _OUT.finditer(text):
        if m.group(1) is None:
            continue
        pieces.append(text[last : m.start()] + "out")
        places += offsets[last : m.start() + 3]
        last = m.end()
    return "".join(pieces) + text[last:], places + offsets[last:]


def _respan(node: Any, place: Callable[[Span], Span]) -> Any:
    """A copy of an AST node with every span moved by `place`."""
    if isinstance(node, Span):
        return place(node)
    if isinstance(node, tuple):
        return tuple(_respan(x, place) for x in node)
    if is_dataclass(node) and not isinstance(node, type):
        return replace(node, **{f.name: _respan(getattr(node, f.name), place) for f in fields(node)})
    return node
