"""The Model: the checked, resolved, typed description that every emitter and the
runtime consume. Built only after checking succeeded, so every reference in it
names an element that exists (references are typed keys into per-kind maps).

This module is the Model's one namespace (`from rdisc.semantics import model as m; m.Primitive`,
as its readers write it): it declares the `Model` and re-exports the classes of the modules that
declare the parts, each with one concern: values and typed expressions (`model_expressions`),
struct layouts and reply actions (`model_layouts`), frames and reply shapes (`model_frames`),
the elements (`model_elements`) and the body (`model_body`).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.semantics.model_body import (
    ORIGIN,
    Actuator,
    ActuatorKind,
    Binding,
    Inertial,
    Joint,
    JointKind,
    Link,
    Mimic,
    Pose,
    Quantity,
    Shape,
    ShapeKind,
    Spawn,
    Transmission,
    Vector,
    Written,
    world_joint,
)
from rdisc.semantics.model_elements import (
    Adapter,
    AdapterField,
    Connection,
    DomainInput,
    DomainOutput,
    FrameworkMapping,
    HookCall,
    Interface,
    Kalman,
    Keepalive,
    Noise,
    Primitive,
    PrimitiveCall,
    Robot,
    Rows,
    Sensor,
    Setting,
    StateVariable,
)
from rdisc.semantics.model_expressions import (
    AdapterRef,
    AnyType,
    Array,
    ArrayValue,
    BinaryOp,
    ConnectionRef,
    Const,
    Element,
    Expr,
    FrameRef,
    FuncCall,
    IfElse,
    InTable,
    InterfaceRef,
    Lookup,
    OutputRef,
    Parameter,
    PrimitiveRef,
    Replaced,
    ReplyValue,
    Scope,
    StateRef,
    Table,
    Type,
    UnaryOp,
    Value,
    Var,
    array_name,
    coerce,
    operands,
    spread,
    variables,
)
from rdisc.semantics.model_frames import (
    INDEX,
    TAG,
    BitField,
    ChecksumAlgorithm,
    ErrorReply,
    Escaping,
    Frame,
    FrameBits,
    FrameBytes,
    FrameChecksum,
    FrameField,
    FrameLength,
    FrameOptional,
    FramePart,
    FramePayload,
    FrameSeed,
    FrameUse,
    ListedReply,
    RepliesEach,
    ReplyCase,
    ReplyTable,
)
from rdisc.semantics.model_layouts import (
    BREAK,
    MODEM_LINES,
    REFUSED,
    Format,
    LineLevel,
    Pack,
    PostAction,
    Regex,
    Slot,
    StructLayout,
    Unpack,
    Varying,
    bit_span,
    looks_up,
    may_outgrow,
)

__all__ = [
    "BREAK",
    "INDEX",
    "MODEM_LINES",
    "ORIGIN",
    "REFUSED",
    "TAG",
    "Actuator",
    "ActuatorKind",
    "Adapter",
    "AdapterField",
    "AdapterRef",
    "AnyType",
    "Array",
    "ArrayValue",
    "BinaryOp",
    "Binding",
    "BitField",
    "ChecksumAlgorithm",
    "Connection",
    "ConnectionRef",
    "Const",
    "DomainInput",
    "DomainOutput",
    "Element",
    "ErrorReply",
    "Escaping",
    "Expr",
    "Format",
    "Frame",
    "FrameBits",
    "FrameBytes",
    "FrameChecksum",
    "FrameField",
    "FrameLength",
    "FrameOptional",
    "FramePart",
    "FramePayload",
    "FrameRef",
    "FrameSeed",
    "FrameUse",
    "FrameworkMapping",
    "FuncCall",
    "HookCall",
    "IfElse",
    "InTable",
    "Inertial",
    "Interface",
    "InterfaceRef",
    "Joint",
    "JointKind",
    "Kalman",
    "Keepalive",
    "LineLevel",
    "Link",
    "ListedReply",
    "Lookup",
    "Mimic",
    "Model",
    "Noise",
    "OutputRef",
    "Pack",
    "Parameter",
    "Pose",
    "PostAction",
    "Primitive",
    "PrimitiveCall",
    "PrimitiveRef",
    "Quantity",
    "Regex",
    "Replaced",
    "RepliesEach",
    "ReplyCase",
    "ReplyTable",
    "ReplyValue",
    "Robot",
    "Rows",
    "Scope",
    "Sensor",
    "Setting",
    "Shape",
    "ShapeKind",
    "Slot",
    "Spawn",
    "StateRef",
    "StateVariable",
    "StructLayout",
    "Table",
    "Transmission",
    "Type",
    "UnaryOp",
    "Unpack",
    "Value",
    "Var",
    "Varying",
    "Vector",
    "Written",
    "array_name",
    "bit_span",
    "coerce",
    "looks_up",
    "may_outgrow",
    "operands",
    "spread",
    "variables",
    "world_joint",
]

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.model_methods import dataclass, field

from rdisc.frozen import Frozen


@dataclass(frozen=True, slots=True)
class Model(metaclass=Frozen):
    robot: Robot
    states: dict[str, StateVariable]
    connections: dict[str, Connection]
    primitives: dict[str, Primitive]
    interfaces: dict[str, Interface]
    adapters: dict[str, Adapter]
    inputs: dict[str, DomainInput]
    outputs: dict[str, DomainOutput]
    frames: dict[str, Frame] = field(default_factory=dict)
    constants: dict[str, Value] = field(default_factory=dict)
    enums: dict[str, dict[str, int]] = field(default_factory=dict)
    tables: dict[str, Table] = field(default_factory=dict)
    # The doc comments of constants and enums, by name: their values are plain, with no place for one.
    constant_docs: dict[str, str] = field(default_factory=dict)
    enum_docs: dict[str, str] = field(default_factory=dict)
    settings: dict[str, Setting] = field(default_factory=dict)
    links: dict[str, Link] = field(default_factory=dict)
    joints: dict[str, Joint] = field(default_factory=dict)  # parents before children
    transmissions: dict[str, Transmission] = field(default_factory=dict)
    sensors: dict[str, Sensor] = field(default_factory=dict)
    actuators: dict[str, Actuator] = field(default_factory=dict)

    def root_link(self) -> Link | None:
        """The link no joint moves: the checker allows exactly one when there are links."""
        children = {j.child for j in self.joints.values()}
        return next((link for link in self.links.values() if link.name not in children), None)

    def frame_id(self, output: DomainOutput) -> str:
        """The frame a framework's stamped message of `output` names (ROS's `header.frame_id`):
        its `frame` link, else the body's base, else "" (no body: no frame to name). Every
        emitter asks here."""
        if output.frame is not None:
            return output.frame
        root = self.root_link()
        return "" if root is None else root.name

    def owner(self, iface: Interface) -> str | None:
        """The connection whose thread runs a periodic interface: its first primitive's."""
        first = self._first_primitive(iface, set())
        if first is not None:
            return self.primitives[first].connection
        return next(iter(self.connections), None)

    def _first_primitive(self, iface: Interface, seen: set[str]) -> PrimitiveRef | None:
        """The primitive an interface calls first, through the interfaces it calls, each looked
        into once (one that led to no primitive leads to none again: loops repeat calls)."""
        seen.add(iface.name)
        for call in iface.run_order():
            if not call.interface:
                return call.primitive
            if call.primitive not in seen:
                found = self._first_primitive(self.interfaces[call.primitive], seen)
                if found is not None:
                    return found
        return None

    def callees_first(self) -> list[Interface]:
        """The interfaces, each after the interfaces it calls (the checker keeps the calls
        between interfaces acyclic), else as declared."""
        ordered: dict[str, Interface] = {}

        def place(iface: Interface) -> None:
            if iface.name in ordered:
                return
            for call in iface.calls:
                if call.interface:
                    place(self.interfaces[call.primitive])
            ordered[iface.name] = iface

        for iface in self.interfaces.values():
            place(iface)
        return list(ordered.values())

