"""Code actions: each diagnostic's did-you-mean (`help: did you mean `NAME`?`, as the resolver,
the checker and the parser write it) is a quick fix putting the suggestion where the diagnostic
points; inside a string (a unit, an algorithm's name), in place of its text."""

from __future__ import annotations

import re

from lsprotocol import types

from rdisc.editor import positions
from rdisc.source import SourceFile, Span

_SUGGESTION = re.compile(r"did you mean `([^`\n]+)`\?")


def suggestion(diagnostic: types.Diagnostic) -> str | None:
    """The name a diagnostic's help suggests, if it suggests one."""
    data = diagnostic.data if isinstance(diagnostic.data, dict) else {}
    found = _SUGGESTION.search(str(data.get("help", "")))
    return found.group(1) if found else None


def quick_fixes(uri: str, source: SourceFile, diagnostics: list[types.Diagnostic]) -> list[types.CodeAction]:
    fixes = []
    for diagnostic in diagnostics:
        name = suggestion(diagnostic)
        if name is None:
            continue
        start, end = (positions.offset(source, diagnostic.range.start), positions.offset(source, diagnostic.range.end))
        written = source.text[start:end]
        place = diagnostic.range
        if len(written) >= 2 and written[0] == written[-1] == '"':  # a string: its text replaced
            place = positions.to_range(source, Span(source.path, start + 1, end - 1))
        fixes.append(types.CodeAction(
            title=f"Change to `{name}`",
            kind=types.CodeActionKind.QuickFix,
            diagnostics=[diagnostic],
            is_preferred=True,
            edit=types.WorkspaceEdit(changes={uri: [types.TextEdit(range=place, new_text=name)]}),
        ))
    return fixes

