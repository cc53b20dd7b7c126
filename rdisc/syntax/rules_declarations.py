"""The Builder's methods for the declarations' rules: the robot, state, connections, primitives and
their clauses, interfaces, adapters, inputs and outputs, constants and enums (rdisc.syntax.build.Rules)."""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.syntax import ast

if TYPE_CHECKING:
    from typing import Any

    from lark.tree import Meta

    from rdisc.source import Span
    from rdisc.syntax.builder import Builder


class DeclarationRules:
    """Each declaration's node, made of its children (its clauses, already made)."""

    b: Builder

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
