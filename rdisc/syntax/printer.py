"""AST → canonical RDIS text, for `rdisc import` and for formatting.

Deterministic and readable: 4-space indents, a blank line between declarations,
doc comments as `///` lines above what they document, short primitives on one
line. Everything the parser keeps is printed as written (clause order, repeated
clauses, every delay and priority), so parsing the output gives the same tree
back: `parse(print_module(m)) == m` for every module the parser produces.
"""

from __future__ import annotations

import re
from typing import NoReturn

from rdisc.syntax import ast
from rdisc.syntax import precedence as p

WIDTH = 100  # a primitive or a call longer than this is spread over several lines
INDENT = "    "

# Values a raw string r"..." can spell: no quote or newline, no trailing backslash.
_RAW_SPELLABLE = re.compile(r'(?:[^"\\\n]|\\[^\n])*')


def print_module(module: ast.Module) -> str:
    return "\n".join("\n".join(_decl(d)) + "\n" for d in module.decls)


def print_expr(expr: ast.Expr) -> str:
    """An expression with the fewest parentheses that keep its tree."""
    return _expr(expr).text


def _expr(e: ast.Expr) -> p.Printed:
    match e:
        case ast.IntLit(value) | ast.BoolLit(value) | ast.StrLit(value) | ast.BytesLit(value):
            return p.literal(value)
        case ast.FloatLit(value):
            return p.literal(float(value))
        case ast.Ref(name):
            return p.Printed(name, p.ATOM)
        case ast.Index(base, index):
            return p.index(_expr(base).text, _expr(index))
        case ast.ArrayLit(items):
            return p.array([_expr(a) for a in items])
        case ast.Unary(op, operand):
            return p.unary(op, _expr(operand))
        case ast.BinOp(op, left, right):
            return p.binary(op, _expr(left), _expr(right))
        case ast.Conditional(then, cond, orelse):
            return p.conditional(_expr(then), _expr(cond), _expr(orelse))
        case ast.CallExpr(func, args):
            return p.call(func.text, [_expr(a) for a in args])
        case ast.Member(enum, member):
            return p.Printed(f"{enum.text}.{member.text}", p.ATOM)
        case ast.MethodCall(base, method, args):
            return p.call(f"{base.text}.{method.text}", [_expr(a) for a in args])
        case _:
            _unreachable(e)


def _unreachable(node: NoReturn) -> NoReturn:
    """`typing.assert_never`, which Python 3.10 lacks: a missed case is a type error."""
    raise AssertionError(f"unhandled node {node!r}")


# ---- declarations ------------------------------------------------------------------


def _decl(d: ast.Decl) -> list[str]:
    return _doc(d.doc) + _code(d)


def _code(d: ast.Decl) -> list[str]:
    match d:
        case ast.ImportDecl(path):
            return [f"import {p.quote(path)}"]
        case ast.RobotDecl(name, attrs):
            return _block(f"robot {name.text}", [f"{a.key} {p.quote(a.value)}" for a in attrs])
        case ast.StateDecl(name, type_, init):
            value = "" if init is None else f" = {print_expr(init)}"
            noise = "" if d.noise is None else f" noise {_error(d.noise)}"
            return [f"state {name.text}: {print_type(type_)}{value}{noise}"]
        case ast.SensorDecl(name, type_, primitive, cache):
            noise = "" if d.noise is None else f" noise {_error(d.noise)}"
            return [f"sensor {name.text}: {print_type(type_)} from {primitive.text}() cache {_duration(cache)}{noise}"]
        case ast.SettingDecl(name, type_, default, _, _, low, high):
            bounds = "" if low is None or high is None else f" in {print_expr(low)}..{print_expr(high)}"
            value = "" if default is None else f" = {print_expr(default)}"
            return [f"setting {name.text}: {print_type(type_)}{bounds}{value}"]
        case ast.ConnectionDecl(name, kind, attrs):
            return _block(f"connection {name.text}: {kind.text}", [_connection_attr(a) for a in attrs])
        case ast.PrimitiveDecl():
            return _primitive(d)
        case ast.InterfaceDecl(name, params, clauses, body):
            words = "".join(" " + _interface_clause(c) for c in clauses)
            head = f"interface {name.text}({print_params(params)}){words}"
            return _block(head, _body(body, len(INDENT)))
        case ast.AdapterDecl(name, ros, fields):
            head = f"adapter {name.text}" + ("" if ros is None else f" ros {p.quote(ros.value)}")
            return _block(head, [line for f in fields for line in _doc(f.doc) + [print_field(f)]])
        case ast.InputDecl(name, adapter, call):
            return _call_lines(f"input {name.text}: {adapter.text} -> ", call, "", 0)
        case ast.OutputDecl(name, adapter, fields, frame=frame, noises=noises, filters=filters):
            at = "" if frame is None else f" frame {frame.text}"
            return _block(f"output {name.text}: {adapter.text}{at}", [_assign(a) for a in fields]
                          + [_noise(n) for n in noises] + [line for f in filters for line in _filter(f)])
        case ast.ConstDecl(name, value):
            if isinstance(value, ast.TableLit):
                return _block(f"const {name.text} =", [f"{print_expr(k)}: {print_expr(v)}," for k, v in value.entries])
            return [f"const {name.text} = {print_expr(value)}"]
        case ast.EnumDecl(name, members):
            return _block(f"enum {name.text}", [f"{m.name.text} = {print_expr(m.value)}," for m in members])
        case ast.FrameDecl(name, params, items):
            head = f"frame {name.text}" + (f"({print_params(params)})" if params else "")
            lines: list[str] = []
            for item in items:
                if isinstance(item, ast.FrameSide):
                    lines += _block(item.side, [_frame_part(part) for part in item.parts])
                elif isinstance(item, ast.FrameStuff):
                    lines.append(f"stuff {p.quote_octets(item.escape.value)} after {p.quote_octets(item.reserved.value)}")
                elif isinstance(item, ast.FrameEscape):
                    lines.append(_escape(item))
                else:
                    lines.append(_frame_part(item))
            return _block(head, lines)
        case ast.LinkDecl(name, items):
            return _block(f"link {name.text}", [_link_item(i) for i in items])
        case ast.JointDecl(name, kind, parent, child, items):
            return _block(f"joint {name.text}: {kind.text} {parent.text} -> {child.text}",
                          [_joint_item(i) for i in items])
        case ast.TransmissionDecl(name, joint, bindings):
            head = f"transmission {name.text}: {joint.text}" + ("" if d.actuator is None else f" actuator {d.actuator.text}")
            return _block(head, [line for b in bindings for line in _binding(b)])
        case ast.ActuatorDecl(name, kind, items):
            return _block(f"actuator {name.text}: {kind.text}", [f"{i.key} {print_expr(i.value)}" for i in items])
        case _:
            _unreachable(d)


def _escape(item: ast.FrameEscape) -> str:
    head = f"escape {p.quote_octets(item.escape.value)}"
    if item.escaped is not None:
        return f"{head} xor 0x{item.xor:02X} for {p.quote_octets(item.escaped.value)}"
    return f"{head} {{ " + ", ".join(f"{p.quote_octets(b.value)}: {p.quote_octets(c.value)}" for b, c in item.table) + " }"


# ---- the body -------------------------------------------------------------------------


def _link_item(item: ast.ShapeUse | ast.BodyValue | ast.LinkSpawn) -> str:
    if isinstance(item, ast.BodyValue):
        return f"{item.key} {print_expr(item.value)}"
    if isinstance(item, ast.LinkSpawn):
        return f"spawn {item.kind.text}" + "".join(f" {word} {print_expr(e)}" for word, e in
                                                   (("at", item.at), ("rpy", item.rpy)) if e is not None)
    shape = f"{item.role} {item.shape.kind.text}({_args(item.shape.args)})"
    return shape + "".join(f" {word} {print_expr(e)}" for word, e in
                           (("at", item.at), ("rpy", item.rpy), ("color", item.color)) if e is not None)


def _joint_item(item: ast.BodyValue | ast.JointLimit | ast.JointMimic) -> str:
    if isinstance(item, ast.JointLimit):
        return f"limit {print_expr(item.low)}..{print_expr(item.high)}"
    if isinstance(item, ast.JointMimic):
        return f"mimic {item.joint.text}" + "".join(f" {word} {print_expr(e)}" for word, e in
                                                    (("multiplier", item.multiplier), ("offset", item.offset))
                                                    if e is not None)
    return f"{item.key} {print_expr(item.value)}"


def _binding(b: ast.Binding) -> list[str]:
    """`command Q to T.P[i] { ... }` or `measure Q from S[i] { ... }`, one conversion a line."""
    place = b.target.text + ("" if b.member is None else f".{b.member.text}")
    place += "" if b.index is None else f"[{print_expr(b.index)}]"
    word = "to" if b.role == "command" else "from"
    return _block(f"{b.role} {b.quantity.text} {word} {place}", [_assign(a) for a in b.conversions])


def _bit_field(f: ast.FrameBitField) -> str:
    if f.name is None:
        return f"length: {f.width} = payload" + (f" {'-' if f.adjust < 0 else '+'} {abs(f.adjust)}" if f.adjust else "")
    return f"field {f.name.text}: {f.width} = {print_expr(f.value)}"  # type: ignore[arg-type]


def _frame_part(part: ast.FramePart) -> str:
    match part:
        case ast.FrameBytes(role, value):
            return f"{role} {p.quote_octets(value.value)}"
        case ast.FrameField(name, fmt, value):
            return f"field {name.text} {p.quote(fmt.value)} = {print_expr(value)}"
        case ast.FrameLength(fmt, adjust):
            return f"length {p.quote(fmt.value)} = payload" + (f" {'-' if adjust < 0 else '+'} {abs(adjust)}"
                                                             if adjust else "")
        case ast.FramePayload(_, trimmed):
            return "payload trimmed" if trimmed else "payload"
        case ast.FrameChecksum(algorithm, fmt, options):
            words = [f"checksum {p.quote(algorithm.value)} {'hex' if fmt is None else p.quote(fmt.value)}"]
            for o in options:
                if o.word == "over":
                    words.append("over " + " .. ".join(i.text for i in o.over))
                elif o.word == "seed":
                    words.append(f"seed {o.over[0].text}[{o.over[1].text}]")
                else:
                    words.append(o.word if o.value is None else f"{o.word} {print_expr(o.value)}")
            return " ".join(words)
        case ast.FrameOptional(parts):
            return _run("optional", parts)
        case ast.FrameBits(fmt, fields):
            return f"bits {p.quote(fmt.value)} {{ " + "  ".join(_bit_field(f) for f in fields) + " }"
        case ast.FrameEither(alternatives, _, conditions):
            heads = [f"when {print_expr(c)}" if c is not None else "" for c in conditions] or [""] * len(alternatives)
            return " or ".join(_run(f"{'either' if i == 0 else ''} {head}".strip(), run).lstrip()
                               for i, (head, run) in enumerate(zip(heads, alternatives)))
        case _:
            _unreachable(part)


def _run(head: str, parts: tuple[ast.FramePart, ...]) -> str:
    """`head { part  part }` on one line: a run of parts inside `optional` or `either`."""
    return f"{head} {{ {'  '.join(_frame_part(part) for part in parts)} }}" if parts else f"{head} {{ }}"


def _doc(doc: str | None) -> list[str]:
    if doc is None:
        return []
    return ["///" + (f" {line}" if line else "") for line in doc.split("\n")]


def _numbers(value: float | ast.NumberRows) -> str:
    """A number, or rows of numbers as `[1.0, 0.0; 0.0, 1.0]`."""
    if isinstance(value, float):
        return repr(value)
    return "[" + "; ".join(", ".join(repr(number) for number in row) for row in value.rows) + "]"


def _error(noise: ast.FieldNoise) -> str:
    """A noise's deviation (or covariance) and its unit, as written after its field or state."""
    unit = "" if noise.unit is None else " " + p.quote(noise.unit.value)
    return f"{_numbers(noise.value)}{unit}"


def _noise(noise: ast.FieldNoise) -> str:
    if noise.others:
        return f"noise ({', '.join(f.text for f in (noise.field, *noise.others))}) {_error(noise)}"
    return f"noise {noise.field.text} {_error(noise)}"


def _filter(given: ast.FieldFilter) -> list[str]:
    return _block(f"filter {given.field.text} kalman", [f"{word.text} {_numbers(value)}" for word, value in given.items])


def _block(head: str, lines: list[str]) -> list[str]:
    if not lines:
        return [f"{head} {{}}"]
    return [f"{head} {{", *(INDENT + line for line in lines), "}"]


def print_params(params: tuple[ast.Param, ...]) -> str:
    return ", ".join(f"{param.name.text}: {print_type(param.type)}" + _range(param)
                     + (f" unit {p.quote(param.unit.value)}" if param.unit is not None else "")
                     + (f" = {print_expr(param.default)}" if param.default is not None else "") for param in params)


def print_type(t: ast.TypeRef) -> str:
    if isinstance(t, ast.ArrayOf):
        return f"{t.element.text}[{'' if t.size is None else print_expr(t.size)}]"
    return t.text


def _range(param: ast.Param) -> str:
    if param.low is None or param.high is None:
        return ""
    return f" in {print_expr(param.low)}..{print_expr(param.high)}"


def _args(args: tuple[ast.Expr, ...]) -> str:
    return ", ".join(print_expr(a) for a in args)


def _call(call: ast.Call) -> str:
    return f"{call.target.text}({_args(call.args)})"


def _call_lines(prefix: str, call: ast.Call, suffix: str, column: int) -> list[str]:
    """A call on one line, or with one argument a line when it is too long."""
    line = f"{prefix}{_call(call)}{suffix}"
    if column + len(line) <= WIDTH or not call.args:
        return [line]
    return [f"{prefix}{call.target.text}(", *(f"{INDENT}{print_expr(a)}," for a in call.args), f"){suffix}"]


def _duration(d: ast.Duration) -> str:
    return f"{print_expr(d.value)} {d.unit}"


def _assign(a: ast.Assign) -> str:
    element = "" if a.index is None else f"[{print_expr(a.index)}]"
    when = "" if a.when is None else f" when {print_expr(a.when)}"
    return f"{a.target.text}{element} = {print_expr(a.value)}{when}"


def _connection_attr(a: ast.ConnectionAttr) -> str:
    match a:
        case ast.Baud(value):
            return f"baud {print_expr(value)}"
        case ast.Threading(model, frequency):
            return f"threading {model.text} at {print_expr(frequency)} Hz"
        case ast.Hook(event, call, every):
            return f"{event} {_call(call)}" + ("" if every is None else f" every {_duration(every)}")
        case ast.Terminator(value):
            return f"terminator {p.quote_octets(value.value)}"
        case ast.Address(value):
            return f"address {p.quote(value.value)}"
        case ast.DataBits(value):
            return f"databits {print_expr(value)}"
        case ast.Parity(value):
            return f"parity {value.text}"
        case ast.StopBits(value):
            return f"stopbits {print_expr(value)}"
        case _:
            _unreachable(a)


def _interface_clause(c: ast.InterfaceClause) -> str:
    match c:
        case ast.Kind(word, _, rate):
            return word if rate is None else f"{word} {print_expr(rate)} Hz"
        case ast.Triggers(outputs):
            return "triggers " + ", ".join(o.text for o in outputs)
        case _:
            _unreachable(c)


def _body(body: tuple[ast.BodyStmt, ...], column: int) -> list[str]:
    """An interface's statements, a loop's own a level deeper (`column`: where they start)."""
    lines: list[str] = []
    for stmt in body:
        match stmt:
            case ast.CallStmt():
                lines += _call_stmt(stmt, column)
            case ast.ForStmt(var, low, high, inner):
                over = print_expr(low) + ("" if high is None else f"..{print_expr(high)}")
                lines += _block(f"for {var.text} in {over}", _body(inner, column + len(INDENT)))
            case _:
                _unreachable(stmt)
    return lines


def _call_stmt(stmt: ast.CallStmt, column: int) -> list[str]:
    suffix = "".join(f" delay {_duration(d)}" for d in stmt.delays)
    suffix += "".join(f" priority {print_expr(e)}" for e in stmt.priorities)
    suffix += "".join(f" when {print_expr(e)}" for e in stmt.conditions)
    suffix += "".join(f" until {print_expr(u.condition)} every {_duration(u.every)} within {_duration(u.within)}"
                      for u in stmt.polls)
    return _call_lines("", stmt.call, suffix, column)


def print_field(f: ast.FieldDecl) -> str:
    unit = "" if f.unit is None else f" unit {p.quote(f.unit)}"
    ros = "" if f.ros is None else f" ros {p.quote(f.ros.value)}"
    return f"{f.name.text}: {print_type(f.type)}{unit}{ros}"


# ---- primitives ----------------------------------------------------------------------


def _primitive(d: ast.PrimitiveDecl) -> list[str]:
    """On one line when it fits, else one clause a line; post-actions always follow
    the clause before them, inline when there is one, as a block when there are more."""
    head = f"primitive {d.name.text}({print_params(d.params)})"
    pieces = [_primitive_clause(c) for c in d.clauses]
    lines = _lay_out(head, pieces, wrapped=False)
    if max(len(line) for line in lines) <= WIDTH:
        return lines
    return _lay_out(head, pieces, wrapped=True)


def _entry(head: str, actions: ast.Actions | None) -> list[str]:
    """One line of a reply table or a reply list, indented: its head, then its post-actions."""
    block = _primitive_clause(actions)[0] if actions is not None else []
    return [INDENT + head + (" " + block[0] if block else ""), *(INDENT + line for line in block[1:])]


def _primitive_clause(c: ast.PrimitiveClause) -> tuple[list[str], bool]:
    """The clause's lines, and whether it continues the line before it."""
    match c:
        case ast.On(connection):
            return [f"on {connection.text}"], False
        case ast.Encoding(kind, template, args):
            return [f"{kind} {spell_template(template.value)} ({_args(args)})"], False
        case ast.Decoding(kind, template):
            return [f"{kind} {spell_template(template.value)}"], False
        case ast.Framed(frame, args):
            return [f"frame {frame.text}({_args(args)})"], False
        case ast.SkipUnmatched():
            return ["skip unmatched"], False
        case ast.ReplyTimeout(duration):
            return [f"timeout {_duration(duration)}"], False
        case ast.Retry(count):
            return [f"retry {print_expr(count)}"], False
        case ast.Expect(condition):
            return [f"expect {print_expr(condition)}"], False
        case ast.Replies(over, _, var, high, framed):
            if var is None:
                return [f"replies {print_expr(over)}"], False
            values = print_expr(over) + ("" if high is None else f"..{print_expr(high)}")
            through = "" if framed is None else f" frame {framed.frame.text}({_args(framed.args)})"
            return [f"replies {var.text} in {values}{through}"], False
        case ast.ReplyList(replies):
            lines = ["replies {"]
            for listed in replies:
                head = "" if listed.frame is None else \
                    f"frame {listed.frame.frame.text}({_args(listed.frame.args)}) "
                head += f"{listed.decoding.kind} {spell_template(listed.decoding.template.value)}"
                if listed.expect is not None:
                    head += f" expect {print_expr(listed.expect)}"
                lines.extend(_entry(head, listed.actions))
            return [*lines, "}"], False
        case ast.ErrorReply(decoding, _, framed, marker, codes, when):
            words = ["error"]
            if framed is not None:
                words.append(f"frame {framed.frame.text}({_args(framed.args)})")
            if marker is not None:
                words.append(p.quote_octets(marker.value))
            if when is not None:
                words.append(f"when {print_expr(when)}")
            if decoding is not None:
                words.append(f"{decoding.kind} {spell_template(decoding.template.value)}")
            if codes is not None:
                words.append(f"code {codes.text}")
            return [" ".join(words)], False
        case ast.Records(marker):
            return [f"reply each until {p.quote_octets(marker.value)}"], False
        case ast.Lines(settings):
            return ["lines " + ", ".join(f"break {_duration(a.duration)}" if isinstance(a, ast.LineBreak)
                                         else _assign(a) for a in settings)], False
        case ast.ReplyTable(key, entries, _, tag, each, length):
            if tag is None:
                lines = [f"reply {key.text} {{"]
            else:
                sized = "" if length is None else f" length {p.quote(length.value)}"
                lines = [f"reply {'each ' if each else ''}tag {p.quote(tag.value)}{sized} {{"]
            for entry in entries:
                values = print_expr(entry.value) + ("" if entry.last is None else f"..{print_expr(entry.last)}")
                if entry.table is not None:  # a nested table, printed as a table is
                    inner, _ = _primitive_clause(entry.table)
                    lines.extend([f"{INDENT}{values}: {inner[0].removeprefix('reply ')}",
                                  *(INDENT + line for line in inner[1:])])
                    continue
                assert entry.decoding is not None
                head = f"{values}: {entry.decoding.kind} {spell_template(entry.decoding.template.value)}"
                if entry.until is not None:
                    head += f" until {p.quote_octets(entry.until.value)}"
                lines.extend(_entry(head, entry.actions))
            return [*lines, "}"], False
        case ast.Actions(()):
            return ["{}"], True
        case ast.Actions((assign,)):
            return [f"{{ {_assign(assign)} }}"], True
        case ast.Actions(assigns):
            return ["{", *(INDENT + _assign(a) for a in assigns), "}"], True
        case _:
            _unreachable(c)


def _lay_out(head: str, pieces: list[tuple[list[str], bool]], wrapped: bool) -> list[str]:
    indent = INDENT if wrapped else ""
    lines = [head]
    for piece, attached in pieces:
        if attached or not wrapped:
            lines[-1] += " " + piece[0]
        else:
            lines.append(indent + piece[0])
        lines.extend(indent + line for line in piece[1:])
    return lines


def spell_template(value: str) -> str:
    """A template (a format's or a regex) as RDIS text: with backslashes (regexes above all) as a
    raw string, so `\\d` stays `\\d`; else quoted, control characters escaped."""
    if "\\" in value and value.isprintable() and _RAW_SPELLABLE.fullmatch(value):
        return f'r"{value}"'
    return p.quote(value)
