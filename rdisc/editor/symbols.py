"""The outline (document symbols), folding ranges and semantic tokens of a document, from the
declarations that parsed: a syntax error costs only the declaration it is in, so a document
with one still has the rest of its outline."""

from __future__ import annotations

import bisect

from lsprotocol import types

from rdisc.editor import positions
from rdisc.editor.documents import Analysis
from rdisc.editor.index import KINDS, Occurrence
from rdisc.source import SourceFile, Span
from rdisc.syntax import ast

_SYMBOL_KINDS = {
    "robot": types.SymbolKind.Module, "state variable": types.SymbolKind.Variable,
    "setting": types.SymbolKind.Property, "connection": types.SymbolKind.Namespace,
    "primitive": types.SymbolKind.Function, "interface": types.SymbolKind.Method,
    "adapter": types.SymbolKind.Struct, "input": types.SymbolKind.Event, "output": types.SymbolKind.Event,
    "constant": types.SymbolKind.Constant, "enum": types.SymbolKind.Enum, "frame": types.SymbolKind.Class,
    "link": types.SymbolKind.Object, "joint": types.SymbolKind.Object, "transmission": types.SymbolKind.Object,
    "parameter": types.SymbolKind.TypeParameter, "field": types.SymbolKind.Field,
    "enum member": types.SymbolKind.EnumMember, "sensor": types.SymbolKind.Variable,
    "actuator": types.SymbolKind.Object,
}

# Semantic token types and modifiers, in the legend's order (their index is what is sent).
TOKEN_TYPES = ["function", "method", "variable", "parameter", "property", "enum", "enumMember", "struct",
               "class", "namespace", "event", "type"]
TOKEN_MODIFIERS = ["declaration", "readonly", "defaultLibrary"]
LEGEND = types.SemanticTokensLegend(token_types=TOKEN_TYPES, token_modifiers=TOKEN_MODIFIERS)
_TOKEN_OF_KIND = {
    "primitive": "function", "interface": "method", "state variable": "variable", "setting": "variable",
    "constant": "variable", "loop variable": "variable", "parameter": "parameter", "field": "property",
    "enum": "enum", "enum member": "enumMember", "adapter": "struct", "frame": "type", "connection": "namespace",
    "input": "event", "output": "event", "link": "class", "joint": "class", "transmission": "class", "robot": "namespace",
    "sensor": "variable", "actuator": "class",
}
_READONLY = {"setting", "constant", "enum member"}


def _main(analysis: Analysis) -> ast.Module | None:
    return analysis.compilation.main


def document_symbols(analysis: Analysis) -> list[types.DocumentSymbol]:
    module = _main(analysis)
    if module is None:
        return []
    source = analysis.source
    found = []
    for decl in module.decls:
        kind = KINDS.get(type(decl))
        if kind is None or isinstance(decl, ast.ImportDecl):
            continue
        children = [_symbol(source, member.name, what, member.span) for what, member in _members(decl)]
        found.append(_symbol(source, decl.name, kind, decl.span, children or None))
    return found


def _members(decl: ast.Decl) -> list[tuple[str, ast.Param | ast.FieldDecl | ast.EnumMember]]:
    match decl:
        case ast.PrimitiveDecl() | ast.InterfaceDecl() | ast.FrameDecl():
            return [("parameter", p) for p in decl.params]
        case ast.AdapterDecl():
            return [("field", f) for f in decl.fields]
        case ast.EnumDecl():
            return [("enum member", member) for member in decl.members]
    return []


def _symbol(source: SourceFile, name: ast.Ident, kind: str, span: Span,
            children: list[types.DocumentSymbol] | None = None) -> types.DocumentSymbol:
    whole = span.to(name.span)
    return types.DocumentSymbol(name=name.text, detail=kind, kind=_SYMBOL_KINDS[kind],
                                range=positions.to_range(source, whole),
                                selection_range=positions.to_range(source, name.span), children=children)


def folding_ranges(analysis: Analysis) -> list[types.FoldingRange]:
    """A range for each declaration of more than one line."""
    module = _main(analysis)
    if module is None:
        return []
    source = analysis.source
    found = []
    for decl in module.decls:
        first, last = source.position(decl.span.start).line, source.position(decl.span.end).line
        if last > first:
            found.append(types.FoldingRange(start_line=first, end_line=last, kind=types.FoldingRangeKind.Region))
    return found


def semantic_tokens(analysis: Analysis) -> types.SemanticTokens:
    """Every declared name in the document, by what it names (keywords and literals are the
    TextMate grammar's to colour)."""
    source = analysis.source
    text, starts = source.text, source.line_starts()
    data: list[int] = []
    line = column = 0
    last: Occurrence | None = None
    for occurrence in analysis.index.by_path.get(source.path, []):
        span = occurrence.span
        if last is not None and span.start < last.span.end:
            continue  # tokens may not overlap
        here = bisect.bisect_right(starts, span.start) - 1
        if here + 1 < len(starts) and span.end >= starts[here + 1]:
            continue  # one line each
        if here == line and last is not None:  # from the last token on: linear in a long line
            start = column + positions.utf16_length(text[last.span.start : span.start])
        else:
            start = positions.utf16_length(text[starts[here] : span.start])
        symbol = occurrence.symbol
        modifiers = (1 if occurrence.declaration else 0) | (2 if symbol.kind in _READONLY else 0) | (
            4 if symbol.standard else 0)
        data += [here - line, start - column if here == line else start,
                 positions.utf16_length(text[span.start : span.end]),
                 TOKEN_TYPES.index(_TOKEN_OF_KIND[symbol.kind]), modifiers]
        line, column, last = here, start, occurrence
    return types.SemanticTokens(data=data)
