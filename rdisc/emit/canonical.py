"""Model → canonical JSON, in the shape of thesis Appendix B.

The thesis keys (`stateVariables`, `connections: {"spp": [...]}`, `primitives`,
`interfaces`, `domainInterfaces`, `domainOutputs`, ...) carry the thesis meaning,
so the original interpreter's loader reads the elements it knows; what the
language adds (types, adapters, docs) is in extra keys. Expressions are written
`"<expr>"` as in the thesis, printed from the typed IR with the parser's
precedence table, and post-actions `"state = expr"` with the reply as `__out__`.

The body (thesis ch. 6) is in `links`, `joints` and `transmissions`, in SI units as in
RDIS and URDF: lengths and positions in m, angles in rad (`rpy`, a revolute joint's
`limit`), masses in kg, inertia in kg m² about the centre of mass, velocities in rad/s
or m/s, efforts in N m or N. A shape or a joint is placed by `xyz` and `rpy` (left out
when zero); a transmission's conversions are `toDevice` (from the joint's quantity, by
its name, to the device's value) and `toJoint` (from `raw` back). A value that reads a setting
is written as its expression (`"<TRACK / 2>"`, an array's items each so), so that a value given
later moves the body read from the JSON as it does the .rdis.

Deterministic: keys in a fixed logical order, elements in model order, 2-space
indentation, no timestamp: the same Model always gives byte-identical text.
"""

from __future__ import annotations

import json
from typing import Any, NoReturn

from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.syntax import precedence as p

_CONNECTION_GROUPS = {"serial": "spp", "tcp": "tcp"}  # the thesis lists serial connections under "spp"

JsonObject = dict[str, Any]


def to_json(model: m.Model) -> str:
    return json.dumps(_document(model), indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def _document(model: m.Model) -> JsonObject:
    robot = model.robot
    connections: dict[str, list[JsonObject]] = {}
    for c in model.connections.values():
        connections.setdefault(_CONNECTION_GROUPS[c.kind], []).append(_connection(c))
    adapters = [_adapter(a) for a in model.adapters.values() if not a.standard]
    return _object(
        ("name", robot.name),
        ("author", robot.author),
        ("description", robot.description),
        ("version", robot.version),
        ("doc", robot.doc),
        ("constants", {name: _value(v) for name, v in model.constants.items()} or None),
        ("enums", dict(model.enums) or None),
        ("tables", {t.name: [[k, _value(v)] for k, v in t.entries] for t in model.tables.values()} or None),
        ("constantDocs", {**model.constant_docs, **{t.name: t.doc for t in model.tables.values() if t.doc}} or None),
        ("enumDocs", dict(model.enum_docs) or None),
        ("settings", [_setting(s) for s in model.settings.values()] or None),
        ("stateVariables", [_state(s) for s in model.states.values()]),
        ("sensors", [_sensor(s) for s in model.sensors.values()] or None),
        ("connections", connections),
        ("frames", [_frame(f) for f in model.frames.values()] or None),
        ("primitives", [_primitive(x) for x in model.primitives.values()]),
        ("interfaces", [_interface(i) for i in model.interfaces.values()]),
        ("domainAdapters", adapters or None),
        ("domainInterfaces", [_input(i, model.adapters[i.adapter]) for i in model.inputs.values()]),
        ("domainOutputs", [_output(o) for o in model.outputs.values()]),
        ("links", [_link(link) for link in model.links.values()] or None),
        ("joints", [_joint(j) for j in model.joints.values()] or None),
        ("transmissions", [_transmission(t) for t in model.transmissions.values()] or None),
        ("actuators", [_actuator(a) for a in model.actuators.values()] or None),
    )


def _object(*members: tuple[str, Any]) -> JsonObject:
    """An object of the members that are not None, in the order given."""
    return {key: value for key, value in members if value is not None}


def _value(value: m.Value) -> m.Value:
    """A constant as a JSON value; bytes, which JSON has not, as an embedded literal `"<b\"...\">"`."""
    return _embedded(m.Const(value, Type.BYTES)) if isinstance(value, bytes) else value


def _number(value: float) -> float | int:
    """100.0 is written 100: delays, intervals and rates read as the thesis wrote them."""
    exact = isinstance(value, float) and value.is_integer() and abs(value) < 2**53  # an int that is the float
    return int(value) if exact else value


def _state(s: m.StateVariable) -> JsonObject:
    return _object(
        ("name", s.name),
        ("type", s.type.value),
        ("value", _embedded(m.Const(s.initial, s.type)) if s.initial != () else None),  # an open array starts empty
        ("noise", _value_noise(s.noise)),
        ("doc", s.doc),
    )


def _sensor(s: m.Sensor) -> JsonObject:
    return _object(("name", s.name), ("type", s.type.value), ("primitive", s.primitive), ("cache", _number(s.cache_ms)),
                   ("noise", _value_noise(s.noise)), ("doc", s.doc))


def _setting(s: m.Setting) -> JsonObject:
    return _object(
        ("name", s.name),
        ("type", s.type.value),
        ("range", None if s.low is None else [s.low, s.high]),
        ("value", _embedded(m.Const(s.default, s.type))),
        ("doc", s.doc),
    )


def _hook(h: m.HookCall | None) -> JsonObject | None:
    if h is None:
        return None
    return {"name": h.interface, "arguments": [_embedded(a) for a in h.args]}


def _connection(c: m.Connection) -> JsonObject:
    keepalive = None
    if c.keepalive is not None:
        k = c.keepalive.call
        keepalive = {
            "name": k.interface,
            "interval": _number(c.keepalive.interval_ms),
            "arguments": [_embedded(a) for a in k.args],
        }
    return _object(
        ("name", c.name),
        ("baud", c.baud if c.baud_setting is None else f"<{c.baud_setting}>"),
        ("dataBits", None if c.data_bits == 8 else c.data_bits),
        ("parity", None if c.parity == "none" else c.parity),
        ("stopBits", None if c.stop_bits == 1 else _number(c.stop_bits)),
        (f"{c.threading}Threading", {"freqHz": _number(c.frequency_hz)}),  # the thesis's SingleThreading, ...
        ("startup", _hook(c.startup)),
        ("terminate", _hook(c.terminate)),
        ("keepalive", keepalive),
        ("terminator", None if c.terminator == "\n" else c.terminator),
        ("address", c.address),
        ("doc", c.doc),
    )


def _primitive(x: m.Primitive) -> JsonObject:
    encoding: tuple[str, str | None]
    match x.encoding:
        case m.Pack(format):
            encoding = ("pack", format)
        case m.Format(template):
            encoding = ("format", template)
        case None:
            encoding = ("pack", None)  # only lines set: the member is left out
        case _:
            _unreachable(x.encoding)
    decoding: tuple[str, str | None]
    match x.decoding:
        case m.Unpack(format):
            decoding = ("unpack", format)
        case m.Regex(pattern):
            decoding = ("regex", pattern)
        case None:
            decoding = ("unpack", None)  # no reply: the member is left out
        case _:
            _unreachable(x.decoding)
    actions = [line for a in x.actions for line in actions_text(a)]
    return _object(
        ("name", x.name),
        ("parameters", [param.name for param in x.params]),
        ("parameterTypes", [param.type.value for param in x.params]),
        ("parameterRanges", _ranges(x.params)),
        ("parameterDefaults", _defaults(x.params)),
        ("parameterUnits", _units(x.params)),
        ("connection", x.connection),
        ("lines", {level.line: _embedded(level.value) for level in x.lines} or None),
        encoding,
        ("formatArgs", None if x.encoding is None else [_embedded(a) for a in x.args]),
        decoding,
        ("recordsUntil", x.records),
        ("frame", None if x.frame is None else {"name": x.frame.frame,
                                                 "arguments": [_embedded(a) for a in x.frame.args]}),
        ("skipUnmatched", x.skip_unmatched or None),
        ("timeout", None if x.timeout_ms is None else _number(x.timeout_ms)),
        ("retry", x.retries or None),
        ("replies", None if x.each is not None else x.replies or None),
        ("repliesEach", None if x.each is None else {"variable": x.each.var, "over": x.each.over}),
        ("replyFrames", [{"name": use.frame, "arguments": [_embedded(a) for a in use.args]}
                         for use in x.reply_frames] or None),
        ("expect", None if x.expect is None else _embedded(x.expect)),
        ("replyTable", None if x.table is None else _object(
            ("key", x.table.key or None), ("tag", x.table.tag), ("each", x.table.each or None),
            ("length", x.table.length), ("cases", _cases(x.table.cases)))),
        ("replyList", [_listed(r) for r in x.listed] or None),
        ("error", None if x.error is None else _error(x.error)),
        ("postActions", actions or None),
        ("doc", x.doc),
    )


def _error(e: m.ErrorReply) -> JsonObject:
    """The reply the device may send instead (`error ...`): its own frame (left out: none), the
    bytes it starts with, its decoding and the enum naming its code; or (`error when`) the
    condition over the reply that makes it the device's error, and the enum."""
    if e.when is not None:
        return _object(("when", _embedded(e.when)), ("codes", e.codes))
    return _object(
        ("frame", None if e.frame is None else {"name": e.frame.frame, "arguments": [_embedded(a) for a in e.frame.args]}),
        ("marker", e.marker or None), ("unpack", e.decoding.format), ("codes", e.codes),
    )


def _listed(r: m.ListedReply) -> JsonObject:
    """One reply of `replies { }`: its own frame (left out: the primitive's), decoding, expect
    and post-actions."""
    kind, template = ("unpack", r.decoding.format) if isinstance(r.decoding, m.Unpack) else ("regex", r.decoding.pattern)
    actions = [line for a in r.actions for line in actions_text(a)]
    return _object(
        ("frame", None if r.frame is None else {"name": r.frame.frame,
                                                 "arguments": [_embedded(a) for a in r.frame.args]}),
        (kind, template), ("expect", None if r.expect is None else _embedded(r.expect)),
        ("postActions", actions or None),
    )


def _cases(cases: tuple[m.ReplyCase, ...]) -> list[JsonObject]:
    """A table's entries in order; a nested table's as one entry, its value, `tag` and `cases`."""
    out: list[JsonObject] = []
    nested: dict[int, list[JsonObject]] = {}
    for c in cases:
        if c.under is None:
            out.append(_case(c))
            continue
        if c.under not in nested:
            nested[c.under] = []
            out.append({"value": c.under, "tag": c.under_tag, "cases": nested[c.under]})
        nested[c.under].append(_case(c))
    return out


def _case(c: m.ReplyCase) -> JsonObject:
    kind, template = ("unpack", c.decoding.format) if isinstance(c.decoding, m.Unpack) else ("regex", c.decoding.pattern)
    actions = [line for a in c.actions for line in actions_text(a)]
    until = c.decoding.until if isinstance(c.decoding, m.Unpack) else None
    return _object(("value", c.value), ("last", c.last), (kind, template), ("until", until),
                   ("postActions", actions or None))


def _ranges(params: tuple[m.Parameter, ...]) -> list[list[int | float | str] | None] | None:
    """Each parameter's `[low, high]` (null without a range; `"<count - 1>"` for a bound that
    reads earlier parameters); left out when none has one."""
    if all(p.low is None for p in params):
        return None
    return [None if p.low is None or p.high is None else [p.low, p.high] if p.limits is None  # both, or neither
            else [_bound(p.limits[0]), _bound(p.limits[1])] for p in params]


def _bound(e: m.Expr) -> int | float | str:
    """A bound of a range that reads earlier parameters: a number as one, else `"<count - 1>"`."""
    return e.value if isinstance(e, m.Const) and isinstance(e.value, (int, float)) else _embedded(e)


def _defaults(params: tuple[m.Parameter, ...]) -> list[str | None] | None:
    """Each parameter's default as `"<value>"` (null without one); left out when none has one."""
    if all(p.default is None for p in params):
        return None
    return [None if p.default is None else _embedded(m.Const(p.default, p.type)) for p in params]


def _units(params: tuple[m.Parameter, ...]) -> list[str | None] | None:
    """Each parameter's unit (null without one); left out when none has one."""
    if all(p.unit is None for p in params):
        return None
    return [p.unit for p in params]


def _frame(f: m.Frame) -> JsonObject:
    return _object(
        ("name", f.name),
        ("parameters", [param.name for param in f.params]),
        ("parameterTypes", [param.type.value for param in f.params]),
        ("parameterRanges", _ranges(f.params)),
        ("parameterDefaults", _defaults(f.params)),
        ("parameterUnits", _units(f.params)),
        ("request", [_frame_part(part) for part in f.request]),
        ("moreRequests", [[_frame_part(part) for part in parts] for parts in f.more_requests] or None),
        ("requestWhen", [None if e is None else _embedded(e) for e in f.request_when] or None),
        ("reply", [_frame_part(part) for part in f.reply]),
        ("moreReplies", [[_frame_part(part) for part in parts] for parts in f.more_replies] or None),
        ("replyWhen", [None if e is None else _embedded(e) for e in f.reply_when] or None),
        ("stuffing", None if f.stuffing is None else {"after": f.stuffing[0], "insert": f.stuffing[1]}),
        ("escaping", None if f.escaping is None else {"escape": f.escaping.escape, "codes": dict(f.escaping.table)}),
        ("doc", f.doc),
    )


def _frame_part(part: m.FramePart) -> JsonObject:
    match part:
        case m.FrameBytes(role, data):
            return {role: data}
        case m.FrameField(name, fmt, value):
            return {"field": name, "format": fmt, "value": _embedded(value)}
        case m.FrameLength(fmt, adjust):
            return {"length": fmt, "adjust": adjust}
        case m.FramePayload(trimmed):
            return {"payload": "trimmed"} if trimmed else {"payload": True}
        case m.FrameChecksum(a, fmt, first, last, with_request, _, seed):
            return _object(
                ("checksum", a.name), ("kind", a.kind), ("width", a.width),
                ("poly", a.poly if a.kind == "crc" else None), ("init", a.init if a.kind == "crc" else None),
                ("reflectIn", a.reflect_in if a.kind == "crc" else None),
                ("reflectOut", a.reflect_out if a.kind == "crc" else None),
                ("xorOut", a.xorout if a.kind == "crc" else None), ("inverted", a.inverted or None),
                ("mask", a.mask), ("format", fmt if fmt is not None else "hex"), ("covers", [first, last]),
                ("withRequest", with_request or None),
                ("seed", None if seed is None else {"table": seed.table, "field": seed.field}),
            )
        case m.FrameOptional(count):
            return {"optional": count}
        case m.FrameBits(fmt, fields):
            return {"bits": fmt, "fields": [
                {"length": True, "width": f.width, "adjust": f.adjust} if f.value is None else
                {"field": f.name, "width": f.width, "value": _embedded(f.value)} for f in fields]}
        case _:
            _unreachable(part)


def _interface(i: m.Interface) -> JsonObject:
    calls = [
        {
            "name": c.primitive,
            "arguments": [_embedded(a) for a in c.args],
            "delay": _number(c.delay_ms),
            "priority": c.priority,
            **({"when": _embedded(c.when)} if c.when is not None else {}),
            **({"until": _embedded(c.until), "every": _number(c.every_ms), "within": _number(c.within_ms)}
               if c.until is not None else {}),
        }
        for c in i.calls
    ]
    return _object(
        ("name", i.name),
        ("type", "periodic" if i.periodic else "adhoc"),
        ("rateHz", None if i.rate_hz is None else _number(i.rate_hz)),
        ("parameters", [param.name for param in i.params] or None),
        ("parameterTypes", [param.type.value for param in i.params] or None),
        ("parameterRanges", _ranges(i.params)),
        ("parameterDefaults", _defaults(i.params)),
        ("parameterUnits", _units(i.params)),
        ("primitiveCalls", calls),
        ("triggers", (i.triggers[0] if len(i.triggers) == 1 else list(i.triggers)) or None),  # one: as the thesis
        ("doc", i.doc),
    )


def _adapter(a: m.Adapter) -> JsonObject:
    fields = [
        _object(("name", f.name), ("type", f.type.value), ("unit", f.unit), ("ros", f.ros), ("doc", f.doc))
        for f in a.fields
    ]
    return _object(("name", a.name), ("ros", a.ros), ("fields", fields), ("doc", a.doc))


def _input(i: m.DomainInput, adapter: m.Adapter) -> JsonObject:
    return _object(
        ("name", i.name),
        ("adapter", i.adapter),
        ("parameters", [f.name for f in adapter.fields]),
        ("calls", {"name": i.interface, "arguments": [_embedded(a) for a in i.args]}),
        ("doc", i.doc),
    )


def _output(o: m.DomainOutput) -> JsonObject:
    return _object(
        ("name", o.name),
        ("adapter", o.adapter),
        ("frame", o.frame),
        ("returns", {name: _embedded(value) for name, value in o.fields}),
        ("noise", [_noise(n) for n in o.noise] or None),
        ("filters", [_kalman(k) for k in o.filters] or None),
        ("doc", o.doc),
    )


def _rows(rows: m.Rows) -> list[list[float | int]]:
    return [[_number(x) for x in row] for row in rows]


def _noise(n: m.Noise) -> JsonObject:
    if n.others:
        return _object(("fields", list(n.fields)), ("covariance", _rows(n.covariance)))
    if n.deviation is not None:
        return _object(("field", n.field), ("deviation", _number(n.deviation)), ("unit", n.unit))
    return _object(("field", n.field), ("covariance", _rows(n.covariance)), ("unit", n.unit))


def _value_noise(n: m.Noise | None) -> JsonObject | None:
    """A state variable's or a sensor's noise: an output field's without the field, which is its name."""
    return None if n is None else {k: v for k, v in _noise(n).items() if k != "field"}


def _kalman(k: m.Kalman) -> JsonObject:
    matrices = (("covariance", k.covariance), ("transition", k.transition), ("process", k.process),
                ("measurement", k.measurement), ("noise", k.noise))
    return {"field": k.field, "kalman": {"state": [_number(x) for x in k.state],
                                         **{word: _rows(rows) for word, rows in matrices}}}


# ---- the body --------------------------------------------------------------------------


def _vector(v: tuple[float, ...]) -> list[float | int]:
    return [_number(x) for x in v]


def _written(expressions: m.Written, word: str, value: Any) -> Any:
    """A member as its clause `word` is written where that reads settings, so that a value given
    later (`--set`) moves the body as it does the .rdis: `"<TRACK / 2>"`, or an array's items so
    where they read one (`[0, "<TRACK / 2>", 0.036]`), the rest at their values; else its value."""
    expr = next((e for w, e in expressions if w == word), None)
    if expr is None:
        return value
    if isinstance(expr, m.ArrayValue) and isinstance(value, list):
        return [_embedded(item) if next(m.variables(item), None) else value[k] for k, item in enumerate(expr.items)]
    return _embedded(expr)


def _pose(pose: m.Pose, expressions: m.Written = ()) -> tuple[tuple[str, Any], tuple[str, Any]]:
    """`xyz` and `rpy` members, each left out when zero and reading no setting."""
    written = {word for word, _ in expressions}
    return (("xyz", _written(expressions, "at", _vector(pose.xyz)) if pose.xyz != m.ORIGIN or "at" in written
             else None),
            ("rpy", _written(expressions, "rpy", _vector(pose.rpy)) if pose.rpy != m.ORIGIN or "rpy" in written
             else None))


def _shape(s: m.Shape) -> JsonObject:
    mesh = s.kind is m.ShapeKind.MESH
    return _object(
        ("shape", s.kind.value),
        ("path", s.path),
        ("scale" if mesh else "size", _written(s.expressions, "scale" if mesh else "size", _vector(s.size))),
        *_pose(s.origin, s.expressions),
        ("color", None if s.color is None else _written(s.expressions, "color", _vector(s.color))),
    )


def _link(link: m.Link) -> JsonObject:
    inertial = link.inertial
    return _object(
        ("name", link.name),
        ("visuals", [_shape(s) for s in link.visuals] or None),
        ("collisions", [_shape(s) for s in link.collisions] or None),
        ("inertial", None if inertial is None else {
            "mass": _written(inertial.expressions, "mass", _number(inertial.mass)),
            "centre": _written(inertial.expressions, "centre", _vector(inertial.centre)),
            "inertia": _written(inertial.expressions, "inertia", _vector(inertial.inertia))}),
        ("spawn", None if link.spawn is None else _object(("floating", link.spawn.floating),
                                                          *_pose(link.spawn.pose, link.spawn.expressions))),
        ("doc", link.doc),
    )


def _joint(j: m.Joint) -> JsonObject:
    read = j.expressions
    written = {word for word, _ in read}
    return _object(
        ("name", j.name),
        ("type", j.kind.value),
        ("parent", j.parent),
        ("child", j.child),
        *_pose(j.origin, read),
        ("axis", _written(read, "axis", _vector(j.axis)) if j.moves() else None),
        ("limit", None if j.lower is None or j.upper is None
         else _written(read, "limit", [_number(j.lower), _number(j.upper)])),
        ("velocity", None if j.velocity is None else _written(read, "velocity", _number(j.velocity))),
        ("effort", None if j.effort is None else _written(read, "effort", _number(j.effort))),
        ("damping", _written(read, "damping", _number(j.damping)) if j.damping or "damping" in written else None),
        ("friction", _written(read, "friction", _number(j.friction)) if j.friction or "friction" in written
         else None),
        ("mimic", None if j.mimic is None else {"joint": j.mimic.joint,
                                                 "multiplier": _written(read, "multiplier", _number(j.mimic.multiplier)),
                                                 "offset": _written(read, "offset", _number(j.mimic.offset))}),
        ("doc", j.doc),
    )


def _binding(b: m.Binding) -> JsonObject:
    target = "state" if b.parameter is None else "interface" if b.interface else "primitive"
    return _object(
        ("quantity", b.quantity.value),
        (target, b.target),
        ("parameter", b.parameter),
        ("index", None if b.index is None else _written(b.expressions, "index", b.index)),
        ("toDevice", _embedded(b.to_device)),
        ("toJoint", _embedded(b.to_joint)),
    )


def _transmission(t: m.Transmission) -> JsonObject:
    return _object(
        ("name", t.name),
        ("joint", t.joint),
        ("commands", [_binding(b) for b in t.commands] or None),
        ("measures", [_binding(b) for b in t.measures] or None),
        ("actuator", t.actuator),
        ("doc", t.doc),
    )


def _actuator(a: m.Actuator) -> JsonObject:
    return _object(
        ("name", a.name),
        ("kind", a.kind.value),
        *((key, None if value is None else _written(a.expressions, key, value)) for key, value in (
            ("velocity", a.velocity), ("acceleration", a.acceleration), ("effort", a.effort), ("gain", a.gain),
            ("damping", a.damping))),
        ("limit", "refuse" if a.refuse else None),
        ("doc", a.doc),
    )


# ---- expressions -----------------------------------------------------------------------


def _embedded(e: m.Expr) -> str:
    """The thesis convention: an expression inside a JSON string is written `<...>`."""
    return f"<{_text(e)}>"


def actions_text(action: m.PostAction) -> list[str]:
    """A post-action as written: `x = value`, or one `x[i] = value` per element it replaces."""
    elements: list[str] = []
    value = action.value
    while isinstance(value, m.Replaced):
        elements.insert(0, f"{action.target}[{_text(value.index)}] = {_text(value.value)}{_when(value.when)}")
        value = value.array
    if elements and isinstance(value, m.Var) and value.name == action.target:
        return elements
    return [f"{action.target} = {_text(action.value)}{_when(action.when)}"]


def _when(condition: m.Expr | None) -> str:
    """A post-action's condition as written after it: ` when COND`."""
    return "" if condition is None else f" when {_text(condition)}"


def range_written(p: m.Parameter) -> str:
    """A parameter's range as written: `0..count - 1` for bounds that read earlier parameters."""
    if p.limits is None:
        return p.range_text()
    return f"{expression_text(p.limits[0])}..{expression_text(p.limits[1])}"


def expression_text(e: m.Expr) -> str:
    """An expression of the Model as RDIS source text."""
    return _expr(e).text


_text = expression_text


def _expr(e: m.Expr) -> p.Printed:
    match e:
        case m.Const(value, type_):
            return _const(value, type_)
        case m.Var(name):
            return p.Printed(name, p.ATOM)
        case m.ReplyValue(index):
            return p.Printed(f"__out__[{index}]", p.ATOM)  # the thesis's name for the reply
        case m.UnaryOp(op, operand):
            return p.unary(op, _expr(operand))
        case m.BinaryOp(op, left, right):
            return p.binary(op, _expr(left), _expr(right))
        case m.IfElse(cond, then, orelse):
            return p.conditional(_expr(then), _expr(cond), _expr(orelse))
        case m.Lookup(table=table, key=key, default=default) if default is not None:
            return p.call(f"{table}.get", [_expr(key), _expr(default)])
        case m.Lookup(table=table, key=key):
            return p.Printed(f"{table}[{_expr(key).text}]", p.ATOM)
        case m.InTable(table=table, key=key):
            return p.binary("in", _expr(key), p.Printed(table, p.ATOM))
        case m.FuncCall(func, args):
            return p.call(func, [_expr(a) for a in args])
        case m.ArrayValue(items):
            return p.array([_expr(a) for a in items])
        case m.Element(array, index):
            return p.index(_expr(array).text, _expr(index))
        case m.Replaced():
            raise AssertionError("a replaced element is written as its post-action (`actions_text`)")
        case _:
            _unreachable(e)


def _const(value: m.Value, type_: m.AnyType) -> p.Printed:
    """A constant spelled by its type, so that 1.0 stays a float and True a bool."""
    if isinstance(type_, m.Array):
        assert isinstance(value, tuple), "an array's value is a tuple"
        return p.array([_const(v, type_.element) for v in value])
    match type_:
        case Type.INT:
            assert isinstance(value, (int, float)), "a checked int constant is a number"
            return p.literal(int(value))
        case Type.FLOAT:
            assert isinstance(value, (int, float)), "a checked float constant is a number"
            return p.literal(float(value))
        case Type.BOOL:
            return p.literal(bool(value))
        case Type.STRING:
            return p.literal(str(value))
        case Type.BYTES:
            assert isinstance(value, bytes), "a checked bytes constant is bytes"
            return p.literal(value)
        case _:
            _unreachable(type_)


def _unreachable(node: NoReturn) -> NoReturn:
    """`typing.assert_never`, which Python 3.10 lacks: a missed case is a type error."""
    raise AssertionError(f"unhandled case {node!r}")
