"""The operations of RDIS expressions, written once, with the limits that bound them.

Every operator and built-in function of the expression language is computed here: ints of
a fixed number of bits, floats whose overflow is an error rather than inf, powers and shifts
that cannot eat memory, strings and bytes of bounded length, and the conversions between
them. The checker folds constants with these functions, the runtime's interpreter calls them,
and every generated driver carries this module's text (all of it after the imports) and calls
them by name; so a value, and the message of an error, is the same at check time, in the
runtime and in a driver. Which function a node of a description needs, and where Python's own
operator computes exactly the same (the sum of two ints, a comparison), is decided once in
rdisc.semantics.operators.

It needs only the standard library and imports nothing of rdisc. The functions a driver calls
start with `_`: a description's names start with a letter, so no parameter hides one. A refused
operation raises EvalError (an ArithmeticError), or ValueError for strings and bytes; the
runtime and drivers report either as an RdisValueError of the element at fault, the checker as
E405.
"""

from __future__ import annotations

import math
import struct
import sys
from collections.abc import Callable, Mapping

TYPE_CHECKING = False  # typing's, without importing typing: `rdisc check` imports this module
if TYPE_CHECKING:
    from typing import Any, Literal

MAX_INT = (1 << 64) - 1  # the largest int a state variable, parameter or field holds; its negation the smallest
MAX_RESULT_BITS = 4096  # of an int result inside an expression, so that no chain of operations explodes
MAX_SHIFT = 1024  # the longest left shift
MAX_TEXT = 1 << 20  # characters of a string, or bytes of bytes, that an expression may build
FLOAT_MAX = sys.float_info.max  # the largest float; a result past it is an error, not inf
MAX_ARRAY = 1024  # the most elements an array holds, and rounds a group repeated as a message says
MAX_INT_BYTES = 8  # bytes that int_le and int_be read: a 64-bit int
MAX_NIBBLES = 16  # nibbles that nibbles() spreads and from_nibbles() gathers: a 64-bit int
MAX_LINE = 4096
"""Bytes of one reply line, terminator included."""

EVAL_ERRORS = (ArithmeticError, ValueError, TypeError, IndexError, OverflowError)
"""What evaluating an expression can raise; each becomes an RdisValueError of the element at fault."""


class EvalError(ArithmeticError):
    """An expression that cannot be evaluated: the message says why."""


def shown(value: Any, spelt: str | None = None) -> str:
    """A value as a message shows it (`spelt` as written, repr by default): a huge int by its
    width, anything long cut short, so that no message repeats a thousand digits."""
    text = repr(value) if spelt is None else spelt
    if isinstance(value, int) and len(text) > 24:
        return f"a {value.bit_length()}-bit integer"
    return text if len(text) <= 40 else text[:37] + "..."


def fits(value: Any) -> bool:
    """Whether a value is within the integers rdisc keeps (64 bits and a sign); non-ints always are."""
    if type(value) is tuple:  # an array
        return all(fits(v) for v in value)
    return type(value) is not int or -MAX_INT <= value <= MAX_INT


# ---- numbers -----------------------------------------------------------------------------------


def _finite(a: Any, b: Any, result: Any) -> Any:
    """`result` of an operation on `a` and `b`: an infinity that neither operand was is an error.
    (Called only where `result` is not within +-FLOAT_MAX, so the common case costs nothing.)"""
    if type(result) is float and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise EvalError("the result is too large for a float")
    return result


def _add(a: Any, b: Any) -> Any:
    """`a + b` of two numbers."""
    result = a + b
    return result if -FLOAT_MAX <= result <= FLOAT_MAX else _finite(a, b, result)


def _sub(a: Any, b: Any) -> Any:
    """`a - b`."""
    result = a - b
    return result if -FLOAT_MAX <= result <= FLOAT_MAX else _finite(a, b, result)


def _mul(a: Any, b: Any) -> Any:
    """`a * b`: an int product is bounded too."""
    result = a * b
    if -FLOAT_MAX <= result <= FLOAT_MAX:
        return result
    if type(result) is int and result.bit_length() > MAX_RESULT_BITS:
        raise EvalError(f"{shown(a)} * {shown(b)} is too large (results are limited to {MAX_RESULT_BITS} bits)")
    return _finite(a, b, result)


def _div(a: Any, b: Any) -> Any:
    """`a / b`, always a float."""
    if b == 0:
        raise EvalError("division by zero")
    result = a / b
    return result if -FLOAT_MAX <= result <= FLOAT_MAX else _finite(a, b, result)


def _floordiv(a: Any, b: Any) -> Any:
    """`a // b`."""
    if b == 0:
        raise EvalError("division by zero")
    return a // b


def _mod(a: Any, b: Any) -> Any:
    """`a % b`, of the divisor's sign."""
    if b == 0:
        raise EvalError("modulo by zero")
    return a % b


def _pow(a: Any, b: Any) -> Any:
    """`a ** b`: an int result within MAX_RESULT_BITS, a float one real and finite."""
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
    """`a << b`, within MAX_RESULT_BITS."""
    if b < 0:
        raise EvalError(f"negative shift count {b}")
    if b > MAX_SHIFT or a.bit_length() + b > MAX_RESULT_BITS:
        raise EvalError(f"{shown(a)} << {shown(b)} is too large (results are limited to {MAX_RESULT_BITS} bits)")
    return a << b


def _rshift(a: int, b: int) -> int:
    """`a >> b`."""
    if b < 0:
        raise EvalError(f"negative shift count {shown(b)}")
    return a >> min(b, MAX_RESULT_BITS + 1)


def _plus(a: Any, b: Any) -> Any:
    """`a + b` of two numbers, two strings or two bytes."""
    return _concat(a, b) if isinstance(a, (str, bytes)) else _add(a, b)


def _reason(err: Exception) -> str:
    """Python's reason, without the value it may quote at length."""
    if isinstance(err, OverflowError):
        return "too large"
    text = str(err)
    if text == "math domain error":
        return "outside the function's domain"
    return text if len(text) <= 60 else text.split(":")[0]


def _round(x: Any, digits: int | None = None) -> Any:
    """`round(x)`, an int, or `round(x, digits)`, a float."""
    try:
        return round(x) if digits is None else round(float(x), digits)
    except (ValueError, OverflowError) as err:
        raise EvalError(f"round({shown(x)}): {err}") from None


def _int(x: Any) -> int:
    """`int(x)`: a float towards zero, a bool, or a string in decimal or with a 0x, 0o or 0b prefix."""
    try:
        if isinstance(x, str) and x.strip()[:2].lower() in ("0x", "0b", "0o"):
            return int(x.strip(), 0)
        return int(x)
    except (ValueError, OverflowError) as err:
        raise EvalError(f"int({shown(x)}): {_reason(err)}") from None


def _float(x: Any) -> float:
    """`float(x)` of a number, a bool or a string. A string's infinity or NaN (`"inf"`, `"nan"`,
    `"1e999"`) is refused, as arithmetic's is: no operation makes one (a clamp would take an
    infinite speed for full speed)."""
    try:
        value = float(x)
    except (ValueError, OverflowError) as err:
        raise EvalError(f"float({shown(x)}): {_reason(err)}") from None
    if not -FLOAT_MAX <= value <= FLOAT_MAX:  # (NaN is not within either)
        raise EvalError(f"float({shown(x)}): not a finite number")
    return value


def _clamp(x: Any, low: Any, high: Any) -> Any:
    """`clamp(x, low, high)`: x, limited to [low, high]."""
    return low if x < low else high if x > high else x  # noqa: FURB136 - a call of min() costs twice this


def _refusing(function: Callable[..., float]) -> Callable[..., float]:
    """A function of `math` whose domain or range error is an EvalError naming the call."""
    def checked(*args: Any) -> float:
        try:
            return function(*args)
        except (ValueError, OverflowError) as err:
            raise EvalError(f"{function.__name__}({', '.join(shown(a) for a in args)}): {_reason(err)}") from None

    return checked


_sqrt = _refusing(math.sqrt)
_sin = _refusing(math.sin)
_cos = _refusing(math.cos)
_atan2 = _refusing(math.atan2)
_hypot = _refusing(math.hypot)


# ---- strings and bytes -------------------------------------------------------------------------


def _byte(data: bytes, index: int) -> int:
    """`byte(b, i)`: byte i of bytes b, 0 first, as an int."""
    if not 0 <= index < len(data):
        raise EvalError(f"byte {index} of {len(data)} bytes: no such byte")
    return int(data[index])


def _concat(a: Any, b: Any) -> Any:
    """`a + b` of two strings or two bytes, at most MAX_TEXT long: no chain grows one without bound."""
    if len(a) + len(b) > MAX_TEXT:
        raise ValueError(f"string longer than {MAX_TEXT} characters" if isinstance(a, str)
                         else f"more than {MAX_TEXT} bytes")
    return a + b


def _hex(data: bytes) -> str:
    """`hex(b)`: the bytes as lowercase hex digits, two a byte: "0a1b"."""
    if 2 * len(data) > MAX_TEXT:
        raise ValueError(f"hex(): {len(data)} bytes make a string longer than {MAX_TEXT} characters")
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
    if 2 * len(data) > MAX_TEXT:
        raise ValueError(f"pack7(): {len(data)} bytes make more than {MAX_TEXT} bytes")
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


def _unhex(text: str) -> bytes:
    """`unhex(s)`: the bytes that hex digits spell, two a byte, either case ("0A1b" is b"\\x0a\\x1b");
    an odd count or any other character (a space too) is refused."""
    for i, ch in enumerate(text):
        if ch not in "0123456789abcdefABCDEF":
            raise ValueError(f"unhex(): character {i} is {shown(ch)}, not a hex digit")
    if len(text) % 2:
        raise ValueError(f"unhex(): an odd number of hex digits ({len(text)})")
    return bytes.fromhex(text)


def _upper(text: Any) -> Any:
    """`upper(s)`: a string, or bytes (ASCII letters only), in upper case; no longer than MAX_TEXT."""
    result = text.upper()
    if len(result) > MAX_TEXT:  # "ß" is "SS": a string may grow
        raise ValueError(f"upper(): the result is longer than {MAX_TEXT} characters")
    return result


def _integer(order: Literal["little", "big"]) -> Callable[..., int]:
    """`int_le(b)` or `int_be(b)` (by `order`): the int that bytes of any length up to
    MAX_INT_BYTES hold, unsigned, or two's complement with `int_le(b, True)`; no bytes are 0."""
    name = "int_le" if order == "little" else "int_be"

    def integer(data: bytes, signed: bool = False) -> int:
        if len(data) > MAX_INT_BYTES:
            raise ValueError(f"{name}(): {len(data)} bytes, more than {MAX_INT_BYTES} (a 64-bit int)")
        return int.from_bytes(data, order, signed=signed)

    integer.__name__ = name
    return integer


_int_le = _integer("little")
_int_be = _integer("big")


def _float_bytes(code: str, name: str) -> tuple[Callable[[Any], bytes], Callable[[bytes], float]]:
    """The pair `f32le(x)` (a number as the bytes of an IEEE 754 float, struct's `code`) and
    `from_f32le(b)` (those bytes back as a float; any other count of bytes is refused)."""
    layout = struct.Struct(code)
    size, bits = layout.size, 8 * layout.size

    def encoded(x: Any) -> bytes:
        try:
            return layout.pack(x)
        except (OverflowError, struct.error):
            raise EvalError(f"{name}({shown(x)}): too large for a {bits}-bit float") from None

    def decoded(data: bytes) -> float:
        if len(data) != size:
            raise ValueError(f"from_{name}(): {len(data)} bytes, not {size}")
        value: float = layout.unpack(data)[0]
        return value

    encoded.__name__, decoded.__name__ = name, "from_" + name
    return encoded, decoded


_f32le, _from_f32le = _float_bytes("<f", "f32le")
_f32be, _from_f32be = _float_bytes(">f", "f32be")
_f64le, _from_f64le = _float_bytes("<d", "f64le")
_f64be, _from_f64be = _float_bytes(">d", "f64be")


def _nibbles(value: int, count: int) -> bytes:
    """`nibbles(v, n)`: v spread over n bytes, 4 bits in each, the most significant first (VISCA's
    `0p 0q 0r 0s`): `nibbles(0x1234, 4)` is b"\\x01\\x02\\x03\\x04"; n is 1 to MAX_NIBBLES and v
    must fit in n nibbles."""
    if not 1 <= count <= MAX_NIBBLES:
        raise ValueError(f"nibbles(): {shown(count)} nibbles, not 1 to {MAX_NIBBLES}")
    if not 0 <= value < 1 << 4 * count:
        raise ValueError(f"nibbles(): {shown(value)} does not fit in {count} nibble{'s' if count != 1 else ''}")
    return bytes(value >> 4 * (count - 1 - i) & 0xF for i in range(count))


def _from_nibbles(data: bytes) -> int:
    """`from_nibbles(b)`: the int that bytes of one nibble each hold, the most significant first;
    a byte past 0x0f, or more than MAX_NIBBLES bytes, is refused."""
    if len(data) > MAX_NIBBLES:
        raise ValueError(f"from_nibbles(): {len(data)} bytes, more than {MAX_NIBBLES} nibbles (a 64-bit int)")
    value = 0
    for i, byte in enumerate(data):
        if byte > 0xF:
            raise ValueError(f"from_nibbles(): byte {i} is 0x{byte:02x}, not a nibble")
        value = value << 4 | byte
    return value


# ---- by the language's spelling: what the checker folds with and the reference interpreter calls ----

BINARY: dict[str, Callable[[Any, Any], Any]] = {
    "+": _plus,
    "-": _sub,
    "*": _mul,
    "/": _div,
    "//": _floordiv,
    "%": _mod,
    "**": _pow,
    "<<": _lshift,
    ">>": _rshift,
    "&": lambda a, b: a & b,
    "|": lambda a, b: a | b,
    "^": lambda a, b: a ^ b,
    "==": lambda a, b: a == b,
    "!=": lambda a, b: a != b,
    "<": lambda a, b: a < b,
    "<=": lambda a, b: a <= b,
    ">": lambda a, b: a > b,
    ">=": lambda a, b: a >= b,
}

UNARY: dict[str, Callable[[Any], Any]] = {
    "-": lambda a: -a,
    "+": lambda a: +a,
    "~": lambda a: ~a,
    "not": lambda a: not a,
}

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
    "sqrt": _sqrt,
    "sin": _sin,
    "cos": _cos,
    "atan2": _atan2,
    "hypot": _hypot,
    "len": len,
    "byte": _byte,
    "hex": _hex,
    "ascii": _ascii,
    "encode": _encode,
    "pack7": _pack7,
    "unpack7": _unpack7,
    "bitset": _bitset,
    "unhex": _unhex,
    "upper": _upper,
    "int_le": _int_le,
    "int_be": _int_be,
    "f32le": _f32le,
    "f32be": _f32be,
    "f64le": _f64le,
    "f64be": _f64be,
    "from_f32le": _from_f32le,
    "from_f32be": _from_f32be,
    "from_f64le": _from_f64le,
    "from_f64be": _from_f64be,
    "nibbles": _nibbles,
    "from_nibbles": _from_nibbles,
}


# ---- arrays and tables ----------------------------------------------------------------------------


class LookupMiss(ValueError):
    """A key a lookup table lacks: in a reply's post-actions, a reply the primitive cannot read."""


def lookup(table: str, entries: Mapping[Any, Any], key: Any) -> Any:
    """`table[key]` of a description's lookup table: a key it lacks is an error, never a default."""
    try:
        return entries[key]
    except (KeyError, TypeError):
        raise LookupMiss(f"table {table} has no entry for {key!r}") from None


def lookup_or(entries: Mapping[Any, Any], key: Any, default: Any) -> Any:
    """`TABLE.get(key, default)`: the table's value for the key, or the default where it has none
    (a driver writes `dict.get`, which computes the same)."""
    return entries.get(key, default)


def element(array: str, values: tuple[Any, ...], index: int) -> Any:
    """`array[index]`: an index outside the array is an error, never wrapped (`a[-1]` too)."""
    if not 0 <= index < len(values):
        raise ValueError(f"index {index} is outside {array}, which has {len(values)} values")
    return values[index]


def replaced(array: str, values: tuple[Any, ...], index: int, value: Any) -> tuple[Any, ...]:
    """The array with `values[index]` made `value` (`array[index] = value` in a post-action)."""
    element(array, values, index)
    if type(value) is int and not -MAX_INT <= value <= MAX_INT:
        raise ValueError(f"{array}[{index}] would be a {value.bit_length()}-bit integer; "
                         "integers are limited to 64 bits and a sign")
    return values[:index] + (value,) + values[index + 1 :]
