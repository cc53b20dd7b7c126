"""A signal at every step of `rdisc run`'s start-up: what CI's busy machines hit once in hundreds
of runs, made deterministic. Figures to read, not a test (a whole sweep takes minutes).

    python benchmarks/signal_sweep.py                   # every 97th step of the start-up
    python benchmarks/signal_sweep.py --step 3 --first 20000 --last 22000

Each run is `rdisc run tests/runtime/data/fast_create.rdis --watch` against an emulated Create on
a pseudo-terminal, in a process of its own that traces its main thread: at the first bytecode
step at or after N (counted from `Robot.open`'s call) where SIGINT is not blocked, the engine's
signal handler is called there, as the interpreter calls it when a SIGINT lands at that step,
and four real SIGINTs follow 2 ms apart. The run must end with 130, print no traceback and no
internal error, and leave the stop command as the last command the device got (if the port was
opened). A run still going after 8 s writes its threads' stacks and is a hang. A step beyond the
start-up's end sends no signal: the sweep ends there (or at --last). The exit code is 1 when a
run failed.

Found this way, and fixed (tests/runtime/test_signals.py, tests/engine/test_flag.py): a signal
handled in importlib's weakref callback, whose exception Python dropped; threading.Event's
Condition code left locked or released twice by the exception (closing then hung); a port's lock
left held, on which closing joined the connection's thread for ever.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's rdisc and its test devices
DESCRIPTION = ROOT / "tests" / "runtime" / "data" / "fast_create.rdis"

CHILD = '''
import faulthandler, os, signal, sys, threading, time
faulthandler.dump_traceback_later(8, exit=True)
import rdisc.start  # holds the signals back, as the command's entry does
from rdisc.engine import signals
step, port, description = int(sys.argv[1]), sys.argv[2], sys.argv[3]
counting, count, sent = [False], [0], [False]

def burst():
    for _ in range(4):
        time.sleep(0.002)
        os.kill(os.getpid(), signal.SIGINT)

def tracer(frame, event, arg):
    if event == "call" and frame.f_code.co_name == "open" and frame.f_code.co_filename.endswith("robot.py"):
        counting[0] = True
    frame.f_trace_opcodes = True
    if counting[0] and event in ("opcode", "line"):
        count[0] += 1
        if (count[0] >= step and not sent[0]
                and signal.SIGINT not in signal.pthread_sigmask(signal.SIG_BLOCK, [])):
            sent[0] = True
            print("sweep: signalled", file=sys.stderr, flush=True)
            threading.Thread(target=burst, daemon=True).start()
            signals._on_signal(signal.SIGINT, None)
    return tracer

sys.argv = ["rdisc", "run", description, "--watch", "--port", port]
sys.settrace(tracer)
status = rdisc.start.main()
sys.settrace(None)
sys.exit(status)
'''


def run_once(step: int) -> tuple[str, str]:
    """One run with the signal at `step`: ("ok" | "no signal" | a failure's reason, stderr)."""
    from tests.devices import CreateEmulator
    from tests.devices.create import STOP

    with CreateEmulator() as device:
        done = subprocess.run([sys.executable, "-c", CHILD, str(step), device.port, str(DESCRIPTION)],
                              capture_output=True, text=True, timeout=60, check=False, cwd=ROOT,
                              env=dict(os.environ, NO_COLOR="1"))
        commands = [command for _, command in device.commands]
    stderr = done.stderr
    if "sweep: signalled" not in stderr:
        return "no signal", stderr
    if "Timeout (0:00:08)!" in stderr:
        return "hang", stderr
    if done.returncode != 130:
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
    args = parser.parse_args()
    tally: dict[str, int] = {}
    failed = False
    step = args.first
    while args.last is None or step <= args.last:
        outcome, stderr = run_once(step)
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
