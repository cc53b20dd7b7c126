"""Parsing a file again after an edit, reusing the declarations the edit left alone (the editor's).

`parse` (rdisc.syntax.parse) cuts a file into its top-level declarations and parses each alone,
and what one gives depends only on its text, the doc comment written before it and where it
starts. A `Reparser` keeps each declaration's nodes by its text and doc comment: an unchanged
declaration is taken from the last parse, its spans shifted by how far it moved, and only the
others are parsed. A declaration that reported anything, or was damaged, is not kept (its
messages are made again by parsing it again). The module equals `parse`'s, spans included.

What moved is written down (`Moved`), so the checks kept of a declaration that only moved are
taken again with their spans shifted the same way (rdisc.semantics.check.memo).
"""

from __future__ import annotations

from collections import Counter
from typing import Any, TypeVar

from rdisc.diagnostics import Diagnostics
from rdisc.frozen import field_names
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.build import Builder
from rdisc.syntax.parse import (
    MAX_FILE_CHARS,
    MAX_SYNTAX_ERRORS,
    parse,
    parse_declaration,
    pieces,
    token_count,
)

Node = TypeVar("Node")
_setattr = object.__setattr__
_new = object.__new__


class Moved:
    """How the last parse of a file took its declarations from the parse before: each one taken
    (old node, new node) where it moved, each old span of those to its new span (`spans`, by id;
    the old nodes held by `pairs`), and every text kept, as the old offsets it covered (`starts`,
    `ends`, in order) and how far it moved (`deltas`). A text found twice is left out: where its
    old spans went is not one place."""

    __slots__ = ("deltas", "ends", "pairs", "spans", "starts")

    def __init__(self, taken: list[tuple[int, int, int, tuple[ast.Decl, ...], tuple[ast.Decl, ...]]],
                 spans: dict[int, Span]) -> None:
        twice = {at for at, count in Counter(item[0] for item in taken).items() if count > 1}
        once = sorted((item for item in taken if item[0] not in twice), key=lambda item: item[0])
        self.starts = [at for at, _, _, _, _ in once]
        self.ends = [at + length for at, length, _, _, _ in once]
        self.deltas = [start - at for at, _, start, _, _ in once]
        self.pairs = [pair for at, _, start, old, new in once if at != start for pair in zip(old, new)]
        self.spans = spans if not twice else {}


class Reparser:
    """Each file's declarations as last parsed (a check reads a document, its imports and the
    stdlib), by (text, doc comment): where each started and what it gave."""

    def __init__(self) -> None:
        self.files: dict[str, dict[tuple[str, str | None], tuple[int, tuple[ast.Decl, ...]]]] = {}
        self.reused = 0  # declarations taken from the file's last parse, by the last parse (for tests)
        self.counted: dict[str, int] = {}  # the tokens of each declaration's text, as counted
        self.cut: tuple[str, tuple[list[tuple[int, int]], dict[int, str]]] | None = None  # the last text's pieces
        self.moved: dict[str, Moved] = {}  # of each file's last parse, by path

    def __call__(self, path: str, text: str, diagnostics: Diagnostics) -> ast.Module:
        return self.parse(path, text, diagnostics)

    def tokens(self, text: str, most: int) -> int:
        """What `token_count(text, most)` gives, each declaration's tokens kept by its text: no
        token spans a line, and a file is cut into declarations at the starts of lines."""
        if len(text) > MAX_FILE_CHARS:
            return token_count(text, most)
        bounds, _ = self.pieces(text)
        counted, total = self.counted, 0
        if len(counted) > 4 * len(bounds) + 1024:  # of files and texts gone: a check counts a few files
            counted.clear()
        for start, end in bounds:
            piece = text[start:end]
            found = counted.get(piece)
            if found is None:
                found = token_count(piece, most)
                if found <= most:  # exact: a count cut short is not kept
                    counted[piece] = found
            total += found
            if total > most:
                break
        return min(total, most + 1)

    def pieces(self, text: str) -> tuple[list[tuple[int, int]], dict[int, str]]:
        """`pieces(text)`, made once for a text counted and then parsed."""
        if self.cut is None or self.cut[0] != text:
            self.cut = (text, pieces(text))
        return self.cut[1]

    def parse(self, path: str, text: str, diagnostics: Diagnostics) -> ast.Module:
        """What `parse(path, text, diagnostics)` gives, reusing the declarations kept."""
        if len(text) > MAX_FILE_CHARS:
            self.files.pop(path, None)
            self.moved.pop(path, None)
            return parse(path, text, diagnostics)
        last = self.files.get(path, {})
        bounds, docs = self.pieces(text)
        builder = Builder(path, docs, diagnostics)
        decls: list[ast.Decl] = []
        damaged: list[ast.Damaged] = []
        errors = reused = 0
        kept: dict[tuple[str, str | None], tuple[int, tuple[ast.Decl, ...]]] = {}
        taken: list[tuple[int, int, int, tuple[ast.Decl, ...], tuple[ast.Decl, ...]]] = []
        spans: dict[int, Span] = {}
        for i, (start, end) in enumerate(bounds):
            key = (text[start:end], docs.get(start))
            found = last.get(key)
            if found is not None:
                at, old = found
                made = old if at == start else tuple([_shifted(decl, start - at, spans) for decl in old])
                taken.append((at, end - start, start, old, made))
                decls.extend(made)
                kept[key] = (start, made)
                reused += 1
                continue
            reported, first, first_damaged = len(diagnostics.items), len(decls), len(damaged)
            if parse_declaration(text, start, end, builder, decls, damaged, errors < MAX_SYNTAX_ERRORS,
                                 i == len(bounds) - 1):
                errors += 1
            elif len(diagnostics.items) == reported and len(damaged) == first_damaged:
                kept[key] = (start, tuple(decls[first:]))
        self.files[path], self.reused, self.moved[path] = kept, reused, Moved(taken, spans)
        return ast.Module(path, tuple(decls), tuple(damaged))


_FIELDS: dict[type, tuple[str, ...]] = {}
_ATOMS = frozenset({str, int, float, bytes, bool, type(None)})


def shifted(node: Node, by: int) -> Node:
    """A copy of a syntax tree with each span `by` characters later (earlier if negative)."""
    if node.__class__ in _ATOMS:
        return node
    return _shifted(node, by, {})  # type: ignore[no-any-return]


def _shifted(node: Any, by: int, spans: dict[int, Span]) -> Any:
    """`shifted`, writing each new span in `spans` by its old span's id (a span made here, not by
    a call: a third of the nodes are spans)."""
    cls = node.__class__
    if cls is tuple:
        return tuple([item if item.__class__ in _ATOMS else _shifted(item, by, spans) for item in node])
    if cls is Span:
        made = _new(Span)
        _setattr(made, "path", node.path)
        _setattr(made, "start", node.start + by)
        _setattr(made, "end", node.end + by)
        spans[id(node)] = made
        return made
    names = _FIELDS.get(cls)
    if names is None:
        names = _FIELDS[cls] = field_names(node)  # a node of rdisc.syntax.ast
    made = _new(cls)
    for name in names:
        value = getattr(node, name)
        kind = value.__class__
        if kind is Span:
            span = _new(Span)
            _setattr(span, "path", value.path)
            _setattr(span, "start", value.start + by)
            _setattr(span, "end", value.end + by)
            spans[id(value)] = span
            _setattr(made, name, span)
        elif kind in _ATOMS:
            _setattr(made, name, value)
        else:
            _setattr(made, name, _shifted(value, by, spans))
    return made
