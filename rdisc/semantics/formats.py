"""Static analysis of the message templates a primitive uses: struct formats
(`pack`/`unpack`), PEP 3101 formats (`format`) and regular expressions (`regex`).

Each analysis returns a value or raises `TemplateError` with a message and an
offset into the template, so the checker can point at the offending character.
"""

from __future__ import annotations

import dataclasses
import re
import string
import struct
from dataclasses import dataclass

from rdisc.semantics import regex_shape
from rdisc.semantics.model import Type

MAX_REPEAT = 4096
MAX_MESSAGE = 65536  # bytes of one request or reply


class TemplateError(ValueError):
    def __init__(self, message: str, offset: int = 0, length: int = 1) -> None:
        super().__init__(message)
        self.message = message
        self.offset = offset
        self.length = length


@dataclass(frozen=True, slots=True)
class Slot:
    """One value a template takes or yields."""

    code: str  # the struct code or the PEP 3101 spec ("" for `{}`)
    type: Type
    low: int | None = None  # integer range, when the code has one
    high: int | None = None
    repeat: int = 0  # in a repeated group `6(BH)`: the group's count (the value is an array of it)


@dataclass(frozen=True, slots=True)
class StructLayout:
    slots: tuple[Slot, ...]
    size: int  # bytes on the wire (before the rest, when it ends in `*`)
    native: bool  # no byte-order prefix: host order and alignment
    rest: bool = False  # ends in `*`: the rest of the message, as bytes
    fixed: str = ""  # the format without its `*` and with its groups written out, for the struct module
    groups: tuple[tuple[int, int, int], ...] = ()  # each repeated group: (its first slot, its codes, its count)


def split_rest(fmt: str) -> tuple[str, bool]:
    """A struct format and whether it ended in `*` (the rest of the message, as bytes)."""
    stripped = fmt.rstrip()
    return (stripped[:-1], True) if stripped.endswith("*") else (fmt, False)


_INT_CODES = "bBhHiIlLqQnN"
_STANDARD_SIZES = {"b": 1, "B": 1, "h": 2, "H": 2, "i": 4, "I": 4, "l": 4, "L": 4, "q": 8, "Q": 8}
_STRUCT_ITEM = re.compile(r"\s*(\d*)\s*([a-zA-Z?])")
_GROUP = re.compile(r"\s*(\d+)\s*\(([^()]*)\)")  # `6(BH)`: a repeated group


def struct_layout(fmt: str) -> StructLayout:
    """The values a struct format packs or unpacks, one slot per value. A final `*`
    stands for the rest of the message: one value of bytes, of any length."""
    fmt, rest = split_rest(fmt)
    for at, ch in enumerate(fmt):  # struct reads only ASCII (its digits, not `١`), and no line breaks
        if not ch.isascii() or ch in "\n\r\x0b\x0c":
            raise TemplateError(f"{ch!r} is not a struct format code (they are ASCII letters and digits)", at)
    if "*" in fmt:
        raise TemplateError("`*` (the rest of the message) comes last", fmt.index("*"))
    order = fmt[:1] if fmt[:1] in "@=<>!" else ""
    body = fmt[len(order) :]
    slots: list[Slot] = []
    groups: list[tuple[int, int, int]] = []
    written: list[str] = []  # the body with each group written out
    pos = 0
    while pos < len(body):
        if body[pos].isspace():
            pos += 1
            continue
        group = _GROUP.match(body, pos)
        if group is not None:
            written.append(_group(group, len(order), slots, groups))
            pos = group.end()
            continue
        m = _STRUCT_ITEM.match(body, pos)
        offset = len(order) + pos
        if re.match(r"\s*\d+\s*\(", body[pos:]):
            raise TemplateError("a repeated group `N(codes)` is closed by `)`, and holds no group", offset)
        if not m:
            raise TemplateError(f"`{body[pos]}` is not a struct format code", offset)
        count_text, code = m.groups()
        count = int(count_text) if count_text else 1
        if count > MAX_REPEAT:
            raise TemplateError(f"repeat count {count} is larger than {MAX_REPEAT}", offset, len(m.group().strip()))
        code_at = len(order) + m.end() - 1
        if code == "P":
            raise TemplateError("pointer code `P` has no meaning on a wire", code_at)
        if code in "nN" and order not in ("", "@"):
            raise TemplateError(f"`{code}` exists only in native mode (no byte-order prefix)", code_at)
        if code in _INT_CODES:
            bits = 8 * (_STANDARD_SIZES.get(code) or struct.calcsize(code))
            signed = code.islower()
            low, high = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)
            slots.extend([Slot(code, Type.INT, low, high)] * count)
        elif code in "efd":
            slots.extend([Slot(code, Type.FLOAT)] * count)
        elif code == "?":
            slots.extend([Slot(code, Type.BOOL)] * count)
        elif code in "sp":
            slots.append(Slot(f"{count}{code}", Type.STRING))
        elif code == "c":
            slots.extend([Slot(code, Type.STRING)] * count)
        elif code == "x":
            pass
        else:
            raise TemplateError(f"`{code}` is not a struct format code", code_at)
        written.append(m.group())
        pos = m.end()
    if groups and any(s.type is Type.STRING for s in slots):
        raise TemplateError("a format with a repeated group holds numbers and bools only", 0, len(fmt))
    fmt = order + "".join(written)
    try:
        size = struct.calcsize(fmt)
    except struct.error as err:
        raise TemplateError(f"invalid struct format: {err}", 0, len(fmt)) from None
    if size > MAX_MESSAGE:
        raise TemplateError(f"the message is {size} bytes; the limit is {MAX_MESSAGE}", 0, len(fmt))
    native = order in ("", "@") and any(c in "hHiIlLqQnNefd" for c in body)
    if rest:
        slots.append(Slot("*", Type.BYTES))
    return StructLayout(tuple(slots), size, native, rest, fmt, tuple(groups))


def _group(group: re.Match[str], at: int, slots: list[Slot], groups: list[tuple[int, int, int]]) -> str:
    """A repeated group `N(codes)`: one slot per code, each taking or giving an array of N
    values; the codes as the struct module reads them, written out N times."""
    count, inner = int(group.group(1)), group.group(2)
    offset = at + group.start(2)
    if not 1 <= count <= MAX_REPEAT:
        raise TemplateError(f"a group repeats 1 to {MAX_REPEAT} times, not {count}", at + group.start(1),
                            len(group.group(1)))
    codes = [(i, ch) for i, ch in enumerate(inner) if not ch.isspace()]
    if not codes:
        raise TemplateError("a repeated group has one code or more", at + group.start(), len(group.group()))
    first = len(slots)
    for i, ch in codes:
        inner_layout = struct_layout("<" + ch) if ch.isascii() and ch.isalpha() or ch == "?" else None
        if inner_layout is None or len(inner_layout.slots) != 1 or inner_layout.slots[0].type is Type.STRING:
            raise TemplateError(f"`{ch}` cannot be repeated in a group: a group holds int, float and bool codes, "
                                "without counts", offset + i)
        slots.append(dataclasses.replace(inner_layout.slots[0], repeat=count))
    groups.append((first, len(codes), count))
    return "".join(ch for _, ch in codes) * count

@dataclass(frozen=True, slots=True)
class FormatField:
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
    try:
        parsed = list(string.Formatter().parse(template))
    except ValueError as err:
        raise TemplateError(f"invalid format string: {err}", 0, len(template)) from None
    for _literal, name, spec, conversion in parsed:
        if name is None:
            continue
        offset = _field_offset(template, len(fields))
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


def _field_offset(template: str, n: int) -> int:
    """Offset of the n-th replacement field's `{` (escaped `{{` skipped)."""
    seen = -1
    i = 0
    while i < len(template):
        if template.startswith("{{", i) or template.startswith("}}", i):
            i += 2
            continue
        if template[i] == "{":
            seen += 1
            if seen == n:
                return i
        i += 1
    return 0


_SPEC_WIDTH = re.compile(r"(?:.?[<>=^])?[+\- ]?z?#?0?(\d+)?")
_SAMPLES = {Type.INT: 0, Type.FLOAT: 0.0, Type.BOOL: False, Type.STRING: ""}


def spec_accepts(spec: str, type_: Type) -> bool:
    """Whether a format spec can format a value of this type."""
    try:
        format(_SAMPLES[type_], spec)
    except (ValueError, TypeError):
        return False
    return True


def format_width(spec: str) -> int:
    """The minimum width a spec asks for (0 if none): a lower bound on bytes."""
    m = _SPEC_WIDTH.match(spec)
    return int(m.group(1)) if m and m.group(1) else 0


def regex_groups(pattern: str) -> int:
    """Number of groups of a regex; raises TemplateError where it does not compile
    or could take more than linear time on a reply line (see `regex_shape`)."""
    try:
        compiled = re.compile(pattern)
        risky = regex_shape.risk(pattern)
    except re.error as err:
        raise TemplateError(f"invalid regular expression: {err.msg}", err.pos or 0) from None
    except (OverflowError, RecursionError, MemoryError):
        raise TemplateError("regular expression is too complex", 0, len(pattern)) from None
    if risky is not None:
        raise TemplateError(risky, 0, len(pattern))
    return compiled.groups


def regex_min_length(pattern: str) -> int:
    """The fewest characters the regex can match (a lower bound on a reply)."""
    try:
        from re import _parser  # type: ignore[attr-defined]

        return min(_parser.parse(pattern).getwidth()[0], 1 << 16)
    except Exception:  # noqa: BLE001 - a lower bound of 0 is always safe
        return 0
