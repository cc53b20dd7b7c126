"""Primitives: request and reply templates, post-actions, reply tables, listed replies, the
error reply, replies per frame; a parameter passed bare as format argument i takes the type of
value i of the template (thesis JSON has no types)."""

from __future__ import annotations

from rdisc.json_import.frames import Frames
from rdisc.json_import.reader import present, type_text
from rdisc.json_import.values import JArray, JBool, JObject, JString, JValue
from rdisc.semantics import formats
from rdisc.syntax import ast
from rdisc.syntax.printer import print_expr

_PRIMITIVE = (
    "name", "parameters", "parameterTypes", "parameterRanges", "parameterDefaults", "parameterUnits", "connection",
    "lines", "pack", "format", "formatArgs", "unpack", "regex", "recordsUntil", "frame", "skipUnmatched",
    "replyTable", "timeout", "retry", "replies", "repliesEach", "replyFrames", "replyList", "error", "expect", "postActions", "doc",
)  # fmt: skip
_FLOAT_SPECS = frozenset("eEfFgG%")


class Primitives(Frames):
    """The reading of primitives."""

    def primitive(self, obj: JObject) -> ast.PrimitiveDecl | None:
        m = self.members(obj, "a primitive", _PRIMITIVE)
        name = self.name(obj, m, "a primitive")
        clauses: list[ast.PrimitiveClause] = []
        connection = self.ident(m["connection"], "`connection`") if "connection" in m else None
        if connection is not None:
            clauses.append(ast.On(connection, connection.span))
        lines = self.object(m.get("lines"), "`lines`")
        if lines is not None:  # {"dtr": "<not on>", "break": 10, ...}: in the order they are set, a break in ms
            settings: list[ast.Assign | ast.LineBreak] = []
            for line_name, value in lines.members:
                line = self.ident(line_name, "a modem line")
                level = self.expr(value, "float" if line is not None and line.text == "break" else "bool")
                if line is None or level is None:
                    continue
                settings.append(ast.LineBreak(ast.Duration(level, "ms", level.span), level.span)
                                if line.text == "break" else ast.Assign(line, level, level.span))
            clauses.append(ast.Lines(tuple(settings), lines.span))
        encodings = [(kind, s) for kind in ("pack", "format") if (s := self.string(m.get(kind), f"`{kind}`"))]
        slots = _slot_types(*encodings[0]) if encodings else {}
        written = self.array(m.get("formatArgs"), "`formatArgs`")
        args = present([self.expr(a, slots.get(i)) for i, a in enumerate(written)])
        if written and not encodings:
            self.error(m["formatArgs"].span, "`formatArgs` without a `pack` or `format` to send them with")
        for kind, s in encodings:
            clauses.append(ast.Encoding(kind, ast.StrLit(s.value, s.span), args, s.span))
        for kind in ("unpack", "regex"):
            s = self.string(m.get(kind), f"`{kind}`")
            if s is not None:
                clauses.append(ast.Decoding(kind, ast.StrLit(s.value, s.span), s.span))
        marker = self.string(m.get("recordsUntil"), "`recordsUntil`")
        if marker is not None:
            clauses.append(ast.Records(ast.StrLit(marker.value, marker.span), marker.span))
        framed = self.framed(m.get("frame"))
        if framed is not None:
            clauses.append(framed)
        skip = m.get("skipUnmatched")
        if isinstance(skip, JBool) and skip.value:
            clauses.append(ast.SkipUnmatched(skip.span))
        if "timeout" in m:
            wait = self.expr(m["timeout"], "float")
            if wait is not None:
                clauses.append(ast.ReplyTimeout(ast.Duration(wait, "ms", wait.span), wait.span))
        if "retry" in m:
            count = self.expr(m["retry"], "int")
            if count is not None:
                clauses.append(ast.Retry(count, count.span))
        if "repliesEach" in m:
            each = self.replies_each(m["repliesEach"], m.get("replyFrames"))
            if each is not None:
                clauses.append(each)
        elif "replyFrames" in m:
            given = m.get("parameters")
            each = self.reply_frames(m["replyFrames"], {item.value for item in given.items if isinstance(item, JString)}
                                     if isinstance(given, JArray) else set())
            if each is not None:
                clauses.append(each)
        elif "replies" in m:
            count = self.expr(m["replies"], "int")
            if count is not None:
                clauses.append(ast.Replies(count, count.span))
        if "expect" in m:
            condition = self.reply_expr(m["expect"], "`expect`")
            if condition is not None:
                clauses.append(ast.Expect(condition, m["expect"].span))
        table = self.object(m.get("replyTable"), "`replyTable`")
        if table is not None:
            clauses.append(self.reply_table(table))
        if "replyList" in m:
            listed = present([self.listed_reply(r) for r in self.array(m["replyList"], "`replyList`")])
            clauses.append(ast.ReplyList(tuple(listed), m["replyList"].span))
        if "error" in m:
            error = self.error_reply(m["error"])
            if error is not None:
                clauses.append(error)
        actions = self.array(m.get("postActions"), "`postActions`")
        if actions:  # none is the default, left unsaid
            assigns = present([self.post_action(a) for a in actions])
            clauses.append(ast.Actions(assigns, m["postActions"].span))

        def infer(param: ast.Ident) -> str:
            bare = (
                i
                for i, a in enumerate(args)
                if isinstance(a, ast.Ref) and a.name == param.text and i in slots
            )
            return next((slots[i] for i in bare), "int")

        params = self.params(m, infer)
        if name is None:
            return None
        self.primitive_types[name.text] = tuple(type_text(p.type) for p in params)
        return ast.PrimitiveDecl(name, params, tuple(clauses), obj.span, self.doc(m))

    def listed_reply(self, v: JValue) -> ast.ListedReply | None:
        """One reply of `"replyList"`: its frame, `unpack` or `regex`, `expect` and post-actions."""
        obj = self.object(v, "a listed reply")
        if obj is None:
            return None
        r = self.members(obj, "a listed reply", ("frame", "unpack", "regex", "expect", "postActions"))
        kind = next((k for k in ("unpack", "regex") if k in r), None)
        template = self.string(r.get(kind), f"`{kind}`") if kind else None
        if kind is None or template is None:
            if kind is None:
                self.error(obj.span, "a listed reply has `unpack` or `regex`")
            return None
        decoding = ast.Decoding(kind, ast.StrLit(template.value, template.span), template.span)
        expect = self.reply_expr(r["expect"], "`expect`") if "expect" in r else None
        assigns = present([self.post_action(a) for a in self.array(r.get("postActions"), "`postActions`")])
        actions = ast.Actions(assigns, r["postActions"].span) if assigns else None
        return ast.ListedReply(decoding, obj.span, self.framed(r.get("frame")), expect, actions)

    def error_reply(self, v: JValue) -> ast.ErrorReply | None:
        """`"error"`: the reply the device may send instead: its frame, marker, `unpack` and `codes`."""
        obj = self.object(v, "`error`")
        if obj is None:
            return None
        e = self.members(obj, "`error`", ("frame", "marker", "unpack", "codes", "when"))
        codes = self.ident(e["codes"], "`codes`") if "codes" in e else None
        if "when" in e:  # `error when COND`: the reply itself, decoded as ever
            if "unpack" in e or "frame" in e or "marker" in e:
                self.error(obj.span, "an error reply `when` a condition holds has no `frame`, `marker` or `unpack`")
                return None
            condition = self.reply_expr(e["when"], "`when`")
            return None if condition is None else ast.ErrorReply(None, obj.span, codes=codes, when=condition)
        template = self.string(e.get("unpack"), "`unpack`")
        if template is None:
            if "unpack" not in e:
                self.error(obj.span, "an error reply has `unpack` (or `when`)")
            return None
        marker = self.string(e.get("marker"), "`marker`")
        decoding = ast.Decoding("unpack", ast.StrLit(template.value, template.span), template.span)
        return ast.ErrorReply(decoding, obj.span, self.framed(e.get("frame")),
                              None if marker is None else ast.StrLit(marker.value, marker.span), codes)

    def reply_table(self, obj: JObject) -> ast.ReplyTable:
        t = self.members(obj, "`replyTable`", ("key", "tag", "each", "length", "cases"))
        tag = self.string(t.get("tag"), "`tag`")
        flag = t.get("each")
        each = isinstance(flag, JBool) and flag.value
        if flag is not None and not isinstance(flag, JBool):
            self.error(flag.span, "`each` is true or false")
        length = self.string(t.get("length"), "`length`")
        if tag is not None:
            key = ast.Ident("tag", tag.span)
        else:
            named = self.required(obj, t, "key", "`replyTable`", self.ident)
            key = named or ast.Ident("", obj.span)
        entries = []
        for item in self.array(t.get("cases"), "`cases`"):
            case = self.object(item, "a reply table entry")
            if case is None:
                continue
            c = self.members(case, "a reply table entry", ("value", "last", "unpack", "regex", "until", "postActions",
                                                            "tag", "cases"))
            value = self.required(case, c, "value", "a reply table entry", lambda v, _: self.expr(v, "int"))
            last = self.expr(c["last"], "int") if "last" in c else None  # a range entry: `value..last`
            if "tag" in c and value is not None:  # a nested table: the next tag chooses among its entries
                inner = self.reply_table(JObject(tuple(kv for kv in case.members if kv[0].value in ("tag", "cases")),
                                                 case.span))
                entries.append(ast.ReplyEntry(value, None, None, case.span, last, table=inner))
                continue
            kind = next((k for k in ("unpack", "regex") if k in c), None)
            template = self.string(c.get(kind), f"`{kind}`") if kind else None
            if value is None or kind is None or template is None or ("last" in c and last is None):
                if kind is None:
                    self.error(case.span, "a reply table entry has `unpack` or `regex`")
                continue
            assigns = present([self.post_action(a) for a in self.array(c.get("postActions"), "`postActions`")])
            decoding = ast.Decoding(kind, ast.StrLit(template.value, template.span), template.span)
            actions = ast.Actions(assigns, c["postActions"].span) if assigns else None
            until = self.string(c["until"], "`until`") if "until" in c else None
            entries.append(ast.ReplyEntry(value, decoding, actions, case.span, last,
                                          None if until is None else ast.StrLit(until.value, until.span)))
        if (each or length is not None) and tag is None:
            self.error(obj.span, "a reply table of sub-payloads (`each`, `length`) has a `tag`")
        return ast.ReplyTable(key, tuple(entries), obj.span,
                              None if tag is None else ast.StrLit(tag.value, tag.span), each and tag is not None,
                              None if length is None or tag is None else ast.StrLit(length.value, length.span))

    def replies_each(self, v: JValue, frames: JValue | None) -> ast.Replies | None:
        """`"repliesEach": {"variable": "id", "over": "ids"}` with its one reply frame in
        `"replyFrames"`, its arguments reading the variable: `replies id in ids frame status(id)`."""
        obj = self.object(v, "`repliesEach`")
        if obj is None:
            return None
        given = self.members(obj, "`repliesEach`", ("variable", "over"))
        var, over = (self.required(obj, given, key, "`repliesEach`", self.ident) for key in ("variable", "over"))
        listed = self.array(frames, "`replyFrames`") if frames is not None else []
        if len(listed) != 1:
            self.error(obj.span, "`repliesEach` reads every reply through one frame: `replyFrames` lists it alone")
            return None
        framed = self.framed(listed[0])
        if var is None or over is None or framed is None:
            return None
        return ast.Replies(ast.Ref(over.text, over.span), obj.span, var, None, framed)

    def reply_frames(self, v: JValue, params: set[str]) -> ast.Replies | None:
        """`"replyFrames"`, each reply's frame written out, as `replies reply in 0..N-1 frame
        NAME(args)`: an argument that differs between replies is `[a0, a1, ...][reply]`."""
        objects = [f for f in self.array(v, "`replyFrames`") if isinstance(f, JObject)]
        frames = [self.members(f, "a reply frame", ("name", "arguments")) for f in objects]
        names = {self.name(obj, f, "a reply frame") for obj, f in zip(objects, frames)}
        if len(frames) < 2 or len(names) != 1 or None in names:
            self.error(v.span, "`replyFrames` names one frame, for each of two replies or more")
            return None
        frame = names.pop()
        assert frame is not None
        rows = [self.args(f.get("arguments"), self.frame_types.get(frame.text, ())) for f in frames]
        if len({len(row) for row in rows}) != 1:
            self.error(v.span, "every reply frame of `replyFrames` takes as many arguments")
            return None
        var = ast.Ident(next(n for n in ("reply", "reply_", "reply__", "reply_n") if n not in params), v.span)
        ref = ast.Ref(var.text, v.span)
        columns = list(zip(*rows))
        varying = [c for c in columns if len({print_expr(a) for a in c}) > 1]
        # Elements of array parameters, as written (`ids[i]`), so that build and import in turn
        # do not grow them: the range starts where their indexes do, when they all start at one.
        indexed = {id(c): found for c in varying if (found := _indexed(c)) is not None}
        starts = {start for _, start in indexed.values()}
        start = starts.pop() if len(starts) == 1 and len(indexed) == len(varying) else 0
        args = [column[0] if column not in varying
                else ast.Index(indexed[id(column)][0], ref, v.span)
                if id(column) in indexed and indexed[id(column)][1] == start
                else ast.Index(ast.ArrayLit(column, v.span), ref, v.span)
                for column in columns]
        framed = ast.Framed(frame, tuple(args), v.span)
        return ast.Replies(ast.IntLit(start, v.span), v.span, var, ast.IntLit(start + len(rows) - 1, v.span), framed)


def _slot_types(kind: str, template: JString) -> dict[int, str]:
    """The type each format argument takes, by position: struct codes for `pack`;
    for `format`, the spec's type (e/f/g/% float, anything else int)."""
    try:
        if kind == "pack":
            return {i: slot.type.value for i, slot in enumerate(formats.struct_layout(template.value).slots)}
        specs = formats.format_fields(template.value)
    except formats.TemplateError:  # the checker reports it; nothing to infer from
        return {}
    return {i: "float" if f.spec[-1:] and f.spec[-1] in _FLOAT_SPECS else "int" for i, f in enumerate(specs)}


def _indexed(column: tuple[ast.Expr, ...]) -> tuple[ast.Ref, int] | None:
    """`a[K], a[K+1], ..., a[K+N-1]`: (`a`, K), a reply frame's argument written from an array
    parameter by the loop variable, which import writes back as `a[var]`."""
    first = column[0]
    if not (isinstance(first, ast.Index) and isinstance(first.base, ast.Ref) and isinstance(first.index, ast.IntLit)):
        return None
    name, start = first.base.name, first.index.value
    for number, arg in enumerate(column, start):
        if not (isinstance(arg, ast.Index) and isinstance(arg.base, ast.Ref) and arg.base.name == name
                and isinstance(arg.index, ast.IntLit) and arg.index.value == number):
            return None
    return first.base, start
