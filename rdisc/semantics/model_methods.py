"""The methods of the frozen dataclasses of rdisc/semantics/model.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from typing import Any

from rdisc.frozen import DEFAULT, FACTORY, MISSING, FieldSpec, Written, classes, field

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


_set_Robot_name = _unbound
_set_Robot_author = _unbound
_set_Robot_description = _unbound
_set_Robot_version = _unbound
_set_Robot_doc = _unbound
_set_Robot_span = _unbound


def _init_Robot(
    self: Any,
    name: Any,
    author: Any = DEFAULT,
    description: Any = DEFAULT,
    version: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_Robot_name(self, name)
    _set_Robot_author(self, author)
    _set_Robot_description(self, description)
    _set_Robot_version(self, version)
    _set_Robot_doc(self, doc)
    _set_Robot_span(self, span)


def _repr_Robot(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, author={self.author!r}, description={self.description!r}, version={self.version!r}, doc={self.doc!r})"


def _eq_Robot(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.author,
            self.description,
            self.version,
            self.doc,
        ) == (
            other.name,
            other.author,
            other.description,
            other.version,
            other.doc,
        )
    return NotImplemented


def _hash_Robot(self: Any) -> int:
    return hash((self.name, self.author, self.description, self.version, self.doc))


_set_StateVariable_name = _unbound
_set_StateVariable_type = _unbound
_set_StateVariable_initial = _unbound
_set_StateVariable_doc = _unbound
_set_StateVariable_span = _unbound
_set_StateVariable_noise = _unbound


def _init_StateVariable(
    self: Any,
    name: Any,
    type: Any,
    initial: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    noise: Any = DEFAULT,
) -> None:
    _set_StateVariable_name(self, name)
    _set_StateVariable_type(self, type)
    _set_StateVariable_initial(self, initial)
    _set_StateVariable_doc(self, doc)
    _set_StateVariable_span(self, span)
    _set_StateVariable_noise(self, noise)


def _repr_StateVariable(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, initial={self.initial!r}, doc={self.doc!r}, noise={self.noise!r})"


def _eq_StateVariable(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.initial,
            self.doc,
            self.noise,
        ) == (
            other.name,
            other.type,
            other.initial,
            other.doc,
            other.noise,
        )
    return NotImplemented


def _hash_StateVariable(self: Any) -> int:
    return hash((self.name, self.type, self.initial, self.doc, self.noise))


_set_Sensor_name = _unbound
_set_Sensor_type = _unbound
_set_Sensor_primitive = _unbound
_set_Sensor_cache_ms = _unbound
_set_Sensor_doc = _unbound
_set_Sensor_span = _unbound
_set_Sensor_noise = _unbound


def _init_Sensor(
    self: Any,
    name: Any,
    type: Any,
    primitive: Any,
    cache_ms: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    noise: Any = DEFAULT,
) -> None:
    _set_Sensor_name(self, name)
    _set_Sensor_type(self, type)
    _set_Sensor_primitive(self, primitive)
    _set_Sensor_cache_ms(self, cache_ms)
    _set_Sensor_doc(self, doc)
    _set_Sensor_span(self, span)
    _set_Sensor_noise(self, noise)


def _repr_Sensor(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, primitive={self.primitive!r}, cache_ms={self.cache_ms!r}, doc={self.doc!r}, noise={self.noise!r})"


def _eq_Sensor(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.primitive,
            self.cache_ms,
            self.doc,
            self.noise,
        ) == (
            other.name,
            other.type,
            other.primitive,
            other.cache_ms,
            other.doc,
            other.noise,
        )
    return NotImplemented


def _hash_Sensor(self: Any) -> int:
    return hash((self.name, self.type, self.primitive, self.cache_ms, self.doc, self.noise))


_set_Setting_name = _unbound
_set_Setting_type = _unbound
_set_Setting_default = _unbound
_set_Setting_low = _unbound
_set_Setting_high = _unbound
_set_Setting_doc = _unbound
_set_Setting_span = _unbound


def _init_Setting(
    self: Any,
    name: Any,
    type: Any,
    default: Any,
    low: Any = DEFAULT,
    high: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_Setting_name(self, name)
    _set_Setting_type(self, type)
    _set_Setting_default(self, default)
    _set_Setting_low(self, low)
    _set_Setting_high(self, high)
    _set_Setting_doc(self, doc)
    _set_Setting_span(self, span)


def _repr_Setting(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, default={self.default!r}, low={self.low!r}, high={self.high!r}, doc={self.doc!r})"


def _eq_Setting(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.default,
            self.low,
            self.high,
            self.doc,
        ) == (
            other.name,
            other.type,
            other.default,
            other.low,
            other.high,
            other.doc,
        )
    return NotImplemented


def _hash_Setting(self: Any) -> int:
    return hash((self.name, self.type, self.default, self.low, self.high, self.doc))


_set_HookCall_interface = _set_HookCall_args = _set_HookCall_span = _unbound


def _init_HookCall(self: Any, interface: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_HookCall_interface(self, interface)
    _set_HookCall_args(self, args)
    _set_HookCall_span(self, span)


def _repr_HookCall(self: Any) -> str:
    return f"{self.__class__.__qualname__}(interface={self.interface!r}, args={self.args!r})"


def _eq_HookCall(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.interface, self.args) == (other.interface, other.args)
    return NotImplemented


def _hash_HookCall(self: Any) -> int:
    return hash((self.interface, self.args))


_set_Keepalive_call = _set_Keepalive_interval_ms = _unbound


def _init_Keepalive(self: Any, call: Any, interval_ms: Any) -> None:
    _set_Keepalive_call(self, call)
    _set_Keepalive_interval_ms(self, interval_ms)


def _repr_Keepalive(self: Any) -> str:
    return f"{self.__class__.__qualname__}(call={self.call!r}, interval_ms={self.interval_ms!r})"


def _eq_Keepalive(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.call, self.interval_ms) == (other.call, other.interval_ms)
    return NotImplemented


def _hash_Keepalive(self: Any) -> int:
    return hash((self.call, self.interval_ms))


_set_Connection_name = _unbound
_set_Connection_kind = _unbound
_set_Connection_baud = _unbound
_set_Connection_frequency_hz = _unbound
_set_Connection_startup = _unbound
_set_Connection_terminate = _unbound
_set_Connection_keepalive = _unbound
_set_Connection_doc = _unbound
_set_Connection_span = _unbound
_set_Connection_terminator = _unbound
_set_Connection_address = _unbound
_set_Connection_baud_setting = _unbound
_set_Connection_data_bits = _unbound
_set_Connection_parity = _unbound
_set_Connection_stop_bits = _unbound
_set_Connection_threading = _unbound


def _init_Connection(
    self: Any,
    name: Any,
    kind: Any,
    baud: Any,
    frequency_hz: Any,
    startup: Any = DEFAULT,
    terminate: Any = DEFAULT,
    keepalive: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    terminator: Any = DEFAULT,
    address: Any = DEFAULT,
    baud_setting: Any = DEFAULT,
    data_bits: Any = DEFAULT,
    parity: Any = DEFAULT,
    stop_bits: Any = DEFAULT,
    threading: Any = DEFAULT,
) -> None:
    _set_Connection_name(self, name)
    _set_Connection_kind(self, kind)
    _set_Connection_baud(self, baud)
    _set_Connection_frequency_hz(self, frequency_hz)
    _set_Connection_startup(self, startup)
    _set_Connection_terminate(self, terminate)
    _set_Connection_keepalive(self, keepalive)
    _set_Connection_doc(self, doc)
    _set_Connection_span(self, span)
    _set_Connection_terminator(self, terminator)
    _set_Connection_address(self, address)
    _set_Connection_baud_setting(self, baud_setting)
    _set_Connection_data_bits(self, data_bits)
    _set_Connection_parity(self, parity)
    _set_Connection_stop_bits(self, stop_bits)
    _set_Connection_threading(self, threading)


def _repr_Connection(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, kind={self.kind!r}, baud={self.baud!r}, frequency_hz={self.frequency_hz!r}, startup={self.startup!r}, terminate={self.terminate!r}, keepalive={self.keepalive!r}, doc={self.doc!r}, terminator={self.terminator!r}, address={self.address!r}, baud_setting={self.baud_setting!r}, data_bits={self.data_bits!r}, parity={self.parity!r}, stop_bits={self.stop_bits!r}, threading={self.threading!r})"


def _eq_Connection(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.kind,
            self.baud,
            self.frequency_hz,
            self.startup,
            self.terminate,
            self.keepalive,
            self.doc,
            self.terminator,
            self.address,
            self.baud_setting,
            self.data_bits,
            self.parity,
            self.stop_bits,
            self.threading,
        ) == (
            other.name,
            other.kind,
            other.baud,
            other.frequency_hz,
            other.startup,
            other.terminate,
            other.keepalive,
            other.doc,
            other.terminator,
            other.address,
            other.baud_setting,
            other.data_bits,
            other.parity,
            other.stop_bits,
            other.threading,
        )
    return NotImplemented


def _hash_Connection(self: Any) -> int:
    return hash((
        self.name,
        self.kind,
        self.baud,
        self.frequency_hz,
        self.startup,
        self.terminate,
        self.keepalive,
        self.doc,
        self.terminator,
        self.address,
        self.baud_setting,
        self.data_bits,
        self.parity,
        self.stop_bits,
        self.threading,
    ))


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


_set_ChecksumAlgorithm_kind = _unbound
_set_ChecksumAlgorithm_width = _unbound
_set_ChecksumAlgorithm_poly = _unbound
_set_ChecksumAlgorithm_init = _unbound
_set_ChecksumAlgorithm_reflect_in = _unbound
_set_ChecksumAlgorithm_reflect_out = _unbound
_set_ChecksumAlgorithm_xorout = _unbound
_set_ChecksumAlgorithm_inverted = _unbound
_set_ChecksumAlgorithm_mask = _unbound
_set_ChecksumAlgorithm_name = _unbound


def _init_ChecksumAlgorithm(
    self: Any,
    kind: Any,
    width: Any,
    poly: Any = DEFAULT,
    init: Any = DEFAULT,
    reflect_in: Any = DEFAULT,
    reflect_out: Any = DEFAULT,
    xorout: Any = DEFAULT,
    inverted: Any = DEFAULT,
    mask: Any = DEFAULT,
    name: Any = DEFAULT,
) -> None:
    _set_ChecksumAlgorithm_kind(self, kind)
    _set_ChecksumAlgorithm_width(self, width)
    _set_ChecksumAlgorithm_poly(self, poly)
    _set_ChecksumAlgorithm_init(self, init)
    _set_ChecksumAlgorithm_reflect_in(self, reflect_in)
    _set_ChecksumAlgorithm_reflect_out(self, reflect_out)
    _set_ChecksumAlgorithm_xorout(self, xorout)
    _set_ChecksumAlgorithm_inverted(self, inverted)
    _set_ChecksumAlgorithm_mask(self, mask)
    _set_ChecksumAlgorithm_name(self, name)


def _repr_ChecksumAlgorithm(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, width={self.width!r}, poly={self.poly!r}, init={self.init!r}, reflect_in={self.reflect_in!r}, reflect_out={self.reflect_out!r}, xorout={self.xorout!r}, inverted={self.inverted!r}, mask={self.mask!r}, name={self.name!r})"


def _eq_ChecksumAlgorithm(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.kind,
            self.width,
            self.poly,
            self.init,
            self.reflect_in,
            self.reflect_out,
            self.xorout,
            self.inverted,
            self.mask,
            self.name,
        ) == (
            other.kind,
            other.width,
            other.poly,
            other.init,
            other.reflect_in,
            other.reflect_out,
            other.xorout,
            other.inverted,
            other.mask,
            other.name,
        )
    return NotImplemented


def _hash_ChecksumAlgorithm(self: Any) -> int:
    return hash((
        self.kind,
        self.width,
        self.poly,
        self.init,
        self.reflect_in,
        self.reflect_out,
        self.xorout,
        self.inverted,
        self.mask,
        self.name,
    ))


_set_FrameBytes_role = _set_FrameBytes_data = _unbound


def _init_FrameBytes(self: Any, role: Any, data: Any) -> None:
    _set_FrameBytes_role(self, role)
    _set_FrameBytes_data(self, data)


def _repr_FrameBytes(self: Any) -> str:
    return f"{self.__class__.__qualname__}(role={self.role!r}, data={self.data!r})"


def _eq_FrameBytes(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.role, self.data) == (other.role, other.data)
    return NotImplemented


def _hash_FrameBytes(self: Any) -> int:
    return hash((self.role, self.data))


_set_FrameField_name = _set_FrameField_format = _set_FrameField_value = _set_FrameField_layout = _unbound


def _init_FrameField(self: Any, name: Any, format: Any, value: Any, layout: Any) -> None:
    _set_FrameField_name(self, name)
    _set_FrameField_format(self, format)
    _set_FrameField_value(self, value)
    _set_FrameField_layout(self, layout)


def _repr_FrameField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, format={self.format!r}, value={self.value!r})"


def _eq_FrameField(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.format, self.value) == (other.name, other.format, other.value)
    return NotImplemented


def _hash_FrameField(self: Any) -> int:
    return hash((self.name, self.format, self.value))


_set_FrameLength_format = _set_FrameLength_adjust = _set_FrameLength_layout = _unbound


def _init_FrameLength(self: Any, format: Any, adjust: Any, layout: Any) -> None:
    _set_FrameLength_format(self, format)
    _set_FrameLength_adjust(self, adjust)
    _set_FrameLength_layout(self, layout)


def _repr_FrameLength(self: Any) -> str:
    return f"{self.__class__.__qualname__}(format={self.format!r}, adjust={self.adjust!r})"


def _eq_FrameLength(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.format, self.adjust) == (other.format, other.adjust)
    return NotImplemented


def _hash_FrameLength(self: Any) -> int:
    return hash((self.format, self.adjust))


_set_FramePayload_trimmed = _unbound


def _init_FramePayload(self: Any, trimmed: Any = DEFAULT) -> None:
    _set_FramePayload_trimmed(self, trimmed)


def _repr_FramePayload(self: Any) -> str:
    return f"{self.__class__.__qualname__}(trimmed={self.trimmed!r})"


def _eq_FramePayload(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.trimmed,) == (other.trimmed,)
    return NotImplemented


def _hash_FramePayload(self: Any) -> int:
    return hash((self.trimmed,))


_set_FrameSeed_table = _set_FrameSeed_field = _set_FrameSeed_part = _set_FrameSeed_entries = _unbound


def _init_FrameSeed(self: Any, table: Any, field: Any, part: Any, entries: Any) -> None:
    _set_FrameSeed_table(self, table)
    _set_FrameSeed_field(self, field)
    _set_FrameSeed_part(self, part)
    _set_FrameSeed_entries(self, entries)


def _repr_FrameSeed(self: Any) -> str:
    return f"{self.__class__.__qualname__}(table={self.table!r}, field={self.field!r}, part={self.part!r}, entries={self.entries!r})"


def _eq_FrameSeed(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.table,
            self.field,
            self.part,
            self.entries,
        ) == (
            other.table,
            other.field,
            other.part,
            other.entries,
        )
    return NotImplemented


def _hash_FrameSeed(self: Any) -> int:
    return hash((self.table, self.field, self.part, self.entries))


_set_FrameChecksum_algorithm = _unbound
_set_FrameChecksum_format = _unbound
_set_FrameChecksum_first = _unbound
_set_FrameChecksum_last = _unbound
_set_FrameChecksum_with_request = _unbound
_set_FrameChecksum_layout = _unbound
_set_FrameChecksum_seed = _unbound


def _init_FrameChecksum(
    self: Any,
    algorithm: Any,
    format: Any,
    first: Any,
    last: Any,
    with_request: Any = DEFAULT,
    layout: Any = DEFAULT,
    seed: Any = DEFAULT,
) -> None:
    _set_FrameChecksum_algorithm(self, algorithm)
    _set_FrameChecksum_format(self, format)
    _set_FrameChecksum_first(self, first)
    _set_FrameChecksum_last(self, last)
    _set_FrameChecksum_with_request(self, with_request)
    _set_FrameChecksum_layout(self, layout)
    _set_FrameChecksum_seed(self, seed)


def _repr_FrameChecksum(self: Any) -> str:
    return f"{self.__class__.__qualname__}(algorithm={self.algorithm!r}, format={self.format!r}, first={self.first!r}, last={self.last!r}, with_request={self.with_request!r}, seed={self.seed!r})"


def _eq_FrameChecksum(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.algorithm,
            self.format,
            self.first,
            self.last,
            self.with_request,
            self.seed,
        ) == (
            other.algorithm,
            other.format,
            other.first,
            other.last,
            other.with_request,
            other.seed,
        )
    return NotImplemented


def _hash_FrameChecksum(self: Any) -> int:
    return hash((self.algorithm, self.format, self.first, self.last, self.with_request, self.seed))


_set_FrameOptional_count = _unbound


def _init_FrameOptional(self: Any, count: Any) -> None:
    _set_FrameOptional_count(self, count)


def _repr_FrameOptional(self: Any) -> str:
    return f"{self.__class__.__qualname__}(count={self.count!r})"


def _eq_FrameOptional(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.count,) == (other.count,)
    return NotImplemented


def _hash_FrameOptional(self: Any) -> int:
    return hash((self.count,))


_set_BitField_name = _set_BitField_width = _set_BitField_value = _set_BitField_adjust = _unbound


def _init_BitField(self: Any, name: Any, width: Any, value: Any = DEFAULT, adjust: Any = DEFAULT) -> None:
    _set_BitField_name(self, name)
    _set_BitField_width(self, width)
    _set_BitField_value(self, value)
    _set_BitField_adjust(self, adjust)


def _repr_BitField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, width={self.width!r}, value={self.value!r}, adjust={self.adjust!r})"


def _eq_BitField(self: Any, other: Any) -> Any:
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


def _hash_BitField(self: Any) -> int:
    return hash((self.name, self.width, self.value, self.adjust))


_set_FrameBits_format = _set_FrameBits_fields = _set_FrameBits_layout = _unbound


def _init_FrameBits(self: Any, format: Any, fields: Any, layout: Any) -> None:
    _set_FrameBits_format(self, format)
    _set_FrameBits_fields(self, fields)
    _set_FrameBits_layout(self, layout)


def _repr_FrameBits(self: Any) -> str:
    return f"{self.__class__.__qualname__}(format={self.format!r}, fields={self.fields!r})"


def _eq_FrameBits(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.format, self.fields) == (other.format, other.fields)
    return NotImplemented


def _hash_FrameBits(self: Any) -> int:
    return hash((self.format, self.fields))


_set_Escaping_escape = _set_Escaping_table = _unbound


def _init_Escaping(self: Any, escape: Any, table: Any) -> None:
    _set_Escaping_escape(self, escape)
    _set_Escaping_table(self, table)


def _repr_Escaping(self: Any) -> str:
    return f"{self.__class__.__qualname__}(escape={self.escape!r}, table={self.table!r})"


def _eq_Escaping(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.escape, self.table) == (other.escape, other.table)
    return NotImplemented


def _hash_Escaping(self: Any) -> int:
    return hash((self.escape, self.table))


_set_Frame_name = _unbound
_set_Frame_params = _unbound
_set_Frame_request = _unbound
_set_Frame_reply = _unbound
_set_Frame_doc = _unbound
_set_Frame_span = _unbound
_set_Frame_stuffing = _unbound
_set_Frame_more_requests = _unbound
_set_Frame_more_replies = _unbound
_set_Frame_escaping = _unbound
_set_Frame_request_when = _unbound
_set_Frame_reply_when = _unbound


def _init_Frame(
    self: Any,
    name: Any,
    params: Any,
    request: Any,
    reply: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    stuffing: Any = DEFAULT,
    more_requests: Any = DEFAULT,
    more_replies: Any = DEFAULT,
    escaping: Any = DEFAULT,
    request_when: Any = DEFAULT,
    reply_when: Any = DEFAULT,
) -> None:
    _set_Frame_name(self, name)
    _set_Frame_params(self, params)
    _set_Frame_request(self, request)
    _set_Frame_reply(self, reply)
    _set_Frame_doc(self, doc)
    _set_Frame_span(self, span)
    _set_Frame_stuffing(self, stuffing)
    _set_Frame_more_requests(self, more_requests)
    _set_Frame_more_replies(self, more_replies)
    _set_Frame_escaping(self, escaping)
    _set_Frame_request_when(self, request_when)
    _set_Frame_reply_when(self, reply_when)


def _repr_Frame(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, request={self.request!r}, reply={self.reply!r}, doc={self.doc!r}, stuffing={self.stuffing!r}, more_requests={self.more_requests!r}, more_replies={self.more_replies!r}, escaping={self.escaping!r}, request_when={self.request_when!r}, reply_when={self.reply_when!r})"


def _eq_Frame(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.request,
            self.reply,
            self.doc,
            self.stuffing,
            self.more_requests,
            self.more_replies,
            self.escaping,
            self.request_when,
            self.reply_when,
        ) == (
            other.name,
            other.params,
            other.request,
            other.reply,
            other.doc,
            other.stuffing,
            other.more_requests,
            other.more_replies,
            other.escaping,
            other.request_when,
            other.reply_when,
        )
    return NotImplemented


def _hash_Frame(self: Any) -> int:
    return hash((
        self.name,
        self.params,
        self.request,
        self.reply,
        self.doc,
        self.stuffing,
        self.more_requests,
        self.more_replies,
        self.escaping,
        self.request_when,
        self.reply_when,
    ))


_set_FrameUse_frame = _set_FrameUse_args = _unbound


def _init_FrameUse(self: Any, frame: Any, args: Any) -> None:
    _set_FrameUse_frame(self, frame)
    _set_FrameUse_args(self, args)


def _repr_FrameUse(self: Any) -> str:
    return f"{self.__class__.__qualname__}(frame={self.frame!r}, args={self.args!r})"


def _eq_FrameUse(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.frame, self.args) == (other.frame, other.args)
    return NotImplemented


def _hash_FrameUse(self: Any) -> int:
    return hash((self.frame, self.args))


_set_ReplyCase_value = _unbound
_set_ReplyCase_decoding = _unbound
_set_ReplyCase_actions = _unbound
_set_ReplyCase_last = _unbound
_set_ReplyCase_under = _unbound
_set_ReplyCase_under_tag = _unbound
_set_ReplyCase_under_layout = _unbound


def _init_ReplyCase(
    self: Any,
    value: Any,
    decoding: Any,
    actions: Any = DEFAULT,
    last: Any = DEFAULT,
    under: Any = DEFAULT,
    under_tag: Any = DEFAULT,
    under_layout: Any = DEFAULT,
) -> None:
    _set_ReplyCase_value(self, value)
    _set_ReplyCase_decoding(self, decoding)
    _set_ReplyCase_actions(self, actions)
    _set_ReplyCase_last(self, last)
    _set_ReplyCase_under(self, under)
    _set_ReplyCase_under_tag(self, under_tag)
    _set_ReplyCase_under_layout(self, under_layout)


def _repr_ReplyCase(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r}, decoding={self.decoding!r}, actions={self.actions!r}, last={self.last!r}, under={self.under!r}, under_tag={self.under_tag!r})"


def _eq_ReplyCase(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.value,
            self.decoding,
            self.actions,
            self.last,
            self.under,
            self.under_tag,
        ) == (
            other.value,
            other.decoding,
            other.actions,
            other.last,
            other.under,
            other.under_tag,
        )
    return NotImplemented


def _hash_ReplyCase(self: Any) -> int:
    return hash((self.value, self.decoding, self.actions, self.last, self.under, self.under_tag))


_set_ListedReply_decoding = _unbound
_set_ListedReply_frame = _unbound
_set_ListedReply_expect = _unbound
_set_ListedReply_actions = _unbound


def _init_ListedReply(
    self: Any,
    decoding: Any,
    frame: Any = DEFAULT,
    expect: Any = DEFAULT,
    actions: Any = DEFAULT,
) -> None:
    _set_ListedReply_decoding(self, decoding)
    _set_ListedReply_frame(self, frame)
    _set_ListedReply_expect(self, expect)
    _set_ListedReply_actions(self, actions)


def _repr_ListedReply(self: Any) -> str:
    return f"{self.__class__.__qualname__}(decoding={self.decoding!r}, frame={self.frame!r}, expect={self.expect!r}, actions={self.actions!r})"


def _eq_ListedReply(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.decoding,
            self.frame,
            self.expect,
            self.actions,
        ) == (
            other.decoding,
            other.frame,
            other.expect,
            other.actions,
        )
    return NotImplemented


def _hash_ListedReply(self: Any) -> int:
    return hash((self.decoding, self.frame, self.expect, self.actions))


_set_RepliesEach_var = _set_RepliesEach_over = _unbound


def _init_RepliesEach(self: Any, var: Any, over: Any) -> None:
    _set_RepliesEach_var(self, var)
    _set_RepliesEach_over(self, over)


def _repr_RepliesEach(self: Any) -> str:
    return f"{self.__class__.__qualname__}(var={self.var!r}, over={self.over!r})"


def _eq_RepliesEach(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.var, self.over) == (other.var, other.over)
    return NotImplemented


def _hash_RepliesEach(self: Any) -> int:
    return hash((self.var, self.over))


_set_ErrorReply_decoding = _unbound
_set_ErrorReply_frame = _unbound
_set_ErrorReply_marker = _unbound
_set_ErrorReply_codes = _unbound
_set_ErrorReply_when = _unbound


def _init_ErrorReply(
    self: Any,
    decoding: Any,
    frame: Any = DEFAULT,
    marker: Any = DEFAULT,
    codes: Any = DEFAULT,
    when: Any = DEFAULT,
) -> None:
    _set_ErrorReply_decoding(self, decoding)
    _set_ErrorReply_frame(self, frame)
    _set_ErrorReply_marker(self, marker)
    _set_ErrorReply_codes(self, codes)
    _set_ErrorReply_when(self, when)


def _repr_ErrorReply(self: Any) -> str:
    return f"{self.__class__.__qualname__}(decoding={self.decoding!r}, frame={self.frame!r}, marker={self.marker!r}, codes={self.codes!r}, when={self.when!r})"


def _eq_ErrorReply(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.decoding,
            self.frame,
            self.marker,
            self.codes,
            self.when,
        ) == (
            other.decoding,
            other.frame,
            other.marker,
            other.codes,
            other.when,
        )
    return NotImplemented


def _hash_ErrorReply(self: Any) -> int:
    return hash((self.decoding, self.frame, self.marker, self.codes, self.when))


_set_ReplyTable_key = _unbound
_set_ReplyTable_cases = _unbound
_set_ReplyTable_tag = _unbound
_set_ReplyTable_each = _unbound
_set_ReplyTable_length = _unbound
_set_ReplyTable_tag_layout = _unbound
_set_ReplyTable_length_layout = _unbound


def _init_ReplyTable(
    self: Any,
    key: Any,
    cases: Any,
    tag: Any = DEFAULT,
    each: Any = DEFAULT,
    length: Any = DEFAULT,
    tag_layout: Any = DEFAULT,
    length_layout: Any = DEFAULT,
) -> None:
    _set_ReplyTable_key(self, key)
    _set_ReplyTable_cases(self, cases)
    _set_ReplyTable_tag(self, tag)
    _set_ReplyTable_each(self, each)
    _set_ReplyTable_length(self, length)
    _set_ReplyTable_tag_layout(self, tag_layout)
    _set_ReplyTable_length_layout(self, length_layout)


def _repr_ReplyTable(self: Any) -> str:
    return f"{self.__class__.__qualname__}(key={self.key!r}, cases={self.cases!r}, tag={self.tag!r}, each={self.each!r}, length={self.length!r})"


def _eq_ReplyTable(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.key,
            self.cases,
            self.tag,
            self.each,
            self.length,
        ) == (
            other.key,
            other.cases,
            other.tag,
            other.each,
            other.length,
        )
    return NotImplemented


def _hash_ReplyTable(self: Any) -> int:
    return hash((self.key, self.cases, self.tag, self.each, self.length))


_set_Primitive_name = _unbound
_set_Primitive_params = _unbound
_set_Primitive_connection = _unbound
_set_Primitive_encoding = _unbound
_set_Primitive_args = _unbound
_set_Primitive_decoding = _unbound
_set_Primitive_actions = _unbound
_set_Primitive_doc = _unbound
_set_Primitive_span = _unbound
_set_Primitive_frame = _unbound
_set_Primitive_skip_unmatched = _unbound
_set_Primitive_table = _unbound
_set_Primitive_timeout_ms = _unbound
_set_Primitive_expect = _unbound
_set_Primitive_lines = _unbound
_set_Primitive_replies = _unbound
_set_Primitive_reply_frames = _unbound
_set_Primitive_records = _unbound
_set_Primitive_listed = _unbound
_set_Primitive_retries = _unbound
_set_Primitive_error = _unbound
_set_Primitive_each = _unbound


def _init_Primitive(
    self: Any,
    name: Any,
    params: Any,
    connection: Any,
    encoding: Any,
    args: Any,
    decoding: Any = DEFAULT,
    actions: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    frame: Any = DEFAULT,
    skip_unmatched: Any = DEFAULT,
    table: Any = DEFAULT,
    timeout_ms: Any = DEFAULT,
    expect: Any = DEFAULT,
    lines: Any = DEFAULT,
    replies: Any = DEFAULT,
    reply_frames: Any = DEFAULT,
    records: Any = DEFAULT,
    listed: Any = DEFAULT,
    retries: Any = DEFAULT,
    error: Any = DEFAULT,
    each: Any = DEFAULT,
) -> None:
    _set_Primitive_name(self, name)
    _set_Primitive_params(self, params)
    _set_Primitive_connection(self, connection)
    _set_Primitive_encoding(self, encoding)
    _set_Primitive_args(self, args)
    _set_Primitive_decoding(self, decoding)
    _set_Primitive_actions(self, actions)
    _set_Primitive_doc(self, doc)
    _set_Primitive_span(self, span)
    _set_Primitive_frame(self, frame)
    _set_Primitive_skip_unmatched(self, skip_unmatched)
    _set_Primitive_table(self, table)
    _set_Primitive_timeout_ms(self, timeout_ms)
    _set_Primitive_expect(self, expect)
    _set_Primitive_lines(self, lines)
    _set_Primitive_replies(self, replies)
    _set_Primitive_reply_frames(self, reply_frames)
    _set_Primitive_records(self, records)
    _set_Primitive_listed(self, listed)
    _set_Primitive_retries(self, retries)
    _set_Primitive_error(self, error)
    _set_Primitive_each(self, each)


def _repr_Primitive(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, connection={self.connection!r}, encoding={self.encoding!r}, args={self.args!r}, decoding={self.decoding!r}, actions={self.actions!r}, doc={self.doc!r}, frame={self.frame!r}, skip_unmatched={self.skip_unmatched!r}, table={self.table!r}, timeout_ms={self.timeout_ms!r}, expect={self.expect!r}, lines={self.lines!r}, replies={self.replies!r}, reply_frames={self.reply_frames!r}, records={self.records!r}, listed={self.listed!r}, retries={self.retries!r}, error={self.error!r}, each={self.each!r})"


def _eq_Primitive(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.connection,
            self.encoding,
            self.args,
            self.decoding,
            self.actions,
            self.doc,
            self.frame,
            self.skip_unmatched,
            self.table,
            self.timeout_ms,
            self.expect,
            self.lines,
            self.replies,
            self.reply_frames,
            self.records,
            self.listed,
            self.retries,
            self.error,
            self.each,
        ) == (
            other.name,
            other.params,
            other.connection,
            other.encoding,
            other.args,
            other.decoding,
            other.actions,
            other.doc,
            other.frame,
            other.skip_unmatched,
            other.table,
            other.timeout_ms,
            other.expect,
            other.lines,
            other.replies,
            other.reply_frames,
            other.records,
            other.listed,
            other.retries,
            other.error,
            other.each,
        )
    return NotImplemented


def _hash_Primitive(self: Any) -> int:
    return hash((
        self.name,
        self.params,
        self.connection,
        self.encoding,
        self.args,
        self.decoding,
        self.actions,
        self.doc,
        self.frame,
        self.skip_unmatched,
        self.table,
        self.timeout_ms,
        self.expect,
        self.lines,
        self.replies,
        self.reply_frames,
        self.records,
        self.listed,
        self.retries,
        self.error,
        self.each,
    ))


_set_PrimitiveCall_primitive = _unbound
_set_PrimitiveCall_args = _unbound
_set_PrimitiveCall_delay_ms = _unbound
_set_PrimitiveCall_priority = _unbound
_set_PrimitiveCall_span = _unbound
_set_PrimitiveCall_interface = _unbound
_set_PrimitiveCall_when = _unbound
_set_PrimitiveCall_until = _unbound
_set_PrimitiveCall_every_ms = _unbound
_set_PrimitiveCall_within_ms = _unbound


def _init_PrimitiveCall(
    self: Any,
    primitive: Any,
    args: Any,
    delay_ms: Any = DEFAULT,
    priority: Any = DEFAULT,
    span: Any = DEFAULT,
    interface: Any = DEFAULT,
    when: Any = DEFAULT,
    until: Any = DEFAULT,
    every_ms: Any = DEFAULT,
    within_ms: Any = DEFAULT,
) -> None:
    _set_PrimitiveCall_primitive(self, primitive)
    _set_PrimitiveCall_args(self, args)
    _set_PrimitiveCall_delay_ms(self, delay_ms)
    _set_PrimitiveCall_priority(self, priority)
    _set_PrimitiveCall_span(self, span)
    _set_PrimitiveCall_interface(self, interface)
    _set_PrimitiveCall_when(self, when)
    _set_PrimitiveCall_until(self, until)
    _set_PrimitiveCall_every_ms(self, every_ms)
    _set_PrimitiveCall_within_ms(self, within_ms)


def _repr_PrimitiveCall(self: Any) -> str:
    return f"{self.__class__.__qualname__}(primitive={self.primitive!r}, args={self.args!r}, delay_ms={self.delay_ms!r}, priority={self.priority!r}, interface={self.interface!r}, when={self.when!r}, until={self.until!r}, every_ms={self.every_ms!r}, within_ms={self.within_ms!r})"


def _eq_PrimitiveCall(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.primitive,
            self.args,
            self.delay_ms,
            self.priority,
            self.interface,
            self.when,
            self.until,
            self.every_ms,
            self.within_ms,
        ) == (
            other.primitive,
            other.args,
            other.delay_ms,
            other.priority,
            other.interface,
            other.when,
            other.until,
            other.every_ms,
            other.within_ms,
        )
    return NotImplemented


def _hash_PrimitiveCall(self: Any) -> int:
    return hash((
        self.primitive,
        self.args,
        self.delay_ms,
        self.priority,
        self.interface,
        self.when,
        self.until,
        self.every_ms,
        self.within_ms,
    ))


_set_Interface_name = _unbound
_set_Interface_params = _unbound
_set_Interface_periodic = _unbound
_set_Interface_calls = _unbound
_set_Interface_triggers = _unbound
_set_Interface_doc = _unbound
_set_Interface_span = _unbound
_set_Interface_rate_hz = _unbound


def _init_Interface(
    self: Any,
    name: Any,
    params: Any,
    periodic: Any,
    calls: Any,
    triggers: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    rate_hz: Any = DEFAULT,
) -> None:
    _set_Interface_name(self, name)
    _set_Interface_params(self, params)
    _set_Interface_periodic(self, periodic)
    _set_Interface_calls(self, calls)
    _set_Interface_triggers(self, triggers)
    _set_Interface_doc(self, doc)
    _set_Interface_span(self, span)
    _set_Interface_rate_hz(self, rate_hz)


def _repr_Interface(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, periodic={self.periodic!r}, calls={self.calls!r}, triggers={self.triggers!r}, doc={self.doc!r}, rate_hz={self.rate_hz!r})"


def _eq_Interface(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.periodic,
            self.calls,
            self.triggers,
            self.doc,
            self.rate_hz,
        ) == (
            other.name,
            other.params,
            other.periodic,
            other.calls,
            other.triggers,
            other.doc,
            other.rate_hz,
        )
    return NotImplemented


def _hash_Interface(self: Any) -> int:
    return hash((self.name, self.params, self.periodic, self.calls, self.triggers, self.doc, self.rate_hz))


_set_AdapterField_name = _unbound
_set_AdapterField_type = _unbound
_set_AdapterField_unit = _unbound
_set_AdapterField_ros = _unbound
_set_AdapterField_doc = _unbound


def _init_AdapterField(
    self: Any,
    name: Any,
    type: Any,
    unit: Any = DEFAULT,
    ros: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_AdapterField_name(self, name)
    _set_AdapterField_type(self, type)
    _set_AdapterField_unit(self, unit)
    _set_AdapterField_ros(self, ros)
    _set_AdapterField_doc(self, doc)


def _repr_AdapterField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, unit={self.unit!r}, ros={self.ros!r}, doc={self.doc!r})"


def _eq_AdapterField(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.unit,
            self.ros,
            self.doc,
        ) == (
            other.name,
            other.type,
            other.unit,
            other.ros,
            other.doc,
        )
    return NotImplemented


def _hash_AdapterField(self: Any) -> int:
    return hash((self.name, self.type, self.unit, self.ros, self.doc))


_set_FrameworkMapping_framework = _unbound
_set_FrameworkMapping_title = _unbound
_set_FrameworkMapping_type = _unbound
_set_FrameworkMapping_paths = _unbound
_set_FrameworkMapping_schema_encoding = _unbound
_set_FrameworkMapping_message_encoding = _unbound


def _init_FrameworkMapping(
    self: Any,
    framework: Any,
    title: Any,
    type: Any,
    paths: Any,
    schema_encoding: Any = DEFAULT,
    message_encoding: Any = DEFAULT,
) -> None:
    _set_FrameworkMapping_framework(self, framework)
    _set_FrameworkMapping_title(self, title)
    _set_FrameworkMapping_type(self, type)
    _set_FrameworkMapping_paths(self, paths)
    _set_FrameworkMapping_schema_encoding(self, schema_encoding)
    _set_FrameworkMapping_message_encoding(self, message_encoding)


def _repr_FrameworkMapping(self: Any) -> str:
    return f"{self.__class__.__qualname__}(framework={self.framework!r}, title={self.title!r}, type={self.type!r}, paths={self.paths!r}, schema_encoding={self.schema_encoding!r}, message_encoding={self.message_encoding!r})"


def _eq_FrameworkMapping(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.framework,
            self.title,
            self.type,
            self.paths,
            self.schema_encoding,
            self.message_encoding,
        ) == (
            other.framework,
            other.title,
            other.type,
            other.paths,
            other.schema_encoding,
            other.message_encoding,
        )
    return NotImplemented


def _hash_FrameworkMapping(self: Any) -> int:
    return hash((
        self.framework,
        self.title,
        self.type,
        self.paths,
        self.schema_encoding,
        self.message_encoding,
    ))


_set_Adapter_name = _unbound
_set_Adapter_fields = _unbound
_set_Adapter_ros = _unbound
_set_Adapter_standard = _unbound
_set_Adapter_doc = _unbound
_set_Adapter_span = _unbound
_set_Adapter_frameworks = _unbound


def _init_Adapter(
    self: Any,
    name: Any,
    fields: Any,
    ros: Any = DEFAULT,
    standard: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    frameworks: Any = DEFAULT,
) -> None:
    _set_Adapter_name(self, name)
    _set_Adapter_fields(self, fields)
    _set_Adapter_ros(self, ros)
    _set_Adapter_standard(self, standard)
    _set_Adapter_doc(self, doc)
    _set_Adapter_span(self, span)
    _set_Adapter_frameworks(self, frameworks)


def _repr_Adapter(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, fields={self.fields!r}, ros={self.ros!r}, standard={self.standard!r}, doc={self.doc!r}, frameworks={self.frameworks!r})"


def _eq_Adapter(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.fields,
            self.ros,
            self.standard,
            self.doc,
            self.frameworks,
        ) == (
            other.name,
            other.fields,
            other.ros,
            other.standard,
            other.doc,
            other.frameworks,
        )
    return NotImplemented


def _hash_Adapter(self: Any) -> int:
    return hash((self.name, self.fields, self.ros, self.standard, self.doc, self.frameworks))


_set_DomainInput_name = _unbound
_set_DomainInput_adapter = _unbound
_set_DomainInput_interface = _unbound
_set_DomainInput_args = _unbound
_set_DomainInput_doc = _unbound
_set_DomainInput_span = _unbound


def _init_DomainInput(
    self: Any,
    name: Any,
    adapter: Any,
    interface: Any,
    args: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_DomainInput_name(self, name)
    _set_DomainInput_adapter(self, adapter)
    _set_DomainInput_interface(self, interface)
    _set_DomainInput_args(self, args)
    _set_DomainInput_doc(self, doc)
    _set_DomainInput_span(self, span)


def _repr_DomainInput(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, adapter={self.adapter!r}, interface={self.interface!r}, args={self.args!r}, doc={self.doc!r})"


def _eq_DomainInput(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.adapter,
            self.interface,
            self.args,
            self.doc,
        ) == (
            other.name,
            other.adapter,
            other.interface,
            other.args,
            other.doc,
        )
    return NotImplemented


def _hash_DomainInput(self: Any) -> int:
    return hash((self.name, self.adapter, self.interface, self.args, self.doc))


_set_Noise_field = _unbound
_set_Noise_covariance = _unbound
_set_Noise_deviation = _unbound
_set_Noise_unit = _unbound
_set_Noise_span = _unbound
_set_Noise_others = _unbound


def _init_Noise(
    self: Any,
    field: Any,
    covariance: Any,
    deviation: Any = DEFAULT,
    unit: Any = DEFAULT,
    span: Any = DEFAULT,
    others: Any = DEFAULT,
) -> None:
    _set_Noise_field(self, field)
    _set_Noise_covariance(self, covariance)
    _set_Noise_deviation(self, deviation)
    _set_Noise_unit(self, unit)
    _set_Noise_span(self, span)
    _set_Noise_others(self, others)


def _repr_Noise(self: Any) -> str:
    return f"{self.__class__.__qualname__}(field={self.field!r}, covariance={self.covariance!r}, deviation={self.deviation!r}, unit={self.unit!r}, others={self.others!r})"


def _eq_Noise(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.field,
            self.covariance,
            self.deviation,
            self.unit,
            self.others,
        ) == (
            other.field,
            other.covariance,
            other.deviation,
            other.unit,
            other.others,
        )
    return NotImplemented


def _hash_Noise(self: Any) -> int:
    return hash((self.field, self.covariance, self.deviation, self.unit, self.others))


_set_Kalman_field = _unbound
_set_Kalman_state = _unbound
_set_Kalman_covariance = _unbound
_set_Kalman_transition = _unbound
_set_Kalman_process = _unbound
_set_Kalman_measurement = _unbound
_set_Kalman_noise = _unbound
_set_Kalman_span = _unbound


def _init_Kalman(
    self: Any,
    field: Any,
    state: Any,
    covariance: Any,
    transition: Any,
    process: Any,
    measurement: Any,
    noise: Any,
    span: Any = DEFAULT,
) -> None:
    _set_Kalman_field(self, field)
    _set_Kalman_state(self, state)
    _set_Kalman_covariance(self, covariance)
    _set_Kalman_transition(self, transition)
    _set_Kalman_process(self, process)
    _set_Kalman_measurement(self, measurement)
    _set_Kalman_noise(self, noise)
    _set_Kalman_span(self, span)


def _repr_Kalman(self: Any) -> str:
    return f"{self.__class__.__qualname__}(field={self.field!r}, state={self.state!r}, covariance={self.covariance!r}, transition={self.transition!r}, process={self.process!r}, measurement={self.measurement!r}, noise={self.noise!r})"


def _eq_Kalman(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.field,
            self.state,
            self.covariance,
            self.transition,
            self.process,
            self.measurement,
            self.noise,
        ) == (
            other.field,
            other.state,
            other.covariance,
            other.transition,
            other.process,
            other.measurement,
            other.noise,
        )
    return NotImplemented


def _hash_Kalman(self: Any) -> int:
    return hash((
        self.field,
        self.state,
        self.covariance,
        self.transition,
        self.process,
        self.measurement,
        self.noise,
    ))


_set_DomainOutput_name = _unbound
_set_DomainOutput_adapter = _unbound
_set_DomainOutput_fields = _unbound
_set_DomainOutput_doc = _unbound
_set_DomainOutput_span = _unbound
_set_DomainOutput_frame = _unbound
_set_DomainOutput_noise = _unbound
_set_DomainOutput_filters = _unbound


def _init_DomainOutput(
    self: Any,
    name: Any,
    adapter: Any,
    fields: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    frame: Any = DEFAULT,
    noise: Any = DEFAULT,
    filters: Any = DEFAULT,
) -> None:
    _set_DomainOutput_name(self, name)
    _set_DomainOutput_adapter(self, adapter)
    _set_DomainOutput_fields(self, fields)
    _set_DomainOutput_doc(self, doc)
    _set_DomainOutput_span(self, span)
    _set_DomainOutput_frame(self, frame)
    _set_DomainOutput_noise(self, noise)
    _set_DomainOutput_filters(self, filters)


def _repr_DomainOutput(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, adapter={self.adapter!r}, fields={self.fields!r}, doc={self.doc!r}, frame={self.frame!r}, noise={self.noise!r}, filters={self.filters!r})"


def _eq_DomainOutput(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.adapter,
            self.fields,
            self.doc,
            self.frame,
            self.noise,
            self.filters,
        ) == (
            other.name,
            other.adapter,
            other.fields,
            other.doc,
            other.frame,
            other.noise,
            other.filters,
        )
    return NotImplemented


def _hash_DomainOutput(self: Any) -> int:
    return hash((self.name, self.adapter, self.fields, self.doc, self.frame, self.noise, self.filters))


_set_Pose_xyz = _set_Pose_rpy = _unbound


def _init_Pose(self: Any, xyz: Any = DEFAULT, rpy: Any = DEFAULT) -> None:
    _set_Pose_xyz(self, xyz)
    _set_Pose_rpy(self, rpy)


def _repr_Pose(self: Any) -> str:
    return f"{self.__class__.__qualname__}(xyz={self.xyz!r}, rpy={self.rpy!r})"


def _eq_Pose(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.xyz, self.rpy) == (other.xyz, other.rpy)
    return NotImplemented


def _hash_Pose(self: Any) -> int:
    return hash((self.xyz, self.rpy))


_set_Shape_kind = _unbound
_set_Shape_size = _unbound
_set_Shape_origin = _unbound
_set_Shape_path = _unbound
_set_Shape_span = _unbound
_set_Shape_color = _unbound
_set_Shape_expressions = _unbound


def _init_Shape(
    self: Any,
    kind: Any,
    size: Any,
    origin: Any = DEFAULT,
    path: Any = DEFAULT,
    span: Any = DEFAULT,
    color: Any = DEFAULT,
    expressions: Any = DEFAULT,
) -> None:
    _set_Shape_kind(self, kind)
    _set_Shape_size(self, size)
    _set_Shape_origin(self, origin)
    _set_Shape_path(self, path)
    _set_Shape_span(self, span)
    _set_Shape_color(self, color)
    _set_Shape_expressions(self, expressions)


def _repr_Shape(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, size={self.size!r}, origin={self.origin!r}, path={self.path!r}, color={self.color!r}, expressions={self.expressions!r})"


def _eq_Shape(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.kind,
            self.size,
            self.origin,
            self.path,
            self.color,
            self.expressions,
        ) == (
            other.kind,
            other.size,
            other.origin,
            other.path,
            other.color,
            other.expressions,
        )
    return NotImplemented


def _hash_Shape(self: Any) -> int:
    return hash((self.kind, self.size, self.origin, self.path, self.color, self.expressions))


_set_Inertial_mass = _set_Inertial_centre = _set_Inertial_inertia = _set_Inertial_expressions = _unbound


def _init_Inertial(self: Any, mass: Any, centre: Any, inertia: Any, expressions: Any = DEFAULT) -> None:
    _set_Inertial_mass(self, mass)
    _set_Inertial_centre(self, centre)
    _set_Inertial_inertia(self, inertia)
    _set_Inertial_expressions(self, expressions)


def _repr_Inertial(self: Any) -> str:
    return f"{self.__class__.__qualname__}(mass={self.mass!r}, centre={self.centre!r}, inertia={self.inertia!r}, expressions={self.expressions!r})"


def _eq_Inertial(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.mass,
            self.centre,
            self.inertia,
            self.expressions,
        ) == (
            other.mass,
            other.centre,
            other.inertia,
            other.expressions,
        )
    return NotImplemented


def _hash_Inertial(self: Any) -> int:
    return hash((self.mass, self.centre, self.inertia, self.expressions))


_set_Link_name = _unbound
_set_Link_visuals = _unbound
_set_Link_collisions = _unbound
_set_Link_inertial = _unbound
_set_Link_doc = _unbound
_set_Link_span = _unbound
_set_Link_spawn = _unbound


def _init_Link(
    self: Any,
    name: Any,
    visuals: Any = DEFAULT,
    collisions: Any = DEFAULT,
    inertial: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    spawn: Any = DEFAULT,
) -> None:
    _set_Link_name(self, name)
    _set_Link_visuals(self, visuals)
    _set_Link_collisions(self, collisions)
    _set_Link_inertial(self, inertial)
    _set_Link_doc(self, doc)
    _set_Link_span(self, span)
    _set_Link_spawn(self, spawn)


def _repr_Link(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, visuals={self.visuals!r}, collisions={self.collisions!r}, inertial={self.inertial!r}, doc={self.doc!r}, spawn={self.spawn!r})"


def _eq_Link(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.visuals,
            self.collisions,
            self.inertial,
            self.doc,
            self.spawn,
        ) == (
            other.name,
            other.visuals,
            other.collisions,
            other.inertial,
            other.doc,
            other.spawn,
        )
    return NotImplemented


def _hash_Link(self: Any) -> int:
    return hash((self.name, self.visuals, self.collisions, self.inertial, self.doc, self.spawn))


_set_Spawn_floating = _set_Spawn_pose = _set_Spawn_expressions = _unbound


def _init_Spawn(self: Any, floating: Any, pose: Any = DEFAULT, expressions: Any = DEFAULT) -> None:
    _set_Spawn_floating(self, floating)
    _set_Spawn_pose(self, pose)
    _set_Spawn_expressions(self, expressions)


def _repr_Spawn(self: Any) -> str:
    return f"{self.__class__.__qualname__}(floating={self.floating!r}, pose={self.pose!r}, expressions={self.expressions!r})"


def _eq_Spawn(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.floating, self.pose, self.expressions) == (other.floating, other.pose, other.expressions)
    return NotImplemented


def _hash_Spawn(self: Any) -> int:
    return hash((self.floating, self.pose, self.expressions))


_set_Mimic_joint = _set_Mimic_multiplier = _set_Mimic_offset = _unbound


def _init_Mimic(self: Any, joint: Any, multiplier: Any = DEFAULT, offset: Any = DEFAULT) -> None:
    _set_Mimic_joint(self, joint)
    _set_Mimic_multiplier(self, multiplier)
    _set_Mimic_offset(self, offset)


def _repr_Mimic(self: Any) -> str:
    return f"{self.__class__.__qualname__}(joint={self.joint!r}, multiplier={self.multiplier!r}, offset={self.offset!r})"


def _eq_Mimic(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.joint, self.multiplier, self.offset) == (other.joint, other.multiplier, other.offset)
    return NotImplemented


def _hash_Mimic(self: Any) -> int:
    return hash((self.joint, self.multiplier, self.offset))


_set_Joint_name = _unbound
_set_Joint_kind = _unbound
_set_Joint_parent = _unbound
_set_Joint_child = _unbound
_set_Joint_origin = _unbound
_set_Joint_axis = _unbound
_set_Joint_lower = _unbound
_set_Joint_upper = _unbound
_set_Joint_velocity = _unbound
_set_Joint_effort = _unbound
_set_Joint_damping = _unbound
_set_Joint_friction = _unbound
_set_Joint_doc = _unbound
_set_Joint_span = _unbound
_set_Joint_mimic = _unbound
_set_Joint_expressions = _unbound


def _init_Joint(
    self: Any,
    name: Any,
    kind: Any,
    parent: Any,
    child: Any,
    origin: Any = DEFAULT,
    axis: Any = DEFAULT,
    lower: Any = DEFAULT,
    upper: Any = DEFAULT,
    velocity: Any = DEFAULT,
    effort: Any = DEFAULT,
    damping: Any = DEFAULT,
    friction: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    mimic: Any = DEFAULT,
    expressions: Any = DEFAULT,
) -> None:
    _set_Joint_name(self, name)
    _set_Joint_kind(self, kind)
    _set_Joint_parent(self, parent)
    _set_Joint_child(self, child)
    _set_Joint_origin(self, origin)
    _set_Joint_axis(self, axis)
    _set_Joint_lower(self, lower)
    _set_Joint_upper(self, upper)
    _set_Joint_velocity(self, velocity)
    _set_Joint_effort(self, effort)
    _set_Joint_damping(self, damping)
    _set_Joint_friction(self, friction)
    _set_Joint_doc(self, doc)
    _set_Joint_span(self, span)
    _set_Joint_mimic(self, mimic)
    _set_Joint_expressions(self, expressions)


def _repr_Joint(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, kind={self.kind!r}, parent={self.parent!r}, child={self.child!r}, origin={self.origin!r}, axis={self.axis!r}, lower={self.lower!r}, upper={self.upper!r}, velocity={self.velocity!r}, effort={self.effort!r}, damping={self.damping!r}, friction={self.friction!r}, doc={self.doc!r}, mimic={self.mimic!r}, expressions={self.expressions!r})"


def _eq_Joint(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.kind,
            self.parent,
            self.child,
            self.origin,
            self.axis,
            self.lower,
            self.upper,
            self.velocity,
            self.effort,
            self.damping,
            self.friction,
            self.doc,
            self.mimic,
            self.expressions,
        ) == (
            other.name,
            other.kind,
            other.parent,
            other.child,
            other.origin,
            other.axis,
            other.lower,
            other.upper,
            other.velocity,
            other.effort,
            other.damping,
            other.friction,
            other.doc,
            other.mimic,
            other.expressions,
        )
    return NotImplemented


def _hash_Joint(self: Any) -> int:
    return hash((
        self.name,
        self.kind,
        self.parent,
        self.child,
        self.origin,
        self.axis,
        self.lower,
        self.upper,
        self.velocity,
        self.effort,
        self.damping,
        self.friction,
        self.doc,
        self.mimic,
        self.expressions,
    ))


_set_Binding_quantity = _unbound
_set_Binding_target = _unbound
_set_Binding_parameter = _unbound
_set_Binding_index = _unbound
_set_Binding_to_device = _unbound
_set_Binding_to_joint = _unbound
_set_Binding_interface = _unbound
_set_Binding_span = _unbound
_set_Binding_expressions = _unbound


def _init_Binding(
    self: Any,
    quantity: Any,
    target: Any,
    parameter: Any,
    index: Any,
    to_device: Any,
    to_joint: Any,
    interface: Any = DEFAULT,
    span: Any = DEFAULT,
    expressions: Any = DEFAULT,
) -> None:
    _set_Binding_quantity(self, quantity)
    _set_Binding_target(self, target)
    _set_Binding_parameter(self, parameter)
    _set_Binding_index(self, index)
    _set_Binding_to_device(self, to_device)
    _set_Binding_to_joint(self, to_joint)
    _set_Binding_interface(self, interface)
    _set_Binding_span(self, span)
    _set_Binding_expressions(self, expressions)


def _repr_Binding(self: Any) -> str:
    return f"{self.__class__.__qualname__}(quantity={self.quantity!r}, target={self.target!r}, parameter={self.parameter!r}, index={self.index!r}, to_device={self.to_device!r}, to_joint={self.to_joint!r}, interface={self.interface!r}, expressions={self.expressions!r})"


def _eq_Binding(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.quantity,
            self.target,
            self.parameter,
            self.index,
            self.to_device,
            self.to_joint,
            self.interface,
            self.expressions,
        ) == (
            other.quantity,
            other.target,
            other.parameter,
            other.index,
            other.to_device,
            other.to_joint,
            other.interface,
            other.expressions,
        )
    return NotImplemented


def _hash_Binding(self: Any) -> int:
    return hash((
        self.quantity,
        self.target,
        self.parameter,
        self.index,
        self.to_device,
        self.to_joint,
        self.interface,
        self.expressions,
    ))


_set_Transmission_name = _unbound
_set_Transmission_joint = _unbound
_set_Transmission_commands = _unbound
_set_Transmission_measures = _unbound
_set_Transmission_doc = _unbound
_set_Transmission_span = _unbound
_set_Transmission_actuator = _unbound


def _init_Transmission(
    self: Any,
    name: Any,
    joint: Any,
    commands: Any = DEFAULT,
    measures: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    actuator: Any = DEFAULT,
) -> None:
    _set_Transmission_name(self, name)
    _set_Transmission_joint(self, joint)
    _set_Transmission_commands(self, commands)
    _set_Transmission_measures(self, measures)
    _set_Transmission_doc(self, doc)
    _set_Transmission_span(self, span)
    _set_Transmission_actuator(self, actuator)


def _repr_Transmission(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, joint={self.joint!r}, commands={self.commands!r}, measures={self.measures!r}, doc={self.doc!r}, actuator={self.actuator!r})"


def _eq_Transmission(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.joint,
            self.commands,
            self.measures,
            self.doc,
            self.actuator,
        ) == (
            other.name,
            other.joint,
            other.commands,
            other.measures,
            other.doc,
            other.actuator,
        )
    return NotImplemented


def _hash_Transmission(self: Any) -> int:
    return hash((self.name, self.joint, self.commands, self.measures, self.doc, self.actuator))


_set_Actuator_name = _unbound
_set_Actuator_kind = _unbound
_set_Actuator_velocity = _unbound
_set_Actuator_acceleration = _unbound
_set_Actuator_effort = _unbound
_set_Actuator_gain = _unbound
_set_Actuator_damping = _unbound
_set_Actuator_doc = _unbound
_set_Actuator_span = _unbound
_set_Actuator_refuse = _unbound
_set_Actuator_expressions = _unbound


def _init_Actuator(
    self: Any,
    name: Any,
    kind: Any,
    velocity: Any = DEFAULT,
    acceleration: Any = DEFAULT,
    effort: Any = DEFAULT,
    gain: Any = DEFAULT,
    damping: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    refuse: Any = DEFAULT,
    expressions: Any = DEFAULT,
) -> None:
    _set_Actuator_name(self, name)
    _set_Actuator_kind(self, kind)
    _set_Actuator_velocity(self, velocity)
    _set_Actuator_acceleration(self, acceleration)
    _set_Actuator_effort(self, effort)
    _set_Actuator_gain(self, gain)
    _set_Actuator_damping(self, damping)
    _set_Actuator_doc(self, doc)
    _set_Actuator_span(self, span)
    _set_Actuator_refuse(self, refuse)
    _set_Actuator_expressions(self, expressions)


def _repr_Actuator(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, kind={self.kind!r}, velocity={self.velocity!r}, acceleration={self.acceleration!r}, effort={self.effort!r}, gain={self.gain!r}, damping={self.damping!r}, doc={self.doc!r}, refuse={self.refuse!r}, expressions={self.expressions!r})"


def _eq_Actuator(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.kind,
            self.velocity,
            self.acceleration,
            self.effort,
            self.gain,
            self.damping,
            self.doc,
            self.refuse,
            self.expressions,
        ) == (
            other.name,
            other.kind,
            other.velocity,
            other.acceleration,
            other.effort,
            other.gain,
            other.damping,
            other.doc,
            other.refuse,
            other.expressions,
        )
    return NotImplemented


def _hash_Actuator(self: Any) -> int:
    return hash((
        self.name,
        self.kind,
        self.velocity,
        self.acceleration,
        self.effort,
        self.gain,
        self.damping,
        self.doc,
        self.refuse,
        self.expressions,
    ))


_set_Model_robot = _unbound
_set_Model_states = _unbound
_set_Model_connections = _unbound
_set_Model_primitives = _unbound
_set_Model_interfaces = _unbound
_set_Model_adapters = _unbound
_set_Model_inputs = _unbound
_set_Model_outputs = _unbound
_set_Model_frames = _unbound
_set_Model_constants = _unbound
_set_Model_enums = _unbound
_set_Model_tables = _unbound
_set_Model_constant_docs = _unbound
_set_Model_enum_docs = _unbound
_set_Model_settings = _unbound
_set_Model_links = _unbound
_set_Model_joints = _unbound
_set_Model_transmissions = _unbound
_set_Model_sensors = _unbound
_set_Model_actuators = _unbound


def _init_Model(
    self: Any,
    robot: Any,
    states: Any,
    connections: Any,
    primitives: Any,
    interfaces: Any,
    adapters: Any,
    inputs: Any,
    outputs: Any,
    frames: Any = DEFAULT,
    constants: Any = DEFAULT,
    enums: Any = DEFAULT,
    tables: Any = DEFAULT,
    constant_docs: Any = DEFAULT,
    enum_docs: Any = DEFAULT,
    settings: Any = DEFAULT,
    links: Any = DEFAULT,
    joints: Any = DEFAULT,
    transmissions: Any = DEFAULT,
    sensors: Any = DEFAULT,
    actuators: Any = DEFAULT,
) -> None:
    _set_Model_robot(self, robot)
    _set_Model_states(self, states)
    _set_Model_connections(self, connections)
    _set_Model_primitives(self, primitives)
    _set_Model_interfaces(self, interfaces)
    _set_Model_adapters(self, adapters)
    _set_Model_inputs(self, inputs)
    _set_Model_outputs(self, outputs)
    _set_Model_frames(self, {} if frames is FACTORY else frames)
    _set_Model_constants(self, {} if constants is FACTORY else constants)
    _set_Model_enums(self, {} if enums is FACTORY else enums)
    _set_Model_tables(self, {} if tables is FACTORY else tables)
    _set_Model_constant_docs(self, {} if constant_docs is FACTORY else constant_docs)
    _set_Model_enum_docs(self, {} if enum_docs is FACTORY else enum_docs)
    _set_Model_settings(self, {} if settings is FACTORY else settings)
    _set_Model_links(self, {} if links is FACTORY else links)
    _set_Model_joints(self, {} if joints is FACTORY else joints)
    _set_Model_transmissions(self, {} if transmissions is FACTORY else transmissions)
    _set_Model_sensors(self, {} if sensors is FACTORY else sensors)
    _set_Model_actuators(self, {} if actuators is FACTORY else actuators)


def _repr_Model(self: Any) -> str:
    return f"{self.__class__.__qualname__}(robot={self.robot!r}, states={self.states!r}, connections={self.connections!r}, primitives={self.primitives!r}, interfaces={self.interfaces!r}, adapters={self.adapters!r}, inputs={self.inputs!r}, outputs={self.outputs!r}, frames={self.frames!r}, constants={self.constants!r}, enums={self.enums!r}, tables={self.tables!r}, constant_docs={self.constant_docs!r}, enum_docs={self.enum_docs!r}, settings={self.settings!r}, links={self.links!r}, joints={self.joints!r}, transmissions={self.transmissions!r}, sensors={self.sensors!r}, actuators={self.actuators!r})"


def _eq_Model(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.robot,
            self.states,
            self.connections,
            self.primitives,
            self.interfaces,
            self.adapters,
            self.inputs,
            self.outputs,
            self.frames,
            self.constants,
            self.enums,
            self.tables,
            self.constant_docs,
            self.enum_docs,
            self.settings,
            self.links,
            self.joints,
            self.transmissions,
            self.sensors,
            self.actuators,
        ) == (
            other.robot,
            other.states,
            other.connections,
            other.primitives,
            other.interfaces,
            other.adapters,
            other.inputs,
            other.outputs,
            other.frames,
            other.constants,
            other.enums,
            other.tables,
            other.constant_docs,
            other.enum_docs,
            other.settings,
            other.links,
            other.joints,
            other.transmissions,
            other.sensors,
            other.actuators,
        )
    return NotImplemented


def _hash_Model(self: Any) -> int:
    return hash((
        self.robot,
        self.states,
        self.connections,
        self.primitives,
        self.interfaces,
        self.adapters,
        self.inputs,
        self.outputs,
        self.frames,
        self.constants,
        self.enums,
        self.tables,
        self.constant_docs,
        self.enum_docs,
        self.settings,
        self.links,
        self.joints,
        self.transmissions,
        self.sensors,
        self.actuators,
    ))


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
    "Robot": Written(
        (
            ("name", MISSING),
            ("author", DEFAULT),
            ("description", DEFAULT),
            ("version", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_Robot, "__repr__": _repr_Robot, "__eq__": _eq_Robot, "__hash__": _hash_Robot},
    ),
    "StateVariable": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("initial", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("noise", DEFAULT),
        ),
        {
            "__init__": _init_StateVariable,
            "__repr__": _repr_StateVariable,
            "__eq__": _eq_StateVariable,
            "__hash__": _hash_StateVariable,
        },
    ),
    "Sensor": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("primitive", MISSING),
            ("cache_ms", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("noise", DEFAULT),
        ),
        {"__init__": _init_Sensor, "__repr__": _repr_Sensor, "__eq__": _eq_Sensor, "__hash__": _hash_Sensor},
    ),
    "Setting": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("default", MISSING),
            ("low", DEFAULT),
            ("high", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_Setting,
            "__repr__": _repr_Setting,
            "__eq__": _eq_Setting,
            "__hash__": _hash_Setting,
        },
    ),
    "HookCall": Written(
        (("interface", MISSING), ("args", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_HookCall,
            "__repr__": _repr_HookCall,
            "__eq__": _eq_HookCall,
            "__hash__": _hash_HookCall,
        },
    ),
    "Keepalive": Written(
        (("call", MISSING), ("interval_ms", MISSING)),
        {
            "__init__": _init_Keepalive,
            "__repr__": _repr_Keepalive,
            "__eq__": _eq_Keepalive,
            "__hash__": _hash_Keepalive,
        },
    ),
    "Connection": Written(
        (
            ("name", MISSING),
            ("kind", MISSING),
            ("baud", MISSING),
            ("frequency_hz", MISSING),
            ("startup", DEFAULT),
            ("terminate", DEFAULT),
            ("keepalive", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("terminator", DEFAULT),
            ("address", DEFAULT),
            ("baud_setting", DEFAULT),
            ("data_bits", DEFAULT),
            ("parity", DEFAULT),
            ("stop_bits", DEFAULT),
            ("threading", DEFAULT),
        ),
        {
            "__init__": _init_Connection,
            "__repr__": _repr_Connection,
            "__eq__": _eq_Connection,
            "__hash__": _hash_Connection,
        },
    ),
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
    "ChecksumAlgorithm": Written(
        (
            ("kind", MISSING),
            ("width", MISSING),
            ("poly", DEFAULT),
            ("init", DEFAULT),
            ("reflect_in", DEFAULT),
            ("reflect_out", DEFAULT),
            ("xorout", DEFAULT),
            ("inverted", DEFAULT),
            ("mask", DEFAULT),
            ("name", DEFAULT),
        ),
        {
            "__init__": _init_ChecksumAlgorithm,
            "__repr__": _repr_ChecksumAlgorithm,
            "__eq__": _eq_ChecksumAlgorithm,
            "__hash__": _hash_ChecksumAlgorithm,
        },
    ),
    "FrameBytes": Written(
        (("role", MISSING), ("data", MISSING)),
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
            ("layout", FieldSpec(MISSING, MISSING, False, False)),
        ),
        {
            "__init__": _init_FrameField,
            "__repr__": _repr_FrameField,
            "__eq__": _eq_FrameField,
            "__hash__": _hash_FrameField,
        },
    ),
    "FrameLength": Written(
        (("format", MISSING), ("adjust", MISSING), ("layout", FieldSpec(MISSING, MISSING, False, False))),
        {
            "__init__": _init_FrameLength,
            "__repr__": _repr_FrameLength,
            "__eq__": _eq_FrameLength,
            "__hash__": _hash_FrameLength,
        },
    ),
    "FramePayload": Written(
        (("trimmed", DEFAULT),),
        {
            "__init__": _init_FramePayload,
            "__repr__": _repr_FramePayload,
            "__eq__": _eq_FramePayload,
            "__hash__": _hash_FramePayload,
        },
    ),
    "FrameSeed": Written(
        (("table", MISSING), ("field", MISSING), ("part", MISSING), ("entries", MISSING)),
        {
            "__init__": _init_FrameSeed,
            "__repr__": _repr_FrameSeed,
            "__eq__": _eq_FrameSeed,
            "__hash__": _hash_FrameSeed,
        },
    ),
    "FrameChecksum": Written(
        (
            ("algorithm", MISSING),
            ("format", MISSING),
            ("first", MISSING),
            ("last", MISSING),
            ("with_request", DEFAULT),
            ("layout", FieldSpec(None, MISSING, False, False)),
            ("seed", DEFAULT),
        ),
        {
            "__init__": _init_FrameChecksum,
            "__repr__": _repr_FrameChecksum,
            "__eq__": _eq_FrameChecksum,
            "__hash__": _hash_FrameChecksum,
        },
    ),
    "FrameOptional": Written(
        (("count", MISSING),),
        {
            "__init__": _init_FrameOptional,
            "__repr__": _repr_FrameOptional,
            "__eq__": _eq_FrameOptional,
            "__hash__": _hash_FrameOptional,
        },
    ),
    "BitField": Written(
        (("name", MISSING), ("width", MISSING), ("value", DEFAULT), ("adjust", DEFAULT)),
        {
            "__init__": _init_BitField,
            "__repr__": _repr_BitField,
            "__eq__": _eq_BitField,
            "__hash__": _hash_BitField,
        },
    ),
    "FrameBits": Written(
        (("format", MISSING), ("fields", MISSING), ("layout", FieldSpec(MISSING, MISSING, False, False))),
        {
            "__init__": _init_FrameBits,
            "__repr__": _repr_FrameBits,
            "__eq__": _eq_FrameBits,
            "__hash__": _hash_FrameBits,
        },
    ),
    "Escaping": Written(
        (("escape", MISSING), ("table", MISSING)),
        {
            "__init__": _init_Escaping,
            "__repr__": _repr_Escaping,
            "__eq__": _eq_Escaping,
            "__hash__": _hash_Escaping,
        },
    ),
    "Frame": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("request", MISSING),
            ("reply", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("stuffing", DEFAULT),
            ("more_requests", DEFAULT),
            ("more_replies", DEFAULT),
            ("escaping", DEFAULT),
            ("request_when", DEFAULT),
            ("reply_when", DEFAULT),
        ),
        {"__init__": _init_Frame, "__repr__": _repr_Frame, "__eq__": _eq_Frame, "__hash__": _hash_Frame},
    ),
    "FrameUse": Written(
        (("frame", MISSING), ("args", MISSING)),
        {
            "__init__": _init_FrameUse,
            "__repr__": _repr_FrameUse,
            "__eq__": _eq_FrameUse,
            "__hash__": _hash_FrameUse,
        },
    ),
    "ReplyCase": Written(
        (
            ("value", MISSING),
            ("decoding", MISSING),
            ("actions", DEFAULT),
            ("last", DEFAULT),
            ("under", DEFAULT),
            ("under_tag", DEFAULT),
            ("under_layout", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_ReplyCase,
            "__repr__": _repr_ReplyCase,
            "__eq__": _eq_ReplyCase,
            "__hash__": _hash_ReplyCase,
        },
    ),
    "ListedReply": Written(
        (("decoding", MISSING), ("frame", DEFAULT), ("expect", DEFAULT), ("actions", DEFAULT)),
        {
            "__init__": _init_ListedReply,
            "__repr__": _repr_ListedReply,
            "__eq__": _eq_ListedReply,
            "__hash__": _hash_ListedReply,
        },
    ),
    "RepliesEach": Written(
        (("var", MISSING), ("over", MISSING)),
        {
            "__init__": _init_RepliesEach,
            "__repr__": _repr_RepliesEach,
            "__eq__": _eq_RepliesEach,
            "__hash__": _hash_RepliesEach,
        },
    ),
    "ErrorReply": Written(
        (
            ("decoding", MISSING),
            ("frame", DEFAULT),
            ("marker", DEFAULT),
            ("codes", DEFAULT),
            ("when", DEFAULT),
        ),
        {
            "__init__": _init_ErrorReply,
            "__repr__": _repr_ErrorReply,
            "__eq__": _eq_ErrorReply,
            "__hash__": _hash_ErrorReply,
        },
    ),
    "ReplyTable": Written(
        (
            ("key", MISSING),
            ("cases", MISSING),
            ("tag", DEFAULT),
            ("each", DEFAULT),
            ("length", DEFAULT),
            ("tag_layout", FieldSpec(None, MISSING, False, False)),
            ("length_layout", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_ReplyTable,
            "__repr__": _repr_ReplyTable,
            "__eq__": _eq_ReplyTable,
            "__hash__": _hash_ReplyTable,
        },
    ),
    "Primitive": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("connection", MISSING),
            ("encoding", MISSING),
            ("args", MISSING),
            ("decoding", DEFAULT),
            ("actions", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("frame", DEFAULT),
            ("skip_unmatched", DEFAULT),
            ("table", DEFAULT),
            ("timeout_ms", DEFAULT),
            ("expect", DEFAULT),
            ("lines", DEFAULT),
            ("replies", DEFAULT),
            ("reply_frames", DEFAULT),
            ("records", DEFAULT),
            ("listed", DEFAULT),
            ("retries", DEFAULT),
            ("error", DEFAULT),
            ("each", DEFAULT),
        ),
        {
            "__init__": _init_Primitive,
            "__repr__": _repr_Primitive,
            "__eq__": _eq_Primitive,
            "__hash__": _hash_Primitive,
        },
    ),
    "PrimitiveCall": Written(
        (
            ("primitive", MISSING),
            ("args", MISSING),
            ("delay_ms", DEFAULT),
            ("priority", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("interface", DEFAULT),
            ("when", DEFAULT),
            ("until", DEFAULT),
            ("every_ms", DEFAULT),
            ("within_ms", DEFAULT),
        ),
        {
            "__init__": _init_PrimitiveCall,
            "__repr__": _repr_PrimitiveCall,
            "__eq__": _eq_PrimitiveCall,
            "__hash__": _hash_PrimitiveCall,
        },
    ),
    "Interface": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("periodic", MISSING),
            ("calls", MISSING),
            ("triggers", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("rate_hz", DEFAULT),
        ),
        {
            "__init__": _init_Interface,
            "__repr__": _repr_Interface,
            "__eq__": _eq_Interface,
            "__hash__": _hash_Interface,
        },
    ),
    "AdapterField": Written(
        (("name", MISSING), ("type", MISSING), ("unit", DEFAULT), ("ros", DEFAULT), ("doc", DEFAULT)),
        {
            "__init__": _init_AdapterField,
            "__repr__": _repr_AdapterField,
            "__eq__": _eq_AdapterField,
            "__hash__": _hash_AdapterField,
        },
    ),
    "FrameworkMapping": Written(
        (
            ("framework", MISSING),
            ("title", MISSING),
            ("type", MISSING),
            ("paths", MISSING),
            ("schema_encoding", DEFAULT),
            ("message_encoding", DEFAULT),
        ),
        {
            "__init__": _init_FrameworkMapping,
            "__repr__": _repr_FrameworkMapping,
            "__eq__": _eq_FrameworkMapping,
            "__hash__": _hash_FrameworkMapping,
        },
    ),
    "Adapter": Written(
        (
            ("name", MISSING),
            ("fields", MISSING),
            ("ros", DEFAULT),
            ("standard", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("frameworks", DEFAULT),
        ),
        {
            "__init__": _init_Adapter,
            "__repr__": _repr_Adapter,
            "__eq__": _eq_Adapter,
            "__hash__": _hash_Adapter,
        },
    ),
    "DomainInput": Written(
        (
            ("name", MISSING),
            ("adapter", MISSING),
            ("interface", MISSING),
            ("args", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_DomainInput,
            "__repr__": _repr_DomainInput,
            "__eq__": _eq_DomainInput,
            "__hash__": _hash_DomainInput,
        },
    ),
    "Noise": Written(
        (
            ("field", MISSING),
            ("covariance", MISSING),
            ("deviation", DEFAULT),
            ("unit", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("others", DEFAULT),
        ),
        {"__init__": _init_Noise, "__repr__": _repr_Noise, "__eq__": _eq_Noise, "__hash__": _hash_Noise},
    ),
    "Kalman": Written(
        (
            ("field", MISSING),
            ("state", MISSING),
            ("covariance", MISSING),
            ("transition", MISSING),
            ("process", MISSING),
            ("measurement", MISSING),
            ("noise", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_Kalman, "__repr__": _repr_Kalman, "__eq__": _eq_Kalman, "__hash__": _hash_Kalman},
    ),
    "DomainOutput": Written(
        (
            ("name", MISSING),
            ("adapter", MISSING),
            ("fields", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("frame", DEFAULT),
            ("noise", DEFAULT),
            ("filters", DEFAULT),
        ),
        {
            "__init__": _init_DomainOutput,
            "__repr__": _repr_DomainOutput,
            "__eq__": _eq_DomainOutput,
            "__hash__": _hash_DomainOutput,
        },
    ),
    "Pose": Written(
        (("xyz", DEFAULT), ("rpy", DEFAULT)),
        {"__init__": _init_Pose, "__repr__": _repr_Pose, "__eq__": _eq_Pose, "__hash__": _hash_Pose},
    ),
    "Shape": Written(
        (
            ("kind", MISSING),
            ("size", MISSING),
            ("origin", DEFAULT),
            ("path", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("color", DEFAULT),
            ("expressions", DEFAULT),
        ),
        {"__init__": _init_Shape, "__repr__": _repr_Shape, "__eq__": _eq_Shape, "__hash__": _hash_Shape},
    ),
    "Inertial": Written(
        (("mass", MISSING), ("centre", MISSING), ("inertia", MISSING), ("expressions", DEFAULT)),
        {
            "__init__": _init_Inertial,
            "__repr__": _repr_Inertial,
            "__eq__": _eq_Inertial,
            "__hash__": _hash_Inertial,
        },
    ),
    "Link": Written(
        (
            ("name", MISSING),
            ("visuals", DEFAULT),
            ("collisions", DEFAULT),
            ("inertial", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("spawn", DEFAULT),
        ),
        {"__init__": _init_Link, "__repr__": _repr_Link, "__eq__": _eq_Link, "__hash__": _hash_Link},
    ),
    "Spawn": Written(
        (("floating", MISSING), ("pose", DEFAULT), ("expressions", DEFAULT)),
        {"__init__": _init_Spawn, "__repr__": _repr_Spawn, "__eq__": _eq_Spawn, "__hash__": _hash_Spawn},
    ),
    "Mimic": Written(
        (("joint", MISSING), ("multiplier", DEFAULT), ("offset", DEFAULT)),
        {"__init__": _init_Mimic, "__repr__": _repr_Mimic, "__eq__": _eq_Mimic, "__hash__": _hash_Mimic},
    ),
    "Joint": Written(
        (
            ("name", MISSING),
            ("kind", MISSING),
            ("parent", MISSING),
            ("child", MISSING),
            ("origin", DEFAULT),
            ("axis", DEFAULT),
            ("lower", DEFAULT),
            ("upper", DEFAULT),
            ("velocity", DEFAULT),
            ("effort", DEFAULT),
            ("damping", DEFAULT),
            ("friction", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("mimic", DEFAULT),
            ("expressions", DEFAULT),
        ),
        {"__init__": _init_Joint, "__repr__": _repr_Joint, "__eq__": _eq_Joint, "__hash__": _hash_Joint},
    ),
    "Binding": Written(
        (
            ("quantity", MISSING),
            ("target", MISSING),
            ("parameter", MISSING),
            ("index", MISSING),
            ("to_device", MISSING),
            ("to_joint", MISSING),
            ("interface", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("expressions", DEFAULT),
        ),
        {
            "__init__": _init_Binding,
            "__repr__": _repr_Binding,
            "__eq__": _eq_Binding,
            "__hash__": _hash_Binding,
        },
    ),
    "Transmission": Written(
        (
            ("name", MISSING),
            ("joint", MISSING),
            ("commands", DEFAULT),
            ("measures", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("actuator", DEFAULT),
        ),
        {
            "__init__": _init_Transmission,
            "__repr__": _repr_Transmission,
            "__eq__": _eq_Transmission,
            "__hash__": _hash_Transmission,
        },
    ),
    "Actuator": Written(
        (
            ("name", MISSING),
            ("kind", MISSING),
            ("velocity", DEFAULT),
            ("acceleration", DEFAULT),
            ("effort", DEFAULT),
            ("gain", DEFAULT),
            ("damping", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("refuse", DEFAULT),
            ("expressions", DEFAULT),
        ),
        {
            "__init__": _init_Actuator,
            "__repr__": _repr_Actuator,
            "__eq__": _eq_Actuator,
            "__hash__": _hash_Actuator,
        },
    ),
    "Model": Written(
        (
            ("robot", MISSING),
            ("states", MISSING),
            ("connections", MISSING),
            ("primitives", MISSING),
            ("interfaces", MISSING),
            ("adapters", MISSING),
            ("inputs", MISSING),
            ("outputs", MISSING),
            ("frames", FieldSpec(MISSING, dict, True, True)),
            ("constants", FieldSpec(MISSING, dict, True, True)),
            ("enums", FieldSpec(MISSING, dict, True, True)),
            ("tables", FieldSpec(MISSING, dict, True, True)),
            ("constant_docs", FieldSpec(MISSING, dict, True, True)),
            ("enum_docs", FieldSpec(MISSING, dict, True, True)),
            ("settings", FieldSpec(MISSING, dict, True, True)),
            ("links", FieldSpec(MISSING, dict, True, True)),
            ("joints", FieldSpec(MISSING, dict, True, True)),
            ("transmissions", FieldSpec(MISSING, dict, True, True)),
            ("sensors", FieldSpec(MISSING, dict, True, True)),
            ("actuators", FieldSpec(MISSING, dict, True, True)),
        ),
        {"__init__": _init_Model, "__repr__": _repr_Model, "__eq__": _eq_Model, "__hash__": _hash_Model},
    ),
}
dataclass = classes(WRITTEN)
