"""`rdisc dump`: each primitive's wire layout as a byte table, to hold against the
device's manual: offset, size, kind and value of every part of the request and the
reply, frames included. Sizes that depend on the values (text) show as `n`. Constant
bytes show in hex as they go on the wire (a constant integer of a format with its
decimal value after it: `84 (132)`), text as RDIS spells it (`"\\r\\n"` escaped).
"""

from __future__ import annotations

import re
import string
import struct
import sys
from collections.abc import Callable
from dataclasses import dataclass

from rdisc.emit.canonical import expression_text, range_written
from rdisc.engine.wire import Bits
from rdisc.semantics import model as m
from rdisc.semantics.formats import format_width
from rdisc.syntax.printer import spell_template


def dump(model: m.Model) -> str:
    blocks = [_primitive(model, p) for p in model.primitives.values()]
    return "\n".join(blocks)


def primitive_layout(model: m.Model, name: str) -> str:
    """One primitive's block of the dump (an editor's hover shows it)."""
    return _primitive(model, model.primitives[name])


def frame_layout(frame: m.Frame) -> str:
    """A frame's request and reply tables around a payload of any size (an editor's hover)."""
    payload: list[Row] = [(None, "bytes", "the primitive's")]
    lines = _sides("request", frame.requests, payload, False, frame.request_when)
    if frame.reply:
        lines += _sides("reply", frame.replies, payload)
    return "\n".join(lines) + "\n"


def _primitive(model: m.Model, p: m.Primitive) -> str:
    params = ", ".join(f"{x.name}: {x.type.value}" + (f" in {range_written(x)}" if x.low is not None else "")
                       for x in p.params)
    head = f"primitive {p.name}({params}) on {p.connection}"
    frame = model.frames[p.frame.frame] if p.frame is not None else None
    if p.frame is not None:
        head += f", frame {p.frame.frame}({', '.join(expression_text(a) for a in p.frame.args)})"
    lines = [head]
    if frame is not None and frame.stuffing is not None:
        reserved, escape = (" ".join(f"{ord(c):02X}" for c in text) for text in frame.stuffing)
        lines.append(f"  payloads stuffed: {escape} inserted after every {reserved}")
    if frame is not None and frame.escaping is not None:
        escape = f"{ord(frame.escaping.escape):02X}"
        codes = ", ".join(f"{ord(byte):02X} as {escape} {ord(code):02X}" for byte, code in frame.escaping.table)
        lines.append(f"  escaped between the flags: {codes}")
    if p.lines:
        levels = ", ".join(f"break {expression_text(level.value)} ms" if level.line == m.BREAK
                           else f"{level.line} = {expression_text(level.value)}" for level in p.lines)
        lines.append(f"  lines: {levels} (set before the request)" if p.encoding else f"  lines: {levels}")
    if p.encoding is None:
        lines.append("  request: none")
    else:
        lines += _sides("request", frame.requests if frame else None, _payload_rows(p.encoding, p.args), False,
                        frame.request_when if frame else ())
    if p.reply_frames:  # each reply through its own frame, all of one frame
        frame = model.frames[p.reply_frames[0].frame]
    framed = frame.replies if frame and frame.reply else None
    answered = frame.reply_when if frame and frame.reply else ()  # `either when`: each layout's condition
    if p.table is not None:
        for case in p.table.cases:
            said = case.values_text()
            if p.table.tag is None:
                lines += _sides(f"reply when {p.table.key} = {said}", framed, _reply_rows(case.decoding), True, answered)
            else:
                rows = [*_tag_rows(p.table, case), *_reply_rows(case.decoding)]
                said = said if case.under is None else f"{case.under} then {said}"
                if p.table.each:  # one sub-payload; the frame is shown around the first alone
                    if p.table.length_layout is not None:
                        assert isinstance(case.decoding, m.Unpack)  # sub-payloads are bytes (E505)
                        layout = case.decoding.layout  # its pad bytes too
                        size = None if layout.rest or layout.varying else layout.size
                        length = p.table.length_layout
                        rows.insert(1, (length.size, f"length {_integer_kind(length)}",
                                        "of what follows" if size is None else f"= {size}"))
                    if case is p.table.cases[0]:
                        skipped = " (an unknown tag skipped by its length)" if p.table.length else ""
                        lines += _sides("reply", framed, [(None, "sub-payloads", f"each a tag and its bytes{skipped}")], True,
                                        answered)
                    lines += _sides(f"sub-payload tagged {said}", None, rows)
                    continue
                lines += _sides(f"reply tagged {said}", framed, rows, True, answered)
    elif p.listed:  # each reply its own shape, through its own frame or the primitive's
        for n, r in enumerate(p.listed, 1):
            use = r.frame or p.frame
            own = model.frames[use.frame] if use is not None else None
            through = "" if r.frame is None else \
                f", frame {r.frame.frame}({', '.join(expression_text(a) for a in r.frame.args)})"
            lines += _sides(f"reply {n} of {len(p.listed)}{through}", own.replies if own and own.reply else None,
                            _reply_rows(r.decoding), True, own.reply_when if own else ())
    elif p.expects_reply(model.frames):
        uses = [f"{use.frame}({', '.join(expression_text(a) for a in use.args)})" for use in p.reply_frames]
        through = f", frame {uses[0]} .. {uses[-1]}" if uses else ""
        rows = _reply_rows(p.decoding)
        if p.records is not None:  # one record; the frame is shown around it
            rows.append((len(p.records), "record end", _hex(p.records.encode("latin-1"))))
        said = f"{p.replies} replies{through}, each" if p.replies else "reply"
        if p.each is not None:  # one frame, its arguments reading each element
            sized = "a reply" if not p.each.array(p.params).size else f"{p.replies} replies, one"
            said = f"{sized} for each of {p.each.over}, frame {uses[0]}, each"
        lines += _sides("reply: records, each" if p.records is not None else said, framed, rows, True, answered)
        if p.error is not None and p.error.when is not None:  # the reply itself says no
            named = "" if p.error.codes is None else f", named by {p.error.codes}"
            condition = expression_text(p.error.when).replace("__out__[", "out[")  # JSON's name for the reply
            lines.append(f"  or an error when {condition}: out[0] its code{named}")
        elif p.error is not None:
            name, sides, rows = _error_layout(model, p, p.error)
            lines += _sides(name, sides, rows)
    else:
        lines.append("  reply: none")
    lines += [f"  out[0] is sensor {s.name}, kept {s.cache_ms:g} ms" for s in model.sensors.values() if s.primitive == p.name]
    return "\n".join(lines) + "\n"


def _error_layout(model: m.Model, p: m.Primitive,
                  e: m.ErrorReply) -> tuple[str, tuple[tuple[m.FramePart, ...], ...] | None, list[Row]]:
    """The reply that may come instead (`error`): its name, its frame's layouts (its own, or the
    primitive's, or none) and its payload's rows, the marker first and the code named."""
    use = e.frame or p.frame
    frame = model.frames[use.frame] if use is not None else None
    through = "" if e.frame is None else f", frame {e.frame.frame}({', '.join(expression_text(a) for a in e.frame.args)})"
    rows = _reply_rows(e.decoding)
    if rows and e.codes is not None:
        size, what, _ = rows[0]
        rows[0] = (size, what, f"code, named by {e.codes}")
    if e.marker:
        rows.insert(0, (len(e.marker), "error marker", _hex(e.marker.encode("latin-1"))))
    return f"or an error{through}", frame.replies if frame is not None and frame.reply else None, rows


Row = tuple[int | None, str, str]  # size (None: varies), what, detail


_KINDS = {"b": "s8", "B": "u8", "h": "s16", "H": "u16", "i": "s32", "I": "u32", "l": "s32", "L": "u32",
          "q": "s64", "Q": "u64", "e": "f16", "f": "f32", "d": "f64", "?": "bool", "c": "char"}


def _kind(layout: m.StructLayout, code: str, size: int) -> str:
    """`s16 BE`, `u8`, `text`, `bytes`: what a struct code of `size` bytes holds, with its byte
    order when it has one."""
    if code == "*":
        return "bytes (the rest)"
    if code.endswith("Z"):
        return "text, padded"
    if code == "%":  # as many bytes as the width field states
        return "uint, width" + {">": " BE", "!": " BE", "<": " LE"}[layout.order]
    kind = f"u{8 * size}" if code == "s{" else _KINDS.get(code[-1], "text")  # `s{`: bytes split into bits
    if size == 1 or kind == "text":
        return kind
    return kind + {">": " BE", "!": " BE", "<": " LE"}.get(layout.order, " native")


def _tag_rows(table: m.ReplyTable, case: m.ReplyCase) -> list[tuple[int | None, str, str]]:
    """The tag choosing an entry, and a nested table's tag after it (Firmata's F0, then 79)."""
    assert table.tag_layout is not None
    said = case.values_text()
    if case.under is None:
        return [(table.tag_layout.size, f"tag {_integer_kind(table.tag_layout)}",
                 f"= {said}" if case.last is None else f"in {said}")]
    inner = case.under_layout
    assert inner is not None
    return [(table.tag_layout.size, f"tag {_integer_kind(table.tag_layout)}", f"= {case.under}"),
            (inner.size, f"tag {_integer_kind(inner)}", f"= {said}" if case.last is None else f"in {said}")]


def _integer_kind(layout: m.StructLayout) -> str:
    """What the one integer of a one-integer format holds: `u8`, `u16 LE`."""
    return _kind(layout, layout.slots[0].code, layout.size)


def _slot_size(slot: m.Slot) -> int | None:
    """Bytes of one value of a slot; None for `*`, the rest of the message, and `%`, as many as
    the width field states."""
    return None if slot.code in ("*", "%") else slot.size


def _payload_rows(encoding: m.Pack | m.Format, args: tuple[m.Expr, ...]) -> list[Row]:
    match encoding:
        case m.Pack(layout=layout, grouped=grouped):
            values = [v for i, a in enumerate(args) for v in ((a,) if i in grouped else m.spread((a,)))]
            codes = [_code_format(layout, slot.code) for slot in layout.slots]
            return _rows(layout, lambda j, k: _value_text(values[j], k, codes[j]), [_constant_rest(v) for v in values])
        case m.Format(template=template):
            shown = ", ".join(expression_text(a) for a in args)
            return [(None, "text", spell_template(template) + (f" ({shown})" if shown else ""))]
    raise AssertionError(encoding)


def _rows(layout: m.StructLayout, text: Callable[[int, int | None], str],
          given: list[Row | None] | None = None) -> list[Row]:
    """One row a value of the format, in wire order: a repeated group's arrays element by
    element (`text(slot, element)`: `goal[0]`, `goal[1]`, ...), a group repeated as the
    message says once, as element `i`, after its count field; an integer split into bit fields
    once, its fields with their bits; `given`, a value's own row where it has one."""
    slots = layout.slots
    groups = {first: (codes, count) for first, codes, count in layout.groups}
    splits = {first: (code[-1] + "{" if code.endswith("s") else code[-1], len(widths))
              for first, code, widths in layout.bits}
    varying = layout.varying
    pads = _pads(layout)
    rows: list[Row] = []
    at = 0
    while at <= len(slots):
        if at in pads:
            rows.append((pads[at], "pad", "zero bytes, skipped when read"))
        if varying is not None and at == varying.count_slot:
            size = varying.count_size
            kind = _kind(layout, varying.count_code, size)
            rows.append((size, f"count {kind}", "k (the rounds of the group)"))
        if at == len(slots):
            break
        if at in groups and not groups[at][1]:
            codes = groups[at][0]
            rows += [(None, f"{_kind(layout, slots[j].code, slots[j].size)} x k", text(j, None) + "[i]")
                     for j in range(at, at + codes)]
            at += codes
            continue
        if at in splits:
            code, fields = splits[at]
            said = [f"{text(j, None)} ({m.bit_span(*slots[j].bits or (0, 0))})"
                    for j in range(at, at + fields)]
            rows.append((slots[at].size, f"bits {_kind(layout, code, slots[at].size)}", ", ".join(said)))
            at += fields
            continue
        if at in groups:
            codes, count = groups[at]
            for element in range(count):
                rows += [(_slot_size(slots[j]), _kind(layout, slots[j].code, slots[j].size), text(j, element))
                         for j in range(at, at + codes)]
            at += codes
            continue
        slot = slots[at]
        rows.append((given[at] if given else None)
                    or (_slot_size(slot), _kind(layout, slot.code, slot.size), text(at, None)))
        at += 1
    return rows


def _pads(layout: m.StructLayout) -> dict[int, int]:
    """The pad bytes (`x`) of a format without repeated groups, by the slot they come before
    (the number of slots: after the last): a value's row after them starts where it is read."""
    if layout.groups or layout.varying is not None:
        return {}
    fields = {first: len(widths) for first, _, widths in layout.bits}
    pads: dict[int, int] = {}
    at = 0
    for count, code in re.findall(r"(\d*)([a-zA-Z?])", layout.codes):
        n = int(count) if count else 1
        if code == "x":
            pads[at] = pads.get(at, 0) + n
        elif code in "sp":  # one value, whatever its count
            at += 1
        else:
            for _ in range(n):
                at += fields.get(at, 1)
    return pads


def _value_text(value: m.Expr, element: int | None, fmt: str) -> str:
    """A format value as a row shows it, or one element of it (a constant's by its value);
    `fmt`, the struct format of its one code."""
    if element is None:
        return _shown(value, fmt)
    assert isinstance(value.type, m.Array), "only an array's value has elements"
    if isinstance(value, m.Const) and isinstance(value.value, tuple):
        return _shown(m.Const(value.value[element], value.type.element), fmt)
    return expression_text(m.Element(value, m.Const(element, m.Type.INT), value.type.element))


def _shown(value: m.Expr, fmt: str) -> str:
    """A value packed by the struct format `fmt` (one code): a constant integer as its bytes in
    hex, as they go on the wire, and its decimal value (`01 F4 (500)`); anything else as RDIS text."""
    match value:
        case m.Const(value=int() as number, type=m.Type.INT):
            pass
        case m.UnaryOp(op="-", operand=m.Const(value=int() as magnitude, type=m.Type.INT)):  # `-2` as written
            number = -magnitude
        case _:
            return expression_text(value)
    try:
        packed = struct.pack(fmt, number)
    except struct.error:  # a value the format cannot hold is the checker's to report
        return expression_text(value)
    return f"{_hex(packed)} ({number})"


def _hex(data: bytes) -> str:
    return " ".join(f"{b:02X}" for b in data)


def _constant_rest(arg: m.Expr) -> Row | None:
    """The row of constant bytes given for a `*` rest: their size is known, and their bytes."""
    if not (isinstance(arg, m.Const) and isinstance(arg.value, bytes) and arg.value):
        return None
    return len(arg.value), "bytes (the rest)", _hex(arg.value)


def _code_format(layout: m.StructLayout, code: str) -> str:
    """The struct format of one code of a layout, standard sizes when the layout gives no byte order."""
    return (layout.order or "<") + code


def _reply_rows(decoding: m.Unpack | m.Regex | None) -> list[Row]:
    match decoding:
        case m.Unpack(layout=layout, until=until):
            rows = _rows(layout, lambda j, k: f"out[{j}]" if k is None else f"out[{j}][{k}]")
            if until is not None:
                rows.append((len(until), "end (dropped)", _hex(until.encode("latin-1"))))
            return rows
        case m.Regex(pattern=pattern):
            return [(None, "text", f"regex {spell_template(pattern)}")]
        case None:
            return []
    raise AssertionError(decoding)


def _sides(name: str, layouts: tuple[tuple[m.FramePart, ...], ...] | None, payload: list[Row],
           reply: bool = True, when: tuple[m.Expr | None, ...] = ()) -> list[str]:
    """A side's table, or one per layout (`either`): the request's in the order the writer tries them,
    each after the condition that chooses it (`either when`)."""
    if layouts is None or len(layouts) == 1:
        return _side(name, layouts[0] if layouts else None, payload, reply)
    heads = [f", when {expression_text(e)}" if e is not None else ", when none holds" for e in when]
    return [line for n, parts in enumerate(layouts, 1)
            for line in _side(f"{name}, alternative {n}{heads[n - 1] if heads else ''}", parts, payload, reply)]


def _side(name: str, parts: tuple[m.FramePart, ...] | None, payload: list[Row], reply: bool) -> list[str]:
    """A layout's table; in a `reply`, its optional parts marked (a request writes them)."""
    rows, optional = _layout_rows(parts, payload, reply)
    total = sum(size for size, _, _ in rows if size is not None)
    varies = any(size is None for size, _, _ in rows)
    out = [f"  {name}: {total}{'+n' if varies else ''} byte{'' if total == 1 and not varies else 's'}"]
    if optional:
        out[0] += f", {sum(rows[i][0] or 0 for i in optional)} of them optional (a reply may lack them)"
    out.append(f"  {'offset':>6}  {'size':>4}  {'kind':<20}  value")
    offset: int | None = 0
    for i, (width, what, detail) in enumerate(rows):
        at = f"{offset:>6}" if offset is not None else f"{'?':>6}"
        what = f"{what} (optional)" if i in optional else what
        out.append(f"  {at}  {width if width is not None else 'n':>4}  {what:<20}  {detail}")
        offset = offset + width if offset is not None and width is not None else None
    return out


def _layout_rows(parts: tuple[m.FramePart, ...] | None, payload: list[Row], reply: bool) -> tuple[list[Row], range]:
    """A layout's rows, the payload's among them, and the indexes of those a `reply` may lack."""
    rows: list[Row] = []
    optional = range(0)  # the indexes of the rows a reply may lack
    if parts is None:
        rows = payload
    else:
        for i, part in enumerate(parts):
            match part:
                case m.FrameOptional(count=count) if reply:
                    optional = range(len(rows), len(rows) + count)
                case m.FrameBytes(role=role, data=data):
                    rows.append((len(data), role, " ".join(f"{ord(c):02X}" for c in data)))
                case m.FrameField(name=field, format=fmt, value=value, layout=layout):
                    rows.append((layout.size, f"field {field}", f'"{fmt}" = {_shown(value, fmt)}'))
                case m.FrameLength(format=fmt, adjust=adjust, layout=layout):
                    sign = f" {'+' if adjust >= 0 else '-'} {abs(adjust)}" if adjust else ""
                    rows.append((layout.size, "length", f'"{fmt}" = payload{sign}'))
                case m.FrameBits(format=fmt, fields=bits, layout=layout):
                    rows.append((layout.size, "bits", f'"{fmt}": ' + _bit_fields(bits)))
                case m.FramePayload(trimmed=trimmed):
                    rows += [(size, f"payload {what}", detail) for size, what, detail in payload] or [
                        (0, "payload", "(empty)")]
                    if trimmed:
                        rows.append((0, "payload trimmed", "trailing zero bytes dropped; put back when read"))
                case m.FrameChecksum(algorithm=a, format=fmt, first=first, last=last, with_request=req):
                    size = part.layout.size if part.layout is not None else (a.width + 3) // 4
                    covers = " .. ".join(dict.fromkeys([_name(parts[first]), _name(parts[last])]))
                    covers = ("the request .. " if req else "") + covers
                    extras = _crc_parameters(a) if a.kind == "crc" and a.name.strip().lower() == "crc" else ""
                    extras += " inverted" if a.inverted else ""
                    extras += f" mask {a.mask:#x}" if a.mask is not None else ""
                    seed = "" if part.seed is None else f", then {part.seed.table}[{part.seed.field}] (not sent)"
                    rows.append((size, "checksum", f"{a.name}{extras} as {fmt or 'hex'}, over {covers}{seed}"))
    return rows, optional


def _crc_parameters(a: m.ChecksumAlgorithm) -> str:
    """A CRC given by its parameters, as written: the catalogue's names say the rest themselves."""
    words = f" width {a.width} poly {a.poly:#x}"
    words += f" init {a.init:#x}" if a.init else ""
    words += f" xorout {a.xorout:#x}" if a.xorout else ""
    if a.reflect_in and a.reflect_out:
        words += " reflect"
    elif a.reflect_in or a.reflect_out:
        words += " reflect in" if a.reflect_in else " reflect out"
    return words


def _bit_fields(bits: tuple[m.BitField, ...]) -> str:
    """A `bits` integer's fields with the bits each takes, from the lowest up."""
    said, low = [], 0
    for bit in bits:
        value = expression_text(bit.value) if bit.value is not None else "payload" + (
            f" {'+' if bit.adjust >= 0 else '-'} {abs(bit.adjust)}" if bit.adjust else "")
        said.append(f"{bit.name} = {value} ({m.bit_span(low, bit.width)})")
        low += bit.width
    return ", ".join(said)


def _name(part: m.FramePart) -> str:
    match part:
        case m.FrameBytes(role=role):
            return role
        case m.FrameField(name=name):
            return name
        case m.FrameLength():
            return "length"
        case m.FrameBits(fields=bits):
            return "length" if any(bit.value is None for bit in bits) else bits[0].name if bits else "bits"
        case m.FramePayload():
            return "payload"
    return "checksum"


# ---- one request's concrete bytes (`rdisc dump FILE PRIMITIVE --args K=V ...`) -----------------------

_FORMATS = {kind: code for code, kind in _KINDS.items() if code not in "lLc"}


def dump_request(model: m.Model, name: str, given: str, data: bytes) -> str:
    """The bytes a request of primitive `name` is for the arguments `given` (as the caller spells
    them), made by the engine, held against the primitive's byte table: each row's offset, size,
    kind, value as the table says it, the value the bytes hold and the bytes. Bytes that do not
    follow the table (a stuffed or escaped frame, sizes that cannot be told apart) show whole."""
    p = model.primitives[name]
    lines = [f"primitive {name}({given}) on {p.connection}: {len(data)} byte{'' if len(data) == 1 else 's'}"]
    if p.encoding is None:
        return "\n".join([*lines, "  request: none (nothing is written)"]) + "\n"
    lines.append(f"  {_hex(data)}")
    frame = model.frames[p.frame.frame] if p.frame is not None else None
    payload = _payload_rows(p.encoding, p.args)
    rows = None
    if frame is None or (frame.stuffing is None and frame.escaping is None):
        for parts in frame.requests if frame is not None else (None,):
            rows = _sized(_layout_rows(parts, payload, False)[0], len(data))
            if rows is not None:
                break
    if rows is None:
        return "\n".join([*lines, "  (stuffed, escaped or of sizes the table cannot tell: the bytes whole)"]) + "\n"
    return "\n".join([*lines, *held_table(rows, data)]) + "\n"


def held_table(rows: list[tuple[int, str, str]], data: bytes) -> list[str]:
    """Rows of known sizes held against `data`, a line each under a heading: offset, size, kind,
    value as the table says it, the value the bytes hold, and the bytes."""
    lines = [f"  {'offset':>6}  {'size':>4}  {'kind':<20}  {'value':<28}  {'holds':<12}  bytes"]
    offset = 0
    for size, what, detail in rows:
        part = data[offset : offset + size]
        lines.append(f"  {offset:>6}  {size:>4}  {what:<20}  {detail:<28}  {_held(what, detail, part):<12}  "
                     f"{_hex(part)}".rstrip())
        offset += size
    return lines


@dataclass(frozen=True, slots=True)
class Written:
    """What a request's `format` can write, as decode holds a text against it: its literal
    pieces in order (the fields' text between them) and the fewest characters its fields write
    (their widths: `{:03X}` at least 3)."""

    pieces: tuple[str, ...]
    least: int

    @classmethod
    def of(cls, template: str) -> Written:
        pieces, least = [""], 0
        for literal, name, spec, _ in string.Formatter().parse(template):  # checked: it parses
            pieces[-1] += literal
            if name is not None:
                least += format_width(spec or "")
                pieces.append("")
        return cls(tuple(pieces), least)

    @property
    def literal(self) -> int:
        """How many characters of a text it fixes: the more, the more specific (`"V"` before `"{}"`)."""
        return sum(len(piece) for piece in self.pieces)

    def holds(self, text: str) -> bool:
        return len(text) >= self.literal + self.least and _pieces_in_order(self.pieces, text)


Layout = tuple[list[Row], str | Written | None]
"""A message's rows, and what its text must be: a reply's regular expression, or what a
request's format can write."""


def request_layouts(model: m.Model, p: m.Primitive, as_read: bool = False) -> list[Layout]:
    """The byte tables a request of `p` can have (a frame's alternatives); none when it writes
    nothing, or when its frame stuffs or escapes (its table is not its bytes) unless `as_read`
    (the table held against its bytes as the engine reads them, unescaped and unstuffed)."""
    if p.encoding is None:
        return []
    frame = model.frames[p.frame.frame] if p.frame is not None else None
    if frame is not None and not as_read and (frame.stuffing is not None or frame.escaping is not None):
        return []
    pattern = None
    if isinstance(p.encoding, m.Format):  # a text: its literal pieces, any text for each `{}`
        pattern = Written.of(p.encoding.template)
    payload = _payload_rows(p.encoding, p.args)
    return [(_layout_rows(parts, payload, False)[0], pattern)
            for parts in (frame.requests if frame is not None else (None,))]


def reply_layouts(model: m.Model, p: m.Primitive, as_read: bool = False) -> list[tuple[str, Layout]]:
    """The byte tables a reply of `p` can have, each with a name (`reply`, `reply when k = 1`,
    `reply 2 of 3`); none for what dump shows as records or sub-payloads, or a stuffed or
    escaped frame, whose tables are not their bytes (unless `as_read`, as `request_layouts`)."""
    use = p.reply_frames[0] if p.reply_frames else p.frame
    frame = model.frames[use.frame] if use is not None else None
    if frame is not None and not as_read and (frame.stuffing is not None or frame.escaping is not None):
        return []
    sides = frame.replies if frame is not None and frame.reply else (None,)

    def layouts(name: str, decoding: m.Unpack | m.Regex | None, payload: list[Row],
                through: tuple[tuple[m.FramePart, ...], ...] | tuple[None] = sides) -> list[tuple[str, Layout]]:
        pattern = decoding.pattern if isinstance(decoding, m.Regex) else None
        return [(name, (_layout_rows(parts, payload, True)[0], pattern)) for parts in through]

    if p.table is not None:
        if p.table.each:
            return []
        found = []
        for case in p.table.cases:
            rows = _reply_rows(case.decoding)
            if p.table.tag is not None:
                rows = [*_tag_rows(p.table, case), *rows]
            found += layouts(f"reply when {p.table.key} = {case.values_text()}", case.decoding, rows)
        return found
    if p.listed:
        found = []
        for n, r in enumerate(p.listed, 1):
            through = r.frame or p.frame
            own = model.frames[through.frame] if through is not None else None
            found += layouts(f"reply {n} of {len(p.listed)}", r.decoding, _reply_rows(r.decoding),
                             own.replies if own is not None and own.reply else (None,))
        return found
    if p.records is not None or not p.expects_reply(model.frames):
        return []
    found = layouts("reply", p.decoding, _reply_rows(p.decoding))
    if p.error is not None:
        _, error_sides, rows = _error_layout(model, p, p.error)
        found += layouts("error", p.error.decoding, rows, error_sides or (None,))
    return found


_TAG = re.compile(r"tag ([su])\d+( LE| native| BE)? (?:= |in )(-?\d+)(?:\.\.(-?\d+))?")
_CONSTANT = re.compile(r"([0-9A-F]{2}(?: [0-9A-F]{2})*)(?: \(-?\d+\))?")


def matched(layout: Layout, data: bytes) -> list[tuple[int, str, str]] | None:
    """The layout's rows sized to `data` when its bytes can be that message: every constant
    (header, constant values) the bytes it says, its text (the payload's, without the frame's
    header and terminator) one its pattern matches; else None."""
    rows, pattern = layout
    sized = _sized(rows, len(data))
    if sized is None:
        return None
    offset = 0
    for size, what, detail in sized:
        if what in ("text", "payload text") and pattern is not None:
            text = data[offset : offset + size].decode("latin-1")
            if isinstance(pattern, Written) and not pattern.holds(text):
                return None
            try:
                if isinstance(pattern, str) and re.match(pattern, text, re.DOTALL) is None:  # as `Match` reads it
                    return None
            except re.error:
                return None
        constant = _CONSTANT.fullmatch(detail)
        if constant is not None and data[offset : offset + size] != bytes.fromhex(constant.group(1)):
            return None
        tag = _TAG.fullmatch(f"{what.removeprefix('payload ')} {detail}")
        if tag is not None:  # a reply table's tag: its value, or one of its range
            order = {" LE": "little", " native": sys.byteorder}.get(tag.group(2) or "", "big")
            value = int.from_bytes(data[offset : offset + size], order, signed=tag.group(1) == "s")
            low, high = int(tag.group(3)), int(tag.group(4) or tag.group(3))
            if not low <= value <= high:
                return None
        offset += size
    return sized


def _sized(rows: list[Row], total: int) -> list[tuple[int, str, str]] | None:
    """The rows with every size known, a single one of varying size taking what the others leave
    of `total`; None when they cannot hold `total` bytes."""
    known = sum(size for size, _, _ in rows if size is not None)
    varying = [i for i, (size, _, _) in enumerate(rows) if size is None]
    if len(varying) > 1 or known > total or (not varying and known != total):
        return None
    return [(total - known if size is None else size, what, detail) for size, what, detail in rows]


def _held(what: str, detail: str, part: bytes) -> str:
    """The number a row's bytes hold, read as its kind says (a frame's field or length by its
    format); text as RDIS spells it; "" for bytes and checksums, shown in hex only."""
    kind = what.removeprefix("payload ")
    fmt = None
    if kind == "bits" or kind.startswith("bits "):
        return _bits_held(kind, detail, part)
    if kind in _FORMATS or kind.rsplit(" ", 1)[0] in _FORMATS:
        base, _, order = kind.partition(" ")
        fmt = {"BE": ">", "LE": "<"}.get(order, "=") + _FORMATS[base]
    elif (what == "length" or what.startswith("field ")) and detail.startswith('"'):
        fmt = detail[1 : detail.index('"', 1)]
    elif kind == "text":
        return spell_template(part.decode("latin-1"))
    elif kind == "text, padded":  # to its first NUL, as an `NZ` is read
        return spell_template(part.decode("latin-1").partition("\0")[0])
    if fmt is None:
        return ""
    try:
        return repr(struct.unpack(fmt, part)[0])
    except struct.error:  # a format that is not one number's
        return ""


_SPAN = re.compile(r"\((?:bit (\d+)|bits (\d+)\.\.(\d+))\)")
"""A bit field's bits as a row says them (`m.bit_span`): `(bit 4)`, `(bits 0..10)`."""


def _bits_held(kind: str, detail: str, part: bytes) -> str:
    """The fields an integer split into bits holds (`22s{11*16}`, `B{4,1,1,1,1}`, a frame's `bits`
    part), in the row's order, split as the engine splits them; "" when the bytes are short."""
    if kind == "bits":  # a frame's part: its format first, `"<H": ...`
        written = detail[1 : detail.index('"', 1)]
        order = written[0] if written[:1] in ("<", ">", "!") else "<" if sys.byteorder == "little" else ">"
    else:
        order = {"LE": "<", "BE": ">", "native": "<" if sys.byteorder == "little" else ">"}.get(kind.split(" ")[-1], "<")
    widths = [1 if bit else int(last) - int(first) + 1 for bit, first, last in _SPAN.findall(detail)]
    bits = Bits(f"{order}{len(part)}s", [(str(k), width, k) for k, width in enumerate(widths)])
    if not part or len(part) * 8 < sum(widths):
        return ""
    return ", ".join(str(value) for value in bits.split(part))


def _pieces_in_order(pieces: tuple[str, ...], text: str) -> bool:
    """Whether `text` is the pieces with anything between them: the first at its start, the last
    at its end, the others found in order between (linear: no regex to backtrack)."""
    first, *middle, last = pieces if len(pieces) > 1 else (pieces[0], pieces[0])
    if len(pieces) == 1:
        return text == first
    if not text.startswith(first) or not text.endswith(last) or len(text) < len(first) + len(last):
        return False
    at, end = len(first), len(text) - len(last)
    for piece in middle:
        found = text.find(piece, at, end)
        if found < 0:
            return False
        at = found + len(piece)
    return True
