"""The methods of the frozen dataclasses of rdisc/semantics/formats.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_FormatField_spec = _set_FormatField_offset = _unbound


def _init_FormatField(self: Any, spec: Any, offset: Any) -> None:
    _set_FormatField_spec(self, spec)
    _set_FormatField_offset(self, offset)


def _repr_FormatField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(spec={self.spec!r}, offset={self.offset!r})"


def _eq_FormatField(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.spec, self.offset) == (other.spec, other.offset)
    return NotImplemented


def _hash_FormatField(self: Any) -> int:
    return hash((self.spec, self.offset))


WRITTEN: dict[str, Written] = {
    "FormatField": Written(
        (("spec", MISSING), ("offset", MISSING)),
        {
            "__init__": _init_FormatField,
            "__repr__": _repr_FormatField,
            "__eq__": _eq_FormatField,
            "__hash__": _hash_FormatField,
        },
    ),
}
dataclass = classes(WRITTEN)
