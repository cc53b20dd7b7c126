"""The methods of the frozen dataclasses of rdisc/syntax/ast_frames.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_FrameBytes_role = _set_FrameBytes_value = _set_FrameBytes_span = _unbound


def _init_FrameBytes(self: Any, role: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_FrameBytes_role(self, role)
    _set_FrameBytes_value(self, value)
    _set_FrameBytes_span(self, span)


def _repr_FrameBytes(self: Any) -> str:
    return f"{self.__class__.__qualname__}(role={self.role!r}, value={self.value!r})"


def _eq_FrameBytes(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.role, self.value) == (other.role, other.value)
    return NotImplemented


def _hash_FrameBytes(self: Any) -> int:
    return hash((self.role, self.value))


_set_FrameField_name = _set_FrameField_format = _set_FrameField_value = _set_FrameField_span = _unbound


def _init_FrameField(self: Any, name: Any, format: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_FrameField_name(self, name)
    _set_FrameField_format(self, format)
    _set_FrameField_value(self, value)
    _set_FrameField_span(self, span)


def _repr_FrameField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, format={self.format!r}, value={self.value!r})"


def _eq_FrameField(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.format, self.value) == (other.name, other.format, other.value)
    return NotImplemented


def _hash_FrameField(self: Any) -> int:
    return hash((self.name, self.format, self.value))


_set_FrameLength_format = _set_FrameLength_adjust = _set_FrameLength_span = _unbound


def _init_FrameLength(self: Any, format: Any, adjust: Any, span: Any = DEFAULT) -> None:
    _set_FrameLength_format(self, format)
    _set_FrameLength_adjust(self, adjust)
    _set_FrameLength_span(self, span)


def _repr_FrameLength(self: Any) -> str:
    return f"{self.__class__.__qualname__}(format={self.format!r}, adjust={self.adjust!r})"


def _eq_FrameLength(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.format, self.adjust) == (other.format, other.adjust)
    return NotImplemented


def _hash_FrameLength(self: Any) -> int:
    return hash((self.format, self.adjust))


_set_FramePayload_span = _set_FramePayload_trimmed = _unbound


def _init_FramePayload(self: Any, span: Any = DEFAULT, trimmed: Any = DEFAULT) -> None:
    _set_FramePayload_span(self, span)
    _set_FramePayload_trimmed(self, trimmed)


def _repr_FramePayload(self: Any) -> str:
    return f"{self.__class__.__qualname__}(trimmed={self.trimmed!r})"


def _eq_FramePayload(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.trimmed,) == (other.trimmed,)
    return NotImplemented


def _hash_FramePayload(self: Any) -> int:
    return hash((self.trimmed,))


_set_ChecksumOption_word = _unbound
_set_ChecksumOption_value = _unbound
_set_ChecksumOption_over = _unbound
_set_ChecksumOption_span = _unbound


def _init_ChecksumOption(
    self: Any,
    word: Any,
    value: Any = DEFAULT,
    over: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_ChecksumOption_word(self, word)
    _set_ChecksumOption_value(self, value)
    _set_ChecksumOption_over(self, over)
    _set_ChecksumOption_span(self, span)


def _repr_ChecksumOption(self: Any) -> str:
    return f"{self.__class__.__qualname__}(word={self.word!r}, value={self.value!r}, over={self.over!r})"


def _eq_ChecksumOption(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.word, self.value, self.over) == (other.word, other.value, other.over)
    return NotImplemented


def _hash_ChecksumOption(self: Any) -> int:
    return hash((self.word, self.value, self.over))


_set_FrameChecksum_algorithm = _unbound
_set_FrameChecksum_format = _unbound
_set_FrameChecksum_options = _unbound
_set_FrameChecksum_span = _unbound


def _init_FrameChecksum(self: Any, algorithm: Any, format: Any, options: Any, span: Any = DEFAULT) -> None:
    _set_FrameChecksum_algorithm(self, algorithm)
    _set_FrameChecksum_format(self, format)
    _set_FrameChecksum_options(self, options)
    _set_FrameChecksum_span(self, span)


def _repr_FrameChecksum(self: Any) -> str:
    return f"{self.__class__.__qualname__}(algorithm={self.algorithm!r}, format={self.format!r}, options={self.options!r})"


def _eq_FrameChecksum(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.algorithm, self.format, self.options) == (other.algorithm, other.format, other.options)
    return NotImplemented


def _hash_FrameChecksum(self: Any) -> int:
    return hash((self.algorithm, self.format, self.options))


_set_FrameOptional_parts = _set_FrameOptional_span = _unbound


def _init_FrameOptional(self: Any, parts: Any, span: Any = DEFAULT) -> None:
    _set_FrameOptional_parts(self, parts)
    _set_FrameOptional_span(self, span)


def _repr_FrameOptional(self: Any) -> str:
    return f"{self.__class__.__qualname__}(parts={self.parts!r})"


def _eq_FrameOptional(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.parts,) == (other.parts,)
    return NotImplemented


def _hash_FrameOptional(self: Any) -> int:
    return hash((self.parts,))


_set_FrameEither_alternatives = _set_FrameEither_span = _set_FrameEither_conditions = _unbound


def _init_FrameEither(self: Any, alternatives: Any, span: Any = DEFAULT, conditions: Any = DEFAULT) -> None:
    _set_FrameEither_alternatives(self, alternatives)
    _set_FrameEither_span(self, span)
    _set_FrameEither_conditions(self, conditions)


def _repr_FrameEither(self: Any) -> str:
    return f"{self.__class__.__qualname__}(alternatives={self.alternatives!r}, conditions={self.conditions!r})"


def _eq_FrameEither(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.alternatives, self.conditions) == (other.alternatives, other.conditions)
    return NotImplemented


def _hash_FrameEither(self: Any) -> int:
    return hash((self.alternatives, self.conditions))


_set_FrameBitField_name = _unbound
_set_FrameBitField_width = _unbound
_set_FrameBitField_value = _unbound
_set_FrameBitField_adjust = _unbound
_set_FrameBitField_span = _unbound


def _init_FrameBitField(
    self: Any,
    name: Any,
    width: Any,
    value: Any,
    adjust: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_FrameBitField_name(self, name)
    _set_FrameBitField_width(self, width)
    _set_FrameBitField_value(self, value)
    _set_FrameBitField_adjust(self, adjust)
    _set_FrameBitField_span(self, span)


def _repr_FrameBitField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, width={self.width!r}, value={self.value!r}, adjust={self.adjust!r})"


def _eq_FrameBitField(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.width,
            self.value,
            self.adjust,
        ) == (
            other.name,
            other.width,
            other.value,
            other.adjust,
        )
    return NotImplemented


def _hash_FrameBitField(self: Any) -> int:
    return hash((self.name, self.width, self.value, self.adjust))


_set_FrameBits_format = _set_FrameBits_fields = _set_FrameBits_span = _unbound


def _init_FrameBits(self: Any, format: Any, fields: Any, span: Any = DEFAULT) -> None:
    _set_FrameBits_format(self, format)
    _set_FrameBits_fields(self, fields)
    _set_FrameBits_span(self, span)


def _repr_FrameBits(self: Any) -> str:
    return f"{self.__class__.__qualname__}(format={self.format!r}, fields={self.fields!r})"


def _eq_FrameBits(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.format, self.fields) == (other.format, other.fields)
    return NotImplemented


def _hash_FrameBits(self: Any) -> int:
    return hash((self.format, self.fields))


_set_FrameSide_side = _set_FrameSide_parts = _set_FrameSide_span = _unbound


def _init_FrameSide(self: Any, side: Any, parts: Any, span: Any = DEFAULT) -> None:
    _set_FrameSide_side(self, side)
    _set_FrameSide_parts(self, parts)
    _set_FrameSide_span(self, span)


def _repr_FrameSide(self: Any) -> str:
    return f"{self.__class__.__qualname__}(side={self.side!r}, parts={self.parts!r})"


def _eq_FrameSide(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.side, self.parts) == (other.side, other.parts)
    return NotImplemented


def _hash_FrameSide(self: Any) -> int:
    return hash((self.side, self.parts))


_set_FrameStuff_escape = _set_FrameStuff_reserved = _set_FrameStuff_span = _unbound


def _init_FrameStuff(self: Any, escape: Any, reserved: Any, span: Any = DEFAULT) -> None:
    _set_FrameStuff_escape(self, escape)
    _set_FrameStuff_reserved(self, reserved)
    _set_FrameStuff_span(self, span)


def _repr_FrameStuff(self: Any) -> str:
    return f"{self.__class__.__qualname__}(escape={self.escape!r}, reserved={self.reserved!r})"


def _eq_FrameStuff(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.escape, self.reserved) == (other.escape, other.reserved)
    return NotImplemented


def _hash_FrameStuff(self: Any) -> int:
    return hash((self.escape, self.reserved))


_set_FrameEscape_escape = _unbound
_set_FrameEscape_table = _unbound
_set_FrameEscape_xor = _unbound
_set_FrameEscape_escaped = _unbound
_set_FrameEscape_span = _unbound


def _init_FrameEscape(
    self: Any,
    escape: Any,
    table: Any,
    xor: Any = DEFAULT,
    escaped: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_FrameEscape_escape(self, escape)
    _set_FrameEscape_table(self, table)
    _set_FrameEscape_xor(self, xor)
    _set_FrameEscape_escaped(self, escaped)
    _set_FrameEscape_span(self, span)


def _repr_FrameEscape(self: Any) -> str:
    return f"{self.__class__.__qualname__}(escape={self.escape!r}, table={self.table!r}, xor={self.xor!r}, escaped={self.escaped!r})"


def _eq_FrameEscape(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.escape,
            self.table,
            self.xor,
            self.escaped,
        ) == (
            other.escape,
            other.table,
            other.xor,
            other.escaped,
        )
    return NotImplemented


def _hash_FrameEscape(self: Any) -> int:
    return hash((self.escape, self.table, self.xor, self.escaped))


_set_FrameDecl_name = _unbound
_set_FrameDecl_params = _unbound
_set_FrameDecl_items = _unbound
_set_FrameDecl_span = _unbound
_set_FrameDecl_doc = _unbound


def _init_FrameDecl(
    self: Any,
    name: Any,
    params: Any,
    items: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_FrameDecl_name(self, name)
    _set_FrameDecl_params(self, params)
    _set_FrameDecl_items(self, items)
    _set_FrameDecl_span(self, span)
    _set_FrameDecl_doc(self, doc)


def _repr_FrameDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, items={self.items!r}, doc={self.doc!r})"


def _eq_FrameDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.items,
            self.doc,
        ) == (
            other.name,
            other.params,
            other.items,
            other.doc,
        )
    return NotImplemented


def _hash_FrameDecl(self: Any) -> int:
    return hash((self.name, self.params, self.items, self.doc))


WRITTEN: dict[str, Written] = {
    "FrameBytes": Written(
        (("role", MISSING), ("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_FrameBytes,
            "__repr__": _repr_FrameBytes,
            "__eq__": _eq_FrameBytes,
            "__hash__": _hash_FrameBytes,
        },
    ),
    "FrameField": Written(
        (
            ("name", MISSING),
            ("format", MISSING),
            ("value", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_FrameField,
            "__repr__": _repr_FrameField,
            "__eq__": _eq_FrameField,
            "__hash__": _hash_FrameField,
        },
    ),
    "FrameLength": Written(
        (("format", MISSING), ("adjust", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_FrameLength,
            "__repr__": _repr_FrameLength,
            "__eq__": _eq_FrameLength,
            "__hash__": _hash_FrameLength,
        },
    ),
    "FramePayload": Written(
        (("span", FieldSpec(None, MISSING, False, False)), ("trimmed", DEFAULT)),
        {
            "__init__": _init_FramePayload,
            "__repr__": _repr_FramePayload,
            "__eq__": _eq_FramePayload,
            "__hash__": _hash_FramePayload,
        },
    ),
    "ChecksumOption": Written(
        (
            ("word", MISSING),
            ("value", DEFAULT),
            ("over", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_ChecksumOption,
            "__repr__": _repr_ChecksumOption,
            "__eq__": _eq_ChecksumOption,
            "__hash__": _hash_ChecksumOption,
        },
    ),
    "FrameChecksum": Written(
        (
            ("algorithm", MISSING),
            ("format", MISSING),
            ("options", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_FrameChecksum,
            "__repr__": _repr_FrameChecksum,
            "__eq__": _eq_FrameChecksum,
            "__hash__": _hash_FrameChecksum,
        },
    ),
    "FrameOptional": Written(
        (("parts", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_FrameOptional,
            "__repr__": _repr_FrameOptional,
            "__eq__": _eq_FrameOptional,
            "__hash__": _hash_FrameOptional,
        },
    ),
    "FrameEither": Written(
        (
            ("alternatives", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("conditions", DEFAULT),
        ),
        {
            "__init__": _init_FrameEither,
            "__repr__": _repr_FrameEither,
            "__eq__": _eq_FrameEither,
            "__hash__": _hash_FrameEither,
        },
    ),
    "FrameBitField": Written(
        (
            ("name", MISSING),
            ("width", MISSING),
            ("value", MISSING),
            ("adjust", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_FrameBitField,
            "__repr__": _repr_FrameBitField,
            "__eq__": _eq_FrameBitField,
            "__hash__": _hash_FrameBitField,
        },
    ),
    "FrameBits": Written(
        (("format", MISSING), ("fields", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_FrameBits,
            "__repr__": _repr_FrameBits,
            "__eq__": _eq_FrameBits,
            "__hash__": _hash_FrameBits,
        },
    ),
    "FrameSide": Written(
        (("side", MISSING), ("parts", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_FrameSide,
            "__repr__": _repr_FrameSide,
            "__eq__": _eq_FrameSide,
            "__hash__": _hash_FrameSide,
        },
    ),
    "FrameStuff": Written(
        (("escape", MISSING), ("reserved", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_FrameStuff,
            "__repr__": _repr_FrameStuff,
            "__eq__": _eq_FrameStuff,
            "__hash__": _hash_FrameStuff,
        },
    ),
    "FrameEscape": Written(
        (
            ("escape", MISSING),
            ("table", MISSING),
            ("xor", DEFAULT),
            ("escaped", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_FrameEscape,
            "__repr__": _repr_FrameEscape,
            "__eq__": _eq_FrameEscape,
            "__hash__": _hash_FrameEscape,
        },
    ),
    "FrameDecl": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("items", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_FrameDecl,
            "__repr__": _repr_FrameDecl,
            "__eq__": _eq_FrameDecl,
            "__hash__": _hash_FrameDecl,
        },
    ),
}
dataclass = classes(WRITTEN)
