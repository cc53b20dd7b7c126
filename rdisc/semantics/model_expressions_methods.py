"""The methods of the frozen dataclasses of rdisc/semantics/model_expressions.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_Array_element = _set_Array_size = _unbound


def _init_Array(self: Any, element: Any, size: Any) -> None:
    _set_Array_element(self, element)
    _set_Array_size(self, size)


def _repr_Array(self: Any) -> str:
    return f"{self.__class__.__qualname__}(element={self.element!r}, size={self.size!r})"


def _eq_Array(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.element, self.size) == (other.element, other.size)
    return NotImplemented


def _hash_Array(self: Any) -> int:
    return hash((self.element, self.size))


_set_Const_value = _set_Const_type = _set_Const_span = _unbound


def _init_Const(self: Any, value: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_Const_value(self, value)
    _set_Const_type(self, type)
    _set_Const_span(self, span)


def _repr_Const(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r}, type={self.type!r})"


def _eq_Const(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value, self.type) == (other.value, other.type)
    return NotImplemented


def _hash_Const(self: Any) -> int:
    return hash((self.value, self.type))


_set_Var_name = _set_Var_scope = _set_Var_type = _set_Var_span = _unbound


def _init_Var(self: Any, name: Any, scope: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_Var_name(self, name)
    _set_Var_scope(self, scope)
    _set_Var_type(self, type)
    _set_Var_span(self, span)


def _repr_Var(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, scope={self.scope!r}, type={self.type!r})"


def _eq_Var(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.scope, self.type) == (other.name, other.scope, other.type)
    return NotImplemented


def _hash_Var(self: Any) -> int:
    return hash((self.name, self.scope, self.type))


_set_ReplyValue_index = _set_ReplyValue_type = _set_ReplyValue_span = _unbound


def _init_ReplyValue(self: Any, index: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_ReplyValue_index(self, index)
    _set_ReplyValue_type(self, type)
    _set_ReplyValue_span(self, span)


def _repr_ReplyValue(self: Any) -> str:
    return f"{self.__class__.__qualname__}(index={self.index!r}, type={self.type!r})"


def _eq_ReplyValue(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.index, self.type) == (other.index, other.type)
    return NotImplemented


def _hash_ReplyValue(self: Any) -> int:
    return hash((self.index, self.type))


_set_UnaryOp_op = _set_UnaryOp_operand = _set_UnaryOp_type = _set_UnaryOp_span = _unbound


def _init_UnaryOp(self: Any, op: Any, operand: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_UnaryOp_op(self, op)
    _set_UnaryOp_operand(self, operand)
    _set_UnaryOp_type(self, type)
    _set_UnaryOp_span(self, span)


def _repr_UnaryOp(self: Any) -> str:
    return f"{self.__class__.__qualname__}(op={self.op!r}, operand={self.operand!r}, type={self.type!r})"


def _eq_UnaryOp(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.op, self.operand, self.type) == (other.op, other.operand, other.type)
    return NotImplemented


def _hash_UnaryOp(self: Any) -> int:
    return hash((self.op, self.operand, self.type))


_set_BinaryOp_op = _unbound
_set_BinaryOp_left = _unbound
_set_BinaryOp_right = _unbound
_set_BinaryOp_type = _unbound
_set_BinaryOp_span = _unbound


def _init_BinaryOp(self: Any, op: Any, left: Any, right: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_BinaryOp_op(self, op)
    _set_BinaryOp_left(self, left)
    _set_BinaryOp_right(self, right)
    _set_BinaryOp_type(self, type)
    _set_BinaryOp_span(self, span)


def _repr_BinaryOp(self: Any) -> str:
    return f"{self.__class__.__qualname__}(op={self.op!r}, left={self.left!r}, right={self.right!r}, type={self.type!r})"


def _eq_BinaryOp(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.op, self.left, self.right, self.type) == (other.op, other.left, other.right, other.type)
    return NotImplemented


def _hash_BinaryOp(self: Any) -> int:
    return hash((self.op, self.left, self.right, self.type))


_set_IfElse_cond = _set_IfElse_then = _set_IfElse_orelse = _set_IfElse_type = _set_IfElse_span = _unbound


def _init_IfElse(self: Any, cond: Any, then: Any, orelse: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_IfElse_cond(self, cond)
    _set_IfElse_then(self, then)
    _set_IfElse_orelse(self, orelse)
    _set_IfElse_type(self, type)
    _set_IfElse_span(self, span)


def _repr_IfElse(self: Any) -> str:
    return f"{self.__class__.__qualname__}(cond={self.cond!r}, then={self.then!r}, orelse={self.orelse!r}, type={self.type!r})"


def _eq_IfElse(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.cond,
            self.then,
            self.orelse,
            self.type,
        ) == (
            other.cond,
            other.then,
            other.orelse,
            other.type,
        )
    return NotImplemented


def _hash_IfElse(self: Any) -> int:
    return hash((self.cond, self.then, self.orelse, self.type))


_set_FuncCall_func = _set_FuncCall_args = _set_FuncCall_type = _set_FuncCall_span = _unbound


def _init_FuncCall(self: Any, func: Any, args: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_FuncCall_func(self, func)
    _set_FuncCall_args(self, args)
    _set_FuncCall_type(self, type)
    _set_FuncCall_span(self, span)


def _repr_FuncCall(self: Any) -> str:
    return f"{self.__class__.__qualname__}(func={self.func!r}, args={self.args!r}, type={self.type!r})"


def _eq_FuncCall(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.func, self.args, self.type) == (other.func, other.args, other.type)
    return NotImplemented


def _hash_FuncCall(self: Any) -> int:
    return hash((self.func, self.args, self.type))


_set_Table_name = _set_Table_key_type = _set_Table_value_type = _set_Table_entries = _set_Table_doc = _unbound


def _init_Table(
    self: Any,
    name: Any,
    key_type: Any,
    value_type: Any,
    entries: Any,
    doc: Any = DEFAULT,
) -> None:
    _set_Table_name(self, name)
    _set_Table_key_type(self, key_type)
    _set_Table_value_type(self, value_type)
    _set_Table_entries(self, entries)
    _set_Table_doc(self, doc)


def _repr_Table(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, key_type={self.key_type!r}, value_type={self.value_type!r}, entries={self.entries!r}, doc={self.doc!r})"


def _eq_Table(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.key_type,
            self.value_type,
            self.entries,
            self.doc,
        ) == (
            other.name,
            other.key_type,
            other.value_type,
            other.entries,
            other.doc,
        )
    return NotImplemented


def _hash_Table(self: Any) -> int:
    return hash((self.name, self.key_type, self.value_type, self.entries, self.doc))


_set_Lookup_table = _unbound
_set_Lookup_entries = _unbound
_set_Lookup_key = _unbound
_set_Lookup_type = _unbound
_set_Lookup_span = _unbound
_set_Lookup_default = _unbound


def _init_Lookup(
    self: Any,
    table: Any,
    entries: Any,
    key: Any,
    type: Any,
    span: Any = DEFAULT,
    default: Any = DEFAULT,
) -> None:
    _set_Lookup_table(self, table)
    _set_Lookup_entries(self, entries)
    _set_Lookup_key(self, key)
    _set_Lookup_type(self, type)
    _set_Lookup_span(self, span)
    _set_Lookup_default(self, default)


def _repr_Lookup(self: Any) -> str:
    return f"{self.__class__.__qualname__}(table={self.table!r}, entries={self.entries!r}, key={self.key!r}, type={self.type!r}, default={self.default!r})"


def _eq_Lookup(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.table,
            self.entries,
            self.key,
            self.type,
            self.default,
        ) == (
            other.table,
            other.entries,
            other.key,
            other.type,
            other.default,
        )
    return NotImplemented


def _hash_Lookup(self: Any) -> int:
    return hash((self.table, self.entries, self.key, self.type, self.default))


_set_InTable_table = _set_InTable_keys = _set_InTable_key = _set_InTable_type = _set_InTable_span = _unbound


def _init_InTable(self: Any, table: Any, keys: Any, key: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_InTable_table(self, table)
    _set_InTable_keys(self, keys)
    _set_InTable_key(self, key)
    _set_InTable_type(self, type)
    _set_InTable_span(self, span)


def _repr_InTable(self: Any) -> str:
    return f"{self.__class__.__qualname__}(table={self.table!r}, keys={self.keys!r}, key={self.key!r}, type={self.type!r})"


def _eq_InTable(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.table,
            self.keys,
            self.key,
            self.type,
        ) == (
            other.table,
            other.keys,
            other.key,
            other.type,
        )
    return NotImplemented


def _hash_InTable(self: Any) -> int:
    return hash((self.table, self.keys, self.key, self.type))


_set_ArrayValue_items = _set_ArrayValue_type = _set_ArrayValue_span = _unbound


def _init_ArrayValue(self: Any, items: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_ArrayValue_items(self, items)
    _set_ArrayValue_type(self, type)
    _set_ArrayValue_span(self, span)


def _repr_ArrayValue(self: Any) -> str:
    return f"{self.__class__.__qualname__}(items={self.items!r}, type={self.type!r})"


def _eq_ArrayValue(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.items, self.type) == (other.items, other.type)
    return NotImplemented


def _hash_ArrayValue(self: Any) -> int:
    return hash((self.items, self.type))


_set_Element_array = _set_Element_index = _set_Element_type = _set_Element_span = _unbound


def _init_Element(self: Any, array: Any, index: Any, type: Any, span: Any = DEFAULT) -> None:
    _set_Element_array(self, array)
    _set_Element_index(self, index)
    _set_Element_type(self, type)
    _set_Element_span(self, span)


def _repr_Element(self: Any) -> str:
    return f"{self.__class__.__qualname__}(array={self.array!r}, index={self.index!r}, type={self.type!r})"


def _eq_Element(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.array, self.index, self.type) == (other.array, other.index, other.type)
    return NotImplemented


def _hash_Element(self: Any) -> int:
    return hash((self.array, self.index, self.type))


_set_Replaced_array = _unbound
_set_Replaced_index = _unbound
_set_Replaced_value = _unbound
_set_Replaced_type = _unbound
_set_Replaced_span = _unbound
_set_Replaced_when = _unbound


def _init_Replaced(
    self: Any,
    array: Any,
    index: Any,
    value: Any,
    type: Any,
    span: Any = DEFAULT,
    when: Any = DEFAULT,
) -> None:
    _set_Replaced_array(self, array)
    _set_Replaced_index(self, index)
    _set_Replaced_value(self, value)
    _set_Replaced_type(self, type)
    _set_Replaced_span(self, span)
    _set_Replaced_when(self, when)


def _repr_Replaced(self: Any) -> str:
    return f"{self.__class__.__qualname__}(array={self.array!r}, index={self.index!r}, value={self.value!r}, type={self.type!r}, when={self.when!r})"


def _eq_Replaced(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.array,
            self.index,
            self.value,
            self.type,
            self.when,
        ) == (
            other.array,
            other.index,
            other.value,
            other.type,
            other.when,
        )
    return NotImplemented


def _hash_Replaced(self: Any) -> int:
    return hash((self.array, self.index, self.value, self.type, self.when))


_set_Parameter_name = _unbound
_set_Parameter_type = _unbound
_set_Parameter_low = _unbound
_set_Parameter_high = _unbound
_set_Parameter_default = _unbound
_set_Parameter_unit = _unbound
_set_Parameter_limits = _unbound


def _init_Parameter(
    self: Any,
    name: Any,
    type: Any,
    low: Any = DEFAULT,
    high: Any = DEFAULT,
    default: Any = DEFAULT,
    unit: Any = DEFAULT,
    limits: Any = DEFAULT,
) -> None:
    _set_Parameter_name(self, name)
    _set_Parameter_type(self, type)
    _set_Parameter_low(self, low)
    _set_Parameter_high(self, high)
    _set_Parameter_default(self, default)
    _set_Parameter_unit(self, unit)
    _set_Parameter_limits(self, limits)


def _repr_Parameter(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, low={self.low!r}, high={self.high!r}, default={self.default!r}, unit={self.unit!r}, limits={self.limits!r})"


def _eq_Parameter(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.low,
            self.high,
            self.default,
            self.unit,
            self.limits,
        ) == (
            other.name,
            other.type,
            other.low,
            other.high,
            other.default,
            other.unit,
            other.limits,
        )
    return NotImplemented


def _hash_Parameter(self: Any) -> int:
    return hash((self.name, self.type, self.low, self.high, self.default, self.unit, self.limits))


WRITTEN: dict[str, Written] = {
    "Array": Written(
        (("element", MISSING), ("size", MISSING)),
        {"__init__": _init_Array, "__repr__": _repr_Array, "__eq__": _eq_Array, "__hash__": _hash_Array},
    ),
    "Const": Written(
        (("value", MISSING), ("type", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Const, "__repr__": _repr_Const, "__eq__": _eq_Const, "__hash__": _hash_Const},
    ),
    "Var": Written(
        (
            ("name", MISSING),
            ("scope", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_Var, "__repr__": _repr_Var, "__eq__": _eq_Var, "__hash__": _hash_Var},
    ),
    "ReplyValue": Written(
        (("index", MISSING), ("type", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_ReplyValue,
            "__repr__": _repr_ReplyValue,
            "__eq__": _eq_ReplyValue,
            "__hash__": _hash_ReplyValue,
        },
    ),
    "UnaryOp": Written(
        (
            ("op", MISSING),
            ("operand", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_UnaryOp,
            "__repr__": _repr_UnaryOp,
            "__eq__": _eq_UnaryOp,
            "__hash__": _hash_UnaryOp,
        },
    ),
    "BinaryOp": Written(
        (
            ("op", MISSING),
            ("left", MISSING),
            ("right", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_BinaryOp,
            "__repr__": _repr_BinaryOp,
            "__eq__": _eq_BinaryOp,
            "__hash__": _hash_BinaryOp,
        },
    ),
    "IfElse": Written(
        (
            ("cond", MISSING),
            ("then", MISSING),
            ("orelse", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_IfElse, "__repr__": _repr_IfElse, "__eq__": _eq_IfElse, "__hash__": _hash_IfElse},
    ),
    "FuncCall": Written(
        (
            ("func", MISSING),
            ("args", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_FuncCall,
            "__repr__": _repr_FuncCall,
            "__eq__": _eq_FuncCall,
            "__hash__": _hash_FuncCall,
        },
    ),
    "Table": Written(
        (
            ("name", MISSING),
            ("key_type", MISSING),
            ("value_type", MISSING),
            ("entries", MISSING),
            ("doc", DEFAULT),
        ),
        {"__init__": _init_Table, "__repr__": _repr_Table, "__eq__": _eq_Table, "__hash__": _hash_Table},
    ),
    "Lookup": Written(
        (
            ("table", MISSING),
            ("entries", MISSING),
            ("key", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("default", DEFAULT),
        ),
        {"__init__": _init_Lookup, "__repr__": _repr_Lookup, "__eq__": _eq_Lookup, "__hash__": _hash_Lookup},
    ),
    "InTable": Written(
        (
            ("table", MISSING),
            ("keys", MISSING),
            ("key", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_InTable,
            "__repr__": _repr_InTable,
            "__eq__": _eq_InTable,
            "__hash__": _hash_InTable,
        },
    ),
    "ArrayValue": Written(
        (("items", MISSING), ("type", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_ArrayValue,
            "__repr__": _repr_ArrayValue,
            "__eq__": _eq_ArrayValue,
            "__hash__": _hash_ArrayValue,
        },
    ),
    "Element": Written(
        (
            ("array", MISSING),
            ("index", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_Element,
            "__repr__": _repr_Element,
            "__eq__": _eq_Element,
            "__hash__": _hash_Element,
        },
    ),
    "Replaced": Written(
        (
            ("array", MISSING),
            ("index", MISSING),
            ("value", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("when", DEFAULT),
        ),
        {
            "__init__": _init_Replaced,
            "__repr__": _repr_Replaced,
            "__eq__": _eq_Replaced,
            "__hash__": _hash_Replaced,
        },
    ),
    "Parameter": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("low", DEFAULT),
            ("high", DEFAULT),
            ("default", DEFAULT),
            ("unit", DEFAULT),
            ("limits", DEFAULT),
        ),
        {
            "__init__": _init_Parameter,
            "__repr__": _repr_Parameter,
            "__eq__": _eq_Parameter,
            "__hash__": _hash_Parameter,
        },
    ),
}
dataclass = classes(WRITTEN)
