"""What a joint's actuator moves: the inertia about the joint's axis of every link it carries, at
the zero pose, and the position gain a simulation at a fixed timestep can integrate for it.

A position servo of gain kp (N m/rad) on an inertia I (kg m²) rings at ω = √(kp/I); stepped every
dt with its damping taken implicitly (MuJoCo's `implicitfast`, critically damped) it stays stable
only while ω·dt is below 2 + 2√2 (the Jury test of that update). A servo's gain taken from its
stall torque alone (205 N m/rad for an XM430) on a 5 g horn (2e-6 kg m²) gives ω·dt of 12: the horn
chatters and reads nonsense. So a gain is derived from both: the servo's (its effort over
POSITION_ERROR) while the links it carries can follow it (ω·dt ≤ CAPPED_STEP), else the stiffest
they follow within a step (ω·dt = DERIVED_STEP).
"""

from __future__ import annotations

import math

from rdisc.semantics import model as m

POSITION_ERROR = 0.05  # rad (m): a derived position servo gives its whole effort this far from its target
CAPPED_STEP = 4.0  # ω·dt past which the servo's own gain is too near the limit to keep
DERIVED_STEP = 1.0  # ω·dt of a gain brought down: well inside the limit, settled within a few steps
STABLE_STEP = 2 + 2 * math.sqrt(2)  # ω·dt beyond which an implicitly damped servo's steps grow
TIMESTEP = 0.002  # s: the simulation's step, MuJoCo's default, fixed so that a simulation repeats exactly

Matrix = tuple[tuple[float, float, float], ...]
_IDENTITY: Matrix = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def _rotation(rpy: m.Vector) -> Matrix:
    """Rz(yaw) Ry(pitch) Rx(roll), as URDF composes them."""
    cr, sr = math.cos(rpy[0]), math.sin(rpy[0])
    cp, sp = math.cos(rpy[1]), math.sin(rpy[1])
    cy, sy = math.cos(rpy[2]), math.sin(rpy[2])
    return ((cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr),
            (sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr),
            (-sp, cp * sr, cp * cr))


def _times(a: Matrix, b: Matrix) -> Matrix:
    def row(i: int) -> tuple[float, float, float]:
        return (a[i][0] * b[0][0] + a[i][1] * b[1][0] + a[i][2] * b[2][0],
                a[i][0] * b[0][1] + a[i][1] * b[1][1] + a[i][2] * b[2][1],
                a[i][0] * b[0][2] + a[i][1] * b[1][2] + a[i][2] * b[2][2])
    return (row(0), row(1), row(2))


def _apply(a: Matrix, v: m.Vector) -> m.Vector:
    return (sum(a[0][k] * v[k] for k in range(3)), sum(a[1][k] * v[k] for k in range(3)),
            sum(a[2][k] * v[k] for k in range(3)))


def _frames(links: dict[str, m.Link], joints: dict[str, m.Joint]) -> dict[str, tuple[Matrix, m.Vector]]:
    """Each link's rotation and origin in the root link's frame, every joint at zero (joints come parents first)."""
    children = {j.child for j in joints.values()}
    root = next((name for name in links if name not in children), None)
    frames: dict[str, tuple[Matrix, m.Vector]] = {} if root is None else {root: (_IDENTITY, (0.0, 0.0, 0.0))}
    for joint in joints.values():
        if joint.parent not in frames:
            continue
        rotation, origin = frames[joint.parent]
        offset = _apply(rotation, joint.origin.xyz)
        frames[joint.child] = (_times(rotation, _rotation(joint.origin.rpy)),
                               (origin[0] + offset[0], origin[1] + offset[1], origin[2] + offset[2]))
    return frames


def joint_inertia(links: dict[str, m.Link], joints: dict[str, m.Joint]) -> dict[str, float]:
    """Each moving joint's reflected inertia (kg m², or kg for a prismatic joint): of every link it
    carries, about (along) its axis at the zero pose. Links without an inertial count nothing."""
    frames = _frames(links, joints)
    carried: dict[str, list[str]] = {}
    for joint in reversed(list(joints.values())):  # children before parents
        carried[joint.name] = [joint.child] + [link for j in joints.values()
                                               if j.parent == joint.child for link in carried.get(j.name, ())]
    found: dict[str, float] = {}
    for joint in joints.values():
        if not joint.moves() or joint.child not in frames:
            continue
        rotation, at = frames[joint.child]
        axis = _apply(rotation, joint.axis)
        total = 0.0
        for name in carried[joint.name]:
            inertial = links[name].inertial
            if inertial is None or name not in frames:
                continue
            if joint.kind is m.JointKind.PRISMATIC:
                total += inertial.mass
                continue
            link_rotation, link_origin = frames[name]
            ixx, iyy, izz, ixy, ixz, iyz = inertial.inertia
            tensor = ((ixx, ixy, ixz), (ixy, iyy, iyz), (ixz, iyz, izz))
            transposed = ((link_rotation[0][0], link_rotation[1][0], link_rotation[2][0]),
                          (link_rotation[0][1], link_rotation[1][1], link_rotation[2][1]),
                          (link_rotation[0][2], link_rotation[1][2], link_rotation[2][2]))
            local = _apply(transposed, axis)  # the axis in the link's own axes
            about_centre = sum(local[i] * tensor[i][j] * local[j] for i in range(3) for j in range(3))
            centre = _apply(link_rotation, inertial.centre)
            d = tuple(link_origin[i] + centre[i] - at[i] for i in range(3))
            along = sum(d[i] * axis[i] for i in range(3))
            total += about_centre + inertial.mass * max(0.0, sum(x * x for x in d) - along * along)
        found[joint.name] = total
    return found


def position_gain(effort: float | None, inertia: float, timestep: float) -> float:
    """A derived position servo's gain: its effort over POSITION_ERROR (10 without one), or, when
    `inertia` could not follow that within CAPPED_STEP, the gain it follows at ω·dt = DERIVED_STEP
    (an inertia of 0: the servo's own)."""
    servo = effort / POSITION_ERROR if effort else 10.0
    if inertia <= 0 or steps_per_period(servo, inertia, timestep) <= CAPPED_STEP:
        return servo
    return inertia * (DERIVED_STEP / timestep) ** 2


def steps_per_period(gain: float, inertia: float, timestep: float) -> float:
    """ω·dt of a position servo of `gain` on `inertia`: past STABLE_STEP its simulation diverges."""
    return math.sqrt(gain / inertia) * timestep if inertia > 0 else 0.0
