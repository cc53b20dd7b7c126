"""Go to definition, find references, document highlights and rename, over the index of a
document's compilation (its imports and the stdlib's adapters included) and, for references
and rename, of the other open documents (a shared import's names are used in each).

A rename is refused, with the reason, where the new name is no name, is a keyword or a built-in
function where one is read (the resolver's rule, `check_name`), or is taken by a declaration the
renamed name would then be confused with; and for a name of the stdlib, which no edit changes.
"""

from __future__ import annotations

import re
from pathlib import Path

from lsprotocol import types

from rdisc.diagnostics import Diagnostics
from rdisc.editor import positions
from rdisc.editor.documents import Analysis
from rdisc.editor.index import READ, Occurrence, Symbol
from rdisc.semantics.resolve import check_name
from rdisc.syntax import ast

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


class Refused(Exception):
    """A rename that would break the description, and why."""


def found_at(analysis: Analysis, at: types.Position) -> Occurrence | None:
    source = analysis.source
    return analysis.index.at(source.path, positions.offset(source, at))


def _location(analysis: Analysis, occurrence: Occurrence | Symbol) -> types.Location | None:
    source = analysis.source_of(occurrence.span.path)
    if source is None:
        return None
    return types.Location(uri=positions.uri_of(occurrence.span.path), range=positions.to_range(source, occurrence.span))


def definition(analysis: Analysis, at: types.Position) -> list[types.Location]:
    """Where the name at `at` is declared; on an `import`, the file it imports."""
    found = found_at(analysis, at)
    if found is None:
        return _imported(analysis, positions.offset(analysis.source, at))
    place = _location(analysis, found.symbol)
    return [place] if place is not None else []


def _imported(analysis: Analysis, offset: int) -> list[types.Location]:
    main = analysis.compilation.main
    for decl in main.decls if main is not None else ():
        if isinstance(decl, ast.ImportDecl) and decl.span.start <= offset <= decl.span.end:
            path = str(Path(decl.span.path).parent / decl.path)
            if path in analysis.compilation.sources:  # read, so allowed and there
                start = types.Position(line=0, character=0)
                return [types.Location(uri=positions.uri_of(path), range=types.Range(start=start, end=start))]
    return []


def _everywhere(analysis: Analysis, symbol: Symbol, others: list[Analysis]) -> list[tuple[Analysis, Occurrence]]:
    """The symbol's occurrences in this document's compilation and in the others', each place once,
    by file and place."""
    seen: set[tuple[str, int]] = set()
    found = []
    for each in [analysis, *others]:
        if each is not analysis and symbol.span.path not in each.compilation.sources:
            continue
        for occurrence in each.index.occurrences(symbol):
            place = (occurrence.span.path, occurrence.span.start)
            if place not in seen:
                seen.add(place)
                found.append((each, occurrence))
    return sorted(found, key=lambda pair: (pair[1].span.path, pair[1].span.start))


def references(analysis: Analysis, at: types.Position, declaration: bool,
               others: list[Analysis]) -> list[types.Location]:
    found = found_at(analysis, at)
    if found is None:
        return []
    places = [_location(each, o) for each, o in _everywhere(analysis, found.symbol, others)
              if declaration or not o.declaration]
    return [place for place in places if place is not None]


def highlights(analysis: Analysis, at: types.Position) -> list[types.DocumentHighlight]:
    found = found_at(analysis, at)
    if found is None:
        return []
    source = analysis.source
    return [types.DocumentHighlight(range=positions.to_range(source, o.span),
                                    kind=types.DocumentHighlightKind.Write if o.declaration
                                    else types.DocumentHighlightKind.Read)
            for o in analysis.index.by_path.get(source.path, []) if o.symbol.key == found.symbol.key]


def prepare_rename(analysis: Analysis, at: types.Position) -> types.Range | None:
    found = found_at(analysis, at)
    if found is None:
        return None
    _renamable(found.symbol)
    return positions.to_range(analysis.source, found.span)


def rename(analysis: Analysis, at: types.Position, new_name: str, others: list[Analysis]) -> types.WorkspaceEdit:
    found = found_at(analysis, at)
    if found is None:
        raise Refused("no declared name here to rename")
    symbol = found.symbol
    _renamable(symbol)
    if new_name == symbol.name:
        return types.WorkspaceEdit(changes={})
    _check_new_name(analysis, symbol, new_name)
    changes: dict[str, list[types.TextEdit]] = {}
    for each, occurrence in _everywhere(analysis, symbol, others):
        place = _location(each, occurrence)
        if place is not None:
            changes.setdefault(place.uri, []).append(types.TextEdit(range=place.range, new_text=new_name))
    return types.WorkspaceEdit(changes=changes)


def _renamable(symbol: Symbol) -> None:
    if symbol.standard:
        raise Refused(f"`{symbol.name}` is declared in the standard library (stdlib/adapters.rdis), "
                      "which a description cannot change")
    if symbol.kind == "robot":
        raise Refused("the robot's name is its only use: edit it where it is declared")


def _check_new_name(analysis: Analysis, symbol: Symbol, new_name: str) -> None:
    if not _NAME.fullmatch(new_name):
        raise Refused(f"`{new_name}` is not a name: a name is a letter, then letters, digits and `_`")
    said = Diagnostics()
    read = symbol.kind not in ("link", "joint", "transmission", "actuator")  # as the resolver names them
    check_name(ast.Ident(new_name), symbol.kind, said, read=read)
    if said.items:
        raise Refused(said.items[0].message)
    taken = _taken(analysis, symbol, new_name)
    if taken is not None:
        where = analysis.source_of(taken.span.path)
        line = f" (line {where.position(taken.span.start).line + 1})" if where is not None else ""
        raise Refused(f"`{new_name}` is already the name of {taken.kind} `{taken.name}`{line}")


def _taken(analysis: Analysis, symbol: Symbol, new_name: str) -> Symbol | None:
    """A declaration named `new_name` that the renamed symbol would clash with or be read as."""
    index = analysis.index
    if symbol.owner is not None:  # a parameter, field or member: its siblings, and what expressions read
        for other in index.symbols:
            if other.owner is not None and other.owner.key == symbol.owner.key and other.name == new_name:
                return other
        return index.lookup(READ, new_name) if symbol.kind == "parameter" else None
    if symbol.kind == "loop variable":
        return index.lookup(READ, new_name)
    kinds: tuple[str, ...] = (symbol.kind,)
    if symbol.kind in READ:
        kinds = READ
    elif symbol.kind in ("primitive", "interface"):  # a call names either
        kinds = ("primitive", "interface")
    return index.lookup(kinds, new_name)
