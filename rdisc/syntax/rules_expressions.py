"""The Builder's methods for the expressions' rules, and the keyword groups read as their words
(rdisc.syntax.build.Rules)."""

from __future__ import annotations

import math

from rdisc import TYPE_CHECKING
from rdisc.diagnostics import abbreviate
from rdisc.limits import MAX_INT
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.builder import int_value

if TYPE_CHECKING:
    from typing import Any

    from lark import Token
    from lark.tree import Meta

    from rdisc.syntax.builder import Builder


class ExpressionRules:
    """Each expression's node, its depth recorded (Builder.nested); a chain of operators
    resolved by precedence (Builder.resolve)."""

    b: Builder

    # -- keyword groups: the word itself --

    def _word(self, meta: Meta, c: list[Token]) -> str:
        return str(c[0])

    robot_key = hook_event = encoding_kind = decoding_kind = kind_word = time_unit = _word
    check_word = hex_word = actuator_key = _word


    def member(self, meta: Meta, c: list[Any]) -> ast.Member:
        return ast.Member(self.b.ident(c[0]), self.b.ident(c[1]), self.b.span(meta))


    # -- expressions --

    def conditional(self, meta: Meta, c: list[ast.Expr]) -> ast.Expr:
        return self.b.nested(ast.Conditional(c[0], c[1], c[2], self.b.span(meta)), *c)

    def chain(self, meta: Meta, c: list[ast.Expr | Token]) -> ast.Expr:
        items: list[ast.Expr | Token] = []
        for child in c:
            prefixed = self.b.prefixed.get(id(child))
            items.extend([child] if prefixed is None else prefixed[1])
        return self.b.resolve(items)

    def prefixed(self, meta: Meta, c: list[ast.Expr | Token]) -> ast.Expr:
        node = self.b.resolve(c)
        self.b.prefixed[id(node)] = (node, c)
        return node

    def group(self, meta: Meta, c: list[ast.Expr]) -> ast.Expr:
        """`( expr )`: a finished operand, never re-opened by the chain around it."""
        self.b.prefixed.pop(id(c[0]), None)
        return c[0]

    def method_call(self, meta: Meta, c: list[Any]) -> ast.Expr:
        return self.b.nested(ast.MethodCall(self.b.ident(c[0]), self.b.ident(c[1]), c[2] or (), self.b.span(meta)),
                             *(c[2] or ()))

    def call(self, meta: Meta, c: list[Any]) -> ast.Expr:
        return self.b.nested(ast.CallExpr(self.b.ident(c[0]), c[1] or (), self.b.span(meta)), *(c[1] or ()))

    def index(self, meta: Meta, c: list[Any]) -> ast.Expr:
        return self.b.nested(ast.Index(ast.Ref(str(c[0]), self.b.token_span(c[0])), c[1], self.b.span(meta)), c[1])

    def nested_index(self, meta: Meta, c: list[Any]) -> ast.Expr:
        name = self.b.token_span(c[0])  # `out[1]` ends at the bracket after its index, as written plainly
        base = ast.Index(ast.Ref(str(c[0]), name), c[1], Span(name.path, name.start, c[1].span.end + 1))
        self.b.nested(base, c[1])
        return self.b.nested(ast.Index(base, c[2], self.b.span(meta)), base, c[2])

    def literal_index(self, meta: Meta, c: list[Any]) -> ast.Expr:
        items = c[0] or ()
        array = ast.ArrayLit(items, self.b.span(meta))
        self.b.nested(array, *items)
        return self.b.nested(ast.Index(array, c[1], self.b.span(meta)), array, c[1])

    def array_lit(self, meta: Meta, c: list[Any]) -> ast.Expr:
        items = c[0] or ()
        return self.b.nested(ast.ArrayLit(items, self.b.span(meta)), *items)

    def int_lit(self, meta: Meta, c: list[Any]) -> ast.IntLit:
        value = int_value(str(c[0]))
        span = self.b.span(meta)
        if value is None:
            self.b.diagnostics.report("E004", span, f"invalid integer literal `{abbreviate(str(c[0]))}`")
            value = 0
        elif value > MAX_INT:
            self.b.diagnostics.report("E004", span, f"integer literal `{abbreviate(str(c[0]))}` is too large: "
                                      f"integers are limited to 64 bits and a sign (at most {MAX_INT})")
            value = 0
        return ast.IntLit(value, span)

    def float_lit(self, meta: Meta, c: list[Any]) -> ast.FloatLit:
        span = self.b.span(meta)
        try:
            value = float(str(c[0]))
        except ValueError:
            value = math.nan
        if not math.isfinite(value):
            self.b.diagnostics.report("E004", span, f"invalid float literal `{abbreviate(str(c[0]))}`")
            value = 0.0
        return ast.FloatLit(value, span)

    def str_lit(self, meta: Meta, c: list[Token]) -> ast.StrLit:
        return self.b.string(c[0])

    def bytes_lit(self, meta: Meta, c: list[Token]) -> ast.BytesLit:
        return self.b.bytes_literal(c[0])

    def bool_lit(self, meta: Meta, c: list[Any]) -> ast.BoolLit:
        return ast.BoolLit(str(c[0]) == "True", self.b.span(meta))

    def name(self, meta: Meta, c: list[Any]) -> ast.Ref:
        return ast.Ref(str(c[0]), self.b.span(meta))
