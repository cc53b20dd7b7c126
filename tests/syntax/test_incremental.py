"""The editor's parser (rdisc.syntax.incremental) gives what a fresh `parse` gives, spans and
diagnostics included, however the text was edited since its last parse; and it parses again only
the declarations the edit touched."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.diagnostics import Diagnostics
from rdisc.source import Span
from rdisc.syntax.incremental import Reparser, shifted
from rdisc.syntax.parse import parse, token_count
from tests.conftest import fuzz_examples

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples").glob("*.rdis"))
TEXTS = {path.name: path.read_text(encoding="utf-8") for path in EXAMPLES}


def whole(node: Any) -> Any:
    """A node as nested tuples of its class and every field, spans too (`==` leaves them out)."""
    if isinstance(node, tuple):
        return tuple(whole(item) for item in node)
    if isinstance(node, Span):
        return (node.path, node.start, node.end)
    if hasattr(node, "__dataclass_fields__"):
        return (type(node).__name__, *(whole(getattr(node, name)) for name in node.__dataclass_fields__))
    return node


def parsed(parser: Reparser | None, text: str) -> tuple[Any, list[Any]]:
    diagnostics = Diagnostics()
    module = (parse if parser is None else parser.parse)("bot.rdis", text, diagnostics)
    return whole(module), [(d.code, d.span, d.message) for d in diagnostics.items]


def same_as_fresh(parser: Reparser, text: str) -> None:
    assert parsed(parser, text) == parsed(None, text)


@pytest.mark.parametrize("name", sorted(TEXTS))
def test_every_example_edited_above_each_declaration_parses_as_a_fresh_parse(name: str) -> None:
    text = TEXTS[name]
    parser = Reparser()
    same_as_fresh(parser, text)
    fresh = parse("bot.rdis", text, Diagnostics())
    assert parser.reused == 0 and fresh.decls
    moved = "# a comment, so that every declaration moves\n\n" + text
    same_as_fresh(parser, moved)
    assert parser.reused == len(parser.files["bot.rdis"]) - 1 > 0  # all but the first piece, which the comment went into
    same_as_fresh(parser, text)  # and back
    broken = text.replace("{", "{ )", 1)  # a syntax error in one declaration, reported anew each time
    same_as_fresh(parser, broken)
    same_as_fresh(parser, broken)
    same_as_fresh(parser, text)


def test_a_moved_declaration_is_the_last_parses_nodes_with_their_spans_moved() -> None:
    """Moving costs no node: the declarations after the edit are the very nodes of the last parse."""
    text = TEXTS["arm.rdis"]
    parser = Reparser()
    before = parser.parse("bot.rdis", text, Diagnostics()).decls
    moved = "# every declaration moves\n" + text
    same_as_fresh(parser, moved)
    after = parser.parse("bot.rdis", moved, Diagnostics()).decls
    assert len(after) == len(before) > 10 and all(a is b for a, b in zip(after[1:], before[1:], strict=True))


PIECES = st.sampled_from(["", "\n", " ", "{", "}", "(", ")", "///doc\n", "/// x\n", "# c\n", "primitive ", "state ",
                          "frame ", "enum ", "x", "1", '"', "..", "\nconst k = 3\n", "\n\n", "robot r { author \"a\" }\n"])


@settings(max_examples=fuzz_examples(60), deadline=None)
@given(name=st.sampled_from(sorted(TEXTS)), data=st.data())
def test_any_edit_of_an_example_parses_as_a_fresh_parse(name: str, data: st.DataObject) -> None:
    text = TEXTS[name]
    start = data.draw(st.integers(0, len(text)))
    end = data.draw(st.integers(start, min(len(text), start + 400)))
    inserted = "".join(data.draw(st.lists(PIECES, max_size=4)))
    edited = text[:start] + inserted + text[end:]
    parser = Reparser()
    parser.parse("bot.rdis", text, Diagnostics())
    same_as_fresh(parser, edited)
    same_as_fresh(parser, text)


def test_a_shifted_tree_has_every_span_moved_and_equals_the_original() -> None:
    module = parse("bot.rdis", TEXTS["arm.rdis"], Diagnostics())
    moved = shifted(module.decls, 7)
    assert moved == module.decls
    spans: list[tuple[Span, Span]] = []

    def pairs(a: Any, b: Any) -> None:
        if isinstance(a, Span):
            spans.append((a, b))
        elif isinstance(a, tuple):
            for x, y in zip(a, b, strict=True):
                pairs(x, y)
        elif hasattr(a, "__dataclass_fields__"):
            assert type(a) is type(b) and a is not b
            for name in a.__dataclass_fields__:
                pairs(getattr(a, name), getattr(b, name))

    pairs(module.decls, moved)
    assert len(spans) > 1000 and all((b.start, b.end) == (a.start + 7, a.end + 7) for a, b in spans)


@settings(max_examples=fuzz_examples(60), deadline=None)
@given(name=st.sampled_from(sorted(TEXTS)), data=st.data())
def test_the_tokens_of_any_edit_of_an_example_are_counted_as_token_count_counts_them(name: str,
                                                                                       data: st.DataObject) -> None:
    text = TEXTS[name]
    start = data.draw(st.integers(0, len(text)))
    end = data.draw(st.integers(start, min(len(text), start + 400)))
    edited = text[:start] + "".join(data.draw(st.lists(PIECES, max_size=4))) + text[end:]
    most = data.draw(st.sampled_from([10, 500, 200_000]))
    parser = Reparser()
    assert parser.tokens(text, most) == token_count(text, most)
    assert parser.tokens(edited, most) == token_count(edited, most)
    assert parser.tokens(text, 200_000) == token_count(text, 200_000)
