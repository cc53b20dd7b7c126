"""The odometry a description computes, held against the simulated body it describes.

A robot's odometry is what its description makes of the device's encoders; the simulation knows
where the base really went. Each delivery of an output of the standard `Odometry` adapter is
compared with the base's pose in the physics, taken from where it started: when they are further
apart than the output's declared error (three deviations of its `x` and `y` noise; 5 cm when it
declares none), the simulation warns once per output, naming both. A wheel radius or wheel base
in the odometry's conversions that is not the body's (which the checker cannot see in a
post-action) is then plain to see. With `--watch`, each such output's line is followed by the
physics' pose in the odometry's frame: `{"simulated": "odom", "contents": {"x", "y", "theta"}}`."""

from __future__ import annotations

import json
import math
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rdisc.semantics import model as m
    from rdisc.sim import Simulation

DEFAULT_ERROR = 0.05  # m: how far odometry may drift from the physics when its output declares no noise
DEVIATIONS = 3.0  # a declared deviation's multiple that still counts as agreeing


class OdometryWatch:
    """Called with each output message (`robot.on_output`): warns, through the simulation's
    warnings, of an odometry that disagrees with the physics."""

    def __init__(self, model: m.Model, simulation: Simulation, *, show: bool = False) -> None:
        self.simulation = simulation
        self.show = show  # print the physics' pose beside each odometry (`--watch`)
        self.errors = {o.name: _error(o) for o in model.outputs.values() if o.adapter == "Odometry"}
        self.warned: set[str] = set()
        self.start = simulation.base_pose() if self.errors else (0.0, 0.0, 0.0)

    def __call__(self, message: dict[str, Any]) -> None:
        name = message.get("name")
        if not isinstance(name, str) or name not in self.errors:
            return
        error = self.errors[name]
        contents = message.get("contents", {})
        said = (contents.get("x"), contents.get("y"))
        if not all(isinstance(v, (int, float)) for v in said):
            return
        x, y, theta = self.simulation.base_pose()
        x0, y0, theta0 = self.start  # the odometry's frame: where the base started, as it was turned
        dx, dy = x - x0, y - y0
        true = (dx * math.cos(theta0) + dy * math.sin(theta0), -dx * math.sin(theta0) + dy * math.cos(theta0))
        if self.show:
            heading = math.remainder(theta - theta0, math.tau)
            pose = {"x": round(true[0], 6), "y": round(true[1], 6), "theta": round(heading, 6)}
            print(json.dumps({"simulated": name, "contents": pose}), flush=True)
        apart = math.hypot(float(said[0]) - true[0], float(said[1]) - true[1])
        if apart > error and name not in self.warned:
            self.warned.add(name)
            self.simulation.warnings.append(
                f"output `{name}` says the base is at ({said[0]:.3f}, {said[1]:.3f}) m, but the simulated base is at "
                f"({true[0]:.3f}, {true[1]:.3f}) m, {apart:.3f} m apart (more than its error of {error:g} m): "
                "its conversions' wheel radius or wheel base may not be the body's")


def _error(output: m.DomainOutput) -> float:
    """How far the output's x and y may be from the truth: three of their declared deviations
    together, or DEFAULT_ERROR."""
    variances = [n.covariance[at][at] for n in output.noise for at, field in enumerate(n.fields)
                 if field in ("x", "y") and len(n.covariance) == len(n.fields)]
    if len(variances) != 2:
        return DEFAULT_ERROR
    return DEVIATIONS * math.sqrt(sum(variances))
