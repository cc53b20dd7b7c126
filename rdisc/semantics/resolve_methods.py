"""The methods of the frozen dataclasses of rdisc/semantics/resolve.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import DEFAULT, MISSING, Written, classes, field

if TYPE_CHECKING:
    from typing import Any

__all__ = ["dataclass", "field"]

# Each field's setter, `_set_<class>_<field>(instance, value)`: its slot's own `__set__`, bound by
# rdisc.frozen when it makes the class (a third faster than object.__setattr__ with the field's name).
_unbound: Any = None


_set_Unit_module = _set_Unit_main = _set_Unit_standard = _unbound


def _init_Unit(self: Any, module: Any, main: Any = DEFAULT, standard: Any = DEFAULT) -> None:
    _set_Unit_module(self, module)
    _set_Unit_main(self, main)
    _set_Unit_standard(self, standard)


def _repr_Unit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(module={self.module!r}, main={self.main!r}, standard={self.standard!r})"


def _eq_Unit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.module, self.main, self.standard) == (other.module, other.main, other.standard)
    return NotImplemented


def _hash_Unit(self: Any) -> int:
    return hash((self.module, self.main, self.standard))


WRITTEN: dict[str, Written] = {
    "Unit": Written(
        (("module", MISSING), ("main", DEFAULT), ("standard", DEFAULT)),
        {"__init__": _init_Unit, "__repr__": _repr_Unit, "__eq__": _eq_Unit, "__hash__": _hash_Unit},
    ),
}
dataclass = classes(WRITTEN)
