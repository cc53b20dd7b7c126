"""What each primitive's and interface's check gave, kept from one check of a document to the next
(the editor's), so a change checks again only the declarations it touched and those reading them.

A primitive's check reads its declaration and what the declarations other than primitives and
interfaces made (state, settings, constants, frames, connections: the context); an interface's
reads also the primitives and interfaces it calls, through the interfaces it calls. A kept check is
taken again when its declaration is the same node (rdisc.syntax.incremental gives an unchanged
declaration's node again only where it did not move), the context the same nodes, and what it
reads of the others equal. Taking it again does what making it did to the checker: its reports
(made again only if none would be a repeat, whose absence could have changed its course), the
constants it folded, the state it read, the calls it wrote out. So a check with a `Memo` gives
what one without gives, diagnostics and Model alike (tests/semantics/test_memo.py holds them equal).

A declaration that only moved (text added or taken away before it) is a new node, as is each
declaration of the context that moved: the parser writes down which old node each is
(rdisc.syntax.incremental.Moved). A kept check whose declaration, depends and context are the same
nodes or those old nodes moved is taken again as a copy whose every span is shifted as the text it
lies in moved (`Shift`); one with a span in text not kept is made again.
"""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Callable
from operator import is_
from typing import TYPE_CHECKING, Any, TypeVar

from rdisc.diagnostics import Diagnostic, Label
from rdisc.frozen import field_names
from rdisc.semantics import model as m
from rdisc.semantics.check.interfaces import MAX_UNROLLED, MAX_UNROLLED_ALL
from rdisc.semantics.check.pieces import Pieces
from rdisc.source import Span
from rdisc.syntax import ast

if TYPE_CHECKING:
    from rdisc.syntax.incremental import Moved

Result = TypeVar("Result")
_POPPED = object()


class Logged(dict[int, Any]):
    """The typer's folded constants, each entry made or dropped written down while `log` is a list."""

    log: list[tuple[int, Any]] | None = None

    def __setitem__(self, key: int, value: Any) -> None:
        super().__setitem__(key, value)
        if self.log is not None:
            self.log.append((key, value))

    def pop(self, key: int, *default: Any) -> Any:
        found = super().pop(key, *default)
        if self.log is not None:
            self.log.append((key, _POPPED))
        return found


class Kept:
    """One declaration's check: what it read, what it gave and what it did to the checker."""

    __slots__ = ("constants", "decl", "depends", "failed_reads", "reads", "reports", "result", "written")

    def __init__(self, decl: object, depends: tuple[object, ...], result: object, reports: list[Diagnostic],
                 constants: list[tuple[int, Any]], reads: set[str], failed_reads: int, written: int) -> None:
        self.decl = decl
        self.depends = depends
        self.result = result
        self.reports = reports
        self.constants = constants
        self.reads = reads
        self.failed_reads = failed_reads
        self.written = written


class Memo:
    """The checks kept from a document's last check, by declaration (its node held, so its id is its own)."""

    def __init__(self) -> None:
        self.context: object = None
        self.kept: dict[tuple[int, str], Kept] = {}  # of the last check
        self.made: dict[tuple[int, str], Kept] = {}  # of the check running
        self.reused = 0  # checks taken again by the last check (for tests)
        self.moved: dict[str, Moved] = {}  # how each file's last parse moved its declarations (the parser's)
        self.shift: Shift | None = None  # of the check running, when something moved
        self.context_moved = False  # the check running's context is the last's, moved

    def begin(self, context: object) -> None:
        """A check starts: what it keeps of the last depends on its context being the same, or
        the same moved."""
        shift = Shift(self.moved) if any(moved.pairs for moved in self.moved.values()) else None
        self.context_moved = False
        if not same(context, self.context):
            if shift is not None and shift.same(context, self.context):
                self.context_moved = True
            else:
                self.kept = {}
        self.context, self.made, self.reused, self.shift = context, {}, 0, shift

    def end(self) -> None:
        self.kept, self.made, self.shift = self.made, {}, None


_VALUES = (str, int, bool, type(None), frozenset)


def same(a: object, b: object) -> bool:
    """Whether two things read are the same: nodes and Models by identity (their `==` leaves spans
    out, and a kept check's spans are where its inputs were), names and flags by value."""
    if a is b:
        return True
    if type(a) is tuple and type(b) is tuple:
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return type(a) is type(b) and type(a) in _VALUES and a == b


class Unmoved(Exception):
    """A span of a kept check lies in text not kept: the check is made again."""


# Taken as they are: values, and the classes found to be no node (enums, patterns), added as found.
_ATOMS = {str, int, float, bytes, bool, type(None), frozenset}
_FIELDS: dict[type, tuple[str, ...] | None] = {}
_setattr = object.__setattr__
_new = object.__new__


class Shift:
    """Where the old nodes of one check are in the next, after the text moved: each old node
    (declaration, or part of a kept check copied) by its id to its new node, and each old span
    to where its text went."""

    def __init__(self, moved: dict[str, Moved]) -> None:
        self.moved = moved
        # id(old) → new; the old nodes are held by the parser's pairs and the Memo's kept checks.
        self.now: dict[int, object] = {id(old): new for file in moved.values() for old, new in file.pairs}
        self.before: dict[int, object] = {id(new): old for file in moved.values() for old, new in file.pairs}
        self.spans: dict[int, Span] = {}  # id(old span) → new, of the declarations the parser moved
        for file in moved.values():
            self.spans.update(file.spans)

    def is_now(self, new: object, old: object) -> bool:
        return new is old or self.now.get(id(old)) is new

    def same(self, new: object, old: object) -> bool:
        """`same`, with an old node also the same as its new node (moved)."""
        if new is old or self.now.get(id(old)) is new:
            return True
        if type(new) is tuple and type(old) is tuple:
            return len(new) == len(old) and all(self.same(x, y) for x, y in zip(new, old))
        return type(new) is type(old) and type(new) in _VALUES and new == old

    def span(self, span: Span) -> Span:
        """Where an old span's text is now; Unmoved if that text was not kept."""
        moved = self.moved.get(span.path)
        if moved is None:
            raise Unmoved
        starts, start, end = moved.starts, span.start, span.end
        i = bisect_right(starts, start) - 1
        if i < 0 or end > moved.ends[i] or (start == end == starts[i] and i > 0 and moved.ends[i - 1] == start
                                             and moved.deltas[i - 1] != moved.deltas[i]):
            raise Unmoved  # outside what was kept, or at the edge of two texts kept that moved apart
        delta = moved.deltas[i]
        if delta == 0:
            return span
        made = _new(Span)
        _setattr(made, "path", span.path)
        _setattr(made, "start", start + delta)
        _setattr(made, "end", end + delta)
        return made

    def copy(self, node: Any) -> Any:
        """`node` (of a kept check) as it is now: a node already copied or moved, its copy; a
        span, shifted; else a copy of its parts (nodes by their fields, tuples, lists, dicts)."""
        cls = node.__class__
        if cls in _ATOMS:
            return node
        if cls is Span:  # not kept in `now`: a value; most are a moved syntax tree's (`spans`)
            return self.spans.get(id(node)) or self.span(node)
        now, key = self.now, id(node)
        found = now.get(key)
        if found is not None:
            return found
        copy = self.copy
        if cls is tuple:
            made: Any = tuple([item if item.__class__ in _ATOMS else copy(item) for item in node])
        elif cls is list:
            made = [copy(item) for item in node]
        elif cls is dict:
            made = {key: copy(value) for key, value in node.items()}
        else:
            names = _FIELDS.get(cls, ())
            if names == ():
                names = _FIELDS[cls] = field_names(node) or None
            if names is None:  # not a node: an enum member, a compiled pattern
                _ATOMS.add(cls)
                return node
            made = _new(cls)
            spans = self.spans
            for name in names:
                value = getattr(node, name)
                kind = value.__class__
                if kind in _ATOMS:
                    _setattr(made, name, value)
                elif kind is Span:
                    _setattr(made, name, spans.get(id(value)) or self.span(value))
                else:
                    _setattr(made, name, copy(value))
        now[key] = made
        return made

    def kept(self, kept: Kept, decl: object, depends: tuple[object, ...]) -> Kept | None:
        """A kept check copied to where its declaration and what it read are now; None if some
        span of it lies in text not kept."""
        now = self.now
        for new, old in zip(depends, kept.depends):  # what it read, as it is now (itself, where it did not move)
            now.setdefault(id(old), new)
        now.setdefault(id(kept.decl), decl)
        try:
            result = self.copy(kept.result)
            reports = [self.copy(report) for report in kept.reports]
        except Unmoved:
            return None
        # The constants it folded, each of a node now copied by its copy; one in neither its result
        # nor its reports is held by no one else, and nothing asks about it: it stays.
        constants: list[tuple[int, Any]] = []
        for key, value in kept.constants:
            found = now.get(key)
            if found is None:
                constants.append((key, value))
            else:
                constants.append((id(found), value if value is _POPPED else (found, value[1])))
        return Kept(decl, depends, result, reports, constants, kept.reads, kept.failed_reads, kept.written)


def context_of(units: list[Any], damaged: set[tuple[str, str]]) -> object:
    """What every primitive's and interface's check reads besides primitives and interfaces: each
    file's role and its other declarations (their nodes), and the names lost to syntax errors."""
    return (tuple((u.module.path, u.main, u.standard, u.module.refused) for u in units),
            tuple(decl for u in units for decl in u.module.decls
                  if not isinstance(decl, (ast.PrimitiveDecl, ast.InterfaceDecl))),
            frozenset(damaged))


class Remembering(Pieces):
    """The checker's side of a `Memo`: a declaration's check made, or taken again."""

    memo: Memo | None = None

    def remember(self, memo: Memo | None) -> None:
        self.memo = memo
        if memo is not None:
            self.typer._constants = Logged()
            memo.begin(context_of(self.units, self.s.damaged))

    def forget_rest(self) -> None:
        if self.memo is not None:
            self.memo.end()

    def recall(self, decl: object, depends: tuple[object, ...], check: Callable[[], Result], part: str = "") -> Result:
        """`check()`, or what it gave last time, for `decl` (its `part`: an interface's parameters are
        made apart from its body) reading `depends` (nodes and Models, by identity) besides the context."""
        memo = self.memo
        if memo is None:
            return check()
        key, shift = (id(decl), part), memo.shift
        kept = memo.kept.get(key)
        if kept is not None and kept.decl is not decl:
            kept = None
        if kept is None and shift is not None:  # the declaration moved: kept by its old node
            old = shift.before.get(id(decl))
            kept = None if old is None else memo.kept.get((id(old), part))
        if kept is not None and len(kept.depends) == len(depends):
            if kept.decl is decl and not memo.context_moved and all(map(is_, kept.depends, depends)):
                taken: Kept | None = kept
            elif shift is not None and shift.is_now(decl, kept.decl) and all(map(shift.is_now, depends, kept.depends)):
                taken = shift.kept(kept, decl, depends)  # it, or what it read, moved
            else:
                taken = None
            if taken is not None and self._again(taken):
                memo.made[key] = taken
                memo.reused += not part
                return taken.result  # type: ignore[return-value]
        made, again = self._made(decl, depends, check)
        if again:  # else its course touched what others reported, or a bound of them all: made each time
            memo.made[key] = made
        return made.result  # type: ignore[return-value]

    def interface_reads(self, decl: ast.InterfaceDecl, primitives: dict[str, m.Primitive]) -> tuple[object, ...]:
        """What an interface's check reads besides its declaration and the context: each primitive
        or interface it calls, through the interfaces it calls (declaration, Model; the parameters
        are made from the declaration and the context). None without a memo: nothing is kept."""
        if self.memo is None:
            return ()
        names: dict[str, None] = {}
        bodies = [decl.body]
        while bodies:
            for stmt in ast.call_stmts(bodies.pop()):
                name = stmt.call.target.text
                if name not in names:
                    names[name] = None
                    called = self.s.interfaces.get(name)
                    if called is not None:
                        bodies.append(called.body)
        return tuple(found for name in names for found in
                     (self.s.primitives.get(name), self.s.interfaces.get(name), primitives.get(name)))

    def _again(self, kept: Kept) -> bool:
        """Do to the checker what the kept check did, if that is what making it again would do."""
        d = self.d
        seen = d._seen
        if any((r.code, r.span, r.message) in seen for r in kept.reports):
            return False
        if self.written + kept.written + MAX_UNROLLED > MAX_UNROLLED_ALL:  # a loop's bound of them all
            return False
        for report in kept.reports:
            seen.add((report.code, report.span, report.message))
            d.items.append(report)
        constants = self.typer._constants
        for key, value in kept.constants:
            if value is _POPPED:
                dict.pop(constants, key, None)
            else:
                dict.__setitem__(constants, key, value)
        self.typer.reads.update(kept.reads)
        self.typer.failed_reads += kept.failed_reads
        self.written += kept.written
        return True

    def _made(self, decl: object, depends: tuple[object, ...], check: Callable[[], Any]) -> tuple[Kept, bool]:
        """Make the check, writing down what it does; and whether it may be taken again (not when a
        report of it was a repeat of another's, or its loops came near the description's bound)."""
        d, typer = self.d, self.typer
        constants = typer._constants
        assert isinstance(constants, Logged)
        first, written, failed_reads = len(d.items), self.written, typer.failed_reads
        reads, typer.reads = typer.reads, set()
        repeated = False
        original = d.report

        def report(code: str, span: Span | None, message: str, *, label: str | None = None,
                   labels: tuple[Label, ...] = (), help: str | None = None) -> None:
            nonlocal repeated
            before = len(d.items)
            original(code, span, message, label=label, labels=labels, help=help)
            if len(d.items) == before and not any((r.code, r.span, r.message) == (code, span, message)
                                                  for r in d.items[first:]):
                repeated = True

        log: list[tuple[int, Any]] = []
        constants.log = log
        d.report = report  # type: ignore[method-assign]
        try:
            result = check()
        finally:
            del d.report
            constants.log = None
            own, typer.reads = typer.reads, reads
            reads.update(own)
        wrote = self.written - written
        kept = Kept(decl, depends, result, d.items[first:], log, own, typer.failed_reads - failed_reads, wrote)
        return kept, not repeated and written + wrote + MAX_UNROLLED <= MAX_UNROLLED_ALL

