"""Frames' checksums: the catalogue of named CRCs and the sums, and the rules of a frame's
`checksum` part (its algorithm and parameters, its `seed` table, the parts it covers), which
`FrameRules` (rdisc.semantics.frames) takes from `ChecksumRules`.
"""

from __future__ import annotations

from collections.abc import Callable

from rdisc.diagnostics import Diagnostics, Label, abbreviate
from rdisc.semantics import formats
from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.semantics.resolve import suggest
from rdisc.semantics.types import Typer
from rdisc.syntax import ast

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
MAX_MASK_BITS = 64  # a `mask`'s, the widest checksum's (a CRC-64's)
_PART_WORDS = frozenset(["header", "literal", "terminator", "length", "payload", "request"])


def algorithm_key(name: str) -> str:
    """`CRC-16/XMODEM`, `crc16_xmodem` and `crc16-xmodem` are one name."""
    key = name.strip().lower().replace("/", "-").replace("_", "-")
    if key.startswith("crc-"):
        key = "crc" + key[4:]
    return _ALIASES.get(key, key)



class ChecksumRules:
    """The checks of a frame's checksum part and its one-integer formats, for FrameRules."""

    typer: Typer
    setting: Callable[[ast.Expr, str], float | None]

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
        mask = options.get("mask")
        if mask is not None and values.get("mask", 0) >> MAX_MASK_BITS:  # (one wider than the checksum keeps it whole)
            d.report("E502", (mask.value or mask).span,
                     f"`mask` {abbreviate(hex(values['mask']))} is wider than any checksum's {MAX_MASK_BITS} bits",
                     help=f"a mask keeps some of the checksum's bits: at most {(1 << MAX_MASK_BITS) - 1:#x}")
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



def _algorithm_hint(name: str) -> str:
    """A hint for an unknown algorithm: a known name only when this one is a slip of it (one
    character changed, added, dropped or swapped). A CRC merely near in spelling is another
    CRC: following such a hint would corrupt every packet, so none is offered then."""
    from rdisc.engine.errors import one_edit  # the rule of every hint; imported only for an unknown name

    known = [*ALGORITHMS, *_ALIASES]
    slips = [k for k in known if k != name and one_edit(name, k)]
    if len(slips) == 1:
        return f"did you mean `{slips[0]}`?"
    return ('algorithms: "sum", "xor", "crc" (with its parameters: width, poly, init, ...), "lrc", "fletcher8" '
            'and the catalogue CRCs: '
            + ", ".join(CATALOGUE))
