"""`rdisc emit-mjcf`: a description's body as a MuJoCo model (MJCF), from the Model alone.

The links become bodies nested as the joints nest them, each placed by its joint's
origin (roll, pitch, yaw composed as URDF composes them); visual shapes are geoms that
never collide, collision shapes geoms that do; a link's inertial is its body's. The root
link is a free body on a floor when it is spawned `floating`, or, without a `spawn`, when
the body rolls (a continuous joint turns a link with a round collision shape: a wheel),
else it is welded to the world (an arm); a `spawn` places it. Each
transmission's command becomes an actuator of its joint: a position command a servo
(`<position>`), a velocity command a `<velocity>` actuator, an effort a `<motor>`, with
the joint's limits as the control's range and its effort as the force's; a servo's gain is
no stiffer than the links it carries can follow within a timestep. A ball fixed
to its parent (a sphere collision on a fixed joint) is a caster: it slides, so it gets
almost no friction. Each joint's two links never collide (a `<contact><exclude>`: MuJoCo keeps a body from its
parent itself, but not from one welded to the world, so an arm's turret stuck to its base plate).
`rdisc sim` runs the same model.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

from rdisc.emit.body_xml import BodyError
from rdisc.semantics import model as m
from rdisc.semantics.reflected import TIMESTEP, joint_inertia, position_gain

CASTER_FRICTION = "0.01 0.005 0.0001"  # sliding, torsional, rolling: a ball caster's
MAX_DEPTH = 256  # joints from the root: Python's XML writer recurses a level a body, and so does MuJoCo's parser
VELOCITY_ERROR = 0.01  # a velocity actuator gives the whole effort this fraction of the speed limit away


def to_mjcf(model: m.Model, mesh_folder: str | None = None) -> str:
    """The MJCF text of the description's body (a model of its robot's links, joints and actuators).
    `mesh_folder`: where a mesh's relative path starts (MuJoCo's `meshdir`; else where it is read)."""
    root = ET.Element("mujoco", model=model.robot.name)
    compiler = ET.SubElement(root, "compiler", angle="radian", autolimits="true", boundmass="0.001",
                             boundinertia="1e-6")
    if mesh_folder is not None:
        compiler.set("meshdir", mesh_folder)
    ET.SubElement(root, "option", timestep=_num(TIMESTEP), integrator="implicitfast")
    meshes = [(link, shape) for link in model.links.values() for shape in (*link.visuals, *link.collisions)
              if shape.kind is m.ShapeKind.MESH]
    if meshes:
        asset = ET.SubElement(root, "asset")
        for n, (link, shape) in enumerate(meshes):
            assert shape.path is not None
            ET.SubElement(asset, "mesh", name=f"{link.name}_mesh{n}", file=shape.path, scale=_vec(shape.size))
    world = ET.SubElement(root, "worldbody")
    ET.SubElement(world, "light", pos="0 0 3", dir="0 0 -1", directional="true")
    ET.SubElement(world, "geom", name="floor", type="plane", size="0 0 0.05", rgba="0.8 0.8 0.8 1")
    base = model.root_link()
    depth = _depth(model)
    if depth > MAX_DEPTH:
        raise BodyError(f"the body is {depth} joints deep; MJCF nests each link in its parent's, "
                        f"and rdisc writes at most {MAX_DEPTH}")
    if base is not None:
        mesh_names = {id(shape): f"{link.name}_mesh{n}" for n, (link, shape) in enumerate(meshes)}
        free = rolls(model) if base.spawn is None else base.spawn.floating
        _body(model, world, base, None, free, mesh_names)
    mimics = [j for j in model.joints.values() if j.mimic is not None]
    if mimics:  # a follower held to its leader: position = offset + multiplier * leader's
        equality = ET.SubElement(root, "equality")
        for joint in mimics:
            assert joint.mimic is not None
            ET.SubElement(equality, "joint", name=f"{joint.name}_mimic", joint1=joint.name, joint2=joint.mimic.joint,
                          polycoef=f"{_num(joint.mimic.offset)} {_num(joint.mimic.multiplier)} 0 0 0")
    if model.joints:  # a link never collides with its parent (MuJoCo keeps them apart only off the world)
        contact = ET.SubElement(root, "contact")
        for joint in model.joints.values():
            ET.SubElement(contact, "exclude", body1=joint.parent, body2=joint.child)
    actuators = [(t, b) for t in model.transmissions.values() for b in t.commands]
    if actuators:
        act = ET.SubElement(root, "actuator")
        inertia = joint_inertia(model.links, model.joints)
        for transmission, binding in actuators:
            joint = model.joints[transmission.joint]
            motor = model.actuators.get(transmission.actuator) if transmission.actuator else None
            _actuator(act, joint, transmission, binding, inertia.get(joint.name, 0.0), motor)
    ET.indent(root)
    return ET.tostring(root, encoding="unicode") + "\n"


def _depth(model: m.Model) -> int:
    """Joints from the root link to the farthest one (the joints come parents first)."""
    depth: dict[str, int] = {}
    for joint in model.joints.values():
        depth[joint.child] = depth.get(joint.parent, 0) + 1
    return max(depth.values(), default=0)


def rolls(model: m.Model) -> bool:
    """Whether the body is a mobile base: a continuous joint turns a link with a round
    collision shape (a wheel), so the root link moves freely on the floor."""
    round_ = (m.ShapeKind.CYLINDER, m.ShapeKind.SPHERE)
    return any(j.kind is m.JointKind.CONTINUOUS and any(s.kind in round_ for s in model.links[j.child].collisions)
               for j in model.joints.values())


def actuator_name(transmission: m.Transmission, binding: m.Binding) -> str:
    """A transmission's actuator for one commanded quantity."""
    return f"{transmission.name}_{binding.quantity.value}"


def quaternion(rpy: m.Vector) -> tuple[float, float, float, float]:
    """(w, x, y, z) of roll, pitch, yaw about the fixed x, y, z axes: Rz(yaw) Ry(pitch) Rx(roll), as URDF."""
    cr, sr = math.cos(rpy[0] / 2), math.sin(rpy[0] / 2)
    cp, sp = math.cos(rpy[1] / 2), math.sin(rpy[1] / 2)
    cy, sy = math.cos(rpy[2] / 2), math.sin(rpy[2] / 2)
    return (cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy)


def _body(model: m.Model, parent: ET.Element, link: m.Link, joint: m.Joint | None, free: bool,
          meshes: dict[int, str]) -> None:
    body = ET.SubElement(parent, "body", name=link.name)
    if joint is not None:
        _place(body, joint.origin)
        if joint.moves():
            _joint(body, joint)
    else:
        if link.spawn is not None:
            _place(body, link.spawn.pose)
        if free:
            ET.SubElement(body, "freejoint", name=f"{link.name}_free")
    if link.inertial is not None:
        i = link.inertial
        ET.SubElement(body, "inertial", pos=_vec(i.centre), mass=_num(i.mass), fullinertia=_vec(i.inertia))
    caster = joint is not None and joint.kind is m.JointKind.FIXED
    for n, shape in enumerate(link.visuals):
        geom = _geom(body, f"{link.name}_visual{n}", shape, meshes)
        geom.set("contype", "0")
        geom.set("conaffinity", "0")
        geom.set("group", "1")
        geom.set("mass", "0")  # a link's mass is its inertial's, or its collision shapes'
    for n, shape in enumerate(link.collisions):
        geom = _geom(body, f"{link.name}_collision{n}", shape, meshes)
        if caster and shape.kind is m.ShapeKind.SPHERE:
            geom.set("friction", CASTER_FRICTION)
    for child in model.joints.values():
        if child.parent == link.name:
            _body(model, body, model.links[child.child], child, free, meshes)


def _joint(body: ET.Element, joint: m.Joint) -> None:
    kind = "slide" if joint.kind is m.JointKind.PRISMATIC else "hinge"
    element = ET.SubElement(body, "joint", name=joint.name, type=kind, axis=_vec(joint.axis))
    if joint.lower is not None and joint.upper is not None:
        element.set("range", f"{_num(joint.lower)} {_num(joint.upper)}")
    if joint.damping:
        element.set("damping", _num(joint.damping))
    if joint.friction:
        element.set("frictionloss", _num(joint.friction))


def _geom(body: ET.Element, name: str, shape: m.Shape, meshes: dict[int, str]) -> ET.Element:
    geom = ET.SubElement(body, "geom", name=name)
    match shape.kind:
        case m.ShapeKind.BOX:
            geom.set("type", "box")
            geom.set("size", _vec(tuple(x / 2 for x in shape.size)))
        case m.ShapeKind.CYLINDER:
            geom.set("type", "cylinder")
            geom.set("size", f"{_num(shape.size[0])} {_num(shape.size[1] / 2)}")
        case m.ShapeKind.SPHERE:
            geom.set("type", "sphere")
            geom.set("size", _num(shape.size[0]))
        case m.ShapeKind.MESH:
            geom.set("type", "mesh")
            geom.set("mesh", meshes[id(shape)])
    _place(geom, shape.origin)
    if shape.color is not None:
        geom.set("rgba", _vec(shape.color))
    return geom


def _place(element: ET.Element, pose: m.Pose) -> None:
    if pose.xyz != m.ORIGIN:
        element.set("pos", _vec(pose.xyz))
    if pose.rpy != m.ORIGIN:
        element.set("quat", _vec(quaternion(pose.rpy)))


def _actuator(parent: ET.Element, joint: m.Joint, transmission: m.Transmission, binding: m.Binding,
              inertia: float, motor: m.Actuator | None) -> None:
    """A position servo's gain is its actuator's, else derived from its effort and the inertia it
    moves (rdisc.semantics.reflected); an actuator's effort is the force's range."""
    name = actuator_name(transmission, binding)
    effort = motor.effort if motor is not None and motor.effort is not None else joint.effort
    match binding.quantity:
        case m.Quantity.POSITION:
            stated = motor.gain if motor is not None else None
            kp = stated if stated is not None else position_gain(effort, inertia, TIMESTEP)
            element = ET.SubElement(parent, "position", name=name, joint=joint.name, kp=_num(kp))
            if motor is not None and motor.damping is not None:
                element.set("kv", _num(motor.damping))
            else:
                element.set("dampratio", "1")
            if joint.lower is not None and joint.upper is not None:
                element.set("ctrlrange", f"{_num(joint.lower)} {_num(joint.upper)}")
        case m.Quantity.VELOCITY:
            kv = effort / (VELOCITY_ERROR * joint.velocity) if effort and joint.velocity else 1.0
            element = ET.SubElement(parent, "velocity", name=name, joint=joint.name, kv=_num(kv))
            if joint.velocity is not None:
                element.set("ctrlrange", f"{_num(-joint.velocity)} {_num(joint.velocity)}")
        case m.Quantity.EFFORT:
            element = ET.SubElement(parent, "motor", name=name, joint=joint.name)
            if effort is not None:
                element.set("ctrlrange", f"{_num(-effort)} {_num(effort)}")
    if effort is not None:
        element.set("forcerange", f"{_num(-effort)} {_num(effort)}")


def _vec(values: tuple[float, ...]) -> str:
    return " ".join(_num(v) for v in values)


def _num(value: float) -> str:
    """A number as MJCF reads it back exactly: the shortest text of the float (no exponent noise for ints)."""
    as_float = float(value)
    return str(int(as_float)) if as_float.is_integer() and abs(as_float) < 1e15 else repr(as_float)
