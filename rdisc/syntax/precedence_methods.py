"""The methods of the frozen dataclasses of rdisc/syntax/precedence.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_Operator_spelling = _set_Operator_level = _set_Operator_operands = _unbound


def _init_Operator(self: Any, spelling: Any, level: Any, operands: Any) -> None:
    _set_Operator_spelling(self, spelling)
    _set_Operator_level(self, level)
    _set_Operator_operands(self, operands)


def _repr_Operator(self: Any) -> str:
    return f"{self.__class__.__qualname__}(spelling={self.spelling!r}, level={self.level!r}, operands={self.operands!r})"


def _eq_Operator(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.spelling, self.level, self.operands) == (other.spelling, other.level, other.operands)
    return NotImplemented


def _hash_Operator(self: Any) -> int:
    return hash((self.spelling, self.level, self.operands))


_set_Printed_text = _set_Printed_level = _unbound


def _init_Printed(self: Any, text: Any, level: Any) -> None:
    _set_Printed_text(self, text)
    _set_Printed_level(self, level)


def _repr_Printed(self: Any) -> str:
    return f"{self.__class__.__qualname__}(text={self.text!r}, level={self.level!r})"


def _eq_Printed(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.text, self.level) == (other.text, other.level)
    return NotImplemented


def _hash_Printed(self: Any) -> int:
    return hash((self.text, self.level))


WRITTEN: dict[str, Written] = {
    "Operator": Written(
        (("spelling", MISSING), ("level", MISSING), ("operands", MISSING)),
        {
            "__init__": _init_Operator,
            "__repr__": _repr_Operator,
            "__eq__": _eq_Operator,
            "__hash__": _hash_Operator,
        },
    ),
    "Printed": Written(
        (("text", MISSING), ("level", MISSING)),
        {
            "__init__": _init_Printed,
            "__repr__": _repr_Printed,
            "__eq__": _eq_Printed,
            "__hash__": _hash_Printed,
        },
    ),
}
dataclass = classes(WRITTEN)
