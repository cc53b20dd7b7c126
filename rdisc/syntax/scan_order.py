"""The order in which the fast loop's scanner tries the whole grammar's terminals
(rdisc.syntax.reduce's pattern): Lark's, where it matters, and cheap tests first elsewhere.

The scanner is one alternation, and `re` tries its alternatives in order: a terminal late in
Lark's order (the punctuation, most of a description's tokens) is read only after every one
before it has failed. `re` rejects an alternative that begins with a literal or a character class
by testing one character; any other (a number's pattern, a group of operators) it enters, at ten
times the cost. Two terminals that cannot begin with the same character never match at the same
place (none matches the empty text), so their order cannot change which one is read: only
terminals that can begin alike keep Lark's order. Within that, the cheap ones come first.

Run when the tables are written (rdisc.syntax.tables_writer), not when a description is read.
"""

from __future__ import annotations

import sys
from typing import Any

from rdisc import TYPE_CHECKING

if TYPE_CHECKING or sys.version_info < (3, 11):  # typeshed describes the parser under its old names
    import sre_constants as c
    import sre_parse as _parser
else:  # where Python 3.11 moved them (the old names warn)
    from re import _constants as c
    from re import _parser

_DIGITS = frozenset(range(ord("0"), ord("9") + 1))


def scan_order(terminals: tuple[str, ...], patterns: dict[str, str]) -> tuple[str, ...]:
    """`terminals` (in Lark's order) reordered: each after every terminal before it in Lark's order
    that can begin with one of its characters, and otherwise the cheap ones (`cheap`) first, in
    Lark's order."""
    firsts = {name: first_characters(patterns[name]) for name in terminals}
    position = {name: i for i, name in enumerate(terminals)}
    remaining = list(terminals)
    order: list[str] = []
    while remaining:
        ready = [name for name in remaining
                 if not any(position[other] < position[name] and _meet(firsts[other], firsts[name])
                            for other in remaining)]
        chosen = min(ready, key=lambda name: (not cheap(patterns[name]), position[name]))
        order.append(chosen)
        remaining.remove(chosen)
    return tuple(order)


def cheap(pattern: str) -> bool:
    """Whether `re` rejects the pattern, as an alternative, by testing the character before it:
    it begins with a literal or a class (after `re`'s parser has made `(?:a|b)` one)."""
    items = _parser.parse(pattern).data
    return bool(items) and items[0][0] in (c.LITERAL, c.IN)


def first_characters(pattern: str) -> frozenset[int] | None:
    """The characters a match of `pattern` can begin with; None where that is not known here (a
    negated class, `\\w`, `.`, a flag, a pattern that matches the empty text): it may be any."""
    parsed = _parser.parse(pattern)
    if parsed.getwidth()[0] == 0:
        return None
    return _first(list(parsed.data), parsed.state)


def _first(items: list[Any], state: Any) -> frozenset[int] | None:
    found: set[int] = set()
    for op, av in items:
        if op in (c.AT, c.ASSERT, c.ASSERT_NOT):  # no character of its own: the next part's come first
            continue
        if op is c.LITERAL:
            part: frozenset[int] | None = frozenset({av})
        elif op is c.IN:
            part = _class(av)
        elif op is c.SUBPATTERN and not av[1] and not av[2]:  # a group without flags
            part = _first(list(av[-1]), state)
        elif op is c.BRANCH:
            alternatives = [_first(list(alternative), state) for alternative in av[1]]
            part = None if None in alternatives else frozenset().union(*alternatives)  # type: ignore[arg-type]
        elif op in (c.MAX_REPEAT, c.MIN_REPEAT) or op is getattr(c, "POSSESSIVE_REPEAT", None):
            part = _first(list(av[2]), state)
        else:
            return None
        if part is None:
            return None
        found |= part
        if _parser.SubPattern(state, [(op, av)]).getwidth()[0] > 0:  # it takes a character: the rest comes after
            return frozenset(found)
    return frozenset(found)


def _class(items: list[Any]) -> frozenset[int] | None:
    found: set[int] = set()
    for op, av in items:
        if op is c.LITERAL:
            found.add(av)
        elif op is c.RANGE:
            found.update(range(av[0], av[1] + 1))
        elif op is c.CATEGORY and av is c.CATEGORY_DIGIT:
            found |= _DIGITS
        else:  # a negation, another category: any
            return None
    return frozenset(found)


def _meet(a: frozenset[int] | None, b: frozenset[int] | None) -> bool:
    return a is None or b is None or bool(a & b)
