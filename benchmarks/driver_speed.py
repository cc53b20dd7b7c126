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
   - the same hand-written code writing under a `threading.RLock`, as the engine writes under
     the port's lock (no target: what a lock costs, against which the generated driver is shown too);
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
4. The Create 2's sensor exchange (`sensors()`: opcode 142 for packet 100, all 80 bytes of the
   sensors), into a port that answers every request with the same 80 bytes:
   - baseline: hand-written, the request written, 80 bytes read and their length checked, one
     `struct.unpack` of the description's format and a dict of the 69 values the description
     takes from it (bits as bools), by name;
   - pycreate2's `Create2.get_sensors()` (its write, its read, its namedtuples), without its
     15 ms sleep, when installed;
   - the generated driver's `robot.primitives.sensors()` (target: within 1.2x of the baseline,
     and faster than pycreate2) and the runtime's; the values they store are the baseline's.

What the ways do besides the baseline is printed under each title: the typed method tests each
value's type (an int for a float field goes the general way, which widens it), and the engine
writes under the port's lock (with its closed and I/O-callback tests), resets the input before
an exchange and stores a reply's values as a new state snapshot under the state lock. The row
"the engine's own part" is that alone: `robot._write` (or `robot._ask`) of the request made
beforehand, the least any way through the engine costs.

Every way is called as the others are, through one function call per command.
Each figure is the best of --repeat runs of --calls calls, the ways interleaved so
that drift hits them alike; a run is timed by this process's CPU time, so that other
processes on a busy machine do not count. Many short runs (60 of 5,000 calls) rather
than a few long ones: on a shared machine whose speed changes within a second, the
set_velocity ratio moved by 0.01 over three runs so, and by 0.15 as 7 runs of 60,000.
Every figure is printed with PASS or MISS against its target; the exit code is 0 either way (1 only when a way writes
other bytes than the baseline or stores other sensor values than it, or the AX-12 baseline
other bytes than the manual's, which is a bug).
"""

from __future__ import annotations

import argparse
import itertools
import re
import struct
import sys
import tempfile
import textwrap
import threading
import time
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


class AnsweringPort(DiscardingPort):
    """A port that answers every write with the same reply."""

    is_open = True  # what pycreate2 asks before it reads
    timeout = 1.0

    def __init__(self, reply: bytes) -> None:
        super().__init__()
        self.reply = reply
        self.pending = b""

    def write(self, data: bytes) -> int:
        self.last = data
        self.pending = self.reply
        return len(data)

    def read(self, size: int = 1) -> bytes:
        taken, self.pending = self.pending[:size], self.pending[size:]
        return taken

    def reset_input_buffer(self) -> None:
        self.pending = b""


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


def set_velocity_locked(port: DiscardingPort, lock: Any, linear: float, angular: float) -> None:
    """set_velocity by hand, called under a lock as the engine writes (`lock`: a `threading.RLock`):
    the baseline's own function, so one call more than it (not a target's baseline)."""
    lock.acquire()
    try:
        set_velocity(port, linear, angular)
    finally:
        lock.release()


def goto_all(port: DiscardingPort, goal: int) -> None:
    """goto_all by hand: FF FF, ID 254, LEN 5, WRITE_DATA (3), address 30, the goal
    little-endian, and ~(ID + LEN + instruction + parameters) & 0xFF, in one struct.pack."""
    if not 0 <= goal <= 1023:
        raise ValueError(f"goal {goal} is outside 0..1023")
    checksum = ~(0xFE + 5 + 3 + 0x1E + (goal & 0xFF) + (goal >> 8)) & 0xFF
    port.write(struct.pack("<6BHB", 0xFF, 0xFF, 0xFE, 5, 3, 0x1E, goal, checksum))


def goto_all_locked(port: DiscardingPort, lock: Any, goal: int) -> None:
    """goto_all by hand, written under a lock as the engine writes (`lock`: a `threading.RLock`):
    what a hand-written driver that others' threads may call costs (not a target's baseline)."""
    if not 0 <= goal <= 1023:
        raise ValueError(f"goal {goal} is outside 0..1023")
    checksum = ~(0xFE + 5 + 3 + 0x1E + (goal & 0xFF) + (goal >> 8)) & 0xFF
    request = struct.pack("<6BHB", 0xFF, 0xFF, 0xFE, 5, 3, 0x1E, goal, checksum)
    lock.acquire()
    try:
        port.write(request)
    finally:
        lock.release()


def drive_direct(port: DiscardingPort, right: int, left: int) -> None:
    """drive_direct by hand: both speeds in -500..500 mm/s, then one struct.pack and one write."""
    if not -500 <= right <= 500 or not -500 <= left <= 500:
        raise ValueError(f"a wheel speed outside -500..500 mm/s: {right}, {left}")
    port.write(struct.pack(">Bhh", 145, right, left))


SENSORS = struct.Struct(">B6?BBxBBhhBHhbHHH4H3xBBB?B6hB6HBB4hB")  # packet 100, as create2.rdis reads it
SENSOR_REPLY = SENSORS.pack(5, True, False, False, True, False, False, 24, 40, 161, 0, 12, -35, 2, 15412, -1285,
                            27, 2410, 2696, 12, 1502, 2048, 87, 955, 3, 2, 0, False, 1, -200, 32767,
                            -210, -190, 31204, -766, 33, 12, 8, 0, 0, 240, 1180, 161, 160, 303, 299, 42, 18, 2)


def sensors(port: DiscardingPort) -> dict[str, Any]:
    """Packet 100 by hand: the request, 80 bytes read and checked, one unpack, the values by name."""
    port.write(b"\x8e\x64")
    data = port.read(80)
    if len(data) != 80:
        raise ValueError(f"sensor packet 100: {len(data)} bytes, not 80")
    out = SENSORS.unpack(data)
    return {
        "bump_right": bool(out[0] & 1), "bump_left": bool(out[0] & 2), "wheel_drop_right": bool(out[0] & 4),
        "wheel_drop_left": bool(out[0] & 8), "wall": out[1], "cliff_left": out[2], "cliff_front_left": out[3],
        "cliff_front_right": out[4], "cliff_right": out[5], "virtual_wall": out[6],
        "side_brush_overcurrent": bool(out[7] & 1), "main_brush_overcurrent": bool(out[7] & 4),
        "right_wheel_overcurrent": bool(out[7] & 8), "left_wheel_overcurrent": bool(out[7] & 16),
        "dirt_detect": out[8], "ir_omni": out[9], "button_clean": bool(out[10] & 1),
        "button_spot": bool(out[10] & 2), "button_dock": bool(out[10] & 4), "button_minute": bool(out[10] & 8),
        "button_hour": bool(out[10] & 16), "button_day": bool(out[10] & 32),
        "button_schedule": bool(out[10] & 64), "button_clock": bool(out[10] & 128), "distance": out[11],
        "angle": out[12], "charging_state": out[13], "voltage": out[14], "current": out[15],
        "temperature": out[16], "battery_charge": out[17], "battery_capacity": out[18], "wall_signal": out[19],
        "cliff_left_signal": out[20], "cliff_front_left_signal": out[21], "cliff_front_right_signal": out[22],
        "cliff_right_signal": out[23], "internal_charger": bool(out[24] & 1), "home_base": bool(out[24] & 2),
        "oi_mode": out[25], "song_number": out[26], "song_playing": out[27], "stream_packets": out[28],
        "velocity": out[29], "radius": out[30], "right_velocity": out[31], "left_velocity": out[32],
        "left_encoder": out[33], "right_encoder": out[34], "light_bumper_left": bool(out[35] & 1),
        "light_bumper_front_left": bool(out[35] & 2), "light_bumper_center_left": bool(out[35] & 4),
        "light_bumper_center_right": bool(out[35] & 8), "light_bumper_front_right": bool(out[35] & 16),
        "light_bumper_right": bool(out[35] & 32), "light_bump_left_signal": out[36],
        "light_bump_front_left_signal": out[37], "light_bump_center_left_signal": out[38],
        "light_bump_center_right_signal": out[39], "light_bump_front_right_signal": out[40],
        "light_bump_right_signal": out[41], "ir_left": out[42], "ir_right": out[43],
        "left_motor_current": out[44], "right_motor_current": out[45], "main_brush_current": out[46],
        "side_brush_current": out[47], "stasis_toggling": bool(out[48] & 1),
        "stasis_disabled": bool(out[48] & 2),
    }


@dataclass
class Way:
    label: str
    call: Callable[..., Any]
    port: DiscardingPort
    target: float | None  # at most this many times the baseline; None for the baseline
    against: str | None = None  # the label of another way the target is relative to (else the baseline)
    beats: str | None = None  # the label of another way this one must also be no slower than
    shown_against: str | None = None  # the label of another way this one is also shown against (no target)


@dataclass
class Bench:
    title: str
    rows: Sequence[tuple[Any, ...]]  # the arguments of each call, in turn
    ways: list[Way]  # the baseline first
    fair: str = ""  # what the baseline does, and what the other ways do besides


def engine_part(robot: Any, port: DiscardingPort, primitive: str, baseline: Way,
                rows: Sequence[tuple[Any, ...]]) -> Way:
    """The engine's own part of a command: `robot`'s write (into `port`) of the request the
    baseline makes for a row, made beforehand (the port's lock, the closed and I/O-callback tests,
    the port's write): the least any way through the engine costs."""
    made = []
    for row in rows:
        baseline.call(*row)
        made.append(baseline.port.last)
    requests, plan, write = itertools.cycle(made), robot.device.primitives[primitive], robot._write
    return Way("the engine's own part, robot._write(plan, bytes)", lambda *row: write(plan, next(requests)), port,
               None)  # the rows are called in turn, and so are their requests


LOCKED = ("the generated driver besides: each value's type tested, the write under the port's lock "
          "(and its closed and I/O-callback tests)")


def zero_delay_copy(folder: Path) -> Path:
    copy = folder / "create_no_delays.rdis"
    copy.write_text(re.sub(r"delay \d+ ms", "delay 0 ms", CREATE.read_text(encoding="utf-8")), encoding="utf-8")
    return copy


def create_bench(folder: Path) -> Bench:
    source = zero_delay_copy(folder)
    port, driver_port, runtime_port = DiscardingPort(), DiscardingPort(), DiscardingPort()
    driver = import_driver(source, folder, "create_driver").connect(driver_port, threads=False)
    runtime = load(source).connect(runtime_port, threads=False)
    baseline = Way("baseline (hand-written struct.pack + write)",
                   lambda linear, angular: set_velocity(port, linear=linear, angular=angular), port, None)
    locked_port, lock = DiscardingPort(), threading.RLock()
    locked = "hand-written under an RLock, the baseline's call"
    return Bench(
        "set_velocity (Table 4.3 inputs in turn, zero delays)",
        TABLE_4_3,
        [
            baseline,
            Way(locked, lambda linear, angular: set_velocity_locked(locked_port, lock, linear, angular), locked_port,
                None),
            Way("generated driver, robot.set_velocity(...)",
                lambda linear, angular: driver.set_velocity(linear=linear, angular=angular), driver_port, 1.2,
                shown_against=locked),
            engine_part(driver, driver_port, "drive", baseline, TABLE_4_3),
            Way("rdisc runtime, robot.call_input(...)",
                lambda linear, angular: runtime.call_input("set_velocity", linear=linear, angular=angular),
                runtime_port, 3.0),
        ],
        "the baseline: the input's arithmetic, one struct.pack, the port's write (no type test, no lock); "
        "the hand-written code under an RLock: the baseline's function called under the lock; " + LOCKED,
    )


def ax12_bench(folder: Path) -> Bench:
    port, driver_port, runtime_port = DiscardingPort(), DiscardingPort(), DiscardingPort()
    driver = import_driver(AX12, folder, "ax12_driver").connect(driver_port, threads=False)
    runtime = load(AX12).connect(runtime_port, threads=False)
    baseline = Way("baseline (hand-written struct.pack + checksum)", lambda goal: goto_all(port, goal), port, None)
    locked_port, lock = DiscardingPort(), threading.RLock()
    locked = "hand-written under an RLock, the same code"
    return Bench(
        "AX-12 goto_all, a framed broadcast write (goals 0, 512, 1023 in turn)",
        GOALS,
        [
            baseline,
            Way(locked, lambda goal: goto_all_locked(locked_port, lock, goal), locked_port, None),
            Way("generated driver, robot.call_primitive(...)",
                lambda goal: driver.call_primitive("goto_all", goal), driver_port, 1.5, shown_against=locked),
            Way("generated driver, robot.primitives.goto_all(...)",
                lambda goal: driver.primitives.goto_all(goal), driver_port, 1.5, shown_against=locked),
            engine_part(driver, driver_port, "goto_all", baseline, GOALS),
            Way("rdisc runtime, robot.call_primitive(...)",
                lambda goal: runtime.call_primitive("goto_all", goal), runtime_port, 3.0),
            Way("rdisc runtime, robot.primitives.goto_all(...)",
                lambda goal: runtime.primitives.goto_all(goal), runtime_port, 3.0),
        ],
        "the baseline: the goal's range test, one struct.pack, the port's write (no type test, no lock); "
        "the hand-written code under an RLock: the same, the write under the lock; " + LOCKED,
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
    SerialCommandInterface.__del__ = lambda self: None  # and its port's closes the port
    return bot


def create2_bench(folder: Path) -> Bench:
    port, theirs, driver_port, runtime_port = DiscardingPort(), DiscardingPort(), DiscardingPort(), DiscardingPort()
    driver = import_driver(CREATE2, folder, "create2_driver").connect(driver_port, threads=False)
    runtime = load(CREATE2).connect(runtime_port, threads=False)
    baseline = Way("baseline (hand-written struct.pack + write)", lambda right, left: drive_direct(port, right, left),
                   port, None)
    ways = [baseline]
    bot = pycreate2_robot(theirs)
    if bot is not None:
        ways.append(Way("pycreate2, Create2.drive_direct(...)", bot.drive_direct, theirs, None))
    ways += [
        Way("generated driver, robot.primitives.drive_direct(...)", driver.primitives.drive_direct, driver_port,
            1.0 if bot is not None else None, "pycreate2, Create2.drive_direct(...)" if bot is not None else None),
        engine_part(driver, driver_port, "drive_direct", baseline, WHEELS),
        Way("rdisc runtime, robot.primitives.drive_direct(...)", runtime.primitives.drive_direct, runtime_port,
            None),
    ]
    return Bench("Create 2 drive_direct, two wheel speeds (three pairs in turn)", WHEELS, ways,
                 "the baseline: both speeds' range test, one struct.pack, the port's write (no type test, no lock); "
                 "pycreate2: a clamp, no lock; " + LOCKED)


def sensors_bench(folder: Path) -> Bench | None:
    """Packet 100 read several ways; None (and why, printed) when a way stores other values than the baseline."""
    port, theirs, driver_port, runtime_port = (AnsweringPort(SENSOR_REPLY) for _ in range(4))
    driver = import_driver(CREATE2, folder, "create2_sensors_driver").connect(driver_port, threads=False)
    runtime = load(CREATE2).connect(runtime_port, threads=False)
    expected = sensors(port)
    for label, robot in (("generated driver", driver), ("rdisc runtime", runtime)):
        robot.primitives.sensors()
        stored = {name: robot.state[name] for name in expected}
        if stored != expected:
            print(f"sensors: the {label} stores {stored}, not {expected}", file=sys.stderr)
            return None
    ways = [Way("baseline (hand-written write, read, unpack, dict)", lambda: sensors(port), port, None)]
    bot = pycreate2_robot(theirs)
    if bot is not None:
        import pycreate2.create2api as api

        api.time = type("NoSleep", (), {"sleep": staticmethod(lambda seconds: None)})  # its 15 ms wait
        ways.append(Way("pycreate2, Create2.get_sensors()", bot.get_sensors, theirs, None))
    plan = driver.device.primitives["sensors"]
    ways += [
        Way("generated driver, robot.primitives.sensors()", driver.primitives.sensors, driver_port, 1.2,
            beats="pycreate2, Create2.get_sensors()" if bot is not None else None),
        Way("the engine's own part, robot._ask(plan, bytes, [])", lambda: driver._ask(plan, b"\x8e\x64", []),
            driver_port, None),
        Way("rdisc runtime, robot.primitives.sensors()", runtime.primitives.sensors, runtime_port, None),
    ]
    return Bench("Create 2 sensors, packet 100 (80 bytes read and decoded)", [()], ways,
                 "the baseline: the write, one read, the length test, one struct.unpack, a dict of the values "
                 "returned (no lock); pycreate2: no test of the length, namedtuples; the generated driver besides: "
                 "the exchange under the port's lock, the input reset before the write, the values stored as a "
                 "new state snapshot under the state lock")


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

    return timeit.timeit(run, number=1, timer=time.process_time) / calls * 1e9


def report(bench: Bench, calls: int, repeat: int) -> None:
    best = {way.label: float("inf") for way in bench.ways}
    for _ in range(repeat):  # interleaved: one run of each way in turn
        for way in bench.ways:
            best[way.label] = min(best[way.label], per_call_ns(way.call, bench.rows, calls))
    base = best[bench.ways[0].label]
    print(f"{bench.title}:")
    if bench.fair:
        print("\n".join(textwrap.wrap(f"({bench.fair})", 108, initial_indent="  ", subsequent_indent="   ")))
    for way in bench.ways:
        line = f"  {way.label:<54}{best[way.label]:8.0f} ns   {best[way.label] / base:5.2f}x baseline"
        if way.target is not None:
            ratio = best[way.label] / best[way.against or bench.ways[0].label]
            if way.against:
                line += f"  {ratio:5.2f}x pycreate2"
            line += f" (target <= {way.target}x)  {'PASS' if ratio <= way.target else 'MISS'}"
        if way.shown_against is not None:
            ratio = best[way.label] / best[way.shown_against]
            line += f"\n  {'':<54}{'':>8}      {ratio:5.2f}x {way.shown_against.split(',')[0]} (no target)"
        if way.beats is not None:
            ratio = best[way.label] / best[way.beats]
            line += f"\n  {'':<54}{'':>8}      {ratio:5.2f}x {way.beats.split(',')[0]} (target <= 1.0x)  "
            line += "PASS" if ratio <= 1.0 else "MISS"
        print(line)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--calls", type=int, default=5_000, help="calls per run (default 5000)")
    parser.add_argument("--repeat", type=int, default=60, help="runs per way; the best counts (default 60)")
    args = parser.parse_args()

    reference = DiscardingPort()
    goto_all(reference, 512)
    if reference.last != GOTO_ALL_512:
        print(f"the hand-written goto_all(512) writes {reference.last.hex(' ')}, "
              f"not the manual's {GOTO_ALL_512.hex(' ')}", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        sensing = sensors_bench(Path(tmp))
        if sensing is None:
            return 1
        benches = [create_bench(Path(tmp)), ax12_bench(Path(tmp)), create2_bench(Path(tmp)), sensing]
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
