"""The methods of the frozen dataclasses of rdisc/syntax/ast.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_ImportDecl_path = _set_ImportDecl_span = _set_ImportDecl_doc = _unbound


def _init_ImportDecl(self: Any, path: Any, span: Any = DEFAULT, doc: Any = DEFAULT) -> None:
    _set_ImportDecl_path(self, path)
    _set_ImportDecl_span(self, span)
    _set_ImportDecl_doc(self, doc)


def _repr_ImportDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(path={self.path!r}, doc={self.doc!r})"


def _eq_ImportDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.path, self.doc) == (other.path, other.doc)
    return NotImplemented


def _hash_ImportDecl(self: Any) -> int:
    return hash((self.path, self.doc))


_set_RobotAttr_key = _set_RobotAttr_value = _set_RobotAttr_span = _unbound


def _init_RobotAttr(self: Any, key: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_RobotAttr_key(self, key)
    _set_RobotAttr_value(self, value)
    _set_RobotAttr_span(self, span)


def _repr_RobotAttr(self: Any) -> str:
    return f"{self.__class__.__qualname__}(key={self.key!r}, value={self.value!r})"


def _eq_RobotAttr(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.key, self.value) == (other.key, other.value)
    return NotImplemented


def _hash_RobotAttr(self: Any) -> int:
    return hash((self.key, self.value))


_set_RobotDecl_name = _set_RobotDecl_attrs = _set_RobotDecl_span = _set_RobotDecl_doc = _unbound


def _init_RobotDecl(self: Any, name: Any, attrs: Any, span: Any = DEFAULT, doc: Any = DEFAULT) -> None:
    _set_RobotDecl_name(self, name)
    _set_RobotDecl_attrs(self, attrs)
    _set_RobotDecl_span(self, span)
    _set_RobotDecl_doc(self, doc)


def _repr_RobotDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, attrs={self.attrs!r}, doc={self.doc!r})"


def _eq_RobotDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.attrs, self.doc) == (other.name, other.attrs, other.doc)
    return NotImplemented


def _hash_RobotDecl(self: Any) -> int:
    return hash((self.name, self.attrs, self.doc))


_set_StateDecl_name = _unbound
_set_StateDecl_type = _unbound
_set_StateDecl_init = _unbound
_set_StateDecl_span = _unbound
_set_StateDecl_doc = _unbound
_set_StateDecl_noise = _unbound


def _init_StateDecl(
    self: Any,
    name: Any,
    type: Any,
    init: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
    noise: Any = DEFAULT,
) -> None:
    _set_StateDecl_name(self, name)
    _set_StateDecl_type(self, type)
    _set_StateDecl_init(self, init)
    _set_StateDecl_span(self, span)
    _set_StateDecl_doc(self, doc)
    _set_StateDecl_noise(self, noise)


def _repr_StateDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, init={self.init!r}, doc={self.doc!r}, noise={self.noise!r})"


def _eq_StateDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.init,
            self.doc,
            self.noise,
        ) == (
            other.name,
            other.type,
            other.init,
            other.doc,
            other.noise,
        )
    return NotImplemented


def _hash_StateDecl(self: Any) -> int:
    return hash((self.name, self.type, self.init, self.doc, self.noise))


_set_SensorDecl_name = _unbound
_set_SensorDecl_type = _unbound
_set_SensorDecl_primitive = _unbound
_set_SensorDecl_cache = _unbound
_set_SensorDecl_span = _unbound
_set_SensorDecl_doc = _unbound
_set_SensorDecl_noise = _unbound


def _init_SensorDecl(
    self: Any,
    name: Any,
    type: Any,
    primitive: Any,
    cache: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
    noise: Any = DEFAULT,
) -> None:
    _set_SensorDecl_name(self, name)
    _set_SensorDecl_type(self, type)
    _set_SensorDecl_primitive(self, primitive)
    _set_SensorDecl_cache(self, cache)
    _set_SensorDecl_span(self, span)
    _set_SensorDecl_doc(self, doc)
    _set_SensorDecl_noise(self, noise)


def _repr_SensorDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, primitive={self.primitive!r}, cache={self.cache!r}, doc={self.doc!r}, noise={self.noise!r})"


def _eq_SensorDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.primitive,
            self.cache,
            self.doc,
            self.noise,
        ) == (
            other.name,
            other.type,
            other.primitive,
            other.cache,
            other.doc,
            other.noise,
        )
    return NotImplemented


def _hash_SensorDecl(self: Any) -> int:
    return hash((self.name, self.type, self.primitive, self.cache, self.doc, self.noise))


_set_SettingDecl_name = _unbound
_set_SettingDecl_type = _unbound
_set_SettingDecl_default = _unbound
_set_SettingDecl_span = _unbound
_set_SettingDecl_doc = _unbound
_set_SettingDecl_low = _unbound
_set_SettingDecl_high = _unbound


def _init_SettingDecl(
    self: Any,
    name: Any,
    type: Any,
    default: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
    low: Any = DEFAULT,
    high: Any = DEFAULT,
) -> None:
    _set_SettingDecl_name(self, name)
    _set_SettingDecl_type(self, type)
    _set_SettingDecl_default(self, default)
    _set_SettingDecl_span(self, span)
    _set_SettingDecl_doc(self, doc)
    _set_SettingDecl_low(self, low)
    _set_SettingDecl_high(self, high)


def _repr_SettingDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, default={self.default!r}, doc={self.doc!r}, low={self.low!r}, high={self.high!r})"


def _eq_SettingDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.default,
            self.doc,
            self.low,
            self.high,
        ) == (
            other.name,
            other.type,
            other.default,
            other.doc,
            other.low,
            other.high,
        )
    return NotImplemented


def _hash_SettingDecl(self: Any) -> int:
    return hash((self.name, self.type, self.default, self.doc, self.low, self.high))


_set_Baud_value = _set_Baud_span = _unbound


def _init_Baud(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_Baud_value(self, value)
    _set_Baud_span(self, span)


def _repr_Baud(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_Baud(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_Baud(self: Any) -> int:
    return hash((self.value,))


_set_Threading_model = _set_Threading_frequency = _set_Threading_span = _unbound


def _init_Threading(self: Any, model: Any, frequency: Any, span: Any = DEFAULT) -> None:
    _set_Threading_model(self, model)
    _set_Threading_frequency(self, frequency)
    _set_Threading_span(self, span)


def _repr_Threading(self: Any) -> str:
    return f"{self.__class__.__qualname__}(model={self.model!r}, frequency={self.frequency!r})"


def _eq_Threading(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.model, self.frequency) == (other.model, other.frequency)
    return NotImplemented


def _hash_Threading(self: Any) -> int:
    return hash((self.model, self.frequency))


_set_Hook_event = _set_Hook_call = _set_Hook_every = _set_Hook_span = _unbound


def _init_Hook(self: Any, event: Any, call: Any, every: Any, span: Any = DEFAULT) -> None:
    _set_Hook_event(self, event)
    _set_Hook_call(self, call)
    _set_Hook_every(self, every)
    _set_Hook_span(self, span)


def _repr_Hook(self: Any) -> str:
    return f"{self.__class__.__qualname__}(event={self.event!r}, call={self.call!r}, every={self.every!r})"


def _eq_Hook(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.event, self.call, self.every) == (other.event, other.call, other.every)
    return NotImplemented


def _hash_Hook(self: Any) -> int:
    return hash((self.event, self.call, self.every))


_set_Terminator_value = _set_Terminator_span = _unbound


def _init_Terminator(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_Terminator_value(self, value)
    _set_Terminator_span(self, span)


def _repr_Terminator(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_Terminator(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_Terminator(self: Any) -> int:
    return hash((self.value,))


_set_Address_value = _set_Address_span = _unbound


def _init_Address(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_Address_value(self, value)
    _set_Address_span(self, span)


def _repr_Address(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_Address(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_Address(self: Any) -> int:
    return hash((self.value,))


_set_DataBits_value = _set_DataBits_span = _unbound


def _init_DataBits(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_DataBits_value(self, value)
    _set_DataBits_span(self, span)


def _repr_DataBits(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_DataBits(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_DataBits(self: Any) -> int:
    return hash((self.value,))


_set_Parity_value = _set_Parity_span = _unbound


def _init_Parity(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_Parity_value(self, value)
    _set_Parity_span(self, span)


def _repr_Parity(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_Parity(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_Parity(self: Any) -> int:
    return hash((self.value,))


_set_StopBits_value = _set_StopBits_span = _unbound


def _init_StopBits(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_StopBits_value(self, value)
    _set_StopBits_span(self, span)


def _repr_StopBits(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_StopBits(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_StopBits(self: Any) -> int:
    return hash((self.value,))


_set_ConnectionDecl_name = _unbound
_set_ConnectionDecl_kind = _unbound
_set_ConnectionDecl_attrs = _unbound
_set_ConnectionDecl_span = _unbound
_set_ConnectionDecl_doc = _unbound


def _init_ConnectionDecl(
    self: Any,
    name: Any,
    kind: Any,
    attrs: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_ConnectionDecl_name(self, name)
    _set_ConnectionDecl_kind(self, kind)
    _set_ConnectionDecl_attrs(self, attrs)
    _set_ConnectionDecl_span(self, span)
    _set_ConnectionDecl_doc(self, doc)


def _repr_ConnectionDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, kind={self.kind!r}, attrs={self.attrs!r}, doc={self.doc!r})"


def _eq_ConnectionDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.kind,
            self.attrs,
            self.doc,
        ) == (
            other.name,
            other.kind,
            other.attrs,
            other.doc,
        )
    return NotImplemented


def _hash_ConnectionDecl(self: Any) -> int:
    return hash((self.name, self.kind, self.attrs, self.doc))


_set_Kind_word = _set_Kind_span = _set_Kind_rate = _unbound


def _init_Kind(self: Any, word: Any, span: Any = DEFAULT, rate: Any = DEFAULT) -> None:
    _set_Kind_word(self, word)
    _set_Kind_span(self, span)
    _set_Kind_rate(self, rate)


def _repr_Kind(self: Any) -> str:
    return f"{self.__class__.__qualname__}(word={self.word!r}, rate={self.rate!r})"


def _eq_Kind(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.word, self.rate) == (other.word, other.rate)
    return NotImplemented


def _hash_Kind(self: Any) -> int:
    return hash((self.word, self.rate))


_set_Triggers_outputs = _set_Triggers_span = _unbound


def _init_Triggers(self: Any, outputs: Any, span: Any = DEFAULT) -> None:
    _set_Triggers_outputs(self, outputs)
    _set_Triggers_span(self, span)


def _repr_Triggers(self: Any) -> str:
    return f"{self.__class__.__qualname__}(outputs={self.outputs!r})"


def _eq_Triggers(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.outputs,) == (other.outputs,)
    return NotImplemented


def _hash_Triggers(self: Any) -> int:
    return hash((self.outputs,))


_set_CallStmt_call = _unbound
_set_CallStmt_delays = _unbound
_set_CallStmt_priorities = _unbound
_set_CallStmt_span = _unbound
_set_CallStmt_conditions = _unbound
_set_CallStmt_polls = _unbound


def _init_CallStmt(
    self: Any,
    call: Any,
    delays: Any,
    priorities: Any,
    span: Any = DEFAULT,
    conditions: Any = DEFAULT,
    polls: Any = DEFAULT,
) -> None:
    _set_CallStmt_call(self, call)
    _set_CallStmt_delays(self, delays)
    _set_CallStmt_priorities(self, priorities)
    _set_CallStmt_span(self, span)
    _set_CallStmt_conditions(self, conditions)
    _set_CallStmt_polls(self, polls)


def _repr_CallStmt(self: Any) -> str:
    return f"{self.__class__.__qualname__}(call={self.call!r}, delays={self.delays!r}, priorities={self.priorities!r}, conditions={self.conditions!r}, polls={self.polls!r})"


def _eq_CallStmt(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.call,
            self.delays,
            self.priorities,
            self.conditions,
            self.polls,
        ) == (
            other.call,
            other.delays,
            other.priorities,
            other.conditions,
            other.polls,
        )
    return NotImplemented


def _hash_CallStmt(self: Any) -> int:
    return hash((self.call, self.delays, self.priorities, self.conditions, self.polls))


_set_Poll_condition = _set_Poll_every = _set_Poll_within = _set_Poll_span = _unbound


def _init_Poll(self: Any, condition: Any, every: Any, within: Any, span: Any = DEFAULT) -> None:
    _set_Poll_condition(self, condition)
    _set_Poll_every(self, every)
    _set_Poll_within(self, within)
    _set_Poll_span(self, span)


def _repr_Poll(self: Any) -> str:
    return f"{self.__class__.__qualname__}(condition={self.condition!r}, every={self.every!r}, within={self.within!r})"


def _eq_Poll(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.condition, self.every, self.within) == (other.condition, other.every, other.within)
    return NotImplemented


def _hash_Poll(self: Any) -> int:
    return hash((self.condition, self.every, self.within))


_set_ForStmt_var = _set_ForStmt_low = _set_ForStmt_high = _set_ForStmt_body = _set_ForStmt_span = _unbound


def _init_ForStmt(self: Any, var: Any, low: Any, high: Any, body: Any, span: Any = DEFAULT) -> None:
    _set_ForStmt_var(self, var)
    _set_ForStmt_low(self, low)
    _set_ForStmt_high(self, high)
    _set_ForStmt_body(self, body)
    _set_ForStmt_span(self, span)


def _repr_ForStmt(self: Any) -> str:
    return f"{self.__class__.__qualname__}(var={self.var!r}, low={self.low!r}, high={self.high!r}, body={self.body!r})"


def _eq_ForStmt(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.var, self.low, self.high, self.body) == (other.var, other.low, other.high, other.body)
    return NotImplemented


def _hash_ForStmt(self: Any) -> int:
    return hash((self.var, self.low, self.high, self.body))


_set_InterfaceDecl_name = _unbound
_set_InterfaceDecl_params = _unbound
_set_InterfaceDecl_clauses = _unbound
_set_InterfaceDecl_body = _unbound
_set_InterfaceDecl_span = _unbound
_set_InterfaceDecl_doc = _unbound


def _init_InterfaceDecl(
    self: Any,
    name: Any,
    params: Any,
    clauses: Any,
    body: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_InterfaceDecl_name(self, name)
    _set_InterfaceDecl_params(self, params)
    _set_InterfaceDecl_clauses(self, clauses)
    _set_InterfaceDecl_body(self, body)
    _set_InterfaceDecl_span(self, span)
    _set_InterfaceDecl_doc(self, doc)


def _repr_InterfaceDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, clauses={self.clauses!r}, body={self.body!r}, doc={self.doc!r})"


def _eq_InterfaceDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.clauses,
            self.body,
            self.doc,
        ) == (
            other.name,
            other.params,
            other.clauses,
            other.body,
            other.doc,
        )
    return NotImplemented


def _hash_InterfaceDecl(self: Any) -> int:
    return hash((self.name, self.params, self.clauses, self.body, self.doc))


_set_FieldDecl_name = _unbound
_set_FieldDecl_type = _unbound
_set_FieldDecl_unit = _unbound
_set_FieldDecl_ros = _unbound
_set_FieldDecl_span = _unbound
_set_FieldDecl_doc = _unbound


def _init_FieldDecl(
    self: Any,
    name: Any,
    type: Any,
    unit: Any,
    ros: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_FieldDecl_name(self, name)
    _set_FieldDecl_type(self, type)
    _set_FieldDecl_unit(self, unit)
    _set_FieldDecl_ros(self, ros)
    _set_FieldDecl_span(self, span)
    _set_FieldDecl_doc(self, doc)


def _repr_FieldDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, unit={self.unit!r}, ros={self.ros!r}, doc={self.doc!r})"


def _eq_FieldDecl(self: Any, other: Any) -> Any:
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


def _hash_FieldDecl(self: Any) -> int:
    return hash((self.name, self.type, self.unit, self.ros, self.doc))


_set_AdapterDecl_name = _unbound
_set_AdapterDecl_ros = _unbound
_set_AdapterDecl_fields = _unbound
_set_AdapterDecl_span = _unbound
_set_AdapterDecl_doc = _unbound


def _init_AdapterDecl(
    self: Any,
    name: Any,
    ros: Any,
    fields: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_AdapterDecl_name(self, name)
    _set_AdapterDecl_ros(self, ros)
    _set_AdapterDecl_fields(self, fields)
    _set_AdapterDecl_span(self, span)
    _set_AdapterDecl_doc(self, doc)


def _repr_AdapterDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, ros={self.ros!r}, fields={self.fields!r}, doc={self.doc!r})"


def _eq_AdapterDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.ros,
            self.fields,
            self.doc,
        ) == (
            other.name,
            other.ros,
            other.fields,
            other.doc,
        )
    return NotImplemented


def _hash_AdapterDecl(self: Any) -> int:
    return hash((self.name, self.ros, self.fields, self.doc))


_set_InputDecl_name = _unbound
_set_InputDecl_adapter = _unbound
_set_InputDecl_call = _unbound
_set_InputDecl_span = _unbound
_set_InputDecl_doc = _unbound


def _init_InputDecl(
    self: Any,
    name: Any,
    adapter: Any,
    call: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_InputDecl_name(self, name)
    _set_InputDecl_adapter(self, adapter)
    _set_InputDecl_call(self, call)
    _set_InputDecl_span(self, span)
    _set_InputDecl_doc(self, doc)


def _repr_InputDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, adapter={self.adapter!r}, call={self.call!r}, doc={self.doc!r})"


def _eq_InputDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.adapter,
            self.call,
            self.doc,
        ) == (
            other.name,
            other.adapter,
            other.call,
            other.doc,
        )
    return NotImplemented


def _hash_InputDecl(self: Any) -> int:
    return hash((self.name, self.adapter, self.call, self.doc))


_set_NumberRows_rows = _set_NumberRows_span = _unbound


def _init_NumberRows(self: Any, rows: Any, span: Any = DEFAULT) -> None:
    _set_NumberRows_rows(self, rows)
    _set_NumberRows_span(self, span)


def _repr_NumberRows(self: Any) -> str:
    return f"{self.__class__.__qualname__}(rows={self.rows!r})"


def _eq_NumberRows(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.rows,) == (other.rows,)
    return NotImplemented


def _hash_NumberRows(self: Any) -> int:
    return hash((self.rows,))


_set_FieldNoise_field = _unbound
_set_FieldNoise_value = _unbound
_set_FieldNoise_unit = _unbound
_set_FieldNoise_span = _unbound
_set_FieldNoise_others = _unbound


def _init_FieldNoise(
    self: Any,
    field: Any,
    value: Any,
    unit: Any,
    span: Any = DEFAULT,
    others: Any = DEFAULT,
) -> None:
    _set_FieldNoise_field(self, field)
    _set_FieldNoise_value(self, value)
    _set_FieldNoise_unit(self, unit)
    _set_FieldNoise_span(self, span)
    _set_FieldNoise_others(self, others)


def _repr_FieldNoise(self: Any) -> str:
    return f"{self.__class__.__qualname__}(field={self.field!r}, value={self.value!r}, unit={self.unit!r}, others={self.others!r})"


def _eq_FieldNoise(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.field,
            self.value,
            self.unit,
            self.others,
        ) == (
            other.field,
            other.value,
            other.unit,
            other.others,
        )
    return NotImplemented


def _hash_FieldNoise(self: Any) -> int:
    return hash((self.field, self.value, self.unit, self.others))


_set_FieldFilter_field = _set_FieldFilter_items = _set_FieldFilter_span = _unbound


def _init_FieldFilter(self: Any, field: Any, items: Any, span: Any = DEFAULT) -> None:
    _set_FieldFilter_field(self, field)
    _set_FieldFilter_items(self, items)
    _set_FieldFilter_span(self, span)


def _repr_FieldFilter(self: Any) -> str:
    return f"{self.__class__.__qualname__}(field={self.field!r}, items={self.items!r})"


def _eq_FieldFilter(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.field, self.items) == (other.field, other.items)
    return NotImplemented


def _hash_FieldFilter(self: Any) -> int:
    return hash((self.field, self.items))


_set_OutputDecl_name = _unbound
_set_OutputDecl_adapter = _unbound
_set_OutputDecl_fields = _unbound
_set_OutputDecl_span = _unbound
_set_OutputDecl_doc = _unbound
_set_OutputDecl_frame = _unbound
_set_OutputDecl_noises = _unbound
_set_OutputDecl_filters = _unbound


def _init_OutputDecl(
    self: Any,
    name: Any,
    adapter: Any,
    fields: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
    frame: Any = DEFAULT,
    noises: Any = DEFAULT,
    filters: Any = DEFAULT,
) -> None:
    _set_OutputDecl_name(self, name)
    _set_OutputDecl_adapter(self, adapter)
    _set_OutputDecl_fields(self, fields)
    _set_OutputDecl_span(self, span)
    _set_OutputDecl_doc(self, doc)
    _set_OutputDecl_frame(self, frame)
    _set_OutputDecl_noises(self, noises)
    _set_OutputDecl_filters(self, filters)


def _repr_OutputDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, adapter={self.adapter!r}, fields={self.fields!r}, doc={self.doc!r}, frame={self.frame!r}, noises={self.noises!r}, filters={self.filters!r})"


def _eq_OutputDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.adapter,
            self.fields,
            self.doc,
            self.frame,
            self.noises,
            self.filters,
        ) == (
            other.name,
            other.adapter,
            other.fields,
            other.doc,
            other.frame,
            other.noises,
            other.filters,
        )
    return NotImplemented


def _hash_OutputDecl(self: Any) -> int:
    return hash((self.name, self.adapter, self.fields, self.doc, self.frame, self.noises, self.filters))


_set_TableLit_entries = _set_TableLit_span = _unbound


def _init_TableLit(self: Any, entries: Any, span: Any = DEFAULT) -> None:
    _set_TableLit_entries(self, entries)
    _set_TableLit_span(self, span)


def _repr_TableLit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(entries={self.entries!r})"


def _eq_TableLit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.entries,) == (other.entries,)
    return NotImplemented


def _hash_TableLit(self: Any) -> int:
    return hash((self.entries,))


_set_ConstDecl_name = _set_ConstDecl_value = _set_ConstDecl_span = _set_ConstDecl_doc = _unbound


def _init_ConstDecl(self: Any, name: Any, value: Any, span: Any = DEFAULT, doc: Any = DEFAULT) -> None:
    _set_ConstDecl_name(self, name)
    _set_ConstDecl_value(self, value)
    _set_ConstDecl_span(self, span)
    _set_ConstDecl_doc(self, doc)


def _repr_ConstDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, value={self.value!r}, doc={self.doc!r})"


def _eq_ConstDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.value, self.doc) == (other.name, other.value, other.doc)
    return NotImplemented


def _hash_ConstDecl(self: Any) -> int:
    return hash((self.name, self.value, self.doc))


_set_EnumMember_name = _set_EnumMember_value = _set_EnumMember_span = _unbound


def _init_EnumMember(self: Any, name: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_EnumMember_name(self, name)
    _set_EnumMember_value(self, value)
    _set_EnumMember_span(self, span)


def _repr_EnumMember(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, value={self.value!r})"


def _eq_EnumMember(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.value) == (other.name, other.value)
    return NotImplemented


def _hash_EnumMember(self: Any) -> int:
    return hash((self.name, self.value))


_set_EnumDecl_name = _set_EnumDecl_members = _set_EnumDecl_span = _set_EnumDecl_doc = _unbound


def _init_EnumDecl(self: Any, name: Any, members: Any, span: Any = DEFAULT, doc: Any = DEFAULT) -> None:
    _set_EnumDecl_name(self, name)
    _set_EnumDecl_members(self, members)
    _set_EnumDecl_span(self, span)
    _set_EnumDecl_doc(self, doc)


def _repr_EnumDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, members={self.members!r}, doc={self.doc!r})"


def _eq_EnumDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.members, self.doc) == (other.name, other.members, other.doc)
    return NotImplemented


def _hash_EnumDecl(self: Any) -> int:
    return hash((self.name, self.members, self.doc))


_set_Damaged_keyword = _set_Damaged_name = _unbound


def _init_Damaged(self: Any, keyword: Any, name: Any) -> None:
    _set_Damaged_keyword(self, keyword)
    _set_Damaged_name(self, name)


def _repr_Damaged(self: Any) -> str:
    return f"{self.__class__.__qualname__}(keyword={self.keyword!r}, name={self.name!r})"


def _eq_Damaged(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.keyword, self.name) == (other.keyword, other.name)
    return NotImplemented


def _hash_Damaged(self: Any) -> int:
    return hash((self.keyword, self.name))


_set_Module_path = _set_Module_decls = _set_Module_damaged = _set_Module_refused = _unbound


def _init_Module(self: Any, path: Any, decls: Any, damaged: Any = DEFAULT, refused: Any = DEFAULT) -> None:
    _set_Module_path(self, path)
    _set_Module_decls(self, decls)
    _set_Module_damaged(self, damaged)
    _set_Module_refused(self, refused)


def _repr_Module(self: Any) -> str:
    return f"{self.__class__.__qualname__}(path={self.path!r}, decls={self.decls!r}, damaged={self.damaged!r}, refused={self.refused!r})"


def _eq_Module(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.path,
            self.decls,
            self.damaged,
            self.refused,
        ) == (
            other.path,
            other.decls,
            other.damaged,
            other.refused,
        )
    return NotImplemented


def _hash_Module(self: Any) -> int:
    return hash((self.path, self.decls, self.damaged, self.refused))


WRITTEN: dict[str, Written] = {
    "ImportDecl": Written(
        (("path", MISSING), ("span", FieldSpec(None, MISSING, False, False)), ("doc", DEFAULT)),
        {
            "__init__": _init_ImportDecl,
            "__repr__": _repr_ImportDecl,
            "__eq__": _eq_ImportDecl,
            "__hash__": _hash_ImportDecl,
        },
    ),
    "RobotAttr": Written(
        (("key", MISSING), ("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_RobotAttr,
            "__repr__": _repr_RobotAttr,
            "__eq__": _eq_RobotAttr,
            "__hash__": _hash_RobotAttr,
        },
    ),
    "RobotDecl": Written(
        (
            ("name", MISSING),
            ("attrs", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_RobotDecl,
            "__repr__": _repr_RobotDecl,
            "__eq__": _eq_RobotDecl,
            "__hash__": _hash_RobotDecl,
        },
    ),
    "StateDecl": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("init", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
            ("noise", DEFAULT),
        ),
        {
            "__init__": _init_StateDecl,
            "__repr__": _repr_StateDecl,
            "__eq__": _eq_StateDecl,
            "__hash__": _hash_StateDecl,
        },
    ),
    "SensorDecl": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("primitive", MISSING),
            ("cache", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
            ("noise", DEFAULT),
        ),
        {
            "__init__": _init_SensorDecl,
            "__repr__": _repr_SensorDecl,
            "__eq__": _eq_SensorDecl,
            "__hash__": _hash_SensorDecl,
        },
    ),
    "SettingDecl": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("default", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
            ("low", DEFAULT),
            ("high", DEFAULT),
        ),
        {
            "__init__": _init_SettingDecl,
            "__repr__": _repr_SettingDecl,
            "__eq__": _eq_SettingDecl,
            "__hash__": _hash_SettingDecl,
        },
    ),
    "Baud": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Baud, "__repr__": _repr_Baud, "__eq__": _eq_Baud, "__hash__": _hash_Baud},
    ),
    "Threading": Written(
        (("model", MISSING), ("frequency", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Threading,
            "__repr__": _repr_Threading,
            "__eq__": _eq_Threading,
            "__hash__": _hash_Threading,
        },
    ),
    "Hook": Written(
        (
            ("event", MISSING),
            ("call", MISSING),
            ("every", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_Hook, "__repr__": _repr_Hook, "__eq__": _eq_Hook, "__hash__": _hash_Hook},
    ),
    "Terminator": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Terminator,
            "__repr__": _repr_Terminator,
            "__eq__": _eq_Terminator,
            "__hash__": _hash_Terminator,
        },
    ),
    "Address": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Address,
            "__repr__": _repr_Address,
            "__eq__": _eq_Address,
            "__hash__": _hash_Address,
        },
    ),
    "DataBits": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_DataBits,
            "__repr__": _repr_DataBits,
            "__eq__": _eq_DataBits,
            "__hash__": _hash_DataBits,
        },
    ),
    "Parity": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Parity, "__repr__": _repr_Parity, "__eq__": _eq_Parity, "__hash__": _hash_Parity},
    ),
    "StopBits": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_StopBits,
            "__repr__": _repr_StopBits,
            "__eq__": _eq_StopBits,
            "__hash__": _hash_StopBits,
        },
    ),
    "ConnectionDecl": Written(
        (
            ("name", MISSING),
            ("kind", MISSING),
            ("attrs", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_ConnectionDecl,
            "__repr__": _repr_ConnectionDecl,
            "__eq__": _eq_ConnectionDecl,
            "__hash__": _hash_ConnectionDecl,
        },
    ),
    "Kind": Written(
        (("word", MISSING), ("span", FieldSpec(None, MISSING, False, False)), ("rate", DEFAULT)),
        {"__init__": _init_Kind, "__repr__": _repr_Kind, "__eq__": _eq_Kind, "__hash__": _hash_Kind},
    ),
    "Triggers": Written(
        (("outputs", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Triggers,
            "__repr__": _repr_Triggers,
            "__eq__": _eq_Triggers,
            "__hash__": _hash_Triggers,
        },
    ),
    "CallStmt": Written(
        (
            ("call", MISSING),
            ("delays", MISSING),
            ("priorities", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("conditions", DEFAULT),
            ("polls", DEFAULT),
        ),
        {
            "__init__": _init_CallStmt,
            "__repr__": _repr_CallStmt,
            "__eq__": _eq_CallStmt,
            "__hash__": _hash_CallStmt,
        },
    ),
    "Poll": Written(
        (
            ("condition", MISSING),
            ("every", MISSING),
            ("within", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_Poll, "__repr__": _repr_Poll, "__eq__": _eq_Poll, "__hash__": _hash_Poll},
    ),
    "ForStmt": Written(
        (
            ("var", MISSING),
            ("low", MISSING),
            ("high", MISSING),
            ("body", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_ForStmt,
            "__repr__": _repr_ForStmt,
            "__eq__": _eq_ForStmt,
            "__hash__": _hash_ForStmt,
        },
    ),
    "InterfaceDecl": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("clauses", MISSING),
            ("body", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_InterfaceDecl,
            "__repr__": _repr_InterfaceDecl,
            "__eq__": _eq_InterfaceDecl,
            "__hash__": _hash_InterfaceDecl,
        },
    ),
    "FieldDecl": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("unit", MISSING),
            ("ros", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_FieldDecl,
            "__repr__": _repr_FieldDecl,
            "__eq__": _eq_FieldDecl,
            "__hash__": _hash_FieldDecl,
        },
    ),
    "AdapterDecl": Written(
        (
            ("name", MISSING),
            ("ros", MISSING),
            ("fields", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_AdapterDecl,
            "__repr__": _repr_AdapterDecl,
            "__eq__": _eq_AdapterDecl,
            "__hash__": _hash_AdapterDecl,
        },
    ),
    "InputDecl": Written(
        (
            ("name", MISSING),
            ("adapter", MISSING),
            ("call", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_InputDecl,
            "__repr__": _repr_InputDecl,
            "__eq__": _eq_InputDecl,
            "__hash__": _hash_InputDecl,
        },
    ),
    "NumberRows": Written(
        (("rows", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_NumberRows,
            "__repr__": _repr_NumberRows,
            "__eq__": _eq_NumberRows,
            "__hash__": _hash_NumberRows,
        },
    ),
    "FieldNoise": Written(
        (
            ("field", MISSING),
            ("value", MISSING),
            ("unit", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("others", DEFAULT),
        ),
        {
            "__init__": _init_FieldNoise,
            "__repr__": _repr_FieldNoise,
            "__eq__": _eq_FieldNoise,
            "__hash__": _hash_FieldNoise,
        },
    ),
    "FieldFilter": Written(
        (("field", MISSING), ("items", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_FieldFilter,
            "__repr__": _repr_FieldFilter,
            "__eq__": _eq_FieldFilter,
            "__hash__": _hash_FieldFilter,
        },
    ),
    "OutputDecl": Written(
        (
            ("name", MISSING),
            ("adapter", MISSING),
            ("fields", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
            ("frame", DEFAULT),
            ("noises", DEFAULT),
            ("filters", DEFAULT),
        ),
        {
            "__init__": _init_OutputDecl,
            "__repr__": _repr_OutputDecl,
            "__eq__": _eq_OutputDecl,
            "__hash__": _hash_OutputDecl,
        },
    ),
    "TableLit": Written(
        (("entries", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_TableLit,
            "__repr__": _repr_TableLit,
            "__eq__": _eq_TableLit,
            "__hash__": _hash_TableLit,
        },
    ),
    "ConstDecl": Written(
        (
            ("name", MISSING),
            ("value", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_ConstDecl,
            "__repr__": _repr_ConstDecl,
            "__eq__": _eq_ConstDecl,
            "__hash__": _hash_ConstDecl,
        },
    ),
    "EnumMember": Written(
        (("name", MISSING), ("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_EnumMember,
            "__repr__": _repr_EnumMember,
            "__eq__": _eq_EnumMember,
            "__hash__": _hash_EnumMember,
        },
    ),
    "EnumDecl": Written(
        (
            ("name", MISSING),
            ("members", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_EnumDecl,
            "__repr__": _repr_EnumDecl,
            "__eq__": _eq_EnumDecl,
            "__hash__": _hash_EnumDecl,
        },
    ),
    "Damaged": Written(
        (("keyword", MISSING), ("name", MISSING)),
        {
            "__init__": _init_Damaged,
            "__repr__": _repr_Damaged,
            "__eq__": _eq_Damaged,
            "__hash__": _hash_Damaged,
        },
    ),
    "Module": Written(
        (("path", MISSING), ("decls", MISSING), ("damaged", DEFAULT), ("refused", DEFAULT)),
        {"__init__": _init_Module, "__repr__": _repr_Module, "__eq__": _eq_Module, "__hash__": _hash_Module},
    ),
}
dataclass = classes(WRITTEN)
