"""The Builder: what the grammar's rules (rdisc.syntax.build.Rules) make their nodes with (spans,
names, strings, the depth of expressions and their precedence), and the literals' decoding."""

from __future__ import annotations

import re
from collections.abc import Callable

from rdisc import TYPE_CHECKING, patterns
from rdisc.diagnostics import Diagnostics
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.precedence import BINARY, COMPARISON, OR, UNARY_OPERATORS

if TYPE_CHECKING:

    from lark import Token
    from lark.tree import Meta

MAX_INT_DIGITS = 64
MAX_EXPR_DEPTH = 100


class Guarded:
    """`when COND { parts }`: one alternative of an `either`, before FrameEither takes it apart
    (a plain class: a clean check imports no dataclasses)."""

    __slots__ = ("condition", "parts")

    def __init__(self, condition: ast.Expr, parts: tuple[ast.FramePart, ...]) -> None:
        self.condition = condition
        self.parts = parts


class TooDeep(Exception):
    """An expression nests deeper than MAX_EXPR_DEPTH: the declaration is refused."""

    def __init__(self, span: Span) -> None:
        super().__init__("expression is nested too deeply")
        self.span = span
# Patterns compiled when first used (rdisc.patterns): most descriptions have no escape and no bytes.
_ESCAPE = r"\\(x[0-9a-fA-F]{2}|u[0-9a-fA-F]{4}|.)"
_SIMPLE_ESCAPES = {"n": "\n", "r": "\r", "t": "\t", "0": "\0", "\\": "\\", '"': '"', "'": "'"}


def decode_string(raw: str, report: Callable[[int, int, str, str | None], None] | None = None) -> str:
    """The value of a string token (quotes included). `report(offset, length, text, why)`
    is called for each escape that is not a character (unknown, or half of a surrogate
    pair, which no text can hold), with offsets into `raw`."""
    if raw.startswith("r"):
        return raw[2:-1]
    body = raw[1:-1]
    if "\\" not in body:
        return body

    def replace(m: re.Match[str]) -> str:
        esc = m.group(1)
        if esc in _SIMPLE_ESCAPES:
            return _SIMPLE_ESCAPES[esc]
        if esc[0] in "xu" and len(esc) > 1:
            code = int(esc[1:], 16)
            if not 0xD800 <= code <= 0xDFFF:
                return chr(code)
            if report is not None:
                report(1 + m.start(), len(m.group()), m.group(), "is half of a surrogate pair, not a character")
            return "\ufffd"
        if report is not None:
            report(1 + m.start(), len(m.group()), m.group(), None)
        return m.group()

    return patterns.pattern(_ESCAPE, re.DOTALL).sub(replace, body)


_BYTES_PART = r"\\(x[0-9a-fA-F]{2}|u[0-9a-fA-F]{4}|.)|[^\x00-\x7f]"


def decode_bytes(raw: str, report: Callable[[int, int, str, bool], None] | None = None) -> bytes:
    """The value of a bytes token `b"..."`: ASCII characters, and the escapes strings have but
    `\\u` (a byte each; `\\xHH` any byte). `report(offset, length, text, escape)` is called for
    each escape that is not a byte (`escape` True) and each character that is not ASCII."""

    def replace(m: re.Match[str]) -> str:
        esc = m.group(1)
        if esc is None:  # a character that is not ASCII
            if report is not None:
                report(2 + m.start(), 1, m.group(), False)
            return ""
        if esc in _SIMPLE_ESCAPES:
            return _SIMPLE_ESCAPES[esc]
        if esc[0] == "x" and len(esc) > 1:
            return chr(int(esc[1:], 16))
        if report is not None:
            report(2 + m.start(), len(m.group()), m.group(), True)
        return ""

    return patterns.pattern(_BYTES_PART, re.DOTALL).sub(replace, raw[2:-1]).encode("latin-1")


def int_value(text: str) -> int | None:
    digits = text.replace("_", "")
    if len(digits) > MAX_INT_DIGITS:
        return None
    try:
        return int(text, 0)
    except ValueError:
        return None


class Builder:
    """Turns the tree of one declaration chunk into AST nodes."""

    def __init__(self, path: str, docs: dict[int, str], diagnostics: Diagnostics) -> None:
        self.path = path
        self.docs = docs
        self.diagnostics = diagnostics
        self.base = 0
        # Per chunk, by id(node), holding the node so that its id stays its own:
        self.prefixed: dict[int, tuple[ast.Expr, list[ast.Expr | Token]]] = {}  # a prefixed operand → its items
        self.depth: dict[int, tuple[ast.Expr, int]] = {}  # an expression → its depth

    def nested(self, node: ast.Expr, *children: ast.Expr) -> ast.Expr:
        """Record the depth of a new expression node; refuse one nested too deeply."""
        deepest = 0  # a child not recorded is a leaf, of depth 1
        for child in children:
            found = self.depth.get(id(child))
            below = 1 if found is None else found[1]
            if below > deepest:  # noqa: PLR1730  # max() of a generator costs more than the node
                deepest = below
        depth = 1 + deepest
        if depth > MAX_EXPR_DEPTH:
            raise TooDeep(node.span)
        self.depth[id(node)] = (node, depth)
        return node

    # -- helpers used by the transformer --

    def span(self, meta: Meta | tuple[int, int]) -> Span:
        if isinstance(meta, tuple):  # the fast loop's (start, end) (rdisc.syntax.reduce)
            return Span(self.path, self.base + meta[0], self.base + meta[1])
        if getattr(meta, "empty", False):
            return Span(self.path, self.base, self.base)
        return Span(self.path, self.base + meta.start_pos, self.base + meta.end_pos)

    def token_span(self, token: Token) -> Span:
        start, end = token.start_pos, token.end_pos
        assert start is not None and end is not None  # the lexer places every token it makes
        return Span(self.path, self.base + start, self.base + end)

    def ident(self, token: Token) -> ast.Ident:
        return ast.Ident(str(token), self.token_span(token))

    def type_ref(self, node: Token | ast.ArrayOf) -> ast.TypeRef:
        """A declared type: a NAME token, or an array type already built."""
        return node if isinstance(node, ast.ArrayOf) else self.ident(node)

    def doc(self, meta: Meta | tuple[int, int]) -> str | None:
        return self.docs.get(self.base + (meta[0] if isinstance(meta, tuple) else meta.start_pos))

    def resolve(self, items: list[ast.Expr | Token]) -> ast.Expr:
        """Operators and operands of a flat chain → a tree, by precedence climbing.

        `items` alternates operands (AST nodes) and operator tokens; a token where
        an operand is due is a prefix operator. Levels and associativity come from
        rdisc.syntax.precedence, the table the printers use. A token (Lark's, or the fast loop's)
        is a `str`; an operand never is.
        """
        return self._climb(items, [0], OR, 0)

    def _climb(self, items: list[ast.Expr | Token], at: list[int], minimum: int, level: int) -> ast.Expr:
        """`resolve`'s climb from `items[at[0]]` over operators of `minimum` precedence or more,
        `at` moved past what it took. (A method, not a function nested in `resolve` that calls
        itself: that is a cycle, which kept what it read until the collector came.)"""
        item = items[at[0]]
        at[0] += 1
        if level > MAX_EXPR_DEPTH:
            raise TooDeep(self.token_span(item) if isinstance(item, str) else item.span)
        if isinstance(item, str):
            op = UNARY_OPERATORS[str(item)]
            if op.level < minimum:
                self.misplaced(item, f"`{item}` cannot stand here without parentheses")
            operand = self._climb(items, at, op.operands[0], level + 1)
            left: ast.Expr = self.nested(
                ast.Unary(str(item), operand, self.token_span(item).to(operand.span)), operand
            )
        else:
            left = item
        compared = False
        while at[0] < len(items):
            token = items[at[0]]
            assert isinstance(token, str)  # operands and operators alternate
            op = BINARY[str(token)]
            if op.level < minimum:
                break
            if op.level == COMPARISON and compared:
                self.misplaced(token, "comparisons cannot be chained: write `a < b and b < c`")
            at[0] += 1
            right = self._climb(items, at, op.operands[1], level + 1)
            left = self.nested(ast.BinOp(str(token), left, right, left.span.to(right.span)), left, right)
            compared = op.level == COMPARISON
        return left

    def misplaced(self, token: Token, message: str) -> None:
        self.diagnostics.report("E001", self.token_span(token), message)

    def string(self, token: Token) -> ast.StrLit:
        span = self.token_span(token)

        def report(offset: int, length: int, text: str, why: str | None) -> None:
            at = span.start + offset
            if why is not None:
                self.diagnostics.report("E003", Span(self.path, at, at + length), f"the escape `{text}` {why}",
                                        help="write the character itself, or its escape if it is one")
                return
            self.diagnostics.report(
                "E003",
                Span(self.path, at, at + length),
                f"unknown escape `{text}` in a string",
                help='write `\\\\` for a backslash, or use a raw string r"..." for a regex',
            )

        return ast.StrLit(decode_string(str(token), report), span)

    def bytes_literal(self, token: Token) -> ast.BytesLit:
        span = self.token_span(token)

        def report(offset: int, length: int, text: str, escape: bool) -> None:
            at = Span(self.path, span.start + offset, span.start + offset + length)
            if escape:
                self.diagnostics.report("E003", at, f"unknown escape `{text}` in bytes",
                                        help="bytes are ASCII characters and the escapes `\\xHH`, `\\n`, `\\r`, "
                                        "`\\t`, `\\0`, `\\\\` and `\\\"`")
                return
            utf8 = "".join(f"\\x{b:02x}" for b in text.encode("utf-8"))
            self.diagnostics.report("E004", at, f"`{text}` in bytes is not ASCII",
                                    help=f"write the bytes it stands for as escapes: `{utf8}` in UTF-8")

        return ast.BytesLit(decode_bytes(str(token), report), span)
