"""What each primitive's and interface's check gave, kept from one check of a document to the next
(the editor's), so a change checks again only the declarations it touched and those reading them.

A primitive's check reads its declaration and what the declarations other than primitives and
interfaces made (state, settings, constants, frames, connections: the context); an interface's
reads also the primitives and interfaces it calls, through the interfaces it calls. A kept check is
taken again when its declaration is the same node (rdisc.syntax.incremental gives an unchanged
declaration's node again, moved or not), the context the same nodes, and what it reads of the
others equal. Taking it again does what making it did to the checker: its reports
(made again only if none would be a repeat, whose absence could have changed its course), the
constants it folded, the state it read, the calls it wrote out. So a check with a `Memo` gives
what one without gives, diagnostics and Model alike (tests/semantics/test_memo.py holds them equal).

A declaration that only moved (text added or taken away before it) is the same node, its spans
moved where they are by the parser (rdisc.syntax.incremental); so are those of the context. The
spans a kept check holds besides its declaration's (those it made, those of what it read) are
moved the same way when it is taken again, each once, as the text it lies in moved (`Moved.place`);
one with a span in text not kept is made again.
"""

from __future__ import annotations

from collections.abc import Callable
from operator import is_

from rdisc import TYPE_CHECKING
from rdisc.diagnostics import Diagnostic, Label
from rdisc.semantics import model as m
from rdisc.semantics.check.interfaces import MAX_UNROLLED, MAX_UNROLLED_ALL
from rdisc.semantics.check.pieces import Pieces
from rdisc.source import Span
from rdisc.syntax import ast

if TYPE_CHECKING:
    from typing import Any, TypeVar

    from rdisc.syntax.incremental import Moved

    Result = TypeVar("Result")

_POPPED = object()


class Logged(dict[int, "Any"]):
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

    __slots__ = ("constants", "decl", "depends", "failed_reads", "reads", "reports", "result", "spans", "written")

    def __init__(self, decl: object, depends: tuple[object, ...], result: object, reports: list[Diagnostic],
                 constants: list[tuple[int, Any]], reads: set[str], failed_reads: int, written: int,
                 spans: list[Span]) -> None:
        self.decl = decl
        self.spans = spans  # of its result and reports, but not of its declaration
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
        self.moving = False  # something moved since the last check

    def begin(self, context: object) -> None:
        """A check starts: what it keeps of the last depends on its context being the same."""
        if not same(context, self.context):
            self.kept = {}
        self.context, self.made, self.reused = context, {}, 0
        self.moving = any(moved.moving for moved in self.moved.values())

    def end(self) -> None:
        self.kept, self.made = self.made, {}

    def placed(self, kept: Kept) -> bool:
        """Move the spans of a kept check to where their texts went (its declaration's are moved
        with its nodes); False if one lies in text not kept."""
        from rdisc.syntax.incremental import Unmoved  # the editor's alone: `rdisc check` keeps nothing

        moved = self.moved
        try:
            for span in kept.spans:
                found = moved.get(span.path)
                if found is None:
                    return False
                if found.moving:
                    found.place(span)
        except Unmoved:
            return False
        return True


_VALUES = (str, int, bool, type(None), frozenset)


def same(a: object, b: object) -> bool:
    """Whether two things read are the same: nodes and Models by identity (their `==` leaves spans
    out, and a kept check's spans are where its inputs were), names and flags by value."""
    if a is b:
        return True
    if type(a) is tuple and type(b) is tuple:
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return type(a) is type(b) and type(a) in _VALUES and a == b


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
        key = (id(decl), part)
        kept = memo.kept.get(key)
        if (kept is not None and kept.decl is decl and len(kept.depends) == len(depends)
                and all(map(is_, kept.depends, depends)) and (not (memo.moving and kept.spans) or memo.placed(kept))
                and self._again(kept)):
            memo.made[key] = kept
            memo.reused += not part
            return kept.result  # type: ignore[return-value]
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
        reports = d.items[first:]
        kept = Kept(decl, depends, result, reports, log, own, typer.failed_reads - failed_reads, wrote,
                    spans_made(decl, result, reports))
        return kept, not repeated and written + wrote + MAX_UNROLLED <= MAX_UNROLLED_ALL



def spans_made(decl: object, result: object, reports: list[Diagnostic]) -> list[Span]:
    """The spans of a check's result and reports that are not its declaration's, once each."""
    from rdisc.syntax.incremental import spans_in  # the editor's alone: `rdisc check` keeps nothing

    own: list[Span] = []
    seen: set[int] = set()
    spans_in(decl, own, seen)
    spans: list[Span] = []
    spans_in(result, spans, seen)
    spans_in(reports, spans, seen)
    return spans
