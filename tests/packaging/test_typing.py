"""rdisc's own source passes `mypy --strict` with the repository's configuration (pyproject's
[tool.mypy]), as every generated driver does: a closed union missing a case, an Optional used
as if present or a stale `type: ignore` fails here rather than in review. Its cache is pytest's
(.pytest_cache), kept between runs: mypy then checks again only what changed since the last run."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

# One test but the suite's longest on a fresh checkout (mypy's cache is cold): started before the other
# files (tests/conftest.py), so that it does not run alone at the end.
pytestmark = pytest.mark.long


def test_mypy_strict_finds_nothing_in_rdisc(request: pytest.FixtureRequest) -> None:
    cache = request.config.cache.mkdir("mypy-rdisc") if request.config.cache is not None else ROOT / ".mypy_cache"
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--cache-dir", str(cache), "rdisc"],
        capture_output=True, text=True, check=False, cwd=ROOT,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stdout.startswith("Success: no issues found"), done.stdout
