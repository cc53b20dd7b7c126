"""Which regular expressions can take more than linear time on a reply line.

Python's `re` backtracks. A regex is slow on a bad line only where the same text can be
split between its parts in many ways, and each way is tried before the match fails:

- two parts of variable length, one after the other, that can match the same
  characters (`\\s*\\s*`, `\\d+\\d*`, `.*,.*`: the characters between them give no
  fence): n² ways, n³ with three, and so on;
- a repeated part whose body can be split that way across two of its rounds
  (`(a+)+`, `(?:a{0,64}){0,64}`, `(a|a)*`, `(a|aa)*`): exponentially many ways.

`risk` walks the parse tree and reports the first such shape. It is conservative: a
fixed character between two parts (`(\\d+),(\\d+)`) is a fence only when neither part
can match it. Possessive repeats and atomic groups give nothing back, so they are safe.
Reply lines are latin-1 text, so character sets are sets of the 256 code points. The walk
also tells what a pattern's matches begin with (`first_characters`), by which the parser's
scanner orders the grammar's terminals.
"""

from __future__ import annotations

import re
import sys
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING or sys.version_info < (3, 11):  # typeshed describes the parser under its old names
    import sre_constants as c
    import sre_parse as _parser
    from sre_compile import compile as _compile_parsed
else:  # where Python 3.11 moved them (the old names warn)
    from re import _constants as c
    from re import _parser
    from re._compiler import compile as _compile_parsed

ALL = frozenset(range(256))
MAX_NESTING = 6  # repeats within repeats: deeper is refused as too complex to judge
LONGEST = 4096  # characters of a reply line (the engine's MAX_LINE): the spread of `*` and `+`
BUDGET = 16 * LONGEST  # the most ways a run of parts that share characters may split a line
MOST_CLASSES = 4096  # classes whose characters are kept: a check's memory stays bounded

_CATEGORIES = {
    c.CATEGORY_DIGIT: r"\d", c.CATEGORY_NOT_DIGIT: r"\D", c.CATEGORY_SPACE: r"\s",
    c.CATEGORY_NOT_SPACE: r"\S", c.CATEGORY_WORD: r"\w", c.CATEGORY_NOT_WORD: r"\W",
}
_CATEGORY_SETS: dict[Any, frozenset[int]] = {}  # each category's bytes, once asked for (start-up time)


def _category(category: Any) -> frozenset[int]:
    """The bytes a category (`\\d`, `\\s`, ...) matches; ALL for one this does not know."""
    found = _CATEGORY_SETS.get(category)
    if found is None:
        pattern = _CATEGORIES.get(category)
        found = ALL if pattern is None else frozenset(i for i in range(256) if re.fullmatch(pattern, chr(i)))
        _CATEGORY_SETS[category] = found
    return found


class Risky(Exception):
    """A shape that can backtrack without bound; the message says which."""


class _Shape:
    """What the walk knows of a part of a pattern (a plain class: `rdisc check` need not import
    `dataclasses`)."""

    __slots__ = ("chars", "first", "nullable", "spread")

    def __init__(self, chars: frozenset[int], first: frozenset[int], spread: int, nullable: bool) -> None:
        self.chars = chars  # what the part can match, anywhere in it
        self.first = first  # what its match can start with
        self.spread = spread  # the ways it can match one text (lengths, branches), 1 for a fixed part
        self.nullable = nullable  # it can match the empty text

    @property
    def variable(self) -> bool:
        return self.spread > 1


def parse_tree(pattern: str) -> _parser.SubPattern:
    """The parse tree of `pattern` by Python's own regex parser (raises re.error)."""
    return _parser.parse(pattern)


def compiled(parsed: _parser.SubPattern) -> re.Pattern[str]:
    """The pattern `re.compile` makes of the text `parsed` was parsed from (without parsing it again)."""
    made: re.Pattern[str] = _compile_parsed(parsed)
    return made


def first_characters(pattern: str) -> frozenset[int]:
    """The characters a match of `pattern` can begin with (case folded both ways, ALL where any
    can): the walk's reading, which the parser's scanner orders its terminals by
    (rdisc.syntax.scan_order). Empty where only characters past 255 can."""
    parsed = parse_tree(pattern)
    return _Walk(parsed.state).first(list(parsed.data))


def tested_by_one_character(pattern: str) -> bool:
    """Whether `re` rejects the pattern, as an alternative of an alternation, by testing the one
    character before it: it begins with a literal or a class (after `re`'s parser has made
    `(?:a|b)` one); any other it enters."""
    items = parse_tree(pattern).data
    return bool(items) and items[0][0] in (c.LITERAL, c.IN)


def risk(pattern: str | _parser.SubPattern) -> str | None:
    """Why `pattern` (its text, or its parse tree) can take more than linear time on some line, or
    None (it cannot)."""
    parsed = parse_tree(pattern) if isinstance(pattern, str) else pattern
    try:
        _Walk(parsed.state).sequence(list(parsed.data), [], 0)
    except Risky as err:
        return str(err)
    return None


class _Walk:
    def __init__(self, state: _parser.State) -> None:
        self.state = state
        self.strict = False  # within two rounds of a repeat: any two variable parts sharing characters are too many

    def sequence(self, items: list[Any], live: list[tuple[frozenset[int], int]],
                 depth: int) -> list[tuple[frozenset[int], int]]:
        """Walk parts in order. `live`: the character sets and spreads of earlier variable parts
        that could still take characters from the part at hand; returned as they are after."""
        for item in items:
            if item[0] is c.LITERAL:  # the commonest part, a fence: what `part` would make of it, made directly
                if live:
                    cased = _cased(item[1])
                    live = [(chars, spread) for chars, spread in live if chars & cased]
                continue
            shape, live = self.part(item, live, depth)
            if shape is None:
                continue
            if shape.variable:
                ways = shape.spread
                for chars, spread in live:
                    if chars & shape.first:
                        ways *= spread
                if ways > (shape.spread if self.strict else BUDGET):
                    raise Risky("parts of variable length in a row can match the same characters, which "
                                "takes polynomial time on a bad reply: put a character neither matches "
                                "between them, or make the first possessive (`*+`, `++`)")
                live = [*live, (shape.chars, shape.spread)]
            elif not shape.nullable:  # a fence, unless an earlier variable part can match it too
                live = [(chars, spread) for chars, spread in live if chars & shape.chars]
        return live

    def part(self, item: Any, live: list[tuple[frozenset[int], int]], depth: int) -> tuple[_Shape | None, list[tuple[frozenset[int], int]]]:
        """The shape of one part (None: zero width) and `live` after what is inside it."""
        op, av = item
        if op is c.AT:
            return None, live
        if op in (c.ASSERT, c.ASSERT_NOT):
            self.sequence(list(av[1]), [], depth)
            return None, live
        if op is c.SUBPATTERN:
            body = av[-1]
            return None, self.sequence(list(body), live, depth)
        if op in (c.MAX_REPEAT, c.MIN_REPEAT):
            return self.repeat(av, live, depth)
        if op is c.BRANCH:
            return self.branch(av[1], live, depth), live
        if op is c.GROUPREF_EXISTS:
            branches = [av[1]] + ([av[2]] if av[2] is not None else [_parser.SubPattern(self.state)])
            return self.branch(branches, live, depth), live
        if op is c.ATOMIC_GROUP or op is getattr(c, "POSSESSIVE_REPEAT", None):
            body = av if op is c.ATOMIC_GROUP else av[2]
            self.sequence(list(body), [], depth + 1)
            low, _ = self.width([item])
            return _Shape(self.chars(list(body)), self.first(list(body)), 1, low == 0), live
        if op is c.GROUPREF:
            return _Shape(ALL, ALL, LONGEST, True), live
        chars = self.chars([item])
        return _Shape(chars, chars, 1, False), live

    def repeat(self, av: Any, live: list[tuple[frozenset[int], int]], depth: int) -> tuple[_Shape, list[tuple[frozenset[int], int]]]:
        low, high, body = av
        if depth >= MAX_NESTING:
            raise Risky(f"repeats are nested more than {MAX_NESTING} deep")
        items = list(body)
        if len(items) == 1 and items[0][0] in _ONE_CHARACTER:  # `\d+`, `[0-9a-f]*`, ` ?`: the commonest repeat
            # One character a round: no part of a round, nor of two, varies, so neither walk below
            # could find a risk; what they leave is its character set, one character wide.
            chars = self.chars(items)
            longest = LONGEST if high >= c.MAXREPEAT else min(high, LONGEST)
            return _Shape(chars, chars, max(1, longest - low + 1), low == 0), live
        self.sequence(items, [], depth + 1)
        if high > 1:  # one round after another must not be able to share characters
            strict, self.strict = self.strict, True
            try:
                self.sequence(items + items, [], depth + 1)
            except Risky:
                raise Risky("a repeated part can split the same text between its rounds in many ways, "
                            "which takes exponential time on a bad reply: rewrite it without nesting, "
                            "or make the inner part possessive (`++`, `*+`)") from None
            finally:
                self.strict = strict
        body_low, body_high = self.width(items)
        longest = LONGEST if high >= c.MAXREPEAT or body_high >= c.MAXREPEAT else min(high * body_high, LONGEST)
        spread = max(1, longest - low * body_low + 1)
        return _Shape(self.chars(items), self.first(items), spread, low == 0 or body_low == 0), live

    def branch(self, branches: list[Any], live: list[tuple[frozenset[int], int]], depth: int) -> _Shape:
        sets, firsts = [], []
        for alternative in branches:
            self.sequence(list(alternative), list(live), depth)
            sets.append(self.chars(list(alternative)))
            firsts.append(self.first(list(alternative)))
        widths = [self.width(list(alternative)) for alternative in branches]
        low = min(w[0] for w in widths)
        high = min(max(w[1] for w in widths), LONGEST)
        overlapping = any(a & b for i, a in enumerate(firsts) for b in firsts[i + 1 :])
        spread = (high - low + 1) * (len(branches) if overlapping else 1)
        return _Shape(frozenset().union(*sets), frozenset().union(*firsts), spread, low == 0)

    def first(self, items: list[Any]) -> frozenset[int]:
        """What a match of the parts can start with (up to the first part that cannot be empty)."""
        out: frozenset[int] = frozenset()
        for item in items:
            op, av = item
            if op in (c.AT, c.ASSERT, c.ASSERT_NOT):
                continue
            nested = _nested(op, av)
            if nested is not None:
                out = out.union(*(self.first(part) for part in nested))
            else:
                out |= self.chars([item])
            if self.width([item])[0] > 0:
                break
        return out

    def width(self, items: list[Any]) -> tuple[int, int]:
        low, high = _parser.SubPattern(self.state, items).getwidth()
        return low, high

    def chars(self, items: list[Any]) -> frozenset[int]:
        """Every character the parts can match (case folded both ways, to be safe)."""
        out: set[int] = set()
        for op, av in items:
            if op is c.LITERAL:
                out |= _cased(av)
            elif op is c.NOT_LITERAL:
                out |= ALL - {av}
            elif op is c.ANY:
                out |= ALL
            elif op is c.IN:
                out |= _in(av)
            elif (nested := _nested(op, av)) is not None:
                for part in nested:
                    out |= self.chars(part)
            elif op is c.GROUPREF_EXISTS:
                out |= self.chars(list(av[1])) | (self.chars(list(av[2])) if av[2] is not None else set())
            elif op not in (c.AT, c.ASSERT, c.ASSERT_NOT):
                out |= ALL  # a back reference, or anything not known here: anything
        return frozenset(out)


def _nested(op: Any, av: Any) -> list[list[Any]] | None:
    """The parts a repeat, a group or a branch holds (each alternative a part of its own), which
    a walk of what a pattern can match goes into; None for any other node."""
    if op in (c.MAX_REPEAT, c.MIN_REPEAT) or op is getattr(c, "POSSESSIVE_REPEAT", None):
        return [list(av[2])]
    if op is c.SUBPATTERN:
        return [list(av[-1])]
    if op is c.ATOMIC_GROUP:
        return [list(av)]
    if op is c.BRANCH:
        return [list(alternative) for alternative in av[1]]
    return None


# The parts that match one character, whatever it is (sre's own `getwidth` counts each as 1 to 1).
_ONE_CHARACTER = (c.LITERAL, c.NOT_LITERAL, c.ANY, c.IN)
_CASED: dict[int, frozenset[int]] = {}  # a character's code → it and its other cases, once asked for


def _cased(code: int) -> frozenset[int]:
    found = _CASED.get(code)
    if found is None:
        ch = chr(code)
        found = frozenset() if code > 255 else \
            frozenset(ord(x) for x in (ch, ch.lower(), ch.upper()) if len(x) == 1 and ord(x) < 256)
        _CASED[code] = found
    return found


_IN_SETS: dict[tuple[Any, ...], frozenset[int]] = {}  # a class's parts → its characters, once made (bounded)


def _in(items: Any) -> frozenset[int]:
    """The characters a class (`[...]`, `\\d`) matches: made once for each class, which a
    description's patterns repeat (`\\d+` in most of them)."""
    key = tuple(items)
    found = _IN_SETS.get(key)
    if found is None:
        found = _made_in(items)
        if len(_IN_SETS) < MOST_CLASSES:
            _IN_SETS[key] = found
    return found


def _made_in(items: Any) -> frozenset[int]:
    out: set[int] = set()
    negate = False
    for op, av in items:
        if op is c.NEGATE:
            negate = True
        elif op is c.LITERAL:
            out |= _cased(av)
        elif op is c.RANGE:
            low, high = av
            for code in range(low, min(high, 255) + 1):
                out |= _cased(code)
        elif op is c.CATEGORY:
            out |= _category(av)
        else:
            out |= ALL
    return ALL - out if negate else frozenset(out)
