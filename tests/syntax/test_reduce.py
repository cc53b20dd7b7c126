"""The parser's fast loop (rdisc.syntax.reduce) builds what Lark's tree and the Builder's walk
build: the same syntax tree, spans and tokens included, and the same diagnostics; it takes
the examples' declarations, and leaves to Lark what it does not take."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any, Self

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc import regex_shape
from rdisc.diagnostics import Diagnostics
from rdisc.resources import stdlib_path
from rdisc.syntax import reduce, tables
from rdisc.syntax.build import MAX_EXPR_DEPTH
from rdisc.syntax.parse import MAX_TREE_DEPTH, parse

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted((ROOT / "examples").glob("*.rdis")) + [stdlib_path()]
LOOP = reduce.parse_built
ONE_LINERS = [
    'robot r { author "a\\qb" description "x\\ud800y" }',  # escapes the Builder reports (E003)
    'state s: bytes = b"\\q\u00e9"',  # bytes: an unknown escape, a character that is not ASCII (E003, E004)
    "state s: int = 0x" + "f" * 80,  # an integer literal too long (E004)
    "state s: int = 1 < 2 < 3",  # a misplaced comparison (E001)
    "state s: int = " + "-" * (MAX_EXPR_DEPTH + 5) + "1",  # too deep for the Builder: Lark's way (E005)
    "state s: int = " + "(" * (MAX_TREE_DEPTH + 5) + "1" + ")" * (MAX_TREE_DEPTH + 5),  # too deep a tree (E005)
    "state mask: int = 0\nstate baud: int = 1",  # keywords as names: Lark's recovery
    "primitive p() on link pack \"B\" (1) {\n",  # a syntax error
    "interface i() { p() delay 1 ms priority 2 when x > 1 }\nstate a: float = -1.5e3 if True else 2 ** 3",
    "const T = { 1: \"a\", 2: \"b\" }\nenum E { A = 1, B }\nstate b: bytes = b\"\\x00ab\"",
]


def dump(value: Any) -> Any:
    """Everything a value holds, spans and a token's attributes included (an AST node's `==` compares less)."""
    if value is None or isinstance(value, (bool, int, float, bytes)):
        return (type(value).__name__, value)
    if isinstance(value, str):
        attributes = ("type", "start_pos", "end_pos", "line", "column", "end_line", "end_column")
        return (type(value).__name__, str(value), tuple(getattr(value, name, None) for name in attributes))
    if isinstance(value, (list, tuple)):
        return (type(value).__name__, [dump(item) for item in value])
    if isinstance(value, dict):
        return ("dict", [(dump(key), dump(item)) for key, item in value.items()])
    names: list[str] = []
    for kind in type(value).__mro__:
        names += [name for name in getattr(kind, "__slots__", ()) if name not in names]
    names += [name for name in getattr(value, "__dict__", {}) if name not in names]
    return (type(value).__name__, [(name, dump(getattr(value, name, None))) for name in names])


def both_ways(monkeypatch: pytest.MonkeyPatch, path: str, text: str) -> tuple[Any, Any, int]:
    """(the loop's tree and diagnostics, Lark's, the declarations the loop left to Lark)."""
    left = 0

    def counted(*args: Any, **kwargs: Any) -> Any:
        nonlocal left
        try:
            return LOOP(*args, **kwargs)
        except reduce.Retry:
            left += 1
            raise

    def never(*args: Any, **kwargs: Any) -> Any:
        raise reduce.Retry

    results = []
    for way in (counted, never):
        monkeypatch.setattr(reduce, "parse_built", way)
        diagnostics = Diagnostics()
        module = parse(path, text, diagnostics)
        results.append((dump(module), [dump(d) for d in diagnostics.sorted()]))
    return results[0], results[1], left


@pytest.mark.parametrize("path", FILES, ids=lambda path: path.name)
def test_the_loop_builds_an_example_as_lark_and_the_builder_do(monkeypatch: pytest.MonkeyPatch, path: Path) -> None:
    fast, general, _ = both_ways(monkeypatch, str(path), path.read_text(encoding="utf-8"))
    assert fast == general


@pytest.mark.parametrize("text", ONE_LINERS)
def test_the_loop_reports_or_leaves_to_lark_what_the_builder_reports(monkeypatch: pytest.MonkeyPatch,
                                                                     text: str) -> None:
    fast, general, _ = both_ways(monkeypatch, "t.rdis", text)
    assert fast == general


def test_the_loop_takes_the_examples_declarations(monkeypatch: pytest.MonkeyPatch) -> None:
    """All but the three that use a keyword as a name, which Lark's recovery reads."""
    taken = left = 0

    def counted(*args: Any, **kwargs: Any) -> Any:
        nonlocal taken, left
        try:
            built = LOOP(*args, **kwargs)
        except reduce.Retry:
            left += 1
            raise
        taken += 1
        return built

    monkeypatch.setattr(reduce, "parse_built", counted)
    declarations = sum(len(parse(str(path), path.read_text(encoding="utf-8"), Diagnostics()).decls)
                       for path in FILES)
    assert declarations > 400 and taken > 400
    assert left == 3


def test_what_the_loop_leaves_is_reported_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """A declaration the Builder reports in and then refuses as too deep: its escape is reported
    once (by Lark's way, as the loop's report is dropped), with the depth."""
    text = 'state s: string = "\\q" + ' + "-" * (MAX_EXPR_DEPTH + 5) + "1"
    diagnostics = Diagnostics()
    module = parse("t.rdis", text, diagnostics)
    assert module.decls == ()
    assert [d.code for d in diagnostics.sorted()] == ["E003", "E005"]
    fast, general, left = both_ways(monkeypatch, "t.rdis", text)
    assert fast == general and left == 1


def _root_tokens(text: str) -> list[tuple[str, int, int]]:
    """The tokens the whole grammar's lexer reads, one terminal at a time as Lark's does: an ignored
    one is skipped and the pattern tried again after it; ("", pos, pos) where nothing matches."""
    root = re.compile("|".join(f"(?P<{name}>{tables.TERMINALS[name]})" for name in tables.ROOT))
    tokens, pos = [], 0
    while pos < len(text):
        hit = root.match(text, pos)
        if hit is None:
            return [*tokens, ("", pos, pos)]
        if hit.lastgroup not in tables.IGNORED:
            tokens.append((str(hit.lastgroup), pos, hit.end()))
        pos = hit.end()
    return tokens


def _scanned_tokens(text: str) -> list[tuple[str, int, int]]:
    """The tokens the fast loop's one pattern reads, each after what it skips."""
    scan = reduce._scanner()
    tokens, pos = [], 0
    while True:
        hit = scan(text, pos)
        if hit.lastgroup == "_STOP":
            return tokens if hit.end() == len(text) else [*tokens, ("", hit.end(), hit.end())]
        begin, pos = hit.end(1), hit.end()
        tokens.append((str(hit.lastgroup), begin, pos))


SCANNED = [
    "state s: int = 1 // 2 /// a doc comment at the end",  # never read back as `//` and `/`
    "x /// doc\n/// more\n",
    "x # a comment at the end",
    "a\n  # comment\n\t/// doc\n  b //c",
    "x $ y",  # no terminal reads `$`
    "r\"a\\\"b\" b\"\\x00\" \"s\" 1.5e3 0x1F 3 .5 ** // <= ->",
    "",
    "   \n# only a comment",
]


@pytest.mark.parametrize("text", [*SCANNED, *(path.read_text(encoding="utf-8") for path in FILES)],
                         ids=[*(repr(text)[:30] for text in SCANNED), *(path.name for path in FILES)])
def test_the_loop_scans_what_the_root_lexer_reads(text: str) -> None:
    assert _scanned_tokens(text) == _root_tokens(text)


# Pieces of text that begin alike and read as different terminals: a random text of them reads
# the same whatever order the scanner tries the terminals in, if that order is right.
_FRAGMENTS = st.sampled_from([
    ".", "..", ".5", "5.", "5..6", "1e3", "0x1F", "0b1", "_", "-", "->", "--", "<", "<<", "<=", "=", "==",
    "!=", ">", ">>", "*", "**", "/", "//", "///", "%", "b", "b\"x\"", "r", "r\"\\\"\"", "\"s\"", "name", "x1",
    " ", "\n", "#c\n", "(", ")", "[", "]", "{", "}", ",", ":", ";", "&", "|", "^", "~", "$", "+",
])


@settings(max_examples=400, deadline=None)
@given(st.lists(_FRAGMENTS, max_size=12).map("".join))
def test_the_loop_scans_any_text_as_the_root_lexer_reads_it(text: str) -> None:
    assert _scanned_tokens(text) == _root_tokens(text)


def test_the_scanner_keeps_the_root_lexer_s_order_of_terminals_that_begin_alike() -> None:
    """SCAN (rdisc.syntax.scan_order) moves a terminal before another only where no character can
    begin both (the written tables against the regex walk's reading of the terminals now); and it
    moves some: the punctuation is tried before the numbers' patterns. Whether that reading is
    right, the scans of texts above say."""
    def first(name: str) -> frozenset[int]:
        return regex_shape.first_characters(tables.TERMINALS[name])

    read = [name for name in tables.ROOT if name not in tables.IGNORED]
    assert sorted(tables.SCAN) == sorted(read)
    for i, name in enumerate(read):
        for earlier in read[:i]:
            if first(name) & first(earlier):
                assert tables.SCAN.index(earlier) < tables.SCAN.index(name), (earlier, name)
    assert tables.SCAN.index("COMMA") < tables.SCAN.index("FLOAT") < tables.SCAN.index("DOT")


def test_a_skipped_terminal_begins_where_no_terminal_tried_before_it_can() -> None:
    """What the loop's pattern relies on to skip them all at once (rdisc.syntax.reduce._scanner)."""
    def first(name: str) -> frozenset[int]:
        return regex_shape.first_characters(tables.TERMINALS[name])

    for i, name in enumerate(tables.ROOT):
        if name in tables.IGNORED:
            assert first(name)
            for earlier in tables.ROOT[:i]:
                assert earlier in tables.IGNORED or not first(name) & first(earlier), (name, earlier)


def _alternation(lexer: reduce.Lexer) -> re.Pattern[str]:
    """A state's own pattern as Lark's contextual lexer compiles it: its terminals' alternation."""
    return re.compile("|".join(f"(?P<{name}>{tables.TERMINALS[name]})" for name in lexer.terminals))


def _fresh_lexers(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every state's lexer as the first check of a process finds it: nothing compiled, never asked."""
    monkeypatch.setattr(reduce, "_TERMINAL_MATCHES", {})
    for lexer in reduce._LEXERS:
        monkeypatch.setattr(lexer, "_tries", ())
        monkeypatch.setattr(lexer, "_asked", 0)
        monkeypatch.setattr(lexer, "_match", None)


@pytest.mark.parametrize("alone", [10**9, 0], ids=["terminals-alone", "alternation"])
def test_a_state_s_lexer_reads_what_its_alternation_reads(monkeypatch: pytest.MonkeyPatch, alone: int) -> None:
    """Each terminal tried alone, in order (a literal compared as a string), and the alternation a
    state compiles once asked often, find the terminal and the end Lark's alternation finds, at
    each token of the examples and a few texts more."""
    _fresh_lexers(monkeypatch)
    monkeypatch.setattr(reduce, "ALONE", alone)
    texts = [*SCANNED, "inputs input in 1..2 0x1F_ 1e5 b\"x\" r\"y\" <<= >>",
             *(path.read_text(encoding="utf-8") for path in (ROOT / "examples" / "create.rdis", stdlib_path()))]
    # Each token and the two characters after it, once each.
    rests = sorted({text[begin:end + 2] for text in texts for _, begin, end in _root_tokens(text)})
    assert len(rests) > 250
    for lexer in reduce._LEXERS:
        match = _alternation(lexer).match
        for rest in rests:
            hit = match(rest)
            assert lexer.own(rest, 0) == (None if hit is None else (hit.lastgroup, hit.end())), rest


def test_a_keyword_a_state_s_lexer_reads_whole_is_what_its_alternation_reads(monkeypatch: pytest.MonkeyPatch) -> None:
    """Where the whole grammar's pattern reads a NAME that a state does not take, the loop asks
    the state's lexer for the keyword first (`Lexer.word`, without a pattern): each keyword it
    gives is the terminal the state's alternation reads there, to the name's end, whatever
    follows; and the keywords of the examples are found so, most of what the states are asked."""
    _fresh_lexers(monkeypatch)
    for lexer in reduce._LEXERS:
        monkeypatch.setattr(lexer, "_words", None)
    found = 0
    for lexer in reduce._LEXERS:
        match = _alternation(lexer).match
        for keyword in (tables.TERMINALS[name] for name in lexer.terminals if name not in tables.ROOT):
            terminal = lexer.word(keyword)
            if terminal is None:
                continue
            found += 1
            for after in ("", " x", "(", "\n", "#", "///", ".5", "\""):
                hit = match(keyword + after)
                assert hit is not None and (hit.lastgroup, hit.end()) == (terminal, len(keyword)), (keyword, after)
        assert lexer.word("not_a_keyword_x") is None
    assert found > 300
    asked = []
    original_own = reduce.Lexer.own

    def own(lexer: reduce.Lexer, text: str, pos: int) -> tuple[str, int] | None:
        asked.append(text[pos:pos + 12])
        return original_own(lexer, text, pos)

    monkeypatch.setattr(reduce.Lexer, "own", own)
    for path in (ROOT / "examples" / "create.rdis", stdlib_path()):
        parse(str(path), path.read_text(encoding="utf-8"), Diagnostics())
    assert asked == []


def _compiled_patterns(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The patterns `re.compile` is asked for from now on (in this test)."""
    compiled: list[str] = []
    original = re.compile

    def counted(pattern: Any, flags: int = 0) -> Any:
        compiled.append(pattern)
        return original(pattern, flags)

    monkeypatch.setattr(re, "compile", counted)
    return compiled


def test_a_check_of_a_small_file_compiles_no_state_s_alternation(monkeypatch: pytest.MonkeyPatch) -> None:
    """Compiling the states' patterns was a third of a cold check of create.rdis: only single
    terminals' patterns are compiled, once each, whichever states are met (each state's lexer
    asked, for a keyword or for what else it reads)."""
    _fresh_lexers(monkeypatch)
    compiled = _compiled_patterns(monkeypatch)
    asked = 0
    original_own, original_word = reduce.Lexer.own, reduce.Lexer.word

    def own(lexer: reduce.Lexer, text: str, pos: int) -> tuple[str, int] | None:
        nonlocal asked
        asked += 1
        return original_own(lexer, text, pos)

    def word(lexer: reduce.Lexer, name: str) -> str | None:
        nonlocal asked
        asked += 1
        return original_word(lexer, name)

    monkeypatch.setattr(reduce.Lexer, "own", own)
    monkeypatch.setattr(reduce.Lexer, "word", word)
    for path in (ROOT / "examples" / "create.rdis", stdlib_path()):
        parse(str(path), path.read_text(encoding="utf-8"), Diagnostics())
    assert asked > 30
    singles = set(tables.TERMINALS.values())
    assert [p for p in compiled if p not in singles] == [] and len(compiled) == len(set(compiled))


def test_a_state_s_lexer_asked_often_compiles_its_alternation_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """A large description asks a few states thousands of times: past ALONE, a state's lexer reads
    with its alternation, compiled once."""
    _fresh_lexers(monkeypatch)
    compiled = _compiled_patterns(monkeypatch)
    lexer = next(lexer for lexer in reduce._LEXERS if "ADAPTER" in lexer.terminals and "NAME" not in lexer.terminals)
    found = {lexer.own("adapter x", 0) for _ in range(reduce.ALONE * 3)}
    assert found == {("ADAPTER", 7)}
    assert [p for p in compiled if "|" in p and "(?P<ADAPTER>" in p] == [_alternation(lexer).pattern]


def test_the_loop_makes_a_token_only_where_the_builder_reads_its_place(monkeypatch: pytest.MonkeyPatch) -> None:
    """Keywords and punctuation are filtered out, and a name, number or word kept for its text alone
    (Rules.TEXT_ONLY) is given as its text: a Token (its text and place) is made only for the rest."""
    made: list[str] = []

    class Counted(reduce.Token):
        def __new__(cls, text: str) -> Self:
            made.append(text)
            return super().__new__(cls, text)

    monkeypatch.setattr(reduce, "Token", Counted)
    text = 'primitive move(speed: int) on link pack ">Bh" (0x89, speed * 2 + 1) timeout 20 ms\n'
    module = parse("t.rdis", text, Diagnostics())
    assert not module.damaged and len(module.decls) == 1
    # The names the Builder makes Idents of (with their spans), the string it decodes, the operators.
    assert sorted(made) == sorted(["move", "speed", "int", "link", '">Bh"', "*", "+"])


class _Forgetful(dict[Any, Any]):
    """A table of unit chains that keeps nothing: each is found again where it is met."""

    def __setitem__(self, key: Any, value: Any) -> None:
        pass


def test_the_loop_passes_an_operand_up_its_units_as_it_would_one_unit_at_a_time(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """The loop passes a value up a chain of `?rule`s of one symbol (an operand to an expression)
    in one step, from a table of where each chain ends found once per (state below, state, token
    kind): the trees, spans and diagnostics are those of making one unit reduction at a time, the
    same declarations are left to Lark, and the second parse of the same texts finds no chain again."""
    texts = [(str(path), path.read_text(encoding="utf-8")) for path in FILES]
    texts += [("t.rdis", text) for text in ONE_LINERS]

    def built() -> list[Any]:
        """Each text's tree and diagnostics, and how many of its declarations the loop left to Lark."""
        results = []
        for path, text in texts:
            left = 0

            def counted_retries(*args: Any, **kwargs: Any) -> Any:
                nonlocal left
                try:
                    return LOOP(*args, **kwargs)
                except reduce.Retry:
                    left += 1
                    raise

            monkeypatch.setattr(reduce, "parse_built", counted_retries)
            diagnostics = Diagnostics()
            tree = dump(parse(path, text, diagnostics))
            results.append((tree, [dump(d) for d in diagnostics.sorted()], left))
        return results

    found = []
    chain_end = reduce._pass_units

    def counted(below: int, state: int, kind: str) -> int:
        found.append((below, state, kind))
        return chain_end(below, state, kind)

    monkeypatch.setattr(reduce, "_CHAINS", {})
    monkeypatch.setattr(reduce, "_pass_units", counted)
    in_steps = built()
    first = len(found)
    assert built() == in_steps and len(found) == first > 0  # each chain found once, in the first parse

    def one_unit(below: int, state: int, kind: str) -> int:
        """The state after the first unit reduction only: the loop makes the next ones itself."""
        return tables.ACTIONS[below][reduce.UNITS[~tables.ACTIONS[state][kind]]]  # type: ignore[index]

    monkeypatch.setattr(reduce, "_CHAINS", _Forgetful())
    monkeypatch.setattr(reduce, "_pass_units", one_unit)
    assert built() == in_steps
