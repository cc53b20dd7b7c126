"""How a primitive reads its replies: `replies N`, `replies { }`, records, reply tables (tags,
nested tables, sized and open entries, sub-payloads), and the post-actions that store them."""

from __future__ import annotations

from rdisc.diagnostics import Label, abbreviate
from rdisc.frozen import replace
from rdisc.limits import MAX_ARRAY
from rdisc.semantics import formats
from rdisc.semantics import model as m
from rdisc.semantics.check.layouts import Layouts
from rdisc.semantics.check.pieces import MAX_TERMINATOR
from rdisc.semantics.frame_facts import (
    payload_end_known,
)
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.operators import shown
from rdisc.semantics.resolve import suggest
from rdisc.semantics.types import Env, Names, describe
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.precedence import octets

MAX_TABLE = 4096  # entries of a reply table


class Replies(Layouts):
    """The rules of a primitive's replies and post-actions."""

    def listed_replies(self, clause: ast.ReplyList, decl: ast.PrimitiveDecl, scope: dict[str, tuple[Scope, m.AnyType]],
                       env: Env, encoding: m.Pack | m.Format | None) -> tuple[m.ListedReply, ...]:
        """`replies { ... }`: 2 to MAX_ARRAY replies in a fixed order, each decoded its own way,
        held by its own `expect` and stored by its own post-actions, through its own frame (one
        whose reply carries a payload) or the primitive's. () where it is refused."""
        name = decl.name.text
        given = ((ast.Decoding, "`unpack`/`regex`"), (ast.Actions, "post-actions"), (ast.Expect, "`expect`"),
                 (ast.ReplyTable, "a reply table"), (ast.Replies, "`replies N`"))
        other = next((what for kind, what in given if any(isinstance(c, kind) for c in decl.clauses)), None)
        if other is not None:
            self.d.report("E203", clause.span, f"primitive `{name}` has `replies {{ }}` and also {other}",
                          help="each reply of `replies { }` has its own decoding, `expect` and post-actions: "
                          "write them there")
            return ()
        if not 2 <= len(clause.replies) <= MAX_ARRAY:
            self.d.report("E204", clause.span, f"a primitive reads 2 to {MAX_ARRAY} replies, not "
                          f"{len(clause.replies)}", help="a primitive that reads one reply says how with `unpack` "
                          "or `regex` alone")
            return ()
        sees = "`out`, parameters and state variables"
        listed: list[m.ListedReply] = []
        for n, r in enumerate(clause.replies, 1):
            decoding, reply = self.decoding(r.decoding)
            expect = None
            if r.expect is not None:
                expect = self.typer.expr(r.expect, self.env_with(scope, "in an `expect`", sees, reply=reply,
                                                                 reply_known=reply is not None))
                if expect.type is not None and expect.type is not Type.BOOL:
                    self.d.report("E401", r.expect.span, f"`expect` takes a bool, but this is {describe(expect.type)}")
            actions: tuple[m.PostAction, ...] = ()
            if r.actions is not None:
                action_env = self.env_with(scope, "in a post-action", sees, reply=reply, reply_known=reply is not None)
                actions = self.actions(r.actions, action_env, set(scope))
            frame = None
            if r.frame is not None:
                frame = self.frame_use(r.frame, env, decl, encoding, [decoding] if decoding else [], None)
                if frame is not None and not self.frames[frame.frame].reply:
                    self.d.report("E504", r.frame.span, f"reply {n} of `{name}` is read through frame "
                                  f"`{frame.frame}`, whose reply is empty",
                                  help="read it through a frame whose reply has a `payload`, or through the "
                                  "primitive's frame (leave out its `frame`)")
            if decoding is not None:
                listed.append(m.ListedReply(decoding, frame, expect, actions))
        return tuple(listed) if len(listed) == len(clause.replies) else ()

    def records(self, clause: ast.Records, name: ast.Ident, decodings: list[ast.Decoding],
                decoding: m.Unpack | m.Regex | None, frame: m.FrameUse | None, count: int,
                table: m.ReplyTable | None) -> str | None:
        """`reply each until "\\x7F"`: a framed payload of records, each ended by the marker (1 to
        8 constant bytes) and decoded by the primitive's one `unpack`; not with `replies` or a
        reply table, which read replies otherwise. The marker, or None where refused."""
        marker = clause.marker
        said = f"`{name.text}` reads its reply as records"
        if not 1 <= len(marker.value) <= MAX_TERMINATOR or not octets(marker.value):
            self.d.report("E509", marker.span, f"a record's end marker is 1 to {MAX_TERMINATOR} bytes "
                          "(characters up to \\xff)")
            return None
        if count or table is not None:
            self.d.report("E509", clause.span, f"{said}, so it reads one reply, not "
                          + ("several (`replies`)" if count else "one chosen by a reply table"),
                          help="each record is decoded by the primitive's `unpack`")
            return None
        if not isinstance(decoding, m.Unpack):
            if decodings and decoding is None:  # its template was reported
                return None
            self.d.report("E509", decodings[0].span if decodings else clause.span,
                          f"{said}, each decoded by an `unpack`" + (", not a `regex`" if decodings else ""),
                          help='e.g. `reply each until "\\x7F" unpack "<*(BB)"`, pairs of bytes until the marker')
            return None
        if frame is None or not self.frames[frame.frame].reply or not payload_end_known(self.frames[frame.frame], False):
            self.d.report("E509", clause.span, f"{said} until its payload ends, so it is read through a frame "
                          "that says where that is",
                          help="give the primitive a frame whose reply has a `length` field or constant bytes "
                          "after its payload")
            return None
        return marker.value

    def reply_count(self, clause: ast.Replies, decl: ast.PrimitiveDecl, reply: tuple[m.AnyType, ...] | None,
                    decoding: m.Unpack | m.Regex | None, env: Env,
                    encoding: m.Pack | m.Format | None) -> tuple[int, tuple[m.FrameUse, ...]]:
        """`replies N` (a constant int) or `replies id in IDS frame status(id)` (a reply, with its
        own frame, a value): 2 to MAX_ARRAY replies, of a primitive with one decoding whose values
        are not arrays (each value of the replies is one, of N). (0, ()) where it is refused."""
        name = decl.name.text
        frames: tuple[m.FrameUse, ...] = ()
        array = self.array_parameter(clause, env)
        if clause.var is None:
            value = self.setting(clause.over, "a reply count", MAX_ARRAY)
        elif array is not None:  # as many as the caller gives: the most, for the link budget
            found = self.reply_frame_each(clause, decl, decoding, env, encoding, array)
            if found is None:
                return 0, ()
            value, frames = array.size or MAX_ARRAY, (found,)
        else:
            found_all = self.reply_frames(clause, decl, decoding, env, encoding)
            if found_all is None:
                return 0, ()
            value, frames = len(found_all), found_all
        if value is None:
            return 0, ()
        if array is None and (not isinstance(value, int) or isinstance(value, bool) or not 2 <= value <= MAX_ARRAY):
            said = f"a reply count is a constant int from 2 to {MAX_ARRAY}, not {shown(value)}" \
                if clause.var is None else f"a primitive reads 2 to {MAX_ARRAY} replies, not {value}"
            self.d.report("E204", clause.over.span if clause.var is None else clause.span, said)
            return 0, ()
        if decoding is None:
            self.d.report("E202", clause.span, f"`{name}` reads {value} replies, but decodes none",
                          help="say how each reply is read: `unpack` or `regex` (a reply table chooses one reply)")
            return 0, ()
        if reply is not None and any(isinstance(t, m.Array) for t in reply):
            self.d.report("E401", clause.span, f"`{name}` reads {value} replies, whose values are arrays: "
                          "each value of the replies would be an array of arrays",
                          help="read a reply of single values, or one reply with a repeated group")
            return 0, ()
        assert isinstance(value, int)  # a constant int from 2 to MAX_ARRAY, or an array's size
        return value, frames

    @staticmethod
    def array_parameter(clause: ast.Replies, env: Env) -> m.Array | None:
        """The type of the array parameter `replies id in ids` goes over, if it goes over one."""
        if clause.var is None or clause.high is not None or not isinstance(clause.over, ast.Ref):
            return None
        scope, type_ = env.names.get(clause.over.name, (None, None))
        return type_ if scope is Scope.PARAM and isinstance(type_, m.Array) else None

    def reply_frame_each(self, clause: ast.Replies, decl: ast.PrimitiveDecl, decoding: m.Unpack | m.Regex | None,
                         env: Env, encoding: m.Pack | m.Format | None, array: m.Array) -> m.FrameUse | None:
        """`replies id in ids frame status(id)` over an array parameter: the one reply frame, its
        arguments over the parameters and the element, `id`, known when it runs; None in error."""
        assert clause.var is not None and clause.frame is not None
        if not self.loop_variable(clause.var, decl.params, {}):
            return None
        own = replace(env, names={**env.names, clause.var.text: (Scope.PARAM, array.element)})
        errors = self.d.error_count
        use = self.frame_use(clause.frame, own, decl, encoding, [decoding] if decoding else [], None)
        return None if use is None or self.d.error_count > errors else use

    def reply_frames(self, clause: ast.Replies, decl: ast.PrimitiveDecl, decoding: m.Unpack | m.Regex | None,
                     env: Env, encoding: m.Pack | m.Format | None) -> tuple[m.FrameUse, ...] | None:
        """`replies id in IDS frame status(id)`: each reply's frame, written out with the variable
        a constant in each (its arguments, constant ones as their values); None where in error."""
        assert clause.var is not None and clause.frame is not None
        if not self.loop_variable(clause.var, decl.params, {}):
            return None
        found = self.constant_values(clause.over, clause.high, env, replies=True)
        if found is None:
            return None
        type_, values = found
        if len(values) > MAX_ARRAY:  # before any is written out
            self.d.report("E204", clause.span, f"a primitive reads 2 to {MAX_ARRAY} replies, not {len(values)}")
            return None
        frames: list[m.FrameUse] = []
        name = clause.var.text  # no constant has it (loop_variable): bound as one, then gone
        for value in values:
            self.typer.named[name] = (type_, value)
            errors = self.d.error_count
            use = self.frame_use(clause.frame, env, decl, encoding, [decoding] if decoding else [], None)
            if use is None or self.d.error_count > errors:
                break
            frames.append(replace(use, args=tuple(self.value_of(a) for a in use.args)))
        del self.typer.named[name]
        return tuple(frames) if len(frames) == len(values) else None

    def reply_table(self, clause: ast.ReplyTable, params: tuple[m.Parameter, ...], scope: Names,
                    name: ast.Ident, unframed: bool, nested: bool = False) -> m.ReplyTable | None:
        """`reply KEY { VALUE: unpack ... }`: one reply per value of an int parameter with a range,
        every value of the range with its entry. `reply tag "fmt" { ... }`: one per tag value; read
        without a frame, each entry's size fixed (the tag says how much follows it)."""
        key = clause.key.text
        tag_slot = None
        tag_layout: m.StructLayout | None = None
        length_layout: m.StructLayout | None = None  # `each`'s length field, if given
        param: m.Parameter | None
        if clause.tag is not None:
            try:
                tag_layout = formats.struct_layout(clause.tag.value)
            except formats.TemplateError as err:
                self.d.report("E301", clause.tag.span, err.message)
                return None
            if len(tag_layout.slots) != 1 or tag_layout.slots[0].type is not Type.INT:
                self.d.report("E505", clause.tag.span, "a reply tag is one integer: a struct format such as "
                              f"\"B\" or \">H\", not \"{abbreviate(clause.tag.value)}\"")
                return None
            tag_slot = tag_layout.slots[0]
            param = m.Parameter(key, Type.INT, tag_slot.low, tag_slot.high)
            if not self.sub_payloads(clause, name, unframed):
                return None
            if clause.each and clause.length is not None:
                length_layout = self.length_field(clause.length)
                if length_layout is None:
                    return None
        else:
            param = next((p for p in params if p.name == key), None)
        if param is None:
            self.d.report("E103", clause.key.span, f"`{key}` is not a parameter of `{name.text}`",
                          help=suggest(key, [p.name for p in params]) or "a reply table's key is a parameter")
            return None
        if param.type is not Type.INT:
            self.d.report("E401", clause.key.span, f"a reply table's key is an int parameter; `{key}` is not")
            return None
        cases: list[m.ReplyCase] = []
        seen: dict[int, ast.ReplyEntry] = {}
        if clause.tag is not None:  # its entries see the tag's value
            scope = {**scope, m.TAG: (Scope.PARAM, Type.INT)}
        sees = ("`out`, `tag`, " if clause.tag is not None else "`out`, ") + "parameters and state variables"
        for entry in clause.entries:
            bounds = self.entry_values(entry, tag_slot)
            if bounds is None:
                continue
            low, high = bounds
            if len(seen) + high - low >= MAX_TABLE:
                self.d.report("E505", entry.span, f"the reply table of `{name.text}` has entries for more than "
                              f"{MAX_TABLE} values", help="a reply table holds a few thousand values at most")
                continue
            twice = next((v for v in range(low, high + 1) if v in seen), None)
            if twice is not None:
                self.d.report("E203", _values_span(entry), f"{twice} has two entries in the reply table",
                              labels=(Label(_values_span(seen[twice]), "first given here"),))
                continue
            seen.update(dict.fromkeys(range(low, high + 1), entry))
            if entry.table is not None:
                cases.extend(self.nested_table(clause, entry, entry.table, low, params, scope, name, unframed, nested))
                continue
            assert entry.decoding is not None  # the grammar's: an entry decodes, or has a table
            decoding, reply = self.decoding(entry.decoding)
            if entry.until is not None:
                decoding = self.until(entry, decoding, name, clause.tag is not None and unframed)
            elif clause.each:
                self.sub_payload_entry(clause, entry, decoding, low, high, length_layout)
            elif clause.tag is not None and unframed:
                self.sized_entry(entry, decoding, name, low, high)
            actions: tuple[m.PostAction, ...] = ()
            if entry.actions is not None:
                action_env = self.env_with(scope, "in a post-action", sees, reply=reply, reply_known=reply is not None)
                actions = self.actions(entry.actions, action_env, {p.name for p in params})
            if decoding is not None:
                cases.append(m.ReplyCase(low, decoding, actions, None if entry.last is None else high))
        if clause.tag is not None:  # an unknown tag is a protocol error when it comes: no coverage to check
            return m.ReplyTable("", tuple(cases), clause.tag.value, clause.each,
                                None if clause.length is None else clause.length.value, tag_layout=tag_layout,
                                length_layout=length_layout)
        if param.low is None:
            self.d.report("E505", clause.key.span, f"`{key}` has no range, so the reply table of `{name.text}` "
                          "cannot have an entry for each of its values",
                          help=f"declare its range: `{key}: int in LOW..HIGH`")
        elif param.high - param.low >= MAX_TABLE:  # type: ignore[operator]
            self.d.report("E505", clause.key.span, f"the range of `{key}` has {param.high - param.low + 1} values, "  # type: ignore[operator]
                          f"more than a reply table holds ({MAX_TABLE})", label=f"in {param.range_text()}")
        else:
            missing = [v for v in range(int(param.low), int(param.high) + 1) if v not in seen]  # type: ignore[arg-type]
            if missing:
                shown_ = ", ".join(map(str, missing[:6])) + (f" and {len(missing) - 6} more" if len(missing) > 6 else "")
                self.d.report("E505", clause.key.span, f"the reply table of `{name.text}` has no entry for "
                              f"{key} = {shown_}", label=f"in {param.range_text()}",
                              help="give every value of the range its reply, or narrow the range")
        return m.ReplyTable(key, tuple(cases))

    def nested_table(self, clause: ast.ReplyTable, entry: ast.ReplyEntry, table: ast.ReplyTable, value: int,
                     params: tuple[m.Parameter, ...], scope: Names, name: ast.Ident, unframed: bool,
                     nested: bool) -> list[m.ReplyCase]:
        """`VALUE: tag "fmt" { ... }`: after the tag VALUE, the next tag chooses among the nested
        table's entries (Firmata's sysex: F0, then the sub-command). One level, of a tagged reply
        read without a frame, for one value; its entries checked as the table's own."""
        assert table.tag is not None  # the grammar's
        if clause.tag is None or not unframed or clause.each or nested or entry.last is not None:
            why = ("a nested table is for one tag value, not a range" if entry.last is not None
                   else "a nested table holds no nested table" if nested
                   else f"`{name.text}` reads no tagged reply without a frame")
            self.d.report("E505", table.tag.span, f"a nested tag table is an entry of a tagged reply read without a "
                          f"frame, one level deep: {why}",
                          help='e.g. `0xF0: tag "B" { 0x79: unpack "BB*" until "\\xF7" }`, Firmata\'s sysex')
            return []
        inner = self.reply_table(table, params, scope, name, unframed, nested=True)
        if inner is None:
            return []
        return [replace(c, under=value, under_tag=table.tag.value, under_layout=inner.tag_layout) for c in inner.cases]

    def sub_payloads(self, clause: ast.ReplyTable, name: ast.Ident, unframed: bool) -> bool:
        """`reply each tag "B" length "B"`: sub-payloads until the framed payload ends, each its
        length an unsigned integer after its tag. Whether the table can be read so."""
        if not clause.each:
            return True
        if unframed:
            self.d.report("E505", clause.span, f"the reply of `{name.text}` is a sequence of sub-payloads until its "
                          "payload ends, so it is read through a frame", help="give the primitive a frame whose reply "
                          "has a `length` field or constant bytes after its payload")
            return False
        return True

    def length_field(self, length: ast.StrLit) -> m.StructLayout | None:
        """The layout of a sub-payload's length field (`length "B"`): one unsigned integer."""
        try:
            layout = formats.struct_layout(length.value)
        except formats.TemplateError as err:
            self.d.report("E301", length.span, err.message)
            return None
        if len(layout.slots) != 1 or layout.slots[0].type is not Type.INT or (layout.slots[0].low or 0) < 0:
            self.d.report("E505", length.span, "a sub-payload's length is one unsigned integer: a struct "
                          f"format such as \"B\" or \"<H\", not \"{abbreviate(length.value)}\"")
            return None
        return layout

    def sub_payload_entry(self, clause: ast.ReplyTable, entry: ast.ReplyEntry, decoding: m.Unpack | m.Regex | None,
                          low: int, high: int, length: m.StructLayout | None) -> None:
        """An entry of sub-payloads decodes its bytes with an `unpack`: of a fixed size without a
        length field (the size says where the next tag starts), one the length field can state."""
        which = f"tag {low}" if low == high else f"tags {low}..{high}"
        if isinstance(decoding, m.Regex):
            self.d.report("E505", _decoding_span(entry), f"the sub-payload of {which} is bytes: decode it with `unpack`")
            return
        if not isinstance(decoding, m.Unpack):
            return
        open_end = why_open(decoding)
        if clause.length is None and open_end:
            self.d.report("E505", _decoding_span(entry), f"the sub-payloads have no length field, so the entry for "
                          f"{which} needs a fixed size, but it {open_end}",
                          help='give each sub-payload its length: `reply each tag "B" length "B" { ... }`')
        elif clause.length is not None and length is not None and not open_end:
            size = decoding.layout.size
            most = length.slots[0].high or 0
            if size > most:
                self.d.report("E505", _decoding_span(entry), f"the entry for {which} decodes {size} bytes, more than "
                              f"a sub-payload's length field \"{clause.length.value}\" states ({most})")

    def sized_entry(self, entry: ast.ReplyEntry, decoding: m.Unpack | m.Regex | None, name: ast.Ident,
                    low: int, high: int) -> None:
        """A tagged reply read without a frame: the entry's decoding says how many bytes follow the tag."""
        if isinstance(decoding, m.Regex):
            why = "it is a `regex`"
        elif isinstance(decoding, m.Unpack) and (open_end := why_open(decoding)):
            why = f"it {open_end}"
        else:
            return
        which = f"tag {low}" if low == high else f"tags {low}..{high}"
        self.d.report("E505", _decoding_span(entry), f"`{name.text}` reads its reply without a frame, so its entry for "
                      f"{which} needs a fixed size, but {why}",
                      help="decode it with an `unpack` of a fixed size, or read the reply through a frame that says "
                      "where it ends")

    def until(self, entry: ast.ReplyEntry, decoding: m.Unpack | m.Regex | None, name: ast.Ident,
              unframed_tag: bool) -> m.Unpack | None:
        """`until "\\xF7"`: an unframed tagged reply's entry read to its end marker (Firmata's sysex),
        the marker dropped and what is before it decoded by an `unpack` ending in `*`."""
        until = entry.until
        assert until is not None
        if not unframed_tag:
            self.d.report("E505", until.span, f"`until` is for a tagged reply read without a frame, and `{name.text}`"
                          " does not read one", help="a frame, or a reply table's key, already says where it ends")
            return None
        if not 1 <= len(until.value) <= MAX_TERMINATOR or not octets(until.value):
            self.d.report("E505", until.span, f"`until` is 1 to {MAX_TERMINATOR} bytes (characters up to \\xff)")
            return None
        if not isinstance(decoding, m.Unpack):
            if decoding is not None:
                self.d.report("E505", _decoding_span(entry), "an entry read `until` its end is decoded by an `unpack`")
            return None
        layout = decoding.layout
        if not layout.rest or layout.varying is not None:
            self.d.report("E505", _decoding_span(entry), "an entry read `until` its end takes what comes before the "
                          "end as bytes: its `unpack` ends in `*`",
                          help='e.g. `0xF0: unpack "B*" until "\\xF7"`, the bytes of a Firmata sysex message')
            return None
        return m.Unpack(decoding.format, layout, until.value)

    def entry_values(self, entry: ast.ReplyEntry, tag_slot: formats.Slot | None) -> tuple[int, int] | None:
        """The first and last value a reply table's entry is for (`VALUE`, or `LOW..HIGH`),
        each an int constant that fits the tag's code; None when reported."""
        ends: list[int] = []
        for expr in (entry.value,) if entry.last is None else (entry.value, entry.last):
            value = self.setting(expr, "a reply table's value")
            if value is None:
                return None
            if value != int(value):
                self.d.report("E204", expr.span, "a reply table's value is an int")
                return None
            if tag_slot is not None and not tag_slot.low <= value <= tag_slot.high:  # type: ignore[operator]
                self.d.report("E403", expr.span, f"{int(value)} does not fit the tag's `{tag_slot.code}`")
                return None
            ends.append(int(value))
        if ends[-1] < ends[0]:
            self.d.report("E204", _values_span(entry), f"the range {ends[0]}..{ends[-1]} is empty")
            return None
        return ends[0], ends[-1]

    def actions(self, block: ast.Actions, env: Env, params: set[str]) -> tuple[m.PostAction, ...]:
        """Post-actions; the elements stored into one array (`position[id] = out[0]`) are one
        action, the array with each element replaced in turn."""
        out: list[m.PostAction] = []
        written: dict[str, ast.Assign] = {}
        for assign in block.assigns:
            value = self.typer.expr(assign.value, env)
            target = assign.target.text
            when = None
            if assign.when is not None:  # made only if it holds: the state variable is read to keep it
                when = self.typer.expr(assign.when, env)
                if when.type is not None and when.type is not Type.BOOL:
                    self.d.report("E401", assign.when.span, f"`when` takes a bool, but this is {describe(when.type)}")
                self.typer.reads.add(target)
            state = self.s.states.get(target)
            if state is None and target in self.settings:
                self.d.report("E207", assign.target.span, f"cannot assign `{target}`: it is a setting, given when "
                              "connecting", help="a setting is read-only: keep what the device reports in a "
                              "state variable")
                continue
            if state is None:
                what = "it is a parameter" if target in params else "it is not a state variable"
                self.d.report(
                    "E207", assign.target.span, f"cannot assign `{target}`: {what}",
                    help=suggest(target, self.s.states) or "post-actions write state variables, and only they do",
                )
                continue
            declared = self.state_env.get(target, (None, None))[1]
            first = written.get(target)
            if first is not None and (assign.index is None or first.index is None):
                self.d.report("E203", assign.target.span, f"state variable `{target}` is assigned twice",
                              labels=(Label(first.target.span, "first assigned here"),))
            if assign.index is None:
                written[target] = assign
                if isinstance(declared, m.Array) and declared.size and isinstance(value.type, m.Array) \
                        and not value.type.size:  # nothing would check its size when it runs
                    self.d.report("E401", assign.value.span, f"state variable `{target}` holds {describe(declared)}, "
                                  "but this array has any size", help=f"declare it `{declared.element.value}[]`")
                    continue
                self.flow(value, declared, assign.value.span, f"state variable `{target}`")
                out.append(m.PostAction(m.StateRef(target), value, assign.span, when))
                continue
            if not isinstance(declared, m.Array):
                if declared is not None:
                    self.d.report("E404", assign.index.span, f"`{target}` is not an array: it is {describe(declared)}")
                continue
            index = self.typer.expr(assign.index, env)
            if index.type is not None and index.type is not Type.INT:
                self.d.report("E404", assign.index.span, f"an index is an int, not {describe(index.type)}")
            self.typer.in_array(declared, index, target, assign.index.span)
            self.flow(value, declared.element, assign.value.span, f"an element of `{target}`")
            self.typer.reads.add(target)
            if first is not None and first.index is not None:  # replace one more element of the same array
                before = next(k for k, a in enumerate(out) if a.target == target)
                out[before] = m.PostAction(m.StateRef(target), m.Replaced(out[before].value, index, value, declared,
                                                                          assign.span, when), out[before].span)
            else:
                written[target] = assign
                whole = m.Var(target, Scope.STATE, declared, assign.target.span)
                out.append(m.PostAction(m.StateRef(target), m.Replaced(whole, index, value, declared, assign.span,
                                                                       when), assign.span))
        return tuple(out)


def _decoding_span(entry: ast.ReplyEntry) -> Span:
    """Where an entry's decoding is written (the entry, for a nested table's)."""
    return entry.span if entry.decoding is None else entry.decoding.span


def _values_span(entry: ast.ReplyEntry) -> Span:
    """Where a reply table's entry says its value, or its range of values."""
    return entry.value.span if entry.last is None else entry.value.span.to(entry.last.span)


def why_open(decoding: m.Unpack) -> str:
    """What makes a reply's size unknown until it is read ("" when nothing does)."""
    layout = decoding.layout
    if layout.rest:
        return "ends in `*` (the rest of the message)"
    if layout.varying is not None:
        return "repeats a group as many times as the message says"
    return ""
