"""How fast a generated driver and the runtime send a command: figures to read, not a test.

    python benchmarks/driver_speed.py             # the figures
    python benchmarks/driver_speed.py --calls 50000

One call of the Create's `set_velocity` input (examples/create.rdis, copied with
every delay made 0 ms), writing into a port object that discards the bytes, three
ways, in this process and this run:

- baseline: hand-written, the minimum: the input's arithmetic (clamp, the
  special radii, round to mm) then `port.write(struct.pack(">Bhh", 137, v, r))`,
  called as the others are, with the fields by keyword;
- the driver `rdisc emit-python` generates: `robot.set_velocity(linear=..., angular=...)`
  (target: within 1.5x of the baseline);
- the rdisc runtime interpreting the description: `robot.call_input("set_velocity", ...)`
  (target: within 5x of the baseline).

The inputs cycle through the six rows of thesis Table 4.3. Each figure is the best
of --repeat runs of --calls calls, the three ways interleaved so that drift hits
them alike. Every figure is printed with PASS or MISS against its target; the exit
code is 0 either way (1 only when a way writes other bytes than the baseline, which
is a bug).
"""

from __future__ import annotations

import argparse
import re
import struct
import sys
import tempfile
import timeit
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc, when it is not installed

from rdisc.emit.python import import_driver

CREATE = ROOT / "examples" / "create.rdis"
TABLE_4_3 = [(-0.2, -0.4), (0.0, 0.0), (0.0, 0.2), (0.0, -0.2), (0.2, 0.0), (-0.2, 0.0)]
GENERATED_TARGET = 1.5
RUNTIME_TARGET = 5.0


class DiscardingPort:
    """A port that takes every byte and keeps none (it counts them)."""

    def __init__(self) -> None:
        self.written = 0
        self.last = b""

    def write(self, data: bytes) -> int:
        self.written += len(data)
        self.last = data
        return len(data)

    def flush(self) -> None:
        pass

    def read(self, size: int = 1) -> bytes:
        return b""

    def close(self) -> None:
        pass


def baseline(port: DiscardingPort, linear: float, angular: float) -> None:
    """set_velocity by hand: the description's arithmetic, then one struct.pack and one write."""
    velocity = linear
    if velocity < -0.5:
        velocity = -0.5
    elif velocity > 0.5:
        velocity = 0.5
    if linear == 0 and angular == 0:
        radius = 0.0
    elif linear == 0:
        radius = -0.001 if angular > 0 else 0.001
    elif angular == 0:
        radius = 32.767
    else:
        radius = linear / angular
        if radius < -2.0:
            radius = -2.0
        elif radius > 2.0:
            radius = 2.0
    port.write(struct.pack(">Bhh", 137, round(velocity * 1000), round(radius * 1000)))


def zero_delay_copy(folder: Path) -> Path:
    copy = folder / "create_no_delays.rdis"
    copy.write_text(re.sub(r"delay \d+ ms", "delay 0 ms", CREATE.read_text(encoding="utf-8")), encoding="utf-8")
    return copy


def generated_driver(source: Path, folder: Path) -> ModuleType:
    return import_driver(source, folder, "create_driver")


def per_call_ns(call: Callable[[float, float], Any], calls: int, repeat: int) -> list[float]:
    """Nanoseconds per call of each run, over the Table 4.3 inputs in turn."""
    rows = TABLE_4_3 * (calls // len(TABLE_4_3) + 1)
    rows = rows[:calls]

    def run() -> None:
        for linear, angular in rows:
            call(linear, angular)

    return [t / calls * 1e9 for t in timeit.repeat(run, number=1, repeat=repeat)]


def same_bytes(ways: dict[str, tuple[Callable[[float, float], Any], DiscardingPort]]) -> bool:
    """Whether every way writes what the baseline writes, row by row."""
    ok = True
    for linear, angular in TABLE_4_3:
        written = {}
        for name, (call, port) in ways.items():
            call(linear, angular)
            written[name] = port.last
        if len(set(written.values())) != 1:
            print(f"different bytes for ({linear}, {angular}): {written}", file=sys.stderr)
            ok = False
    return ok


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--calls", type=int, default=60_000, help="calls per run (default 60000)")
    parser.add_argument("--repeat", type=int, default=7, help="runs per way; the best counts (default 7)")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        source = zero_delay_copy(folder)
        driver = generated_driver(source, folder)
        ports = {name: DiscardingPort() for name in ("baseline", "generated", "runtime")}
        robot = driver.connect(ports["generated"], threads=False)
        ways: dict[str, tuple[Callable[[float, float], Any], DiscardingPort]] = {
            "baseline": (lambda linear, angular: baseline(ports["baseline"], linear=linear, angular=angular),
                         ports["baseline"]),
            "generated": (lambda linear, angular: robot.set_velocity(linear=linear, angular=angular),
                          ports["generated"]),
        }
        runtime_note = None
        try:
            from rdisc.runtime import load
        except ImportError:
            runtime_note = "rdisc.runtime.load does not exist yet: no runtime figure"
        else:
            interpreted = load(source).connect(ports["runtime"], threads=False)
            ways["runtime"] = (
                lambda linear, angular: interpreted.call_input("set_velocity", linear=linear, angular=angular),
                ports["runtime"],
            )
        if not same_bytes(ways):
            return 1

        best = {name: float("inf") for name in ways}
        for _ in range(args.repeat):  # interleaved: one run of each way in turn
            for name, (call, _port) in ways.items():
                best[name] = min(best[name], min(per_call_ns(call, args.calls, 1)))

    print(f"set_velocity per call, best of {args.repeat} runs of {args.calls} calls "
          f"(Table 4.3 inputs in turn, zero delays, a port that discards bytes), Python {sys.version.split()[0]}:")
    base = best["baseline"]
    print(f"  baseline (hand-written struct.pack + write)  {base:8.0f} ns")
    ratio = best["generated"] / base
    verdict = "PASS" if ratio <= GENERATED_TARGET else "MISS"
    print(f"  generated driver, robot.set_velocity(...)    {best['generated']:8.0f} ns   "
          f"{ratio:5.2f}x baseline  (target <= {GENERATED_TARGET}x)  {verdict}")
    if "runtime" in best:
        ratio = best["runtime"] / base
        verdict = "PASS" if ratio <= RUNTIME_TARGET else "MISS"
        print(f"  rdisc runtime, robot.call_input(...)         {best['runtime']:8.0f} ns   "
              f"{ratio:5.2f}x baseline  (target <= {RUNTIME_TARGET}x)  {verdict}")
    else:
        print(f"  rdisc runtime: {runtime_note}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
