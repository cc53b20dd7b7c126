"""Writes rdisc/syntax/tables.py: the grammar's LALR tables and lexers as plain literals.

Lark builds the parser from grammar/rdis.lark (its cache makes that about 120 ms of a cold
`rdisc check`, importing Lark included). Like Lark's standalone tool, this writes what the
parser runs on ahead of time, read from the parser Lark makes: each state's actions, each rule's
shaping (from the wrappers Lark's tree builder puts around it), the terminals' patterns, and each
state lexer's terminals in Lark's order with the keywords its names may be. rdisc.syntax.reduce
runs them; Lark still parses a declaration the fast loop leaves (a syntax error), and stays the
grammar's one source: `python -m rdisc.syntax.tables_writer --check` (and a test) hold the
written module equal to what Lark makes of the grammar now.

Lark numbers its LALR states in the order it meets them in sets of objects hashed by identity, so
each interpreter numbers the same states differently (and Lark's cache keeps whichever numbering a
machine made first). The states are written in an order of their own: breadth first from the start
states, each state's moves taken by the names of their symbols. The same grammar gives the same
text on every machine.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

import lark
from lark.parse_tree_builder import (
    ChildFilterLALR,
    ChildFilterLALR_NoPlaceholders,
    ExpandSingleChild,
    PropagatePositions,
)
from lark.parsers.lalr_analysis import Shift

from rdisc.syntax.lexing import _keywords
from rdisc.syntax.parse import lark_parser
from rdisc.syntax.scan_order import scan_order

TARGET = Path(__file__).resolve().parent / "tables.py"

HEADER = '''\
"""The grammar's LALR tables and lexers (grammar/rdis.lark, as Lark {version} makes them), for
rdisc.syntax.reduce: a cold `rdisc check` neither imports Lark nor loads the grammar.

Written by `python -m rdisc.syntax.tables_writer`: do not edit; rerun it after changing the
grammar (a test holds this file equal to what it writes).
"""

# fmt: off
'''


def _rule(rule: Any, callback: Any) -> tuple[Any, ...]:
    """How `rule`'s children become its value, read from the chain of wrappers Lark made for it
    (ParseTreeBuilder): (origin, size, kept children or None for all, placeholders after,
    single, name, spliced, unit); rdisc.syntax.reduce.Rule says what each means."""
    if not isinstance(callback, PropagatePositions) or callback.node_filter is not None:
        raise TypeError(f"unexpected wrapper of {rule}")
    inner = callback.node_builder
    keep: tuple[tuple[int, bool, int], ...] | None = None
    nones_after = 0
    if isinstance(inner, ChildFilterLALR):
        keep, nones_after = tuple(tuple(kept) for kept in inner.to_include), inner.append_none
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
    # Lark's names are Tokens when it builds the grammar afresh, str when it loads its cache: written as str
    origin, name = str(rule.origin.name), str(name)
    return (origin, size, keep, nones_after, single, name, name.startswith("_"), unit)


def _lexer(lexer: Any) -> tuple[tuple[str, ...], dict[str, str]]:
    """A state lexer's terminals in the order Lark tries them, and its keywords (a name's text → its type)."""
    made = _keywords(lexer)
    if made is None or set(made[1]) - {"NAME"} or lexer.ignore_types & set(made[1]):
        raise TypeError("a lexer with callbacks other than keywords read as names")
    terminals, callbacks = made
    return tuple(t.name for t in terminals), dict(callbacks["NAME"].types) if callbacks else {}


def _canonical_order(table: Any) -> list[int]:
    """Lark's states in the order they are written: breadth first from the start states (by name),
    each state's shifts and gotos followed by the names of their symbols."""
    order = [state for _, state in sorted(table.start_states.items())]
    seen = set(order)
    for state in order:  # grows as it goes
        for _, (action, arg) in sorted(table.states[state].items(), key=lambda item: str(item[0])):
            if action is Shift and arg not in seen:
                seen.add(arg)
                order.append(arg)
    if len(order) != len(table.states):
        raise TypeError("parser states that no start state reaches")
    return order


def write() -> str:
    """The text of rdisc/syntax/tables.py for the grammar as it is now."""
    made = lark_parser()
    frontend = made.parser
    lalr = frontend.parser.parser
    table = lalr.parse_table
    contextual = frontend.lexer
    root = contextual.root_lexer
    if root.g_regex_flags or root.user_callbacks or any(t.pattern.flags for t in root.terminals):
        raise TypeError("a terminal with flags")
    ignored = sorted(root.ignore_types)
    if any(sorted(lexer.ignore_types) != ignored for lexer in contextual.lexers.values()):
        raise TypeError("states that skip different terminals")
    if sorted(table.states) != list(range(len(table.states))):
        raise TypeError("parser states are not numbered 0 to n - 1")
    order = _canonical_order(table)
    number = {state: i for i, state in enumerate(order)}

    rules = {rule: i for i, rule in enumerate(lalr.callbacks)}
    lexers: dict[tuple[tuple[str, ...], tuple[tuple[str, str], ...]], int] = {}
    state_lexers = []
    for state in order:
        terminals, keywords = _lexer(contextual.lexers[state])
        if not set(ignored) <= set(terminals):  # the loop skips what the root's lexer skips, in every state
            raise TypeError(f"state {state} does not skip {', '.join(ignored)}")
        key = (terminals, tuple(sorted(keywords.items())))
        state_lexers.append(lexers.setdefault(key, len(lexers)))

    out = [HEADER.format(version=lark.__version__)]
    out.append("# Each terminal's pattern, as Lark compiles it.\nTERMINALS = {\n")
    out += [f"    {t.name!r}: {t.pattern.to_regexp()!r},\n" for t in sorted(root.terminals, key=lambda t: t.name)]
    out.append("}\n\n")
    out.append(f"# Terminals read and skipped.\nIGNORED = frozenset({ignored!r})\n\n")
    out.append("# The whole grammar's lexer: its terminals in the order it tries them.\n")
    out.append(f"ROOT = {_lexer(root)[0]!r}\n\n")
    read = tuple(name for name in _lexer(root)[0] if name not in ignored)
    patterns = {t.name: t.pattern.to_regexp() for t in root.terminals}
    out.append("# The order in which the fast loop's scanner tries the terminals it reads: ROOT's where two\n"
               "# can begin alike, and otherwise those re rejects by one character first (scan_order).\n")
    out.append(f"SCAN = {scan_order(read, patterns)!r}\n\n")
    out.append("# The lexers of the parser states: the terminals each tries, in order, and the keywords a\n"
               "# NAME it reads may be (the text → the keyword's terminal).\n"
               "LEXERS: tuple[tuple[tuple[str, ...], dict[str, str]], ...] = (\n")
    for terminals, pairs in lexers:
        out.append(f"    ({terminals!r},\n     {dict(pairs)!r}),\n")
    out.append(")\n\n")
    out.append(f"# Each parser state's lexer (an index into LEXERS).\nSTATE_LEXERS = {tuple(state_lexers)!r}\n\n")
    out.append("# Each rule: (origin, size, kept children or None for all, placeholders after, single, name,\n"
               "# spliced, unit); rdisc.syntax.reduce.Rule says what each means.\nRULES = (\n")
    out += [f"    {_rule(rule, callback)!r},\n" for rule, callback in lalr.callbacks.items()]
    out.append(")\n\n")
    out.append("# Each parser state's actions: on a terminal or a rule's origin, shift to state n (n >= 0),\n"
               "# or reduce by rule ~n (n < 0).\nACTIONS: tuple[dict[str, int], ...] = (\n")
    for state in order:
        row = {str(kind): (number[arg] if action is Shift else ~rules[arg])
               for kind, (action, arg) in sorted(table.states[state].items(), key=lambda item: str(item[0]))}
        out.append(f"    {row!r},\n")
    out.append(")\n\n")
    out.append(f"START = { {start: number[state] for start, state in sorted(table.start_states.items())}!r}\n")
    out.append(f"END = { {start: number[state] for start, state in sorted(table.end_states.items())}!r}\n")
    return "".join(out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m rdisc.syntax.tables_writer",
                                     description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="only say whether the written module is stale (exit 1)")
    args = parser.parse_args(argv)
    text = write()
    if TARGET.is_file() and TARGET.read_text(encoding="utf-8") == text:
        return 0
    if args.check:
        print(f"{TARGET} is stale: run python -m rdisc.syntax.tables_writer", file=sys.stderr)
        return 1
    TARGET.write_text(text, encoding="utf-8", newline="\n")
    print(f"wrote {TARGET}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
