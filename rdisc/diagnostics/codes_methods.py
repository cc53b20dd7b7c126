"""The methods of the frozen dataclasses of rdisc/diagnostics/codes.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_Code_id = _set_Code_name = _set_Code_explanation = _unbound


def _init_Code(self: Any, id: Any, name: Any, explanation: Any) -> None:
    _set_Code_id(self, id)
    _set_Code_name(self, name)
    _set_Code_explanation(self, explanation)


def _repr_Code(self: Any) -> str:
    return f"{self.__class__.__qualname__}(id={self.id!r}, name={self.name!r}, explanation={self.explanation!r})"


def _eq_Code(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.id, self.name, self.explanation) == (other.id, other.name, other.explanation)
    return NotImplemented


def _hash_Code(self: Any) -> int:
    return hash((self.id, self.name, self.explanation))


WRITTEN: dict[str, Written] = {
    "Code": Written(
        (("id", MISSING), ("name", MISSING), ("explanation", MISSING)),
        {"__init__": _init_Code, "__repr__": _repr_Code, "__eq__": _eq_Code, "__hash__": _hash_Code},
    ),
}
dataclass = classes(WRITTEN)
