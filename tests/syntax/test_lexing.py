"""The parser whose states' lexers share one pattern (rdisc/syntax/lexing.py) reads every
example and test description, and damaged copies of them, exactly as Lark's own does: the
same trees, the same syntax errors."""

from __future__ import annotations

import random
from pathlib import Path

import lark

from rdisc.syntax import lexing
from rdisc.syntax.parse import declaration_bounds, keyword_as_name, lark_parser, parser

REPO = Path(__file__).resolve().parents[2]


def outcomes(made: lark.Lark, texts: list[str]) -> list[tuple[str, ...]]:
    """What `made` gives for each declaration of each text, in order; a declaration's text met
    again (two in three are: the damaged copies and the files share most) is parsed once."""
    found: list[tuple[str, ...]] = []
    parsed: dict[str, tuple[str, ...]] = {}
    for text in texts:
        for start, end in declaration_bounds(text):
            declaration = text[start:end]
            if declaration not in parsed:
                parsed[declaration] = outcome(made, declaration)
            found.append(parsed[declaration])
    return found


def outcome(made: lark.Lark, declaration: str) -> tuple[str, ...]:
    try:
        return ("tree", str(made.parse(declaration, start="start", on_error=keyword_as_name)))
    except lark.exceptions.UnexpectedInput as err:
        return ("error", type(err).__name__, str(err))


def test_shared_lexers_read_as_larks_own() -> None:
    paths = sorted([*REPO.glob("examples/*.rdis"), *REPO.glob("tests/**/*.rdis")])
    texts = [path.read_bytes().decode("utf-8", errors="replace") for path in paths]
    rng = random.Random(5)
    for text in texts[:60]:  # damaged copies: characters deleted here and there
        for _ in range(5):
            at = rng.randrange(len(text))
            texts.append(text[:at] + text[at + rng.randrange(1, 4):])
    shared, own = parser(), lark_parser()
    assert any(isinstance(state, lexing._SharedLexer) for state in shared.parser.lexer.lexers.values())
    assert not any(isinstance(state, lexing._SharedLexer) for state in own.parser.lexer.lexers.values())
    mine, theirs = outcomes(shared, texts), outcomes(own, texts)
    assert mine == theirs
    assert sum(kind == "error" for kind, *_ in mine) > 50  # the damaged copies' errors are compared too
