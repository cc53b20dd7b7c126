"""The methods of the frozen dataclasses of rdisc/semantics/types.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_Env_names = _unbound
_set_Env_where = _unbound
_set_Env_sees = _unbound
_set_Env_reply = _unbound
_set_Env_reply_note = _unbound
_set_Env_reply_known = _unbound
_set_Env_setting_note = _unbound


def _init_Env(
    self: Any,
    names: Any,
    where: Any,
    sees: Any,
    reply: Any = DEFAULT,
    reply_note: Any = DEFAULT,
    reply_known: Any = DEFAULT,
    setting_note: Any = DEFAULT,
) -> None:
    _set_Env_names(self, names)
    _set_Env_where(self, where)
    _set_Env_sees(self, sees)
    _set_Env_reply(self, reply)
    _set_Env_reply_note(self, reply_note)
    _set_Env_reply_known(self, reply_known)
    _set_Env_setting_note(self, setting_note)


def _repr_Env(self: Any) -> str:
    return f"{self.__class__.__qualname__}(names={self.names!r}, where={self.where!r}, sees={self.sees!r}, reply={self.reply!r}, reply_note={self.reply_note!r}, reply_known={self.reply_known!r}, setting_note={self.setting_note!r})"


def _eq_Env(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.names,
            self.where,
            self.sees,
            self.reply,
            self.reply_note,
            self.reply_known,
            self.setting_note,
        ) == (
            other.names,
            other.where,
            other.sees,
            other.reply,
            other.reply_note,
            other.reply_known,
            other.setting_note,
        )
    return NotImplemented


def _hash_Env(self: Any) -> int:
    return hash((
        self.names,
        self.where,
        self.sees,
        self.reply,
        self.reply_note,
        self.reply_known,
        self.setting_note,
    ))


WRITTEN: dict[str, Written] = {
    "Env": Written(
        (
            ("names", MISSING),
            ("where", MISSING),
            ("sees", MISSING),
            ("reply", DEFAULT),
            ("reply_note", DEFAULT),
            ("reply_known", DEFAULT),
            ("setting_note", DEFAULT),
        ),
        {"__init__": _init_Env, "__repr__": _repr_Env, "__eq__": _eq_Env, "__hash__": _hash_Env},
    ),
}
dataclass = classes(WRITTEN)
