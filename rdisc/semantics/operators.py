"""What the operators and built-in functions of the expression language compute.

One definition, used by constant folding in the checker and by the runtime's
interpreter. Every operation that could be made to eat memory or time (powers,
shifts, string and bytes building) is bounded here and raises `EvalError` (or
`ValueError`, in the part a generated driver carries) instead.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from typing import Any

from rdisc.limits import MAX_INT
from rdisc.syntax.precedence import quote_bytes

MAX_SHIFT = 1024
MAX_RESULT_BITS = 4096  # of an int result inside an expression (so that no chain of operations can explode)


class EvalError(ArithmeticError):
    """An expression that cannot be evaluated: the message says why."""


def shown(value: Any) -> str:
    """A value as a message shows it: huge numbers abbreviated, strings quoted, bytes as written."""
    text = quote_bytes(value) if isinstance(value, bytes) else repr(value)
    if isinstance(value, int) and len(text) > 24:
        return f"a {value.bit_length()}-bit integer"
    return text if len(text) <= 40 else text[:37] + "..."


def _pow(a: Any, b: Any) -> Any:
    if isinstance(a, int) and isinstance(b, int):
        if b < 0:
            raise EvalError(f"negative integer exponent {shown(b)}: write a float base, e.g. {shown(a)}.0 ** {shown(b)}")
        if abs(a) > 1 and b * max(1, abs(a).bit_length()) > MAX_RESULT_BITS:
            raise EvalError(f"{shown(a)} ** {shown(b)} is too large (results are limited to {MAX_RESULT_BITS} bits)")
        return a**b
    try:
        result = float(a) ** float(b)
    except OverflowError:
        raise EvalError(f"{shown(a)} ** {shown(b)} is too large for a float") from None
    except ZeroDivisionError:
        raise EvalError(f"{shown(a)} ** {shown(b)}: zero to a negative power") from None
    if isinstance(result, complex):
        raise EvalError(f"{shown(a)} ** {shown(b)} has no real value")
    return result


def _lshift(a: int, b: int) -> int:
    if b < 0:
        raise EvalError(f"negative shift count {b}")
    if b > MAX_SHIFT or a.bit_length() + b > MAX_RESULT_BITS:
        raise EvalError(f"{shown(a)} << {shown(b)} is too large (results are limited to {MAX_RESULT_BITS} bits)")
    return a << b


def _rshift(a: int, b: int) -> int:
    if b < 0:
        raise EvalError(f"negative shift count {shown(b)}")
    return a >> min(b, MAX_RESULT_BITS + 1)


def _mul(a: Any, b: Any) -> Any:
    result = a * b
    if type(result) is int and result.bit_length() > MAX_RESULT_BITS:
        raise EvalError(f"{shown(a)} * {shown(b)} is too large (results are limited to {MAX_RESULT_BITS} bits)")
    return result


def fits(value: Any) -> bool:
    """Whether a value is within the integers rdisc keeps (64 bits and a sign); non-ints always are."""
    if type(value) is tuple:  # an array
        return all(fits(v) for v in value)
    return type(value) is not int or -MAX_INT <= value <= MAX_INT


def _div(a: Any, b: Any) -> float:
    if b == 0:
        raise EvalError("division by zero")
    return a / b


def _floordiv(a: Any, b: Any) -> Any:
    if b == 0:
        raise EvalError("division by zero")
    return a // b


def _mod(a: Any, b: Any) -> Any:
    if b == 0:
        raise EvalError("modulo by zero")
    return a % b


def _add(a: Any, b: Any) -> Any:
    return _concat(a, b) if isinstance(a, (str, bytes)) else a + b


def _checked_float(f: Callable[..., Any]) -> Callable[..., Any]:
    def wrapper(a: Any, b: Any) -> Any:
        result = f(a, b)
        if isinstance(result, float) and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
            raise EvalError("the result is too large for a float")
        return result

    return wrapper


BINARY: dict[str, Callable[[Any, Any], Any]] = {
    "+": _checked_float(_add),
    "-": _checked_float(operator.sub),
    "*": _checked_float(_mul),
    "/": _checked_float(_div),
    "//": _floordiv,
    "%": _mod,
    "**": _pow,
    "<<": _lshift,
    ">>": _rshift,
    "&": operator.and_,
    "|": operator.or_,
    "^": operator.xor,
    "==": operator.eq,
    "!=": operator.ne,
    "<": operator.lt,
    "<=": operator.le,
    ">": operator.gt,
    ">=": operator.ge,
}

UNARY: dict[str, Callable[[Any], Any]] = {
    "-": operator.neg,
    "+": operator.pos,
    "~": operator.invert,
    "not": operator.not_,
}


def _round(x: Any, ndigits: int | None = None) -> Any:
    try:
        return round(x) if ndigits is None else round(float(x), ndigits)
    except (ValueError, OverflowError) as err:
        raise EvalError(f"round({shown(x)}): {err}") from None


def _int(x: Any) -> int:
    try:
        return int(x.strip(), 0) if isinstance(x, str) and x.strip()[:2].lower() in ("0x", "0b", "0o") else int(x)
    except (ValueError, OverflowError) as err:
        raise EvalError(f"int({shown(x)}): {_reason(err)}") from None


def _float(x: Any) -> float:
    try:
        return float(x)
    except (ValueError, OverflowError) as err:
        raise EvalError(f"float({shown(x)}): {_reason(err)}") from None


def _clamp(x: Any, lo: Any, hi: Any) -> Any:
    return lo if x < lo else min(x, hi)


def _reason(err: Exception) -> str:
    """Python's reason, without the value it may quote at length."""
    if isinstance(err, OverflowError):
        return "too large"
    text = str(err)
    if text == "math domain error":
        return "outside the function's domain"
    return text if len(text) <= 60 else text.split(":")[0]


def _math(f: Callable[..., float]) -> Callable[..., float]:
    def wrapper(*args: Any) -> float:
        try:
            return f(*args)
        except (ValueError, OverflowError) as err:
            raise EvalError(f"{f.__name__}({', '.join(shown(a) for a in args)}): {_reason(err)}") from None

    return wrapper


def _byte(data: Any, index: Any) -> int:
    """`byte(b, i)`: byte i of bytes b, 0 first, as an int."""
    if not 0 <= index < len(data):
        raise EvalError(f"byte {index} of {len(data)} bytes: no such byte")
    return int(data[index])


# ---- strings and bytes: carried by every driver that uses them ----------------------------------
#
# From here to the end marker, the text is copied as it is into a generated driver
# (rdisc.emit.python_support), so the runtime, the checker and every driver compute these
# with the same code. It uses only builtins and raises ValueError.

_MAX_TEXT = 1 << 20  # characters of a string, or bytes of bytes, that an expression may build


def _concat(a: Any, b: Any) -> Any:
    """`a + b` of two strings or two bytes, at most _MAX_TEXT long: no chain grows one without bound."""
    if len(a) + len(b) > _MAX_TEXT:
        raise ValueError(f"string longer than {_MAX_TEXT} characters" if isinstance(a, str)
                         else f"more than {_MAX_TEXT} bytes")
    return a + b


def _hex(data: bytes) -> str:
    """`hex(b)`: the bytes as lowercase hex digits, two a byte: "0a1b"."""
    if 2 * len(data) > _MAX_TEXT:
        raise ValueError(f"hex(): {len(data)} bytes make a string longer than {_MAX_TEXT} characters")
    return data.hex()


def _ascii(data: bytes) -> str:
    """`ascii(b)`: the text of ASCII bytes; a byte past 0x7f is refused, never guessed at."""
    for i, byte in enumerate(data):
        if byte > 0x7F:
            raise ValueError(f"ascii(): byte {i} is 0x{byte:02x}, not ASCII")
    return data.decode("ascii")


def _encode(text: str) -> bytes:
    """`encode(s)`: the bytes of an ASCII string; a character past U+007F is refused."""
    for i, ch in enumerate(text):
        if ord(ch) > 0x7F:
            raise ValueError(f"encode(): character {i} is {ch!r}, not ASCII")
    return text.encode("ascii")


def _pack7(data: bytes) -> bytes:
    """`pack7(b)`: Firmata's 7-bit form of bytes (STRING_DATA and other sysex payloads): each
    byte as two bytes of 7 bits, the low 7 bits first, then bit 7."""
    if 2 * len(data) > _MAX_TEXT:
        raise ValueError(f"pack7(): {len(data)} bytes make more than {_MAX_TEXT} bytes")
    out = bytearray()
    for byte in data:
        out += bytes((byte & 0x7F, byte >> 7 & 0x7F))
    return bytes(out)


def _unpack7(data: bytes) -> bytes:
    """`unpack7(b)`: bytes from Firmata's 7-bit pairs, low bits first; an odd length, a byte with
    bit 7 set or a pair past 255 is refused."""
    if len(data) % 2:
        raise ValueError(f"unpack7(): an odd number of bytes ({len(data)}), not pairs of 7-bit bytes")
    out = bytearray()
    for i in range(0, len(data), 2):
        low, high = data[i], data[i + 1]
        if low > 0x7F or high > 0x7F:
            raise ValueError(f"unpack7(): byte {i if low > 0x7F else i + 1} has bit 7 set, not a 7-bit byte")
        if high > 1:
            raise ValueError(f"unpack7(): bytes {i} and {i + 1} make {low | high << 7}, more than a byte")
        out.append(low | high << 7)
    return bytes(out)


def _bitset(bits: tuple[int, ...]) -> int:
    """`bitset(a)`: one int with bit a[i] set for each element (a Firmata pin's set of modes),
    each element 0..63 so the set stays a 64-bit int; any other is refused."""
    out = 0
    for i, bit in enumerate(bits):
        if not 0 <= bit <= 63:
            raise ValueError(f"bitset(): element {i} is {bit}, not a bit from 0 to 63")
        out |= 1 << bit
    return out


# ---- end of what drivers carry ----


FUNCTIONS: dict[str, Callable[..., Any]] = {
    "abs": abs,
    "min": min,
    "max": max,
    "round": _round,
    "int": _int,
    "float": _float,
    "bool": bool,
    "str": str,
    "clamp": _clamp,
    "sqrt": _math(math.sqrt),
    "sin": _math(math.sin),
    "cos": _math(math.cos),
    "atan2": _math(math.atan2),
    "hypot": _math(math.hypot),
    "len": len,
    "byte": _byte,
    "hex": _hex,
    "ascii": _ascii,
    "encode": _encode,
    "pack7": _pack7,
    "unpack7": _unpack7,
    "bitset": _bitset,
}
