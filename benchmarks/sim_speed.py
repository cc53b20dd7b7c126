"""How fast `rdisc sim` runs: simulated seconds per CPU second, figures to read, not a test.

    python benchmarks/sim_speed.py                # examples/create2.rdis driving a curve for 20 s
    python benchmarks/sim_speed.py --seconds 60

The Create 2 (examples/create2.rdis) is driven at 0.2 m/s and 0.5 rad/s through its
`set_velocity` input, its 20 Hz odometry poll running, against the MuJoCo simulation of its
body (timestep 2 ms), through the runtime and through the generated driver, in simulated time.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc, when it is not installed

from rdisc.emit.python import import_driver
from rdisc.runtime import load
from rdisc.sim import Simulation

CREATE2 = ROOT / "examples" / "create2.rdis"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=20.0, help="simulated seconds per run (default 20)")
    args = parser.parse_args()
    description = load(CREATE2)
    with tempfile.TemporaryDirectory() as folder:
        driver = import_driver(CREATE2, folder)
        for way, connect in (("rdisc runtime", description.connect), ("generated driver", driver.connect)):
            sim = Simulation(description.model)
            robot = connect(sim=sim)
            began = time.process_time()
            robot.call_input("set_velocity", linear=0.2, angular=0.5)
            robot.run_for(args.seconds)
            spent = time.process_time() - began
            x, y, heading = sim.pose("base")
            robot.close()
            print(f"{way:17} {args.seconds / spent:8.1f} simulated s per CPU s "
                  f"({args.seconds:g} s in {spent:.2f} CPU s; ends at x {x:.3f} m, y {y:.3f} m, heading {heading:.3f} rad)")


if __name__ == "__main__":
    main()
