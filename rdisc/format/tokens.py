"""Source text → a tree of the tokens as written, each comment attached to a token.

The grammar's parser is run with every token kept (`keep_all_tokens`), over the same
declaration chunks `rdisc.syntax.parse` cuts, so the tree is the one `rdisc check` reads. The text
between two tokens holds only white space and comments (the lexer's ignored stream); each comment
found there is attached to a neighbouring token:

- a comment on the line of the token before it *trails* that token;
- any other comment *leads* the token after it (at the end of the file, the `END` token);
- a token or comment remembers whether a blank line came before it.

A list's trailing comma is dropped here (layout writes one back where a list is laid out one item a
line). A comma is written right after the item before it, so the comments around a comma are moved
to where that puts them: a comment trailing the item trails the comma; a comma's own-line comments
lead the next item.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import lark

_COMMENT = re.compile(r"///[^\n]*|#[^\n]*")
# Rules whose last comma may be a trailing one: (the rule, whether the list ends the rule's children).
_LIST_ENDS_RULE = {"args": True, "params": True, "table_lit": False, "enum_decl": False, "f_escape_table": False}


@dataclass(slots=True)
class Comment:
    text: str
    blank: bool  # a blank line comes before it


@dataclass(slots=True)
class Leaf:
    """One token as written: its text, terminal name and the rule it is a child of."""

    text: str
    kind: str
    rule: str
    start: int
    end: int
    leading: list[Comment] = field(default_factory=list)
    trailing: str | None = None
    blank: bool = False  # a blank line comes before it (after its leading comments)
    broken: bool = False  # a line break comes before it (a block's layout keeps a one-line block)
    dropped: bool = False  # a trailing comma: not laid out


@dataclass(slots=True)
class Node:
    rule: str
    children: list[Child]
    known: list[Leaf] | None = None  # the leaves, once asked

    def leaves(self) -> list[Leaf]:
        if self.known is not None:
            return self.known
        found: list[Leaf] = []
        stack: list[Child] = [self]
        while stack:
            item = stack.pop()
            if isinstance(item, Leaf):
                found.append(item)
            else:
                stack.extend(reversed(item.children))
        self.known = found
        return found


Child = Node | Leaf


@dataclass(slots=True)
class Tokens:
    """A file's declarations as token trees, and the end-of-file token leading the last comments."""

    decls: list[Node]
    end: Leaf


@lru_cache(maxsize=1)
def _parser() -> lark.Lark:
    """The grammar's parser keeping every token (keywords and punctuation too), its states' lexers
    sharing one pattern as `rdisc check`'s do."""
    import lark

    from rdisc.resources import grammar_path
    from rdisc.syntax.lexing import share_scanners

    made = lark.Lark.open(str(grammar_path()), parser="lalr", lexer="contextual", start="start",
                          keep_all_tokens=True, maybe_placeholders=False, cache=True)
    share_scanners(made)
    return made


def read_tokens(text: str, chunks: list[tuple[int, int]]) -> Tokens:
    """The token trees of `text`, which parses without errors in the chunks `chunks`."""
    from rdisc.syntax.parse import keyword_as_name

    decls: list[Node] = []
    leaves: list[Leaf] = []
    for start, stop in chunks:
        tree = _parser().parse(text[start:stop], on_error=keyword_as_name)
        for child in tree.children:
            made = _convert(child, "start", start, leaves)
            assert isinstance(made, Node), "a declaration is a rule"
            decls.append(made)
    end = Leaf("", "$END", "start", len(text), len(text))
    _attach(text, [*leaves, end])
    _move_around_commas(leaves + [end])
    return Tokens(decls, end)


def _convert(item: lark.Tree[lark.Token] | lark.Token, rule: str, base: int, leaves: list[Leaf]) -> Child:
    import lark

    if isinstance(item, lark.Token):
        leaf = Leaf(str(item), item.type, rule, base + (item.start_pos or 0), base + (item.end_pos or 0))
        leaves.append(leaf)
        return leaf
    name = str(item.data)
    children = [_convert(child, name, base, leaves) for child in item.children]
    ends_rule = _LIST_ENDS_RULE.get(name)
    if ends_rule is not None:
        at = len(children) - (1 if ends_rule else 2)
        last = children[at] if 0 <= at < len(children) else None
        if isinstance(last, Leaf) and last.text == ",":
            last.dropped = True
            del children[at]
    return Node(name, children)


def _attach(text: str, leaves: list[Leaf]) -> None:
    """Attach each comment of the gaps between tokens to a token (see the module's docstring)."""
    previous: Leaf | None = None
    gap_start = 0
    for leaf in leaves:
        gap = text[gap_start:leaf.start]
        at = 0
        if "#" in gap or "///" in gap:
            for m in _COMMENT.finditer(gap):
                before = gap[at:m.start()]
                comment = m.group().rstrip()
                if previous is not None and at == 0 and "\n" not in before:
                    previous.trailing = comment
                else:
                    leaf.leading.append(Comment(comment, before.count("\n") >= 2))
                at = m.end()
        leaf.blank = gap[at:].count("\n") >= 2
        leaf.broken = "\n" in gap
        previous, gap_start = leaf, leaf.end


def _move_around_commas(leaves: list[Leaf]) -> None:
    for i, comma in enumerate(leaves):
        if comma.text != "," or comma.kind == "$END":
            continue
        before, after = leaves[i - 1], leaves[i + 1]
        moved, comma.leading = comma.leading, []
        if comma.dropped:
            if comma.trailing is not None:
                if before.trailing is None and not moved:
                    before.trailing = comma.trailing
                else:
                    moved.append(Comment(comma.trailing, False))
                comma.trailing = None
        elif before.trailing is not None:
            if comma.trailing is not None:
                moved.append(Comment(comma.trailing, False))
            comma.trailing, before.trailing = before.trailing, None
        after.leading[:0] = moved
