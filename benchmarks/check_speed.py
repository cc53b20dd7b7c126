from __future__ import annotations

import argparse
import os
import resource
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
# Bytecode cached, as in a user's installation.
ENVIRONMENT = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}

COLD_TARGET_MS = 100.0
COLD_TARGET_RATIO = 3.0
SCALE_LARGEST = 100_000  # lines
SCALE_TARGET_S = 5.0  # CPU seconds for SCALE_LARGEST lines
SCALE_TARGET_RATIO = 12.0  # SCALE_LARGEST lines against 10,000
MAX_TOKENS = "100000000"


def rdisc_command() -> list[str]:
    """The `rdisc` entry point of this environment, not whatever is first on PATH."""
    script = Path(sys.executable).parent / ("rdisc.exe" if os.name == "nt" else "rdisc")
    return [str(script)] if script.is_file() else [sys.executable, "-m", "rdisc"]


def children_cpu() -> float:
    """CPU seconds (user and system) of the processes this one has waited for."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(cmd: list[str], expect: int = 0) -> tuple[float, float]:
    """Wall-clock and CPU time of one process, in milliseconds."""
    cpu, start = children_cpu(), time.perf_counter()
    done = subprocess.run(cmd, check=False, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, cwd=NEUTRAL, env=ENVIRONMENT)
    elapsed, used = (time.perf_counter() - start) * 1000, (children_cpu() - cpu) * 1000
    if done.returncode != expect:
        sys.exit(f"{' '.join(cmd)} exited {done.returncode}:\n{done.stderr.decode(errors='replace')}")
    return elapsed, used


def medians(commands: dict[str, list[str]], runs: int) -> dict[str, tuple[float, float]]:
    """Median wall and CPU time of each command; the runs are interleaved so drift hits all alike."""
    for cmd in commands.values():  # warm-up: Lark's cache, the OS's file cache, .pyc files
        run(cmd)
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in commands}
    for _ in range(runs):
        for name, cmd in commands.items():
            times[name].append(run(cmd))
    return {name: (statistics.median(w for w, _ in t), statistics.median(c for _, c in t))
            for name, t in times.items()}


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
    (bare, bare_cpu), (check, check_cpu) = m["python -c pass"], m["rdisc check create.rdis"]
    ratio = check / bare
    print(f"1. cold start, whole process, median of {runs} runs (after one warm-up run)")
    print(f"   rdisc: {' '.join(rdisc)}")
    for name, (ms, cpu) in m.items():
        print(f"   {name:<26}{ms:8.1f} ms  {ms / bare:5.2f}x python -c pass  ({cpu:.1f} ms CPU, "
              f"{cpu / bare_cpu:.2f}x its CPU)")
    target = f"target: within {COLD_TARGET_MS:.0f} ms"
    print(f"   {target:<36}{verdict(check <= COLD_TARGET_MS)} ({check:.1f} ms; {check_cpu:.1f} ms CPU)")
    target = f"target: within {COLD_TARGET_RATIO:.0f}x python -c pass"
    print(f"   {target:<36}{verdict(ratio <= COLD_TARGET_RATIO)} ({ratio:.2f}x; in CPU time, which a busy "
          f"machine stretches less: {check_cpu / bare_cpu:.2f}x)")
    phases()


PHASES = """
import sys, time
t0 = time.perf_counter()
import rdisc.cli.main
from rdisc.compile import compile_path
t1 = time.perf_counter()
import rdisc.syntax.reduce
t2 = time.perf_counter()
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
    rows = [subprocess.run(cmd, check=True, capture_output=True, text=True, cwd=NEUTRAL,
                           env=ENVIRONMENT).stdout.split() for _ in range(runs)]
    imports, tables, _, first, again = (statistics.median(float(r[i]) for r in rows) for i in range(5))
    print(f"   where it goes, in one process (median of {runs}): importing rdisc's CLI and pipeline"
          f" {imports:.1f} ms,")
    print(f"   importing the parser's tables (rdisc/syntax/tables.py, no Lark) {tables:.1f} ms, checking"
          f" create.rdis")
    print(f"   (and the stdlib) {first:.1f} ms; a second check in the same process {again:.1f} ms")


def import_profile(top: int = 15) -> None:
    """`python -X importtime -m rdisc check create.rdis`, summarised."""
    cmd = [sys.executable, "-X", "importtime", "-m", "rdisc", "check", str(EXAMPLE)]
    err = subprocess.run(cmd, check=False, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                         cwd=NEUTRAL, env=ENVIRONMENT).stderr
    rows = []  # (self us, cumulative us, depth, module)
    for line in err.splitlines():
        if not line.startswith("import time:") or "[us]" in line:
            continue
        own, cumulative, name = line[len("import time:"):].split("|", 2)
        depth = (len(name) - len(name.lstrip(" "))) // 2
        rows.append((int(own), int(cumulative), depth, name.strip()))
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


def scale(sizes: list[int], runs: int = 3) -> None:
    """Each size checked by whole `rdisc check --max-tokens ...` processes, `runs` of each, the
    sizes interleaved: the least CPU time of a size's runs, and the most. On a shared machine
    another's work only ever adds to a run's CPU time (the same check has measured 4.4 s and
    5.3 s one after the other), so the least is the figure the targets are read from."""
    print(f"\n2. generated descriptions, each checked by one `rdisc check --max-tokens 100000000` process, "
          f"the least CPU time of {runs} (and the most)")
    spent: dict[int, list[float]] = {lines: [] for lines in sizes}
    with tempfile.TemporaryDirectory(prefix="rdisc-bench-") as tmp:
        texts = {lines: generate(lines) for lines in sizes}
        paths = {lines: os.path.join(tmp, f"generated-{lines}.rdis") for lines in sizes}
        for lines, text in texts.items():
            with open(paths[lines], "w", encoding="utf-8", newline="\n") as f:
                f.write(text)
        for _ in range(runs):
            for lines in sizes:
                spent[lines].append(run([*rdisc_command(), "check", "--max-tokens", MAX_TOKENS, paths[lines]])[1] / 1000)
    cpu = {lines: min(times) for lines, times in spent.items()}
    for lines, text in texts.items():
        counts = {kind: text.count(f"\n{kind} ") for kind in ("primitive", "interface", "input", "output")}
        shown = ", ".join(f"{count} {kind}s" for kind, count in counts.items())
        print(f"   {lines:>7} lines ({len(text) // 1024:>5} KiB; {shown}): {cpu[lines]:6.2f} s CPU"
              f" (most {max(spent[lines]):.2f} s; {cpu[lines] / lines * 1e6:.0f} us a line)")
    if SCALE_LARGEST in cpu:
        largest = cpu[SCALE_LARGEST]
        target = f"target: {SCALE_LARGEST} lines within {SCALE_TARGET_S:.0f} s CPU"
        print(f"   {target:<47}{verdict(largest <= SCALE_TARGET_S)} ({largest:.2f} s)")
        if 10_000 in cpu:
            ratio = largest / cpu[10_000]
            target = f"target: {SCALE_LARGEST} lines within {SCALE_TARGET_RATIO:.0f}x 10000"
            print(f"   {target:<47}{verdict(ratio <= SCALE_TARGET_RATIO)} ({ratio:.2f}x; linear: "
                  f"{SCALE_LARGEST / 10_000:.0f}x)")


def main() -> int:
    p = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    p.add_argument("--runs", type=int, default=15,
                   help="processes per command for the cold start (default 15)")
    p.add_argument("--sizes", default="10000,50000,100000",
                   help="lengths of the generated descriptions, in lines (default 10000,50000,100000)")
    p.add_argument("--scale-runs", type=int, default=3,
                   help="processes per generated description; the least CPU time counts (default 3)")
    p.add_argument("--verbose", action="store_true", help="also summarise python -X importtime")
    args = p.parse_args()
    print(f"Python {sys.version.split()[0]} on {sys.platform}, {os.cpu_count()} CPUs")
    cold_start(args.runs)
    if args.verbose:
        import_profile()
    scale([int(size) for size in args.sizes.split(",")], args.scale_runs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
