"""How fast a generated driver and the runtime send a command: figures to read, not a test.

    python benchmarks/driver_speed.py             # the figures
    python benchmarks/driver_speed.py --calls 50000

Two commands, each written into a port object that discards the bytes, three ways,
in this process and this run:

1. The Create's `set_velocity` input (examples/create.rdis, copied with every delay
   made 0 ms), over the six rows of thesis Table 4.3 in turn:
   - baseline: hand-written, the minimum: the input's arithmetic (clamp, the
     special radii, round to mm) then `port.write(struct.pack(">Bhh", 137, v, r))`,
     with the fields by keyword;
   - the driver `rdisc emit-python` generates: `robot.set_velocity(linear=..., angular=...)`
     (target: within 1.3x of the baseline);
   - the rdisc runtime interpreting the description: `robot.call_input("set_velocity", ...)`
     (target: within 3x of the baseline).
2. The AX-12's broadcast goal position, a framed write (examples/ax12.rdis,
   primitive `goto_all`: WRITE_DATA of address 30 to ID 254, which every servo
   obeys and none answers; `goto_all(512)` is `FF FF FE 05 03 1E 00 02 D9`), over
   the goals 0, 512 and 1023 in turn:
   - baseline: hand-written and specialised to this one packet: the goal's range
     check, then one `struct.pack` of the whole packet, its checksum summed from
     the constant bytes and the goal's two;
   - the generated driver: `robot.call_primitive("goto_all", goal)` (target: within 2x);
   - the runtime: `robot.call_primitive("goto_all", goal)` (target: within 4x).

Every way is called as the others are, through one function call per command.
Each figure is the best of --repeat runs of --calls calls, the three ways
interleaved so that drift hits them alike. Every figure is printed with PASS or
MISS against its target; the exit code is 0 either way (1 only when a way writes
other bytes than the baseline, or the AX-12 baseline other bytes than the manual's,
which is a bug).
"""

from __future__ import annotations

import argparse
import re
import struct
import sys
import tempfile
import timeit
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc, when it is not installed

from rdisc.emit.python import import_driver
from rdisc.runtime import load

CREATE = ROOT / "examples" / "create.rdis"
AX12 = ROOT / "examples" / "ax12.rdis"
TABLE_4_3 = [(-0.2, -0.4), (0.0, 0.0), (0.0, 0.2), (0.0, -0.2), (0.2, 0.0), (-0.2, 0.0)]
GOALS = [(0,), (512,), (1023,)]
GOTO_ALL_512 = bytes.fromhex("FF FF FE 05 03 1E 00 02 D9")  # written out from the AX-12 manual, not computed


class DiscardingPort:
    """A port that takes every byte and keeps only the last write (to compare the ways' bytes)."""

    def __init__(self) -> None:
        self.last = b""

    def write(self, data: bytes) -> int:
        self.last = data
        return len(data)

    def flush(self) -> None:
        pass

    def read(self, size: int = 1) -> bytes:
        return b""

    def close(self) -> None:
        pass


def set_velocity(port: DiscardingPort, linear: float, angular: float) -> None:
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


def goto_all(port: DiscardingPort, goal: int) -> None:
    """goto_all by hand: FF FF, ID 254, LEN 5, WRITE_DATA (3), address 30, the goal
    little-endian, and ~(ID + LEN + instruction + parameters) & 0xFF, in one struct.pack."""
    if not 0 <= goal <= 1023:
        raise ValueError(f"goal {goal} is outside 0..1023")
    checksum = ~(0xFE + 5 + 3 + 0x1E + (goal & 0xFF) + (goal >> 8)) & 0xFF
    port.write(struct.pack("<6BHB", 0xFF, 0xFF, 0xFE, 5, 3, 0x1E, goal, checksum))


@dataclass
class Way:
    label: str
    call: Callable[..., Any]
    port: DiscardingPort
    target: float | None  # at most this many times the baseline; None for the baseline


@dataclass
class Bench:
    title: str
    rows: Sequence[tuple[Any, ...]]  # the arguments of each call, in turn
    ways: list[Way]  # the baseline first


def zero_delay_copy(folder: Path) -> Path:
    copy = folder / "create_no_delays.rdis"
    copy.write_text(re.sub(r"delay \d+ ms", "delay 0 ms", CREATE.read_text(encoding="utf-8")), encoding="utf-8")
    return copy


def create_bench(folder: Path) -> Bench:
    source = zero_delay_copy(folder)
    port, driver_port, runtime_port = DiscardingPort(), DiscardingPort(), DiscardingPort()
    driver = import_driver(source, folder, "create_driver").connect(driver_port, threads=False)
    runtime = load(source).connect(runtime_port, threads=False)
    return Bench(
        "set_velocity (Table 4.3 inputs in turn, zero delays)",
        TABLE_4_3,
        [
            Way("baseline (hand-written struct.pack + write)",
                lambda linear, angular: set_velocity(port, linear=linear, angular=angular), port, None),
            Way("generated driver, robot.set_velocity(...)",
                lambda linear, angular: driver.set_velocity(linear=linear, angular=angular), driver_port, 1.3),
            Way("rdisc runtime, robot.call_input(...)",
                lambda linear, angular: runtime.call_input("set_velocity", linear=linear, angular=angular),
                runtime_port, 3.0),
        ],
    )


def ax12_bench(folder: Path) -> Bench:
    port, driver_port, runtime_port = DiscardingPort(), DiscardingPort(), DiscardingPort()
    driver = import_driver(AX12, folder, "ax12_driver").connect(driver_port, threads=False)
    runtime = load(AX12).connect(runtime_port, threads=False)
    return Bench(
        "AX-12 goto_all, a framed broadcast write (goals 0, 512, 1023 in turn)",
        GOALS,
        [
            Way("baseline (hand-written struct.pack + checksum)", lambda goal: goto_all(port, goal), port, None),
            Way("generated driver, robot.call_primitive(...)",
                lambda goal: driver.call_primitive("goto_all", goal), driver_port, 2.0),
            Way("rdisc runtime, robot.call_primitive(...)",
                lambda goal: runtime.call_primitive("goto_all", goal), runtime_port, 4.0),
        ],
    )


def same_bytes(bench: Bench) -> bool:
    """Whether every way writes what the baseline writes, row by row."""
    ok = True
    for row in bench.rows:
        written = {}
        for way in bench.ways:
            way.call(*row)
            written[way.label] = way.port.last
        if len(set(written.values())) != 1:
            print(f"{bench.title}: different bytes for {row}: {written}", file=sys.stderr)
            ok = False
    return ok


def per_call_ns(call: Callable[..., Any], rows: Sequence[tuple[Any, ...]], calls: int) -> float:
    """Nanoseconds per call of one run of `calls` calls, over the rows in turn."""
    args = (list(rows) * (calls // len(rows) + 1))[:calls]

    def run() -> None:
        for row in args:
            call(*row)

    return timeit.timeit(run, number=1) / calls * 1e9


def report(bench: Bench, calls: int, repeat: int) -> None:
    best = {way.label: float("inf") for way in bench.ways}
    for _ in range(repeat):  # interleaved: one run of each way in turn
        for way in bench.ways:
            best[way.label] = min(best[way.label], per_call_ns(way.call, bench.rows, calls))
    base = best[bench.ways[0].label]
    print(f"{bench.title}:")
    for way in bench.ways:
        line = f"  {way.label:<48}{best[way.label]:8.0f} ns"
        if way.target is not None:
            ratio = best[way.label] / base
            line += (f"   {ratio:5.2f}x baseline  (target <= {way.target}x)  "
                     f"{'PASS' if ratio <= way.target else 'MISS'}")
        print(line)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--calls", type=int, default=60_000, help="calls per run (default 60000)")
    parser.add_argument("--repeat", type=int, default=7, help="runs per way; the best counts (default 7)")
    args = parser.parse_args()

    reference = DiscardingPort()
    goto_all(reference, 512)
    if reference.last != GOTO_ALL_512:
        print(f"the hand-written goto_all(512) writes {reference.last.hex(' ')}, "
              f"not the manual's {GOTO_ALL_512.hex(' ')}", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        benches = [create_bench(Path(tmp)), ax12_bench(Path(tmp))]
        checked = [same_bytes(bench) for bench in benches]  # every difference printed, not only the first
        if not all(checked):
            return 1
        print(f"Per call, best of {args.repeat} runs of {args.calls} calls, into a port that discards bytes, "
              f"Python {sys.version.split()[0]}:")
        for bench in benches:
            report(bench, args.calls, args.repeat)
    return 0


if __name__ == "__main__":
    sys.exit(main())
