"""Frames: a frame's parts (bytes, fields, bit fields, the payload, checksums), and a frame used
by a primitive, its reply or its error."""

from __future__ import annotations

from rdisc.json_import.expressions import Expressions
from rdisc.json_import.reader import present, type_text
from rdisc.json_import.values import JArray, JBool, JNull, JNumber, JObject, JString, JValue
from rdisc.syntax import ast

_FRAME = ("name", "parameters", "parameterTypes", "parameterRanges", "parameterDefaults", "parameterUnits",
          "request", "reply", "moreRequests", "moreReplies", "requestWhen", "replyWhen",
          "stuffing", "escaping", "doc")
_CHECKSUM = (
    "checksum", "kind", "width", "poly", "init", "reflectIn", "reflectOut", "xorOut", "inverted", "mask", "format",
    "covers", "withRequest", "seed",
)  # fmt: skip
_BYTES_ROLES = ("header", "literal", "terminator")


class Frames(Expressions):
    """The reading of frames and of their uses."""

    def framed(self, v: JValue | None) -> ast.Framed | None:
        """`{"name": ..., "arguments": [...]}`: a primitive's frame, or a listed reply's."""
        framed = self.object(v, "`frame`")
        if framed is None:
            return None
        f = self.members(framed, "`frame`", ("name", "arguments"))
        frame = self.name(framed, f, "`frame`")
        if frame is None:
            return None
        return ast.Framed(frame, self.args(f.get("arguments"), self.frame_types.get(frame.text, ())), framed.span)

    def frame(self, obj: JObject) -> ast.FrameDecl | None:
        m = self.members(obj, "a frame", _FRAME)
        name = self.name(obj, m, "a frame")
        params = self.params(m, lambda _: "int")
        sides: dict[str, tuple[ast.FramePart, ...]] = {}
        for side, more in (("request", "moreRequests"), ("reply", "moreReplies")):
            layouts = [self.frame_parts(m.get(side), f"`{side}`"),
                       *(self.frame_parts(v, "a layout") for v in self.array(m.get(more), f"`{more}`"))]
            when: tuple[ast.Expr | None, ...] = ()
            when_key = f"{side}When"
            if when_key in m:  # `either when`: a condition (or null) per layout
                when = tuple(None if isinstance(v, JNull) else self.expr(v, "bool")
                             for v in self.array(m[when_key], f"`{when_key}`"))
                if len(when) != len(layouts) or len(layouts) < 2:
                    self.error(m[when_key].span, f"`{when_key}` has {len(when)} condition{'' if len(when) == 1 else 's'} for "
                               f"{len(layouts)} {side} layout{'' if len(layouts) == 1 else 's'}",
                               help=f"give a condition (or null, the last only) for `{side}` and each of `{more}`")
                    when = ()
            sides[side] = layouts[0] if len(layouts) == 1 and not when else (
                ast.FrameEither(tuple(layouts), m[more].span if more in m else m[side].span, when),)
        if name is None:
            return None
        self.frame_types[name.text] = tuple(type_text(p.type) for p in params)
        written = {side: m[side] for side in ("request", "reply") if side in m}
        chosen = any(isinstance(p, ast.FrameEither) and p.conditions for parts in sides.values() for p in parts)
        if sides["request"] == sides["reply"] and not chosen:  # one sequence for both directions
            items: tuple[ast.FramePart | ast.FrameSide | ast.FrameStuff | ast.FrameEscape, ...] = sides["request"]
        else:
            items = tuple(ast.FrameSide(side, parts, written[side].span if side in written else obj.span)
                          for side, parts in sides.items() if parts or side == "request")
        stuffing = self.object(m.get("stuffing"), "`stuffing`")
        if stuffing is not None:
            s = self.members(stuffing, "`stuffing`", ("after", "insert"))
            after, insert = self.string(s.get("after"), "`after`"), self.string(s.get("insert"), "`insert`")
            if after is not None and insert is not None:
                items += (ast.FrameStuff(ast.StrLit(insert.value, insert.span), ast.StrLit(after.value, after.span),
                                         stuffing.span),)
        escaping = self.object(m.get("escaping"), "`escaping`")
        if escaping is not None:
            e = self.members(escaping, "`escaping`", ("escape", "codes"))
            escape = self.required(escaping, e, "escape", "`escaping`", self.string)
            codes = self.required(escaping, e, "codes", "`escaping`", self.object)
            if escape is not None and codes is not None:
                table = []
                for key, value in codes.members:
                    code = self.string(value, "a code")
                    if code is not None:
                        table.append((ast.StrLit(key.value, key.span), ast.StrLit(code.value, code.span)))
                items += (ast.FrameEscape(ast.StrLit(escape.value, escape.span), tuple(table), span=escaping.span),)
        return ast.FrameDecl(name, params, items, obj.span, self.doc(m))

    def frame_parts(self, value: JValue | None, what: str) -> tuple[ast.FramePart, ...]:
        """One layout's parts; `{"optional": N}` takes the N parts after it into an `optional`."""
        objs = [self.object(p, "a frame part") for p in self.array(value, what)]
        out: list[ast.FramePart | None] = []
        at = 0
        while at < len(objs):
            obj = objs[at]
            at += 1
            if obj is None or not any(k.value == "optional" for k, _ in obj.members):
                out.append(None if obj is None else self.frame_part(obj, objs))
                continue
            count = self.members(obj, "an optional part", ("optional",)).get("optional")
            if not (isinstance(count, JNumber) and count.value == int(count.value) and 1 <= count.value <= len(objs) - at):
                self.error(obj.span, f"`optional` is the number of parts after it that a reply may lack (1 to "
                                     f"{len(objs) - at})")
                continue
            inner = [None if p is None else self.frame_part(p, objs) for p in objs[at : at + int(count.value)]]
            out.append(ast.FrameOptional(present(inner), obj.span))
            at += int(count.value)
        return present(out)

    def frame_part(self, obj: JObject, side: list[JObject | None]) -> ast.FramePart | None:
        keys = [k.value for k, _ in obj.members]
        role = next((r for r in _BYTES_ROLES if r in keys), None)
        if role is not None:
            m = self.members(obj, f"a `{role}` part", (role,))
            s = self.string(m.get(role), f"`{role}`")
            return None if s is None else ast.FrameBytes(role, ast.StrLit(s.value, s.span), obj.span)
        if "field" in keys:
            m = self.members(obj, "a frame field", ("field", "format", "value"))
            name, fmt = self.ident(m["field"], "`field`"), self.string(m.get("format"), "`format`")
            value = self.required(obj, m, "value", "a frame field", lambda v, _: self.expr(v, "int"))
            if name is None or fmt is None or value is None:
                return None
            return ast.FrameField(name, ast.StrLit(fmt.value, fmt.span), value, obj.span)
        if "length" in keys:
            m = self.members(obj, "a length part", ("length", "adjust"))
            fmt, adjust = self.string(m.get("length"), "`length`"), m.get("adjust")
            if fmt is None:
                return None
            amount = int(adjust.value) if isinstance(adjust, JNumber) else 0
            return ast.FrameLength(ast.StrLit(fmt.value, fmt.span), amount, obj.span)
        if "bits" in keys:
            return self.bits(obj)
        if "payload" in keys:
            given = self.members(obj, "a payload part", ("payload",)).get("payload")
            trimmed = isinstance(given, JString) and given.value == "trimmed"
            if not trimmed and not isinstance(given, JBool):
                self.error(obj.span, 'a payload part is `"payload": true` or `"payload": "trimmed"`')
            return ast.FramePayload(obj.span, trimmed)
        if "checksum" in keys:
            return self.checksum(obj, side)
        self.error(obj.span, "a frame part is one of header, literal, terminator, field, length, bits, payload, "
                             "checksum, optional")
        return None

    def bits(self, obj: JObject) -> ast.FrameBits | None:
        """`{"bits": "<I", "fields": [{"length": true, "width": 30, "adjust": 0}, {"field": "mode", ...}]}`."""
        m = self.members(obj, "a bits part", ("bits", "fields"))
        fmt = self.string(m.get("bits"), "`bits`")
        out: list[ast.FrameBitField | None] = []
        for entry in self.array(m.get("fields"), "`fields`"):
            o = self.object(entry, "a bit field")
            if o is None:
                out.append(None)
                continue
            keys = [k.value for k, _ in o.members]
            f = self.members(o, "a bit field", ("length", "adjust", "width") if "length" in keys else
                             ("field", "width", "value"))
            width = f.get("width")
            if not (isinstance(width, JNumber) and width.value == int(width.value)):
                self.error(o.span, "a bit field has a `width`: its number of bits")
                out.append(None)
                continue
            if "length" in keys:
                adjust = f.get("adjust")
                out.append(ast.FrameBitField(None, int(width.value), None,
                                             int(adjust.value) if isinstance(adjust, JNumber) else 0, o.span))
                continue
            name = self.required(o, f, "field", "a bit field", self.ident)
            value = self.required(o, f, "value", "a bit field", lambda v, _: self.expr(v, "int"))
            out.append(None if name is None or value is None else
                       ast.FrameBitField(name, int(width.value), value, 0, o.span))
        return None if fmt is None else ast.FrameBits(ast.StrLit(fmt.value, fmt.span), present(out), obj.span)

    def checksum(self, obj: JObject, side: list[JObject | None]) -> ast.FrameChecksum | None:
        m = self.members(obj, "a checksum", _CHECKSUM)
        name, fmt = self.string(m.get("checksum"), "`checksum`"), self.string(m.get("format"), "`format`")
        if name is None or fmt is None:
            return None
        options: list[ast.ChecksumOption] = []
        given = m.get("inverted")
        if isinstance(given, JBool) and given.value:
            options.append(ast.ChecksumOption("inverted", span=given.span))
        # `reflect` is written only for a CRC given by its parameters: a catalogue CRC fixes its own
        if name.value.lower() in ("crc", "sum", "xor"):
            ways = [isinstance(way, JBool) and way.value for way in (m.get("reflectIn"), m.get("reflectOut"))]
            if any(ways):
                word = "reflect" if all(ways) else ("reflect in" if ways[0] else "reflect out")
                options.append(ast.ChecksumOption(word, span=m["reflectIn" if ways[0] else "reflectOut"].span))
        settings = ("mask", "width", "poly", "init", "xorOut") if name.value.lower() == "crc" else ("mask",)
        for key in settings:
            if isinstance(m.get(key), JNumber):
                options.append(ast.ChecksumOption(key.lower(), self.expr(m[key], "int"), span=m[key].span))
        covers = self.array(m.get("covers"), "`covers`")
        here = side.index(obj)
        numbers = [c.value for c in covers if isinstance(c, JNumber)]
        if len(covers) == 2 and len(numbers) == 2:
            first, last = numbers
            if not (first == int(first) and last == int(last) and 0 <= first <= last < here):
                self.d.report("E008", m["covers"].span, f"`covers` is [first, last], the indexes of two parts before "
                                                        f"the checksum (0 to {here - 1}), first <= last")
                first, last = (1 if here > 1 else 0), here - 1
            first, last = int(first), int(last)
            with_request = m.get("withRequest")
            request = isinstance(with_request, JBool) and with_request.value
            header = side and side[0] is not None and any(k.value == "header" for k, _ in side[0].members)
            if request or (first, last) != (1 if header else 0, here - 1):
                names = [_part_name(p) for p in side]
                over = ([ast.Ident("request", m["covers"].span)] if request else
                        [ast.Ident(names[first], m["covers"].span)])
                over.append(ast.Ident(names[last], m["covers"].span))
                options.append(ast.ChecksumOption("over", over=tuple(over), span=m["covers"].span))
        if "seed" in m:
            seed = self.members(m["seed"], "a checksum's seed", ("table", "field")) \
                if isinstance(m["seed"], JObject) else {}
            table, field = (self.string(seed.get(word), f"the seed's `{word}`") for word in ("table", "field"))
            if table is None or field is None:
                self.d.report("E008", m["seed"].span, 'a checksum\'s `seed` is {"table": NAME, "field": NAME}')
            else:
                options.append(ast.ChecksumOption("seed", over=(ast.Ident(table.value, table.span),
                                                                ast.Ident(field.value, field.span)), span=m["seed"].span))
        encoding = None if fmt.value == "hex" else ast.StrLit(fmt.value, fmt.span)
        return ast.FrameChecksum(ast.StrLit(name.value, name.span), encoding, tuple(options), obj.span)


def _part_name(part: JObject | None) -> str:
    """The name a checksum's `over` gives a frame part."""
    for key, value in part.members if part else ():
        if key.value in _BYTES_ROLES or key.value in ("length", "payload"):
            return key.value
        if key.value == "field" and isinstance(value, JString):
            return value.value
        if key.value == "fields" and isinstance(value, JArray):  # a `bits` part: any of its fields names it
            names = [_part_name(f) if isinstance(f, JObject) else "" for f in value.items]
            return "length" if "length" in names else next(iter(names), "checksum")
    return "checksum"
