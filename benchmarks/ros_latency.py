"""How long a Twist takes from a ROS publisher to the robot's serial port, through the
node `rdisc emit-ros` generates: figures to read, not a test.

    python benchmarks/ros_latency.py             # needs Debian's ROS 1 (see .ci/run)
    python benchmarks/ros_latency.py --messages 500

On one roscore (a free loopback port): the generated Create node drives an emulated
Create on a pseudo-terminal; a publisher sends --messages Twists, one every
--interval seconds, and the latency of each is the time its drive command's bytes
reached the emulated device minus the time it was published (time.monotonic, one
clock for every process). The floor is the same publisher to a bare rospy
subscriber on the same roscore. Target: the bridge adds under 1 ms at the median.
The exit code is 0 either way.
"""

from __future__ import annotations

import argparse
import os
import re
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc and its test devices

from tests.devices import CreateEmulator

PYTHON3 = "/usr/bin/python3"
HELPERS = ROOT / "tests" / "ros"
TARGET_MS = 1.0


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _publish(env: dict[str, str], count: int, interval: float) -> list[float]:
    """Publish `count` Twists (alternating speeds, so that each is a new command); their times."""
    publisher = subprocess.Popen([PYTHON3, str(HELPERS / "twists.py")], env=env, stdin=subprocess.PIPE,
                                 stdout=subprocess.PIPE, text=True)
    assert publisher.stdin is not None and publisher.stdout is not None
    try:
        assert publisher.stdout.readline().strip() == "ready"
        sent = []
        for i in range(count):
            publisher.stdin.write(f"{0.1 if i % 2 else 0.2} 0.0\n")
            publisher.stdin.flush()
            sent.append(float(publisher.stdout.readline().split()[1]))
            time.sleep(interval)
        return sent
    finally:
        publisher.stdin.close()
        publisher.wait(timeout=10)


def _stats(latencies: list[float]) -> tuple[float, float]:
    ordered = sorted(latencies)
    return statistics.median(ordered) * 1000, ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))] * 1000


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--messages", type=int, default=300)
    parser.add_argument("--interval", type=float, default=0.01)
    args = parser.parse_args()
    if not Path(PYTHON3).exists() or subprocess.run(["which", "roscore"], capture_output=True, check=False).returncode:
        print("ROS 1 is not installed (apt-get install ros-core python3-rospy ...): nothing to measure")
        return 0
    port = _free_port()
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_HOSTNAME="127.0.0.1",
                   ROS_LOG_DIR=tmp, PYTHONPATH="")
        core = subprocess.Popen(["roscore", "-p", str(port)], env=env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, start_new_session=True)
        try:
            while subprocess.run(["rosparam", "list"], env=env, capture_output=True, check=False).returncode:
                time.sleep(0.2)
            # the floor: a bare rospy subscriber
            listener = subprocess.Popen([PYTHON3, str(HELPERS / "twist_listener.py")], env=env,
                                        stdout=subprocess.PIPE, text=True)
            assert listener.stdout is not None and listener.stdout.readline().strip() == "ready"
            sent = _publish(env, args.messages, args.interval)
            time.sleep(0.5)
            listener.send_signal(signal.SIGINT)
            got = [float(line.split()[1]) for line in listener.communicate(timeout=15)[0].splitlines()
                   if line.startswith("got ")]
            floor = [g - s for s, g in zip(sent, got)]
            # the bridge: publisher -> generated node -> emulated Create
            source = Path(tmp) / "create.rdis"  # the Create with its delays made 0, as driver_speed.py does
            source.write_text(re.sub(r"delay\s+[0-9.]+\s*(ms|s)\b", "delay 0 ms",
                                     (ROOT / "examples" / "create.rdis").read_text()))
            node_file = Path(tmp) / "irobot_create_node.py"
            subprocess.run([sys.executable, "-m", "rdisc", "emit-ros", str(source), "-o", str(node_file)],
                           check=True, cwd=ROOT)
            with CreateEmulator() as device:
                node = subprocess.Popen([PYTHON3, str(node_file), f"_port:={device.port}"], env=env,
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                try:
                    device.wait_for_commands(1, timeout=30, opcode=132)
                    sent = _publish(env, args.messages, args.interval)
                    drives = device.wait_for_commands(args.messages, timeout=30, opcode=137)
                finally:
                    node.send_signal(signal.SIGINT)
                    node.wait(timeout=30)
            bridge = [t - s for s, (t, _cmd) in zip(sent, drives[: args.messages])]
        finally:
            os.killpg(core.pid, signal.SIGINT)
            core.wait(timeout=30)
    floor_median, floor_p99 = _stats(floor)
    median, p99 = _stats(bridge)
    added = median - floor_median
    print(f"Twist to serial bytes, {args.messages} messages every {args.interval * 1000:g} ms, one roscore")
    print(f"  bare rospy publisher -> subscriber      median {floor_median:6.2f} ms   p99 {floor_p99:6.2f} ms")
    print(f"  publisher -> rdisc node -> device bytes  median {median:6.2f} ms   p99 {p99:6.2f} ms")
    print(f"  the bridge adds {added:.2f} ms at the median (target < {TARGET_MS:g} ms)  "
          f"{'PASS' if added < TARGET_MS else 'MISS'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
