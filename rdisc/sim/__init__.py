"""A description's body simulated in MuJoCo, in place of its device (`rdisc sim`, `connect(sim=True)`).

The engine runs the description as it always does; at each primitive it hands the
simulation the primitive's parameters' values instead of writing them
(`rdisc.engine.Simulator`). What the device would do with them, and what it
would answer, comes from the transmissions:

- a transmission that commands a parameter of the primitive, or of an interface being
  called, sets its joint's actuator (`rdisc emit-mjcf`) to the parameter's value
  converted to the joint's units (`to_joint`, which reads it as `raw`);
- a reply value that a post-action stores directly into a state variable a
  transmission measures (`left_encoder = out[33]`, `present[i] = out[2]`) is the
  simulated joint's quantity converted to the device's (`to_device`); a value the
  primitive's `expect` pins (`out[0] == 0x55`) is that value; any other is zero (an
  empty string, a "0" group of a regex).

A state variable that declares noise (`state present: int[2] = [512, 512] noise 3`) has
seeded Gaussian noise of its deviation (each element's, for a covariance) added to each such
value, and a sensor that does to the one value its primitive's reply holds, rounded where the reply holds an int: the same seed gives the same replies, and a
simulated run scatters as a real one does.

Then `expect` and the post-actions run on that reply as on a real one, so state,
outputs and inputs are unchanged. A primitive told to fail (`answer_error`, `rdisc sim
--error P=CODE`) is answered with its declared `error` reply instead, raised as a device's
is: an RdisDeviceError with the code and its name from the enum, so a driver's error path
runs without hardware. Time is simulated (a fixed timestep, advanced by the
robot's schedule and delays: the same run gives the same figures), or the wall clock's
with `realtime`. MuJoCo is imported when a simulation is made, not before.
"""

from __future__ import annotations

import math
import os
import random
import re
import struct
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from rdisc import engine
from rdisc.emit.mjcf import actuator_name, to_mjcf
from rdisc.lowering.constructs import decoder
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import Prepared, prepare
from rdisc.semantics.meshes import rebased

__all__ = ["Simulation", "SimulationError"]

JITTER = 0.01  # rad (m): how far `seed` moves each joint from where it starts
OVERSPEED = 2  # a joint faster than this many times its `velocity` is warned of: no command asks that


class SimulationError(engine.RdisError):
    """The body cannot be simulated: MuJoCo refused it, or its state stopped being finite (an
    unstable integration, which MuJoCo would otherwise reset to time 0 and go on)."""


_warnings: list[str] = []  # MuJoCo's warnings since a simulation last looked, in place of its MUJOCO_LOG.TXT


def _take_warning(text: str) -> None:
    """MuJoCo's warning handler: kept for the simulation to raise, never written into the user's folder."""
    if len(_warnings) < 16:
        _warnings.append(text.strip())


@dataclass(frozen=True, slots=True)
class _Command:
    """A transmission's command: a parameter (an element of it) sets an actuator's target."""

    param: int
    element: int | None
    actuator: int
    to_joint: Callable[[Any], float]
    joint: str = ""
    quantity: m.Quantity = m.Quantity.POSITION


@dataclass(frozen=True, slots=True)
class _Sensed:
    """A reply value the simulation gives: the joint's quantity, as the device reports it.
    `element`, over the primitive's parameters, says which element of an array variable the
    value is stored in (None: a variable that is not an array)."""

    out: int
    state: str
    element: Callable[[Sequence[Any]], Any] | None


@dataclass(frozen=True, slots=True)
class _Reply:
    """What the simulation knows of one reply: its values when nothing sets them (what its
    decoding gives for zero bytes; a regex's groups each "0"), those it senses and those
    `expect` pins."""

    zeros: tuple[Any, ...]
    sensed: tuple[_Sensed, ...]
    pinned: tuple[tuple[int, m.Value], ...]


class Simulation:
    """The MuJoCo twin of a description's body, answering as its device would (`engine.Simulator`).

    `seed` moves each joint's starting position by up to JITTER, the same for the same seed
    (None: every joint starts at zero), and seeds the noise of state variables that declare it
    (None: seed 0); `realtime` runs the physics on the wall clock."""

    def __init__(self, model: m.Model, *, seed: int | None = None, realtime: bool = False) -> None:
        import mujoco

        self._mujoco = mujoco
        mujoco.set_mju_user_warning(_take_warning)  # no MUJOCO_LOG.TXT in the current folder
        _warnings.clear()
        self.model = model
        self.realtime = realtime
        self.failed: SimulationError | None = None  # once unstable, the physics stays where it failed
        try:
            described = model.robot.span.path if model.robot.span is not None else None
            folder = os.path.dirname(os.path.abspath(described)) if described else None  # a mesh's path starts there
            self.physics = mujoco.MjModel.from_xml_string(to_mjcf(rebased(model, None, files=True), folder))
            self.data = mujoco.MjData(self.physics)
        except (ValueError, mujoco.FatalError) as err:  # a mesh it cannot read, a body it cannot hold
            raise SimulationError(f"{model.robot.name}: MuJoCo cannot simulate this body: "
                                  f"{str(err).strip().splitlines()[0] if str(err).strip() else type(err).__name__}"
                                  ) from None
        self._lock = threading.Lock()
        self._time = 0.0
        self._began = time.monotonic()
        self._commands: dict[tuple[bool, str], list[_Command]] = {}
        self._measures: dict[tuple[str, int | None], tuple[m.Joint, m.Quantity, Callable[[float], Any]]] = {}
        for t in model.transmissions.values():
            joint = model.joints[t.joint]
            for b in t.commands:
                owner = model.interfaces[b.target] if b.interface else model.primitives[b.target]
                param = next(i for i, p in enumerate(owner.params) if p.name == b.parameter)
                actuator = mujoco.mj_name2id(self.physics, mujoco.mjtObj.mjOBJ_ACTUATOR, actuator_name(t, b))
                self._commands.setdefault((b.interface, b.target), []).append(
                    _Command(param, b.index, actuator, _conversion(b.to_joint, "raw"), joint.name, b.quantity))
            for b in t.measures:
                self._measures[b.target, b.index] = (joint, b.quantity, _conversion(b.to_device, b.quantity.value))
        self._bodies = {name: mujoco.mj_name2id(self.physics, mujoco.mjtObj.mjOBJ_BODY, name) for name in model.links}
        self._direct = {p.name: _format_positions(p) for p in model.primitives.values() if p.formats_its_params()}
        self._replies = {p.name: _replies(p) for p in model.primitives.values()}
        self._keys = {p.name: [q.name for q in p.params].index(p.table.key)
                      for p in model.primitives.values() if p.table is not None and p.table.key}
        self._listed = {p.name for p in model.primitives.values() if p.listed}  # replies by their place
        self._errors: dict[str, tuple[Any, ...]] = {}  # the error reply each primitive told to fail answers
        self._noise = random.Random(0 if seed is None else seed)  # the declared noise's draws, one per value
        self._deviations = {s.name: [math.sqrt(row[i]) for i, row in enumerate(s.noise.covariance)]
                            for s in model.states.values() if s.noise is not None}
        self._read_noise: dict[str, float] = {s.primitive: math.sqrt(s.noise.covariance[0][0])  # a sensor's one value
                            for s in model.sensors.values() if s.noise is not None}
        self.warnings: list[str] = []  # what the simulation does that the device would not, in order
        self._clipped: set[int] = set()  # actuators whose last command lay beyond their joint's range
        self._fast: set[str] = set()  # joints warned of moving faster than OVERSPEED times their velocity
        self._rest_on_ground()
        if seed is not None:
            jitter = random.Random(seed)
            for joint in model.joints.values():
                if joint.moves():
                    self.data.qpos[self._joint(joint.name).qposadr[0]] += jitter.uniform(-JITTER, JITTER)
        try:
            mujoco.mj_forward(self.physics, self.data)
        except mujoco.FatalError as err:  # its memory for contacts overflowed, say
            raise SimulationError(f"{model.robot.name}: MuJoCo cannot simulate this body: "
                                  f"{str(err).strip().splitlines()[0]}") from None

    # ---- engine.Simulator ---------------------------------------------------------------------------

    def interface(self, plan: engine.Interface, args: engine.Args) -> None:
        commands = self._commands.get((True, plan.name))
        if commands:
            with self._lock:
                self._catch_up()
                self._command(commands, args)

    def exchange(self, plan: engine.Primitive, local: engine.Args) -> None:
        commands = self._commands.get((False, plan.name))
        with self._lock:
            self._catch_up()
            if commands:
                positions = self._direct.get(plan.name)
                if positions is not None and len(local) != len(plan.params):  # a direct call's format values
                    local = [local[i] for i in positions]
                self._command(commands, local)

    def reply(self, plan: engine.Primitive, local: engine.Args, place: int | None) -> Sequence[Any]:
        with self._lock:
            return self._reply(plan, local, place)

    def error(self, plan: engine.Primitive, local: engine.Args) -> Sequence[Any] | None:
        return self._errors.get(plan.name)  # (`answer_error`)

    def answer_error(self, primitive: str, code: int | str | None) -> None:
        """Answer every call of `primitive` from now on with its declared `error` reply, the code
        `code` (an int, or a member of the reply's enum by name: "ILLEGAL_DATA_ADDRESS"), its
        other values zero; None answers its reply again. A primitive without an `error` reply, or
        a name its enum lacks, is a ValueError that says so."""
        p = self.model.primitives.get(primitive)
        if p is None:
            raise ValueError(f"{self.model.robot.name} has no primitive named {primitive!r}")
        if code is None:
            self._errors.pop(primitive, None)
            return
        if p.error is None:
            raise ValueError(f"{primitive} declares no `error` reply to answer with")
        if isinstance(code, str):
            members = self.model.enums.get(p.error.codes or "", {})
            if code not in members:
                listed = ", ".join(members) if members else "none: its `error` names no enum, give a number"
                raise ValueError(f"{primitive}: {code!r} is no code of its error reply (its codes: {listed})")
            code = members[code]
        values = list(_zeros(p.error.decoding))
        if not values or not isinstance(values[0], int):
            raise ValueError(f"{primitive}: its error reply's first value is no code")
        layout = p.error.decoding.layout
        try:
            struct.pack(layout.order + layout.slots[0].code, code)
        except struct.error:
            raise ValueError(f"{primitive}: code {code} does not fit its error reply's first value "
                             f"({layout.slots[0].code})") from None
        values[0] = code
        self._errors[primitive] = tuple(values)

    def advance(self, seconds: float) -> None:
        """Step the physics `seconds` further (to the nearest whole timestep)."""
        with self._lock:
            self._step_to(self._time + seconds)

    def now(self) -> float:
        """The simulated time: seconds since the simulation began."""
        return self._time

    # ---- what a test or a viewer reads -------------------------------------------------------------

    def position(self, joint: str) -> float:
        """A joint's position (rad or m) now."""
        return float(self.data.qpos[self._joint(joint).qposadr[0]])

    def link_poses(self) -> dict[str, tuple[float, ...]]:
        """Each link's frame in the world now: x, y, z (m), then its orientation as a unit
        quaternion w, x, y, z (every link is a body of its own in `emit.mjcf`, fixed joints'
        too). On the wall clock the physics is first brought up to now, so that a view sees the
        body move even while the robot sends nothing."""
        with self._lock:
            self._catch_up()
            return {name: (*map(float, self.data.xpos[body]), *map(float, self.data.xquat[body]))
                    for name, body in self._bodies.items()}

    def joint_positions(self) -> dict[str, float]:
        """Each moving joint's position (rad or m) now."""
        with self._lock:
            self._catch_up()
            return {j.name: float(self.data.qpos[self._joint(j.name).qposadr[0]])
                    for j in self.model.joints.values() if j.moves()}

    def base_pose(self) -> tuple[float, float, float]:
        """The root link's x, y (m) and heading (rad) in the world now (the physics brought up to now)."""
        root = self.model.root_link()
        if root is None:
            return (0.0, 0.0, 0.0)
        with self._lock:
            self._catch_up()
            return self.pose(root.name)

    def pose(self, link: str) -> tuple[float, float, float]:
        """A link's x, y (m) and heading (rad, about z) in the world now."""
        body = self.data.body(link)
        w, _x, _y, z = body.xquat
        return float(body.xpos[0]), float(body.xpos[1]), 2 * math.atan2(float(z), float(w))

    # ---- inside ---------------------------------------------------------------------------------------

    def _catch_up(self) -> None:
        if self.realtime:
            self._step_to(time.monotonic() - self._began)

    def _step_to(self, target: float) -> None:
        """Step to `target`: as many steps as fit, counted before the first (MuJoCo resets an
        unstable simulation's time to 0, so a loop on its time would never end). A warning or a
        state that is no longer finite stops the physics there, for good: SimulationError."""
        if self.failed is not None:  # the clock goes on (a schedule waiting for it ends), the physics not
            self._time = max(self._time, target)
            return
        step = self.physics.opt.timestep
        began = self.data.time
        steps = max(0, math.floor((target - began) / step + 0.5))
        try:
            for _ in range(steps):
                self._mujoco.mj_step(self.physics, self.data)
                if _warnings or self.data.time < began:
                    break
        except self._mujoco.FatalError as err:  # its memory for contacts overflowed, say
            _warnings.insert(0, str(err).strip().splitlines()[0])
        self._time = max(self._time, target)
        self._overspeed()
        if _warnings or not (math.isfinite(float(self.data.qpos.sum())) and math.isfinite(float(self.data.qvel.sum()))):
            said = _warnings[0] if _warnings else "its state is no longer finite"
            _warnings.clear()
            self.failed = SimulationError(f"{self.model.robot.name}: the simulation became unstable near "
                                          f"t = {began:.4f} s: {said} (is a mass, an inertia or a gain "
                                          "out of proportion to the others?)")
            raise self.failed

    def _overspeed(self) -> None:
        """Warn when a joint moves faster than OVERSPEED times its `velocity` (the physics going unstable,
        or a simulated servo doing what the device's could not): once a joint, as a servo's overshoot swings
        above and below it."""
        for joint in self.model.joints.values():
            if joint.velocity is None or not joint.moves() or joint.name in self._fast:
                continue
            speed = abs(float(self.data.qvel[self._joint(joint.name).dofadr[0]]))
            if speed > OVERSPEED * joint.velocity and math.isfinite(speed):
                self._fast.add(joint.name)
                self.warnings.append(f"joint `{joint.name}` moves at {speed:.3g}, more than {OVERSPEED:g} times its "
                                     f"velocity {joint.velocity:g}: the physics is unstable, or the simulated "
                                     "servo does what the device's could not")

    def _rest_on_ground(self) -> None:
        """A free base with no `spawn` pose starts with its lowest collision shape on the floor, wherever
        its origin is (a base whose origin is its chassis's centre would start inside the floor and be
        thrown up)."""
        mujoco = self._mujoco
        root = self.model.root_link()
        free = [j for j in range(self.physics.njnt) if self.physics.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
        if root is None or root.spawn is not None or not free:
            return
        mujoco.mj_kinematics(self.physics, self.data)
        bottoms = [_bottom(self.physics, self.data, g) for g in range(self.physics.ngeom)
                   if self.physics.geom_bodyid[g] != 0
                   and (self.physics.geom_contype[g] or self.physics.geom_conaffinity[g])]
        if bottoms:
            self.data.qpos[self.physics.jnt_qposadr[free[0]] + 2] -= min(bottoms)

    def _joint(self, name: str) -> Any:
        return self.physics.joint(name)

    def _command(self, commands: list[_Command], values: Sequence[Any]) -> None:
        for c in commands:
            value = values[c.param] if c.element is None else values[c.param][c.element]
            target = c.to_joint(value)
            self.data.ctrl[c.actuator] = target
            self._clip(c, float(target))

    def _clip(self, command: _Command, target: float) -> None:
        """Warn when a command lies beyond its joint's range (MuJoCo holds the actuator at the limit, a
        real servo would go on): once as it crosses, again only after a command within the range."""
        if not self.physics.actuator_ctrllimited[command.actuator]:
            return
        low, high = (float(v) for v in self.physics.actuator_ctrlrange[command.actuator])
        if low <= target <= high:
            self._clipped.discard(command.actuator)
            return
        if command.actuator in self._clipped:
            return
        self._clipped.add(command.actuator)
        held = min(max(target, low), high)
        self.warnings.append(f"joint `{command.joint}`: a {command.quantity.value} command of {target:.4g} is "
                             f"beyond its range {low:g}..{high:g}; the simulation holds it at {held:g}, "
                             "where the device would go on")

    def _quantity(self, joint: m.Joint, quantity: m.Quantity) -> float:
        j = self._joint(joint.name)
        match quantity:
            case m.Quantity.POSITION:
                return float(self.data.qpos[j.qposadr[0]])
            case m.Quantity.VELOCITY:
                return float(self.data.qvel[j.dofadr[0]])
            case m.Quantity.EFFORT:
                return float(self.data.qfrc_actuator[j.dofadr[0]])

    def _reply(self, plan: engine.Primitive, local: Sequence[Any], place: int | None) -> Sequence[Any]:
        """The values of a reply (at `place` among several: the `place`th of `replies { }`, or
        reply n of `replies N`, whose `present = out[2]` stores element n): zeros, the values
        `expect` pins, and what the measured joints read."""
        replies = self._replies[plan.name]
        listed = plan.name in self._listed
        key = self._keys.get(plan.name)
        reply = replies.get(place if listed else None if key is None else local[key])
        if reply is None:
            return ()
        values = list(reply.zeros)
        for k, value in reply.pinned:
            values[k] = value
        for s in reply.sensed:
            try:
                index = (None if listed else place) if s.element is None else s.element(local)
            except (LookupError, *engine.EVAL_ERRORS):
                continue
            measure = self._measures.get((s.state, index))
            if measure is not None:
                joint, quantity, to_device = measure
                values[s.out] = to_device(self._quantity(joint, quantity))
            deviations = self._deviations.get(s.state)
            if deviations is not None:
                element = index if isinstance(index, int) and 0 <= index < len(deviations) else 0
                values[s.out] = self._noisy(values[s.out], deviations[element])
        read = self._read_noise.get(plan.name)
        if read is not None and values:
            values[0] = self._noisy(values[0], read)
        return values

    def _noisy(self, value: Any, deviation: float) -> Any:
        """A reply value with the declared noise added (one draw), an int's rounded; others as they are."""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return value
        noisy = value + self._noise.gauss(0.0, deviation)
        return round(noisy) if isinstance(value, int) else noisy


def _bottom(physics: Any, data: Any, geom: int) -> float:
    """The height of a geom's lowest point, as placed: a sphere's, a box's and a cylinder's exactly, a
    mesh's its bounding sphere's."""
    import mujoco

    z = float(data.geom_xpos[geom][2])
    up = data.geom_xmat[geom][6:9]  # the world's z in the geom's frame: the rotation's last row
    size = physics.geom_size[geom]
    match physics.geom_type[geom]:
        case mujoco.mjtGeom.mjGEOM_SPHERE:
            return z - float(size[0])
        case mujoco.mjtGeom.mjGEOM_BOX:
            return z - sum(abs(float(up[i])) * float(size[i]) for i in range(3))
        case mujoco.mjtGeom.mjGEOM_CYLINDER:
            tilt = abs(float(up[2]))
            return z - tilt * float(size[1]) - float(size[0]) * math.sqrt(max(0.0, 1 - tilt * tilt))
        case _:
            return z - float(physics.geom_rbound[geom])


def _replies(p: m.Primitive) -> dict[int | None, _Reply]:
    """The primitive's reply, or its table's replies by key value (a tag's table: none), or its
    listed replies by their place."""
    if p.listed:  # by their place
        return {n: _reply(r.decoding, r.actions, r.expect, p.params) for n, r in enumerate(p.listed)}
    if p.table is None:
        return {None: _reply(p.decoding, p.actions, p.expect, p.params)}
    if p.table.tag is not None:
        return {}
    return {v: _reply(c.decoding, c.actions, p.expect, p.params) for c in p.table.cases for v in c.values()}


def _reply(decoding: m.Unpack | m.Regex | None, actions: tuple[m.PostAction, ...], expect: m.Expr | None,
           params: tuple[m.Parameter, ...]) -> _Reply:
    slots = {p.name: i for i, p in enumerate(params)}
    sensed: list[_Sensed] = []
    for a in actions:
        match a.value:
            case m.ReplyValue(index=k):
                sensed.append(_Sensed(k, a.target, None))
            case m.Replaced(array=m.Var(name=name), index=index, value=m.ReplyValue(index=k)) if name == a.target:
                sensed.append(_Sensed(k, a.target, _over_params(prepare(index, slots))))
    pins = tuple(_pins(expect)) if expect is not None else ()
    return _Reply(_zeros(decoding), tuple(sensed), pins)


def _zeros(decoding: m.Unpack | m.Regex | None) -> tuple[Any, ...]:
    """A reply of zeros: what the decoding gives for zero bytes, or a regex's groups each "0"."""
    match decoding:
        case m.Unpack():
            unpack = decoder(decoding)
            assert isinstance(unpack, engine.Unpack)
            return tuple(unpack.decode("", bytes(unpack.size)))
        case m.Regex(pattern=pattern):
            return ("0",) * re.compile(pattern).groups
    return ()


def _pins(expect: m.Expr) -> list[tuple[int, m.Value]]:
    """The reply values `expect` fixes: `out[k] == C` in a conjunction."""
    match expect:
        case m.BinaryOp(op="and", left=left, right=right):
            return _pins(left) + _pins(right)
        case m.BinaryOp(op="==", left=m.ReplyValue(index=k), right=m.Const(value=value)):
            return [(k, value)]
        case m.BinaryOp(op="==", left=m.Const(value=value), right=m.ReplyValue(index=k)):
            return [(k, value)]
    return []


def _over_params(f: Prepared) -> Callable[[Sequence[Any]], Any]:
    """An expression over a primitive's parameters alone (an element's index)."""
    return lambda local: f({}, local, ())


def _format_positions(p: m.Primitive) -> list[int]:
    """Where each parameter is among the format values of a primitive called directly."""
    at = {a.name: i for i, a in enumerate(p.args) if isinstance(a, m.Var)}
    return [at[param.name] for param in p.params]


def _conversion(expr: m.Expr, name: str) -> Callable[[Any], Any]:
    """A transmission's conversion as a function of the one value it reads (`raw`, or the quantity)."""
    converted = prepare(expr, {name: 0})
    if name == "raw":
        return lambda value: converted({}, [value], ())
    return lambda value: converted({}, [float(value)], ())
