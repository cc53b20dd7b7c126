"""Diagnostics are data: made by every stage, rendered by `text` and `lsp`."""

from rdisc.diagnostics.core import Diagnostic, Diagnostics, Label, Severity, abbreviate

__all__ = ["Diagnostic", "Diagnostics", "Label", "Severity", "abbreviate"]
