"""The figures issue 13 asks of `rdisc sim`, printed against their targets: figures to read, not a test.

    python benchmarks/sim_figures.py

In simulated time (the same figures every run), through the runtime and the generated driver:
- the Create 2 (examples/create2.rdis) told `set_velocity linear=0.2 angular=0` for 2 s ends
  with odometry x = 0.4 m +- 10 % and |y| < 5 cm, and `angular=0.5` for 2 s turns 1 rad +- 10 %;
- the arm (examples/arm.rdis) told through its JointState input to six angles within its limits
  reports them back, through its sync read, within 2 units of its servos (0.003 rad) after 2 s.
"""

from __future__ import annotations

import math
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc, when it is not installed

from rdisc.emit.python import import_driver
from rdisc.runtime import load
from rdisc.sim import Simulation

CREATE2 = ROOT / "examples" / "create2.rdis"
ARM = ROOT / "examples" / "arm.rdis"
ARM_TARGET = [0.5, -0.3, 0.8, -0.6, 1.0, 0.2]  # rad, within every joint's limit
SERVO_UNIT = 2 * math.pi / 4096


def last_output(model: Any, connect: Callable[..., Any], call: Callable[[Any], None]) -> dict[str, Any]:
    """The contents of the last output of a 2 s simulated run of `model`'s body after `call`."""
    outputs: list[dict[str, Any]] = []
    robot = connect(sim=Simulation(model), on_output=outputs.append)
    try:
        call(robot)
        robot.run_for(2.0)
    finally:
        robot.close()
    contents: dict[str, Any] = outputs[-1]["contents"]
    return contents


def verdict(ok: bool) -> str:
    return "PASS" if ok else "MISS"


def main() -> int:
    met = True
    create2, arm = load(CREATE2), load(ARM)
    with tempfile.TemporaryDirectory() as folder:
        ways = (("rdisc runtime", create2.connect, arm.connect),
                ("generated driver", import_driver(CREATE2, folder).connect, import_driver(ARM, folder).connect))
        for way, drive, move in ways:
            straight = last_output(create2.model, drive, lambda r: r.call_input("set_velocity", linear=0.2, angular=0.0))
            turn = last_output(create2.model, drive, lambda r: r.call_input("set_velocity", linear=0.0, angular=0.5))
            joints = last_output(arm.model, move, lambda r: r.call_input("command", name=[], position=ARM_TARGET))
            worst = max(abs(got - want) for got, want in zip(joints["position"], ARM_TARGET, strict=True))
            rows = [
                (f"straight 2 s at 0.2 m/s: x {straight['x']:.3f} m (target 0.36..0.44)",
                 0.36 <= straight["x"] <= 0.44),
                (f"                        |y| {abs(straight['y']):.3f} m (target < 0.05)", abs(straight["y"]) < 0.05),
                (f"turn 2 s at 0.5 rad/s: theta {turn['theta']:.3f} rad (target 0.9..1.1)",
                 0.9 <= turn["theta"] <= 1.1),
                (f"arm to six angles: worst {worst:.4f} rad off (target <= {2 * SERVO_UNIT:.4f}, 2 servo units)",
                 worst <= 2 * SERVO_UNIT),
            ]
            print(way)
            for text, ok in rows:
                print(f"  {text:72} {verdict(ok)}")
                met &= ok
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
