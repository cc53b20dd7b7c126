"""Exact text and LSP shapes of rendered diagnostics, over small hand-built sources."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from textwrap import dedent

from rdisc.diagnostics import Diagnostic, Label, Severity
from rdisc.diagnostics.lsp import to_lsp
from rdisc.diagnostics.text import render, render_plain, summary
from rdisc.source import Sources, Span


def block(text: str) -> str:
    """The expected rendering: dedented, without the surrounding newlines."""
    return dedent(text).strip("\n")


def span(sources: Sources, path: str, needle: str, length: int | None = None, nth: int = 0) -> Span:
    """The span of the nth occurrence of `needle` (or `length` characters from it)."""
    text = sources[path].text
    start = -1
    for _ in range(nth + 1):
        start = text.index(needle, start + 1)
    return Span(path, start, start + (len(needle) if length is None else length))


def error(
    code: str,
    message: str,
    at: Span | None,
    label: str | None = None,
    labels: tuple[Label, ...] = (),
    help: str | None = None,
) -> Diagnostic:
    return Diagnostic(code, Severity.ERROR, message, at, label, labels, help)


def create_file() -> Sources:
    sources = Sources()
    sources.add("examples/create.rdis", "robot create\n" * 40 + "    drve(velocity, radius)\n")
    return sources


def test_the_documented_example() -> None:
    sources = create_file()
    d = error(
        "E102",
        "unknown primitive `drve`",
        span(sources, "examples/create.rdis", "drve"),
        label="no primitive of this name",
        help="did you mean `drive`?",
    )
    assert render_plain([d], sources) == block("""
        error[E102]: unknown primitive `drve`
          --> examples/create.rdis:41:5
           |
        41 |     drve(velocity, radius)
           |     ^^^^ no primitive of this name
           |
           = help: did you mean `drive`?

        1 error emitted
        """)


def test_gutter_is_one_wide_for_short_files_and_no_label_no_help() -> None:
    sources = Sources()
    sources.add("a.rdis", "robot r\nstate n: int = 1\n")
    d = Diagnostic("W103", Severity.WARNING, "state `n` is never read", span(sources, "a.rdis", "n:", 1))
    assert render_plain([d], sources) == block("""
        warning[W103]: state `n` is never read
         --> a.rdis:2:7
          |
        2 | state n: int = 1
          |       ^

        1 warning emitted
        """)


def test_gutter_width_follows_the_largest_line_shown() -> None:
    sources = Sources()
    sources.add("a.rdis", "".join(f"line{i}\n" for i in range(1, 121)))
    d = error(
        "E101",
        "duplicate primitive `p`",
        span(sources, "a.rdis", "line120"),
        label="declared again",
        labels=(Label(span(sources, "a.rdis", "line9"), "first declared here"),),
    )
    assert render_plain([d], sources) == block("""
        error[E101]: duplicate primitive `p`
           --> a.rdis:120:1
            |
          9 | line9
            | ----- first declared here
        ...
        120 | line120
            | ^^^^^^^ declared again

        1 error emitted
        """)


def test_empty_multi_line_and_end_of_file_spans() -> None:
    sources = Sources()
    text = sources.add("a.rdis", "on x {\n  y\n}\n").text
    empty = error("E001", "empty", Span("a.rdis", 3, 3))
    multi = error("E001", "multi", Span("a.rdis", 5, len(text)), label="here")
    at_end = Span("a.rdis", len(text), len(text))
    eof = error("E001", "expected a closing `}`, found the end of the file", at_end)
    assert render_plain([empty, multi, eof], sources) == block("""
        error[E001]: empty
         --> a.rdis:1:4
          |
        1 | on x {
          |    ^

        error[E001]: multi
         --> a.rdis:1:6
          |
        1 | on x {
          |      ^ here

        error[E001]: expected a closing `}`, found the end of the file
         --> a.rdis:4:1
          |
        4 |
          | ^

        3 errors emitted
        """)


def test_secondary_labels_in_the_same_file_are_in_source_order() -> None:
    sources = Sources()
    sources.add("a.rdis", "primitive p()\nprimitive q()\n\n\nprimitive p(x)\n")
    d = error(
        "E101",
        "duplicate primitive `p`",
        span(sources, "a.rdis", "p(", 1, nth=1),
        label="declared again",
        labels=(
            Label(span(sources, "a.rdis", "(x)"), "with other parameters"),
            Label(span(sources, "a.rdis", "q"), "unrelated"),
            Label(span(sources, "a.rdis", "p(", 1), "first declared here"),
        ),
    )
    assert render_plain([d], sources) == block("""
        error[E101]: duplicate primitive `p`
         --> a.rdis:5:11
          |
        1 | primitive p()
          |           - first declared here
        2 | primitive q()
          |           - unrelated
        ...
        5 | primitive p(x)
          |           ^ declared again
          |            --- with other parameters

        1 error emitted
        """)


def test_secondary_labels_in_other_files_get_their_own_header() -> None:
    sources = Sources()
    sources.add("main.rdis", "import \"lib.rdis\"\nprimitive ping() on serial\n")
    sources.add("lib.rdis", "adapter a {}\nprimitive ping() on serial\n")
    sources.add("zoo.rdis", "primitive ping() on serial\n")
    d = error(
        "E101",
        "duplicate primitive `ping`",
        span(sources, "main.rdis", "ping"),
        labels=(
            Label(span(sources, "zoo.rdis", "ping"), "and here"),
            Label(span(sources, "lib.rdis", "ping"), "first declared here"),
        ),
        help="rename one of them",
    )
    assert render_plain([d], sources) == block("""
        error[E101]: duplicate primitive `ping`
         --> main.rdis:2:11
          |
        2 | primitive ping() on serial
          |           ^^^^
          |
         ::: lib.rdis:2:11
          |
        2 | primitive ping() on serial
          |           ---- first declared here
          |
         ::: zoo.rdis:1:11
          |
        1 | primitive ping() on serial
          |           ---- and here
          |
          = help: rename one of them

        1 error emitted
        """)


def test_tabs_show_as_four_spaces_and_carets_follow() -> None:
    sources = Sources()
    sources.add("t.rdis", "\tpack\t\">Bhh\"\n")
    d = error("E301", "bad", span(sources, "t.rdis", "\t\">"), label="tab included")
    assert render_plain([d], sources) == block("""
        error[E301]: bad
         --> t.rdis:1:6
          |
        1 |     pack    ">Bhh"
          |         ^^^^^^ tab included

        1 error emitted
        """)


def test_astral_characters_are_one_column_and_two_cells() -> None:
    sources = Sources()
    sources.add("e.rdis", 'state s: string = "😀" x\n')
    d = error("E001", "unexpected name", span(sources, "e.rdis", "x"), label="here")
    # Code point 22 (column 23), terminal cell 23: the emoji is two cells wide.
    assert render_plain([d], sources) == block("""
        error[E001]: unexpected name
         --> e.rdis:1:23
          |
        1 | state s: string = "😀" x
          |                        ^ here

        1 error emitted
        """)
    [lsp] = to_lsp([d], sources)
    assert lsp["range"] == {"start": {"line": 0, "character": 23}, "end": {"line": 0, "character": 24}}


def test_no_span_prints_one_line_and_warnings_count() -> None:
    sources = Sources()
    diagnostics = [
        error("E107", "no `robot` declaration", None, help="add one"),
        Diagnostic("W101", Severity.WARNING, "a", None),
        Diagnostic("W102", Severity.WARNING, "b", None),
    ]
    assert render_plain(diagnostics, sources) == block("""
        error[E107]: no `robot` declaration

        warning[W101]: a

        warning[W102]: b

        1 error, 2 warnings emitted
        """)


def test_summary_wording() -> None:
    assert summary(2, 1) == "2 errors, 1 warning emitted"
    assert summary(1, 0) == "1 error emitted"
    assert summary(0, 3) == "3 warnings emitted"
    assert summary(0, 0) is None
    assert render_plain([], Sources()) == ""


def test_styled_text_matches_plain_and_colours_the_severity() -> None:
    sources = create_file()
    at = span(sources, "examples/create.rdis", "drve")
    diagnostics = [
        error("E102", "unknown primitive `drve`", at, label="no primitive"),
        Diagnostic("W103", Severity.WARNING, "unused", at),
    ]
    text = render(diagnostics, sources)
    assert text.plain == render_plain(diagnostics, sources)
    styled = {text.plain[s.start : s.end]: str(s.style) for s in text.spans}
    assert styled["error[E102]"] == "bold red"
    assert styled["warning[W103]"] == "bold yellow"
    assert styled["^^^^ no primitive"] == "bold red"


def test_importing_the_renderers_does_not_import_rich() -> None:
    code = (
        "import sys, rdisc.diagnostics.text, rdisc.diagnostics.lsp;"
        "print(any(m.startswith('rich') for m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_lsp_shape() -> None:
    sources = Sources()
    sources.add("a.rdis", "primitive p()\nprimitive p()\n")
    d = error(
        "E101",
        "duplicate primitive `p`",
        span(sources, "a.rdis", "p()", 1, nth=1),
        label="declared again",
        labels=(Label(span(sources, "a.rdis", "p()", 1), "first declared here"),),
        help="rename one",
    )
    w = Diagnostic("W103", Severity.WARNING, "unread", Span("missing.rdis", 5, 9))
    plain = error("E107", "no `robot` declaration", None)
    assert to_lsp([d, w, plain], sources) == [
        {
            "file": "a.rdis",
            "range": {"start": {"line": 1, "character": 10}, "end": {"line": 1, "character": 11}},
            "severity": 1,
            "code": "E101",
            "source": "rdisc",
            "message": "duplicate primitive `p`",
            "relatedInformation": [
                {
                    "location": {
                        "uri": Path("a.rdis").resolve().as_uri(),
                        "range": {"start": {"line": 0, "character": 10}, "end": {"line": 0, "character": 11}},
                    },
                    "message": "first declared here",
                }
            ],
            "data": {"name": "duplicate-name", "label": "declared again", "help": "rename one"},
        },
        {
            "file": "missing.rdis",
            "range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}},
            "severity": 2,
            "code": "W103",
            "source": "rdisc",
            "message": "unread",
            "relatedInformation": [],
            "data": {"name": "unread-state"},
        },
        {
            "file": None,
            "range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}},
            "severity": 1,
            "code": "E107",
            "source": "rdisc",
            "message": "no `robot` declaration",
            "relatedInformation": [],
            "data": {"name": "robot-declaration"},
        },
    ]
    keys = ["file", "range", "severity", "code", "source", "message", "relatedInformation", "data"]
    assert [list(item) for item in to_lsp([d, plain], sources)] == [keys, keys]
    assert list(to_lsp([d], sources)[0]["data"]) == ["name", "label", "help"]


def test_lsp_multi_line_range_counts_utf16_units() -> None:
    sources = Sources()
    sources.add("u.rdis", 'a = "😀😀" {\n  b }\n')
    [lsp] = to_lsp([error("E001", "m", span(sources, "u.rdis", "{\n  b"))], sources)
    assert lsp["range"] == {"start": {"line": 0, "character": 11}, "end": {"line": 1, "character": 3}}
