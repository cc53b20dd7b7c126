"""Static analysis of the message templates a primitive uses: struct formats
(`pack`/`unpack`), PEP 3101 formats (`format`) and regular expressions (`regex`).

Each analysis returns a value or raises `TemplateError` with a message and an
offset into the template, so the checker can point at the offending character. A struct
format is parsed here alone, once, into the `StructLayout` the Model stores beside it:
lowering, emitters and the engine read that layout, never the format's text.
"""

from __future__ import annotations

import re
import struct
import warnings
from functools import lru_cache

from rdisc import TYPE_CHECKING, patterns
from rdisc.frozen import replace
from rdisc.limits import MAX_ARRAY
from rdisc.semantics.model import AnyType, Array, Slot, StructLayout, Type, Varying, bit_span

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.formats_methods import dataclass

from rdisc.frozen import Frozen

__all__ = ["MAX_MESSAGE", "MAX_REPEAT", "MOST_WIDTH", "FormatField", "Slot", "StructLayout", "TemplateError", "Varying",
           "bit_span", "format_fields", "format_width", "most_rounds", "regex_groups", "regex_min_length", "spec_accepts",
           "split_rest", "struct_codes", "struct_layout", "text_room", "varying_args", "widest"]

MAX_REPEAT = 4096
MAX_MESSAGE = 65536  # bytes of one request or reply


class TemplateError(ValueError):
    def __init__(self, message: str, offset: int = 0, length: int = 1) -> None:
        super().__init__(message)
        self.message = message
        self.offset = offset
        self.length = length


def split_rest(fmt: str) -> tuple[str, bool]:
    """A struct format and whether it ended in `*` (the rest of the message, as bytes)."""
    stripped = fmt.rstrip()
    return (stripped[:-1], True) if stripped.endswith("*") else (fmt, False)


_INT_CODES = "bBhHiIlLqQnN"
_STANDARD_SIZES = {"b": 1, "B": 1, "h": 2, "H": 2, "i": 4, "I": 4, "l": 4, "L": 4, "q": 8, "Q": 8}
_STRUCT_ITEM = re.compile(r"\s*(\d*)\s*([a-zA-Z?])")
_GROUP = re.compile(r"\s*(\d+|#|\*)\s*\(([^()]*)\)")  # `6(BH)`: a repeated group; `#(BH)`, `*(BH)`: as the message says
_COUNT = re.compile(r"\s*#\s*([a-zA-Z?]?)")  # `#B`: the count field of the `#(...)` group
_SPLIT = re.compile(r"\s*\{([^{}]*)\}")  # `B{1,1,6}`: the integer before it split into bit fields
_WIDTH = re.compile(r"\s*%\s*([a-zA-Z?]?)")  # `%H`: the width field of the `%` codes of its groups
MOST_WIDTH = 8  # bytes of the widest `%` code: an int holds 64 bits


def widest(fmt: str) -> str:
    """A struct format with each `%` code (an unsigned integer of the width its width field
    states) at its widest, `Q`: the most bytes the message takes."""
    return fmt.replace("%", "Q")


@lru_cache(maxsize=4096)  # a layout is immutable, and a generated description repeats its formats
def struct_layout(fmt: str) -> StructLayout:
    """The values a struct format packs or unpacks, one slot per value. A final `*`
    stands for the rest of the message: one value of bytes, of any length. One group may be
    repeated as the message says: `#(BH)`, counted by a field `#B` before it, or `*(BH)`,
    until the message ends (see `Varying`). An unsigned integer code may be split into bit
    fields, one value each, from its lowest bit up: `B{1,1,6}` (see `_bit_widths`)."""
    fmt, rest = split_rest(fmt)
    for at, ch in enumerate(fmt):  # struct reads only ASCII (its digits, not `١`), and no line breaks
        if not ch.isascii() or ch in "\n\r\x0b\x0c":
            raise TemplateError(f"{ch!r} is not a struct format code (they are ASCII letters and digits)", at)
    star = re.search(r"\*(?!\s*\()(?![^{}]*\})", fmt)  # not a group's `*(...)`, nor a width's `{11*16}`
    if star is not None:
        raise TemplateError("`*` (the rest of the message) comes last", star.start())
    order = fmt[:1] if fmt[:1] in "@=<>!" else ""
    body = fmt[len(order) :]
    slots: list[Slot] = []
    groups: list[tuple[int, int, int]] = []
    written: list[str] = []  # the body with each group written out
    wire = 0  # the values the struct module packs so far
    count: tuple[int, str, int, int] | None = None  # the count field `#B`: its value's index, code, offset, slot
    splits: list[tuple[int, str, tuple[int, ...]]] = []  # `StructLayout.bits`
    varying: tuple[int, str, int] | None = None  # the varying group: its place in `written`, its codes, its offset
    sizer: tuple[int, int] | None = None  # the width field `%H`: its slot, its offset
    pos = 0
    while pos < len(body):
        if body[pos].isspace():
            pos += 1
            continue
        offset = len(order) + pos
        group = _GROUP.match(body, pos)
        if group is not None:
            codes = _group(group, len(order), slots, groups)
            if "%" in codes and sizer is None:
                raise TemplateError("a `%` code is an unsigned integer of as many bytes as a width field before it "
                                    "states: `<%H 6(B%)`", offset + group.group().index("%"))
            kind = group.group(1)
            if kind in "#*":
                if varying is not None:
                    raise TemplateError("one group of a message is repeated as the message says, not two", offset,
                                        len(group.group().strip()))
                if kind == "#" and count is None:
                    raise TemplateError("a `#(...)` group is counted by a field before it: `<#B #(BH)`", offset)
                if kind == "*" and count is not None:
                    raise TemplateError("a `*(...)` group is repeated until the message ends: it has no count "
                                        "field `#B`", count[2], 2)
                if kind == "*" and body[group.end() :].strip():
                    raise TemplateError("a `*(...)` group is repeated until the message ends, so it comes last",
                                        offset, len(group.group().strip()))
                if rest:
                    raise TemplateError("`*` (the rest of the message) cannot follow a group repeated as the message "
                                        "says: where would the group end?", len(fmt))
                if order in ("", "@"):
                    raise TemplateError("a group repeated as the message says needs a byte order (`<` or `>`): "
                                        "in host order, padding would move with the count", offset)
                varying = (len(written), codes, offset)
            else:
                written.append(codes * groups[-1][2])
                wire += len(codes) * groups[-1][2]
            pos = group.end()
            continue
        width_field = _WIDTH.match(body, pos)
        if width_field is not None:
            code = width_field.group(1)
            if not code:
                raise TemplateError("a `%` code is in a repeated group, as wide as a width field before it says: "
                                    "`<%H 6(B%)`", offset)
            if code not in "BHILQ":
                raise TemplateError("a width field is `%` and an unsigned integer code: `%B`, `%H`, `%I`, `%L` or "
                                    "`%Q`", offset, len(width_field.group().strip()))
            if sizer is not None:
                raise TemplateError("a message has one width field `%H`, for its `%` codes", offset, 2)
            if groups:
                raise TemplateError("a width field `%H` comes before the groups whose `%` codes it sizes", offset, 2)
            if order not in ("<", ">", "!"):
                raise TemplateError("a width field `%H` needs a byte order (`<` or `>`): its `%` codes are integers "
                                    "in it", offset, 2)
            sizer = (len(slots), offset)
            slots.append(Slot(f"%{code}", Type.INT, 1, MOST_WIDTH))
            written.append(code)
            wire += 1
            pos = width_field.end()
            continue
        counted = _COUNT.match(body, pos)
        if counted is not None:
            code = counted.group(1)
            if not code or code not in "BHILQ":
                raise TemplateError("a count field is `#` and an unsigned integer code: `#B`, `#H`, `#I`, `#L` or "
                                    "`#Q`", offset, len(counted.group().strip()))
            if count is not None:
                raise TemplateError("a message has one count field `#B`, for its `#(...)` group", offset, 2)
            count = (wire, code, offset, len(slots))
            written.append(code)
            wire += 1
            pos = counted.end()
            continue
        m = _STRUCT_ITEM.match(body, pos)
        if re.match(r"\s*(\d+|#|\*)\s*\(", body[pos:]):
            raise TemplateError("a repeated group `N(codes)` is closed by `)`, and holds no group", offset)
        if body[pos] == "{" and "}" not in body[pos:]:
            raise TemplateError("bit fields `{...}` are closed by `}`", offset)
        if body[pos] == "{":
            raise TemplateError("bit fields `{...}` follow the unsigned integer code they split: `B{1,1,6}`", offset)
        if not m:
            raise TemplateError(f"`{body[pos]}` is not a struct format code", offset)
        count_text, code = m.groups()
        n = int(count_text) if count_text else 1
        if n > MAX_REPEAT:
            raise TemplateError(f"repeat count {n} is larger than {MAX_REPEAT}", offset, len(m.group().strip()))
        code_at = len(order) + m.end() - 1
        if code == "P":
            raise TemplateError("pointer code `P` has no meaning on a wire", code_at)
        if code in "nN" and order not in ("", "@"):
            raise TemplateError(f"`{code}` exists only in native mode (no byte-order prefix)", code_at)
        split = _SPLIT.match(body, m.end())
        if split is not None:
            widths = _bit_widths(split, order, count_text, code, len(order))
            low = 0
            code = count_text + code  # `22s`: bytes, one integer
            splits.append((len(slots), order + code, widths))
            for width in widths:
                slots.append(Slot(f"{code}{{{','.join(map(str, widths))}}}", Type.INT, 0, (1 << width) - 1,
                                  bits=(low, width)))
                low += width
            written.append(code)
            wire += 1
            pos = split.end()
            continue
        if code in _INT_CODES:
            bits = 8 * (_STANDARD_SIZES.get(code) or struct.calcsize(code))
            signed = code.islower()
            low, high = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)
            slots.extend([Slot(code, Type.INT, low, high)] * n)
        elif code in "efd":
            slots.extend([Slot(code, Type.FLOAT)] * n)
        elif code == "?":
            slots.extend([Slot(code, Type.BOOL)] * n)
        elif code in "spZ":  # `Z`: `s` padded with NUL bytes, read back to the first (as Perl's `Z`)
            slots.append(Slot(f"{n}{code}", Type.STRING))
        elif code == "c":
            slots.extend([Slot(code, Type.STRING)] * n)
        elif code == "x":
            pass
        else:
            raise TemplateError(f"`{code}` is not a struct format code", code_at)
        written.append(f"{count_text}s" if code == "Z" else m.group())
        wire += 0 if code == "x" else 1 if code in "spZ" else n
        pos = m.end()
    if count is not None and varying is None:
        raise TemplateError("a count field `#B` counts a `#(...)` group after it, and there is none", count[2], 2)
    if sizer is not None and not any(slot.code == "%" for slot in slots):
        raise TemplateError("a width field `%H` states the bytes of the `%` codes in the groups after it, and there "
                            "is none", sizer[1], 2)
    if groups and any(s.type is Type.STRING for s in slots):
        raise TemplateError("a format with a repeated group holds numbers and bools only", 0, len(fmt))
    fixed = order + "".join(written)
    try:
        size = struct.calcsize(widest(fixed))
    except struct.error as err:
        raise TemplateError(f"invalid struct format: {err}", 0, len(fmt)) from None
    if size > MAX_MESSAGE:
        raise TemplateError(f"the message is {size} bytes; the limit is {MAX_MESSAGE}", 0, len(fixed))
    native = order in ("", "@") and any(c in "hHiIlLqQnNefd" for c in body)
    if rest:
        slots.append(Slot("*", Type.BYTES))
    shape = None
    if varying is not None:
        at, codes, _ = varying
        high = min(MAX_ARRAY, (1 << 8 * _STANDARD_SIZES[count[1]]) - 1) if count is not None else 0
        tail = "".join(written[at:])
        count_at, count_code, count_slot = (-1, "", -1) if count is None else (count[0], count[1], count[3])
        shape = Varying(order + "".join(written[:at]), codes, tail, count_at, high, count_code, count_slot,
                        unit_size=struct.calcsize(widest(order + codes)), tail_size=struct.calcsize(order + tail),
                        count_size=struct.calcsize(order + count_code) if count_code else 0)
    sized = tuple(replace(slot, size=_code_size(order, slot.code)) for slot in slots)
    layout = StructLayout(sized, size, native, rest, fixed, tuple(groups), shape, tuple(splits), order,
                          width=-1 if sizer is None else sizer[0])
    rooms = tuple((layout.joined(i), text_room(slot.code)) for i, slot in enumerate(sized)
                  if slot.code[-1:] in ("s", "p", "Z"))
    return replace(layout, rooms=rooms)


def _code_size(order: str, code: str) -> int:
    """Bytes of one value of a slot's code (a bit field's: its integer's), in the format's byte order."""
    code = code.split("{")[0]
    code = code.lstrip("%")  # a width field's code; a `%` code at its widest
    return 0 if code == "*" else MOST_WIDTH if code == "" else \
        struct.calcsize(order + (code[:-1] + "s" if code.endswith("Z") else code))


def struct_codes() -> str:
    """The letters a struct format may hold, each a value or a pad byte (`Z` included, `P` not), as
    `struct_layout` reads them: for the highlighters' colours (rdisc.highlight.writer)."""
    import string

    codes = []
    for code in string.ascii_letters + "?":
        try:
            struct_layout(code)
        except TemplateError:
            continue
        codes.append(code)
    return "".join(codes)


def text_room(code: str) -> int:
    """The most bytes of text an `Ns`, `NZ` or `Np` value holds (struct cuts the rest short)."""
    count = int(code[:-1] or 1)
    return count if code[-1:] in ("s", "Z") else max(0, min(count - 1, 255))


def _bit_widths(split: re.Match[str], order: str, count: str, code: str, at: int) -> tuple[int, ...]:
    """The widths of an integer code's bit fields `B{1,1,6}`: an unsigned code without a
    count, two fields or more, every bit of the integer in one of them. `Ns{...}` splits the
    integer that N bytes hold in the format's byte order (SBUS's and CRSF's sixteen 11-bit
    channels in 22 bytes, least significant first: `<22s{11,...}`), into one field or more
    (`>3s{24}`: a 3-byte integer), each of at most 64 bits, as the state keeps."""
    offset = at + split.start(1) - 1
    wide = code == "s"
    if count and not wide:
        raise TemplateError(f"a code split into bit fields has no count: `{code}{{...}}`, not `{count}{code}{{...}}`",
                            at + split.start() - len(count) - 1, len(count))
    if code not in "BHILQs":
        hint = f" (signed): use `{code.upper()}`" if code in "bhilq" else ""
        raise TemplateError(f"bit fields split an unsigned integer code (`B`, `H`, `I`, `L` or `Q`), not `{code}`"
                            f"{hint}", offset - 1)
    if wide and order not in ("<", ">", "!"):
        raise TemplateError("bytes split into bit fields are one integer in the format's byte order: `<` (least "
                            "significant byte first) or `>`", offset - 1 - len(count), len(count) + 1)
    words = re.sub(r"\s*\*\s*", "*", split.group(1)).replace(",", " ").split()
    repeated = [word.partition("*") for word in words]  # `11*16`: sixteen fields of 11 bits, as Python's `[11] * 16`
    if not all(width.isdigit() and (not star or times.isdigit() and 1 <= int(times) <= MAX_REPEAT)
               for width, star, times in repeated):
        raise TemplateError("bit fields are two widths or more, from the lowest bit up: `B{1,1,6}`", offset,
                            len(split.group(1)) + 2)
    widths = tuple(int(width) for width, star, times in repeated for _ in range(int(times) if star else 1))
    if len(widths) < (1 if wide else 2):
        raise TemplateError("bit fields are two widths or more, from the lowest bit up: `B{1,1,6}`" if not wide else
                            "bytes split into bit fields take one width or more: `>3s{24}`", offset,
                            len(split.group(1)) + 2)
    size = 8 * struct.calcsize(order + count + code)
    if 0 in widths or max(widths) > 64 or sum(widths) != size:
        said = "a bit field is 1 bit wide or more" if 0 in widths else "a bit field is at most 64 bits wide" \
            if max(widths) > 64 else \
            f"the bit fields of `{count}{code}` take {sum(widths)} of its {size} bits: every bit is in one field " \
            "(a reserved bit too)"
        raise TemplateError(said, offset, len(split.group(1)) + 2)
    return widths


def _group(group: re.Match[str], at: int, slots: list[Slot], groups: list[tuple[int, int, int]]) -> str:
    """A repeated group `N(codes)`, `#(codes)` or `*(codes)`: one slot per code, each taking or
    giving an array of N values (of any size for `#` and `*`, count 0 in `groups`); the
    group's codes once, as the struct module reads them."""
    varying = group.group(1) in "#*"
    count, inner = (0 if varying else int(group.group(1))), group.group(2)
    offset = at + group.start(2)
    if not varying and not 1 <= count <= MAX_REPEAT:
        raise TemplateError(f"a group repeats 1 to {MAX_REPEAT} times, not {count}", at + group.start(1),
                            len(group.group(1)))
    codes = [(i, ch) for i, ch in enumerate(inner) if not ch.isspace()]
    if not codes:
        raise TemplateError("a repeated group has one code or more", at + group.start(), len(group.group()))
    first = len(slots)
    for i, ch in codes:
        if ch in "{}":
            raise TemplateError("a repeated group holds no bit fields", offset + i)
        if ch == "%":  # an unsigned integer of the bytes the width field states
            slots.append(Slot("%", Type.INT, 0, (1 << 8 * MOST_WIDTH) - 1, repeat=-1 if varying else count))
            continue
        inner_layout = struct_layout("<" + ch) if ch.isascii() and ch.isalpha() or ch == "?" else None
        if inner_layout is None or len(inner_layout.slots) != 1 or inner_layout.slots[0].type is Type.STRING:
            raise TemplateError(f"`{ch}` cannot be repeated in a group: a group holds int, float and bool codes, "
                                "without counts", offset + i)
        slots.append(replace(inner_layout.slots[0], repeat=-1 if varying else count))
    groups.append((first, len(codes), count))
    return "".join(ch for _, ch in codes)


def varying_args(layout: StructLayout, grouped: tuple[int, ...]) -> list[int]:
    """Of the arguments that fill a request's groups (`grouped`, in order), those that fill its
    group repeated as the message says."""
    at = 0
    for _, codes, count in layout.groups:
        if not count:
            return list(grouped[at : at + codes])
        at += codes
    return []


def most_rounds(layout: StructLayout, types: list[AnyType | None]) -> int:
    """The most rounds of a varying group filled by arrays of these types: the size of one of a
    fixed size, else what its count field holds, at most MAX_ARRAY."""
    sizes = [t.size for t in types if isinstance(t, Array) and t.size]
    if sizes:
        return min(sizes)
    return layout.varying.count_high if layout.varying is not None and layout.varying.count_high else MAX_ARRAY


@dataclass(frozen=True, slots=True)
class FormatField(metaclass=Frozen):
    spec: str
    offset: int  # of the `{` in the template


def format_fields(template: str) -> tuple[FormatField, ...]:
    """The positional fields of a PEP 3101 template, in argument order.

    Only `{}`/`{N}` with a plain spec are allowed: field names with attributes or
    indexes would let a description reach into Python objects.
    """
    fields: list[tuple[int, FormatField]] = []
    auto = 0
    manual = False
    import string  # only for a `format` primitive: its import is a millisecond of a cold `rdisc check`

    try:
        parsed = list(string.Formatter().parse(template))
    except ValueError as err:
        raise TemplateError(f"invalid format string: {err}", 0, len(template)) from None
    offsets = _field_offsets(template)
    for _literal, name, spec, conversion in parsed:
        if name is None:
            continue
        offset = offsets[len(fields)] if len(fields) < len(offsets) else 0
        if conversion:
            raise TemplateError(f"conversion `!{conversion}` is not allowed in a format field", offset)
        if spec and ("{" in spec or "}" in spec):
            raise TemplateError("nested fields are not allowed in a format spec", offset)
        if any(int(n) > MAX_REPEAT for n in re.findall(r"\d+", spec or "")):
            raise TemplateError(f"a width or precision above {MAX_REPEAT} in `{{:{spec}}}`", offset)
        if name == "":
            if manual:
                raise TemplateError("cannot mix `{}` and `{N}` fields", offset)
            index = auto
            auto += 1
        elif name.isdigit():
            if auto:
                raise TemplateError("cannot mix `{}` and `{N}` fields", offset)
            manual = True
            index = int(name)
            if index > MAX_REPEAT:
                raise TemplateError(f"field index {index} is too large", offset)
        elif "." in name or "[" in name:
            reach = "an attribute" if name.find(".") != -1 and (name.find("[") == -1 or name.find(".") < name.find("[")) else "an index"
            raise TemplateError(
                f"field `{{{name}}}` reaches into {reach} of its argument: fields are `{{}}` or `{{0}}` "
                "with an optional format spec", offset, len(name) + 2
            )
        else:
            raise TemplateError(
                f"field `{{{name}}}` is named: format arguments are positional, write `{{}}` or `{{0}}`",
                offset, len(name) + 2
            )
        fields.append((index, FormatField(spec or "", offset)))
    by_index: dict[int, FormatField] = {}
    for index, field in fields:
        by_index.setdefault(index, field)
    count = max(by_index, default=-1) + 1
    missing = [i for i in range(count) if i not in by_index]
    if missing:
        raise TemplateError(f"format field {{{missing[0]}}} is never used", 0, len(template))
    return tuple(by_index[i] for i in range(count))


def _field_offsets(template: str) -> list[int]:
    """Offset of each replacement field's `{`, in order (escaped `{{` and `}}` skipped): one pass."""
    offsets: list[int] = []
    i = 0
    while i < len(template):
        if template.startswith("{{", i) or template.startswith("}}", i):
            i += 2
            continue
        if template[i] == "{":
            offsets.append(i)
        i += 1
    return offsets


_SPEC_WIDTH = r"(?:.?[<>=^])?[+\- ]?z?#?0?(\d+)?"  # compiled when first used (rdisc.patterns)
_SAMPLES = {Type.INT: 0, Type.FLOAT: 0.0, Type.BOOL: False, Type.STRING: ""}


def spec_accepts(spec: str, type_: AnyType) -> bool:
    """Whether a format spec can format a value of this type (text, never bytes: they have no
    one way to be written as text)."""
    if type_ not in _SAMPLES:
        return False
    try:
        format(_SAMPLES[type_], spec)
    except (ValueError, TypeError):
        return False
    return True


def format_width(spec: str) -> int:
    """The minimum width a spec asks for (0 if none): a lower bound on bytes."""
    m = patterns.pattern(_SPEC_WIDTH).match(spec)
    return int(m.group(1)) if m and m.group(1) else 0


def regex_groups(pattern: str) -> int:
    """Number of groups of a regex; raises TemplateError where it does not compile
    or could take more than linear time on a reply line (see `regex_shape`)."""
    from rdisc import regex_shape  # for a `regex` primitive only: start-up time

    try:
        with warnings.catch_warnings():  # Python's hints about future syntax (`[[`) are not the user's to see
            warnings.simplefilter("ignore", FutureWarning)
            parsed = regex_shape.parse_tree(pattern)  # once for both: `re.compile` parses, and so would `risk`
            compiled = regex_shape.compiled(parsed)
            risky = regex_shape.risk(parsed)
    except re.error as err:
        raise TemplateError(f"invalid regular expression: {err.msg}", err.pos or 0) from None
    except (OverflowError, RecursionError, MemoryError):
        raise TemplateError("regular expression is too complex", 0, len(pattern)) from None
    if risky is not None:
        raise TemplateError(risky, 0, len(pattern))
    return compiled.groups


def regex_min_length(pattern: str) -> int:
    """The fewest characters the regex can match (a lower bound on a reply)."""
    from rdisc import regex_shape  # for a `regex` primitive only: start-up time

    try:
        return min(regex_shape.parse_tree(pattern).getwidth()[0], 1 << 16)
    except Exception:  # noqa: BLE001 - a lower bound of 0 is always safe
        return 0
