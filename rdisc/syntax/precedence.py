"""Operator precedence and spelling of the expression language, in one table,
and the spelling of its literals.

Both expression printers (AST → .rdis text in `printer`, typed IR → canonical JSON
in `rdisc.emit.canonical`) build their text through this module, so they agree
with each other and with grammar/rdis.lark on where parentheses are needed: only
where the grammar would otherwise read a different tree.
"""

from __future__ import annotations

import math

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.syntax.precedence_methods import dataclass

from rdisc.frozen import Frozen

# Levels, loosest first; an operand printed at a level below what its place in
# the grammar accepts gets parentheses.
CONDITIONAL = 0  # x if c else y
OR = 1
AND = 2
NOT = 3
COMPARISON = 4
BIT_OR = 5
BIT_XOR = 6
BIT_AND = 7
SHIFT = 8
ARITH = 9  # + -
TERM = 10  # * / // %
UNARY = 11  # - + ~
POWER = 12
ATOM = 13  # literals, names, calls, indexing, parenthesised expressions


@dataclass(frozen=True, slots=True)
class Operator(metaclass=Frozen):
    spelling: str  # as printed, spaces included
    level: int
    operands: tuple[int, ...]  # the lowest level each operand may have without parentheses


def _left(level: int, spelling: str) -> Operator:
    """A left-associative binary operator: `a - b - c` is `(a - b) - c`."""
    return Operator(f" {spelling} ", level, (level, level + 1))


BINARY: dict[str, Operator] = {
    "or": _left(OR, "or"),
    "and": _left(AND, "and"),
    # Comparisons do not chain in RDIS (`a < b < c` is a syntax error), so a
    # comparison operand of a comparison is parenthesised on both sides.
    **{op: Operator(f" {op} ", COMPARISON, (BIT_OR, BIT_OR)) for op in ("==", "!=", "<", "<=", ">", ">=", "in")},
    "|": _left(BIT_OR, "|"),
    "^": _left(BIT_XOR, "^"),
    "&": _left(BIT_AND, "&"),
    **{op: _left(SHIFT, op) for op in ("<<", ">>")},
    **{op: _left(ARITH, op) for op in ("+", "-")},
    **{op: _left(TERM, op) for op in ("*", "/", "//", "%")},
    # Right-associative, and tighter than a unary operator on its left
    # (-2 ** 2 is -(2 ** 2)) but not on its right (2 ** -1).
    "**": Operator(" ** ", POWER, (ATOM, UNARY)),
}

UNARY_OPERATORS: dict[str, Operator] = {
    "not": Operator("not ", NOT, (NOT,)),
    **{op: Operator(op, UNARY, (UNARY,)) for op in ("-", "+", "~")},
}

# `then if cond else orelse`: then and cond are or-expressions, orelse nests freely.
CONDITIONAL_OPERANDS = (OR, OR, CONDITIONAL)


@dataclass(frozen=True, slots=True)
class Printed(metaclass=Frozen):
    """Expression text and the level of its outermost operator."""

    text: str
    level: int

    def at(self, minimum: int) -> str:
        """The text, parenthesised if its level is below `minimum`."""
        return self.text if self.level >= minimum else f"({self.text})"


def binary(op: str, left: Printed, right: Printed) -> Printed:
    o = BINARY[op]
    low, high = o.operands
    if o.level == COMPARISON:
        # Not needed by the grammar, but kept for readers used to C, where
        # `flags & 3 == 0` means `flags & (3 == 0)`.
        low = high = ARITH
    return Printed(left.at(low) + o.spelling + right.at(high), o.level)


def unary(op: str, operand: Printed) -> Printed:
    o = UNARY_OPERATORS[op]
    return Printed(o.spelling + operand.at(o.operands[0]), o.level)


def conditional(then: Printed, cond: Printed, orelse: Printed) -> Printed:
    t, c, e = CONDITIONAL_OPERANDS
    return Printed(f"{then.at(t)} if {cond.at(c)} else {orelse.at(e)}", CONDITIONAL)


def call(func: str, args: list[Printed]) -> Printed:
    return Printed(f"{func}({', '.join(a.at(CONDITIONAL) for a in args)})", ATOM)


def array(items: list[Printed]) -> Printed:
    return Printed(f"[{', '.join(a.at(CONDITIONAL) for a in items)}]", ATOM)


def index(base: str, at: Printed) -> Printed:
    return Printed(f"{base}[{at.at(CONDITIONAL)}]", ATOM)


def literal(value: float | str | bytes) -> Printed:  # bool and int included
    """A constant as the grammar reads it back: floats always with `.` or an
    exponent, negative numbers as a unary minus, non-finite floats through `float`."""
    if isinstance(value, bool):
        return Printed("True" if value else "False", ATOM)
    if isinstance(value, str):
        return Printed(quote(value), ATOM)
    if isinstance(value, bytes):
        return Printed(quote_bytes(value), ATOM)
    if isinstance(value, float) and math.isnan(value):
        return Printed('float("nan")', ATOM)
    magnitude = abs(value)
    text = 'float("inf")' if isinstance(magnitude, float) and math.isinf(magnitude) else repr(magnitude)
    negative = math.copysign(1.0, value) < 0 if isinstance(value, float) else value < 0
    return unary("-", Printed(text, ATOM)) if negative else Printed(text, ATOM)


_ESCAPES = {"\n": "\\n", "\r": "\\r", "\t": "\\t", "\0": "\\0", "\\": "\\\\", '"': '\\"'}


def quote(value: str) -> str:
    """A double-quoted string literal that reads back as `value`: the usual escapes,
    `\\xHH`/`\\uHHHH` for other characters that are not printable, the rest as is."""
    out = ['"']
    for ch in value:
        if ch in _ESCAPES:
            out.append(_ESCAPES[ch])
        elif ch.isprintable():
            out.append(ch)
        elif ord(ch) <= 0xFF:
            out.append(f"\\x{ord(ch):02x}")
        elif ord(ch) <= 0xFFFF:
            out.append(f"\\u{ord(ch):04x}")
        else:  # astral and not printable: the lexer takes any character but `"`, `\\` and a newline
            out.append(ch)
    out.append('"')
    return "".join(out)


def octets(value: str) -> bool:
    """Whether a string literal stands for bytes on the wire: every character up to `\xff`
    (the checker refuses any other in a header, a terminator, a marker)."""
    return all(ord(ch) <= 0xFF for ch in value)


def quote_octets(value: str) -> str:
    """A string literal of bytes on the wire (a header, a terminator, a marker) that reads back
    as `value`: text (printable ASCII and the usual escapes) as text, `"AT\\r\\n"`; any other
    bytes all as `\\xHH`, `"\\xff\\xff"` rather than `"ÿÿ"`, not a mixture that reads as neither."""
    if all(" " <= ch < "\x7f" or ch in "\n\r\t" for ch in value):
        return '"' + "".join(_ESCAPES.get(ch, ch) for ch in value) + '"'
    if octets(value):
        return '"' + "".join(f"\\x{ord(ch):02x}" for ch in value) + '"'
    return quote(value)  # past a byte: the checker's to refuse, printed as written


def quote_bytes(value: bytes) -> str:
    """A bytes literal `b"..."` that reads back as `value`, as `quote_octets` writes a string."""
    return "b" + quote_octets(value.decode("latin-1"))
