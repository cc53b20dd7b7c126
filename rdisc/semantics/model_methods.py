"""The methods of the frozen dataclasses of rdisc/semantics/model.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import DEFAULT, FACTORY, MISSING, FieldSpec, Written, classes, field

if TYPE_CHECKING:
    from typing import Any

__all__ = ["dataclass", "field"]

# Each field's setter, `_set_<class>_<field>(instance, value)`: its slot's own `__set__`, bound by
# rdisc.frozen when it makes the class (a third faster than object.__setattr__ with the field's name).
_unbound: Any = None


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
