"""The methods of the frozen dataclasses of rdisc/semantics/model_layouts.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import DEFAULT, MISSING, FieldSpec, Written, classes, field

if TYPE_CHECKING:
    from typing import Any

__all__ = ["dataclass", "field"]

# Each field's setter, `_set_<class>_<field>(instance, value)`: its slot's own `__set__`, bound by
# rdisc.frozen when it makes the class (a third faster than object.__setattr__ with the field's name).
_unbound: Any = None


_set_Slot_code = _unbound
_set_Slot_type = _unbound
_set_Slot_low = _unbound
_set_Slot_high = _unbound
_set_Slot_repeat = _unbound
_set_Slot_bits = _unbound
_set_Slot_size = _unbound


def _init_Slot(
    self: Any,
    code: Any,
    type: Any,
    low: Any = DEFAULT,
    high: Any = DEFAULT,
    repeat: Any = DEFAULT,
    bits: Any = DEFAULT,
    size: Any = DEFAULT,
) -> None:
    _set_Slot_code(self, code)
    _set_Slot_type(self, type)
    _set_Slot_low(self, low)
    _set_Slot_high(self, high)
    _set_Slot_repeat(self, repeat)
    _set_Slot_bits(self, bits)
    _set_Slot_size(self, size)


def _repr_Slot(self: Any) -> str:
    return f"{self.__class__.__qualname__}(code={self.code!r}, type={self.type!r}, low={self.low!r}, high={self.high!r}, repeat={self.repeat!r}, bits={self.bits!r}, size={self.size!r})"


def _eq_Slot(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.code,
            self.type,
            self.low,
            self.high,
            self.repeat,
            self.bits,
        ) == (
            other.code,
            other.type,
            other.low,
            other.high,
            other.repeat,
            other.bits,
        )
    return NotImplemented


def _hash_Slot(self: Any) -> int:
    return hash((self.code, self.type, self.low, self.high, self.repeat, self.bits))


_set_Varying_head = _unbound
_set_Varying_unit = _unbound
_set_Varying_tail = _unbound
_set_Varying_count_at = _unbound
_set_Varying_count_high = _unbound
_set_Varying_count_code = _unbound
_set_Varying_count_slot = _unbound
_set_Varying_unit_size = _unbound
_set_Varying_tail_size = _unbound
_set_Varying_count_size = _unbound


def _init_Varying(
    self: Any,
    head: Any,
    unit: Any,
    tail: Any,
    count_at: Any,
    count_high: Any = DEFAULT,
    count_code: Any = DEFAULT,
    count_slot: Any = DEFAULT,
    unit_size: Any = DEFAULT,
    tail_size: Any = DEFAULT,
    count_size: Any = DEFAULT,
) -> None:
    _set_Varying_head(self, head)
    _set_Varying_unit(self, unit)
    _set_Varying_tail(self, tail)
    _set_Varying_count_at(self, count_at)
    _set_Varying_count_high(self, count_high)
    _set_Varying_count_code(self, count_code)
    _set_Varying_count_slot(self, count_slot)
    _set_Varying_unit_size(self, unit_size)
    _set_Varying_tail_size(self, tail_size)
    _set_Varying_count_size(self, count_size)


def _repr_Varying(self: Any) -> str:
    return f"{self.__class__.__qualname__}(head={self.head!r}, unit={self.unit!r}, tail={self.tail!r}, count_at={self.count_at!r}, count_high={self.count_high!r}, count_code={self.count_code!r}, count_slot={self.count_slot!r}, unit_size={self.unit_size!r}, tail_size={self.tail_size!r}, count_size={self.count_size!r})"


def _eq_Varying(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.head,
            self.unit,
            self.tail,
            self.count_at,
            self.count_high,
            self.count_code,
            self.count_slot,
        ) == (
            other.head,
            other.unit,
            other.tail,
            other.count_at,
            other.count_high,
            other.count_code,
            other.count_slot,
        )
    return NotImplemented


def _hash_Varying(self: Any) -> int:
    return hash((
        self.head,
        self.unit,
        self.tail,
        self.count_at,
        self.count_high,
        self.count_code,
        self.count_slot,
    ))


_set_StructLayout_slots = _unbound
_set_StructLayout_size = _unbound
_set_StructLayout_native = _unbound
_set_StructLayout_rest = _unbound
_set_StructLayout_fixed = _unbound
_set_StructLayout_groups = _unbound
_set_StructLayout_varying = _unbound
_set_StructLayout_bits = _unbound
_set_StructLayout_order = _unbound
_set_StructLayout_rooms = _unbound
_set_StructLayout_width = _unbound


def _init_StructLayout(
    self: Any,
    slots: Any,
    size: Any,
    native: Any,
    rest: Any = DEFAULT,
    fixed: Any = DEFAULT,
    groups: Any = DEFAULT,
    varying: Any = DEFAULT,
    bits: Any = DEFAULT,
    order: Any = DEFAULT,
    rooms: Any = DEFAULT,
    width: Any = DEFAULT,
) -> None:
    _set_StructLayout_slots(self, slots)
    _set_StructLayout_size(self, size)
    _set_StructLayout_native(self, native)
    _set_StructLayout_rest(self, rest)
    _set_StructLayout_fixed(self, fixed)
    _set_StructLayout_groups(self, groups)
    _set_StructLayout_varying(self, varying)
    _set_StructLayout_bits(self, bits)
    _set_StructLayout_order(self, order)
    _set_StructLayout_rooms(self, rooms)
    _set_StructLayout_width(self, width)


def _repr_StructLayout(self: Any) -> str:
    return f"{self.__class__.__qualname__}(slots={self.slots!r}, size={self.size!r}, native={self.native!r}, rest={self.rest!r}, fixed={self.fixed!r}, groups={self.groups!r}, varying={self.varying!r}, bits={self.bits!r}, order={self.order!r}, rooms={self.rooms!r}, width={self.width!r})"


def _eq_StructLayout(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.slots,
            self.size,
            self.native,
            self.rest,
            self.fixed,
            self.groups,
            self.varying,
            self.bits,
            self.order,
            self.rooms,
            self.width,
        ) == (
            other.slots,
            other.size,
            other.native,
            other.rest,
            other.fixed,
            other.groups,
            other.varying,
            other.bits,
            other.order,
            other.rooms,
            other.width,
        )
    return NotImplemented


def _hash_StructLayout(self: Any) -> int:
    return hash((
        self.slots,
        self.size,
        self.native,
        self.rest,
        self.fixed,
        self.groups,
        self.varying,
        self.bits,
        self.order,
        self.rooms,
        self.width,
    ))


_set_Pack_format = _set_Pack_layout = _set_Pack_grouped = _unbound


def _init_Pack(self: Any, format: Any, layout: Any, grouped: Any = DEFAULT) -> None:
    _set_Pack_format(self, format)
    _set_Pack_layout(self, layout)
    _set_Pack_grouped(self, grouped)


def _repr_Pack(self: Any) -> str:
    return f"{self.__class__.__qualname__}(format={self.format!r}, grouped={self.grouped!r})"


def _eq_Pack(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.format, self.grouped) == (other.format, other.grouped)
    return NotImplemented


def _hash_Pack(self: Any) -> int:
    return hash((self.format, self.grouped))


_set_Format_template = _unbound


def _init_Format(self: Any, template: Any) -> None:
    _set_Format_template(self, template)


def _repr_Format(self: Any) -> str:
    return f"{self.__class__.__qualname__}(template={self.template!r})"


def _eq_Format(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.template,) == (other.template,)
    return NotImplemented


def _hash_Format(self: Any) -> int:
    return hash((self.template,))


_set_Unpack_format = _set_Unpack_layout = _set_Unpack_until = _unbound


def _init_Unpack(self: Any, format: Any, layout: Any, until: Any = DEFAULT) -> None:
    _set_Unpack_format(self, format)
    _set_Unpack_layout(self, layout)
    _set_Unpack_until(self, until)


def _repr_Unpack(self: Any) -> str:
    return f"{self.__class__.__qualname__}(format={self.format!r}, until={self.until!r})"


def _eq_Unpack(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.format, self.until) == (other.format, other.until)
    return NotImplemented


def _hash_Unpack(self: Any) -> int:
    return hash((self.format, self.until))


_set_Regex_pattern = _unbound


def _init_Regex(self: Any, pattern: Any) -> None:
    _set_Regex_pattern(self, pattern)


def _repr_Regex(self: Any) -> str:
    return f"{self.__class__.__qualname__}(pattern={self.pattern!r})"


def _eq_Regex(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.pattern,) == (other.pattern,)
    return NotImplemented


def _hash_Regex(self: Any) -> int:
    return hash((self.pattern,))


_set_PostAction_target = _set_PostAction_value = _set_PostAction_span = _set_PostAction_when = _unbound


def _init_PostAction(self: Any, target: Any, value: Any, span: Any = DEFAULT, when: Any = DEFAULT) -> None:
    _set_PostAction_target(self, target)
    _set_PostAction_value(self, value)
    _set_PostAction_span(self, span)
    _set_PostAction_when(self, when)


def _repr_PostAction(self: Any) -> str:
    return f"{self.__class__.__qualname__}(target={self.target!r}, value={self.value!r}, when={self.when!r})"


def _eq_PostAction(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.target, self.value, self.when) == (other.target, other.value, other.when)
    return NotImplemented


def _hash_PostAction(self: Any) -> int:
    return hash((self.target, self.value, self.when))


_set_LineLevel_line = _set_LineLevel_value = _set_LineLevel_span = _unbound


def _init_LineLevel(self: Any, line: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_LineLevel_line(self, line)
    _set_LineLevel_value(self, value)
    _set_LineLevel_span(self, span)


def _repr_LineLevel(self: Any) -> str:
    return f"{self.__class__.__qualname__}(line={self.line!r}, value={self.value!r})"


def _eq_LineLevel(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.line, self.value) == (other.line, other.value)
    return NotImplemented


def _hash_LineLevel(self: Any) -> int:
    return hash((self.line, self.value))


WRITTEN: dict[str, Written] = {
    "Slot": Written(
        (
            ("code", MISSING),
            ("type", MISSING),
            ("low", DEFAULT),
            ("high", DEFAULT),
            ("repeat", DEFAULT),
            ("bits", DEFAULT),
            ("size", FieldSpec(0, MISSING, False, True)),
        ),
        {"__init__": _init_Slot, "__repr__": _repr_Slot, "__eq__": _eq_Slot, "__hash__": _hash_Slot},
    ),
    "Varying": Written(
        (
            ("head", MISSING),
            ("unit", MISSING),
            ("tail", MISSING),
            ("count_at", MISSING),
            ("count_high", DEFAULT),
            ("count_code", DEFAULT),
            ("count_slot", DEFAULT),
            ("unit_size", FieldSpec(0, MISSING, False, True)),
            ("tail_size", FieldSpec(0, MISSING, False, True)),
            ("count_size", FieldSpec(0, MISSING, False, True)),
        ),
        {
            "__init__": _init_Varying,
            "__repr__": _repr_Varying,
            "__eq__": _eq_Varying,
            "__hash__": _hash_Varying,
        },
    ),
    "StructLayout": Written(
        (
            ("slots", MISSING),
            ("size", MISSING),
            ("native", MISSING),
            ("rest", DEFAULT),
            ("fixed", DEFAULT),
            ("groups", DEFAULT),
            ("varying", DEFAULT),
            ("bits", DEFAULT),
            ("order", DEFAULT),
            ("rooms", DEFAULT),
            ("width", DEFAULT),
        ),
        {
            "__init__": _init_StructLayout,
            "__repr__": _repr_StructLayout,
            "__eq__": _eq_StructLayout,
            "__hash__": _hash_StructLayout,
        },
    ),
    "Pack": Written(
        (("format", MISSING), ("layout", FieldSpec(MISSING, MISSING, False, False)), ("grouped", DEFAULT)),
        {"__init__": _init_Pack, "__repr__": _repr_Pack, "__eq__": _eq_Pack, "__hash__": _hash_Pack},
    ),
    "Format": Written(
        (("template", MISSING),),
        {"__init__": _init_Format, "__repr__": _repr_Format, "__eq__": _eq_Format, "__hash__": _hash_Format},
    ),
    "Unpack": Written(
        (("format", MISSING), ("layout", FieldSpec(MISSING, MISSING, False, False)), ("until", DEFAULT)),
        {"__init__": _init_Unpack, "__repr__": _repr_Unpack, "__eq__": _eq_Unpack, "__hash__": _hash_Unpack},
    ),
    "Regex": Written(
        (("pattern", MISSING),),
        {"__init__": _init_Regex, "__repr__": _repr_Regex, "__eq__": _eq_Regex, "__hash__": _hash_Regex},
    ),
    "PostAction": Written(
        (
            ("target", MISSING),
            ("value", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("when", DEFAULT),
        ),
        {
            "__init__": _init_PostAction,
            "__repr__": _repr_PostAction,
            "__eq__": _eq_PostAction,
            "__hash__": _hash_PostAction,
        },
    ),
    "LineLevel": Written(
        (("line", MISSING), ("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_LineLevel,
            "__repr__": _repr_LineLevel,
            "__eq__": _eq_LineLevel,
            "__hash__": _hash_LineLevel,
        },
    ),
}
dataclass = classes(WRITTEN)
