"""The expression helpers a generated driver may need, and the engine's text it carries.

`rdisc.emit.python` writes the helpers a description's expressions use, as they
are, after the engine's text (`engine_text`: its modules as marked sections), which every
driver carries.
"""

from __future__ import annotations

from pathlib import Path

from rdisc.semantics import operators

CARRIED = "strings and bytes"  # the helper that is the part of rdisc.semantics.operators drivers carry
_CARRIED_FROM = "_MAX_TEXT = "
_CARRIED_TO = "# ---- end of what drivers carry ----"


def carried_text() -> str:
    """The functions on strings and bytes of rdisc.semantics.operators, as written there: what
    a driver whose expressions use one carries, byte for byte."""
    text = Path(operators.__file__).read_text(encoding="utf-8")
    return text[text.index(_CARRIED_FROM) : text.index(_CARRIED_TO)].rstrip("\n")


# Expression helpers: each one the same operation as rdisc.semantics.operators
# defines, written out so that the driver needs nothing of rdisc. Only the
# helpers a description uses are written into its driver.
HELPERS = {
    "_add": '''\
def _add(a: float, b: float) -> float:
    """a + b; a float result too large to represent is an error, not inf."""
    result = a + b
    if result - result != 0.0 and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise ArithmeticError("the result is too large for a float")
    return result''',
    "_sub": '''\
def _sub(a: float, b: float) -> float:
    """a - b; a float result too large to represent is an error, not inf."""
    result = a - b
    if result - result != 0.0 and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise ArithmeticError("the result is too large for a float")
    return result''',
    "_mul": '''\
def _mul(a: float, b: float) -> float:
    """a * b; a float result too large to represent is an error, not inf."""
    result = a * b
    if result - result != 0.0 and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise ArithmeticError("the result is too large for a float")
    return result''',
    "_div": '''\
def _div(a: float, b: float) -> float:
    """a / b; division by zero, or a result too large to represent, is an error."""
    result = a / b
    if result - result != 0.0 and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise ArithmeticError("the result is too large for a float")
    return result''',
    CARRIED: carried_text(),
    "_pow": '''\
def _pow(a: Any, b: Any) -> Any:
    """a ** b, bounded: an int result stays within 4096 bits, a float one must be real and finite."""
    if isinstance(a, int) and isinstance(b, int):
        if b < 0:
            raise ArithmeticError(f"negative integer exponent {b}: write a float base")
        if abs(a) > 1 and b * max(1, abs(a).bit_length()) > 4096:
            raise ArithmeticError(f"{a} ** {b} is too large (results are limited to 4096 bits)")
        return a**b
    try:
        result = float(a) ** float(b)
    except OverflowError:
        raise ArithmeticError(f"{a} ** {b} is too large for a float") from None
    except ZeroDivisionError:
        raise ArithmeticError(f"{a} ** {b}: zero to a negative power") from None
    if isinstance(result, float):
        return result
    raise ArithmeticError(f"{a} ** {b} has no real value")  # a complex result''',
    "_imul": '''\
def _imul(a: int, b: int) -> int:
    """a * b for ints, bounded: results stay within 4096 bits."""
    result = a * b
    if result.bit_length() > 4096:
        raise ArithmeticError(f"{a} * {b} is too large (results are limited to 4096 bits)")
    return result''',
    "_lshift": '''\
def _lshift(a: int, b: int) -> int:
    """a << b, bounded: results stay below 4096 bits."""
    if b < 0:
        raise ArithmeticError(f"negative shift count {b}")
    if b > 1024 or a.bit_length() + b > 4096:
        raise ArithmeticError(f"{a} << {b} is too large (results are limited to 4096 bits)")
    return a << b''',
    "_clamp": '''\
def _clamp(x: Any, low: Any, high: Any) -> Any:
    """x, limited to [low, high]."""
    if x < low:
        return low
    if x > high:
        return high
    return x''',
    "_int": '''\
def _int(text: str) -> int:
    """The int a string spells, in decimal or with a 0x, 0o or 0b prefix."""
    stripped = text.strip()
    return int(stripped, 0) if stripped[:2].lower() in ("0x", "0b", "0o") else int(text)''',
    "_byte": '''\
def _byte(data: bytes, index: int) -> int:
    """`byte(b, i)`: byte i of bytes b, 0 first."""
    if not 0 <= index < len(data):
        raise IndexError(f"byte {index} of {len(data)} bytes: no such byte")
    return data[index]''',
}


def engine_text() -> str:
    """The engine as every driver carries it: the modules of rdisc.engine as marked sections, in
    their listed order, each byte for byte from the end of its imports (`rdisc.engine.carry`)."""
    from rdisc.engine import carry

    return carry.text()
