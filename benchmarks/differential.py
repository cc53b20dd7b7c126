"""A long differential search: the runtime against the generated driver on many random
descriptions, listing every problem found, each shrunk to a minimal example.

    python benchmarks/differential.py --descriptions 2000            # about 0.1 s a description
    python benchmarks/differential.py --descriptions 2000 --jobs 2   # one search per CPU
    python benchmarks/differential.py --descriptions 300 --no-shrink # first examples, unshrunk
    python benchmarks/differential.py --descriptions 300 --renamed   # names the engine's (lookup, lane, open...)

It uses the test suite's strategies and harness (tests/properties/descriptions.py and
differential_support.py; tests/properties/test_differential.py runs a few dozen).
Hypothesis generates descriptions and sessions. A problem is a disagreement, or a rule
of the contract broken by either implementation (on_io, valid replies, error types,
ranges, outputs, terminate hooks). Each is shrunk, printed and remembered by its signature (what differs
first, or the rule and how), and the search goes on, failing only on signatures not
seen yet, until the budget of descriptions is spent; a bug listed in KNOWN is printed
as first seen, unshrunk. Also printed: the calls' outcomes, apart those of calls whose
every reply was valid, and how many descriptions exercised each rarer construct (layouts
a setting chooses, lookups in framed replies): a check on the strategies as much as on
rdisc. Exit status 1
if anything was found. Leave rdisc alone while it runs (see `fingerprint`).
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
import importlib.util
import os
import sys
import tempfile
import time
from collections import Counter
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "properties"))
if importlib.util.find_spec("rdisc") is None:
    sys.path.append(str(ROOT))  # this checkout's rdisc, when none is installed (PYTHONPATH may give another)

from descriptions import Description, Script, constructs, descriptions, scripts
from differential_support import Outcome, Pairs, compare
from hypothesis import HealthCheck, Phase, given, seed, settings
from hypothesis import strategies as st
from renaming import renamed, renamings


@dataclass
class Finding:
    signature: tuple[Any, ...]
    description: str
    script: str
    report: str


@dataclass
class Tally:
    """What one search tried and found."""

    descriptions: int = 0  # generated (shrinking excluded)
    shrink_runs: int = 0
    sessions: int = 0
    calls: int = 0
    outcomes: Counter[str] = field(default_factory=Counter)  # call outcomes, runtime side
    valid: Counter[str] = field(default_factory=Counter)  # the same, of calls every reply of which is valid
    constructs: Counter[str] = field(default_factory=Counter)  # descriptions exercising each rarer construct
    findings: dict[tuple[Any, ...], Finding] = field(default_factory=dict)
    seconds: float = 0.0


class Found(Exception):
    """A problem with a signature not seen yet in this search."""

    def __init__(self, signature: tuple[Any, ...], description: Description, script: Script, outcome: Outcome):
        super().__init__(str(signature))
        self.finding = Finding(signature, description.text, script.text(), outcome.report())


def count(tally: Tally, script: Script, outcome: Outcome) -> None:
    """The runtime's outcome of each call; apart, those of calls answered validly throughout."""
    results = {entry[0]: entry[1] for entry in outcome.runtime.log if str(entry[0]).startswith("call")}
    for op in script.operations:
        if op.kind == "tick" or op.label() not in results:
            continue
        tally.outcomes[results[op.label()]] += 1
        if op.plans and all(p.kind in ("valid", "lower") for p in op.plans):
            tally.valid[results[op.label()]] += 1


def search(budget: int, first_seed: int, sessions: int, shrink: bool, renaming: bool = False) -> Tally:
    """Up to `budget` generated descriptions; every new kind of problem, shrunk (known bugs: as first seen).
    `renaming`: each description's names renamed to the engine's (tests/properties/renaming.py)."""
    tally = Tally()
    folder = tempfile.mkdtemp(prefix="rdisc-differential-")
    pairs = Pairs(folder)
    start = time.perf_counter()
    shrinking = False
    rounds = 0
    while tally.descriptions < budget:
        phases = [Phase.generate, Phase.shrink] if shrink else [Phase.generate]

        @seed(first_seed + rounds)
        @settings(max_examples=budget - tally.descriptions, deadline=None, database=None, phases=phases,
                  report_multiple_bugs=False, suppress_health_check=list(HealthCheck))
        @given(data=st.data())
        def probe(data: st.DataObject) -> None:
            nonlocal shrinking
            description = data.draw(descriptions())
            if shrinking:
                tally.shrink_runs += 1
            else:
                tally.descriptions += 1
                tally.constructs.update(constructs(description))
            if renaming:
                names = data.draw(renamings(description.text))
                pair = pairs(dataclasses.replace(description, text=renamed(description.text, names)), names)
            else:
                pair = pairs(description)
            for _ in range(sessions):
                script = data.draw(scripts(description))
                outcome = compare(pair, script)
                if not shrinking:
                    tally.sessions += 1
                    tally.calls += len(script.operations)
                    count(tally, script, outcome)
                for signature in outcome.signatures():
                    if signature in tally.findings:
                        continue
                    if signature[0] == "known":  # listed as first seen, not shrunk again
                        tally.findings[signature] = Found(signature, description, script, outcome).finding
                        continue
                    shrinking = shrink
                    raise Found(signature, description, script, outcome)

        rounds += 1
        shrinking = False
        try:
            probe()
            break  # the budget is spent, nothing new
        except Found as found:
            tally.findings[found.finding.signature] = found.finding
            print(f"  found {found.finding.signature} after {tally.descriptions} descriptions", file=sys.stderr)
    tally.seconds = time.perf_counter() - start
    return tally


def merge(tallies: list[Tally]) -> Tally:
    total = Tally()
    for t in tallies:
        total.descriptions += t.descriptions
        total.shrink_runs += t.shrink_runs
        total.sessions += t.sessions
        total.calls += t.calls
        total.outcomes.update(t.outcomes)
        total.valid.update(t.valid)
        total.constructs.update(t.constructs)
        for signature, finding in t.findings.items():
            total.findings.setdefault(signature, finding)
        total.seconds = max(total.seconds, t.seconds)
    return total


def fingerprint() -> str:
    """A digest of rdisc's sources: a driver generated now carries the engine as it is on disk now, while
    the runtime runs the one imported at start, so an edit during a search shows up as disagreements."""
    import rdisc

    digest = hashlib.sha1()
    for path in sorted(Path(rdisc.__file__).parent.rglob("*.py")):
        digest.update(path.read_bytes())
    return digest.hexdigest()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--descriptions", type=int, default=200, help="descriptions to generate (default 200)")
    parser.add_argument("--sessions", type=int, default=3, help="sessions (scripts) per description (default 3)")
    parser.add_argument("--seed", type=int, default=0, help="first seed (default 0; each job and round adds)")
    parser.add_argument("--jobs", type=int, default=1, help="parallel searches, one process each (default 1)")
    parser.add_argument("--no-shrink", action="store_true", help="report problems as found, unshrunk")
    parser.add_argument("--renamed", action="store_true",
                        help="rename each description's names to the engine's (lookup, lane, open, incoming...)")
    args = parser.parse_args()
    jobs = max(1, args.jobs)
    shares = [args.descriptions // jobs + (1 if i < args.descriptions % jobs else 0) for i in range(jobs)]
    started = time.perf_counter()
    sources = fingerprint()
    if jobs == 1:
        tallies = [search(shares[0], args.seed, args.sessions, not args.no_shrink, args.renamed)]
    else:
        with ProcessPoolExecutor(jobs) as pool:
            futures = [pool.submit(search, share, args.seed + 1000 * i, args.sessions, not args.no_shrink, args.renamed)
                       for i, share in enumerate(shares)]
            tallies = [f.result() for f in futures]
    total = merge(tallies)
    elapsed = time.perf_counter() - started
    print(f"{total.descriptions} descriptions, {total.sessions} sessions, {total.calls} calls "
          f"in {elapsed:.1f} s ({jobs} job{'s' if jobs > 1 else ''}; {total.shrink_runs} more runs shrinking); "
          f"Python {sys.version.split()[0]}, {os.cpu_count()} CPUs")
    if fingerprint() != sources:
        print("WARNING: rdisc's sources changed during the search: disagreements may be that change, not bugs")
    outcomes = ", ".join(f"{kind} {count}" for kind, count in total.outcomes.most_common())
    print(f"call outcomes (runtime): {outcomes}")
    valid = ", ".join(f"{kind} {count}" for kind, count in total.valid.most_common())
    print(f"  of calls whose every reply was valid: {valid}")
    drawn = ", ".join(f"{kind} {count}" for kind, count in sorted(total.constructs.items()))
    print(f"descriptions with: {drawn or 'none of the rarer constructs'}")
    if not total.findings:
        print("no problem found: the implementations agree and keep the contract")
        return 0
    print(f"{len(total.findings)} kind{'s' if len(total.findings) > 1 else ''} of problem found:")
    for i, finding in enumerate(total.findings.values(), 1):
        print(f"\n==== {i}. {finding.signature}")
        print(finding.description)
        print("-- session")
        print(finding.script)
        print("-- what differs")
        print(finding.report)
    return 1


if __name__ == "__main__":
    sys.exit(main())
