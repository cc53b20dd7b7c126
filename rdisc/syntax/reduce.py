"""Lark's LALR tables run by a loop of rdisc's own that builds AST nodes as it reduces.

Lark parses a declaration into a tree (each node shaped by wrappers: tokens filtered out,
`_rule`s spliced into their parent, a `?rule` of one child passed through, positions
propagated), and then a Transformer walks the tree to build AST nodes: at 100,000 lines the
wrappers and the walk are most of a check. This loop reads Lark's own parse table, its
contextual lexer's tokens and each rule's shaping (taken from Lark's wrappers, not written
again), and calls the Builder's method for a rule the moment the rule is reduced, with the
children and positions Lark's tree would have given it.

It takes only the clean case: at any syntax error (a keyword read as a name included), a tree
deeper than MAX_TREE_DEPTH, an expression the Builder refuses as too deep, or a shape the
Builder never sees, it gives up (`Retry`) and the declaration is parsed by Lark and built from
its tree as before. So every diagnostic comes from the one path that writes it; what the
Builder reports along the way is kept back until the declaration is built.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, cast

import lark
import lark.utils
from lark.parse_tree_builder import (
    ChildFilterLALR,
    ChildFilterLALR_NoPlaceholders,
    ExpandSingleChild,
    PropagatePositions,
)
from lark.parsers.lalr_analysis import Shift

from rdisc.syntax import ast
from rdisc.syntax.build import Builder, TooDeep, transformer_class
from rdisc.syntax.lexing import SharedScanner


class Retry(Exception):
    """This declaration is not for the fast loop: Lark parses it, and the Builder walks its tree."""


class _Meta:
    """The positions of a rule's node, as Lark's Meta holds them for the Builder."""

    __slots__ = ("end_pos", "start_pos")
    empty = False

    def __init__(self, span: tuple[int, int]) -> None:
        self.start_pos, self.end_pos = span


class _Empty:
    """The Meta of a node with no tokens (an empty optional part): Lark's has no positions."""

    __slots__ = ()
    empty = True


_EMPTY = _Empty()


@dataclass(frozen=True, slots=True)
class _Rule:
    """How one grammar rule's children become its value, read from Lark's wrappers of the rule."""

    origin: str  # the nonterminal it reduces to
    size: int  # symbols on its right-hand side
    keep: tuple[tuple[int, bool, int], ...] | None  # kept children: (index, spliced, Nones before); None: all
    nones_after: int
    single: bool  # a `?rule`: one child left is the value itself
    name: str  # the Builder's method, or the `_rule` spliced into its parent
    spliced: bool  # a `_rule`: its children go into its parent's
    unit: bool  # a `?rule` of one symbol, kept: it passes its child on as it is (value, span, depth)


_NONE = (None, None, False, 0)  # a placeholder of an optional part that is not there


def _kept(rule: _Rule, entries: list[Any]) -> list[Any]:
    """The entries of the children a rule keeps, as Lark's ChildFilterLALR keeps them: tokens
    filtered out, placeholders of absent optional parts put in, a `_rule`'s entries (its value)
    spliced in its place."""
    kept: list[Any] = []
    for i, spliced, nones in rule.keep or ():
        if nones:
            kept += [_NONE] * nones
        if spliced:
            kept += entries[i][0]
        else:
            kept.append(entries[i])
    if rule.nones_after:
        kept += [_NONE] * rule.nones_after
    return kept


def _rule(rule: Any, callback: Any) -> _Rule:
    """The shaping of `rule` from the chain of wrappers Lark made for it (ParseTreeBuilder)."""
    if not isinstance(callback, PropagatePositions) or callback.node_filter is not None:
        raise TypeError(f"unexpected wrapper of {rule}")
    inner = callback.node_builder
    keep: tuple[tuple[int, bool, int], ...] | None = None
    nones_after = 0
    if isinstance(inner, ChildFilterLALR):
        keep, nones_after = tuple(inner.to_include), inner.append_none
        inner = inner.node_builder
    elif isinstance(inner, ChildFilterLALR_NoPlaceholders):
        keep = tuple((i, spliced, 0) for i, spliced in inner.to_include)
        inner = inner.node_builder
    single = isinstance(inner, ExpandSingleChild)
    if single:
        inner = inner.node_builder
    name = rule.alias or rule.options.template_source or rule.origin.name
    if getattr(inner, "func", None) is not lark.Tree or tuple(getattr(inner, "args", ())) != (name,):
        raise TypeError(f"unexpected node builder of {rule}")
    size = len(rule.expansion)
    unit = single and size == 1 and keep is None
    return _Rule(rule.origin.name, size, keep, nones_after, single, name, name.startswith("_"), unit)


class _Rows(dict[int, dict[str, tuple[Any, Any]]]):
    """Lark's parse table, each state's row taken when the state is first met (most of the 765 are
    not, in a small description), with each reduction's _Rule in place of Lark's Rule (whose
    hash is a Python function)."""

    def __init__(self, states: dict[int, dict[str, tuple[Any, Any]]], rules: dict[Any, _Rule]) -> None:
        super().__init__()
        self.states, self.rules = states, rules

    def __missing__(self, state: int) -> dict[str, tuple[Any, Any]]:
        rules = self.rules
        row = {kind: (action, arg if action is Shift else rules[arg]) for kind, (action, arg) in self.states[state].items()}
        self[state] = row
        return row


@dataclass(frozen=True)
class Tables:
    """What the loop reads: Lark's parse table and lexers, and each rule's shaping."""

    states: dict[int, dict[str, tuple[Any, Any]]]  # per state and terminal: Shift and a state, or Reduce and a _Rule
    start: dict[str, int]
    end: dict[str, int]
    lexer: Any  # Lark's contextual lexer
    methods: dict[str, Callable[..., Any]] = field(default_factory=dict)  # the Builder's, by rule, once met
    scanners: dict[int, Any] = field(default_factory=dict)  # per parser state, once met: _scanner(its lexer)


@lru_cache(maxsize=1)
def tables(parser: lark.Lark) -> Tables | None:
    """The tables of `parser`, or None where its shape is not one this loop knows (then Lark parses all)."""
    try:
        frontend = parser.parser
        lalr = frontend.parser.parser
        table = lalr.parse_table
        rules = {rule: _rule(rule, callback) for rule, callback in lalr.callbacks.items()}
        return Tables(_Rows(table.states, rules), table.start_states, table.end_states, frontend.lexer)
    except (AttributeError, TypeError):
        return None


def _subject(text: str) -> Any:
    """What Lark's scanners match against: the text, or (Lark 1.2 on) a TextSlice of it."""
    slice_type = getattr(lark.utils, "TextSlice", None)
    return text if slice_type is None else slice_type.cast_from(text)


_Match = Callable[..., Any]
_Scanner = tuple[_Match | None, "frozenset[str] | set[str] | None", _Match, frozenset[str], dict[str, Any],
                 frozenset[str]]


def _scanner(lexer: Any) -> _Scanner:
    """What the loop reads of a state's lexer (Lark's BasicLexer): the compiled pattern's match
    it may call itself (or None) and the terminals whose match it may take from it (None: all),
    the scanner's match for the rest, the terminals it skips, its callbacks (keywords read as
    names), the terminals that may hold a newline. Retry for a lexer whose skipped terminals
    have callbacks (this loop drops them)."""
    scanner = lexer.scanner  # made now, with the callbacks
    if set(lexer.callback) & lexer.ignore_types:
        raise Retry
    pattern: _Match | None = None
    allowed = None
    patterns: list[Any]
    if isinstance(scanner, SharedScanner):  # the root's pattern, where the state takes its terminal
        patterns, allowed = getattr(scanner.root, "_mres", []), scanner.allowed_types
    else:
        patterns = getattr(scanner, "_mres", [])
    if len(patterns) == 1:
        pattern = patterns[0].match
    return pattern, allowed, scanner.match, lexer.ignore_types, lexer.callback, lexer.newline_types


def _method(transformer: type, name: str) -> Callable[..., Any]:
    """The function of the Builder's transformer for the rules named `name` (under `v_args(meta=True)`:
    it takes the transformer, the meta and the children); Retry where there is none (Lark's tree
    would keep the node)."""
    method = getattr(transformer.__dict__.get(name), "base_func", None)
    if method is None:
        raise Retry
    return cast(Callable[..., Any], method)


class _Deferred:
    """What the Builder reports while a declaration is built by the loop, kept until it is done."""

    def __init__(self) -> None:
        self.reports: list[tuple[tuple[Any, ...], dict[str, Any]]] = []

    def report(self, *args: Any, **kwargs: Any) -> None:
        self.reports.append((args, kwargs))


def build(found: Tables, text: str, start: str, builder: Builder, base: int, most_depth: int) -> Any:
    """The value of the rule `start` over `text` (a chunk at `base` in its file), built by
    `builder` as it reduces; raises Retry where Lark and the Builder's walk must do it."""
    diagnostics = builder.diagnostics
    deferred = _Deferred()
    builder.diagnostics = deferred  # type: ignore[assignment]  # it only reports
    builder.base = base
    builder.prefixed.clear()
    builder.depth.clear()
    try:
        value = _run(found, text, start, transformer_class()(builder), most_depth)
    except TooDeep:
        raise Retry from None
    finally:
        builder.diagnostics = diagnostics
        builder.prefixed.clear()
        builder.depth.clear()
    for args, kwargs in deferred.reports:
        diagnostics.report(*args, **kwargs)
    return value


def _run(found: Tables, text: str, start: str, transformer: Any, most_depth: int) -> Any:
    """The LALR loop (Lark's `ParserState.feed_token`), each reduction shaped as Lark's tree
    builder shapes it (`PropagatePositions`, `ChildFilterLALR`, `ExpandSingleChild`)."""
    states, end_state = found.states, found.end[start]
    lexers = found.lexer.lexers
    new_token: Callable[..., Any] = lark.Token._future_new
    methods = found.methods
    scanners: dict[int, _Scanner] = found.scanners
    pos, line, line_start, length = 0, 1, 0, len(text)
    subject = _subject(text)
    state_stack = [found.start[start]]
    # Per value on the stack: (the value, its span as its parent sees it (Lark's container
    # positions) or None, whether Lark's value would be a Tree, its depth in Lark's tree).
    stack: list[tuple[Any, tuple[int, int] | None, bool, int]] = []
    end = False
    token: Any = None
    while True:
        while not end:  # the next token, as Lark's lexer of this state reads it (BasicLexer.next_token)
            if pos >= length:
                token, end = lark.Token("$END", ""), True
                break
            state = state_stack[-1]
            scanner = scanners.get(state)
            if scanner is None:
                scanner = scanners[state] = _scanner(lexers[state])
            pattern, allowed, match, ignored, callbacks, newlines = scanner
            hit = pattern(text, pos) if pattern is not None else None  # Lark's Scanner.match, inline
            if hit is not None and (allowed is None or hit.lastgroup in allowed):
                read, kind = hit.group(0), hit.lastgroup
            else:
                matched = match(subject, pos)
                if not matched:
                    raise Retry
                read, kind = matched
            begin, begin_line, column = pos, line, pos - line_start + 1
            pos += len(read)
            if kind in newlines:
                count = read.count("\n")
                if count:
                    line += count
                    line_start = begin + read.rindex("\n") + 1
            if kind in ignored:
                continue
            token = new_token(kind, read, begin, begin_line, column, line, pos - line_start + 1, pos)
            callback = callbacks.get(kind)
            if callback is not None:
                token = callback(token)
            break
        while True:
            action = states[state_stack[-1]].get(token.type)
            if action is None:
                raise Retry
            if action[0] is Shift:
                if end:
                    raise Retry
                state_stack.append(action[1])
                stack.append((token, (token.start_pos, token.end_pos), False, 0))
                break
            rule = action[1]
            if rule.unit:  # a `?rule` over one symbol: its child's value, span and depth are its own
                del state_stack[-1]
                state_stack.append(states[state_stack[-1]][rule.origin][1])
                if end and state_stack[-1] == end_state:
                    return stack[-1][0]
                continue
            size = rule.size
            if size:
                entries = stack[-size:]
                del stack[-size:], state_stack[-size:]
            else:
                entries = []
            span = None
            depth = 0
            for entry in entries:
                if entry[3] > depth:  # noqa: PLR1730  # max() would be a call per child
                    depth = entry[3]
                if entry[1] is not None:
                    if span is None:
                        span = entry[1]
                    else:
                        span = (span[0], entry[1][1])
            if rule.keep is not None:
                entries = _kept(rule, entries)
            if rule.single and len(entries) == 1:
                value, child_span, tree, _ = entries[0]
                if tree and child_span is None and span is not None:
                    raise Retry  # Lark would give the empty child this rule's positions after it was built
                if not tree or span is None:
                    span = child_span
            elif rule.spliced:
                value, tree = entries, True
            else:
                method = methods.get(rule.name)
                if method is None:
                    method = methods[rule.name] = _method(type(transformer), rule.name)
                depth += 1
                if depth > most_depth:
                    raise Retry
                value = method(transformer, _EMPTY if span is None else _Meta(span), [entry[0] for entry in entries])
                tree = True
            state_stack.append(states[state_stack[-1]][rule.origin][1])
            stack.append((value, span, tree, depth))
            if end and state_stack[-1] == end_state:
                return value


def parse_built(text: str, builder: Builder, base: int, parser: lark.Lark, most_depth: int) -> list[ast.Decl]:
    """The declarations of `text` (a chunk at `base` in its file) built by the loop, or Retry."""
    found = tables(parser)
    if found is None:
        raise Retry
    built: list[ast.Decl] = build(found, text, "start", builder, base, most_depth)
    return built

