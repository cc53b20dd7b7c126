"""How fast a generated driver and the runtime send a command: figures to read, not a test.

    python benchmarks/driver_speed.py             # the figures
    python benchmarks/driver_speed.py --calls 50000

Three commands, each written into a port object that discards the bytes, several ways,
in this process and this run (the targets are issue 21's):

1. The Create's `set_velocity` input (examples/create.rdis, copied with every delay
   made 0 ms), over the six rows of thesis Table 4.3 in turn:
   - baseline: hand-written, the minimum: the input's arithmetic (clamp, the
     special radii, round to mm) then `port.write(struct.pack(">Bhh", 137, v, r))`,
     with the fields by keyword;
   - the driver `rdisc emit-python` generates: `robot.set_velocity(linear=..., angular=...)`
     (target: within 1.2x of the baseline);
   - the rdisc runtime interpreting the description: `robot.call_input("set_velocity", ...)`
     (target: within 3x of the baseline).
2. The AX-12's broadcast goal position, a framed write (examples/ax12.rdis,
   primitive `goto_all`: WRITE_DATA of address 30 to ID 254, which every servo
   obeys and none answers; `goto_all(512)` is `FF FF FE 05 03 1E 00 02 D9`), over
   the goals 0, 512 and 1023 in turn:
   - baseline: hand-written and specialised to this one packet: the goal's range
     check, then one `struct.pack` of the whole packet, its checksum summed from
     the constant bytes and the goal's two;
   - the generated driver: `robot.call_primitive("goto_all", goal)` and its typed method
     `robot.primitives.goto_all(goal)` (target: within 1.5x);
   - the runtime: `robot.call_primitive("goto_all", goal)` and `robot.primitives.goto_all(goal)`
     (target: within 3x).
3. The Create 2's Drive Direct (examples/create2.rdis, `drive_direct(right, left)`: opcode 145,
   two big-endian mm/s), over three pairs of wheel speeds:
   - baseline: hand-written, the range check and one `struct.pack`;
   - pycreate2 0.9's own `Create2.drive_direct(r, l)` (its clamp, a pack, an unpack to
     bytes, a pack of them), when installed (`pip install --no-deps -r tests/published-drivers.txt`);
   - the generated driver's `robot.primitives.drive_direct(right, left)` (target: no slower
     than pycreate2) and the runtime's.

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
CREATE2 = ROOT / "examples" / "create2.rdis"
WHEELS = [(200, 200), (-500, 500), (123, -45)]
TABLE_4_3 = [(-0.2, -0.4), (0.0, 0.0), (0.0, 0.2), (0.0, -0.2), (0.2, 0.0), (-0.2, 0.0)]
GOALS = [(0,), (512,), (1023,)]
GOTO_ALL_512 = bytes.fromhex("FF FF FE 05 03 1E 00 02 D9")  # written out from the AX-12 manual, not computed


class DiscardingPort:
    """A port that takes every byte and keeps only the last write (to compare the ways' bytes)."""

    is_open = False  # what pycreate2's destructor asks before it would close the port

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


def drive_direct(port: DiscardingPort, right: int, left: int) -> None:
    """drive_direct by hand: both speeds in -500..500 mm/s, then one struct.pack and one write."""
    if not -500 <= right <= 500 or not -500 <= left <= 500:
        raise ValueError(f"a wheel speed outside -500..500 mm/s: {right}, {left}")
    port.write(struct.pack(">Bhh", 145, right, left))


@dataclass
class Way:
    label: str
    call: Callable[..., Any]
    port: DiscardingPort
    target: float | None  # at most this many times the baseline; None for the baseline
    against: str | None = None  # the label of another way the target is relative to (else the baseline)


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
                lambda linear, angular: driver.set_velocity(linear=linear, angular=angular), driver_port, 1.2),
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
                lambda goal: driver.call_primitive("goto_all", goal), driver_port, 1.5),
            Way("generated driver, robot.primitives.goto_all(...)",
                lambda goal: driver.primitives.goto_all(goal), driver_port, 1.5),
            Way("rdisc runtime, robot.call_primitive(...)",
                lambda goal: runtime.call_primitive("goto_all", goal), runtime_port, 3.0),
            Way("rdisc runtime, robot.primitives.goto_all(...)",
                lambda goal: runtime.primitives.goto_all(goal), runtime_port, 3.0),
        ],
    )


def pycreate2_robot(port: DiscardingPort) -> Any:
    """pycreate2's Create2 writing into `port`, its serial port never opened; None when not installed."""
    try:
        import pycreate2.create2api as api
        from pycreate2.createSerial import SerialCommandInterface
    except ImportError:
        return None
    bot = api.Create2.__new__(api.Create2)
    bot.SCI = SerialCommandInterface.__new__(SerialCommandInterface)
    bot.SCI.ser = port
    api.Create2.__del__ = lambda self: None  # its destructor drives the robot
    return bot


def create2_bench(folder: Path) -> Bench:
    port, theirs, driver_port, runtime_port = DiscardingPort(), DiscardingPort(), DiscardingPort(), DiscardingPort()
    driver = import_driver(CREATE2, folder, "create2_driver").connect(driver_port, threads=False)
    runtime = load(CREATE2).connect(runtime_port, threads=False)
    ways = [Way("baseline (hand-written struct.pack + write)",
                lambda right, left: drive_direct(port, right, left), port, None)]
    bot = pycreate2_robot(theirs)
    if bot is not None:
        ways.append(Way("pycreate2, Create2.drive_direct(...)", bot.drive_direct, theirs, None))
    ways += [
        Way("generated driver, robot.primitives.drive_direct(...)", driver.primitives.drive_direct, driver_port,
            1.0 if bot is not None else None, "pycreate2, Create2.drive_direct(...)" if bot is not None else None),
        Way("rdisc runtime, robot.primitives.drive_direct(...)", runtime.primitives.drive_direct, runtime_port,
            None),
    ]
    return Bench("Create 2 drive_direct, two wheel speeds (three pairs in turn)", WHEELS, ways)


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
        line = f"  {way.label:<54}{best[way.label]:8.0f} ns   {best[way.label] / base:5.2f}x baseline"
        if way.target is not None:
            ratio = best[way.label] / best[way.against or bench.ways[0].label]
            if way.against:
                line += f"  {ratio:5.2f}x pycreate2"
            line += f" (target <= {way.target}x)  {'PASS' if ratio <= way.target else 'MISS'}"
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
        benches = [create_bench(Path(tmp)), ax12_bench(Path(tmp)), create2_bench(Path(tmp))]
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
