"""A modest run of the mutation fuzzer (benchmarks/fuzz.py runs long ones): no mutant of the
examples and test descriptions makes rdisc raise anything but a diagnostic, anywhere in
the pipeline (check, rendering, canonical JSON and back, dump, driver, ROS node, plans)."""

from __future__ import annotations

from pathlib import Path

import pytest
from mutants import finding, mutants, run_pipeline

pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

COUNT = 120  # the same mutants every run (seeded): a failure here reproduces


@pytest.mark.parametrize("batch", range(4))
def test_no_mutant_raises_inside_rdisc(tmp_path: Path, batch: int) -> None:
    found: dict[str, str] = {}
    for i, mutant in enumerate(mutants(seed=batch, count=COUNT // 4)):
        path = tmp_path / f"mutant{i}{mutant.suffix}"
        path.write_text(mutant.text, encoding="utf-8", errors="surrogatepass")
        try:
            run_pipeline(path)
        except Exception as err:  # noqa: BLE001 - every one is a finding
            found.setdefault(finding(err), mutant.text)
    assert not found, "\n\n".join(f"{place}:\n{text[:1500]}" for place, text in found.items())
