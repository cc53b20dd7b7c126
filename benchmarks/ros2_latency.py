"""How long a Twist takes from a ROS 2 publisher to the robot's serial port, through the node
`rdisc emit-ros2` generates: figures to read, not a test (beside benchmarks/ros_latency.py's ROS 1
figure).

    python benchmarks/ros2_latency.py             # needs cyclonedds and rosbags (pip install '.[test]')
    python benchmarks/ros2_latency.py --messages 500

On loopback, in a domain of its own: the generated Create node drives an emulated Create on a
pseudo-terminal; the tests' independent participant (tests/ros2/participant.py) sends --messages
Twists, one every --interval seconds, and the latency of each is the time its drive command's bytes
reached the emulated device minus the time it was written (time.monotonic, one clock for every
process). The exit code is 0 either way.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc and its test devices

from tests.devices import CreateEmulator
from tests.ros2.loopback import LOOPBACK


def _stats(latencies: list[float]) -> tuple[float, float]:
    ordered = sorted(latencies)
    return statistics.median(ordered) * 1000, ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))] * 1000


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--messages", type=int, default=300)
    parser.add_argument("--interval", type=float, default=0.01)
    args = parser.parse_args()
    if importlib.util.find_spec("cyclonedds") is None or importlib.util.find_spec("rosbags") is None:
        print("cyclonedds or rosbags is not installed (pip install '.[test]'): nothing to measure")
        return 0
    env = dict(os.environ, ROS_DOMAIN_ID="150", CYCLONEDDS_URI=LOOPBACK)
    with tempfile.TemporaryDirectory() as tmp:
        source = Path(tmp) / "create.rdis"  # the Create with its delays made 0, as ros_latency.py does
        source.write_text(re.sub(r"delay\s+[0-9.]+\s*(ms|s)\b", "delay 0 ms",
                                 (ROOT / "examples" / "create.rdis").read_text()))
        node_file = Path(tmp) / "irobot_create_node.py"
        subprocess.run([sys.executable, "-m", "rdisc", "emit-ros2", str(source), "-o", str(node_file)],
                       check=True, cwd=ROOT)
        with CreateEmulator() as device:
            node = subprocess.Popen([sys.executable, str(node_file), "--ros-args", "-p", f"port:={device.port}"],
                                    env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            sender = subprocess.Popen([sys.executable, str(ROOT / "tests" / "ros2" / "participant.py"), "jazzy",
                                       "irobot_create"], env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                      text=True)
            assert sender.stdin is not None and sender.stdout is not None
            try:
                while "matched" not in (event := json.loads(sender.stdout.readline())):
                    assert "unmatched" not in event, "the node did not subscribe"
                sent = []
                for i in range(args.messages):
                    sender.stdin.write(f"{0.1 if i % 2 else 0.2} 0.0\n")
                    sender.stdin.flush()
                    while "sent" not in (event := json.loads(sender.stdout.readline())):
                        pass
                    sent.append(float(event["sent"]))
                    time.sleep(args.interval)
                drives = device.wait_for_commands(args.messages, timeout=30, opcode=137)
            finally:
                sender.stdin.close()
                sender.wait(timeout=30)
                node.send_signal(signal.SIGINT)
                node.wait(timeout=30)
        bridge = [t - s for s, (t, _cmd) in zip(sent, drives[: args.messages])]
    median, p99 = _stats(bridge)
    print(f"Twist to serial bytes, {args.messages} messages every {args.interval * 1000:g} ms, Cyclone DDS on loopback")
    print(f"  participant -> rdisc ROS 2 node -> device bytes  median {median:6.2f} ms   p99 {p99:6.2f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
