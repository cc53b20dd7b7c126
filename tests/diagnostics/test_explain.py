"""`rdisc explain` texts say what the checker accepts: where a text lists the allowed
things, the list is held here against the checker's own (so neither drifts)."""

from __future__ import annotations

import re

import pytest

from rdisc.diagnostics.codes import CODES
from rdisc.engine.operations import FUNCTIONS
from rdisc.semantics.check import declarations
from rdisc.semantics.model import Type


def _words(text: str) -> set[str]:
    return set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", text))


@pytest.mark.parametrize(("code", "accepted"), [
    ("E105", [t.value for t in Type]),
    ("E106", list(FUNCTIONS)),
    ("E209", list(declarations.CONNECTION_KINDS)),
])
def test_a_text_names_everything_the_checker_accepts(code: str, accepted: list[str]) -> None:
    assert sorted(set(accepted) - _words(CODES[code].explanation)) == []


def test_every_code_has_a_text() -> None:
    assert [c for c, entry in CODES.items() if len(entry.explanation) < 40] == []


def test_the_limits_text_states_the_limits_in_force() -> None:
    from rdisc import compile as compile_module
    from rdisc.syntax import build, parse

    text = CODES["E005"].explanation.replace("\n", " ")
    for figure in (f"{build.MAX_EXPR_DEPTH} levels", f"{parse.MAX_LINE_CHARS:,} characters",
                   f"{parse.MAX_DECL_TOKENS:,} tokens", f"{compile_module.MAX_TOKENS:,} tokens",
                   f"{parse.MAX_FILE_CHARS // 2**20} MiB", f"{compile_module.MAX_IMPORTS} imported files"):
        assert figure in text, figure
