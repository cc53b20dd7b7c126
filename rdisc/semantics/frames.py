"""Frames: the rules of a `frame` declaration, lowered to the Model's parts (its checksums'
rules and the catalogue of named CRCs are rdisc.semantics.checksums; what later passes read of
a checked frame, rdisc.semantics.frame_facts).

A frame's parts all have fixed sizes but the payload; these rules make sure a
reader can always find the payload's end and that every checksum covers parts
that come before it.
"""

from __future__ import annotations

from collections.abc import Callable

from rdisc.diagnostics import Diagnostics, Label, abbreviate
from rdisc.semantics import model as m
from rdisc.semantics.checksums import _PART_WORDS, ChecksumRules
from rdisc.semantics.frame_facts import length_part, length_range
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.types import Env, Typer, describe
from rdisc.syntax import ast
from rdisc.syntax.precedence import octets

MAX_BYTES = 64  # of one constant part


class FrameRules(ChecksumRules):
    """Checks `frame` declarations for a checker that owns the diagnostics and the typer."""

    def __init__(self, diagnostics: Diagnostics, typer: Typer,
                 setting: Callable[[ast.Expr, str], float | None]) -> None:
        self.d = diagnostics
        self.typer = typer
        self.setting = setting

    def frame(self, decl: ast.FrameDecl, params: tuple[m.Parameter, ...]) -> m.Frame:
        scope = {p.name: (Scope.PARAM, p.type) for p in params if p.type is not None}
        env = Env(scope, "in a frame", "its parameters",
                  setting_note=f"a frame reads only its parameters: give `{decl.name.text}` one and pass the setting "
                  f"where a primitive names the frame, `frame {decl.name.text}(SETTING)`")
        direct = tuple(i for i in decl.items if not isinstance(i, (ast.FrameSide, ast.FrameStuff, ast.FrameEscape)))
        stuffs = [i for i in decl.items if isinstance(i, ast.FrameStuff)]
        for extra in stuffs[1:]:
            self.d.report("E501", extra.span, f"frame `{decl.name.text}` has two `stuff` rules",
                          labels=(Label(stuffs[0].span, "first given here"),))
        stuffing = None
        if stuffs:
            escape, reserved = stuffs[0].escape, stuffs[0].reserved
            for lit in (escape, reserved):
                if not 1 <= len(lit.value) <= MAX_BYTES or not octets(lit.value):
                    self.d.report("E501", lit.span, f"stuffing bytes are 1 to {MAX_BYTES} bytes (characters up to \\xff)")
            stuffing = (reserved.value, escape.value)
        escapes = [i for i in decl.items if isinstance(i, ast.FrameEscape)]
        for again in escapes[1:]:
            self.d.report("E510", again.span, f"frame `{decl.name.text}` has two `escape` rules",
                          labels=(Label(escapes[0].span, "first given here"),))
        if escapes and stuffs:
            self.d.report("E510", escapes[0].span, f"frame `{decl.name.text}` both stuffs and escapes",
                          labels=(Label(stuffs[0].span, "stuffed here"),),
                          help="a frame has one kind of byte stuffing: `stuff` or `escape`")
        escaping = self.escaping(escapes[0]) if escapes else None
        sides: dict[str, ast.FrameSide] = {}
        for item in decl.items:
            if isinstance(item, ast.FrameSide):
                if item.side in sides:
                    self.d.report("E501", item.span, f"frame `{decl.name.text}` has two `{item.side}` sides",
                                  labels=(Label(sides[item.side].span, "first given here"),))
                sides.setdefault(item.side, item)
        if direct and sides:
            self.d.report("E501", next(iter(sides.values())).span,
                          f"frame `{decl.name.text}` mixes parts with `request {{ }}`/`reply {{ }}` sides",
                          help="write the parts once for both directions, or give each side its own")
        fields: dict[str, int] = {}
        if sides:
            for part in _nested(sides["request"].parts if "request" in sides else ()):
                if isinstance(part, ast.FrameOptional):
                    self.d.report("E506", part.span, "a request writes every part: `optional` belongs to a reply",
                                  help="write these parts without `optional`")
            request = self.layouts(sides["request"].parts if "request" in sides else (), "request", decl, env,
                                   fields)
            reply = self.layouts(sides["reply"].parts, "reply", decl, env, fields) if "reply" in sides else ((),)
        else:
            request = self.layouts(direct, "request", decl, env, fields)
            reply = self.layouts(direct, "reply", decl, env, fields, quiet=True)
        chosen = self.chooser(sides["request"].parts, env) if "request" in sides else ()
        answered = self.chooser(sides["reply"].parts, env) if "reply" in sides else ()
        self.chooser(direct, env, both=True)  # refused there
        frame = m.Frame(decl.name.text, params, request[0], reply[0], decl.doc, decl.span, stuffing, request[1:],
                        reply[1:], escaping, chosen, answered)
        if escaping is not None:
            self.escaped(frame, escapes[0], decl)
        return frame

    def escaping(self, item: ast.FrameEscape) -> m.Escaping | None:
        """An `escape` rule's table of (byte, code), each one byte; None when it is wrong (reported)."""
        wrong = False
        for lit in (item.escape, *(lit for entry in item.table for lit in entry)):
            if len(lit.value) != 1 or ord(lit.value) > 0xFF:
                self.d.report("E510", lit.span, f"an escape, an escaped byte and a code are one byte each, "
                              f"not \"{abbreviate(lit.value)}\"")
                wrong = True
        if item.escaped is not None:
            if not 1 <= len(item.escaped.value) <= MAX_BYTES or not octets(item.escaped.value):
                self.d.report("E510", item.escaped.span, f"the escaped bytes are 1 to {MAX_BYTES} bytes "
                              "(characters up to \\xff)")
                wrong = True
            mask = item.xor if item.xor is not None else 0
            if not 1 <= mask <= 0xFF:
                self.d.report("E510", item.span, f"an `escape`'s mask is 1 to 255 (0x01 to 0xFF), not {mask}")
                wrong, mask = True, 0  # no codes of it to check further
            table = tuple((ch, chr(ord(ch) ^ mask)) for ch in item.escaped.value)
        else:
            table = tuple((byte.value, code.value) for byte, code in item.table)
            if not table:
                self.d.report("E510", item.span, "an `escape` table lists each byte it escapes and its code",
                              help='SLIP: `escape "\\xDB" { "\\xC0": "\\xDC", "\\xDB": "\\xDD" }`')
                wrong = True
        if wrong:
            return None
        codes: dict[str, str] = {}
        for byte, code in table:
            if table.count((byte, code)) > 1 or [b for b, _ in table].count(byte) > 1:
                self.d.report("E510", item.span, f"\"{abbreviate(byte)}\" is escaped twice")
                return None
            if code in codes:
                self.d.report("E510", item.span, f"\"{abbreviate(codes[code])}\" and \"{abbreviate(byte)}\" are both "
                              f"escaped as \"{abbreviate(item.escape.value + code)}\", so a reader cannot tell them apart")
                return None
            codes[code] = byte
        escaped = {byte for byte, _ in table}
        if item.escape.value not in escaped:
            self.d.report("E510", item.escape.span, f"the escape \"{abbreviate(item.escape.value)}\" is not itself "
                          "escaped, so a reader takes the same byte in the data for an escape",
                          help="escape it too, as SLIP escapes DB as DB DD and HDLC 7D as 7D 5D")
            return None
        for code, byte in codes.items():
            if code in escaped:
                self.d.report("E510", item.span, f"\"{abbreviate(byte)}\" is escaped as \"{abbreviate(item.escape.value + code)}"
                              f"\", whose code \"{abbreviate(code)}\" is an escaped byte itself",
                              help="a code follows the escape unescaped: give each byte a code that is not escaped")
                return None
        return m.Escaping(item.escape.value, table)

    def escaped(self, frame: m.Frame, item: ast.FrameEscape, decl: ast.FrameDecl) -> None:
        """Where escaping works: one layout each way, each ending with a terminator whose first byte
        is escaped (so a reader finds the packet's end at the first one that comes)."""
        assert frame.escaping is not None
        parts = tuple(p for i in decl.items for p in (i.parts if isinstance(i, ast.FrameSide) else (i,))
                      if not isinstance(p, (ast.FrameStuff, ast.FrameEscape)))
        for part in _nested(parts):
            if isinstance(part, (ast.FrameOptional, ast.FrameEither)):
                word = "optional" if isinstance(part, ast.FrameOptional) else "either"
                self.d.report("E510", part.span, f"a frame that escapes has no `{word}`: its reply is found between its "
                              "flags and taken apart by the sizes of its parts",
                              labels=(Label(item.span, "escaped here"),))
                return
        said: set[str] = set()
        escaped = {byte for byte, _ in frame.escaping.table}
        for side, layout in (("request", frame.request), ("reply", frame.reply)):
            last = layout[-1] if layout else None
            if not layout:
                continue
            if not isinstance(last, m.FrameBytes) or last.role != "terminator":
                whose = f"the {side} of frame" if frame.request != frame.reply else "frame"
                message = f"{whose} `{frame.name}` escapes but ends with no `terminator`"
                help_ = ("a reader finds a packet's end at its terminator, whose first byte the escaping keeps out of "
                         "the bytes before it: `terminator \"\\x7E\"`")
            elif last.data[:1] == frame.escaping.escape:
                message = (f"the terminator \"{abbreviate(last.data)}\" of frame `{frame.name}` starts with the "
                           "escape, which comes before every code")
                help_ = "escape with another byte than the terminator's"
            elif last.data[:1] not in escaped:
                message = (f"the terminator \"{abbreviate(last.data)}\" of frame `{frame.name}` starts with a byte that "
                           "is not escaped, so it may come before the packet ends")
                help_ = "escape it: the escaping keeps it out of the bytes between the flags"
            else:
                continue
            if message not in said:
                said.add(message)
                self.d.report("E510", item.span, message, help=help_)

    def layouts(self, parts: tuple[ast.FramePart, ...], side: str, decl: ast.FrameDecl, env: Env,
                fields: dict[str, int], quiet: bool = False) -> tuple[tuple[m.FramePart, ...], ...]:
        """One direction's layouts: its parts, or one layout per alternative of its `either`
        (the parts around it in each). `quiet` silences what the request's check reported."""
        eithers = [p for p in parts if isinstance(p, ast.FrameEither)]
        for extra in eithers[1:]:
            self.d.report("E507", extra.span, f"frame `{decl.name.text}` has two `either`s",
                          labels=(Label(eithers[0].span, "first given here"),),
                          help="write each whole layout as one alternative")
        if not eithers:
            return (self.side(self.flat(parts), side, decl, env, fields, quiet),)
        either = eithers[0]
        for inner in _nested(either.alternatives):
            if isinstance(inner, ast.FrameEither):
                self.d.report("E507", inner.span, "an `either` inside an `either`",
                              help="write each whole layout as one alternative")
        at = parts.index(either)
        runs = [(*parts[:at], *alt, *parts[at + 1 :]) for alt in either.alternatives]
        layouts = tuple(self.side(self.flat(run), side, decl, env, fields, quiet) for run in runs)
        name = decl.name.text
        if side == "request" and not either.conditions:
            for n, layout in enumerate(layouts[:-1], 1):
                if length_part(layout) is None:
                    self.d.report("E507", either.span, f"alternative {n + 1} of frame `{name}` is never written: "
                                  f"alternative {n} has no length field, so it carries every payload",
                                  help="the writer takes the first alternative whose length field can state the "
                                  "payload: put the one without a length field last")
                    break
        if side == "request":
            return layouts
        heads = []
        for n, layout in enumerate(layouts if not either.conditions else (), 1):  # else chosen by a condition
            first = layout[0] if layout else None
            if not isinstance(first, m.FrameBytes) or first.role != "header":
                self.d.report("E507", either.span, f"alternative {n} of frame `{name}` starts with no `header`",
                              help="a reader knows which alternative came by its header: start each with its own")
                return layouts
            if not octets(first.data):  # not bytes, which E501 says (`constant_bytes`)
                return layouts
            heads.append(first.data.encode("latin-1"))
        for i, a in enumerate(heads):
            for j in range(i + 1, len(heads)):
                b = heads[j]
                if a.endswith(b) or b.endswith(a):
                    self.d.report("E507", either.span, f"alternatives {i + 1} and {j + 1} of frame `{name}` start with "
                                  f"headers a reader cannot tell apart: {a!r} and {b!r}",
                                  help="give each alternative a header that is not the end of another's")
        if len({any(isinstance(p, m.FramePayload) for p in layout) for layout in layouts}) > 1:
            self.d.report("E507", either.span, f"some alternatives of frame `{name}` have a `payload` and some not",
                          help="give every alternative of a reply a payload, or none")
        return layouts

    def chooser(self, parts: tuple[ast.FramePart, ...], env: Env, both: bool = False) -> tuple[m.Expr | None, ...]:
        """The conditions of a side's `either when`, typed over the frame's parameters: a plain
        alternative only last (taken when none holds); () when its `either` is chosen by size
        (a request) or by its header (a reply). `both`: parts written for both directions, where
        one condition cannot choose for both sides."""
        either = next((p for p in parts if isinstance(p, ast.FrameEither)), None)
        if either is None or not either.conditions:
            return ()
        if both:
            self.d.report("E513", either.span, "parts written for both directions cannot be chosen by `when`",
                          help="give the frame a `request { }` and a `reply { }`, each with its own `either when`")
            return ()
        out: list[m.Expr | None] = []
        for n, condition in enumerate(either.conditions, 1):
            if condition is None:
                if n < len(either.conditions):
                    self.d.report("E513", either.span, f"alternative {n} has no `when`, but alternatives chosen by "
                                  "size and by a condition cannot be mixed",
                                  help="give every alternative a `when`, except a plain last one, taken when none holds")
                out.append(None)
                continue
            typed = self.typer.expr(condition, env)
            if typed.type is not None and typed.type is not Type.BOOL:
                self.d.report("E513", condition.span, f"`when` takes a bool, but this is {describe(typed.type)}")
            out.append(typed)
        return tuple(out)

    def flat(self, parts: tuple[ast.FramePart, ...]) -> tuple[ast.FramePart, ...]:
        """The parts in a row, an `optional`'s own right after it (it says how many follow)."""
        out: list[ast.FramePart] = []
        for part in parts:
            if isinstance(part, ast.FrameEither):
                continue  # a second or a nested one: `layouts` reported it
            out.append(part)
            if isinstance(part, ast.FrameOptional):
                for inner in part.parts:
                    if isinstance(inner, (ast.FrameOptional, ast.FrameEither)):
                        self.d.report("E506", inner.span, "an `optional` holds constant bytes, fields and checksums, "
                                      f"not an `{'optional' if isinstance(inner, ast.FrameOptional) else 'either'}`")
                    else:
                        out.append(inner)
        return tuple(out)

    def side(self, parts: tuple[ast.FramePart, ...], side: str, decl: ast.FrameDecl, env: Env,
             fields: dict[str, int], quiet: bool = False) -> tuple[m.FramePart, ...]:
        """One layout's parts (`flat`); `quiet` when the same parts were checked as the request."""
        d = self.d if not quiet else Diagnostics()
        payloads = [p for p in parts if isinstance(p, ast.FramePayload)]
        if side == "request" and len(payloads) != 1:
            d.report("E501", payloads[1].span if payloads else decl.name.span,
                     f"the request of frame `{decl.name.text}` needs exactly one `payload`",
                     help="`payload` marks where the primitive's own bytes go")
        elif side == "reply" and len(payloads) > 1:
            d.report("E501", payloads[1].span, f"the reply of frame `{decl.name.text}` has two payloads")
        lengths = [p for p in parts if isinstance(p, ast.FrameLength)] + [
            f for p in parts if isinstance(p, ast.FrameBits) for f in p.fields if f.name is None]
        # Two `length` fields (Kobuki's packet length, then its sub-payload's): each states the
        # payload with its own adjustment, the second checked against the first when read.
        ordered = sorted(lengths, key=lambda p: p.span.start)
        plain = all(isinstance(p, ast.FrameLength) for p in ordered)
        for extra in ordered[2 if plain else 1 :]:
            d.report("E501", extra.span, f"frame `{decl.name.text}` has {'more than two' if plain else 'two'} "
                     "length fields", help="a frame states its payload twice at most" if plain else "two `length` "
                     "fields may each state the payload (a packet's length and its sub-payload's), not in a `bits`")
        for trimmed in (p for p in payloads if p.trimmed and not lengths):
            d.report("E503", trimmed.span, f"the {side} of frame `{decl.name.text}` trims its payload, so it "
                     "needs a `length` field to say how many bytes were kept",
                     help="add `length FORMAT = payload` before the payload (MAVLink 2's is `length \"B\"`)")
        optionals = [p for p in parts if isinstance(p, ast.FrameOptional)]
        for again in optionals[1:]:
            d.report("E506", again.span, f"frame `{decl.name.text}` has two `optional`s",
                     labels=(Label(optionals[0].span, "first given here"),),
                     help="one `optional`, right after the payload, may hold several parts")
        names: dict[str, int] = {}
        out: list[m.FramePart] = []
        for i, part in enumerate(parts):
            match part:
                case ast.FrameBytes():
                    out.append(self.constant_bytes(part, i, len(parts), d))
                case ast.FrameField():
                    out.append(self.field(part, env, d, fields))
                    names[part.name.text] = i
                case ast.FrameLength():
                    layout = self.integer_format(part.format, "a length field", d, "E503")
                    out.append(m.FrameLength(part.format.value, part.adjust, layout))
                case ast.FramePayload():
                    out.append(m.FramePayload(part.trimmed))
                case ast.FrameChecksum():
                    out.append(self.checksum(part, i, parts, names, side, d))
                case ast.FrameBits():
                    out.append(self.bits(part, env, d, fields))
                    for bit in part.fields:
                        names[bit.name.text if bit.name is not None else "length"] = i
                case ast.FrameOptional():
                    count = sum(1 for p in part.parts if not isinstance(p, (ast.FrameOptional, ast.FrameEither)))
                    self.optional(part, parts[i - 1] if i else None, parts[i + 1 : i + 1 + count],
                                  parts[i + 1 + count :], d)
                    out.append(m.FrameOptional(count))
                case ast.FrameEither():  # `flat` leaves none
                    raise AssertionError(part)
            if isinstance(part, (ast.FrameBytes, ast.FrameLength, ast.FramePayload)):
                names.setdefault(part.role if isinstance(part, ast.FrameBytes) else
                                 "length" if isinstance(part, ast.FrameLength) else "payload", i)
        stated = [(p, written) for p, written in zip(out, parts) if isinstance(p, m.FrameLength)]
        if len(stated) == 2 and all(p.layout.slots for p, _ in stated):  # the second states what the first does
            (first, _), (second, written) = stated
            (low, high), (second_low, second_high) = length_range(first), length_range(second)
            if not second_low <= low or not high <= second_high:
                d.report("E503", written.span, f"the second length field of frame `{decl.name.text}` states "
                         f"payloads of {second_low} to {second_high} bytes, but the first {low} to {high}",
                         help="each length field states the same payload: give the second a format and an "
                         "adjustment that hold every size the first states")
        return tuple(out)

    def optional(self, part: ast.FrameOptional, before: ast.FramePart | None, inner: tuple[ast.FramePart, ...],
                 after: tuple[ast.FramePart, ...], d: Diagnostics) -> None:
        """Where an `optional` may stand: a reader sees whether it came by one byte, the first of
        its constant bytes, right where the payload ends."""
        if not isinstance(before, ast.FramePayload):
            d.report("E506", part.span, "an `optional` comes right after the `payload`",
                     help="a reader looks for it where the payload ends")
        for p in inner:
            if isinstance(p, ast.FrameBits) and any(f.name is None for f in p.fields):
                d.report("E506", p.span, "an `optional` holds constant bytes, fields and checksums, not a `length`")
            if isinstance(p, (ast.FramePayload, ast.FrameLength)) or (isinstance(p, ast.FrameBytes)
                                                                      and p.role != "literal"):
                word = p.role if isinstance(p, ast.FrameBytes) else "payload" if isinstance(
                    p, ast.FramePayload) else "length"
                d.report("E506", p.span, f"an `optional` holds constant bytes, fields and checksums, not a `{word}`")
        first = inner[0] if inner else None
        if not isinstance(first, ast.FrameBytes) or not first.value.value:
            d.report("E506", part.span, "an `optional` starts with constant bytes: `optional { literal \"*\" ... }`",
                     help="a reader sees by them whether the optional parts came")
            return
        follow = after[0] if after else None
        if not isinstance(follow, ast.FrameBytes) or not follow.value.value:
            d.report("E506", part.span, "an `optional` is followed by constant bytes (a `literal` or the `terminator`)",
                     help="a reader sees by its first byte whether the optional parts came or these")
        elif follow.value.value[0] == first.value.value[0]:
            d.report("E506", follow.span, f"the bytes after an `optional` start as it does "
                     f"(\"{abbreviate(first.value.value[0])}\"), so a reader cannot tell whether it came")

    def constant_bytes(self, part: ast.FrameBytes, i: int, count: int, d: Diagnostics) -> m.FrameBytes:
        text = part.value.value
        if not 1 <= len(text) <= MAX_BYTES or not octets(text):
            d.report("E501", part.value.span, f"constant bytes are 1 to {MAX_BYTES} bytes (characters up to \\xff)")
        if part.role == "header" and i != 0:
            d.report("E501", part.span, "a `header` comes first in its frame",
                     help="use `literal` for constant bytes between other parts")
        if part.role == "terminator" and i != count - 1:
            d.report("E501", part.span, "a `terminator` comes last in its frame",
                     help="use `literal` for constant bytes between other parts")
        return m.FrameBytes(part.role, text)

    def field(self, part: ast.FrameField, env: Env, d: Diagnostics, fields: dict[str, int]) -> m.FrameField:
        if part.name.text in _PART_WORDS:
            d.report("E104", part.name.span, f"`{part.name.text}` names a part of every frame and cannot name a field")
        layout = self.integer_format(part.format, f"field `{part.name.text}`", d, "E501")
        slot = layout.slots[0] if layout.slots else None
        value = self.typer.expr(part.value, env)
        if value.type is not None and value.type is not Type.INT:
            d.report("E401", part.value.span, f"field `{part.name.text}` takes an int")
        constant = self.typer.constant(value)
        if (slot is not None and isinstance(constant, int) and slot.low is not None
                and not slot.low <= constant <= slot.high):  # type: ignore[operator]
            d.report("E403", part.value.span, f"{constant} does not fit `{part.format.value}`")
        fields.setdefault(part.name.text, len(fields))
        return m.FrameField(part.name.text, part.format.value, value, layout)

    def bits(self, part: ast.FrameBits, env: Env, d: Diagnostics, fields: dict[str, int]) -> m.FrameBits:
        """An integer split into fields from its lowest bit up: unsigned, every bit of it said once."""
        fmt = part.format.value
        layout = self.integer_format(part.format, "a `bits` integer", d, "E508")
        size = 0
        if layout.slots and layout.slots[0].low != 0:
            d.report("E508", part.format.span, f"a `bits` integer is unsigned: \"{abbreviate(fmt)}\" is signed",
                     help=f"use \"{fmt[:-1]}{fmt[-1].upper()}\"")
        elif layout.slots:
            size = 8 * layout.size
        out: list[m.BitField] = []
        for bit in part.fields:
            name = bit.name.text if bit.name is not None else "length"
            if not 1 <= bit.width <= 64:
                d.report("E508", bit.span, f"bit field `{name}` is 1 to 64 bits wide, not {bit.width}")
                continue
            if bit.name is None or bit.value is None:
                out.append(m.BitField(name, bit.width, None, bit.adjust))
                continue
            if name in _PART_WORDS:
                d.report("E104", bit.name.span, f"`{name}` names a part of every frame and cannot name a field")
            value = self.typer.expr(bit.value, env)
            if value.type is not None and value.type is not Type.INT:
                d.report("E401", bit.value.span, f"field `{name}` takes an int")
            constant = self.typer.constant(value)
            if isinstance(constant, int) and not isinstance(constant, bool) and not (
                    0 <= constant < 1 << bit.width):
                d.report("E403", bit.value.span, f"{constant} does not fit the {bit.width} bits of field `{name}` "
                         f"(0 to {(1 << bit.width) - 1})")
            fields.setdefault(name, len(fields))
            out.append(m.BitField(name, bit.width, value))
        taken = sum(bit.width for bit in part.fields)
        if size and taken != size and len(out) == len(part.fields):
            missing = size - taken
            d.report("E508", part.span, f"the fields of `bits \"{abbreviate(fmt)}\"` take {taken} of its {size} bits",
                     help=f"say the other {missing} bit{'s' if missing != 1 else ''}: `field reserved: {missing} = 0`"
                     if missing > 0 else "narrow the fields, or take a wider integer")
        return m.FrameBits(fmt, tuple(out), layout)


def _nested(parts: tuple[ast.FramePart, ...] | tuple[tuple[ast.FramePart, ...], ...]) -> list[ast.FramePart]:
    """Every part, those inside `optional` and `either` included (runs of parts taken apart)."""
    out: list[ast.FramePart] = []
    for part in parts:
        if isinstance(part, tuple):
            out += _nested(part)
            continue
        out.append(part)
        if isinstance(part, ast.FrameOptional):
            out += _nested(part.parts)
        elif isinstance(part, ast.FrameEither):
            out += _nested(part.alternatives)
    return out
