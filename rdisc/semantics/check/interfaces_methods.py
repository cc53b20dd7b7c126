"""The methods of the frozen dataclasses of rdisc/semantics/check/interfaces.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from typing import Any

from rdisc.frozen import MISSING, Written, classes, field

__all__ = ["dataclass", "field"]

_set = object.__setattr__


def _init__Unrolling(
    self: Any,
    decl: Any,
    env: Any,
    interface_params: Any,
    primitives: Any,
    calls: Any,
) -> None:
    _set(self, "decl", decl)
    _set(self, "env", env)
    _set(self, "interface_params", interface_params)
    _set(self, "primitives", primitives)
    _set(self, "calls", calls)


def _repr__Unrolling(self: Any) -> str:
    return f"{self.__class__.__qualname__}(decl={self.decl!r}, env={self.env!r}, interface_params={self.interface_params!r}, primitives={self.primitives!r}, calls={self.calls!r})"


def _eq__Unrolling(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.decl,
            self.env,
            self.interface_params,
            self.primitives,
            self.calls,
        ) == (
            other.decl,
            other.env,
            other.interface_params,
            other.primitives,
            other.calls,
        )
    return NotImplemented


def _hash__Unrolling(self: Any) -> int:
    return hash((self.decl, self.env, self.interface_params, self.primitives, self.calls))


WRITTEN: dict[str, Written] = {
    "_Unrolling": Written(
        (
            ("decl", MISSING),
            ("env", MISSING),
            ("interface_params", MISSING),
            ("primitives", MISSING),
            ("calls", MISSING),
        ),
        {
            "__init__": _init__Unrolling,
            "__repr__": _repr__Unrolling,
            "__eq__": _eq__Unrolling,
            "__hash__": _hash__Unrolling,
        },
    ),
}
dataclass = classes(WRITTEN)
