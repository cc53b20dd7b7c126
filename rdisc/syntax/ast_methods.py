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


_set_Ident_text = _set_Ident_span = _unbound


def _init_Ident(self: Any, text: Any, span: Any = DEFAULT) -> None:
    _set_Ident_text(self, text)
    _set_Ident_span(self, span)


def _repr_Ident(self: Any) -> str:
    return f"{self.__class__.__qualname__}(text={self.text!r})"


def _eq_Ident(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.text,) == (other.text,)
    return NotImplemented


def _hash_Ident(self: Any) -> int:
    return hash((self.text,))


_set_IntLit_value = _set_IntLit_span = _unbound


def _init_IntLit(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_IntLit_value(self, value)
    _set_IntLit_span(self, span)


def _repr_IntLit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_IntLit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_IntLit(self: Any) -> int:
    return hash((self.value,))


_set_FloatLit_value = _set_FloatLit_span = _unbound


def _init_FloatLit(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_FloatLit_value(self, value)
    _set_FloatLit_span(self, span)


def _repr_FloatLit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_FloatLit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_FloatLit(self: Any) -> int:
    return hash((self.value,))


_set_StrLit_value = _set_StrLit_span = _unbound


def _init_StrLit(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_StrLit_value(self, value)
    _set_StrLit_span(self, span)


def _repr_StrLit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_StrLit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_StrLit(self: Any) -> int:
    return hash((self.value,))


_set_BytesLit_value = _set_BytesLit_span = _unbound


def _init_BytesLit(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_BytesLit_value(self, value)
    _set_BytesLit_span(self, span)


def _repr_BytesLit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_BytesLit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_BytesLit(self: Any) -> int:
    return hash((self.value,))


_set_BoolLit_value = _set_BoolLit_span = _unbound


def _init_BoolLit(self: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_BoolLit_value(self, value)
    _set_BoolLit_span(self, span)


def _repr_BoolLit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r})"


def _eq_BoolLit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value,) == (other.value,)
    return NotImplemented


def _hash_BoolLit(self: Any) -> int:
    return hash((self.value,))


_set_Ref_name = _set_Ref_span = _unbound


def _init_Ref(self: Any, name: Any, span: Any = DEFAULT) -> None:
    _set_Ref_name(self, name)
    _set_Ref_span(self, span)


def _repr_Ref(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r})"


def _eq_Ref(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name,) == (other.name,)
    return NotImplemented


def _hash_Ref(self: Any) -> int:
    return hash((self.name,))


_set_Index_base = _set_Index_index = _set_Index_span = _unbound


def _init_Index(self: Any, base: Any, index: Any, span: Any = DEFAULT) -> None:
    _set_Index_base(self, base)
    _set_Index_index(self, index)
    _set_Index_span(self, span)


def _repr_Index(self: Any) -> str:
    return f"{self.__class__.__qualname__}(base={self.base!r}, index={self.index!r})"


def _eq_Index(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.base, self.index) == (other.base, other.index)
    return NotImplemented


def _hash_Index(self: Any) -> int:
    return hash((self.base, self.index))


_set_ArrayLit_items = _set_ArrayLit_span = _unbound


def _init_ArrayLit(self: Any, items: Any, span: Any = DEFAULT) -> None:
    _set_ArrayLit_items(self, items)
    _set_ArrayLit_span(self, span)


def _repr_ArrayLit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(items={self.items!r})"


def _eq_ArrayLit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.items,) == (other.items,)
    return NotImplemented


def _hash_ArrayLit(self: Any) -> int:
    return hash((self.items,))


_set_Unary_op = _set_Unary_operand = _set_Unary_span = _unbound


def _init_Unary(self: Any, op: Any, operand: Any, span: Any = DEFAULT) -> None:
    _set_Unary_op(self, op)
    _set_Unary_operand(self, operand)
    _set_Unary_span(self, span)


def _repr_Unary(self: Any) -> str:
    return f"{self.__class__.__qualname__}(op={self.op!r}, operand={self.operand!r})"


def _eq_Unary(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.op, self.operand) == (other.op, other.operand)
    return NotImplemented


def _hash_Unary(self: Any) -> int:
    return hash((self.op, self.operand))


_set_BinOp_op = _set_BinOp_left = _set_BinOp_right = _set_BinOp_span = _unbound


def _init_BinOp(self: Any, op: Any, left: Any, right: Any, span: Any = DEFAULT) -> None:
    _set_BinOp_op(self, op)
    _set_BinOp_left(self, left)
    _set_BinOp_right(self, right)
    _set_BinOp_span(self, span)


def _repr_BinOp(self: Any) -> str:
    return f"{self.__class__.__qualname__}(op={self.op!r}, left={self.left!r}, right={self.right!r})"


def _eq_BinOp(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.op, self.left, self.right) == (other.op, other.left, other.right)
    return NotImplemented


def _hash_BinOp(self: Any) -> int:
    return hash((self.op, self.left, self.right))


_set_Conditional_then = _set_Conditional_cond = _set_Conditional_orelse = _set_Conditional_span = _unbound


def _init_Conditional(self: Any, then: Any, cond: Any, orelse: Any, span: Any = DEFAULT) -> None:
    _set_Conditional_then(self, then)
    _set_Conditional_cond(self, cond)
    _set_Conditional_orelse(self, orelse)
    _set_Conditional_span(self, span)


def _repr_Conditional(self: Any) -> str:
    return f"{self.__class__.__qualname__}(then={self.then!r}, cond={self.cond!r}, orelse={self.orelse!r})"


def _eq_Conditional(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.then, self.cond, self.orelse) == (other.then, other.cond, other.orelse)
    return NotImplemented


def _hash_Conditional(self: Any) -> int:
    return hash((self.then, self.cond, self.orelse))


_set_CallExpr_func = _set_CallExpr_args = _set_CallExpr_span = _unbound


def _init_CallExpr(self: Any, func: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_CallExpr_func(self, func)
    _set_CallExpr_args(self, args)
    _set_CallExpr_span(self, span)


def _repr_CallExpr(self: Any) -> str:
    return f"{self.__class__.__qualname__}(func={self.func!r}, args={self.args!r})"


def _eq_CallExpr(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.func, self.args) == (other.func, other.args)
    return NotImplemented


def _hash_CallExpr(self: Any) -> int:
    return hash((self.func, self.args))


_set_Member_enum = _set_Member_member = _set_Member_span = _unbound


def _init_Member(self: Any, enum: Any, member: Any, span: Any = DEFAULT) -> None:
    _set_Member_enum(self, enum)
    _set_Member_member(self, member)
    _set_Member_span(self, span)


def _repr_Member(self: Any) -> str:
    return f"{self.__class__.__qualname__}(enum={self.enum!r}, member={self.member!r})"


def _eq_Member(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.enum, self.member) == (other.enum, other.member)
    return NotImplemented


def _hash_Member(self: Any) -> int:
    return hash((self.enum, self.member))


_set_MethodCall_base = _set_MethodCall_method = _set_MethodCall_args = _set_MethodCall_span = _unbound


def _init_MethodCall(self: Any, base: Any, method: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_MethodCall_base(self, base)
    _set_MethodCall_method(self, method)
    _set_MethodCall_args(self, args)
    _set_MethodCall_span(self, span)


def _repr_MethodCall(self: Any) -> str:
    return f"{self.__class__.__qualname__}(base={self.base!r}, method={self.method!r}, args={self.args!r})"


def _eq_MethodCall(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.base, self.method, self.args) == (other.base, other.method, other.args)
    return NotImplemented


def _hash_MethodCall(self: Any) -> int:
    return hash((self.base, self.method, self.args))


_set_ArrayOf_element = _set_ArrayOf_size = _set_ArrayOf_span = _unbound


def _init_ArrayOf(self: Any, element: Any, size: Any, span: Any = DEFAULT) -> None:
    _set_ArrayOf_element(self, element)
    _set_ArrayOf_size(self, size)
    _set_ArrayOf_span(self, span)


def _repr_ArrayOf(self: Any) -> str:
    return f"{self.__class__.__qualname__}(element={self.element!r}, size={self.size!r})"


def _eq_ArrayOf(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.element, self.size) == (other.element, other.size)
    return NotImplemented


def _hash_ArrayOf(self: Any) -> int:
    return hash((self.element, self.size))


_set_Param_name = _unbound
_set_Param_type = _unbound
_set_Param_span = _unbound
_set_Param_low = _unbound
_set_Param_high = _unbound
_set_Param_default = _unbound
_set_Param_unit = _unbound


def _init_Param(
    self: Any,
    name: Any,
    type: Any,
    span: Any = DEFAULT,
    low: Any = DEFAULT,
    high: Any = DEFAULT,
    default: Any = DEFAULT,
    unit: Any = DEFAULT,
) -> None:
    _set_Param_name(self, name)
    _set_Param_type(self, type)
    _set_Param_span(self, span)
    _set_Param_low(self, low)
    _set_Param_high(self, high)
    _set_Param_default(self, default)
    _set_Param_unit(self, unit)


def _repr_Param(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, low={self.low!r}, high={self.high!r}, default={self.default!r}, unit={self.unit!r})"


def _eq_Param(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.low,
            self.high,
            self.default,
            self.unit,
        ) == (
            other.name,
            other.type,
            other.low,
            other.high,
            other.default,
            other.unit,
        )
    return NotImplemented


def _hash_Param(self: Any) -> int:
    return hash((self.name, self.type, self.low, self.high, self.default, self.unit))


_set_Call_target = _set_Call_args = _set_Call_span = _unbound


def _init_Call(self: Any, target: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_Call_target(self, target)
    _set_Call_args(self, args)
    _set_Call_span(self, span)


def _repr_Call(self: Any) -> str:
    return f"{self.__class__.__qualname__}(target={self.target!r}, args={self.args!r})"


def _eq_Call(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.target, self.args) == (other.target, other.args)
    return NotImplemented


def _hash_Call(self: Any) -> int:
    return hash((self.target, self.args))


_set_Duration_value = _set_Duration_unit = _set_Duration_span = _unbound


def _init_Duration(self: Any, value: Any, unit: Any, span: Any = DEFAULT) -> None:
    _set_Duration_value(self, value)
    _set_Duration_unit(self, unit)
    _set_Duration_span(self, span)


def _repr_Duration(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r}, unit={self.unit!r})"


def _eq_Duration(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.value, self.unit) == (other.value, other.unit)
    return NotImplemented


def _hash_Duration(self: Any) -> int:
    return hash((self.value, self.unit))


_set_Assign_target = _set_Assign_value = _set_Assign_span = _set_Assign_index = _set_Assign_when = _unbound


def _init_Assign(
    self: Any,
    target: Any,
    value: Any,
    span: Any = DEFAULT,
    index: Any = DEFAULT,
    when: Any = DEFAULT,
) -> None:
    _set_Assign_target(self, target)
    _set_Assign_value(self, value)
    _set_Assign_span(self, span)
    _set_Assign_index(self, index)
    _set_Assign_when(self, when)


def _repr_Assign(self: Any) -> str:
    return f"{self.__class__.__qualname__}(target={self.target!r}, value={self.value!r}, index={self.index!r}, when={self.when!r})"


def _eq_Assign(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.target,
            self.value,
            self.index,
            self.when,
        ) == (
            other.target,
            other.value,
            other.index,
            other.when,
        )
    return NotImplemented


def _hash_Assign(self: Any) -> int:
    return hash((self.target, self.value, self.index, self.when))


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


_set_On_connection = _set_On_span = _unbound


def _init_On(self: Any, connection: Any, span: Any = DEFAULT) -> None:
    _set_On_connection(self, connection)
    _set_On_span(self, span)


def _repr_On(self: Any) -> str:
    return f"{self.__class__.__qualname__}(connection={self.connection!r})"


def _eq_On(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.connection,) == (other.connection,)
    return NotImplemented


def _hash_On(self: Any) -> int:
    return hash((self.connection,))


_set_Encoding_kind = _set_Encoding_template = _set_Encoding_args = _set_Encoding_span = _unbound


def _init_Encoding(self: Any, kind: Any, template: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_Encoding_kind(self, kind)
    _set_Encoding_template(self, template)
    _set_Encoding_args(self, args)
    _set_Encoding_span(self, span)


def _repr_Encoding(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, template={self.template!r}, args={self.args!r})"


def _eq_Encoding(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.kind, self.template, self.args) == (other.kind, other.template, other.args)
    return NotImplemented


def _hash_Encoding(self: Any) -> int:
    return hash((self.kind, self.template, self.args))


_set_Decoding_kind = _set_Decoding_template = _set_Decoding_span = _unbound


def _init_Decoding(self: Any, kind: Any, template: Any, span: Any = DEFAULT) -> None:
    _set_Decoding_kind(self, kind)
    _set_Decoding_template(self, template)
    _set_Decoding_span(self, span)


def _repr_Decoding(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, template={self.template!r})"


def _eq_Decoding(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.kind, self.template) == (other.kind, other.template)
    return NotImplemented


def _hash_Decoding(self: Any) -> int:
    return hash((self.kind, self.template))


_set_Actions_assigns = _set_Actions_span = _unbound


def _init_Actions(self: Any, assigns: Any, span: Any = DEFAULT) -> None:
    _set_Actions_assigns(self, assigns)
    _set_Actions_span(self, span)


def _repr_Actions(self: Any) -> str:
    return f"{self.__class__.__qualname__}(assigns={self.assigns!r})"


def _eq_Actions(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.assigns,) == (other.assigns,)
    return NotImplemented


def _hash_Actions(self: Any) -> int:
    return hash((self.assigns,))


_set_Framed_frame = _set_Framed_args = _set_Framed_span = _unbound


def _init_Framed(self: Any, frame: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_Framed_frame(self, frame)
    _set_Framed_args(self, args)
    _set_Framed_span(self, span)


def _repr_Framed(self: Any) -> str:
    return f"{self.__class__.__qualname__}(frame={self.frame!r}, args={self.args!r})"


def _eq_Framed(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.frame, self.args) == (other.frame, other.args)
    return NotImplemented


def _hash_Framed(self: Any) -> int:
    return hash((self.frame, self.args))


_set_SkipUnmatched_span = _unbound


def _init_SkipUnmatched(self: Any, span: Any = DEFAULT) -> None:
    _set_SkipUnmatched_span(self, span)


def _repr_SkipUnmatched(self: Any) -> str:
    return f"{self.__class__.__qualname__}()"


def _eq_SkipUnmatched(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return () == ()
    return NotImplemented


def _hash_SkipUnmatched(self: Any) -> int:
    return hash(())


_set_ReplyEntry_value = _unbound
_set_ReplyEntry_decoding = _unbound
_set_ReplyEntry_actions = _unbound
_set_ReplyEntry_span = _unbound
_set_ReplyEntry_last = _unbound
_set_ReplyEntry_until = _unbound
_set_ReplyEntry_table = _unbound


def _init_ReplyEntry(
    self: Any,
    value: Any,
    decoding: Any,
    actions: Any,
    span: Any = DEFAULT,
    last: Any = DEFAULT,
    until: Any = DEFAULT,
    table: Any = DEFAULT,
) -> None:
    _set_ReplyEntry_value(self, value)
    _set_ReplyEntry_decoding(self, decoding)
    _set_ReplyEntry_actions(self, actions)
    _set_ReplyEntry_span(self, span)
    _set_ReplyEntry_last(self, last)
    _set_ReplyEntry_until(self, until)
    _set_ReplyEntry_table(self, table)


def _repr_ReplyEntry(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r}, decoding={self.decoding!r}, actions={self.actions!r}, last={self.last!r}, until={self.until!r}, table={self.table!r})"


def _eq_ReplyEntry(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.value,
            self.decoding,
            self.actions,
            self.last,
            self.until,
            self.table,
        ) == (
            other.value,
            other.decoding,
            other.actions,
            other.last,
            other.until,
            other.table,
        )
    return NotImplemented


def _hash_ReplyEntry(self: Any) -> int:
    return hash((self.value, self.decoding, self.actions, self.last, self.until, self.table))


_set_ReplyTable_key = _unbound
_set_ReplyTable_entries = _unbound
_set_ReplyTable_span = _unbound
_set_ReplyTable_tag = _unbound
_set_ReplyTable_each = _unbound
_set_ReplyTable_length = _unbound


def _init_ReplyTable(
    self: Any,
    key: Any,
    entries: Any,
    span: Any = DEFAULT,
    tag: Any = DEFAULT,
    each: Any = DEFAULT,
    length: Any = DEFAULT,
) -> None:
    _set_ReplyTable_key(self, key)
    _set_ReplyTable_entries(self, entries)
    _set_ReplyTable_span(self, span)
    _set_ReplyTable_tag(self, tag)
    _set_ReplyTable_each(self, each)
    _set_ReplyTable_length(self, length)


def _repr_ReplyTable(self: Any) -> str:
    return f"{self.__class__.__qualname__}(key={self.key!r}, entries={self.entries!r}, tag={self.tag!r}, each={self.each!r}, length={self.length!r})"


def _eq_ReplyTable(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.key,
            self.entries,
            self.tag,
            self.each,
            self.length,
        ) == (
            other.key,
            other.entries,
            other.tag,
            other.each,
            other.length,
        )
    return NotImplemented


def _hash_ReplyTable(self: Any) -> int:
    return hash((self.key, self.entries, self.tag, self.each, self.length))


_set_Retry_count = _set_Retry_span = _unbound


def _init_Retry(self: Any, count: Any, span: Any = DEFAULT) -> None:
    _set_Retry_count(self, count)
    _set_Retry_span(self, span)


def _repr_Retry(self: Any) -> str:
    return f"{self.__class__.__qualname__}(count={self.count!r})"


def _eq_Retry(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.count,) == (other.count,)
    return NotImplemented


def _hash_Retry(self: Any) -> int:
    return hash((self.count,))


_set_ReplyTimeout_duration = _set_ReplyTimeout_span = _unbound


def _init_ReplyTimeout(self: Any, duration: Any, span: Any = DEFAULT) -> None:
    _set_ReplyTimeout_duration(self, duration)
    _set_ReplyTimeout_span(self, span)


def _repr_ReplyTimeout(self: Any) -> str:
    return f"{self.__class__.__qualname__}(duration={self.duration!r})"


def _eq_ReplyTimeout(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.duration,) == (other.duration,)
    return NotImplemented


def _hash_ReplyTimeout(self: Any) -> int:
    return hash((self.duration,))


_set_Replies_over = _set_Replies_span = _set_Replies_var = _set_Replies_high = _set_Replies_frame = _unbound


def _init_Replies(
    self: Any,
    over: Any,
    span: Any = DEFAULT,
    var: Any = DEFAULT,
    high: Any = DEFAULT,
    frame: Any = DEFAULT,
) -> None:
    _set_Replies_over(self, over)
    _set_Replies_span(self, span)
    _set_Replies_var(self, var)
    _set_Replies_high(self, high)
    _set_Replies_frame(self, frame)


def _repr_Replies(self: Any) -> str:
    return f"{self.__class__.__qualname__}(over={self.over!r}, var={self.var!r}, high={self.high!r}, frame={self.frame!r})"


def _eq_Replies(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.over,
            self.var,
            self.high,
            self.frame,
        ) == (
            other.over,
            other.var,
            other.high,
            other.frame,
        )
    return NotImplemented


def _hash_Replies(self: Any) -> int:
    return hash((self.over, self.var, self.high, self.frame))


_set_ListedReply_decoding = _unbound
_set_ListedReply_span = _unbound
_set_ListedReply_frame = _unbound
_set_ListedReply_expect = _unbound
_set_ListedReply_actions = _unbound


def _init_ListedReply(
    self: Any,
    decoding: Any,
    span: Any = DEFAULT,
    frame: Any = DEFAULT,
    expect: Any = DEFAULT,
    actions: Any = DEFAULT,
) -> None:
    _set_ListedReply_decoding(self, decoding)
    _set_ListedReply_span(self, span)
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


_set_ReplyList_replies = _set_ReplyList_span = _unbound


def _init_ReplyList(self: Any, replies: Any, span: Any = DEFAULT) -> None:
    _set_ReplyList_replies(self, replies)
    _set_ReplyList_span(self, span)


def _repr_ReplyList(self: Any) -> str:
    return f"{self.__class__.__qualname__}(replies={self.replies!r})"


def _eq_ReplyList(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.replies,) == (other.replies,)
    return NotImplemented


def _hash_ReplyList(self: Any) -> int:
    return hash((self.replies,))


_set_Expect_condition = _set_Expect_span = _unbound


def _init_Expect(self: Any, condition: Any, span: Any = DEFAULT) -> None:
    _set_Expect_condition(self, condition)
    _set_Expect_span(self, span)


def _repr_Expect(self: Any) -> str:
    return f"{self.__class__.__qualname__}(condition={self.condition!r})"


def _eq_Expect(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.condition,) == (other.condition,)
    return NotImplemented


def _hash_Expect(self: Any) -> int:
    return hash((self.condition,))


_set_Records_marker = _set_Records_span = _unbound


def _init_Records(self: Any, marker: Any, span: Any = DEFAULT) -> None:
    _set_Records_marker(self, marker)
    _set_Records_span(self, span)


def _repr_Records(self: Any) -> str:
    return f"{self.__class__.__qualname__}(marker={self.marker!r})"


def _eq_Records(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.marker,) == (other.marker,)
    return NotImplemented


def _hash_Records(self: Any) -> int:
    return hash((self.marker,))


_set_LineBreak_duration = _set_LineBreak_span = _unbound


def _init_LineBreak(self: Any, duration: Any, span: Any = DEFAULT) -> None:
    _set_LineBreak_duration(self, duration)
    _set_LineBreak_span(self, span)


def _repr_LineBreak(self: Any) -> str:
    return f"{self.__class__.__qualname__}(duration={self.duration!r})"


def _eq_LineBreak(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.duration,) == (other.duration,)
    return NotImplemented


def _hash_LineBreak(self: Any) -> int:
    return hash((self.duration,))


_set_Lines_settings = _set_Lines_span = _unbound


def _init_Lines(self: Any, settings: Any, span: Any = DEFAULT) -> None:
    _set_Lines_settings(self, settings)
    _set_Lines_span(self, span)


def _repr_Lines(self: Any) -> str:
    return f"{self.__class__.__qualname__}(settings={self.settings!r})"


def _eq_Lines(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.settings,) == (other.settings,)
    return NotImplemented


def _hash_Lines(self: Any) -> int:
    return hash((self.settings,))


_set_ErrorReply_decoding = _unbound
_set_ErrorReply_span = _unbound
_set_ErrorReply_frame = _unbound
_set_ErrorReply_marker = _unbound
_set_ErrorReply_codes = _unbound
_set_ErrorReply_when = _unbound


def _init_ErrorReply(
    self: Any,
    decoding: Any,
    span: Any = DEFAULT,
    frame: Any = DEFAULT,
    marker: Any = DEFAULT,
    codes: Any = DEFAULT,
    when: Any = DEFAULT,
) -> None:
    _set_ErrorReply_decoding(self, decoding)
    _set_ErrorReply_span(self, span)
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


_set_PrimitiveDecl_name = _unbound
_set_PrimitiveDecl_params = _unbound
_set_PrimitiveDecl_clauses = _unbound
_set_PrimitiveDecl_span = _unbound
_set_PrimitiveDecl_doc = _unbound


def _init_PrimitiveDecl(
    self: Any,
    name: Any,
    params: Any,
    clauses: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_PrimitiveDecl_name(self, name)
    _set_PrimitiveDecl_params(self, params)
    _set_PrimitiveDecl_clauses(self, clauses)
    _set_PrimitiveDecl_span(self, span)
    _set_PrimitiveDecl_doc(self, doc)


def _repr_PrimitiveDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, clauses={self.clauses!r}, doc={self.doc!r})"


def _eq_PrimitiveDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.clauses,
            self.doc,
        ) == (
            other.name,
            other.params,
            other.clauses,
            other.doc,
        )
    return NotImplemented


def _hash_PrimitiveDecl(self: Any) -> int:
    return hash((self.name, self.params, self.clauses, self.doc))


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


_set_Shape_kind = _set_Shape_args = _set_Shape_span = _unbound


def _init_Shape(self: Any, kind: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_Shape_kind(self, kind)
    _set_Shape_args(self, args)
    _set_Shape_span(self, span)


def _repr_Shape(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, args={self.args!r})"


def _eq_Shape(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.kind, self.args) == (other.kind, other.args)
    return NotImplemented


def _hash_Shape(self: Any) -> int:
    return hash((self.kind, self.args))


_set_ShapeUse_role = _unbound
_set_ShapeUse_shape = _unbound
_set_ShapeUse_at = _unbound
_set_ShapeUse_rpy = _unbound
_set_ShapeUse_span = _unbound
_set_ShapeUse_color = _unbound


def _init_ShapeUse(
    self: Any,
    role: Any,
    shape: Any,
    at: Any,
    rpy: Any,
    span: Any = DEFAULT,
    color: Any = DEFAULT,
) -> None:
    _set_ShapeUse_role(self, role)
    _set_ShapeUse_shape(self, shape)
    _set_ShapeUse_at(self, at)
    _set_ShapeUse_rpy(self, rpy)
    _set_ShapeUse_span(self, span)
    _set_ShapeUse_color(self, color)


def _repr_ShapeUse(self: Any) -> str:
    return f"{self.__class__.__qualname__}(role={self.role!r}, shape={self.shape!r}, at={self.at!r}, rpy={self.rpy!r}, color={self.color!r})"


def _eq_ShapeUse(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.role,
            self.shape,
            self.at,
            self.rpy,
            self.color,
        ) == (
            other.role,
            other.shape,
            other.at,
            other.rpy,
            other.color,
        )
    return NotImplemented


def _hash_ShapeUse(self: Any) -> int:
    return hash((self.role, self.shape, self.at, self.rpy, self.color))


_set_LinkSpawn_kind = _set_LinkSpawn_at = _set_LinkSpawn_rpy = _set_LinkSpawn_span = _unbound


def _init_LinkSpawn(self: Any, kind: Any, at: Any, rpy: Any, span: Any = DEFAULT) -> None:
    _set_LinkSpawn_kind(self, kind)
    _set_LinkSpawn_at(self, at)
    _set_LinkSpawn_rpy(self, rpy)
    _set_LinkSpawn_span(self, span)


def _repr_LinkSpawn(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, at={self.at!r}, rpy={self.rpy!r})"


def _eq_LinkSpawn(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.kind, self.at, self.rpy) == (other.kind, other.at, other.rpy)
    return NotImplemented


def _hash_LinkSpawn(self: Any) -> int:
    return hash((self.kind, self.at, self.rpy))


_set_BodyValue_key = _set_BodyValue_value = _set_BodyValue_span = _unbound


def _init_BodyValue(self: Any, key: Any, value: Any, span: Any = DEFAULT) -> None:
    _set_BodyValue_key(self, key)
    _set_BodyValue_value(self, value)
    _set_BodyValue_span(self, span)


def _repr_BodyValue(self: Any) -> str:
    return f"{self.__class__.__qualname__}(key={self.key!r}, value={self.value!r})"


def _eq_BodyValue(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.key, self.value) == (other.key, other.value)
    return NotImplemented


def _hash_BodyValue(self: Any) -> int:
    return hash((self.key, self.value))


_set_JointLimit_low = _set_JointLimit_high = _set_JointLimit_span = _unbound


def _init_JointLimit(self: Any, low: Any, high: Any, span: Any = DEFAULT) -> None:
    _set_JointLimit_low(self, low)
    _set_JointLimit_high(self, high)
    _set_JointLimit_span(self, span)


def _repr_JointLimit(self: Any) -> str:
    return f"{self.__class__.__qualname__}(low={self.low!r}, high={self.high!r})"


def _eq_JointLimit(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.low, self.high) == (other.low, other.high)
    return NotImplemented


def _hash_JointLimit(self: Any) -> int:
    return hash((self.low, self.high))


_set_JointMimic_joint = _set_JointMimic_multiplier = _set_JointMimic_offset = _set_JointMimic_span = _unbound


def _init_JointMimic(self: Any, joint: Any, multiplier: Any, offset: Any, span: Any = DEFAULT) -> None:
    _set_JointMimic_joint(self, joint)
    _set_JointMimic_multiplier(self, multiplier)
    _set_JointMimic_offset(self, offset)
    _set_JointMimic_span(self, span)


def _repr_JointMimic(self: Any) -> str:
    return f"{self.__class__.__qualname__}(joint={self.joint!r}, multiplier={self.multiplier!r}, offset={self.offset!r})"


def _eq_JointMimic(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.joint, self.multiplier, self.offset) == (other.joint, other.multiplier, other.offset)
    return NotImplemented


def _hash_JointMimic(self: Any) -> int:
    return hash((self.joint, self.multiplier, self.offset))


_set_LinkDecl_name = _set_LinkDecl_items = _set_LinkDecl_span = _set_LinkDecl_doc = _unbound


def _init_LinkDecl(self: Any, name: Any, items: Any, span: Any = DEFAULT, doc: Any = DEFAULT) -> None:
    _set_LinkDecl_name(self, name)
    _set_LinkDecl_items(self, items)
    _set_LinkDecl_span(self, span)
    _set_LinkDecl_doc(self, doc)


def _repr_LinkDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, items={self.items!r}, doc={self.doc!r})"


def _eq_LinkDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.items, self.doc) == (other.name, other.items, other.doc)
    return NotImplemented


def _hash_LinkDecl(self: Any) -> int:
    return hash((self.name, self.items, self.doc))


_set_JointDecl_name = _unbound
_set_JointDecl_kind = _unbound
_set_JointDecl_parent = _unbound
_set_JointDecl_child = _unbound
_set_JointDecl_items = _unbound
_set_JointDecl_span = _unbound
_set_JointDecl_doc = _unbound


def _init_JointDecl(
    self: Any,
    name: Any,
    kind: Any,
    parent: Any,
    child: Any,
    items: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_JointDecl_name(self, name)
    _set_JointDecl_kind(self, kind)
    _set_JointDecl_parent(self, parent)
    _set_JointDecl_child(self, child)
    _set_JointDecl_items(self, items)
    _set_JointDecl_span(self, span)
    _set_JointDecl_doc(self, doc)


def _repr_JointDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, kind={self.kind!r}, parent={self.parent!r}, child={self.child!r}, items={self.items!r}, doc={self.doc!r})"


def _eq_JointDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.kind,
            self.parent,
            self.child,
            self.items,
            self.doc,
        ) == (
            other.name,
            other.kind,
            other.parent,
            other.child,
            other.items,
            other.doc,
        )
    return NotImplemented


def _hash_JointDecl(self: Any) -> int:
    return hash((self.name, self.kind, self.parent, self.child, self.items, self.doc))


_set_Binding_role = _unbound
_set_Binding_quantity = _unbound
_set_Binding_target = _unbound
_set_Binding_member = _unbound
_set_Binding_index = _unbound
_set_Binding_conversions = _unbound
_set_Binding_span = _unbound


def _init_Binding(
    self: Any,
    role: Any,
    quantity: Any,
    target: Any,
    member: Any,
    index: Any,
    conversions: Any,
    span: Any = DEFAULT,
) -> None:
    _set_Binding_role(self, role)
    _set_Binding_quantity(self, quantity)
    _set_Binding_target(self, target)
    _set_Binding_member(self, member)
    _set_Binding_index(self, index)
    _set_Binding_conversions(self, conversions)
    _set_Binding_span(self, span)


def _repr_Binding(self: Any) -> str:
    return f"{self.__class__.__qualname__}(role={self.role!r}, quantity={self.quantity!r}, target={self.target!r}, member={self.member!r}, index={self.index!r}, conversions={self.conversions!r})"


def _eq_Binding(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.role,
            self.quantity,
            self.target,
            self.member,
            self.index,
            self.conversions,
        ) == (
            other.role,
            other.quantity,
            other.target,
            other.member,
            other.index,
            other.conversions,
        )
    return NotImplemented


def _hash_Binding(self: Any) -> int:
    return hash((self.role, self.quantity, self.target, self.member, self.index, self.conversions))


_set_TransmissionDecl_name = _unbound
_set_TransmissionDecl_joint = _unbound
_set_TransmissionDecl_bindings = _unbound
_set_TransmissionDecl_span = _unbound
_set_TransmissionDecl_doc = _unbound
_set_TransmissionDecl_actuator = _unbound


def _init_TransmissionDecl(
    self: Any,
    name: Any,
    joint: Any,
    bindings: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
    actuator: Any = DEFAULT,
) -> None:
    _set_TransmissionDecl_name(self, name)
    _set_TransmissionDecl_joint(self, joint)
    _set_TransmissionDecl_bindings(self, bindings)
    _set_TransmissionDecl_span(self, span)
    _set_TransmissionDecl_doc(self, doc)
    _set_TransmissionDecl_actuator(self, actuator)


def _repr_TransmissionDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, joint={self.joint!r}, bindings={self.bindings!r}, doc={self.doc!r}, actuator={self.actuator!r})"


def _eq_TransmissionDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.joint,
            self.bindings,
            self.doc,
            self.actuator,
        ) == (
            other.name,
            other.joint,
            other.bindings,
            other.doc,
            other.actuator,
        )
    return NotImplemented


def _hash_TransmissionDecl(self: Any) -> int:
    return hash((self.name, self.joint, self.bindings, self.doc, self.actuator))


_set_ActuatorDecl_name = _unbound
_set_ActuatorDecl_kind = _unbound
_set_ActuatorDecl_items = _unbound
_set_ActuatorDecl_span = _unbound
_set_ActuatorDecl_doc = _unbound


def _init_ActuatorDecl(
    self: Any,
    name: Any,
    kind: Any,
    items: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_ActuatorDecl_name(self, name)
    _set_ActuatorDecl_kind(self, kind)
    _set_ActuatorDecl_items(self, items)
    _set_ActuatorDecl_span(self, span)
    _set_ActuatorDecl_doc(self, doc)


def _repr_ActuatorDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, kind={self.kind!r}, items={self.items!r}, doc={self.doc!r})"


def _eq_ActuatorDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.kind,
            self.items,
            self.doc,
        ) == (
            other.name,
            other.kind,
            other.items,
            other.doc,
        )
    return NotImplemented


def _hash_ActuatorDecl(self: Any) -> int:
    return hash((self.name, self.kind, self.items, self.doc))


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
    "Ident": Written(
        (("text", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Ident, "__repr__": _repr_Ident, "__eq__": _eq_Ident, "__hash__": _hash_Ident},
    ),
    "IntLit": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_IntLit, "__repr__": _repr_IntLit, "__eq__": _eq_IntLit, "__hash__": _hash_IntLit},
    ),
    "FloatLit": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_FloatLit,
            "__repr__": _repr_FloatLit,
            "__eq__": _eq_FloatLit,
            "__hash__": _hash_FloatLit,
        },
    ),
    "StrLit": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_StrLit, "__repr__": _repr_StrLit, "__eq__": _eq_StrLit, "__hash__": _hash_StrLit},
    ),
    "BytesLit": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_BytesLit,
            "__repr__": _repr_BytesLit,
            "__eq__": _eq_BytesLit,
            "__hash__": _hash_BytesLit,
        },
    ),
    "BoolLit": Written(
        (("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_BoolLit,
            "__repr__": _repr_BoolLit,
            "__eq__": _eq_BoolLit,
            "__hash__": _hash_BoolLit,
        },
    ),
    "Ref": Written(
        (("name", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Ref, "__repr__": _repr_Ref, "__eq__": _eq_Ref, "__hash__": _hash_Ref},
    ),
    "Index": Written(
        (("base", MISSING), ("index", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Index, "__repr__": _repr_Index, "__eq__": _eq_Index, "__hash__": _hash_Index},
    ),
    "ArrayLit": Written(
        (("items", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_ArrayLit,
            "__repr__": _repr_ArrayLit,
            "__eq__": _eq_ArrayLit,
            "__hash__": _hash_ArrayLit,
        },
    ),
    "Unary": Written(
        (("op", MISSING), ("operand", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Unary, "__repr__": _repr_Unary, "__eq__": _eq_Unary, "__hash__": _hash_Unary},
    ),
    "BinOp": Written(
        (
            ("op", MISSING),
            ("left", MISSING),
            ("right", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_BinOp, "__repr__": _repr_BinOp, "__eq__": _eq_BinOp, "__hash__": _hash_BinOp},
    ),
    "Conditional": Written(
        (
            ("then", MISSING),
            ("cond", MISSING),
            ("orelse", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_Conditional,
            "__repr__": _repr_Conditional,
            "__eq__": _eq_Conditional,
            "__hash__": _hash_Conditional,
        },
    ),
    "CallExpr": Written(
        (("func", MISSING), ("args", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_CallExpr,
            "__repr__": _repr_CallExpr,
            "__eq__": _eq_CallExpr,
            "__hash__": _hash_CallExpr,
        },
    ),
    "Member": Written(
        (("enum", MISSING), ("member", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Member, "__repr__": _repr_Member, "__eq__": _eq_Member, "__hash__": _hash_Member},
    ),
    "MethodCall": Written(
        (
            ("base", MISSING),
            ("method", MISSING),
            ("args", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_MethodCall,
            "__repr__": _repr_MethodCall,
            "__eq__": _eq_MethodCall,
            "__hash__": _hash_MethodCall,
        },
    ),
    "ArrayOf": Written(
        (("element", MISSING), ("size", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_ArrayOf,
            "__repr__": _repr_ArrayOf,
            "__eq__": _eq_ArrayOf,
            "__hash__": _hash_ArrayOf,
        },
    ),
    "Param": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("low", DEFAULT),
            ("high", DEFAULT),
            ("default", DEFAULT),
            ("unit", DEFAULT),
        ),
        {"__init__": _init_Param, "__repr__": _repr_Param, "__eq__": _eq_Param, "__hash__": _hash_Param},
    ),
    "Call": Written(
        (("target", MISSING), ("args", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Call, "__repr__": _repr_Call, "__eq__": _eq_Call, "__hash__": _hash_Call},
    ),
    "Duration": Written(
        (("value", MISSING), ("unit", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Duration,
            "__repr__": _repr_Duration,
            "__eq__": _eq_Duration,
            "__hash__": _hash_Duration,
        },
    ),
    "Assign": Written(
        (
            ("target", MISSING),
            ("value", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("index", DEFAULT),
            ("when", DEFAULT),
        ),
        {"__init__": _init_Assign, "__repr__": _repr_Assign, "__eq__": _eq_Assign, "__hash__": _hash_Assign},
    ),
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
    "On": Written(
        (("connection", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_On, "__repr__": _repr_On, "__eq__": _eq_On, "__hash__": _hash_On},
    ),
    "Encoding": Written(
        (
            ("kind", MISSING),
            ("template", MISSING),
            ("args", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_Encoding,
            "__repr__": _repr_Encoding,
            "__eq__": _eq_Encoding,
            "__hash__": _hash_Encoding,
        },
    ),
    "Decoding": Written(
        (("kind", MISSING), ("template", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Decoding,
            "__repr__": _repr_Decoding,
            "__eq__": _eq_Decoding,
            "__hash__": _hash_Decoding,
        },
    ),
    "Actions": Written(
        (("assigns", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Actions,
            "__repr__": _repr_Actions,
            "__eq__": _eq_Actions,
            "__hash__": _hash_Actions,
        },
    ),
    "Framed": Written(
        (("frame", MISSING), ("args", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Framed, "__repr__": _repr_Framed, "__eq__": _eq_Framed, "__hash__": _hash_Framed},
    ),
    "SkipUnmatched": Written(
        (("span", FieldSpec(None, MISSING, False, False)),),
        {
            "__init__": _init_SkipUnmatched,
            "__repr__": _repr_SkipUnmatched,
            "__eq__": _eq_SkipUnmatched,
            "__hash__": _hash_SkipUnmatched,
        },
    ),
    "ReplyEntry": Written(
        (
            ("value", MISSING),
            ("decoding", MISSING),
            ("actions", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("last", DEFAULT),
            ("until", DEFAULT),
            ("table", DEFAULT),
        ),
        {
            "__init__": _init_ReplyEntry,
            "__repr__": _repr_ReplyEntry,
            "__eq__": _eq_ReplyEntry,
            "__hash__": _hash_ReplyEntry,
        },
    ),
    "ReplyTable": Written(
        (
            ("key", MISSING),
            ("entries", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("tag", DEFAULT),
            ("each", DEFAULT),
            ("length", DEFAULT),
        ),
        {
            "__init__": _init_ReplyTable,
            "__repr__": _repr_ReplyTable,
            "__eq__": _eq_ReplyTable,
            "__hash__": _hash_ReplyTable,
        },
    ),
    "Retry": Written(
        (("count", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Retry, "__repr__": _repr_Retry, "__eq__": _eq_Retry, "__hash__": _hash_Retry},
    ),
    "ReplyTimeout": Written(
        (("duration", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_ReplyTimeout,
            "__repr__": _repr_ReplyTimeout,
            "__eq__": _eq_ReplyTimeout,
            "__hash__": _hash_ReplyTimeout,
        },
    ),
    "Replies": Written(
        (
            ("over", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("var", DEFAULT),
            ("high", DEFAULT),
            ("frame", DEFAULT),
        ),
        {
            "__init__": _init_Replies,
            "__repr__": _repr_Replies,
            "__eq__": _eq_Replies,
            "__hash__": _hash_Replies,
        },
    ),
    "ListedReply": Written(
        (
            ("decoding", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("frame", DEFAULT),
            ("expect", DEFAULT),
            ("actions", DEFAULT),
        ),
        {
            "__init__": _init_ListedReply,
            "__repr__": _repr_ListedReply,
            "__eq__": _eq_ListedReply,
            "__hash__": _hash_ListedReply,
        },
    ),
    "ReplyList": Written(
        (("replies", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_ReplyList,
            "__repr__": _repr_ReplyList,
            "__eq__": _eq_ReplyList,
            "__hash__": _hash_ReplyList,
        },
    ),
    "Expect": Written(
        (("condition", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Expect, "__repr__": _repr_Expect, "__eq__": _eq_Expect, "__hash__": _hash_Expect},
    ),
    "Records": Written(
        (("marker", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Records,
            "__repr__": _repr_Records,
            "__eq__": _eq_Records,
            "__hash__": _hash_Records,
        },
    ),
    "LineBreak": Written(
        (("duration", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_LineBreak,
            "__repr__": _repr_LineBreak,
            "__eq__": _eq_LineBreak,
            "__hash__": _hash_LineBreak,
        },
    ),
    "Lines": Written(
        (("settings", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Lines, "__repr__": _repr_Lines, "__eq__": _eq_Lines, "__hash__": _hash_Lines},
    ),
    "ErrorReply": Written(
        (
            ("decoding", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
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
    "PrimitiveDecl": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("clauses", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_PrimitiveDecl,
            "__repr__": _repr_PrimitiveDecl,
            "__eq__": _eq_PrimitiveDecl,
            "__hash__": _hash_PrimitiveDecl,
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
    "Shape": Written(
        (("kind", MISSING), ("args", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Shape, "__repr__": _repr_Shape, "__eq__": _eq_Shape, "__hash__": _hash_Shape},
    ),
    "ShapeUse": Written(
        (
            ("role", MISSING),
            ("shape", MISSING),
            ("at", MISSING),
            ("rpy", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("color", DEFAULT),
        ),
        {
            "__init__": _init_ShapeUse,
            "__repr__": _repr_ShapeUse,
            "__eq__": _eq_ShapeUse,
            "__hash__": _hash_ShapeUse,
        },
    ),
    "LinkSpawn": Written(
        (
            ("kind", MISSING),
            ("at", MISSING),
            ("rpy", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_LinkSpawn,
            "__repr__": _repr_LinkSpawn,
            "__eq__": _eq_LinkSpawn,
            "__hash__": _hash_LinkSpawn,
        },
    ),
    "BodyValue": Written(
        (("key", MISSING), ("value", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_BodyValue,
            "__repr__": _repr_BodyValue,
            "__eq__": _eq_BodyValue,
            "__hash__": _hash_BodyValue,
        },
    ),
    "JointLimit": Written(
        (("low", MISSING), ("high", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_JointLimit,
            "__repr__": _repr_JointLimit,
            "__eq__": _eq_JointLimit,
            "__hash__": _hash_JointLimit,
        },
    ),
    "JointMimic": Written(
        (
            ("joint", MISSING),
            ("multiplier", MISSING),
            ("offset", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_JointMimic,
            "__repr__": _repr_JointMimic,
            "__eq__": _eq_JointMimic,
            "__hash__": _hash_JointMimic,
        },
    ),
    "LinkDecl": Written(
        (
            ("name", MISSING),
            ("items", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_LinkDecl,
            "__repr__": _repr_LinkDecl,
            "__eq__": _eq_LinkDecl,
            "__hash__": _hash_LinkDecl,
        },
    ),
    "JointDecl": Written(
        (
            ("name", MISSING),
            ("kind", MISSING),
            ("parent", MISSING),
            ("child", MISSING),
            ("items", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_JointDecl,
            "__repr__": _repr_JointDecl,
            "__eq__": _eq_JointDecl,
            "__hash__": _hash_JointDecl,
        },
    ),
    "Binding": Written(
        (
            ("role", MISSING),
            ("quantity", MISSING),
            ("target", MISSING),
            ("member", MISSING),
            ("index", MISSING),
            ("conversions", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_Binding,
            "__repr__": _repr_Binding,
            "__eq__": _eq_Binding,
            "__hash__": _hash_Binding,
        },
    ),
    "TransmissionDecl": Written(
        (
            ("name", MISSING),
            ("joint", MISSING),
            ("bindings", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
            ("actuator", DEFAULT),
        ),
        {
            "__init__": _init_TransmissionDecl,
            "__repr__": _repr_TransmissionDecl,
            "__eq__": _eq_TransmissionDecl,
            "__hash__": _hash_TransmissionDecl,
        },
    ),
    "ActuatorDecl": Written(
        (
            ("name", MISSING),
            ("kind", MISSING),
            ("items", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_ActuatorDecl,
            "__repr__": _repr_ActuatorDecl,
            "__eq__": _eq_ActuatorDecl,
            "__hash__": _hash_ActuatorDecl,
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
