"""The methods of the frozen dataclasses of rdisc/syntax/ast_expressions.py, written out ahead of time (why: rdisc/frozen.py).

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
}
dataclass = classes(WRITTEN)
