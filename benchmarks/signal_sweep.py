"""A signal at every step of `rdisc run`'s start-up: what CI's busy machines hit once in hundreds
of runs, made deterministic. Figures to read, not a test (a whole sweep takes minutes).

    python benchmarks/signal_sweep.py                   # every 97th place of the start-up
    python benchmarks/signal_sweep.py --step 1 --first 1000 --last 1400
    python benchmarks/signal_sweep.py --moment call     # from a --call of three commands
    python benchmarks/signal_sweep.py --driver          # the generated driver's main(), not rdisc run
    python benchmarks/signal_sweep.py --ros2            # the ROS 2 node rdisc emit-ros2 writes

Each run is `rdisc run tests/runtime/data/fast_create.rdis --watch` (or `--call dance`, an
interface of three commands with delays) against an emulated Create on a pseudo-terminal, in a
process of its own that traces its main thread (with --driver: the driver `rdisc emit-python`
writes of the description, run as `python driver.py`, whose engine is the same text, carried): at the N-th place (counted from `Robot.open`'s
call, or the call's) where the interpreter would run a signal's handler (after a call, at a
function's start, at a loop's turn) and SIGINT is not blocked, the engine's handler is called,
as the interpreter calls it when a SIGINT has landed just before,
and four real SIGINTs follow 2 ms apart. The run must end with 130 (or as it would have, when
the signal came after its shutdown began, which ignores it), print no traceback and no
internal error, and leave the stop command as the last command the device got (if the port was
opened). A run still going after 8 s writes its threads' stacks and is a hang. A step beyond the
start-up's end sends no signal: the sweep ends there (or at --last). The exit code is 1 when a
run failed.

Found this way, and fixed (tests/runtime/test_signals.py, tests/engine/test_flag.py): a signal
handled in importlib's weakref callback, whose exception Python dropped; threading.Event's
Condition code left locked or released twice by the exception (closing then hung); a port's lock
left held, on which closing joined the connection's thread for ever; the shutdown marked by a
call from a `finally`, at whose start a signal escaped before the robot was closed.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc and its test devices
DESCRIPTION = ROOT / "tests" / "runtime" / "data" / "fast_create.rdis"

CHILD = '''
import faulthandler, os, signal, sys, threading, time
faulthandler.dump_traceback_later(8, exit=True)
import rdisc.start  # holds the signals back, as the command's entry does
from tests.support.interrupts import check_points
step, port, description, start, kind, driver, extra = (int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4],
                                                       sys.argv[5], sys.argv[6], sys.argv[7:])
if driver:  # the generated driver or ROS 2 node: its own copy of the engine's signals, and its entry
    import importlib.util
    spec = importlib.util.spec_from_file_location("driver", driver)
    signals = sys.modules["driver"] = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(signals)
    if kind == "ros2":  # as `python node.py --ros-args -p port:=...` runs it
        sys.argv = [driver, "--ros-args", "-p", f"port:={port}"]
        entry = lambda: signals.command_line(signals.ros_main)
    else:
        sys.argv = [driver, "--port", port, *extra]
        entry = signals.main
    inside = driver
else:
    from rdisc.engine import signals
    sys.argv = ["rdisc", "run", description, "--port", port, *extra]
    entry, inside = rdisc.start.main, "rdisc"
counting, count, sent = [False], [0], [False]

def burst():
    for _ in range(4):
        time.sleep(0.002)
        os.kill(os.getpid(), signal.SIGINT)

def tracer(frame, event, arg):
    if event == "call" and frame.f_code.co_name == start and inside in frame.f_code.co_filename:
        counting[0] = True
    frame.f_trace_opcodes = True
    if counting[0] and event == "opcode" and frame.f_lasti in check_points(frame.f_code):
        count[0] += 1
        if (count[0] >= step and not sent[0] and signal.getsignal(signal.SIGINT) is signals._on_signal
                and signal.SIGINT not in signal.pthread_sigmask(signal.SIG_BLOCK, [])):
            sent[0] = True
            where = f"{frame.f_code.co_name} ({os.path.basename(frame.f_code.co_filename)}:{frame.f_lineno})"
            late = " (late: the shutdown began)" if signals._shutting_down[0] else ""
            print(f"sweep: signalled in {where}{late}", file=sys.stderr, flush=True)
            threading.Thread(target=burst, daemon=True).start()
            signals._on_signal(signal.SIGINT, None)
    return tracer

sys.settrace(tracer)
status = entry()
sys.settrace(None)
sys.exit(status)
'''


# What each sweep runs: the description's text, the function whose call starts the count, and
# `rdisc run`'s options besides the description and port.
DANCE = """
interface dance() {
    drive(100, 0) delay 20 ms
    drive(200, 0) delay 20 ms
    drive(300, 0)
}
"""
MOMENTS = {
    "start-up": ("", "open", ["--watch"]),  # the port opened, the start-up hook, the thread started
    "call": (DANCE, "make_call", ["--call", "dance"]),  # a call of three commands with delays
}


def run_once(step: int, moment: str, folder: Path, kind: str) -> tuple[str, str]:
    """One run with the signal at `step`: ("ok" | "no signal" | a failure's reason, stderr).
    `kind`: what runs, `rdisc run` ("rdisc"), the description's generated driver ("driver") or
    its ROS 2 node ("ros2", which runs until the signal, as `rdisc run --watch` does)."""
    from tests.devices import CreateEmulator
    from tests.devices.create import STOP

    added, start, extra = MOMENTS[moment]
    description = folder / f"{moment}.rdis"
    source = folder / f"{moment}_{kind}.py"
    if kind != "rdisc" and not source.exists():  # the sweep's first run: the description and its program
        description.write_text(DESCRIPTION.read_text(encoding="utf-8") + added, encoding="utf-8")
        emit = "emit-ros2" if kind == "ros2" else "emit-python"
        subprocess.run([sys.executable, "-m", "rdisc", emit, str(description), "-o", str(source)], check=True, cwd=ROOT)
    elif not description.exists():
        description.write_text(DESCRIPTION.read_text(encoding="utf-8") + added, encoding="utf-8")
    with CreateEmulator() as device:
        done = subprocess.run([sys.executable, "-c", CHILD, str(step), device.port, str(description), start, kind,
                               str(source) if kind != "rdisc" else "", *extra],
                              capture_output=True, text=True, timeout=60, check=False, cwd=ROOT,
                              env=dict(os.environ, NO_COLOR="1"))
        commands = [command for _, command in device.commands]
    stderr = done.stderr
    if "sweep: signalled" not in stderr:
        return "no signal", stderr
    if "Timeout (0:00:08)!" in stderr:
        return "hang", stderr
    if done.returncode != 130 and not (done.returncode == 0 and "(late: " in stderr):  # a late one is ignored
        return f"exit {done.returncode}", stderr
    if "Traceback" in stderr or "internal error" in stderr:
        return "printed a traceback", stderr
    if commands and commands[-1] != STOP:
        return f"last command {commands[-1].hex(' ')}, not the stop", stderr
    return "ok", stderr


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--first", type=int, default=1, help="the first step (default 1)")
    parser.add_argument("--last", type=int, default=None,
                        help="the last step (default: until a step is past the start-up's end)")
    parser.add_argument("--step", type=int, default=97, help="steps between runs (default 97)")
    parser.add_argument("--moment", choices=MOMENTS, default="start-up",
                        help="start-up (default): from Robot.open; call: from a --call of three commands")
    runs = parser.add_mutually_exclusive_group()
    runs.add_argument("--driver", action="store_true",
                      help="run the generated driver's main() (python driver.py), not rdisc run")
    runs.add_argument("--ros2", action="store_true",
                      help="run the ROS 2 node `rdisc emit-ros2` writes (over Cyclone DDS; start-up only)")
    args = parser.parse_args()
    if args.ros2 and args.moment != "start-up":
        parser.error("--ros2 sweeps the start-up only: a node takes no --call")
    kind = "ros2" if args.ros2 else "driver" if args.driver else "rdisc"
    folder = Path(tempfile.mkdtemp())
    tally: dict[str, int] = {}
    failed = False
    step = args.first
    while args.last is None or step <= args.last:
        outcome, stderr = run_once(step, args.moment, folder, kind)
        tally[outcome] = tally.get(outcome, 0) + 1
        step += args.step
        if outcome == "no signal" and args.last is None:
            break
        if outcome not in ("ok", "no signal"):
            failed = True
            print(f"step {step}: {outcome}\n{stderr[-3000:]}", flush=True)
    print(", ".join(f"{outcome}: {count}" for outcome, count in sorted(tally.items())))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
