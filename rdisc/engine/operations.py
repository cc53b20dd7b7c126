"""Operations on values and their named limits, the same wherever a description runs."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

# The engine's: the named limits, and an element of an array read or replaced.

MAX_INT = (1 << 64) - 1  # the largest int a state variable holds (and its negation the smallest)
MAX_ARRAY = 1024  # the most elements an array holds, and rounds a group repeated as a message says
MAX_LINE = 4096
"""Bytes of one reply line, terminator included."""

EVAL_ERRORS = (ArithmeticError, ValueError, TypeError, IndexError, OverflowError)
"""What evaluating an expression can raise; each becomes an RdisValueError of the element at fault."""


def lookup(table: str, entries: Mapping[Any, Any], key: Any) -> Any:
    """`table[key]` of a description's lookup table: a key it lacks is an error, never a default."""
    try:
        return entries[key]
    except (KeyError, TypeError):
        raise ValueError(f"table {table} has no entry for {key!r}") from None


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
