"""The methods of the frozen dataclasses of rdisc/source.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import MISSING, Written, classes, field

if TYPE_CHECKING:
    from typing import Any

__all__ = ["dataclass", "field"]

# Each field's setter, `_set_<class>_<field>(instance, value)`: its slot's own `__set__`, bound by
# rdisc.frozen when it makes the class (a third faster than object.__setattr__ with the field's name).
_unbound: Any = None


_set_Span_path = _set_Span_start = _set_Span_end = _unbound


def _init_Span(self: Any, path: Any, start: Any, end: Any) -> None:
    _set_Span_path(self, path)
    _set_Span_start(self, start)
    _set_Span_end(self, end)


def _repr_Span(self: Any) -> str:
    return f"{self.__class__.__qualname__}(path={self.path!r}, start={self.start!r}, end={self.end!r})"


def _eq_Span(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.path, self.start, self.end) == (other.path, other.start, other.end)
    return NotImplemented


def _hash_Span(self: Any) -> int:
    return hash((self.path, self.start, self.end))


_set_Position_line = _set_Position_column = _set_Position_utf16_column = _unbound


def _init_Position(self: Any, line: Any, column: Any, utf16_column: Any) -> None:
    _set_Position_line(self, line)
    _set_Position_column(self, column)
    _set_Position_utf16_column(self, utf16_column)


def _repr_Position(self: Any) -> str:
    return f"{self.__class__.__qualname__}(line={self.line!r}, column={self.column!r}, utf16_column={self.utf16_column!r})"


def _eq_Position(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.line, self.column, self.utf16_column) == (other.line, other.column, other.utf16_column)
    return NotImplemented


def _hash_Position(self: Any) -> int:
    return hash((self.line, self.column, self.utf16_column))


WRITTEN: dict[str, Written] = {
    "Span": Written(
        (("path", MISSING), ("start", MISSING), ("end", MISSING)),
        {"__init__": _init_Span, "__repr__": _repr_Span, "__eq__": _eq_Span, "__hash__": _hash_Span},
    ),
    "Position": Written(
        (("line", MISSING), ("column", MISSING), ("utf16_column", MISSING)),
        {
            "__init__": _init_Position,
            "__repr__": _repr_Position,
            "__eq__": _eq_Position,
            "__hash__": _hash_Position,
        },
    ),
}
dataclass = classes(WRITTEN)
