"""A primitive: its clauses together (connection, request, reply, frame, timeout, `retry`,
`expect`, modem lines) and the error reply a device may send instead of the one asked for."""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.diagnostics import Label
from rdisc.semantics import model as m
from rdisc.semantics.check.pieces import MAX_TERMINATOR
from rdisc.semantics.check.replies import Replies, why_open
from rdisc.semantics.frame_facts import (
    payload_end_known,
)
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.operators import shown
from rdisc.semantics.types import Env, Names, describe
from rdisc.syntax import ast
from rdisc.syntax.precedence import octets

if TYPE_CHECKING:
    from typing import Any, TypeVar

    _Clause = TypeVar("_Clause")


def _of(clauses: dict[type, list[Any]], kind: type[_Clause]) -> list[_Clause]:
    """The clauses of one class, of a declaration's clauses grouped by their class."""
    found: list[_Clause] = clauses.get(kind, [])
    return found


MAX_RETRIES = 10  # resends of one request: each may wait a whole timeout
MAX_BREAK_MS = 10_000  # a serial break held longer is a line left low, not a break


class Primitives(Replies):
    """The rules of a primitive declaration."""

    def primitive(self, decl: ast.PrimitiveDecl) -> m.Primitive:
        name = decl.name
        # Its clauses by their class (each AST class is final: no clause is of a subclass), found
        # once where each kind's list was a pass over them (a tenth of checking a primitive).
        clauses: dict[type, list[Any]] = {}
        for clause in decl.clauses:
            clauses.setdefault(type(clause), []).append(clause)
        params = self.params(decl.params, "primitive")
        on = self.once(_of(clauses, ast.On), "`on`", name)
        if on is None:
            self.d.report("E202", name.span, f"primitive `{name.text}` has no connection",
                          help=f"add `on CONNECTION` after `{name.text}(...)`")
        encodings = _of(clauses, ast.Encoding)
        decodings = _of(clauses, ast.Decoding)
        action_blocks = _of(clauses, ast.Actions)
        lines_clause = self.once(_of(clauses, ast.Lines), "`lines`", name)
        replied = any(kind in clauses for kind in (ast.Decoding, ast.Framed, ast.ReplyTable, ast.ReplyList))
        if not encodings and (lines_clause is None or replied):
            self.d.report("E202", name.span, f"primitive `{name.text}` has neither `pack` nor `format`",
                          help='say how the request is written: `pack ">Bhh" (...)` or `format "D,{},{}\\n" (...)`'
                          if lines_clause is None else "a primitive that only sets `lines` writes no request, "
                          "so it has no reply and no frame")
        for extra in encodings[1:]:
            self.d.report("E203", extra.span, f"primitive `{name.text}` has more than one of `pack`/`format`",
                          labels=(Label(encodings[0].span, "first given here"),))
        for repeated in decodings[1:]:
            self.d.report("E203", repeated.span, f"primitive `{name.text}` has more than one of `unpack`/`regex`",
                          labels=(Label(decodings[0].span, "first given here"),))
        for block in action_blocks[1:]:
            self.d.report("E203", block.span, f"primitive `{name.text}` has more than one post-action block",
                          labels=(Label(action_blocks[0].span, "first given here"),))
        scope = {p.name: (Scope.PARAM, p.type) for p in params}  # one of a type in error: known, of type None
        env = self.env_with(scope, "in a primitive", "its parameters and state variables",
                            reply_note="`out`, the reply, is in scope only in post-actions")
        encoding: m.Pack | m.Format | None = None
        args: tuple[m.Expr, ...] = ()
        if encodings:
            encoding, args = self.encoding(encodings[0], env)
        decoding: m.Unpack | m.Regex | None = None
        reply: tuple[m.AnyType, ...] | None = ()
        if decodings:
            decoding, reply = self.decoding(decodings[0])
        records_clause = self.once(_of(clauses, ast.Records), "`reply each until`", name)
        if isinstance(records_clause, ast.Records):  # each record's post-actions read its position as `index`
            self.not_a_param(decl, m.INDEX, "the position of a record of the reply")
            scope = {**scope, m.INDEX: (Scope.PARAM, Type.INT)}
        replies_clause = self.once(_of(clauses, ast.Replies), "`replies`", name)
        count, reply_frames = self.reply_count(replies_clause, decl, reply, decoding, env, encoding) \
            if isinstance(replies_clause, ast.Replies) else (0, ())
        list_clause = self.once(_of(clauses, ast.ReplyList), "`replies { }`", name)
        listed = self.listed_replies(list_clause, decl, scope, env, encoding) \
            if isinstance(list_clause, ast.ReplyList) else ()
        actions: tuple[m.PostAction, ...] = ()
        if action_blocks:
            note = None if decodings else f"primitive `{name.text}` reads no reply: add `unpack` or `regex`"
            # A count only with scalar values (E401 for arrays): out[i] is the array of the i-th values.
            each_array = self.array_parameter(replies_clause, env) if isinstance(replies_clause, ast.Replies) else None
            size = count if each_array is None else each_array.size
            collected = tuple(m.Array(t, size) if isinstance(t, Type) else t for t in reply) \
                if count and reply is not None else reply
            refused = isinstance(replies_clause, ast.Replies) and not count  # reported: `out` unknown, no cascade
            action_env = self.env_with(
                scope, "in a post-action", "`out`, parameters and state variables",
                reply=None if refused else collected if decodings else None, reply_note=note,
                reply_known=reply is not None and not refused,
            )
            actions = self.actions(action_blocks[0], action_env, {p.name for p in params})
        expect = self.expect(decl, scope, reply, bool(decodings))
        connection = m.ConnectionRef(on.connection.text) if isinstance(on, ast.On) else m.ConnectionRef("")
        framed = self.once(_of(clauses, ast.Framed), "`frame`", name)
        # Read without a frame: none, or one whose reply is empty (a frame in error: neither)
        unframed = framed is None or (isinstance(framed, ast.Framed) and framed.frame.text in self.frames
                                      and not self.frames[framed.frame.text].reply)
        lines = self.modem_lines(lines_clause, env, name, connection) if isinstance(lines_clause, ast.Lines) else ()
        table_clause = self.once(_of(clauses, ast.ReplyTable), "a reply table", name)
        table = None
        if isinstance(table_clause, ast.ReplyTable):
            if decodings or action_blocks:
                self.d.report("E203", table_clause.span, f"primitive `{name.text}` has a reply table and also "
                              "`unpack`/`regex` or post-actions", help="give each of its replies in the table")
            if table_clause.tag is not None:
                self.not_a_param(decl, m.TAG, "the tag of the reply")
            table = self.reply_table(table_clause, params, scope, name, unframed)
        tagged = table is not None and table.tag is not None
        replies = [decoding] if decoding is not None else [c.decoding for c in table.cases] if table else \
            [r.decoding for r in listed if r.frame is None]  # read through the primitive's frame, or none
        frame = (self.frame_use(framed, env, decl, encoding, replies, self.request_sizes(encoding, args, params))
                 if isinstance(framed, ast.Framed) else None)
        records = self.records(records_clause, name, decodings, decoding, frame, count or len(listed), table) \
            if isinstance(records_clause, ast.Records) else None
        open_ends = [why for r in replies if isinstance(r, m.Unpack) and (why := why_open(r))]
        if (open_ends and (frame is None or not self.frames[frame.frame].reply) and not tagged  # tagged: E505
                and records_clause is None):  # records: E509
            self.d.report("E503", decodings[0].span if decodings else name.span,
                          f"the reply of `{name.text}` {open_ends[0]}, but no frame says where the reply ends",
                          help="read it through a frame with a `length` field or constant bytes after its payload")
        if (isinstance(table_clause, ast.ReplyTable) and tagged and frame is not None and self.frames[frame.frame].reply
                and not payload_end_known(self.frames[frame.frame], False)):
            self.d.report("E505", table_clause.span, f"the reply of `{name.text}` is chosen by its tag, so its frame "
                          "must say where the reply ends",
                          help="give the frame's reply a `length` field or constant bytes after its payload, "
                          "or read the reply without a frame")
        skip = self.once(_of(clauses, ast.SkipUnmatched), "`skip unmatched`", name)
        framed_all = bool(listed) and all(r.frame is not None or (frame and self.frames[frame.frame].reply)
                                          for r in listed)
        if skip is not None and not (tagged and unframed) and not framed_all and (
                not replies or frame is None or not self.frames[frame.frame].reply):
            self.d.report("E504", skip.span, f"`skip unmatched` reads past frames that do not decode, but "
                          f"`{name.text}` does not decode a framed reply",
                          help="give it a frame with a reply, and `unpack` or `regex`")
        timeout_clause = self.once(_of(clauses, ast.ReplyTimeout), "`timeout`", name)
        timeout = None
        if isinstance(timeout_clause, ast.ReplyTimeout):
            timeout = self.duration(timeout_clause.duration, "a timeout")
            if timeout is not None and timeout <= 0:
                self.d.report("E204", timeout_clause.span, "a timeout must be positive")
                timeout = None
            elif not replies and not listed and not (frame and self.frames[frame.frame].reply):
                self.d.report("E204", timeout_clause.span, f"`{name.text}` reads no reply, so it has no timeout")
        retry = self.once(_of(clauses, ast.Retry), "`retry`", name)
        replied = bool(replies or listed or (frame and self.frames[frame.frame].reply))
        writes = encoding is not None and (frame is not None or encoding != m.Format(""))  # `format "" ()` listens
        retries = self.retries(retry, name, writes, replied) if isinstance(retry, ast.Retry) else 0
        if expect is not None and table is not None:
            self.d.report("E203", expect.span, f"primitive `{name.text}` has a reply table and also `expect`",
                          help="`expect` checks the reply of a primitive with one decoding")
        error_clause = self.once(_of(clauses, ast.ErrorReply), "`error`", name)
        error = None
        if isinstance(error_clause, ast.ErrorReply):
            one = table is None and not count and not listed and records is None
            error = (self.error_when(error_clause, error_clause.when, decl, scope, reply, decoding, one)
                     if error_clause.when is not None else
                     self.error_reply(error_clause, decl, env, encoding, frame if one else None, decoding, one))
        return m.Primitive(name.text, params, connection, encoding, args, decoding, actions, decl.doc, decl.span,
                           frame, skip is not None, table, timeout, expect, lines, count, reply_frames, records,
                           listed, retries, error, self.replies_each(replies_clause, env, count))

    def replies_each(self, clause: object, env: Env, count: int) -> m.RepliesEach | None:
        """`replies id in ids` over an array parameter, when it was taken (`count`)."""
        if not count or not isinstance(clause, ast.Replies) or self.array_parameter(clause, env) is None:
            return None
        assert clause.var is not None and isinstance(clause.over, ast.Ref)  # array_parameter's
        return m.RepliesEach(clause.var.text, clause.over.name)

    def error_reply(self, clause: ast.ErrorReply, decl: ast.PrimitiveDecl, env: Env,
                    encoding: m.Pack | m.Format | None, frame: m.FrameUse | None,
                    decoding: m.Unpack | m.Regex | None, one: bool) -> m.ErrorReply | None:
        """`error [frame F(args)] ["MARKER"] unpack FORMAT [code ENUM]`: the reply the device may
        send instead of the one asked for, of a primitive that reads one reply (decoded, or a
        frame that acknowledges). It must be told apart from that reply before it is read: by its
        own frame, or by its first bytes; unframed, it has a fixed size. None where refused."""
        name = decl.name.text
        framed_reply = frame is not None and bool(self.frames[frame.frame].reply)
        if not one or not (framed_reply or isinstance(decoding, m.Unpack)):
            self.d.report("E511", clause.span, f"`{name}` does not read one reply that an error could stand in for",
                          help="an `error` reply goes with `unpack` (read with or without a frame) or a frame "
                          "that acknowledges, not with `regex`, `replies` or a reply table")
            return None
        marker = ""
        if clause.marker is not None:
            marker = clause.marker.value
            if not 1 <= len(marker) <= MAX_TERMINATOR or not octets(marker):
                self.d.report("E204", clause.marker.span,
                              f"an error's marker is 1 to {MAX_TERMINATOR} bytes (characters up to \\xff)")
                return None
        assert clause.decoding is not None  # `error when` has none: `error_when`
        if clause.decoding.kind != "unpack":
            self.d.report("E511", clause.decoding.span, "an error reply is bytes: decode it with `unpack`",
                          help='such as `unpack "B"`, the device\'s code')
            return None
        unpack, values = self.decoding(clause.decoding)
        if not isinstance(unpack, m.Unpack) or values is None:
            return None
        if clause.codes is not None and (not values or values[0] is not Type.INT):
            self.d.report("E511", clause.decoding.span, f"the first value of an error reply is the device's code, "
                          f"named by `{clause.codes.text}`, so it is an int",
                          help='decode it first with an integer code: `unpack "B"`')
            return None
        own = None
        if clause.frame is not None:
            own = self.frame_use(clause.frame, env, decl, encoding, [unpack], None)
            if own is None:
                return None
            reply = self.frames[own.frame].reply
            if not any(isinstance(part, m.FramePayload) for part in reply):
                if not reply:  # else `frame_use` said so
                    self.d.report("E504", clause.frame.span, f"the error reply of `{name}` is read through frame "
                                  f"`{own.frame}`, whose reply is empty",
                                  help="read it through a frame whose reply has a `payload`")
                return None
        elif not marker:
            self.d.report("E511", clause.span, f"the error reply of `{name}` cannot be told from its reply",
                          help='give it its own frame (`error frame rtu(unit, 0x83) ...`) or the bytes it starts '
                          'with (`error "\\x15" ...`)')
            return None
        elif framed_reply:
            assert frame is not None
            if not any(isinstance(part, m.FramePayload) for part in self.frames[frame.frame].reply):
                self.d.report("E511", clause.span, f"the error reply of `{name}` is known by its first bytes, but "
                              f"the reply of frame `{frame.frame}` has no payload to start with them",
                              help="give the error its own frame (`error frame nak() unpack \"B\"`)")
                return None
            if not payload_end_known(self.frames[frame.frame], False):
                self.d.report("E511", clause.span, f"the error reply of `{name}` is known by its first bytes, so "
                              f"frame `{frame.frame}` must say where a payload ends without its decoding",
                              help="give the frame's reply a `length` field or constant bytes after its payload, "
                              "or give the error its own frame")
                return None
        if own is None and not framed_reply and why_open(unpack):
            self.d.report("E511", clause.decoding.span, f"the error reply of `{name}` is read without a frame, "
                          "so its size is fixed: no `*`")
            return None
        return m.ErrorReply(unpack, own, marker, None if clause.codes is None else clause.codes.text)

    def error_when(self, clause: ast.ErrorReply, when: ast.Expr, decl: ast.PrimitiveDecl, scope: Names,
                   reply: tuple[m.AnyType, ...] | None, decoding: m.Unpack | m.Regex | None,
                   one: bool) -> m.ErrorReply | None:
        """`error when COND [code ENUM]`: the reply itself, decoded by the primitive's `unpack`, is
        the device's error when COND (a bool over `out`, the parameters and state) holds, its first
        value the code (a TMCL status below 100). None where refused."""
        name = decl.name.text
        if not one or not isinstance(decoding, m.Unpack):
            self.d.report("E511", clause.span, f"`{name}` does not decode one reply that could say it is an error",
                          help="`error when` goes with `unpack` (read with or without a frame), not with `regex`, "
                          "`replies` or a reply table")
            return None
        env = self.env_with(scope, "in an `error when`", "`out`, parameters and state variables", reply=reply,
                            reply_known=reply is not None)
        condition = self.typer.expr(when, env)
        if condition.type is not None and condition.type is not Type.BOOL:
            self.d.report("E401", when.span, f"`error when` takes a bool, but this is {describe(condition.type)}")
            return None
        if clause.codes is not None and reply is not None and (not reply or reply[0] is not Type.INT):
            self.d.report("E511", clause.span, f"the first value of `{name}`'s reply is the device's code when it "
                          f"is an error, named by `{clause.codes.text}`, so it is an int",
                          help='decode it first with an integer code: `unpack ">BBi"`')
            return None
        return m.ErrorReply(decoding, codes=None if clause.codes is None else clause.codes.text, when=condition)

    def retries(self, clause: ast.Retry, name: ast.Ident, writes: bool, replied: bool) -> int:
        """`retry N`: resends of a request whose reply timed out or did not match, a constant
        int from 1 to MAX_RETRIES, of a primitive that writes a request and reads a reply. 0
        where it is refused."""
        value = self.setting(clause.count, "a retry count", MAX_RETRIES)
        if value is None:
            return 0
        if not isinstance(value, int) or isinstance(value, bool) or value < 1:
            self.d.report("E204", clause.count.span,
                          f"a retry count is a constant int from 1 to {MAX_RETRIES}, not {shown(value)}")
            return 0
        if not replied:
            self.d.report("E204", clause.span, f"`{name.text}` reads no reply, so it has nothing to retry",
                          help="`retry` resends a request whose reply timed out or did not match")
            return 0
        if not writes:
            self.d.report("E204", clause.span, f"`{name.text}` writes no request, so it has nothing to resend",
                          help="a primitive that only listens waits for its reply within its `timeout`")
            return 0
        return value

    def modem_lines(self, clause: ast.Lines, env: Env, name: ast.Ident,
                    connection: m.ConnectionRef) -> tuple[m.LineLevel, ...]:
        """`lines dtr = COND, rts = COND`: each line of a serial port once, a bool over the
        parameters and state; a `tcp` connection has no modem lines."""
        conn = self.s.connections.get(connection)
        if conn is not None and conn.kind.text == "tcp":
            self.d.report("E211", clause.span, f"`{name.text}` sets modem lines, but connection `{connection}` is "
                          "`tcp`, which has none", help="DTR and RTS are a serial port's: use a `serial` connection")
        levels: list[m.LineLevel] = []
        seen: dict[str, ast.Assign | ast.LineBreak] = {}
        for setting in clause.settings:
            if isinstance(setting, ast.LineBreak):
                if m.BREAK in seen:
                    self.d.report("E203", setting.span, f"`break` is given twice in `{name.text}`",
                                  labels=(Label(seen[m.BREAK].span, "first given here"),))
                    continue
                seen[m.BREAK] = setting
                held = self.duration(setting.duration, "a break")
                if held is not None and not 0 < held <= MAX_BREAK_MS:
                    self.d.report("E211", setting.duration.span, f"a break is held from more than 0 to "
                                  f"{MAX_BREAK_MS} ms, not {shown(held)} ms",
                                  help="a serial break holds TX low for a few character times to a few "
                                  "hundred ms (pyserial's `send_break` holds it 250 ms)")
                elif held is not None:
                    levels.append(m.LineLevel(m.BREAK, m.Const(float(held), Type.FLOAT), setting.span))
                continue
            line = setting.target.text
            value = self.typer.expr(setting.value, env)
            if line not in m.MODEM_LINES:
                self.d.report("E211", setting.target.span, f"`{line}` is not a modem line a primitive sets",
                              help="a primitive sets `dtr` or `rts` (CTS, DSR, RI and CD are the device's)")
                continue
            if line in seen:
                self.d.report("E203", setting.target.span, f"`{line}` is given twice in `{name.text}`",
                              labels=(Label(seen[line].span, "first given here"),))
                continue
            seen[line] = setting
            if value.type is not None and value.type is not Type.BOOL:
                self.d.report("E401", setting.value.span, f"`{line}` takes a bool, but this is {describe(value.type)}")
            levels.append(m.LineLevel(line, value, setting.span))
        return tuple(levels)

    def expect(self, decl: ast.PrimitiveDecl, scope: Names, reply: tuple[m.AnyType, ...] | None,
               decodes: bool) -> m.Expr | None:
        """`expect COND`: a bool over the parameters, state and the decoded reply `out`
        (`reply`, its types: None when its template was reported)."""
        clause = self.once([c for c in decl.clauses if isinstance(c, ast.Expect)], "`expect`", decl.name)
        if not isinstance(clause, ast.Expect):
            return None
        note = None if decodes else f"primitive `{decl.name.text}` decodes no reply: add `unpack` or `regex`"
        env = self.env_with(scope, "in an `expect`", "`out`, parameters and state variables",
                            reply=reply if decodes else None, reply_note=note, reply_known=reply is not None)
        condition = self.typer.expr(clause.condition, env)
        if not decodes and not any(isinstance(c, ast.ReplyTable) for c in decl.clauses):  # a table: E203
            self.d.report("E202", clause.span, f"`expect` checks a decoded reply, but `{decl.name.text}` decodes none",
                          help="add `unpack` or `regex`")
        elif condition.type is not None and condition.type is not Type.BOOL:
            self.d.report("E401", clause.condition.span, f"`expect` takes a bool, but this is {describe(condition.type)}")
        return condition

    def not_a_param(self, decl: ast.PrimitiveDecl, local: str, what: str) -> None:
        """A name the post-actions read besides the parameters (a tagged reply's `tag`, a
        record's `index`): no parameter may have it."""
        for param in decl.params:
            if param.name.text == local:
                self.d.report("E104", param.name.span, f"`{local}` names {what} of `{decl.name.text}` "
                              "and cannot name a parameter of it", help="rename the parameter")
