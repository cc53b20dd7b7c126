"""`format_text`: a description in the canonical layout, every comment kept where it was written.

Why a token-stream formatter, not the AST printer with comments attached: the formatter re-emits
the tokens the parser read, in their order and spelled as written (`0xFE` stays `0xFE`, a string
keeps its escapes, parentheses stay), and changes only the white space between them (and a list's
trailing comma). Every comment lies between two tokens, so it is attached to one of them and
written next to it: none can be lost, wherever it stands, and the formatted file parses to the
same declarations, by construction. The AST printer (rdisc/syntax/printer.py) respells literals
and has no place for a comment inside an expression or between a clause and its post-actions.
The *layout*, though, is the printer's: the tokens are grouped by the grammar's own parse tree,
and each construct is laid out as the printer lays it out (rdisc/format/layout.py).

Pure and fast enough for an editor: no files read or written, no state kept between calls (the
grammar's parser is made once, as `rdisc check`'s is).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rdisc.diagnostics import Diagnostic, Diagnostics, Severity

if TYPE_CHECKING:
    from rdisc.format.tokens import Tokens

__all__ = ["FormatError", "declarations", "format_text"]


class FormatError(Exception):
    """The text does not parse: its syntax errors (`diagnostics`), as `rdisc check` reports them."""

    def __init__(self, name: str, text: str, diagnostics: tuple[Diagnostic, ...]) -> None:
        first = diagnostics[0].message if diagnostics else "it does not parse"
        super().__init__(f"{name}: cannot be formatted: {first}")
        self.name = name
        self.text = text
        self.diagnostics = diagnostics


def format_text(text: str, name: str = "<text>") -> str:
    """`text` (a description called `name` in diagnostics) in the canonical layout; FormatError
    when it does not parse."""
    from rdisc.format.layout import lay_out

    tokens, errors = _read(text, name)
    if tokens is None:
        raise FormatError(name, text, errors)
    return lay_out(tokens.decls, tokens.end)


def declarations(text: str) -> list[tuple[int, int]]:
    """Where each declaration of `text` starts and ends (its first token's start, its last token's
    end, as character offsets), for formatting a part of a file; [] when it does not parse."""
    tokens, _ = _read(text, "<text>")
    if tokens is None:
        return []
    spans = []
    for decl in tokens.decls:
        leaves = decl.leaves()
        spans.append((leaves[0].start, leaves[-1].end))
    return spans


def _read(text: str, name: str) -> tuple[Tokens | None, tuple[Diagnostic, ...]]:
    """The text's tokens by declaration, or None and its syntax errors: parsed as `rdisc check`
    parses it, refused past the same token budget."""
    from rdisc.compile import _Tokens
    from rdisc.format.tokens import read_tokens
    from rdisc.syntax.parse import declaration_bounds

    diagnostics = Diagnostics()
    _Tokens().parse(name, text, diagnostics)
    if diagnostics.has_errors():
        return None, tuple(d for d in diagnostics.sorted() if d.severity is Severity.ERROR)
    return read_tokens(text, declaration_bounds(text)), ()
