"""A document's diagnostics as LSP sends them: those of its own file from its latest check, in
the shape `rdisc check --format json` gives (rdisc.diagnostics.lsp), codes, related places and
did-you-mean (`data.help`) included."""

from __future__ import annotations

from typing import Any

from lsprotocol import types

from rdisc.diagnostics.lsp import to_lsp
from rdisc.editor.documents import Analysis, Document


def published(document: Document, analysis: Analysis) -> list[types.Diagnostic]:
    """The diagnostics of the document's file (one without a place, at its start)."""
    items = analysis.compilation.diagnostics.sorted()
    mine = [d for d in items if d.span is None or d.span.path == document.path]
    return [_diagnostic(item) for item in to_lsp(mine, analysis.compilation.sources)]


def _range(shape: dict[str, dict[str, int]]) -> types.Range:
    return types.Range(start=types.Position(**shape["start"]), end=types.Position(**shape["end"]))


def _diagnostic(item: dict[str, Any]) -> types.Diagnostic:
    return types.Diagnostic(
        range=_range(item["range"]),
        severity=types.DiagnosticSeverity(item["severity"]),
        code=item["code"],
        source=item["source"],
        message=item["message"],
        related_information=[
            types.DiagnosticRelatedInformation(
                location=types.Location(uri=related["location"]["uri"], range=_range(related["location"]["range"])),
                message=related["message"])
            for related in item["relatedInformation"]
        ] or None,
        data=item["data"],
    )
