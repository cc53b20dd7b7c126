"""The methods of the frozen dataclasses of rdisc/semantics/model_body.py, written out ahead of time (why: rdisc/frozen.py).

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


WRITTEN: dict[str, Written] = {
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
}
dataclass = classes(WRITTEN)
