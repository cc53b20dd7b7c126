"""The Model's body (thesis ch. 6): links, joints, transmissions, sensors and actuators."""

from __future__ import annotations

import enum

from rdisc import TYPE_CHECKING
from rdisc.semantics.model_expressions import Expr
from rdisc.source import Span

if TYPE_CHECKING:
    from dataclasses import dataclass, field
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.model_body_methods import dataclass, field

from rdisc.frozen import Frozen

_span = field(compare=False, repr=False, default=None)


# ---- the body (thesis ch. 6) -------------------------------------------------------

Vector = tuple[float, float, float]
ORIGIN: Vector = (0.0, 0.0, 0.0)


Written = tuple[tuple[str, Expr], ...]
"""A body element's clauses that read settings, by their word (`at`, `size`, `mass`, `limit`, ...): each
as written, typed (a list of separate values, a shape's sizes or a joint's limits, an array of them).
The element's numbers are at the settings' values; these let canonical JSON carry what they follow."""


@dataclass(frozen=True, slots=True)
class Pose(metaclass=Frozen):
    """A frame relative to its parent's: a translation (m), then roll, pitch, yaw (rad) about
    the parent's fixed x, y, z axes, as URDF's `origin`."""

    xyz: Vector = ORIGIN
    rpy: Vector = ORIGIN

    def is_identity(self) -> bool:
        return self.xyz == ORIGIN and self.rpy == ORIGIN


class ShapeKind(enum.Enum):
    BOX = "box"  # size: x, y, z (full lengths, m)
    CYLINDER = "cylinder"  # size: radius, length (along its z axis, m)
    SPHERE = "sphere"  # size: radius (m)
    MESH = "mesh"  # size: scale x, y, z; path: the mesh file, as written


@dataclass(frozen=True, slots=True)
class Shape(metaclass=Frozen):
    """A visual or collision shape placed in its link's frame."""

    kind: ShapeKind
    size: tuple[float, ...]
    origin: Pose = Pose()
    path: str | None = None
    span: Span | None = _span
    color: tuple[float, float, float, float] | None = None  # red, green, blue, alpha: each 0 to 1
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)


@dataclass(frozen=True, slots=True)
class Inertial(metaclass=Frozen):
    """Mass (kg) at `centre` (m, in the link's frame), and the inertia tensor about the centre,
    in the link's axes (kg m²): ixx, iyy, izz, ixy, ixz, iyz."""

    mass: float
    centre: Vector
    inertia: tuple[float, float, float, float, float, float]
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)


@dataclass(frozen=True, slots=True)
class Link(metaclass=Frozen):
    name: str
    visuals: tuple[Shape, ...] = ()
    collisions: tuple[Shape, ...] = ()
    inertial: Inertial | None = None
    doc: str | None = None
    span: Span | None = _span
    spawn: Spawn | None = None  # the root link's: how and where it meets the world


def world_joint(root: str) -> str:
    """The fixed joint the URDF and SDF add between the world and a root link spawned `fixed`."""
    return f"world_to_{root}"


@dataclass(frozen=True, slots=True)
class Spawn(metaclass=Frozen):
    """The root link `floating` (free on the floor: a mobile base) or `fixed` to the world (an arm
    bolted down), its frame at `pose` in the world's when the simulation starts."""

    floating: bool
    pose: Pose = Pose()
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)


class JointKind(enum.Enum):
    FIXED = "fixed"
    REVOLUTE = "revolute"  # about `axis`, within `limit` (rad)
    CONTINUOUS = "continuous"  # about `axis`, without a position limit
    PRISMATIC = "prismatic"  # along `axis`, within `limit` (m)


@dataclass(frozen=True, slots=True)
class Mimic(metaclass=Frozen):
    """A joint that follows another: its position is `multiplier` times `joint`'s, plus `offset`
    (URDF's `<mimic>`, MuJoCo's joint equality)."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True, slots=True)
class Joint(metaclass=Frozen):
    """`child`'s frame is `origin` in `parent`'s, then moved about or along the unit `axis`."""

    name: str
    kind: JointKind
    parent: str
    child: str
    origin: Pose = Pose()
    axis: Vector = (1.0, 0.0, 0.0)
    lower: float | None = None  # the position limit (revolute, prismatic)
    upper: float | None = None
    velocity: float | None = None  # the largest speed (rad/s, m/s)
    effort: float | None = None  # the largest torque (N m) or force (N)
    damping: float = 0.0
    friction: float = 0.0
    doc: str | None = None
    span: Span | None = _span
    mimic: Mimic | None = None  # another joint this one follows
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)

    def moves(self) -> bool:
        return self.kind is not JointKind.FIXED


class Quantity(enum.Enum):
    POSITION = "position"  # rad or m
    VELOCITY = "velocity"  # rad/s or m/s
    EFFORT = "effort"  # N m or N


@dataclass(frozen=True, slots=True)
class Binding(metaclass=Frozen):
    """A joint quantity and a device value, converted both ways. A command drives a parameter
    of a primitive or interface (`target.parameter[index]`); a measure reads a state variable
    (`target[index]`). `to_device` reads the quantity by its name (`position`, ...) and gives the
    device's value; `to_joint` reads that value as `raw` and gives the quantity back."""

    quantity: Quantity
    target: str
    parameter: str | None
    index: int | None
    to_device: Expr
    to_joint: Expr
    interface: bool = False  # the target is an interface, not a primitive
    span: Span | None = _span
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)

    def place(self) -> str:
        where = self.target if self.parameter is None else f"{self.target}.{self.parameter}"
        return where if self.index is None else f"{where}[{self.index}]"


@dataclass(frozen=True, slots=True)
class Transmission(metaclass=Frozen):
    """How the device moves and senses one joint."""

    name: str
    joint: str
    commands: tuple[Binding, ...] = ()
    measures: tuple[Binding, ...] = ()
    doc: str | None = None
    span: Span | None = _span
    actuator: str | None = None  # the actuator between its command and the joint


class ActuatorKind(enum.Enum):
    SERVO = "servo"  # a position servo: the command is a position it moves to
    WHEEL = "wheel"  # a velocity-controlled motor: the command is a speed it holds


@dataclass(frozen=True, slots=True)
class Actuator(metaclass=Frozen):
    """What drives a joint (thesis §7.2.6): its limits, which shape (or, `refuse`, refuse) the commands
    a joint is given (a position moves at most `velocity`, a speed changes by at most `acceleration` a second), and
    the gains the simulation gives it (`gain` N m/rad, `damping` N m s/rad; None: derived)."""

    name: str
    kind: ActuatorKind
    velocity: float | None = None  # rad/s (m/s)
    acceleration: float | None = None  # rad/s² (m/s²)
    effort: float | None = None  # N m (N)
    gain: float | None = None
    damping: float | None = None
    doc: str | None = None
    span: Span | None = _span
    refuse: bool = False  # `limit refuse`: a command beyond a limit is refused, not shaped (`limit shape`)
    expressions: Written = ()  # the clauses that read settings (rdisc.semantics.body)
