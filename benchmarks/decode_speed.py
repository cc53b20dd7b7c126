"""How fast the Create 2's sensor packet 100 (80 bytes) is read and decoded: figures
to read, not a test.

    python benchmarks/decode_speed.py            # needs pycreate2: pip install '.[test]'

One "read every sensor" exchange, against a port object that answers the 80-byte
packet at once, in this process and this run:

- baseline: pycreate2's own `Create2.get_sensors()` (its 15 ms wait made 0), which
  writes `142 100`, reads 80 bytes and decodes them with `SensorPacketDecoder`
  into named tuples;
- the driver `rdisc emit-python` generates from examples/create2.rdis:
  `robot.call_primitive("sensors")`, which writes, reads, unpacks the packet and
  stores its 69 values in the robot's state (target: at least as fast as pycreate2);
- the rdisc runtime interpreting the same description (for reference).

pycreate2's decoder alone (no port) is printed too. Each figure is the best of
--repeat runs of --calls calls, the ways interleaved. The exit code is 0 either way.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import timeit
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc, when it is not installed

from rdisc.emit.python import import_driver
from rdisc.runtime import load

CREATE2 = ROOT / "examples" / "create2.rdis"
# A plausible packet 100: bumps, a wall, cliffs, distances, battery figures, encoders.
PACKET = bytes(range(1, 81))
TARGET = 1.0  # the generated driver's time over pycreate2's


class AnsweringPort:
    """Takes every write; each read returns the packet (or its next `size` bytes)."""

    is_open, port, baudrate = True, "memory", 115200  # what pycreate2 asks of a port

    def __init__(self) -> None:
        self.written = 0

    def write(self, data: bytes) -> int:
        self.written += len(data)
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


def generated_driver(folder: Path) -> Any:
    return import_driver(CREATE2, folder)


def pycreate2_robot() -> Any:
    import pycreate2.create2api as api
    from pycreate2.createSerial import SerialCommandInterface

    api.time.sleep = lambda seconds: None  # type: ignore[attr-defined]  # its 15 ms wait, not the decoding
    bot = api.Create2.__new__(api.Create2)
    bot.SCI = SerialCommandInterface.__new__(SerialCommandInterface)
    bot.SCI.ser = AnsweringPort()
    bot.decoder = None
    bot.song_list = {}
    api.Create2.__del__ = lambda self: None  # its destructor drives the robot
    return bot


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--calls", type=int, default=20000)
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    try:
        from pycreate2.packets import SensorPacketDecoder
    except ImportError:
        print("pycreate2 is not installed (pip install '.[test]'): nothing to compare with")
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        driver = generated_driver(Path(tmp))
        generated = driver.connect(AnsweringPort(), threads=False)
        runtime = load(CREATE2).connect(AnsweringPort(), threads=False)
        bot = pycreate2_robot()
        ways = {
            "pycreate2, bot.get_sensors()": bot.get_sensors,
            "pycreate2, SensorPacketDecoder(data) alone": lambda: SensorPacketDecoder(PACKET),
            "generated driver, robot.call_primitive('sensors')": lambda: generated.call_primitive("sensors"),
            "rdisc runtime, robot.call_primitive('sensors')": lambda: runtime.call_primitive("sensors"),
        }
        best = {name: float("inf") for name in ways}
        for _ in range(args.repeat):
            for name, way in ways.items():
                best[name] = min(best[name], timeit.timeit(way, number=args.calls) / args.calls)
        state = generated.state
        assert state == runtime.state, "the driver and the runtime decode the packet differently"
        generated.close()
        runtime.close()
        bot.SCI.ser.is_open = False  # pycreate2's destructor would print that it closes the port
    baseline = best["pycreate2, bot.get_sensors()"]
    print(f"Create 2 sensor packet 100 (80 bytes), best of {args.repeat} x {args.calls} calls")
    for name, seconds in best.items():
        ratio = seconds / baseline
        line = f"  {name:<52}{seconds * 1e6:8.2f} us  {ratio:5.2f}x pycreate2"
        if name.startswith("generated"):
            line += f"  (target <= {TARGET:.1f}x)  {'PASS' if ratio <= TARGET else 'MISS'}"
        print(line)
    print(f"  {len(state)} state values decoded per read by rdisc; pycreate2 gives 49 fields (6 of them tuples of bits)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
