"""Parsing a file again after an edit, reusing the declarations the edit left alone (the editor's).

`parse` (rdisc.syntax.parse) cuts a file into its top-level declarations and parses each alone,
and what one gives depends only on its text, the doc comment written before it and where it
starts. A `Reparser` keeps each declaration's nodes by its text and doc comment: an unchanged
declaration's nodes are taken from the last parse, and only the others are parsed. A declaration
that reported anything, or was damaged, is not kept (its messages are made again by parsing it
again). The module equals `parse`'s, spans included.

A declaration that moved (text added or taken away before it) keeps its nodes too: its spans are
moved where they are, each a few assignments, where copying its nodes cost a hundred times more
(most of an editor's check when one types near the top of a file). So the last parse's nodes are
not the last text's any more: they belong to the newest parse alone (the editor asks its questions
of the newest check). What moved is written down (`Moved`), so the spans the checks kept of a
declaration made apart from its nodes are moved the same way (rdisc.semantics.check.memo).
"""

from __future__ import annotations

from bisect import bisect_right
from collections import deque
from collections.abc import Callable, Iterator
from itertools import repeat
from operator import add, attrgetter
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


class Unmoved(Exception):
    """A span lies in text the last parse did not keep: where it went is not known."""


class Moved:
    """How the last parse of a file took its declarations from the parse before: every text kept,
    as the old offsets it covered (`starts`, `ends`, in order) and how far it moved (`deltas`),
    and the spans it moved with their nodes (`shifted`: each is moved once, and once moved its
    offsets are the new text's)."""

    __slots__ = ("_done", "deltas", "ends", "moving", "shifted", "starts")

    def __init__(self) -> None:
        self.starts: list[int] = []
        self.ends: list[int] = []
        self.deltas: list[int] = []
        self.moving = False
        self.shifted: list[list[Span]] = []
        self._done: set[int] | None = None  # the ids of the spans moved, made when first asked

    def kept(self, taken: list[tuple[int, int, int]]) -> None:
        """The texts kept, each (old start, length, new start)."""
        taken.sort()
        self.starts = [at for at, _, _ in taken]
        self.ends = [at + length for at, length, _ in taken]
        self.deltas = [start - at for at, _, start in taken]
        self.moving = any(self.deltas)

    def shift(self, spans: list[Span], by: int) -> None:
        """Move spans of texts that moved `by` characters (none moved yet): each a call from C,
        not a line of Python (a 1,000-line file has 6,000)."""
        _exhaust(map(_set_start, spans, map(add, map(_start, spans), repeat(by))))
        _exhaust(map(_set_end, spans, map(add, map(_end, spans), repeat(by))))
        self.shifted.append(spans)
        if self._done is not None:
            self._done.update(map(id, spans))

    def shift_all(self, moves: dict[int, list[Span]]) -> None:
        """`shift` each list of spans by how far it moved (its key), emptying `moves`."""
        for by, spans in moves.items():
            self.shift(spans, by)
        moves.clear()

    def place(self, span: Span) -> None:
        """Move a span of the last text (if not moved yet) to where its text went; Unmoved if
        that text was not kept, or the span is empty at the edge of two texts that moved apart."""
        done = self._done
        if done is None:  # most checks kept hold no span but their declaration's: never asked
            done = self._done = {id(span) for spans in self.shifted for span in spans}
        if id(span) in done:
            return
        starts, start, end = self.starts, span.start, span.end
        i = bisect_right(starts, start) - 1
        if i < 0 or end > self.ends[i] or (start == end == starts[i] and i > 0 and self.ends[i - 1] == start
                                           and self.deltas[i - 1] != self.deltas[i]):
            raise Unmoved
        delta = self.deltas[i]
        if delta:
            _setattr(span, "start", start + delta)
            _setattr(span, "end", end + delta)
            done.add(id(span))


_set_start: Callable[[Span, int], None] = vars(Span)["start"].__set__  # the slots' own setters
_set_end: Callable[[Span, int], None] = vars(Span)["end"].__set__
_start, _end = attrgetter("start"), attrgetter("end")


def _exhaust(calls: Iterator[object]) -> None:
    deque(calls, 0)


_ATOMS = {str, int, float, bytes, bool, type(None), frozenset}  # and the classes found to be no node
_FIELDS: dict[type, tuple[str, ...]] = {}


def spans_in(value: object, spans: list[Span], seen: set[int]) -> None:
    """Add to `spans` each span in `value` (a node, or a Model part: by their fields, tuples, lists
    and dicts) whose id is not in `seen`, adding it there: every span once."""
    cls = value.__class__
    if cls is Span:
        if id(value) not in seen:
            seen.add(id(value))
            spans.append(value)  # type: ignore[arg-type]
        return
    if cls is tuple or cls is list:
        for item in value:  # type: ignore[attr-defined]
            if item.__class__ not in _ATOMS:
                spans_in(item, spans, seen)
        return
    if cls is dict:
        for item in value.values():  # type: ignore[attr-defined]
            if item.__class__ not in _ATOMS:
                spans_in(item, spans, seen)
        return
    names = _FIELDS.get(cls)
    if names is None:
        names = _FIELDS[cls] = field_names(value)
        if not names:  # not a node: an enum member, a compiled pattern
            _ATOMS.add(cls)
            return
    for name in names:
        item = getattr(value, name)
        if item.__class__ not in _ATOMS:
            spans_in(item, spans, seen)


class Reparser:
    """Each file's declarations as last parsed (a check reads a document, its imports and the
    stdlib), by (text, doc comment): where each started, what it gave, and its spans (found when
    it first moves)."""

    def __init__(self) -> None:
        self.files: dict[str, dict[tuple[str, str | None], Parsed]] = {}
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
        kept: dict[tuple[str, str | None], Parsed] = {}
        taken: list[tuple[int, int, int]] = []
        moved = Moved()
        moves: dict[int, list[Span]] = {}  # the spans of the declarations that moved, by how far
        for i, (start, end) in enumerate(bounds):
            key = (text[start:end], docs.get(start))
            found = last.pop(key, None)
            if found is not None:  # its nodes, moved if its text moved
                taken.append((found.start, end - start, start))
                if found.start != start:  # moved after the loop, those moving as far at once
                    moves.setdefault(start - found.start, []).extend(found.spans())
                    found.start = start
                decls.extend(found.decls)
                kept[key] = found
                reused += 1
                continue
            again = kept.get(key)
            if again is not None:  # the same text again: a copy of the first's nodes, where it is
                moved.shift_all(moves)
                decls.extend(shifted(again.decls, start - again.start))
                reused += 1
                continue
            reported, first, first_damaged = len(diagnostics.items), len(decls), len(damaged)
            if parse_declaration(text, start, end, builder, decls, damaged, errors < MAX_SYNTAX_ERRORS,
                                 i == len(bounds) - 1):
                errors += 1
            elif len(diagnostics.items) == reported and len(damaged) == first_damaged:
                kept[key] = Parsed(start, tuple(decls[first:]))
        moved.shift_all(moves)
        moved.kept(taken)
        self.files[path], self.reused, self.moved[path] = kept, reused, moved
        return ast.Module(path, tuple(decls), tuple(damaged))


class Parsed:
    """One declaration's text as last parsed: where it started, what it gave, and its spans."""

    __slots__ = ("_spans", "decls", "start")

    def __init__(self, start: int, decls: tuple[ast.Decl, ...]) -> None:
        self.start = start
        self.decls = decls
        self._spans: list[Span] | None = None

    def spans(self) -> list[Span]:
        """Every span of its nodes, once each (found when it first moves: most never do)."""
        if self._spans is None:
            self._spans = []
            spans_in(self.decls, self._spans, set())
        return self._spans


def shifted(node: Node, by: int) -> Node:
    """A copy of a syntax tree with each span `by` characters later (earlier if negative)."""
    if node.__class__ in _ATOMS:
        return node
    return _shifted(node, by)  # type: ignore[no-any-return]


def _shifted(node: Any, by: int) -> Any:
    """`shifted`, each span made here, not by a call (a third of the nodes are spans)."""
    cls = node.__class__
    if cls is tuple:
        return tuple([item if item.__class__ in _ATOMS else _shifted(item, by) for item in node])
    if cls is Span:
        made = _new(Span)
        _setattr(made, "path", node.path)
        _setattr(made, "start", node.start + by)
        _setattr(made, "end", node.end + by)
        return made
    names = _FIELDS.get(cls)
    if names is None:
        names = _FIELDS[cls] = field_names(node)  # a node of rdisc.syntax.ast (never an atom)
    made = _new(cls)
    for name in names:
        value = getattr(node, name)
        kind = value.__class__
        if kind is Span:
            span = _new(Span)
            _setattr(span, "path", value.path)
            _setattr(span, "start", value.start + by)
            _setattr(span, "end", value.end + by)
            _setattr(made, name, span)
        elif kind in _ATOMS:
            _setattr(made, name, value)
        else:
            _setattr(made, name, _shifted(value, by))
    return made
