"""The syntax stage: AST construction, literals, doc comments, errors in words, recovery."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.diagnostics import Diagnostics
from rdisc.diagnostics.text import render_plain
from rdisc.source import Sources
from rdisc.syntax import ast
from rdisc.syntax import parse as parse_module
from rdisc.syntax.build import MAX_EXPR_DEPTH
from rdisc.syntax.parse import parse

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def parsed(text: str) -> tuple[ast.Module, Diagnostics]:
    diagnostics = Diagnostics()
    return parse("t.rdis", text, diagnostics), diagnostics


def rendered(text: str) -> str:
    _module, diagnostics = parsed(text)
    sources = Sources()
    sources.add("t.rdis", text)
    return render_plain(diagnostics.sorted(), sources)


def only_expr(text: str) -> ast.Expr:
    module, diagnostics = parsed(f"state x: int = {text}\n")
    assert not diagnostics.items, diagnostics.items
    decl = module.decls[0]
    assert isinstance(decl, ast.StateDecl) and decl.init is not None
    return decl.init


@pytest.mark.parametrize(
    ("text", "value"),
    [("0x1F", 31), ("0b1010", 10), ("0o17", 15), ("1_000", 1000), ("2.5", 2.5), ("1e3", 1000.0), (".5", 0.5),
     ('"a\\n\\x41\\u00e9"', "a\nAé"), ('r"\\d+"', "\\d+"), ("True", True), ("False", False)],
)
def test_literals(text: str, value: object) -> None:
    lit = only_expr(text)
    assert isinstance(lit, (ast.IntLit, ast.FloatLit, ast.StrLit, ast.BoolLit))
    assert lit.value == value and type(lit.value) is type(value)


def test_precedence_follows_python() -> None:
    assert only_expr("-2 ** 2") == ast.Unary("-", ast.BinOp("**", ast.IntLit(2), ast.IntLit(2)))
    assert only_expr("1 + 2 * 3 << 1") == ast.BinOp(
        "<<", ast.BinOp("+", ast.IntLit(1), ast.BinOp("*", ast.IntLit(2), ast.IntLit(3))), ast.IntLit(1)
    )
    assert only_expr("a if not b or c else d") == ast.Conditional(
        ast.Ref("a"), ast.BinOp("or", ast.Unary("not", ast.Ref("b")), ast.Ref("c")), ast.Ref("d")
    )


def test_doc_comments_travel_to_their_declaration() -> None:
    module, diagnostics = parsed(
        "/// The bumpers.\n/// Bit 0 right.\n# not a doc\nstate b: int = 0\n"
        "adapter A {\n  /// metres\n  d: float unit \"m\"\n}\n"
    )
    assert not diagnostics.items
    state, adapter = module.decls
    assert isinstance(state, ast.StateDecl) and state.doc == "The bumpers.\nBit 0 right."
    assert isinstance(adapter, ast.AdapterDecl) and adapter.fields[0].doc == "metres"


def test_spans_are_absolute_offsets() -> None:
    text = "state a: int = 0\nstate bee: int = 1\n"
    module, _ = parsed(text)
    name = module.decls[1].name  # type: ignore[union-attr]
    assert text[name.span.start : name.span.end] == "bee"


def test_a_syntax_error_costs_only_its_declaration() -> None:
    module, diagnostics = parsed(
        'state a: int = = 0\nprimitive p() on c pack "B" (1\nstate ok: int = 1\nstate b: int = )\n'
    )
    assert [d.code for d in diagnostics.sorted()] == ["E001", "E001", "E001"]
    assert [d.name.text for d in module.decls] == ["ok"]  # type: ignore[union-attr]
    assert [(d.keyword, d.name.text) for d in module.damaged] == [("state", "a"), ("primitive", "p"), ("state", "b")]


def test_errors_say_what_was_expected_in_words() -> None:
    assert rendered("connection c: serial { baud 9600 speed 3 }\n") == """\
error[E001]: expected `address`, `baud`, `databits`, `keepalive`, `parity`, a closing `}`, `startup`, `stopbits`, `terminate`, `terminator` or `threading`, found `speed`
 --> t.rdis:1:34
  |
1 | connection c: serial { baud 9600 speed 3 }
  |                                  ^^^^^

1 error emitted"""


def test_an_unfinished_declaration_is_reported_where_the_next_begins() -> None:
    assert rendered('primitive p(x: int) on c pack ">h" (x\ninterface i() { p(1) }\n') == """\
error[E001]: expected `,` or a closing `)` before the next declaration
 --> t.rdis:2:1
  |
2 | interface i() { p(1) }
  | ^ the declaration before this one is not finished

1 error emitted"""


def test_end_of_file_errors_are_placed_at_the_end() -> None:
    text = "output o: Range { distance = 1.0\n"
    _, diagnostics = parsed(text)
    (d,) = diagnostics.items
    assert d.message == "expected a name or a closing `}`, found the end of the file"
    assert d.span is not None and d.span.start == len(text)


@pytest.mark.parametrize(
    ("text", "code", "message"),
    [
        ('state s: string = "abc\n', "E002", "unterminated string"),
        ("state s: int = __import__\n", "E002", "names cannot start with `_`"),
        ("state s: int = a@b\n", "E002", "unexpected character `@`"),
        ('state s: string = "a\\q"\n', "E003", "unknown escape `\\q` in a string"),
        ("state s: int = 0099\n", "E004", "invalid integer literal `0099`"),
        ("state s: int = " + "9" * 80 + "\n", "E004", "invalid integer literal `999999999999999999999...`"),
        ("state s: float = 1e999\n", "E004", "invalid float literal `1e999`"),
        ("state s: int = 1 +\n", "E001", "expected an expression, found the end of the file"),
    ],
)
def test_lexical_errors(text: str, code: str, message: str) -> None:
    _, diagnostics = parsed(text)
    assert [(d.code, d.message) for d in diagnostics.items] == [(code, message)]


def test_deep_nesting_is_refused_before_it_is_walked() -> None:
    depth = MAX_EXPR_DEPTH + 10
    _, diagnostics = parsed("state s: int = " + "-" * depth + "1\nstate t: int = " + "(" * 10_000 + "1" + ")" * 10_000)
    assert [d.code for d in diagnostics.items] == ["E005", "E005"]
    assert diagnostics.items[0].message == f"expression is nested too deeply (the limit is {MAX_EXPR_DEPTH} levels)"


def test_clause_keywords_are_names_where_a_name_is_expected() -> None:
    """`baud`, `length`, `mask` ... after an expression are names, not the start of a clause."""
    module, diagnostics = parsed(
        'primitive get() on bus pack "B" (1) unpack "BBB" { a = out[0]  baud = out[1]  length = out[2] + mask }\n'
    )
    assert list(diagnostics.items) == []
    actions = module.decls[0].clauses[-1]
    assert [a.target.text for a in actions.assigns] == ["a", "baud", "length"]
    assert actions.assigns[2].value == ast.BinOp("+", ast.Index(ast.Ref("out"), ast.IntLit(2)), ast.Ref("mask"))


@pytest.mark.parametrize(
    ("text", "help"),
    [
        ('primtive p() on c pack "B" (1)\n', "did you mean `primitive`?"),
        ("conection c: serial { baud 9600 }\n", "did you mean `connection`?"),
        ('primitive p() on c pack "B" (1) unpakc "B"\n', "did you mean `unpack`?"),
        ("connection c: serial { baud 9600 treminator 10 }\n", "did you mean `terminator`?"),
        ("// a comment as in C\nstate s: int = 0\n", "comments start with `#`, and doc comments with `///`"),
        ("/* a comment as in C */\nstate s: int = 0\n", "comments start with `#`, and doc comments with `///`"),
        ("state s: int = 0\nbanana b\n", None),  # nothing close: no guess
    ],
)
def test_a_slip_gets_help(text: str, help: str | None) -> None:
    _, diagnostics = parsed(text)
    assert [d.help for d in diagnostics.items] == [help]


def test_an_expression_tree_builds_the_expression_an_embedded_one_parses_to() -> None:
    """`build_expression` (an `expr_start` tree, as a JSON string holds one) gives the node, with
    its spans, that `parse_expression` gives for the same text and offset."""
    from rdisc.syntax.build import Builder, build_expression
    from rdisc.syntax.parse import parse_expression, parser

    for text in ("1 + 2 * -x", "y", "[1, 2][i] if ok else f(3)"):
        built = build_expression(Builder("t.json", {}, Diagnostics()), parser().parse(text, start="expr_start"), 10)
        expected = parse_expression("t.json", text, 10, Diagnostics())
        assert expected is not None
        assert built == expected and built.span == expected.span, (built, expected)


def test_tokens_are_counted_across_blocks_of_lines_as_one_at_a_time() -> None:
    """token_count finds a block of lines' tokens at once: the count is the one-at-a-time count,
    and it stops past `most`."""
    line = 'primitive p_1(a: int) on link format "M{},{}\\n" (a, 0x1F) # note\n'
    text = line * (3 * parse_module._TOKEN_BLOCK // len(line) + 7) + "x"
    one_at_a_time = sum(1 for _ in parse_module._TOKEN.finditer(text))
    assert one_at_a_time > 3 * parse_module._TOKEN_BLOCK // len(line) * 10
    assert parse_module.token_count(text, 10**9) == one_at_a_time
    assert parse_module.token_count(text, one_at_a_time) == one_at_a_time
    assert parse_module.token_count(text, one_at_a_time - 1) == one_at_a_time
    assert parse_module.token_count(text, 5) == 6


@pytest.mark.parametrize("text", ["/// a\nx", "  /// a\n\t/// b\n\ny /// not\n", "a /// b\n/// c", "//// d",
                                  "x\n   ///", "/ // ///", "#/// a\n///b\r\n///c"])
def test_doc_comment_runs_are_found_as_the_pattern_finds_them(text: str) -> None:
    assert [m.span() for m in parse_module._doc_runs(text)] == \
        [m.span() for m in parse_module._DOC_RUN.finditer(text)]


def test_patterns_only_some_descriptions_need_are_compiled_when_first_needed() -> None:
    """A string's escapes, bytes, a damaged declaration's name: their patterns are compiled for the
    first description that has them (rdisc.patterns), not when rdisc is imported, and then kept."""
    from rdisc import patterns
    from rdisc.compile import compile_text

    patterns.pattern.cache_clear()
    compile_text("plain.rdis", 'robot r { author "a" }\nstate s: int = 1\n')
    assert patterns.pattern.cache_info().currsize == 0
    for _ in range(2):
        compile_text("odd.rdis", 'robot r { author "a\\tb" }\nstate b: bytes = b"\\x01"\nstate s: int = \n')
    # Escapes, bytes, and for the damaged `s` its name and a keyword read as a name (Lark's recovery): once each.
    assert patterns.pattern.cache_info().currsize == 4


def test_declarations_are_cut_at_each_keyword_that_starts_a_line() -> None:
    """`declaration_bounds` cuts where DECL_START (the editor's pattern) finds a keyword at a line's start,
    and at 0 whatever is there."""
    from rdisc.syntax.parse import DECL_START, declaration_bounds

    texts = ["", "state a: int = 0", "\n\nstate a: int = 0\n", "# c\nstate a: int\n state b\nstates c\nprimitive\n",
             "robot r {}\r\nconst C = 1\n\n\nenum E { A }\ninput", *(p.read_text(encoding="utf-8") for p in sorted(EXAMPLES.glob("*.rdis")))]
    for text in texts:
        starts = sorted({0, *(m.start() for m in DECL_START.finditer(text))})
        assert declaration_bounds(text) == list(zip(starts, [*starts[1:], len(text)]))
