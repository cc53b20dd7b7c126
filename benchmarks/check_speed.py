"""How fast `rdisc check` is: figures to read, not a test that can fail.

    python benchmarks/check_speed.py            # the figures
    python benchmarks/check_speed.py --verbose  # and what the start-up imports cost

1. Cold start: the whole `rdisc check examples/create.rdis` process, median of
   --runs runs after one warm-up run (which leaves Lark's grammar cache in the
   temporary directory), beside a bare `python -c pass` and a process that only
   imports the CLI, measured in the same run. Targets: 150 ms, and 3x `python -c pass`.
2. Scale: a generated, valid description of --lines lines (primitives with
   `pack`/`unpack` and `format`/`regex`, interfaces, inputs, outputs, state),
   checked in-process with `rdisc.compile.compile_path` (target: under 1 s) and
   as a whole `rdisc check` process.

The `rdisc` used is the entry point installed beside this Python (the same
environment), or `python -m rdisc` when there is none. Every figure is printed
with PASS or MISS against its target; the exit code is 0 either way (1 only
when the generated description does not check, which is a bug in this script
or in rdisc).
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "examples" / "create.rdis"
# Processes run outside the checkout, so `python -c` and `-m` import this environment's
# rdisc, as the entry point does.
NEUTRAL = tempfile.gettempdir()

COLD_TARGET_MS = 150.0
COLD_TARGET_RATIO = 3.0
SCALE_TARGET_MS = 1000.0


def rdisc_command() -> list[str]:
    """The `rdisc` entry point of this environment, not whatever is first on PATH."""
    script = Path(sys.executable).parent / ("rdisc.exe" if os.name == "nt" else "rdisc")
    return [str(script)] if script.is_file() else [sys.executable, "-m", "rdisc"]


def run_ms(cmd: list[str], expect: int = 0) -> float:
    """Wall-clock time of one process, in milliseconds."""
    start = time.perf_counter()
    done = subprocess.run(cmd, check=False, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, cwd=NEUTRAL)
    elapsed = (time.perf_counter() - start) * 1000
    if done.returncode != expect:
        sys.exit(f"{' '.join(cmd)} exited {done.returncode}:\n{done.stderr.decode(errors='replace')}")
    return elapsed


def medians(commands: dict[str, list[str]], runs: int) -> dict[str, float]:
    """Median wall time of each command; the runs are interleaved so drift hits all alike."""
    for cmd in commands.values():  # warm-up: Lark's cache, the OS's file cache, .pyc files
        run_ms(cmd)
    times: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(runs):
        for name, cmd in commands.items():
            times[name].append(run_ms(cmd))
    return {name: statistics.median(t) for name, t in times.items()}


def verdict(ok: bool) -> str:
    return "PASS" if ok else "MISS"


# ---- 1. cold start -------------------------------------------------------------------


def cold_start(runs: int) -> None:
    rdisc = rdisc_command()
    commands = {
        "python -c pass": [sys.executable, "-c", "pass"],
        "import rdisc.cli.main": [sys.executable, "-c", "import rdisc.cli.main"],
        "rdisc check create.rdis": [*rdisc, "check", str(EXAMPLE)],
    }
    m = medians(commands, runs)
    bare, check = m["python -c pass"], m["rdisc check create.rdis"]
    ratio = check / bare
    print(f"1. cold start, whole process, median of {runs} runs (after one warm-up run)")
    print(f"   rdisc: {' '.join(rdisc)}")
    for name, ms in m.items():
        print(f"   {name:<26}{ms:8.1f} ms  {ms / bare:5.2f}x python -c pass")
    target = f"target: within {COLD_TARGET_MS:.0f} ms"
    print(f"   {target:<36}{verdict(check <= COLD_TARGET_MS)} ({check:.1f} ms)")
    target = f"target: within {COLD_TARGET_RATIO:.0f}x python -c pass"
    print(f"   {target:<36}{verdict(ratio <= COLD_TARGET_RATIO)} ({ratio:.2f}x)")
    phases()


PHASES = """
import sys, time
t0 = time.perf_counter()
import rdisc.cli.main
from rdisc.compile import compile_path
from rdisc.syntax.parse import parser
t1 = time.perf_counter()
import lark
t2 = time.perf_counter()
parser()
t3 = time.perf_counter()
compile_path(sys.argv[1])
t4 = time.perf_counter()
compile_path(sys.argv[1])
t5 = time.perf_counter()
print(*(round((b - a) * 1000, 1) for a, b in ((t0, t1), (t1, t2), (t2, t3), (t3, t4), (t4, t5))))
"""


def phases(runs: int = 5) -> None:
    """Where a cold check spends its time once the interpreter is up (medians of a few processes)."""
    cmd = [sys.executable, "-c", PHASES, str(EXAMPLE)]
    rows = [subprocess.run(cmd, check=True, capture_output=True, text=True, cwd=NEUTRAL).stdout.split()
            for _ in range(runs)]
    imports, lark, grammar, first, again = (statistics.median(float(r[i]) for r in rows) for i in range(5))
    print(f"   where it goes, in one process (median of {runs}): importing rdisc's CLI and pipeline"
          f" {imports:.1f} ms,")
    print(f"   importing lark {lark:.1f} ms, loading the grammar from Lark's cache {grammar:.1f} ms, checking"
          f" create.rdis")
    print(f"   (and the stdlib) {first:.1f} ms; a second check in the same process {again:.1f} ms")


def import_profile(top: int = 15) -> None:
    """`python -X importtime -m rdisc check create.rdis`, summarised."""
    cmd = [sys.executable, "-X", "importtime", "-m", "rdisc", "check", str(EXAMPLE)]
    err = subprocess.run(cmd, check=False, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                         cwd=NEUTRAL).stderr
    rows = []  # (self us, cumulative us, depth, module)
    for line in err.splitlines():
        if not line.startswith("import time:") or "[us]" in line:
            continue
        self_us, cumulative_us, name = line[len("import time:"):].split("|", 2)
        depth = (len(name) - len(name.lstrip(" "))) // 2
        rows.append((int(self_us), int(cumulative_us), depth, name.strip()))
    total = sum(r[0] for r in rows)
    print("\n   python -X importtime -m rdisc check examples/create.rdis")
    print(f"   all imports: {total / 1000:.1f} ms (one run, importtime's own overhead included)")
    print("   top-level imports by cumulative time:")
    for _, cumulative_us, _, name in sorted((r for r in rows if r[2] == 0), key=lambda r: -r[1])[:top]:
        print(f"     {cumulative_us / 1000:7.1f} ms  {name}")
    print("   modules by own time:")
    for self_us, _, _, name in sorted(rows, key=lambda r: -r[0])[:top]:
        print(f"     {self_us / 1000:7.1f} ms  {name}")


# ---- 2. scale ------------------------------------------------------------------------

HEADER = """\
# Generated by benchmarks/check_speed.py: a large, valid description.

robot generated {
    author "benchmarks/check_speed.py"
    description "many primitives, interfaces, inputs and outputs on one link"
}

connection link: serial {
    baud 115200
    threading single at 10 Hz
}
"""

GROUP = """
/// Last reading of device {i}, in counts.
state reading_{i}: int = 0
/// Metres per count of device {i}.
state scale_{i}: float = {scale}

/// Motor {i}: opcode, channel, speed (mm/s) and acceleration.
primitive set_motor_{i}(speed: int, accel: int) on link pack ">BBhH" (0x80, {channel}, speed, accel)

/// Sensor {i}: a big-endian signed 16-bit reply.
primitive read_sensor_{i}() on link pack "BB" (0x8E, {channel}) unpack ">h" {{
    reading_{i} = out[0]
}}

/// The same device over its ASCII protocol.
primitive query_{i}(a: int, b: int) on link format "M{i},{{}},{{}}\\n" (a, b) regex r"^m{i},(-?\\d+)\\s*$" {{
    reading_{i} = int(out[0]) + {offset}
}}

/// Drive device {i} in SI units and report its range.
interface motor_{i}(speed: float, accel: float) triggers range_{i} {{
    set_motor_{i}(clamp(round(speed * 1000), -500, 500), round(abs(accel) * 100)) delay {delay} ms
    read_sensor_{i}() priority 1
    query_{i}(round(speed), {channel})
}}

input velocity_{i}: DifferentialSpeed -> motor_{i}(
    linear * {gain} - 0.5,
    angular / 3.0 if angular != 0 else 0.0
)

output range_{i}: Range {{
    distance = reading_{i} * scale_{i} if reading_{i} >= 0 else 0.0
}}
"""


def generate(lines: int) -> str:
    """A valid description of exactly `lines` lines; the same text every time."""
    parts = [HEADER]
    count = HEADER.count("\n")
    i = 0
    while True:
        group = GROUP.format(i=i, channel=i % 250, scale=f"{0.001 * (1 + i % 7):.3f}",
                             offset=i % 5, delay=1 + i % 10, gain=f"{1.0 + (i % 9) / 4:.2f}")
        if count + group.count("\n") > lines:
            break
        parts.append(group)
        count += group.count("\n")
        i += 1
    parts.append("#\n" * (lines - count))
    return "".join(parts)


def scale(lines: int, runs: int, process_runs: int) -> None:
    try:  # the rdisc of this environment, as for the processes; else the checkout's
        from rdisc.compile import compile_path
    except ImportError:
        sys.path.insert(0, str(ROOT))
        from rdisc.compile import compile_path

    text = generate(lines)
    with tempfile.TemporaryDirectory(prefix="rdisc-bench-") as tmp:
        path = os.path.join(tmp, "generated.rdis")
        with open(path, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
        first = compile_path(path)  # also loads the grammar: not part of the figure
        if first.model is None or first.diagnostics.items:
            print(f"the generated description does not check cleanly: "
                  f"{len(first.diagnostics.items)} diagnostics", file=sys.stderr)
            for d in first.diagnostics.sorted()[:5]:
                print(f"  {d.code}: {d.message}", file=sys.stderr)
            sys.exit(1)
        times = []
        for _ in range(runs):
            start = time.perf_counter()
            compile_path(path)
            times.append((time.perf_counter() - start) * 1000)
        in_process = statistics.median(times)
        whole = medians({"check": [*rdisc_command(), "check", path]}, process_runs)["check"]

    m = first.model
    counts = ", ".join(f"{len(getattr(m, kind))} {kind}" for kind in
                       ("primitives", "interfaces", "inputs", "outputs", "states"))
    print(f"\n2. a generated description of {text.count(chr(10))} lines ({len(text) // 1024} KiB): {counts}")
    print(f"   compile_path, in-process, median of {runs} runs   {in_process:8.1f} ms"
          f"  ({in_process / lines * 1000:.1f} us per line)")
    print(f"   rdisc check, whole process, median of {process_runs} runs {whole:8.1f} ms")
    target = f"target: in-process under {SCALE_TARGET_MS:.0f} ms"
    print(f"   {target:<47}{verdict(in_process < SCALE_TARGET_MS)}"
          f" ({in_process / SCALE_TARGET_MS:.2f}x the target)")


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--runs", type=int, default=15,
                   help="processes per command for the cold start (default 15)")
    p.add_argument("--lines", type=int, default=10_000,
                   help="length of the generated description (default 10000)")
    p.add_argument("--verbose", action="store_true", help="also summarise python -X importtime")
    args = p.parse_args()
    print(f"Python {sys.version.split()[0]} on {sys.platform}, {os.cpu_count()} CPUs")
    if sys.dont_write_bytecode:  # as PYTHONDONTWRITEBYTECODE says: cold starts compile every module
        print("   no bytecode is cached here (PYTHONDONTWRITEBYTECODE): each start compiles rdisc's modules"
              " from source, as a user's installation does not")
    cold_start(args.runs)
    if args.verbose:
        import_profile()
    scale(args.lines, runs=5, process_runs=3)
    return 0


if __name__ == "__main__":
    sys.exit(main())
