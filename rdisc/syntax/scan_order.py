"""The order in which the fast loop's scanner tries the whole grammar's terminals
(rdisc.syntax.reduce's pattern): Lark's, where it matters, and cheap tests first elsewhere.

The scanner is one alternation, and `re` tries its alternatives in order: a terminal late in
Lark's order (the punctuation, most of a description's tokens) is read only after every one
before it has failed. `re` rejects an alternative that begins with a literal or a character class
by testing one character; any other (a number's pattern, a group of operators) it enters, at ten
times the cost. Two terminals that cannot begin with the same character never match at the same
place (none matches the empty text), so their order cannot change which one is read: only
terminals that can begin alike keep Lark's order. What a terminal can begin with is the regex
walk's reading (rdisc.regex_shape.first_characters). Within that, the cheap ones come first.

Run when the tables are written (rdisc.syntax.tables_writer), not when a description is read.
"""

from __future__ import annotations

from rdisc import regex_shape


def scan_order(terminals: tuple[str, ...], patterns: dict[str, str]) -> tuple[str, ...]:
    """`terminals` (in Lark's order) reordered: each after every terminal before it in Lark's order
    that can begin with one of its characters, and otherwise those `re` tests by one character
    first (`regex_shape.tested_by_one_character`), in Lark's order."""
    firsts = {name: regex_shape.first_characters(patterns[name]) for name in terminals}
    cheap = {name: regex_shape.tested_by_one_character(patterns[name]) for name in terminals}
    position = {name: i for i, name in enumerate(terminals)}
    remaining = list(terminals)
    order: list[str] = []
    while remaining:
        ready = [name for name in remaining
                 if not any(position[other] < position[name] and _meet(firsts[other], firsts[name])
                            for other in remaining)]
        chosen = min(ready, key=lambda name: (not cheap[name], position[name]))
        order.append(chosen)
        remaining.remove(chosen)
    return tuple(order)


def _meet(a: frozenset[int], b: frozenset[int]) -> bool:
    """Whether two terminals can begin alike: an empty reading (characters past 255 only) is
    taken as any."""
    return not a or not b or bool(a & b)
