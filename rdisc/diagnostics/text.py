"""Diagnostics as text for people: the header, the source lines, carets, help.

One diagnostic looks like this (a blank line separates diagnostics):

    error[E102]: unknown primitive `drve`
      --> examples/create.rdis:41:5
       |
    41 |     drve(velocity, radius)
       |     ^^^^ no primitive of this name
       |
       = help: did you mean `drive`?

Columns in the `-->` line are 1-based code points. Secondary labels are underlined
with `-`; those in the primary file share its header, in source order with the
primary line (`...` marks skipped lines); those in other files get a `:::` header
each file. After all diagnostics comes one summary line, e.g.
`2 errors, 1 warning emitted` (`1 error emitted`, `3 warnings emitted`), absent
when there is neither. The result has no trailing newline: printing adds one.

The layout is built once as styled segments, so `render` (rich) and
`render_plain` (golden tests, pipes) cannot drift apart. rich is imported inside
`render` only: a clean `rdisc check` never pays for it.
"""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rdisc.diagnostics.core import Diagnostic, Severity
from rdisc.source import Sources, Span

if TYPE_CHECKING:
    from rich.text import Text

_Segment = tuple[str, str]  # (text, rich style; "" for none)
_Line = list[_Segment]

_TAB = "    "
_WORDS = {
    Severity.ERROR: ("error", "bold red"),
    Severity.WARNING: ("warning", "bold yellow"),
    Severity.INFORMATION: ("info", "bold blue"),
    Severity.HINT: ("hint", "bold cyan"),
}
_GUTTER = "bold blue"


def render(diagnostics: list[Diagnostic], sources: Sources) -> Text:
    """The diagnostics, styled for a terminal, in the order given."""
    from rich.text import Text

    text = Text()
    for i, line in enumerate(_layout(diagnostics, sources)):
        if i:
            text.append("\n")
        for part, style in line:
            text.append(part, style or None)
    return text


def render_plain(diagnostics: list[Diagnostic], sources: Sources) -> str:
    """The same text as `render`, without styles."""
    return "\n".join("".join(part for part, _ in line) for line in _layout(diagnostics, sources))


def summary(errors: int, warnings: int) -> str | None:
    """`2 errors, 1 warning emitted`; None when there is nothing to count."""
    parts = [_plural(n, word) for n, word in ((errors, "error"), (warnings, "warning")) if n]
    return ", ".join(parts) + " emitted" if parts else None


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def _layout(diagnostics: list[Diagnostic], sources: Sources) -> list[_Line]:
    lines: list[_Line] = []
    for diagnostic in diagnostics:
        if lines:
            lines.append([])
        lines.extend(_diagnostic(diagnostic, sources))
    errors = sum(1 for d in diagnostics if d.severity is Severity.ERROR)
    warnings = sum(1 for d in diagnostics if d.severity is Severity.WARNING)
    total = summary(errors, warnings)
    if total:
        lines += [[], [(total, "bold")]]
    return lines


@dataclass(frozen=True, slots=True)
class _Mark:
    """One underlined place: where, with which character, saying what."""

    span: Span
    char: str  # "^" primary, "-" secondary
    message: str | None


def _diagnostic(d: Diagnostic, sources: Sources) -> list[_Line]:
    word, style = _WORDS[d.severity]
    lines: list[_Line] = [[(f"{word}[{d.code}]", style), (f": {d.message}", "bold")]]
    if d.span is None:
        return lines
    marks = [_Mark(d.span, "^", d.label)] + [_Mark(lab.span, "-", lab.message) for lab in d.labels]
    primary = d.span.path
    others = sorted({m.span.path for m in marks} - {primary})
    groups = [(p, sorted((m for m in marks if m.span.path == p), key=_order)) for p in [primary, *others]]
    width = max(len(str(_line_of(m.span, sources) + 1)) for m in marks)
    pad = " " * width
    for path, group in groups:
        head = d.span if path == primary else group[0].span
        if path != primary:
            lines.append([(pad + " |", _GUTTER)])
        arrow = "-->" if path == primary else ":::"
        lines.append([(f"{pad}{arrow} ", _GUTTER), (_location(head, sources), "")])
        if path in sources:
            lines.append([(pad + " |", _GUTTER)])
            lines.extend(_excerpt(group, sources, width, style))
    if d.help:
        lines.append([(pad + " |", _GUTTER)])
        lines.append([(pad + " = ", _GUTTER), ("help", "bold"), (f": {d.help}", "")])
    return lines


def _order(mark: _Mark) -> tuple[int, int]:
    return (mark.span.start, mark.span.end)


def _line_of(span: Span, sources: Sources) -> int:
    source = sources.get(span.path)
    return source.position(span.start).line if source else 0


def _location(span: Span, sources: Sources) -> str:
    source = sources.get(span.path)
    if source is None:
        return span.path
    position = source.position(span.start)
    return f"{span.path}:{position.line + 1}:{position.column + 1}"


def _excerpt(marks: list[_Mark], sources: Sources, width: int, style: str) -> list[_Line]:
    """Each marked line once, then one underline row per mark on it."""
    source = sources[marks[0].span.path]
    lines: list[_Line] = []
    previous: int | None = None
    cut = 0
    for mark in marks:
        start = source.position(mark.span.start)
        text = source.line_text(start.line)
        if start.line != previous:
            if previous is not None and start.line > previous + 1:
                lines.append([("...", _GUTTER)])
            cut = _cut(text, start.column)
            text = _window(text, cut)
            shown = " " + text.replace("\t", _TAB) if text else ""
            lines.append([(f"{start.line + 1:>{width}} |", _GUTTER), (shown, "")])
            previous = start.line
        else:
            text = _window(text, cut)
        end = source.position(mark.span.end)
        stop = end.column if end.line == start.line else len(text) + cut
        column = max(0, start.column - cut)
        stop = max(column, min(stop - cut, len(text)))
        carets = mark.char * max(1, _width(text[column:stop]))
        mark_style = style if mark.char == "^" else _GUTTER
        row: _Line = [(" " * width + " |", _GUTTER), (" " + " " * _width(text[:column]), "")]
        row.append((carets + (f" {mark.message}" if mark.message else ""), mark_style))
        lines.append(row)
    return lines


_EXCERPT = 160  # columns of a long line shown around its mark


def _cut(text: str, column: int) -> int:
    """Where a long line's window starts (less one, for the `…` that stands for what is cut)."""
    if len(text) <= _EXCERPT:
        return 0
    begin = max(0, min(column - 40, len(text) - _EXCERPT))
    return begin - 1 if begin else 0


def _window(text: str, cut: int) -> str:
    """A long line cut to the window that starts after `cut` characters, `…` where it is cut."""
    if len(text) <= _EXCERPT:
        return text
    head = "…" if cut else ""
    body = text[cut + len(head): cut + len(head) + _EXCERPT]
    return head + body + ("…" if cut + len(head) + _EXCERPT < len(text) else "")


def _width(text: str) -> int:
    """Terminal cells: tabs show as four spaces, wide characters (emoji, CJK) as two."""
    return sum(_cells(ch) for ch in text)


def _cells(ch: str) -> int:
    if ch == "\t":
        return len(_TAB)
    if unicodedata.combining(ch):
        return 0
    return 2 if unicodedata.east_asian_width(ch) in ("W", "F") else 1
