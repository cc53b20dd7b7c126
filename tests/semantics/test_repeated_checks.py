"""A process that checks again and again (the editor, the console) keeps no cycle for ever.
A check pauses the cyclic garbage collector and hands what it made to the oldest generation
(rdisc.compile._without_collections) by freezing, which also resets the collector's counts, so
its full collection never came: the simulation fuzzer's workers ran out of memory after about
500 cases. A check now leaves no cycle (three nested functions that called themselves each held
one, and with it what they read: 5,500 objects a check of arm.rdis), and the process's own are
collected every CHECKS_PER_COLLECTION checks. Each in a process of its own: a pytest worker's
heap and threads would add to the counts."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

NO_CYCLES = """
import gc, glob
from rdisc.compile import compile_path
files = sorted(glob.glob("examples/*.rdis")) + sorted(glob.glob("tests/semantics/cases/*.rdis"))
for name in files:  # imports, caches and tables made first
    compile_path(name)
gc.collect()
gc.set_debug(gc.DEBUG_SAVEALL)
for name in files:
    compile_path(name)
gc.collect()
print(len(files), len(gc.garbage), sorted({type(o).__qualname__ for o in gc.garbage})[:20])
"""
# What a process does between checks (a robot run, a simulation): here 20,000 objects held by a
# function that calls itself, a cycle, each time.
THE_PROCESS_S_CYCLES = """
import gc
from rdisc.compile import CHECKS_PER_COLLECTION, compile_path

def run_of_the_process() -> None:
    held = [[index] for index in range(20_000)]

    def walk(depth: int) -> int:
        return len(held) if depth == 0 else walk(depth - 1)

    walk(3)

counts = []
for _ in range(100):
    run_of_the_process()
    compile_path("examples/create.rdis")
    counts.append(len(gc.get_objects()))
print(CHECKS_PER_COLLECTION, max(counts))
"""


def run(script: str) -> str:
    return subprocess.run([sys.executable, "-c", script], cwd=REPO, capture_output=True, text=True,
                          check=True).stdout


def test_a_check_leaves_no_cycles() -> None:
    """Every example and checker case, each checked again: nothing for the collector to find."""
    files, garbage, kinds = run(NO_CYCLES).split(" ", 2)
    assert int(files) > 40 and int(garbage) == 0, kinds



def test_the_process_s_cycles_are_collected_between_checks() -> None:
    """100 checks, each after 20,000 objects were left in a cycle: 2 million kept before; now
    no more than a collection's worth of checks' (32 of them: 640,000) and the process's own."""
    per_collection, most = (int(word) for word in run(THE_PROCESS_S_CYCLES).split())
    assert most < (per_collection + 8) * 20_000, most
