"""Mutation fuzzing of the whole pipeline: figures to read, not a test.

    python benchmarks/fuzz.py                        # 2,000 mutants, seed 1
    python benchmarks/fuzz.py --count 20000 --seed 7 --jobs 2
    python benchmarks/fuzz.py --seed 7 --keep /tmp/found   # and each reproducer whole, as a file
    python benchmarks/fuzz.py --surface console --count 20000   # or replay, or sim

`--surface` other than `pipeline` (the default) fuzzes what is not a description's text
(tests/properties/surfaces.py): the console's messages through `Console.call`, recordings
through what `rdisc replay` does, bodies through check, MJCF, MuJoCo and a few timesteps of
the robot's schedule. Each case is made in the worker from (seed, index), so a finding is
reproduced from its numbers.

Mutants of the examples and test descriptions (tests/properties/mutants.py) go
through check, the rendered diagnostics, canonical JSON and back, dump, the Python
driver, the ROS node and the runtime's plans, in worker processes whose address
space is limited (so that a mutant needing more than --memory MB fails there with
MemoryError) and whose every mutant has an alarm (--alarm seconds). Printed: how
many were tried, and the counts of tracebacks (grouped by the place in rdisc they
came from, each with the smallest reproducer found), of mutants over 5 s of CPU, and
of mutants over the memory limit. The exit code is 1 when any of the three is not zero.
"""

from __future__ import annotations

import argparse
import multiprocessing
import resource
import signal
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests" / "properties"))
sys.path.insert(0, str(ROOT / "tests" / "support"))

import surfaces
from mutants import Mutant, finding, mutants, run_pipeline

SLOW = 5.0  # seconds of CPU for one mutant


class _Alarm(Exception):
    pass


def _on_alarm(signum: int, frame: object) -> None:
    raise _Alarm


def _init(memory_mb: int) -> None:
    limit = memory_mb * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    signal.signal(signal.SIGALRM, _on_alarm)
    signal.signal(signal.SIGPROF, _on_alarm)


def _try(job: tuple[int, Mutant, int]) -> tuple[int, str | None, float]:
    """(index, what went wrong or None, CPU seconds)."""
    index, mutant, alarm = job
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / f"mutant{mutant.suffix}"
        path.write_text(mutant.text, encoding="utf-8", errors="surrogatepass")
        start = time.process_time()
        signal.alarm(alarm)
        try:
            run_pipeline(path)
            outcome = None
        except _Alarm:
            outcome = "slow"
        except MemoryError:
            outcome = "memory"
        except Exception as err:  # noqa: BLE001 - every one is a finding
            outcome = finding(err)
        finally:
            signal.alarm(0)
        return index, outcome, time.process_time() - start


def _try_surface(job: tuple[str, int, int, int]) -> tuple[int, str | None, float, float, int]:
    """(index, what went wrong or None, CPU seconds, wall seconds, the worker's peak RSS in KiB so far)."""
    surface, seed, index, alarm = job
    with tempfile.TemporaryDirectory() as folder:
        start, began = time.process_time(), time.monotonic()
        signal.setitimer(signal.ITIMER_PROF, alarm)  # of CPU time: a loaded machine's waits are no hang
        try:
            try:
                surfaces.run(surface, surfaces.case(surface, seed, index), Path(folder))
                outcome = None
            finally:
                signal.setitimer(signal.ITIMER_PROF, 0)
        except _Alarm:  # in the case, or as it ended
            outcome = "slow"
        except MemoryError:
            outcome = "memory"
        except Exception as err:  # noqa: BLE001 - every one is a finding
            outcome = finding(err)
        return (index, outcome, time.process_time() - start, time.monotonic() - began,
                resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)


def _surface(args: argparse.Namespace) -> int:
    """A run of `--surface console|replay|sim`; its figures printed."""
    groups: dict[str, list[int]] = defaultdict(list)
    slow, memory, slowest, longest, peak = [], [], (0.0, -1), (0.0, -1), 0
    started = time.monotonic()
    with multiprocessing.Pool(args.jobs, _init, (args.memory + 512,), maxtasksperchild=500) as pool:
        jobs = [(args.surface, args.seed, i, args.alarm) for i in range(args.count)]
        for done, (index, outcome, cpu, wall, rss) in enumerate(pool.imap_unordered(_try_surface, jobs, chunksize=8)):
            slowest, longest, peak = max(slowest, (cpu, index)), max(longest, (wall, index)), max(peak, rss)
            if outcome == "slow" or cpu > SLOW:
                slow.append(index)
            elif outcome == "memory":
                memory.append(index)
            elif outcome is not None:
                groups[outcome].append(index)
            if args.progress and (done + 1) % args.progress == 0:
                print(f"... {done + 1} cases, {sum(map(len, groups.values()))} tracebacks, {len(slow)} slow, "
                      f"{len(memory)} over memory, {time.monotonic() - started:.0f} s; worst {slowest[0]:.2f} s "
                      f"of CPU, {longest[0]:.2f} s on the clock, peak {peak / 1024:.0f} MB", flush=True)
    took = time.monotonic() - started
    print(f"surface {args.surface}: cases tried: {args.count} (seed {args.seed}), {took:.0f} s with {args.jobs} workers")
    print(f"tracebacks: {sum(len(v) for v in groups.values())} at {len(groups)} places in rdisc")
    print(f"over {SLOW:g} s of CPU or {args.alarm} s: {len(slow)}; over {args.memory} MB: {len(memory)}")
    print(f"worst time: {slowest[0]:.2f} s of CPU (case {slowest[1]}), {longest[0]:.2f} s on the clock "
          f"(case {longest[1]})")
    print(f"peak memory: {peak / 1024:.0f} MB resident in a worker (limit {args.memory} MB of heap)")
    for place, indexes in sorted(groups.items(), key=lambda kv: -len(kv[1])):
        smallest = min(indexes, key=lambda i: surfaces.size(surfaces.case(args.surface, args.seed, i)))
        made = surfaces.case(args.surface, args.seed, smallest)
        print(f"\n{place}: {len(indexes)} cases; the smallest, case {smallest}: {surfaces.shown(args.surface, made)}")
        if args.keep is not None:
            args.keep.mkdir(parents=True, exist_ok=True)
            kept = args.keep / f"{args.surface}{smallest}"
            what = made[1]
            kept.write_bytes(what if isinstance(what, bytes) else what.encode("utf-8", "surrogatepass"))
            print(f"(whole in {kept})")
    for label, indexes in (("slow", slow), ("over the memory limit", memory)):
        for i in indexes[:3]:
            print(f"\n{label}: case {i}: {surfaces.shown(args.surface, surfaces.case(args.surface, args.seed, i))}")
    return 1 if groups or slow or memory else 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--memory", type=int, default=1024, help="MB of address space a worker may use")
    parser.add_argument("--alarm", type=int, default=30, help="seconds before a mutant is given up (of CPU, for --surface)")
    parser.add_argument("--keep", type=Path, help="a folder to write each place's smallest reproducer to, whole "
                        "(the report shows its first 2,000 characters)")
    parser.add_argument("--surface", choices=("pipeline", *surfaces.SURFACES), default="pipeline",
                        help="what is fuzzed: descriptions through the pipeline (default), the console's "
                        "messages, recordings through replay, or bodies through the simulation")
    parser.add_argument("--progress", type=int, default=0, metavar="N", help="a line of figures every N cases")
    args = parser.parse_args()
    if args.surface != "pipeline":
        return _surface(args)
    tried = mutants(args.seed, args.count)
    groups: dict[str, list[int]] = defaultdict(list)
    slow, memory, slowest = [], [], (0.0, -1)
    started = time.monotonic()
    with multiprocessing.Pool(args.jobs, _init, (args.memory + 512,), maxtasksperchild=200) as pool:
        jobs = [(i, m, args.alarm) for i, m in enumerate(tried)]
        for index, outcome, cpu in pool.imap_unordered(_try, jobs, chunksize=8):
            slowest = max(slowest, (cpu, index))
            if outcome == "slow" or cpu > SLOW:
                slow.append(index)
            elif outcome == "memory":
                memory.append(index)
            elif outcome is not None:
                groups[outcome].append(index)
    took = time.monotonic() - started
    print(f"mutants tried: {len(tried)} (seed {args.seed}; {sum(m.suffix == '.json' for m in tried)} JSON), "
          f"{took:.0f} s with {args.jobs} workers")
    print(f"tracebacks: {sum(len(v) for v in groups.values())} at {len(groups)} places in rdisc")
    print(f"over {SLOW:g} s of CPU: {len(slow)}; over {args.memory} MB: {len(memory)}")
    print(f"slowest: {slowest[0]:.2f} s of CPU (mutant {slowest[1]} of {tried[slowest[1]].seed})")
    for place, indexes in sorted(groups.items(), key=lambda kv: -len(kv[1])):
        smallest = min(indexes, key=lambda i: len(tried[i].text))
        print(f"\n{place}: {len(indexes)} mutants; the smallest ({tried[smallest].seed}, "
              f"{tried[smallest].suffix}):")
        print(tried[smallest].text[:2000])
        if args.keep is not None:
            args.keep.mkdir(parents=True, exist_ok=True)
            kept = args.keep / f"mutant{smallest}{tried[smallest].suffix}"
            kept.write_text(tried[smallest].text, encoding="utf-8", errors="surrogatepass")
            print(f"(whole in {kept})")
    for label, indexes in (("slow", slow), ("over the memory limit", memory)):
        for i in indexes[:3]:
            print(f"\n{label}: mutant {i} of {tried[i].seed}:\n{tried[i].text[:2000]}")
    return 1 if groups or slow or memory else 0


if __name__ == "__main__":
    sys.exit(main())
