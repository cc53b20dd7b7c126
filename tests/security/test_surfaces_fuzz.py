"""A modest run of the fuzzer of the surfaces that are not a description's text (benchmarks/fuzz.py
--surface runs 20,000 of each): no page's message makes the console raise, no recording makes a
replay raise but the errors `rdisc replay` says in a line, no body the checker accepts makes the
simulation raise but SimulationError. The same cases every run (seeded): a failure reproduces
from its numbers with `surfaces.case(surface, seed, index)`."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "properties"))  # where the fuzzers live

import surfaces
from mutants import finding

COUNTS = {"console": 200, "replay": 120, "sim": 16}  # a few seconds each on a shared core


@pytest.mark.parametrize("surface", surfaces.SURFACES)
def test_no_hostile_case_raises_inside_rdisc(surface: str, tmp_path: Path) -> None:
    if surface == "sim":
        pytest.importorskip("mujoco")
    if surface == "replay":
        pytest.importorskip("mcap_ros2")
    found: dict[str, int] = {}
    for index in range(COUNTS[surface]):
        try:
            surfaces.run(surface, surfaces.case(surface, 3, index), tmp_path)
        except Exception as err:  # noqa: BLE001 - every one is a finding
            found.setdefault(finding(err), index)
    assert not found, "\n\n".join(f"{place}: {surfaces.shown(surface, surfaces.case(surface, 3, index))}"
                                  for place, index in found.items())
