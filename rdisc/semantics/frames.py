"""Frames: the rules of a `frame` declaration, lowered to the Model's parts, and
the catalogue of named CRCs.

A frame's parts all have fixed sizes but the payload; these rules make sure a
reader can always find the payload's end and that every checksum covers parts
that come before it.
"""

from __future__ import annotations

from collections.abc import Callable

from rdisc.diagnostics import Diagnostics, Label, abbreviate
from rdisc.semantics import formats
from rdisc.semantics import model as m
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.resolve import suggest
from rdisc.semantics.types import Env, Typer, describe
from rdisc.syntax import ast

MAX_BYTES = 64  # of one constant part

# Catalogue CRCs (parameters as in the CRC RevEng catalogue): width, poly, init,
# reflect in and out, xorout.
CATALOGUE: dict[str, tuple[int, int, int, bool, int]] = {
    "crc8": (8, 0x07, 0x00, False, 0x00),
    "crc8-maxim": (8, 0x31, 0x00, True, 0x00),
    "crc8-dvb-s2": (8, 0xD5, 0x00, False, 0x00),
    "crc16-xmodem": (16, 0x1021, 0x0000, False, 0x0000),
    "crc16-ccitt-false": (16, 0x1021, 0xFFFF, False, 0x0000),
    "crc16-kermit": (16, 0x1021, 0x0000, True, 0x0000),
    "crc16-modbus": (16, 0x8005, 0xFFFF, True, 0x0000),
    "crc16-arc": (16, 0x8005, 0x0000, True, 0x0000),
    "crc16-x25": (16, 0x1021, 0xFFFF, True, 0xFFFF),
    "crc32": (32, 0x04C11DB7, 0xFFFFFFFF, True, 0xFFFFFFFF),
    "crc32c": (32, 0x1EDC6F41, 0xFFFFFFFF, True, 0xFFFFFFFF),
    "crc8-rohc": (8, 0x07, 0xFF, True, 0x00),
    "crc8-cdma2000": (8, 0x9B, 0xFF, False, 0x00),
    "crc8-wcdma": (8, 0x9B, 0x00, True, 0x00),
    "crc16-buypass": (16, 0x8005, 0x0000, False, 0x0000),
    "crc16-dnp": (16, 0x3D65, 0x0000, True, 0xFFFF),
    "crc16-maxim": (16, 0x8005, 0x0000, True, 0xFFFF),
    "crc16-usb": (16, 0x8005, 0xFFFF, True, 0xFFFF),
    "crc16-genibus": (16, 0x1021, 0xFFFF, False, 0xFFFF),
    "crc32-bzip2": (32, 0x04C11DB7, 0xFFFFFFFF, False, 0xFFFFFFFF),
    "crc32-mpeg-2": (32, 0x04C11DB7, 0xFFFFFFFF, False, 0x00000000),
    "crc32-posix": (32, 0x04C11DB7, 0x00000000, False, 0xFFFFFFFF),
    "crc32-jamcrc": (32, 0x04C11DB7, 0xFFFFFFFF, True, 0x00000000),
    "crc16-mcrf4xx": (16, 0x1021, 0xFFFF, True, 0x0000),  # MAVLink's "X.25" CRC
    "crc3-gsm": (3, 0x3, 0x0, False, 0x7),
    "crc4-g-704": (4, 0x3, 0x0, True, 0x0),
    "crc5-usb": (5, 0x05, 0x1F, True, 0x1F),
    "crc7-mmc": (7, 0x09, 0x00, False, 0x00),
    "crc7-rohc": (7, 0x4F, 0x7F, True, 0x00),
    "crc7-umts": (7, 0x45, 0x00, False, 0x00),
    "crc10-atm": (10, 0x233, 0x000, False, 0x000),
    "crc12-dect": (12, 0x80F, 0x000, False, 0x000),
    "crc15-can": (15, 0x4599, 0x0000, False, 0x0000),
    "crc24-lte-a": (24, 0x864CFB, 0x000000, False, 0x000000),
    "crc24-openpgp": (24, 0x864CFB, 0xB704CE, False, 0x000000),
    "crc24-ble": (24, 0x00065B, 0x555555, True, 0x000000),
    "crc64-ecma-182": (64, 0x42F0E1EBA9EA3693, 0x0, False, 0x0),
    "crc64-xz": (64, 0x42F0E1EBA9EA3693, 0xFFFFFFFFFFFFFFFF, True, 0xFFFFFFFFFFFFFFFF),
}
_ALIASES = {
    "crc8-smbus": "crc8", "crc8-maxim-dow": "crc8-maxim", "crc16-ibm-3740": "crc16-ccitt-false",
    "crc16-autosar": "crc16-ccitt-false", "crc16-ccitt": "crc16-kermit", "crc16-ibm-sdlc": "crc16-x25",
    "crc16": "crc16-arc", "crc32-iso-hdlc": "crc32", "crc32-iscsi": "crc32c",
    "crc16-umts": "crc16-buypass", "crc16-verifone": "crc16-buypass", "crc16-maxim-dow": "crc16-maxim",
    "crc32-cksum": "crc32-posix", "crc4-itu": "crc4-g-704", "crc24q": "crc24-lte-a", "crc24": "crc24-openpgp",
    "crc64": "crc64-ecma-182", "crc64-go-ecma": "crc64-xz", "crc10": "crc10-atm", "crc12-x25": "crc12-dect",
    "twos-complement": "lrc",
}
# Checksums that are no CRC: their kind and fixed width (None: as wide as their format, 1 to 32 bits).
SUMS: dict[str, int | None] = {"sum": None, "xor": None, "lrc": None, "fletcher8": 16}
ALGORITHMS = (*SUMS, "crc", *CATALOGUE)
_PART_WORDS = frozenset(["header", "literal", "terminator", "length", "payload", "request"])


def algorithm_key(name: str) -> str:
    """`CRC-16/XMODEM`, `crc16_xmodem` and `crc16-xmodem` are one name."""
    key = name.strip().lower().replace("/", "-").replace("_", "-")
    if key.startswith("crc-"):
        key = "crc" + key[4:]
    return _ALIASES.get(key, key)


class FrameRules:
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
                if not 1 <= len(lit.value) <= MAX_BYTES or any(ord(ch) > 0xFF for ch in lit.value):
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
            if not 1 <= len(item.escaped.value) <= MAX_BYTES or any(ord(ch) > 0xFF for ch in item.escaped.value):
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
        if not 1 <= len(text) <= MAX_BYTES or any(ord(ch) > 0xFF for ch in text):
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

    def integer_format(self, lit: ast.StrLit, what: str, d: Diagnostics, code: str) -> m.StructLayout:
        """The layout of a part's struct format, one integer; anything else is reported, and
        gives `REFUSED` (no slots)."""
        try:
            layout = formats.struct_layout(lit.value)
        except formats.TemplateError as err:
            d.report("E301", lit.span, err.message)
            return m.REFUSED
        if len(layout.slots) != 1 or layout.slots[0].type is not Type.INT:
            bytes_only = len(layout.slots) == 1 and layout.slots[0].code.endswith("s") and layout.slots[0].bits is None
            d.report(code, lit.span, f"{what} is one integer: a struct format such as \"B\", \">H\" or \"<I\", "
                     f"not \"{abbreviate(lit.value)}\"",
                     help=f"for the one integer {layout.size} bytes hold, write \"{lit.value}{{{8 * layout.size}}}\""
                     if bytes_only and 0 < layout.size <= 8 else None)
            return m.REFUSED
        return layout

    def checksum(self, part: ast.FrameChecksum, i: int, parts: tuple[ast.FramePart, ...], names: dict[str, int],
                 side: str, d: Diagnostics) -> m.FrameChecksum:
        name = part.algorithm.value
        key = algorithm_key(name)
        options: dict[str, ast.ChecksumOption] = {}
        for option in part.options:
            if option.word in options:
                d.report("E502", option.span, f"`{option.word}` is given twice",
                         labels=(Label(options[option.word].span, "first given here"),))
            options.setdefault(option.word, option)
        values: dict[str, int] = {}
        for word in ("mask", "poly", "init", "xorout", "width"):
            given = options.get(word)
            if given is None or given.value is None:
                continue
            value = self.setting(given.value, f"`{word}`")
            if value is not None and (value != int(value) or value < 0):
                d.report("E502", given.value.span, f"`{word}` is a non-negative integer")
            elif value is not None:
                values[word] = int(value)
        size_bits = None
        layout: m.StructLayout | None = None
        if part.format is not None:
            layout = self.integer_format(part.format, "a checksum", d, "E502")
            if layout.slots:
                size_bits = layout.size * 8
        crc_only = [w for w in ("poly", "init", "xorout", "reflect", "reflect in", "reflect out") if w in options]
        if key in CATALOGUE:
            width, poly, init, reflect, xorout = CATALOGUE[key]
            for word in crc_only + (["width"] if "width" in options else []):
                d.report("E502", options[word].span, f"`{name}` fixes its own `{word}`",
                         help='use "crc" with `poly`, `init`, `xorout` and `reflect` for another CRC')
            algorithm = m.ChecksumAlgorithm("crc", width, poly, init, reflect, reflect, xorout,
                                            "inverted" in options, values.get("mask"), name)
        elif key == "crc":
            width = values.get("width", size_bits or 8)
            if "poly" not in values:
                d.report("E502", part.algorithm.span, 'a "crc" needs its `poly`',
                         help='or name a catalogue CRC, such as "crc16-xmodem"')
            if not 1 <= width <= 64:
                d.report("E502", (options["width"].value or part).span if "width" in options else part.span,
                         f"a CRC is 1 to 64 bits wide, not {width}")
            else:
                for word in ("poly", "init", "xorout"):
                    if values.get(word, 0) >> width:
                        d.report("E502", (options[word].value or options[word]).span,
                                 f"`{word}` {values[word]:#x} does not fit a {width}-bit CRC",
                                 help=("write the polynomial without its top bit, as the catalogue does: "
                                       f"{values[word] & ((1 << width) - 1):#x}") if word == "poly" else None)
            sides = [w for w in ("reflect", "reflect in", "reflect out") if w in options]
            for word in sides[1:]:
                d.report("E502", options[word].span, f"`{word}` beside `{sides[0]}`: write `reflect` for both ways, "
                         "`reflect in` or `reflect out` for one")
            reflect_in = bool(sides) and sides[0] in ("reflect", "reflect in")
            reflect_out = bool(sides) and sides[0] in ("reflect", "reflect out")
            algorithm = m.ChecksumAlgorithm("crc", width, values.get("poly", 0), values.get("init", 0), reflect_in,
                                            reflect_out, values.get("xorout", 0), "inverted" in options,
                                            values.get("mask"), name)
        elif key in SUMS:
            fixed = SUMS[key]
            for word in crc_only + (["width"] if fixed is not None and "width" in options else []):
                d.report("E502", options[word].span, f"`{word}` belongs to a CRC, not to a {key}"
                         if word != "width" else f"a {key} is {fixed} bits wide: it takes no `width`")
            width = fixed or values.get("width", size_bits or 8)
            if not 1 <= width <= 32:
                d.report("E502", part.span, f"a {key} is 1 to 32 bits wide, not {width}")
            algorithm = m.ChecksumAlgorithm(key, width, inverted="inverted" in options, mask=values.get("mask"),
                                            name=name)
        else:
            d.report("E502", part.algorithm.span, f"unknown checksum algorithm \"{abbreviate(name)}\"",
                     help=_algorithm_hint(key))
            algorithm = m.ChecksumAlgorithm("sum", 8, name=name)
        if size_bits is not None and part.format is not None and algorithm.width > size_bits:
            d.report("E502", part.format.span,
                     f"a {algorithm.width}-bit checksum does not fit \"{part.format.value}\" ({size_bits} bits)")
        first, last, with_request = self.span_of(part, options.get("over"), i, parts, names, side, d)
        fmt = part.format.value if part.format else None
        seed = self.seed(options["seed"], parts, d) if "seed" in options else None
        return m.FrameChecksum(algorithm, fmt, first, last, with_request, layout, seed)

    def seed(self, option: ast.ChecksumOption, parts: tuple[ast.FramePart, ...], d: Diagnostics) -> m.FrameSeed | None:
        """`seed TABLE[FIELD]`: a lookup table of bytes, keyed by a `field` of the checksum's side (E512)."""
        table, key = option.over
        found = self.typer.tables.get(table.text)
        if found is None:
            d.report("E512", table.span, f"`{table.text}` is no lookup table",
                     help=suggest(table.text, self.typer.tables) or "declare it: `const EXTRAS = { 0: 50, 23: 168 }`")
            return None
        at = next((i for i, p in enumerate(parts) if isinstance(p, ast.FrameField) and p.name.text == key.text), None)
        if at is None:
            fields = {p.name.text: 0 for p in parts if isinstance(p, ast.FrameField)}
            d.report("E512", key.span, f"`{key.text}` is no `field` of this side of the frame: a seed is keyed "
                     "by a field the frame carries", help=suggest(key.text, fields))
            return None
        key_type, _, entries = found
        if key_type is not Type.INT:
            d.report("E512", table.span, f"`{table.text}` is keyed by {key_type.value}s, not by a field's integers")
            return None
        if any(isinstance(value, bool) or not isinstance(value, int) for value in entries.values()):
            d.report("E512", table.span, f"`{table.text}` holds values that are not integers: a seed is one byte, "
                     "0 to 255")
            return None
        for entry_key, value in entries.items():
            if not 0 <= value <= 255:  # type: ignore[operator]
                d.report("E512", table.span, f"`{table.text}[{entry_key!r}]` is {value!r}: a seed is one byte, 0 to 255")
                return None
        return m.FrameSeed(table.text, key.text, at, tuple((int(k), int(v)) for k, v in entries.items()))  # type: ignore[arg-type]

    def span_of(self, part: ast.FrameChecksum, over: ast.ChecksumOption | None, i: int,
                parts: tuple[ast.FramePart, ...], names: dict[str, int], side: str,
                d: Diagnostics) -> tuple[int, int, bool]:
        """The parts a checksum covers: (first, last, with the request)."""
        if over is None:
            first = 1 if parts and isinstance(parts[0], ast.FrameBytes) and parts[0].role == "header" else 0
            if first > i - 1:
                d.report("E502", part.span, "this checksum has nothing before it to cover")
            return first, i - 1, False
        idents = over.over
        with_request = idents[0].text == "request"
        if with_request and side != "reply":
            d.report("E502", idents[0].span, "only a reply's checksum can cover the `request`")
        if with_request and len(idents) == 1:
            d.report("E502", idents[0].span, "name the last reply part it covers: `over request .. payload`")
            return 0, max(i - 1, 0), True
        found: list[int] = []
        for ident in (idents[1:] if with_request else idents):
            at = names.get(ident.text)
            if at is None:
                later = ident.text in _PART_WORDS or any(isinstance(p, ast.FrameField) and p.name.text == ident.text
                                                        for p in parts)
                d.report("E502", ident.span,
                         f"a checksum covers parts before it; `{ident.text}` is "
                         + ("not before it" if later else "no part of this frame"),
                         help=None if later else suggest(ident.text, names))
                return 0, max(i - 1, 0), with_request
            found.append(at)
        first = 0 if with_request else found[0]
        last = found[-1]
        if first > last:
            d.report("E502", over.span, "the parts of `over` are in the wrong order")
        return first, last, with_request


def unseeded(frames: dict[str, m.Frame], primitives: dict[str, m.Primitive],
             decls: dict[str, ast.PrimitiveDecl], d: Diagnostics) -> None:
    """W501: a message a primitive frames (its frame arguments constants, so its `seed` field's
    value known) that the checksum's seed table has no entry for: its request cannot be framed,
    or its reply cannot be checked."""
    if not any(isinstance(part, m.FrameChecksum) and part.seed is not None for frame in frames.values()
               for parts in (*frame.requests, *frame.replies) for part in parts):
        return
    from rdisc.semantics.evaluate import prepare  # the runtime's own interpreter: the value is the one framed

    for name, p in primitives.items():
        decl = decls.get(name)
        if decl is None:
            continue
        at = next((c.span for c in decl.clauses if isinstance(c, ast.Framed)), decl.name.span)
        uses: list[tuple[m.FrameUse, tuple[str, ...]]] = [(p.frame, ("request", "reply"))] if p.frame else []
        uses += [(use, ("reply",)) for use in (*p.reply_frames, *(r.frame for r in p.listed if r.frame),
                                              *((p.error.frame,) if p.error is not None and p.error.frame else ()))]
        told: set[tuple[str, int]] = set()
        for use, sides in uses:
            frame = frames.get(use.frame)
            if frame is None:
                continue
            args = [a.value if isinstance(a, m.Const) else None for a in use.args]
            slots = {param.name: i for i, param in enumerate(frame.params)}
            for side in sides:
                for parts in frame.requests if side == "request" else frame.replies if frame.reply else ():
                    for part in parts:
                        seed = part.seed if isinstance(part, m.FrameChecksum) else None
                        field = parts[seed.part] if seed is not None else None
                        if seed is None or not isinstance(field, m.FrameField):
                            continue
                        try:
                            value = prepare(field.value, slots)({}, args, ())
                        except Exception:  # noqa: BLE001, S112 - a value known only at run time: not checked here
                            continue
                        if type(value) is not int or value in dict(seed.entries) or (seed.table, value) in told:
                            continue
                        told.add((seed.table, value))
                        what = ("its request cannot be framed (an RdisValueError)" if side == "request"
                                else "no reply of it can be checked")
                        d.report("W501", at, f"`{name}` frames {field.name} {value} with `{frame.name}`, but its "
                                 f"seed table `{seed.table}` has no entry for {value}: {what}",
                                 help=f"add the message's byte to the table: `{value}: ...` in `{seed.table}`")


def payload_end_known(frame: m.Frame, size_known: bool) -> bool:
    """Whether a reader can find where the reply's payload ends, in each layout."""
    if frame.escaping is not None:  # read up to its terminator (E510 otherwise)
        return True
    size_known = size_known and frame.stuffing is None  # stuffing makes a payload longer on the wire
    return all(_end_known(reply, size_known) for reply in frame.replies)


def _end_known(reply: tuple[m.FramePart, ...], size_known: bool) -> bool:
    at = next((i for i, p in enumerate(reply) if isinstance(p, m.FramePayload)), None)
    if at is None or size_known or length_part(reply) is not None:
        return True
    after = at + 1
    optional = reply[after] if after < len(reply) else None
    if isinstance(optional, m.FrameOptional):  # the constant after it ends both
        after += 1 + optional.count
    return after < len(reply) and isinstance(reply[after], m.FrameBytes)


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


def _algorithm_hint(name: str) -> str:
    """A hint for an unknown algorithm: a known name only when this one is a slip of it (one
    character changed, added, dropped or swapped). A CRC merely near in spelling is another
    CRC: following such a hint would corrupt every packet, so none is offered then."""
    known = [*ALGORITHMS, *_ALIASES]
    slips = [k for k in known if _one_slip(name, k)]
    if len(slips) == 1:
        return f"did you mean `{slips[0]}`?"
    return ('algorithms: "sum", "xor", "crc" (with its parameters: width, poly, init, ...), "lrc", "fletcher8" '
            'and the catalogue CRCs: '
            + ", ".join(CATALOGUE))


def _one_slip(a: str, b: str) -> bool:
    """Whether `a` is `b` with one character changed, added or dropped, or two neighbours swapped."""
    if a == b or abs(len(a) - len(b)) > 1:
        return False
    if len(a) == len(b):
        diff = [i for i, (x, y) in enumerate(zip(a, b)) if x != y]
        return len(diff) == 1 or (len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]]
                                  and a[diff[1]] == b[diff[0]])
    short, long_ = (a, b) if len(a) < len(b) else (b, a)
    return any(long_[:i] + long_[i + 1:] == short for i in range(len(long_)))


def length_part(parts: tuple[m.FramePart, ...]) -> m.FrameLength | m.FrameBits | None:
    """The part of a layout holding its length: a `length`, or a `bits` with a length field in it."""
    return next((p for p in parts if isinstance(p, m.FrameLength)
                 or (isinstance(p, m.FrameBits) and p.length is not None)), None)


def length_words(part: m.FrameLength | m.FrameBits) -> str:
    """How a message names a length field: `"B"`, or `"<I" bits 0..29` in a `bits`."""
    if isinstance(part, m.FrameLength):
        return f'"{part.format}"'
    low = 0
    for bit in part.fields:
        if bit.value is None:
            return f'"{part.format}" bits {low}..{low + bit.width - 1}'
        low += bit.width
    raise AssertionError(part)


def length_range(part: m.FrameLength | m.FrameBits) -> tuple[int, int]:
    """The payload sizes a length field can state (none, when its format was refused)."""
    if isinstance(part, m.FrameBits):
        length = part.length
        assert length is not None
        return max(0, -length.adjust), (1 << length.width) - 1 - length.adjust
    if not part.layout.slots:  # refused: reported where the frame is checked
        return 0, -1
    slot = part.layout.slots[0]
    return max(0, (slot.low or 0) - part.adjust), (slot.high or 0) - part.adjust

