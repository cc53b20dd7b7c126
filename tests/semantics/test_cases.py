"""Checker case files: each offending line says which diagnostics it must produce
(`# E102 W101`); the set of (line, code) produced must equal the set written, so a
missed fault and a cascade of follow-on errors both fail."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rdisc.compile import compile_path

CASES = sorted((Path(__file__).parent / "cases").glob("*.rdis"))
_EXPECT = re.compile(r"#\s*((?:[EW]\d{3}\s*)+)$")


def expected(path: Path) -> set[tuple[int, str]]:
    found = set()
    for number, line in enumerate(path.read_text().splitlines(), 1):
        m = _EXPECT.search(line)
        if m:
            found |= {(number, code) for code in m.group(1).split()}
    return found


def produced(path: Path) -> set[tuple[int, str]]:
    c = compile_path(str(path))
    source = c.sources[str(path)]
    return {
        (source.position(d.span.start).line + 1, d.code)
        for d in c.diagnostics.items
        if d.span is not None and d.span.path == str(path)
    }


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_case_file(path: Path) -> None:
    assert produced(path) == expected(path)
