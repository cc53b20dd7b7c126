"""The grammar's LALR tables (rdisc/syntax/tables.py, written from Lark's) run by a loop of rdisc's
own that builds AST nodes as it reduces, without Lark.

Lark parses a declaration into a tree (each node shaped by wrappers: tokens filtered out,
`_rule`s spliced into their parent, a `?rule` of one child passed through, positions
propagated), and then a Transformer walks the tree to build AST nodes: at 100,000 lines the
wrappers and the walk are most of a check, and importing Lark and loading the grammar are most
of a cold check of a small file. This loop reads Lark's parse table, its contextual lexer's
terminals and each rule's shaping as rdisc.syntax.tables_writer wrote them from Lark's parser,
and calls the Builder's method for a rule the moment the rule is reduced, with the children and
positions Lark's tree would have given it.

It takes only the clean case: at any syntax error (a keyword read as a name included), a tree
deeper than MAX_TREE_DEPTH, an expression the Builder refuses as too deep, or a shape the
Builder never sees, it gives up (`Retry`) and the declaration is parsed by Lark and built from
its tree as before. So every diagnostic comes from the one path that writes it; what the
Builder reports along the way is kept back until the declaration is built.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from rdisc import TYPE_CHECKING
from rdisc.syntax import ast, tables
from rdisc.syntax.build import Builder, Rules, TooDeep, rule_methods

if TYPE_CHECKING:
    from typing import Any


class Retry(Exception):
    """This declaration is not for the fast loop: Lark parses it, and the Builder walks its tree."""


class _Empty:
    """The Meta of a node with no tokens (an empty optional part): Lark's has no positions. (A node
    with tokens gets its (start, end) in place of a Meta: Builder.span reads either.)"""

    __slots__ = ()
    empty = True


_EMPTY = _Empty()


class Token(str):
    """A token as the Builder reads it, Lark's Token made lighter: its text, and where it starts
    and ends in the chunk (in slots: made and read faster than in a dict)."""

    __slots__ = ("end_pos", "start_pos")
    start_pos: int
    end_pos: int


def _token(entry: tuple[Any, tuple[int, int] | None, bool, int]) -> Token | None:
    """The Token of a token's stack entry (None for the placeholder of an absent optional part),
    made only when the Builder takes it: most tokens (keywords, punctuation) are filtered out, and
    making one for each was a tenth of the loop."""
    if entry[1] is None:
        return None
    token = Token(entry[0])
    token.start_pos, token.end_pos = entry[1]
    return token


# One rule of tables.RULES: how its children become its value, as Lark's wrappers of the rule shape
# them: (origin: the nonterminal it reduces to; size: the symbols on its right-hand side; keep: the
# kept children, each (index, spliced, Nones before), or None for all; Nones after; single: a
# `?rule`, one child left is the value itself; name: the Builder's method, or the `_rule` spliced
# into its parent; spliced: a `_rule`, its children go into its parent's; unit: a `?rule` of one
# symbol, kept, which passes its child on as it is (value, span, depth)). Plain tuples, as written:
# a cold check makes no object of its ~450 rules.
Rule = tuple[str, int, tuple[tuple[int, bool, int], ...] | None, int, bool, str, bool, bool]
_NONE = (None, None, False, 0)  # a placeholder of an optional part that is not there


def _kept(keep: tuple[tuple[int, bool, int], ...], entries: list[Any], nones_after: int = 0) -> list[Any]:
    """The entries of the children a rule keeps, as Lark's ChildFilterLALR keeps them: tokens
    filtered out, placeholders of absent optional parts put in, a `_rule`'s entries (its value)
    spliced in its place."""
    kept: list[Any] = []
    for i, spliced, nones in keep:
        if nones:
            kept += [_NONE] * nones
        if spliced:
            kept += entries[i][0]
        else:
            kept.append(entries[i])
    if nones_after:
        kept += [_NONE] * nones_after
    return kept


class Lexer:
    """A parser state's lexer, as Lark's contextual lexer makes it: the terminals the state
    accepts, tried in Lark's order, and the keywords a name may be there.

    The whole grammar's pattern tries the same terminals in the same order, so where the terminal
    it finds is one the state accepts, the state's own pattern would have found that terminal and
    that text too (the first alternative to match is the first of any subset that contains it);
    only where it is not is the state's own lexer asked (rdisc/syntax/lexing.py does the same
    inside Lark)."""

    __slots__ = ("_asked", "_match", "_tries", "_words", "allowed", "keywords", "terminals")

    def __init__(self, terminals: tuple[str, ...], keywords: dict[str, str]) -> None:
        self.terminals, self.keywords = terminals, keywords
        self.allowed = frozenset(terminals)
        self._tries: tuple[tuple[str, str | None, Callable[[str, int], re.Match[str] | None]], ...] = ()
        self._asked = 0
        self._match: Callable[[str, int], re.Match[str] | None] | None = None
        self._words: dict[str, str] | None = None

    def word(self, name: str) -> str | None:
        """The terminal `own` reads, to the end of `name`, where the whole grammar's pattern read
        `name` as a NAME and `name` is one of the state's keywords: most of what `own` is asked
        (`primitive` at the start of a declaration, `on`, `pack`), found without its pattern. None
        where `own` must be asked."""
        if self._words is None:
            self._words = self._keywords_alone()
        return self._words.get(name)

    def _keywords_alone(self) -> dict[str, str]:
        """Each keyword of the state and the terminal `own` reads at that keyword when the whole
        grammar's pattern reads a NAME there, to its end: the first of the state's terminals that
        can match there, in order. A terminal the whole grammar's pattern tries before NAME did
        not match there (it would have been read instead); a keyword (a literal of word
        characters) matches where it begins the name; nor did a skipped one (comments, white space:
        the pattern skips them all before a token); for any other terminal the text after the name
        could matter, and `own` is asked."""
        before_name = set(tables.ROOT[:tables.ROOT.index("NAME")])
        literals = {name: _terminal(name)[0] for name in self.terminals if name not in tables.ROOT}
        words: dict[str, str] = {}
        for keyword in literals.values():
            if keyword is None or not re.fullmatch(r"\w+", keyword):
                continue
            for name in self.terminals:
                if name in before_name or name in tables.IGNORED:
                    continue
                literal = literals.get(name)
                if literal is None or not re.fullmatch(r"\w+", literal):
                    break  # `own` must say
                if keyword.startswith(literal):
                    if literal == keyword:  # (a shorter one, read first, leaves the rest to `own`)
                        words[keyword] = name
                    break
        return words

    def own(self, text: str, pos: int) -> tuple[str, int] | None:
        """The terminal the state's own pattern (its terminals' alternation, in order) reads at
        `pos`, and where it ends: the first terminal that matches there, as an alternation's
        first matching alternative is. The first ALONE times, each terminal is tried alone (a
        literal as a string): compiling the alternations of the dozen states a small file meets
        was a third of its cold check. A state asked more (a large description asks a few states
        thousands of times) has its alternation compiled, which reads the same faster."""
        if self._match is None:
            self._asked += 1
            if self._asked <= ALONE:
                return self._alone(text, pos)
            self._match = re.compile("|".join(f"(?P<{name}>{tables.TERMINALS[name]})" for name in self.terminals)).match
        hit = self._match(text, pos)
        return None if hit is None else (str(hit.lastgroup), hit.end())

    def _alone(self, text: str, pos: int) -> tuple[str, int] | None:
        """`own`, each terminal tried alone, in order."""
        if not self._tries:
            self._tries = tuple((name, *_terminal(name)) for name in self.terminals)
        for name, literal, match in self._tries:
            if literal is not None:
                if text.startswith(literal, pos):
                    return name, pos + len(literal)
            else:
                hit = match(text, pos)
                if hit is not None:
                    return name, hit.end()
        return None


ALONE = 32  # times a state's lexer tries its terminals one at a time before it compiles their alternation
_TERMINAL_MATCHES: dict[str, tuple[str | None, Callable[[str, int], re.Match[str] | None]]] = {}


def _terminal(name: str) -> tuple[str | None, Callable[[str, int], re.Match[str] | None]]:
    """How a terminal is tried alone: its text where its pattern is a literal (Lark writes a
    string terminal as its escaped text), else its pattern's match (compiled once, for every
    state)."""
    made = _TERMINAL_MATCHES.get(name)
    if made is None:
        pattern = tables.TERMINALS[name]
        text = re.sub(r"\\(.)", r"\1", pattern, flags=re.DOTALL)
        if re.escape(text) == pattern:
            made = (text, _never)
        else:
            made = (None, re.compile(pattern).match)
        _TERMINAL_MATCHES[name] = made
    return made


def _never(text: str, pos: int) -> None:
    """The match of a literal terminal, never asked (it is compared as a string)."""


_LEXERS = [Lexer(terminals, keywords) for terminals, keywords in tables.LEXERS]
STATE_LEXERS = tuple(_LEXERS[i] for i in tables.STATE_LEXERS)
_STATE_ALLOWED = tuple(lexer.allowed for lexer in STATE_LEXERS)
_STATE_KEYWORDS = tuple(lexer.keywords for lexer in STATE_LEXERS)
_STOP = "_STOP"  # the scanner's last alternative: nothing else matches (the end of the text, or no token)
_scanners: list[re.Pattern[str]] = []  # the scanner's pattern, once made


def _scanner() -> Callable[[str, int], re.Match[str]]:
    """The match of the scanner's pattern (`_pattern`)."""
    return _pattern().match  # type: ignore[return-value]  # its last alternative never fails


def _pattern() -> re.Pattern[str]:
    """One pattern that skips what every lexer skips (group 1) and then reads the
    whole grammar's next token: the root lexer's terminals (in `tables.SCAN`'s order, which reads
    what the root lexer's order reads: rdisc.syntax.scan_order), each followed by an empty
    group named after it (the last group a match closes, so its `lastgroup`), and last an empty
    `_STOP`.

    The skipped terminals (comments, white space) can begin where no terminal tried before them
    can (a test holds that), so skipping them all at once skips what the root lexer, tried again
    after each, would. The empty last alternative makes the match never fail after the skip, so
    the pattern never backtracks into what it skipped (a `///` comment is never read back as `//`); the
    skip is possessive (`*+`), which says so to `re`, and saves it keeping the places to go back to.
    A terminal's name goes after it, not around it, so that an alternative begins with its first
    character, which `re` checks before it tries the alternative (a quarter of the lexer's time)."""
    if not _scanners:
        _scanners.append(scanner_pattern(tables.SCAN))
    return _scanners[0]


def scanner_pattern(read: tuple[str, ...]) -> re.Pattern[str]:
    """`_pattern` with the terminals read tried in the order `read` (a test compares the root
    lexer's own order with SCAN's)."""
    skipped = [tables.TERMINALS[name] for name in tables.ROOT if name in tables.IGNORED]
    # White space (a character class, repeated) skipped first, by a loop over its characters:
    # most tokens follow one space, which the general loop over the skipped terminals is slower at.
    spaces = "".join(f"{pattern[:-1]}*+" for pattern in skipped if re.fullmatch(r"\[[^\]]+\]\+", pattern))
    alternatives = "|".join(f"(?:{tables.TERMINALS[name]})(?P<{name}>)" for name in read)
    return re.compile(f"({spaces}(?:(?:{'|'.join(skipped)}){spaces})*+)(?:{alternatives}|(?P<{_STOP}>))")


# The Builder's method for each rule name that has one (under `v_args(meta=True)`: it takes the
# Rules, the meta and the children).
_METHODS: dict[str, Callable[..., Any]] = rule_methods()


def _step(rule: Rule) -> tuple[Any, ...]:
    """What the loop reads of a rule that is not a unit (`UNITS`), in one tuple: (origin, size,
    keep, nones after, the kept children's indices where it splices none (else None; `size`
    stands for a placeholder, which the loop puts after the children), single, spliced, the
    Builder's method or None, those indices again where the rule is simply the method called with
    those children (else None), whether the method reads only the text of a token child
    (Rules.TEXT_ONLY), and whether the rule has placeholders)."""
    origin, size, keep, nones_after, single, name, spliced, _ = rule
    picked: tuple[int, ...] | None = None
    if keep is None:
        picked = tuple(range(size))
    elif not any(spliced for _, spliced, _ in keep):  # as _kept keeps them, a placeholder at `size`
        picked = (*(j for i, _, nones in keep for j in (*[size] * nones, i)), *[size] * nones_after)
    padded = picked is not None and size in picked
    method = None if spliced else _METHODS.get(name)
    direct = None
    # (A rule of one symbol with placeholders is not for the loop's path of one child.)
    if method is not None and picked is not None and not (single and len(picked) == 1) and not (padded and size == 1):
        direct = picked
    return (origin, size, keep, nones_after, picked, single, spliced, method, direct, name in Rules.TEXT_ONLY,
            padded)


STEPS = tuple(_step(rule) for rule in tables.RULES)
# Each rule's origin where it is a unit (a `?rule` of one symbol, kept), else None: the loop's most
# frequent reduction (an operand passed on as an expression) needs nothing else of its rule.
UNITS = tuple(rule[0] if rule[7] else None for rule in tables.RULES)


# (the state below, a state whose action on the token is a unit's reduction, the token's kind) → the
# state after that reduction and each unit reduction that follows it on the same token; found once.
_CHAINS: dict[tuple[int, int, str], int] = {}


def _pass_units(below: int, state: int, kind: str) -> int:
    """The state the loop reaches from `state` (over `below`) by the unit reductions it makes on a
    token of `kind`, one after another, before it shifts the token or makes another reduction (or
    finds no action: the loop's next lookup raises the syntax error)."""
    actions = tables.ACTIONS
    action = actions[state][kind]
    while action < 0 and (origin := UNITS[~action]) is not None:
        state = actions[below][origin]
        action = actions[state].get(kind, 0)  # none: the loop's own lookup raises
    return state


class _Deferred:
    """What the Builder reports while a declaration is built by the loop, kept until it is done."""

    def __init__(self) -> None:
        self.reports: list[tuple[tuple[Any, ...], dict[str, Any]]] = []

    def report(self, *args: Any, **kwargs: Any) -> None:
        self.reports.append((args, kwargs))


def build(text: str, start: str, builder: Builder, base: int, most_depth: int) -> Any:
    """The value of the rule `start` over `text` (a chunk at `base` in its file), built by
    `builder` as it reduces; raises Retry where Lark and the Builder's walk must do it."""
    diagnostics = builder.diagnostics
    deferred = _Deferred()
    builder.diagnostics = deferred  # type: ignore[assignment]  # it only reports
    builder.base = base
    builder.prefixed.clear()
    builder.depth.clear()
    try:
        value = _run(text, start, Rules(builder), most_depth)
    except (TooDeep, KeyError):  # KeyError: a token the state has no action for (a syntax error)
        raise Retry from None
    finally:
        builder.diagnostics = diagnostics
        builder.prefixed.clear()
        builder.depth.clear()
    for args, kwargs in deferred.reports:
        diagnostics.report(*args, **kwargs)
    return value


def _run(text: str, start: str, rules: Rules, most_depth: int) -> Any:
    """The LALR loop (Lark's `ParserState.feed_token`) over Lark's contextual lexer's tokens
    (`ContextualLexer.lex`), each reduction shaped as Lark's tree builder shapes it
    (`PropagatePositions`, `ChildFilterLALR`, `ExpandSingleChild`)."""
    actions, steps, units, lexers, ignored = tables.ACTIONS, STEPS, UNITS, STATE_LEXERS, tables.IGNORED
    chains = _CHAINS
    allowed, keywords = _STATE_ALLOWED, _STATE_KEYWORDS
    # The pattern's matches one after another, each where the last ended (`_scanner`'s match at that
    # place: a `re` scanner, which sets up its matching once, not at each token, a tenth of the loop's
    # lexing); made again where a state's own lexer read a token of another length. (After an empty
    # match a scanner's next may not be empty: the loop reads none after one, `_STOP`.)
    # (`Pattern.scanner`, what `re.Scanner` reads with, is left out of the typing stubs.)
    scanner: Callable[..., Any] = _pattern().scanner  # type: ignore[attr-defined]
    scan: Callable[[], re.Match[str]] = scanner(text).match
    end_state = tables.END[start]
    pos, length = 0, len(text)
    state = tables.START[start]
    states = [state]
    # Per value on the stack: (the value, its span as its parent sees it (Lark's container
    # positions) or None, whether Lark's value would be a Tree (else it is a token's text, and the
    # span its own), its depth in Lark's tree).
    stack: list[tuple[Any, tuple[int, int] | None, bool, int]] = []
    push, push_state = stack.append, states.append
    end = False
    token: Any = None
    kind: str | Any = ""
    begin = 0
    while True:
        if not end:  # the next token, as Lark's lexer of this state reads it (BasicLexer.next_token)
            hit = scan()
            kind = hit.lastgroup
            if kind == _STOP:
                if hit.end() < length:
                    raise Retry  # no terminal matches here: neither does the state's lexer
                kind, token, end = "$END", None, True
            else:
                begin, pos = hit.end(1), hit.end()
                if kind not in allowed[state]:  # the state's own lexer reads something else here
                    lexer = lexers[state]
                    word = lexer.word(text[begin:pos]) if kind == "NAME" else None
                    if word is not None:  # a keyword, read whole
                        kind = word
                    else:
                        own = lexer.own(text, begin)
                        if own is None or own[0] in ignored:
                            raise Retry
                        kind, own_end = own
                        if own_end != pos:
                            pos = own_end
                            scan = scanner(text, pos).match
                token = text[begin:pos]  # a plain str on the stack until the Builder takes it (_token)
                if kind == "NAME":
                    kind = keywords[state].get(token, kind)
        while True:
            action = actions[state][kind]  # KeyError: a syntax error, Retry (build)
            if action >= 0:  # shift
                if end:
                    raise Retry
                push_state(action)
                state = action
                push((token, (begin, pos), False, 0))
                break
            origin = units[~action]
            if origin is not None:  # a `?rule` over one symbol: its child's value, span and depth are its own
                if end:
                    state = states[-1] = actions[states[-2]][origin]
                    if state == end_state:
                        return stack[-1][0]
                    continue
                # The state after this unit and the units it leads to (an operand passed up to an
                # expression), the same wherever the state below and the token are the same.
                key = (states[-2], state, kind)
                passed = chains.get(key)
                if passed is None:
                    passed = chains[key] = _pass_units(states[-2], state, kind)
                state = states[-1] = passed
                continue
            origin, size, keep, nones_after, picked, single, spliced, method, direct, text_only, padded = steps[~action]
            if size == 1:
                entry = stack.pop()
                del states[-1]
                span, depth = entry[1], entry[3]
                if direct is not None:  # the Builder's node of one child (a literal, a name)
                    if depth >= most_depth:
                        raise Retry
                    state = actions[states[-1]][origin]
                    push_state(state)
                    child = entry[0] if entry[2] or text_only else _token(entry)
                    push((method(rules, _EMPTY if span is None else span, [child]), span, True, depth + 1))
                    if end and state == end_state:
                        return stack[-1][0]
                    continue
                entries = [entry]
            else:
                if size:
                    entries = stack[-size:]
                    del stack[-size:], states[-size:]
                else:
                    entries = []
                first = last = None
                depth = 0
                for entry in entries:
                    if entry[3] > depth:  # noqa: PLR1730  # max() would be a call per child
                        depth = entry[3]
                    if entry[1] is not None:
                        if first is None:
                            first = entry[1]
                        last = entry[1]
                span = None if first is None or last is None else (first[0], last[1])
            if padded:  # the placeholder `picked` reads at `size`
                entries.append(_NONE)
            if direct is not None:  # the common case: the Builder's node of some of the children
                depth += 1
                if depth > most_depth:
                    raise Retry
                value = method(rules, _EMPTY if span is None else span,
                               [entry[0] if entry[2] else _token(entry) for entry in map(entries.__getitem__, direct)])
                tree = True
            else:
                if keep is not None and picked is not None:
                    entries = [entries[i] for i in picked]
                elif keep is not None:
                    entries = _kept(keep, entries, nones_after)
                if single and len(entries) == 1:
                    value, child_span, tree, _ = entries[0]
                    if tree and child_span is None and span is not None:
                        raise Retry  # Lark would give the empty child this rule's positions after it was built
                    if not tree or span is None:
                        span = child_span
                elif spliced:
                    value, tree = entries, True
                else:
                    if method is None:
                        raise Retry  # Lark's tree would keep the node
                    depth += 1
                    if depth > most_depth:
                        raise Retry
                    value = method(rules, _EMPTY if span is None else span,
                                   [entry[0] if entry[2] else _token(entry) for entry in entries])
                    tree = True
            state = actions[states[-1]][origin]
            push_state(state)
            push((value, span, tree, depth))
            if end and state == end_state:
                return value


def parse_built(text: str, builder: Builder, base: int, most_depth: int) -> list[ast.Decl]:
    """The declarations of `text` (a chunk at `base` in its file) built by the loop, or Retry."""
    built: list[ast.Decl] = build(text, "start", builder, base, most_depth)
    return built
