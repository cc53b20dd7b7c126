"""How fast the Create 2's sensor packet 100 (80 bytes) is requested, read, decoded and
stored: figures to read, not a test.

    python benchmarks/decode_speed.py            # pycreate2's figures need: pip install '.[test]'

One whole "read every sensor" exchange, against a port object that answers the
80-byte packet at once, in this process and this run:

- baseline: hand-written, the minimum a driver does: discard unread input, write
  `142 100`, read 80 bytes, refuse a short reply, one `struct.unpack`, then the
  69 values of examples/create2.rdis (bit fields included) written out into its
  state dict;
- pycreate2's own `Create2.get_sensors()` (its 15 ms wait made 0), which writes
  `142 100`, reads 80 bytes and decodes them with `SensorPacketDecoder` into named
  tuples; and its decoder alone (no port), for reference;
- the driver `rdisc emit-python` generates from examples/create2.rdis:
  `robot.call_primitive("sensors")`, which does what the baseline does and
  publishes the new state as an immutable snapshot (targets: within 1.2x of the
  baseline, and at least as fast as pycreate2);
- the rdisc runtime interpreting the same description (for reference).

Each figure is the best of --repeat runs of --calls calls, the ways interleaved.
The exit code is 0 either way (1 only when a way writes other bytes than the
baseline, or rdisc decodes other values, which is a bug).
"""

from __future__ import annotations

import argparse
import struct
import sys
import tempfile
import timeit
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc, when it is not installed

from rdisc.emit.python import import_driver
from rdisc.runtime import load

CREATE2 = ROOT / "examples" / "create2.rdis"
# A plausible packet 100: bumps, a wall, cliffs, distances, battery figures, encoders.
PACKET = bytes(range(1, 81))
REQUEST = bytes((142, 100))
BASELINE_TARGET = 1.2  # the generated driver's time over the hand-written exchange's
PYCREATE2_TARGET = 1.0  # the generated driver's time over pycreate2's


class AnsweringPort:
    """Takes every write (keeping the last); each read returns the packet (or its next `size` bytes)."""

    is_open, port, baudrate = True, "memory", 115200  # what pycreate2 asks of a port

    def __init__(self) -> None:
        self.last = b""

    def write(self, data: bytes) -> int:
        self.last = data
        return len(data)

    def read(self, size: int = 1) -> bytes:
        return PACKET[:size]

    def read_until(self, expected: bytes = b"\n", size: int | None = None) -> bytes:
        return PACKET

    def reset_input_buffer(self) -> None:
        pass

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


PACKET_100 = struct.Struct(">B6?BBxBBhhBHhbHHH4H3xBBB?B6hB6HBB4hB")


def sensors(port: AnsweringPort, state: dict[str, Any]) -> None:
    """Packet 100 by hand: the exchange, one unpack, and every value of create2.rdis into `state`."""
    port.reset_input_buffer()
    port.write(REQUEST)
    data = port.read(80)
    if len(data) != 80:
        raise OSError(f"sensors: expected 80 bytes, got {len(data)}")
    r = PACKET_100.unpack(data)
    state.update({
        "bump_right": bool(r[0] & 1), "bump_left": bool(r[0] & 2),
        "wheel_drop_right": bool(r[0] & 4), "wheel_drop_left": bool(r[0] & 8),
        "wall": r[1], "cliff_left": r[2], "cliff_front_left": r[3], "cliff_front_right": r[4],
        "cliff_right": r[5], "virtual_wall": r[6],
        "side_brush_overcurrent": bool(r[7] & 1), "main_brush_overcurrent": bool(r[7] & 4),
        "right_wheel_overcurrent": bool(r[7] & 8), "left_wheel_overcurrent": bool(r[7] & 16),
        "dirt_detect": r[8], "ir_omni": r[9],
        "button_clean": bool(r[10] & 1), "button_spot": bool(r[10] & 2), "button_dock": bool(r[10] & 4),
        "button_minute": bool(r[10] & 8), "button_hour": bool(r[10] & 16), "button_day": bool(r[10] & 32),
        "button_schedule": bool(r[10] & 64), "button_clock": bool(r[10] & 128),
        "distance": r[11], "angle": r[12], "charging_state": r[13], "voltage": r[14], "current": r[15],
        "temperature": r[16], "battery_charge": r[17], "battery_capacity": r[18], "wall_signal": r[19],
        "cliff_left_signal": r[20], "cliff_front_left_signal": r[21],
        "cliff_front_right_signal": r[22], "cliff_right_signal": r[23],
        "internal_charger": bool(r[24] & 1), "home_base": bool(r[24] & 2), "oi_mode": r[25],
        "song_number": r[26], "song_playing": r[27], "stream_packets": r[28],
        "velocity": r[29], "radius": r[30], "right_velocity": r[31], "left_velocity": r[32],
        "left_encoder": r[33], "right_encoder": r[34],
        "light_bumper_left": bool(r[35] & 1), "light_bumper_front_left": bool(r[35] & 2),
        "light_bumper_center_left": bool(r[35] & 4), "light_bumper_center_right": bool(r[35] & 8),
        "light_bumper_front_right": bool(r[35] & 16), "light_bumper_right": bool(r[35] & 32),
        "light_bump_left_signal": r[36], "light_bump_front_left_signal": r[37],
        "light_bump_center_left_signal": r[38], "light_bump_center_right_signal": r[39],
        "light_bump_front_right_signal": r[40], "light_bump_right_signal": r[41],
        "ir_left": r[42], "ir_right": r[43],
        "left_motor_current": r[44], "right_motor_current": r[45],
        "main_brush_current": r[46], "side_brush_current": r[47],
        "stasis_toggling": bool(r[48] & 1), "stasis_disabled": bool(r[48] & 2),
    })


def pycreate2_robot(port: AnsweringPort) -> Any:
    import pycreate2.create2api as api
    from pycreate2.createSerial import SerialCommandInterface

    api.time.sleep = lambda seconds: None  # type: ignore[attr-defined]  # its 15 ms wait, not the decoding
    bot = api.Create2.__new__(api.Create2)
    bot.SCI = SerialCommandInterface.__new__(SerialCommandInterface)
    bot.SCI.ser = port
    bot.decoder = None
    bot.song_list = {}
    api.Create2.__del__ = lambda self: None  # its destructor drives the robot
    return bot


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--calls", type=int, default=20000)
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        port, driver_port, runtime_port = AnsweringPort(), AnsweringPort(), AnsweringPort()
        state: dict[str, Any] = {}
        generated = import_driver(CREATE2, Path(tmp)).connect(driver_port, threads=False)
        runtime = load(CREATE2).connect(runtime_port, threads=False)
        ways: dict[str, tuple[Callable[[], Any], AnsweringPort | None]] = {
            "hand-written exchange": (lambda: sensors(port, state), port),
        }
        try:
            from pycreate2.packets import SensorPacketDecoder
        except ImportError:
            bot = None
        else:
            bot = pycreate2_robot(AnsweringPort())
            ways["pycreate2, bot.get_sensors()"] = (bot.get_sensors, bot.SCI.ser)
            ways["pycreate2, SensorPacketDecoder(data) alone"] = (lambda: SensorPacketDecoder(PACKET), None)
        ways["generated driver, robot.call_primitive('sensors')"] = (
            lambda: generated.call_primitive("sensors"), driver_port)
        ways["rdisc runtime, robot.call_primitive('sensors')"] = (lambda: runtime.call_primitive("sensors"), runtime_port)

        for name, (way, written) in ways.items():
            way()
            if written is not None and written.last != REQUEST:
                print(f"{name} wrote {written.last.hex(' ')}, not {REQUEST.hex(' ')}", file=sys.stderr)
                return 1
        for name, robot in (("generated driver", generated), ("runtime", runtime)):
            differ = {key: (value, robot.state[key]) for key, value in state.items() if robot.state[key] != value}
            if differ:
                print(f"the {name} decodes otherwise (baseline, rdisc): {differ}", file=sys.stderr)
                return 1

        best = {name: float("inf") for name in ways}
        for _ in range(args.repeat):
            for name, (way, _port) in ways.items():
                best[name] = min(best[name], timeit.timeit(way, number=args.calls) / args.calls)
        generated.close()
        runtime.close()
        if bot is not None:
            bot.SCI.ser.is_open = False  # pycreate2's destructor would print that it closes the port

    baseline = best["hand-written exchange"]
    print(f"Create 2 sensor packet 100 (80 bytes), one whole exchange, best of {args.repeat} x {args.calls} calls, "
          f"Python {sys.version.split()[0]}:")
    for name, seconds in best.items():
        ratio = seconds / baseline
        line = f"  {name:<52}{seconds * 1e6:8.2f} us  {ratio:5.2f}x hand-written"
        if name.startswith("generated"):
            line += f"  (target <= {BASELINE_TARGET}x)  {'PASS' if ratio <= BASELINE_TARGET else 'MISS'}"
            if bot is not None:
                ratio = seconds / best["pycreate2, bot.get_sensors()"]
                line += (f"   {ratio:5.2f}x pycreate2  (target <= {PYCREATE2_TARGET}x)  "
                         f"{'PASS' if ratio <= PYCREATE2_TARGET else 'MISS'}")
        print(line)
    if bot is None:
        print("  pycreate2 is not installed (pip install '.[test]'): no figure to compare with")
    print(f"  {len(state)} values decoded and stored per exchange; pycreate2 gives 49 fields (6 of them tuples of bits)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
