"""Lark parse tree → AST nodes. Construction only: no checking beyond literals."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from functools import lru_cache

from rdisc import TYPE_CHECKING, patterns
from rdisc.diagnostics import Diagnostics, abbreviate
from rdisc.limits import MAX_INT
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.precedence import BINARY, COMPARISON, OR, UNARY_OPERATORS

if TYPE_CHECKING:
    from typing import Any

    from lark import Token, Transformer, Tree
    from lark.tree import Meta

MAX_INT_DIGITS = 64
MAX_EXPR_DEPTH = 100


class _Guarded:
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


def _int_value(text: str) -> int | None:
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

    def build(self, tree: Tree[Token], base: int) -> list[ast.Decl]:
        """The declarations of one chunk (a `start` tree); raises TooDeep for an expression past
        the limit."""
        self.base = base
        self.prefixed.clear()
        self.depth.clear()
        try:
            return transformer_class()(self).transform(tree)
        finally:
            self.prefixed.clear()
            self.depth.clear()

    def expression(self, tree: Tree[Token], base: int) -> ast.Expr:
        """The expression of an `expr_start` tree (one expression on its own, as a JSON string
        holds it); raises TooDeep as `build` does."""
        built: object = self.build(tree, base)  # the transformer builds the tree's root: here, an expression
        assert isinstance(built, _EXPRESSIONS), f"an expression tree built {built!r}"
        return built

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
        pos = 0

        def climb(minimum: int, level: int) -> ast.Expr:
            nonlocal pos
            item = items[pos]
            pos += 1
            if level > MAX_EXPR_DEPTH:
                raise TooDeep(self.token_span(item) if isinstance(item, str) else item.span)
            if isinstance(item, str):
                op = UNARY_OPERATORS[str(item)]
                if op.level < minimum:
                    self.misplaced(item, f"`{item}` cannot stand here without parentheses")
                operand = climb(op.operands[0], level + 1)
                left: ast.Expr = self.nested(
                    ast.Unary(str(item), operand, self.token_span(item).to(operand.span)), operand
                )
            else:
                left = item
            compared = False
            while pos < len(items):
                token = items[pos]
                assert isinstance(token, str)  # operands and operators alternate
                op = BINARY[str(token)]
                if op.level < minimum:
                    break
                if op.level == COMPARISON and compared:
                    self.misplaced(token, "comparisons cannot be chained: write `a < b and b < c`")
                pos += 1
                right = climb(op.operands[1], level + 1)
                left = self.nested(ast.BinOp(str(token), left, right, left.span.to(right.span)), left, right)
                compared = op.level == COMPARISON
            return left

        return climb(OR, 0)

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


_EXPRESSIONS = (ast.IntLit, ast.FloatLit, ast.StrLit, ast.BytesLit, ast.BoolLit, ast.Ref, ast.Index, ast.ArrayLit,
                ast.Unary, ast.BinOp, ast.Conditional, ast.CallExpr, ast.Member, ast.MethodCall)


class Rules:
    """The Builder's method for each rule of the grammar (`v_args(meta=True)`: the rule's positions
    and its children): Lark's Transformer walks a tree with them (`transformer_class`), and the
    fast loop (rdisc.syntax.reduce) calls them as it reduces, without Lark."""

    # The methods that read only the text of their one child where it is a token (`str(c[0])`), never
    # its positions: the fast loop gives them the text, without making a Token.
    TEXT_ONLY = frozenset({"name", "int_lit", "float_lit", "bool_lit", "robot_key", "hook_event", "encoding_kind",
                           "decoding_kind", "kind_word", "time_unit", "check_word", "hex_word", "actuator_key"})

    def __init__(self, builder: Builder) -> None:
        self.b = builder

    # -- top level --

    def start(self, meta: Meta, children: list[ast.Decl | None]) -> list[ast.Decl]:
        return [c for c in children if c is not None]

    def import_decl(self, meta: Meta, c: list[Any]) -> ast.ImportDecl:
        return ast.ImportDecl(self.b.string(c[0]).value, self.b.span(meta), self.b.doc(meta))

    def robot_decl(self, meta: Meta, c: list[Any]) -> ast.RobotDecl:
        return ast.RobotDecl(self.b.ident(c[0]), tuple(c[1:]), self.b.span(meta), self.b.doc(meta))

    def robot_attr(self, meta: Meta, c: list[Any]) -> ast.RobotAttr:
        return ast.RobotAttr(c[0], self.b.string(c[1]).value, self.b.span(meta))

    def state_decl(self, meta: Meta, c: list[Any]) -> ast.StateDecl:
        name, type_, init, noise = c
        made = None if noise is None else ast.FieldNoise(self.b.ident(name), noise[0], noise[1], noise[2])
        return ast.StateDecl(self.b.ident(name), self.b.type_ref(type_), init, self.b.span(meta), self.b.doc(meta),
                             made)

    def state_noise(self, meta: Meta, c: list[Any]) -> tuple[float | ast.NumberRows, ast.StrLit | None, Span]:
        return c[0], None if c[1] is None else self.b.string(c[1]), self.b.span(meta)

    def sensor_decl(self, meta: Meta, c: list[Any]) -> ast.SensorDecl:
        name, type_, primitive, cache, noise = c
        made = None if noise is None else ast.FieldNoise(self.b.ident(name), noise[0], noise[1], noise[2])
        return ast.SensorDecl(self.b.ident(name), self.b.type_ref(type_), self.b.ident(primitive), cache,
                              self.b.span(meta), self.b.doc(meta), made)

    def setting_decl(self, meta: Meta, c: list[Any]) -> ast.SettingDecl:
        name, type_, low, high, default = c
        return ast.SettingDecl(self.b.ident(name), self.b.type_ref(type_), default, self.b.span(meta),
                               self.b.doc(meta), low, high)

    def connection_decl(self, meta: Meta, c: list[Any]) -> ast.ConnectionDecl:
        return ast.ConnectionDecl(
            self.b.ident(c[0]), self.b.ident(c[1]), tuple(c[2:]), self.b.span(meta), self.b.doc(meta)
        )

    def baud(self, meta: Meta, c: list[Any]) -> ast.Baud:
        return ast.Baud(c[0], self.b.span(meta))

    def threading(self, meta: Meta, c: list[Any]) -> ast.Threading:
        return ast.Threading(self.b.ident(c[0]), c[1], self.b.span(meta))

    def hook(self, meta: Meta, c: list[Any]) -> ast.Hook:
        return ast.Hook(c[0], c[1], None, self.b.span(meta))

    def keepalive(self, meta: Meta, c: list[Any]) -> ast.Hook:
        return ast.Hook("keepalive", c[0], c[1], self.b.span(meta))

    def terminator(self, meta: Meta, c: list[Any]) -> ast.Terminator:
        return ast.Terminator(self.b.string(c[0]), self.b.span(meta))

    def hook_call(self, meta: Meta, c: list[Any]) -> ast.Call:
        return ast.Call(self.b.ident(c[0]), c[1] or (), self.b.span(meta))

    def primitive_decl(self, meta: Meta, c: list[Any]) -> ast.PrimitiveDecl:
        return ast.PrimitiveDecl(
            self.b.ident(c[0]), c[1] or (), tuple(c[2:]), self.b.span(meta), self.b.doc(meta)
        )

    def on(self, meta: Meta, c: list[Any]) -> ast.On:
        return ast.On(self.b.ident(c[0]), self.b.span(meta))

    def encoding(self, meta: Meta, c: list[Any]) -> ast.Encoding:
        return ast.Encoding(c[0], self.b.string(c[1]), c[2] or (), self.b.span(meta))

    def decoding(self, meta: Meta, c: list[Any]) -> ast.Decoding:
        return ast.Decoding(c[0], self.b.string(c[1]), self.b.span(meta))

    def actions(self, meta: Meta, c: list[Any]) -> ast.Actions:
        return ast.Actions(tuple(c), self.b.span(meta))

    def assign(self, meta: Meta, c: list[Any]) -> ast.Assign:
        return ast.Assign(self.b.ident(c[0]), c[2], self.b.span(meta), c[1])

    def post_assign(self, meta: Meta, c: list[Any]) -> ast.Assign:
        return ast.Assign(self.b.ident(c[0]), c[2], self.b.span(meta), c[1], c[3])

    def array_type(self, meta: Meta, c: list[Any]) -> ast.ArrayOf:
        return ast.ArrayOf(self.b.ident(c[0]), c[1], self.b.span(meta))

    def interface_decl(self, meta: Meta, c: list[Any]) -> ast.InterfaceDecl:
        name, params, *rest = c
        clauses = tuple(x for x in rest if isinstance(x, (ast.Kind, ast.Triggers)))
        body = tuple(x for x in rest if isinstance(x, (ast.CallStmt, ast.ForStmt)))
        return ast.InterfaceDecl(
            self.b.ident(name), params or (), clauses, body, self.b.span(meta), self.b.doc(meta)
        )

    def kind(self, meta: Meta, c: list[Any]) -> ast.Kind:
        return ast.Kind(c[0], self.b.span(meta))

    def periodic_rate(self, meta: Meta, c: list[Any]) -> ast.Kind:
        return ast.Kind("periodic", self.b.span(meta), c[0])

    def triggers(self, meta: Meta, c: list[Any]) -> ast.Triggers:
        return ast.Triggers(tuple(self.b.ident(n) for n in c), self.b.span(meta))

    def call_stmt(self, meta: Meta, c: list[Any]) -> ast.CallStmt:
        call = ast.Call(self.b.ident(c[0]), c[1] or (), self.b.span(meta))
        delays = tuple(x[1] for x in c[2:] if x[0] == "delay")
        priorities = tuple(x[1] for x in c[2:] if x[0] == "priority")
        conditions = tuple(x[1] for x in c[2:] if x[0] == "when")
        polls = tuple(x[1] for x in c[2:] if x[0] == "until")
        return ast.CallStmt(call, delays, priorities, self.b.span(meta), conditions, polls)

    def for_stmt(self, meta: Any, c: list[Any]) -> ast.ForStmt:
        name, low, high, *body = c
        return ast.ForStmt(self.b.ident(name), low, high, tuple(body), self.b.span(meta))

    def delay(self, meta: Meta, c: list[ast.Duration]) -> tuple[str, ast.Duration]:
        return ("delay", c[0])

    def priority(self, meta: Meta, c: list[ast.Expr]) -> tuple[str, ast.Expr]:
        return ("priority", c[0])

    def when(self, meta: Meta, c: list[ast.Expr]) -> tuple[str, ast.Expr]:
        return ("when", c[0])

    def until(self, meta: Meta, c: list[Any]) -> tuple[str, ast.Poll]:
        return ("until", ast.Poll(c[0], c[1], c[2], self.b.span(meta)))

    def adapter_decl(self, meta: Meta, c: list[Any]) -> ast.AdapterDecl:
        ros = self.b.string(c[1]) if c[1] is not None else None
        return ast.AdapterDecl(self.b.ident(c[0]), ros, tuple(c[2:]), self.b.span(meta), self.b.doc(meta))

    def field_decl(self, meta: Meta, c: list[Any]) -> ast.FieldDecl:
        unit = self.b.string(c[2]).value if c[2] is not None else None
        ros = self.b.string(c[3]) if c[3] is not None else None
        return ast.FieldDecl(
            self.b.ident(c[0]), self.b.type_ref(c[1]), unit, ros, self.b.span(meta), self.b.doc(meta)
        )

    def address(self, meta: Meta, c: list[Any]) -> ast.Address:
        return ast.Address(self.b.string(c[0]), self.b.span(meta))

    def data_bits(self, meta: Meta, c: list[Any]) -> ast.DataBits:
        return ast.DataBits(c[0], self.b.span(meta))

    def parity(self, meta: Meta, c: list[Any]) -> ast.Parity:
        return ast.Parity(self.b.ident(c[0]), self.b.span(meta))

    def stop_bits(self, meta: Meta, c: list[Any]) -> ast.StopBits:
        return ast.StopBits(c[0], self.b.span(meta))

    def reply_table(self, meta: Meta, c: list[Any]) -> ast.ReplyTable:
        return ast.ReplyTable(self.b.ident(c[0]), tuple(c[1:]), self.b.span(meta))

    def reply_tag_table(self, meta: Meta, c: list[Any]) -> ast.ReplyTable:
        tag = self.b.string(c[0])
        return ast.ReplyTable(ast.Ident("tag", tag.span), tuple(c[1:]), self.b.span(meta), tag)

    def reply_each_table(self, meta: Meta, c: list[Any]) -> ast.ReplyTable:
        tag = self.b.string(c[0])
        length = None if c[1] is None else self.b.string(c[1])
        return ast.ReplyTable(ast.Ident("tag", tag.span), tuple(c[2:]), self.b.span(meta), tag, True, length)

    def reply_records(self, meta: Meta, c: list[Any]) -> ast.Records:
        return ast.Records(self.b.string(c[0]), self.b.span(meta))

    def reply_entry(self, meta: Meta, c: list[Any]) -> ast.ReplyEntry:
        value, last, kind, template, until, *assigns = c
        decoding = ast.Decoding(kind, self.b.string(template), self.b.span(meta))
        actions = None if assigns == [None] else ast.Actions(tuple(assigns), self.b.span(meta))
        return ast.ReplyEntry(value, decoding, actions, self.b.span(meta), last,
                              None if until is None else self.b.string(until))

    def reply_nested(self, meta: Meta, c: list[Any]) -> ast.ReplyEntry:
        tag = self.b.string(c[1])
        table = ast.ReplyTable(ast.Ident("tag", tag.span), tuple(c[2:]), self.b.span(meta), tag)
        return ast.ReplyEntry(c[0], None, None, self.b.span(meta), table=table)

    def reply_timeout(self, meta: Meta, c: list[Any]) -> ast.ReplyTimeout:
        return ast.ReplyTimeout(c[0], self.b.span(meta))

    def retry(self, meta: Meta, c: list[ast.Expr]) -> ast.Retry:
        return ast.Retry(c[0], self.b.span(meta))

    def replies(self, meta: Meta, c: list[ast.Expr]) -> ast.Replies:
        return ast.Replies(c[0], self.b.span(meta))

    def replies_each(self, meta: Meta, c: list[Any]) -> ast.Replies:
        var, low, high, frame, args = c
        span = self.b.span(meta)
        framed = ast.Framed(self.b.ident(frame), args or (), span)
        return ast.Replies(low, span, self.b.ident(var), high, framed)

    def listed_reply(self, meta: Meta, c: list[Any]) -> ast.ListedReply:
        framed, kind, template, condition, *assigns = c
        span = self.b.span(meta)
        actions = ast.Actions(tuple(assigns), span) if assigns else None  # `{}` says nothing more
        return ast.ListedReply(ast.Decoding(kind, self.b.string(template), span), span, framed, condition, actions)

    def error_reply(self, meta: Meta, c: list[Any]) -> ast.ErrorReply:
        framed, marker, kind, template, codes = c
        span = self.b.span(meta)
        return ast.ErrorReply(ast.Decoding(kind, self.b.string(template), span), span, framed,
                              None if marker is None else self.b.string(marker),
                              None if codes is None else self.b.ident(codes))

    def error_when(self, meta: Meta, c: list[Any]) -> ast.ErrorReply:
        condition, codes = c
        return ast.ErrorReply(None, self.b.span(meta), codes=None if codes is None else self.b.ident(codes),
                              when=condition)

    def reply_list(self, meta: Meta, c: list[ast.ListedReply]) -> ast.ReplyList:
        return ast.ReplyList(tuple(c), self.b.span(meta))

    def expect(self, meta: Meta, c: list[Any]) -> ast.Expect:
        return ast.Expect(c[0], self.b.span(meta))

    def modem_lines(self, meta: Meta, c: list[ast.Assign | ast.LineBreak]) -> ast.Lines:
        return ast.Lines(tuple(c), self.b.span(meta))

    def line_break(self, meta: Meta, c: list[ast.Duration]) -> ast.LineBreak:
        return ast.LineBreak(c[0], self.b.span(meta))

    def skip_unmatched(self, meta: Meta, c: list[Any]) -> ast.SkipUnmatched:
        return ast.SkipUnmatched(self.b.span(meta))

    def framed(self, meta: Meta, c: list[Any]) -> ast.Framed:
        return ast.Framed(self.b.ident(c[0]), c[1] or (), self.b.span(meta))

    def const_decl(self, meta: Meta, c: list[Any]) -> ast.ConstDecl:
        return ast.ConstDecl(self.b.ident(c[0]), c[1], self.b.span(meta), self.b.doc(meta))

    def table_lit(self, meta: Meta, c: list[Any]) -> ast.TableLit:
        return ast.TableLit(tuple(x for x in c if x is not None), self.b.span(meta))

    def table_entry(self, meta: Meta, c: list[ast.Expr]) -> tuple[ast.Expr, ast.Expr]:
        return (c[0], c[1])

    def enum_decl(self, meta: Meta, c: list[Any]) -> ast.EnumDecl:
        members = tuple(x for x in c[1:] if x is not None)
        return ast.EnumDecl(self.b.ident(c[0]), members, self.b.span(meta), self.b.doc(meta))

    def enum_member(self, meta: Meta, c: list[Any]) -> ast.EnumMember:
        return ast.EnumMember(self.b.ident(c[0]), c[1], self.b.span(meta))

    def frame_decl(self, meta: Meta, c: list[Any]) -> ast.FrameDecl:
        return ast.FrameDecl(self.b.ident(c[0]), c[1] or (), tuple(c[2:]), self.b.span(meta), self.b.doc(meta))

    def f_stuff(self, meta: Meta, c: list[Any]) -> ast.FrameStuff:
        return ast.FrameStuff(self.b.string(c[0]), self.b.string(c[1]), self.b.span(meta))

    def f_escape_xor(self, meta: Meta, c: list[Any]) -> ast.FrameEscape:
        mask = _int_value(str(c[1]))
        return ast.FrameEscape(self.b.string(c[0]), (), -1 if mask is None else mask, self.b.string(c[2]),
                               self.b.span(meta))

    def f_escape_table(self, meta: Meta, c: list[Any]) -> ast.FrameEscape:
        return ast.FrameEscape(self.b.string(c[0]), tuple(e for e in c[1:] if e is not None), span=self.b.span(meta))

    def escape_entry(self, meta: Meta, c: list[Any]) -> tuple[ast.StrLit, ast.StrLit]:
        return self.b.string(c[0]), self.b.string(c[1])

    def request_side(self, meta: Meta, c: list[Any]) -> ast.FrameSide:
        return ast.FrameSide("request", tuple(c), self.b.span(meta))

    def reply_side(self, meta: Meta, c: list[Any]) -> ast.FrameSide:
        return ast.FrameSide("reply", tuple(c), self.b.span(meta))

    @staticmethod
    def _bytes(role: str) -> Callable[[Any, Meta, list[Any]], ast.FrameBytes]:
        def part(self: Any, meta: Meta, c: list[Any]) -> ast.FrameBytes:
            return ast.FrameBytes(role, self.b.string(c[0]), self.b.span(meta))
        return part

    f_header, f_literal, f_terminator = _bytes("header"), _bytes("literal"), _bytes("terminator")

    def f_field(self, meta: Meta, c: list[Any]) -> ast.FrameField:
        return ast.FrameField(self.b.ident(c[0]), self.b.string(c[1]), c[2], self.b.span(meta))

    def f_length(self, meta: Meta, c: list[Any]) -> ast.FrameLength:
        fmt, sign, amount = c
        adjust = 0
        if amount is not None:
            adjust = _int_value(str(amount)) or 0
            adjust = -adjust if str(sign) == "-" else adjust
        return ast.FrameLength(self.b.string(fmt), adjust, self.b.span(meta))

    def f_bits(self, meta: Meta, c: list[Any]) -> ast.FrameBits:
        return ast.FrameBits(self.b.string(c[0]), tuple(c[1:]), self.b.span(meta))

    def b_length(self, meta: Meta, c: list[Any]) -> ast.FrameBitField:
        width, sign, amount = c
        adjust = _int_value(str(amount)) or 0 if amount is not None else 0
        return ast.FrameBitField(None, _int_value(str(width)) or 0, None, -adjust if str(sign) == "-" else adjust,
                                 self.b.span(meta))

    def b_field(self, meta: Meta, c: list[Any]) -> ast.FrameBitField:
        return ast.FrameBitField(self.b.ident(c[0]), _int_value(str(c[1])) or 0, c[2], 0, self.b.span(meta))

    def f_optional(self, meta: Meta, c: list[ast.FramePart]) -> ast.FrameOptional:
        return ast.FrameOptional(tuple(c), self.b.span(meta))

    def part_run(self, meta: Meta, c: list[ast.FramePart]) -> tuple[ast.FramePart, ...]:
        return tuple(c)

    def when_run(self, meta: Meta, c: list[Any]) -> _Guarded:
        condition, *parts = c
        return _Guarded(condition, tuple(parts))

    def f_either(self, meta: Meta, c: list[object]) -> ast.FrameEither:
        runs = [run for run in c if isinstance(run, (tuple, _Guarded))]
        conditions = tuple(run.condition if isinstance(run, _Guarded) else None for run in runs)
        return ast.FrameEither(tuple(run.parts if isinstance(run, _Guarded) else run for run in runs),
                               self.b.span(meta), conditions if any(c is not None for c in conditions) else ())

    def f_payload(self, meta: Meta, c: list[Any]) -> ast.FramePayload:
        return ast.FramePayload(self.b.span(meta))

    def f_payload_trimmed(self, meta: Meta, c: list[Any]) -> ast.FramePayload:
        return ast.FramePayload(self.b.span(meta), trimmed=True)

    def f_checksum(self, meta: Meta, c: list[Any]) -> ast.FrameChecksum:
        algorithm, encoding, *options = c
        fmt = None if encoding == "hex" else self.b.string(encoding)
        return ast.FrameChecksum(self.b.string(algorithm), fmt, tuple(options), self.b.span(meta))

    def c_inverted(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        return ast.ChecksumOption("inverted", span=self.b.span(meta))

    def c_reflect(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        side = c[0] if c and c[0] is not None else None
        return ast.ChecksumOption("reflect" if side is None else f"reflect {side}", span=self.b.span(meta))

    def reflect_side(self, meta: Meta, c: list[Any]) -> str:
        return str(c[0])

    def c_setting(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        return ast.ChecksumOption(str(c[0]), c[1], span=self.b.span(meta))

    def c_over(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        names = tuple(self.b.ident(t) for t in c if t is not None)
        return ast.ChecksumOption("over", over=names, span=self.b.span(meta))

    def c_seed(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        return ast.ChecksumOption("seed", over=(self.b.ident(c[0]), self.b.ident(c[1])), span=self.b.span(meta))

    def member(self, meta: Meta, c: list[Any]) -> ast.Member:
        return ast.Member(self.b.ident(c[0]), self.b.ident(c[1]), self.b.span(meta))

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

    def input_decl(self, meta: Meta, c: list[Any]) -> ast.InputDecl:
        call_span = self.b.token_span(c[2])
        if c[3]:
            call_span = call_span.to(c[3][-1].span)
        call = ast.Call(self.b.ident(c[2]), c[3] or (), call_span)
        return ast.InputDecl(self.b.ident(c[0]), self.b.ident(c[1]), call, self.b.span(meta), self.b.doc(meta))

    def output_decl(self, meta: Meta, c: list[Any]) -> ast.OutputDecl:
        frame = None if c[2] is None else self.b.ident(c[2])
        items = c[3:]
        return ast.OutputDecl(
            self.b.ident(c[0]), self.b.ident(c[1]), tuple(i for i in items if isinstance(i, ast.Assign)),
            self.b.span(meta), self.b.doc(meta), frame, tuple(i for i in items if isinstance(i, ast.FieldNoise)),
            tuple(i for i in items if isinstance(i, ast.FieldFilter)),
        )

    def field_noise(self, meta: Meta, c: list[Any]) -> ast.FieldNoise:
        unit = None if c[2] is None else self.b.string(c[2])
        return ast.FieldNoise(self.b.ident(c[0]), c[1], unit, self.b.span(meta))

    def fields_noise(self, meta: Meta, c: list[Any]) -> ast.FieldNoise:
        *names, value = c
        return ast.FieldNoise(self.b.ident(names[0]), value, None, self.b.span(meta),
                              tuple(self.b.ident(n) for n in names[1:]))

    def field_filter(self, meta: Meta, c: list[Any]) -> ast.FieldFilter:
        return ast.FieldFilter(self.b.ident(c[0]), tuple(c[1:]), self.b.span(meta))

    def kalman_item(self, meta: Meta, c: list[Any]) -> tuple[ast.Ident, float | ast.NumberRows]:
        return c[0], c[1]

    def kalman_word(self, meta: Meta, c: list[Any]) -> ast.Ident:
        return self.b.ident(c[0])

    def number_rows(self, meta: Meta, c: list[Any]) -> ast.NumberRows:
        return ast.NumberRows(tuple(c), self.b.span(meta))

    def number_row(self, meta: Meta, c: list[Any]) -> tuple[float, ...]:
        return tuple(c)

    def number(self, meta: Meta, c: list[Any]) -> float:
        value = float(str(c[1]).replace("_", "")) if str(c[1])[:2].lower() not in ("0x", "0b", "0o") else float(
            int(str(c[1]).replace("_", ""), 0))
        return -value if c[0] is not None and str(c[0]) == "-" else value

    def params(self, meta: Meta, c: list[ast.Param | None]) -> tuple[ast.Param, ...]:
        return tuple(x for x in c if x is not None)

    def param(self, meta: Meta, c: list[Any]) -> ast.Param:
        unit = None if c[4] is None else self.b.string(c[4])
        return ast.Param(self.b.ident(c[0]), self.b.type_ref(c[1]), self.b.span(meta), c[2], c[3], c[5], unit)

    def args(self, meta: Meta, c: list[ast.Expr | None]) -> tuple[ast.Expr, ...]:
        return tuple(x for x in c if x is not None)

    def duration(self, meta: Meta, c: list[Any]) -> ast.Duration:
        return ast.Duration(c[0], c[1], self.b.span(meta))

    # -- keyword groups: the word itself --

    def _word(self, meta: Meta, c: list[Token]) -> str:
        return str(c[0])

    robot_key = hook_event = encoding_kind = decoding_kind = kind_word = time_unit = _word
    check_word = hex_word = actuator_key = _word

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
        value = _int_value(str(c[0]))
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


@lru_cache(maxsize=1)
def transformer_class() -> Callable[[Builder], Transformer[Token, list[ast.Decl]]]:
    """Lark's Transformer of the Rules, defined when first needed: Lark is imported lazily (start-up time)."""
    import lark
    from lark import v_args

    def __init__(self: Any, builder: Builder) -> None:
        lark.Transformer.__init__(self, visit_tokens=False)
        self.b = builder

    namespace = {name: value for name, value in vars(Rules).items() if not name.startswith("__")}
    namespace["__init__"] = __init__
    made: Callable[[Builder], Transformer[Token, list[ast.Decl]]] = v_args(meta=True)(
        type("Transformer", (lark.Transformer,), namespace))
    return made
