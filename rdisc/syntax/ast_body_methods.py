"""The methods of the frozen dataclasses of rdisc/syntax/ast_body.py, written out ahead of time (why: rdisc/frozen.py).

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


WRITTEN: dict[str, Written] = {
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
}
dataclass = classes(WRITTEN)
