"""Requests and replies as bytes: `pack`/`format` templates and the values they take, `unpack`/
`regex` decodings, a frame used by a primitive, and constants that must fit their codes."""

from __future__ import annotations

import math
from collections.abc import Sequence

from rdisc.diagnostics import Label, abbreviate
from rdisc.frozen import replace
from rdisc.semantics import formats
from rdisc.semantics import model as m
from rdisc.semantics.check.pieces import Pieces, counted
from rdisc.semantics.frame_facts import (
    length_part,
    length_range,
    length_words,
    payload_end_known,
)
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.operators import shown
from rdisc.semantics.types import Env, describe
from rdisc.source import Span
from rdisc.syntax import ast

FLOAT_LIMITS = {"e": 65504.0, "f": 3.4028234663852886e38}  # the largest finite half and single floats


class Layouts(Pieces):
    """The rules of message templates and of the frames a primitive is read and written through."""

    def request_sizes(self, encoding: m.Pack | m.Format | None, args: tuple[m.Expr, ...],
                      params: tuple[m.Parameter, ...]) -> tuple[int, int, str] | None:
        """The fewest and most bytes a packed request can have, and what decides them: a
        `*` rest of constant bytes or of a `bytes` parameter with a range (None otherwise)."""
        if not isinstance(encoding, m.Pack):
            return None
        layout = encoding.layout
        if layout.varying is not None:
            rounds = formats.most_rounds(layout, [args[i].type for i in formats.varying_args(layout, encoding.grouped)])
            return layout.size, layout.most(rounds), f"a repeated group of up to {rounds} rounds"
        if not layout.rest:
            return layout.size, layout.size, ""
        rest = args[-1] if args else None
        value = self.typer.constant(rest) if rest is not None else None
        if isinstance(value, bytes):
            return layout.size + len(value), layout.size + len(value), ""
        if isinstance(rest, m.Var) and rest.scope is Scope.PARAM:
            param = next(p for p in params if p.name == rest.name)
            if param.low is not None and param.high is not None:
                return layout.size + int(param.low), layout.size + int(param.high), f"parameter `{param.name}`"
        return None

    def frame_use(self, clause: ast.Framed, env: Env, decl: ast.PrimitiveDecl, encoding: m.Pack | m.Format | None,
                  replies: Sequence[m.Unpack | m.Regex], request: tuple[int, int, str] | None) -> m.FrameUse | None:
        """`frame NAME(args)`: its arguments, and whether the frame can carry this primitive."""
        frame = self.frames.get(clause.frame.text)
        target = self.s.frames.get(clause.frame.text)
        args = self.call(ast.Call(clause.frame, clause.args, clause.span), frame.params if frame else None, env,
                         "frame", target.name if target else None)
        if frame is None:
            return None
        self.frame_fields_fit(frame, clause, args)
        has_payload = any(isinstance(p, m.FramePayload) for p in frame.reply)
        if replies and frame.reply and not has_payload:
            self.d.report("E504", clause.span, f"primitive `{decl.name.text}` decodes a reply, but the reply of "
                          f"frame `{frame.name}` has no `payload`")
        reply_sizes = []
        for decoding in replies:
            layout = decoding.layout if isinstance(decoding, m.Unpack) else None
            reply_sizes.append(layout.size if layout is not None and not layout.open_end else None)
        if any(not payload_end_known(frame, size is not None) for size in reply_sizes):
            self.d.report("E503", clause.span, f"the reply of frame `{frame.name}` gives no way to find where the "
                          f"payload of `{decl.name.text}` ends",
                          help="add a `length` field, constant bytes after the payload, or decode with `unpack`")
        self.answered_by_settings(frame, clause, args)
        sizes = [(frame.requests, request, bool(frame.request_when)),
                 *((frame.replies, None if n is None else (n, n, ""), bool(frame.reply_when)) for n in reply_sizes)]
        for layouts, payload, chosen in sizes:
            found = [length_part(parts) for parts in layouts]
            if chosen:  # `either when`: any layout with a length field may be the one written
                found = [length for length in found if length is not None]
            if not found or None in found or payload is None:  # a layout without a length field carries any payload
                continue
            lengths = [length for length in found if length is not None]
            ranges = [length_range(length) for length in lengths]
            low, high = min(r[0] for r in ranges), max(r[1] for r in ranges)  # the writer takes the first that fits
            if chosen:
                low, high = max(r[0] for r in ranges), min(r[1] for r in ranges)
            fewest, most, by = payload
            if low <= fewest and most <= high:
                continue
            field = (f"the length field {length_words(lengths[0])}" if len(lengths) == 1 else
                     "the length fields " + ", ".join(length_words(length) for length in lengths))
            states = f"{'it states' if len(lengths) == 1 else 'they state'} payloads of {low} to {high} bytes"
            if not by:
                self.d.report("E503", clause.span, f"{field} of frame `{frame.name}` "
                              f"cannot state the {fewest}-byte payload of `{decl.name.text}`", help=states)
            else:
                self.d.report("E503", clause.span, f"{field} of frame `{frame.name}` "
                              f"cannot state every payload of `{decl.name.text}`: {fewest} to {most} bytes, as "
                              f"{by} allows", help=f"{states}; " + (f"narrow the range of {by}" if "parameter" in by else
                                                                   "give the group's arrays a fixed size, or fewer"))
        return m.FrameUse(m.FrameRef(frame.name), args)

    def answered_by_settings(self, frame: m.Frame, clause: ast.Framed, args: tuple[m.Expr, ...]) -> None:
        """A reply's layout chosen by `either when` is the device's configuration, known when
        connecting: each argument its conditions read is a setting or a constant (E513)."""
        read = {v.name for e in frame.reply_when if e is not None for v in m.variables(e)}
        for param, arg, given in zip(frame.params, args, clause.args):
            wrong = next((v for v in m.variables(arg) if param.name in read
                          and (v.scope is not Scope.STATE or v.name not in self.s.settings)), None)
            if wrong is not None:
                what = "parameter" if wrong.scope is Scope.PARAM else "state variable"
                self.d.report("E513", given.span, f"the reply's layout is chosen by `{param.name}` of frame "
                              f"`{frame.name}`, so it is a setting or a constant, but this reads {what} "
                              f"`{wrong.name}`", help="pass a setting: the device answers as it is configured, "
                              "which is known when connecting")

    def frame_fields_fit(self, frame: m.Frame, clause: ast.Framed, args: tuple[m.Expr, ...]) -> None:
        """Each field of a frame over its parameters, computed from the constant arguments of
        this use (those in their ranges: one outside is reported already), must fit its code."""
        known: dict[str, object] = {}
        for param, arg in zip(frame.params, args):
            value = self.typer.constant(arg)
            if arg.type is not param.type or value is None:  # a mismatch is reported already
                continue
            if param.low is None or param.low <= value <= param.high:  # type: ignore[operator]
                known[param.name] = value
        spans = {p.name: expr.span for p, expr in zip(frame.params, clause.args)}
        seen: set[tuple[str, m.Expr]] = set()
        parts = [part for layout in (*frame.requests, *frame.replies) for part in layout]
        for part in [*parts, *(bit for bits in parts if isinstance(bits, m.FrameBits) for bit in bits.fields)]:
            if (not isinstance(part, (m.FrameField, m.BitField)) or part.value is None
                    or (part.name, part.value) in seen
                    or self.typer.is_constant(part.value)):  # a constant field is checked with its frame
                continue
            seen.add((part.name, part.value))
            computed = self.typer.value_over(part.value, known)
            direct = isinstance(part.value, m.Var) and part.value.name in spans
            span = spans[part.value.name] if isinstance(part.value, m.Var) and direct else clause.span
            where = f" of frame `{frame.name}`" if direct else f" as field `{part.name}` of frame `{frame.name}`"
            if isinstance(part, m.BitField):
                if isinstance(computed, int) and not isinstance(computed, bool) and not 0 <= computed < 1 << part.width:
                    self.d.report("E403", span, f"{computed} does not fit the {part.width} bits of field "
                                  f"`{part.name}`{where}", label=f"field `{part.name}` is {part.width} bits, "
                                  f"0 to {(1 << part.width) - 1}")
                continue
            if not part.layout.slots:  # refused: the frame's own check reported it
                continue
            slot = part.layout.slots[0]
            self.fits(computed, slot, span, where,
                      f"field `{part.name}` is packed as `{slot.code}`, {slot.low} to {slot.high}")

    def template_span(self, lit: ast.StrLit, offset: int, length: int) -> Span:
        """The span of characters inside a template, exact when the literal has no escapes."""
        s = lit.span
        prefix = s.end - s.start - len(lit.value) - 1  # 1 for `"`, 2 for `r"`
        if prefix in (1, 2):
            start = s.start + prefix + offset
            return Span(s.path, start, min(start + max(length, 1), s.end - 1))
        return s

    def encoding(self, enc: ast.Encoding, env: Env) -> tuple[m.Pack | m.Format | None, tuple[m.Expr, ...]]:
        args = tuple(self.typer.expr(a, env) for a in enc.args)
        template = enc.template.value
        try:
            layout = None
            if enc.kind == "pack":
                layout = formats.struct_layout(template)
                slots: tuple[formats.Slot | formats.FormatField, ...] = layout.slots
                if layout.native:
                    self.native_warning(enc.template)
            else:
                slots = formats.format_fields(template)
        except formats.TemplateError as err:
            code = "E301" if enc.kind == "pack" else "E303"
            self.d.report(code, self.template_span(enc.template, err.offset, err.length), err.message)
            return None, args
        arrays = [(arg, expr) for arg, expr in zip(args, enc.args) if isinstance(arg.type, m.Array)]
        if arrays and enc.kind == "format":
            array, written = arrays[0]
            self.d.report("E401", written.span, f"a format field cannot format {describe(array.type)}",
                          help="format its elements: `position[0]`")
            return None, args
        values: list[m.Expr] = []  # one a slot: an array spread into its elements, except into a group
        exprs: list[ast.Expr] = []
        grouped: list[int] = []
        for i, (arg, expr) in enumerate(zip(args, enc.args)):
            slot = slots[len(values)] if len(values) < len(slots) else None
            if isinstance(slot, formats.Slot) and slot.repeat:
                grouped.append(i)
                values.append(arg)
                exprs.append(expr)
                continue
            spread = m.spread((arg,))
            values.extend(spread)
            exprs.extend([expr] * len(spread))
        if len(slots) != len(values):
            given = counted(len(args), "argument") + (f" giving {counted(len(values), 'value')}" if arrays else " given")
            self.d.report(
                "E302", enc.span,
                f"`{enc.kind} \"{abbreviate(template)}\"` takes {counted(len(slots), 'value')}, but {given}",
                help="an array gives each of its elements" if arrays else None,
            )
            return None, args
        for arg, expr, slot in zip(values, exprs, slots):
            if isinstance(slot, formats.FormatField):  # `format`: every slot is one; `pack`: none is
                self.format_value(arg, expr, slot)
            elif slot.repeat:
                self.group_value(arg, expr, slot)
            else:
                self.pack_value(self.typer.folded(arg), expr, slot)
        if layout is not None and layout.width >= 0:
            self.widths_fit(layout, values, exprs)
        if layout is not None and layout.varying is not None:
            self.rounds_fit(layout, [(args[i], enc.args[i]) for i in formats.varying_args(layout, tuple(grouped))])
        if layout is not None:
            return m.Pack(template, layout, tuple(grouped)), args
        return m.Format(template), args

    def widths_fit(self, layout: formats.StructLayout, values: list[m.Expr], exprs: list[ast.Expr]) -> None:
        """A constant given to a `%` code fits the bytes a constant width field states (the run
        refuses one that does not, where either is known only then)."""
        width = self.typer.constant(values[layout.width])
        if not isinstance(width, int) or isinstance(width, bool) or not 1 <= width <= formats.MOST_WIDTH:
            return
        sized = replace(layout.slots[layout.width], code="%", low=0, high=(1 << 8 * width) - 1)
        for value, expr, slot in zip(values, exprs, layout.slots):
            constant = self.typer.constant(value) if slot.code == "%" else None
            for item in constant if isinstance(constant, tuple) else ():
                self.fits(item, sized, expr.span, "", f"the width field `{layout.slots[layout.width].code}` states "
                          f"{width} bytes: 0 to {sized.high}")

    def rounds_fit(self, layout: formats.StructLayout, arrays: list[tuple[m.Expr, ast.Expr]]) -> None:
        """The arrays of a group repeated as the message says: of one size where their sizes are
        fixed, and no more than its count field holds."""
        assert layout.varying is not None
        sized = [(t.size, expr) for arg, expr in arrays if isinstance(t := arg.type, m.Array) and t.size]
        if any(size != sized[0][0] for size, _ in sized):
            size, expr = next((size, expr) for size, expr in sized if size != sized[0][0])
            self.d.report("E403", expr.span, f"the arrays of a repeated group have one size, but this one has {size} "
                          f"values and the first {sized[0][0]}", labels=(Label(sized[0][1].span, "the first"),))
        high = layout.varying.count_high
        if high and sized and max(size for size, _ in sized) > high:
            size, expr = max(sized, key=lambda item: item[0])
            self.d.report("E403", expr.span, f"the count field `#{layout.varying.count_code}` holds at most {high}, but this array "
                          f"has {size} values", help="count the group with a wider field: `#H`")

    def native_warning(self, lit: ast.StrLit) -> None:
        self.d.report(
            "W301", lit.span, f"struct format \"{abbreviate(lit.value)}\" has no byte order",
            label="host byte order and alignment", help=f"write \">{lit.value.lstrip('@')}\" (big-endian) or "
            f"\"<{lit.value.lstrip('@')}\" (little-endian), as the device expects",
        )

    def group_value(self, arg: m.Expr, expr: ast.Expr, slot: formats.Slot) -> None:
        """A repeated group's code takes an array of the group's count (of any size when the
        message says it), each element as the code takes a value."""
        code = f"`{slot.code}` of a group of {slot.repeat}" if slot.repeat > 0 else f"`{slot.code}` of a repeated group"
        self.flow(arg, m.Array(slot.type, max(slot.repeat, 0)), expr.span, f"pack code {code}")
        value = self.typer.constant(arg)
        if isinstance(value, tuple) and slot.low is not None:
            for item in value:
                self.fits(item, slot, expr.span, "", f"{code} holds {slot.low} to {slot.high}")

    def pack_value(self, arg: m.Expr, expr: ast.Expr, slot: formats.Slot) -> None:
        self.flow(arg, slot.type, expr.span, f"pack code {slot.shown}")
        value = self.typer.constant(arg)
        if arg.type is Type.INT:
            self.fits(value, slot, expr.span, "", f"{slot.shown} holds {slot.low} to {slot.high}")
        if slot.code == "c" and isinstance(value, str) and len(value) != 1:
            self.d.report("E403", expr.span, "pack code `c` takes a string of exactly one character")
        elif slot.code[-1:] in ("s", "p", "Z") and isinstance(value, str):
            room = formats.text_room(slot.code)
            if len(value) > room:
                self.d.report("E403", expr.span, f"{shown(value)} is {len(value)} characters; `{slot.code}` holds "
                              f"{room}, and struct would cut the rest")
        elif slot.code in FLOAT_LIMITS and isinstance(value, (int, float)) and not isinstance(value, bool) \
                and (isinstance(value, int) or math.isfinite(value)) and abs(value) > FLOAT_LIMITS[slot.code]:
            self.d.report("E403", expr.span, f"{shown(value)} is too large for pack code `{slot.code}` "
                          f"(at most {FLOAT_LIMITS[slot.code]:g})")

    def format_value(self, arg: m.Expr, expr: ast.Expr, field: formats.FormatField) -> None:
        if arg.type is None or formats.spec_accepts(field.spec, arg.type):
            return
        written = f"{{:{field.spec}}}" if field.spec else "{}"
        if arg.type is Type.FLOAT and formats.spec_accepts(field.spec, Type.INT):
            self.d.report(
                "E402", expr.span, f"format field `{written}` takes an int, but this is a float",
                help="convert it: `round(...)` to the nearest integer, `int(...)` towards zero",
            )
        else:
            self.d.report("E401", expr.span, f"format field `{written}` cannot format {describe(arg.type)}",
                          help="write bytes as text with `ascii(...)` or `hex(...)`" if arg.type is Type.BYTES
                          else None)

    def decoding(self, dec: ast.Decoding) -> tuple[m.Unpack | m.Regex | None, tuple[m.AnyType, ...] | None]:
        """The decoding and the types of its values; None for a template already reported."""
        template = dec.template.value
        try:
            if dec.kind == "unpack":
                layout = formats.struct_layout(template)
                if layout.width >= 0:
                    raise formats.TemplateError("a width field `%H` and its `%` codes are for requests (`pack`): "
                                                "a reply's are read as `*` bytes", template.index("%"))
                if layout.native:
                    self.native_warning(dec.template)
                types = tuple(m.Array(s.type, max(s.repeat, 0)) if s.repeat else s.type for s in layout.slots)
                return m.Unpack(template, layout), types
            groups = formats.regex_groups(template)
            return m.Regex(template), (Type.STRING,) * groups
        except formats.TemplateError as err:
            code = "E301" if dec.kind == "unpack" else "E304"
            self.d.report(code, self.template_span(dec.template, err.offset, err.length), err.message)
            return None, None

    def constants_into_pack(self, prim: m.Primitive, args: tuple[m.Expr, ...], exprs: tuple[ast.Expr, ...]) -> None:
        """A constant argument whose parameter goes straight into a pack code must fit it."""
        if not isinstance(prim.encoding, m.Pack) or len(args) != len(prim.params):
            return
        slots = prim.encoding.layout.slots
        for slot, packed in zip(slots, prim.format_values()):
            if not isinstance(packed, m.Var) or packed.scope is not Scope.PARAM or slot.low is None:
                continue
            i = next(i for i, p in enumerate(prim.params) if p.name == packed.name)
            if i >= len(exprs):  # its default, checked where it is declared
                continue
            self.fits(
                self.typer.constant(args[i]), slot, exprs[i].span, f" of primitive `{prim.name}`",
                f"parameter `{packed.name}` is packed as {slot.shown}, {slot.low} to {slot.high}",
            )

    def fits(self, value: object, slot: formats.Slot, span: Span, where: str, label: str) -> None:
        """A constant integer must fit the range of the pack code it is written with."""
        if slot.low is None or not isinstance(value, int) or isinstance(value, bool):
            return
        if not slot.low <= value <= slot.high:  # type: ignore[operator]
            self.d.report("E403", span, f"{shown(value)} does not fit pack code {slot.shown}{where}", label=label)
