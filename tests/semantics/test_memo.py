"""The editor's check (a Reparser and a Memo kept from one check of a document to the next) gives
what a fresh check gives, diagnostics and Model with every span, however the text was edited
since; and it checks again only the primitives and interfaces the edit touched."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.compile import Compilation, compile_text, token_budget
from rdisc.semantics.check.memo import Memo
from rdisc.source import Span
from rdisc.syntax.incremental import Reparser
from tests.conftest import fuzz_examples

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = {path.name: path.read_text(encoding="utf-8") for path in sorted((ROOT / "examples").glob("*.rdis"))}
sys.path.insert(0, str(ROOT / "benchmarks"))
from lsp_speed import description

BIG = description()
BIG_PATH = "/nonexistent/big.rdis"  # no file: the checks read the text given


def whole(node: Any) -> Any:
    """A value as nested tuples of its class and every field, spans too (`==` leaves them out)."""
    if isinstance(node, (tuple, list)):
        return tuple(whole(item) for item in node)
    if isinstance(node, dict):
        return tuple((key, whole(value)) for key, value in node.items())
    if isinstance(node, Span):
        return (node.path, node.start, node.end)
    if hasattr(node, "__dataclass_fields__"):
        return (type(node).__name__, *(whole(getattr(node, name)) for name in node.__dataclass_fields__))
    return node


class Editor:
    """One document as the language server checks it."""

    def __init__(self, path: str) -> None:
        self.path, self.parser, self.memo = path, Reparser(), Memo()

    def check(self, text: str) -> Compilation:
        return compile_text(self.path, text, parser=self.parser, memo=self.memo)


def same_as_fresh(editor: Editor, text: str) -> None:
    kept, fresh = editor.check(text), fresh_check(editor.path, text)
    assert whole(kept.diagnostics.items) == fresh[0]
    assert whole(kept.model) == fresh[1]
    assert whole(kept.budgets) == fresh[2]


_FRESH: dict[tuple[Any, ...], tuple[Any, Any, Any]] = {}


def fresh_check(path: str, text: str) -> tuple[Any, Any, Any]:
    """A fresh check's diagnostics, Model and budgets as `whole` gives them, made once for each path,
    text and bound that decides them (the token budget, the bounds on unrolled calls): the tests
    compare many edited checks with the fresh check of a text they met before (an example, BIG)."""
    from rdisc.compile import _max_tokens
    from rdisc.semantics.check import interfaces, memo

    key = (path, text, _max_tokens.get(), interfaces.MAX_UNROLLED, interfaces.MAX_UNROLLED_ALL, memo.MAX_UNROLLED,
           memo.MAX_UNROLLED_ALL)
    if key not in _FRESH:
        fresh = compile_text(path, text)
        _FRESH[key] = (whole(fresh.diagnostics.items), whole(fresh.model), whole(fresh.budgets))
    return _FRESH[key]


def test_a_change_to_one_primitive_checks_only_it_and_the_interface_calling_it() -> None:
    editor = Editor(BIG_PATH)
    same_as_fresh(editor, BIG)
    assert editor.memo.reused == 0
    same_as_fresh(editor, BIG.replace("0..1000", "0..1001", 1))  # set_0's range: set_0 and move_0 again
    assert editor.memo.reused == 2 * 165 - 2
    same_as_fresh(editor, BIG.replace('unit "mm"', 'unit "mx"', 1))  # an unknown unit, reported
    assert editor.memo.reused == 2 * 165 - 2
    same_as_fresh(editor, BIG.replace("0..1000", "0..99999", 1))  # the declarations after it move: checked again
    same_as_fresh(editor, BIG.replace("state last: int = 0", "state last: float = 0"))  # the context: all again
    assert editor.memo.reused == 0


def test_declarations_that_only_moved_are_taken_again_with_their_spans_shifted() -> None:
    editor = Editor(BIG_PATH)
    same_as_fresh(editor, BIG)
    same_as_fresh(editor, BIG.replace("0..1000", "0..99999", 1))  # set_0 and move_0 again; the rest moved
    assert editor.memo.reused == 2 * 165 - 2
    same_as_fresh(editor, BIG)  # moved back
    assert editor.memo.reused == 2 * 165 - 2
    same_as_fresh(editor, "# the context moves too\n\n" + BIG)
    assert editor.memo.reused == 2 * 165
    same_as_fresh(editor, "# the context moves too\n\n" + BIG.replace("set_99(round(", "set_99(  round("))
    assert editor.memo.reused == 2 * 165 - 1  # move_99 again; those before it stay, those after it move


def test_a_moved_check_reports_its_faults_where_they_now_are() -> None:
    editor = Editor(BIG_PATH)
    broken = BIG.replace("set_100(round(value * 1000))", "set_7(1, 2)").replace('unit "mm"', 'unit "mmm"', 101)
    same_as_fresh(editor, broken)
    moved = broken.replace("set_50(value: int in 0..1000", "set_50(value: int in 0..1000000")  # after it moves
    same_as_fresh(editor, moved)
    assert editor.memo.reused == 2 * 165 - 2
    faults = editor.check(moved).diagnostics.items
    assert sorted(d.code for d in faults) == ["E109"] * 101 + ["E201"]
    call = next(d for d in faults if d.code == "E201")
    assert call.span is not None and moved[call.span.start:call.span.end] == "set_7(1, 2)"
    assert [moved[label.span.start:label.span.end] for label in call.labels] == ["set_7"]


def test_a_moved_check_is_taken_again_as_it_was_its_spans_moved_once_each() -> None:
    """Nothing that only moved is made again: the moved declarations' nodes, Model parts and
    diagnostics are the last check's, their spans moved where they are; a span a kept check holds
    of another declaration that moved too (a label on the primitive called) is moved once."""
    editor = Editor(BIG_PATH)
    broken = BIG.replace("set_100(round(value * 1000))", "set_7(1, 2)")
    same_as_fresh(editor, broken)
    before = editor.check(broken)
    moved = "# everything moves\n" + broken
    same_as_fresh(editor, moved)
    after = editor.check(moved)
    assert editor.memo.reused == 2 * 165
    assert all(a is b for a, b in zip(after.main.decls, before.main.decls, strict=True))
    call = next(d for d in after.diagnostics.items if d.code == "E201")
    assert call is next(d for d in before.diagnostics.items if d.code == "E201")
    assert moved[call.span.start:call.span.end] == "set_7(1, 2)"
    assert [moved[label.span.start:label.span.end] for label in call.labels] == ["set_7"]
    good = "# everything moves\n" + BIG
    kept = editor.check(good).model
    same_as_fresh(editor, "\n" + good)
    assert kept is not None and editor.check("\n" + good).model.primitives["set_9"] is kept.primitives["set_9"]


def test_a_declaration_written_twice_checks_as_a_fresh_check_where_it_moves() -> None:
    """Two declarations of the same text came from one old one: where its spans went is not one
    place, so neither is taken from it shifted."""
    editor = Editor(BIG_PATH)
    start = BIG.index("/// Set register 5.")
    block = BIG[start:BIG.index("/// Set register 6.")]
    twice = BIG + block
    same_as_fresh(editor, BIG)
    same_as_fresh(editor, twice)
    same_as_fresh(editor, "# moved\n" + twice)
    same_as_fresh(editor, "# moved\n" + BIG[:start] + block + BIG[start:])
    assert sorted({d.code for d in editor.check("# moved\n" + twice).diagnostics.items}) == ["E101"]  # declared twice


def test_a_reused_check_reports_its_faults_again() -> None:
    editor = Editor(BIG_PATH)
    broken = BIG.replace("set_7(round(value * 1000))", "set_7(value * 1000)").replace('unit "mm"', 'unit "mmm"', 1)
    same_as_fresh(editor, broken)
    edited = broken.replace("0..1000", "0..1001", 2)  # two primitives' ranges (one with the fault), the others kept
    same_as_fresh(editor, edited)
    assert editor.memo.reused == 2 * 165 - 4
    codes = sorted(d.code for d in editor.check(edited).diagnostics.items)
    assert codes == ["E109", "E402"]


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_every_example_checked_again_after_edits_as_a_fresh_check(name: str) -> None:
    text = EXAMPLES[name]
    editor = Editor(str(ROOT / "examples" / name))
    same_as_fresh(editor, text)
    same_as_fresh(editor, text)
    assert editor.memo.reused == sum(not part for _, part in editor.memo.kept) > 0 or "primitive" not in text
    same_as_fresh(editor, "# every declaration moves\n" + text)
    assert editor.memo.reused == sum(not part for _, part in editor.memo.kept) > 0 or "primitive" not in text
    same_as_fresh(editor, text.replace("{", "{ )", 1))
    same_as_fresh(editor, text)


PIECES = st.sampled_from(["", "\n", " ", "{", "}", "(", ")", "///doc\n", "# c\n", "x", "1", '"', "..", ".0",
                          "\nconst k = 3\n", "\nstate s: int = 0\n", "unit \"mm\" ", " + 1", "round(", "float",
                          "int", "primitive p() on link pack \"B\" (1)\n", "interface i() { p() }\n", "set_1(2)"])


def edits(data: st.DataObject, text: str) -> str:
    start = data.draw(st.integers(0, len(text)))
    end = data.draw(st.integers(start, min(len(text), start + 200)))
    return text[:start] + "".join(data.draw(st.lists(PIECES, max_size=4))) + text[end:]


@settings(max_examples=fuzz_examples(20), deadline=None)
@given(name=st.sampled_from(sorted(EXAMPLES)), data=st.data())
def test_any_edits_of_an_example_check_as_a_fresh_check(name: str, data: st.DataObject) -> None:
    editor = Editor(str(ROOT / "examples" / name))
    text = EXAMPLES[name]
    same_as_fresh(editor, text)
    for _ in range(data.draw(st.integers(1, 3))):
        text = edits(data, text)
        same_as_fresh(editor, text)


LINES = st.sampled_from(["\n", "# a comment\n", "\n\n\n", "/// a doc comment\n", "const moved = 1\n"])


@settings(max_examples=fuzz_examples(20), deadline=None)
@given(name=st.sampled_from(sorted(EXAMPLES)), data=st.data())
def test_lines_added_or_taken_away_check_as_a_fresh_check(name: str, data: st.DataObject) -> None:
    """Whole lines added and taken away: most declarations only move, and are taken again shifted."""
    editor = Editor(str(ROOT / "examples" / name))
    text = EXAMPLES[name]
    same_as_fresh(editor, text)
    for _ in range(data.draw(st.integers(1, 4))):
        lines = text.splitlines(keepends=True)
        at = data.draw(st.integers(0, len(lines)))
        if data.draw(st.booleans()) and at < len(lines):
            del lines[at:at + data.draw(st.integers(1, 3))]
        else:
            lines.insert(at, data.draw(LINES))
        text = "".join(lines)
        same_as_fresh(editor, text)


@settings(max_examples=fuzz_examples(3), deadline=None)
@given(data=st.data())
def test_any_edits_of_the_large_description_check_as_a_fresh_check(data: st.DataObject) -> None:
    editor = Editor(BIG_PATH)
    text = BIG
    same_as_fresh(editor, text)
    for _ in range(data.draw(st.integers(1, 3))):
        text = edits(data, text)
        same_as_fresh(editor, text)


def test_what_a_reused_check_read_still_counts_as_used() -> None:
    editor = Editor(BIG_PATH)
    text = BIG.replace("state last: int = 0", "state last: int = 0\nstate speed: int = 0").replace(
        "set_9(round(value * 1000))", "set_9(speed)")  # `speed` read by move_9 only
    same_as_fresh(editor, text)
    same_as_fresh(editor, text.replace("0..1000", "0..1001", 1))  # move_9 kept: `speed` is still read (no W103)
    assert editor.memo.reused == 2 * 165 - 2


def test_a_description_over_the_token_budget_is_refused_as_by_a_fresh_check() -> None:
    editor = Editor(BIG_PATH)
    same_as_fresh(editor, BIG)
    with token_budget(5000):  # the description has about 8,000
        same_as_fresh(editor, BIG)
        assert [d.code for d in editor.check(BIG).diagnostics.items] == ["E005"]
    same_as_fresh(editor, BIG)


def test_interfaces_near_the_bound_of_all_calls_are_checked_each_time_and_once(monkeypatch: pytest.MonkeyPatch) -> None:
    from rdisc.semantics.check import interfaces, memo

    for module in (interfaces, memo):  # bounds made small, so the test is quick
        monkeypatch.setattr(module, "MAX_UNROLLED", 300)
        monkeypatch.setattr(module, "MAX_UNROLLED_ALL", 700)
    text = BIG.replace("interface move_1(value: float) {", "interface move_1(value: float) {\n    for i in 0..249 { set_0(1) }") \
        .replace("interface move_2(value: float) {", "interface move_2(value: float) {\n    for i in 0..249 { set_0(1) }") \
        .replace("interface move_3(value: float) {", "interface move_3(value: float) {\n    for i in 0..198 { set_0(1) }")
    editor = Editor(BIG_PATH)
    same_as_fresh(editor, text)
    assert [d.code for d in editor.check(text).diagnostics.items] == ["E212"]  # move_3: 503 calls before it, 199 in its loop
    same_as_fresh(editor, text.replace("0..198", "0..189"))  # 693: within the bound
    assert [d.code for d in editor.check(text.replace("0..198", "0..189")).diagnostics.items] == []


def test_what_a_check_made_goes_to_the_oldest_generation_without_a_collection() -> None:
    """The first young collection after a check would pass over everything it made (a third of
    an editor's check when most declarations moved): it is put in the oldest generation at once."""
    import gc

    passes: list[int] = []

    def watch(phase: str, info: dict[str, int]) -> None:
        if phase == "start":
            passes.append(info["generation"])

    assert gc.isenabled()
    gc.callbacks.append(watch)
    try:
        compile_text(BIG_PATH, BIG)
        young = gc.get_count()[0]
    finally:
        gc.callbacks.remove(watch)
    assert passes == [] and young < 50 and gc.isenabled()
