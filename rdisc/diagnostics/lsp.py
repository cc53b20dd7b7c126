"""Diagnostics as JSON-ready dicts in the shape of LSP `Diagnostic` objects.

Editors get each diagnostic with its file (LSP groups diagnostics by document, so
the consumer needs it): lines 0-based, characters in UTF-16 code units as LSP
counts them. Keys come in a fixed order so the JSON output is stable:

    file, range, severity, code, source, message, relatedInformation, data

`file` is the span's path as given (None for a diagnostic without a span, whose
range is 0:0-0:0). `relatedInformation` holds the secondary labels in the order
they were reported, with file URIs. `data` has the code's kebab-case `name`,
then `label` (the primary label's text) and `help` when set.
"""

from __future__ import annotations

import pathlib
from typing import Any

from rdisc.diagnostics.core import Diagnostic
from rdisc.source import Sources, Span


def to_lsp(diagnostics: list[Diagnostic], sources: Sources) -> list[dict[str, Any]]:
    """One LSP-shaped dict per diagnostic, in the order given."""
    return [_diagnostic(d, sources) for d in diagnostics]


def _diagnostic(d: Diagnostic, sources: Sources) -> dict[str, Any]:
    data: dict[str, str] = {"name": d.name}
    if d.label is not None:
        data["label"] = d.label
    if d.help is not None:
        data["help"] = d.help
    return {
        "file": d.span.path if d.span else None,
        "range": _range(d.span, sources),
        "severity": int(d.severity),
        "code": d.code,
        "source": "rdisc",
        "message": d.message,
        "relatedInformation": [
            {
                "location": {
                    "uri": pathlib.Path(label.span.path).resolve().as_uri(),
                    "range": _range(label.span, sources),
                },
                "message": label.message,
            }
            for label in d.labels
        ],
        "data": data,
    }


def _range(span: Span | None, sources: Sources) -> dict[str, dict[str, int]]:
    """0-based line and UTF-16 character of both ends; 0:0-0:0 when unknown."""
    source = sources.get(span.path) if span else None
    if span is None or source is None:
        zero = {"line": 0, "character": 0}
        return {"start": zero, "end": dict(zero)}
    start, end = source.position(span.start), source.position(span.end)
    return {
        "start": {"line": start.line, "character": start.utf16_column},
        "end": {"line": end.line, "character": end.utf16_column},
    }
