"""Token trees → text in the printer's canonical layout (rdisc/syntax/printer.py), comments kept.

The layout of each construct is the printer's: 4-space indents; a block (`robot`, `connection`,
`frame`, `interface`, an enum, a table, a reply table, ...) one item a line, `head {}` when empty;
a primitive on one line when it fits in `WIDTH` columns, else one clause a line; post-actions
`{ a = 1 }` inline when there is one, as a block when there are more; the parts inside `optional`,
`either` and `bits` on one line, two spaces apart, as a block when that line is longer than
`WIDTH` (and an `either` longer than that has each `or` start a line); an enum's members and a
table's entries one a line, each with its comma. The one-line rule (`_one_line`): a block, an enum or a table written
on one line, no comment inside, stays on one line when it fits (the writer's choice, which
formatting again keeps). The one wrapping rule (`_fit`) generalises the printer's for a call
statement: a line longer than `WIDTH` has one bracketed list spread one item a line, or, with
none to spread, breaks before the `else`s, `or`s or `and`s of its outermost expression, or
where the writer broke it before other operators (a long arithmetic expression).

Comments decide only where lines break: a construct with a comment inside takes its several-line
form; an own-line comment is written on its own line before its token; a trailing comment ends
its line, two spaces after the code. Blank lines are kept (one at most) where a line starts
anyway: before a declaration, a block's item, a wrapped clause or argument, and their comments.
"""

from __future__ import annotations

from collections.abc import Callable

from rdisc.format.tokens import Child, Leaf, Node
from rdisc.syntax.printer import INDENT, WIDTH

_OPENERS = ("{", "(", "[")
# Rules whose braces hold items one a line; one a line with a comma each; on one line two spaces
# apart (a block when a comment is inside); post-actions.
_BLOCK, _LIST, _INLINE, _ACTIONS = "block", "list", "inline", "actions"
_STYLE = {
    "enum_decl": _LIST, "table_lit": _LIST,
    "f_optional": _INLINE, "part_run": _INLINE, "when_run": _INLINE, "f_bits": _INLINE,
    "f_escape_table": _INLINE,
    "actions": _ACTIONS, "reply_entry": _ACTIONS, "listed_reply": _ACTIONS,
}  # fmt: skip


def spaced(before: Leaf | None, after: Leaf) -> bool:
    """Whether one space separates two tokens on a line: none inside brackets, before `,`, `;`, `:`
    and after a prefix operator, around `.` and `..` (but `over a .. b`), before the `(` of a call
    and the `[` of an index."""
    if before is None:
        return False
    first, then = before.text, after.text
    if then in (",", ";", ")", "]", ":") or first in ("(", "[") or "." in (first, then):
        return False
    if before.rule == "prefixed" and before.kind in ("ADD_OP", "UNARY_OP"):
        return False
    if ".." in (first, then):
        return after.rule == "c_over" or before.rule == "c_over"
    if then == "(":
        return before.kind != "NAME"
    if then == "[":
        return before.kind != "NAME" and first != "]"
    return True


class Writer:
    """Lines made token by token: `begin` starts a line of the layout (made when its first token
    comes, after that token's comments); a comment in mid-line breaks it, the code going on one
    level deeper. A writer without comments measures a layout."""

    def __init__(self, comments: bool = True) -> None:
        self.comments = comments
        self.lines: list[str] = []
        self.text = ""  # the current line, indent included
        self.started = False
        self.level = 0  # of the current line of the layout (a continuation is one deeper)
        self.fresh: int | None = None  # a line of the layout starts here, at this level
        self.pending: str | None = None  # a comment ending the current line
        self.last: Leaf | None = None
        self.space: int | None = None  # the spaces before the next token, where the rule is not wanted
        self.columns: dict[int, int] = {}  # where each token starts on its line, by id (when measuring)
        self.spread: set[int] = set()  # the lists `_fit` chose to lay out one item a line, by id
        self.breaks: dict[int, int] = {}  # the operators `_fit` chose to start a line with: their level

    def begin(self, level: int) -> None:
        self.fresh = level

    def column(self) -> int:
        return len(INDENT) * self.fresh if self.fresh is not None else len(self.text)

    def put(self, leaf: Leaf, own_comments: bool = True) -> None:
        if id(leaf) in self.breaks and self.fresh is None:
            self.begin(self.breaks[id(leaf)])
        leading = leaf.leading if self.comments and own_comments else []
        if self.fresh is not None:
            level, self.fresh = self.fresh, None
            self.level = level
            for comment in leading:
                self._line(level, comment.blank)
                self.text += comment.text
            self._line(level, leaf.blank and self.comments)
            self.text += leaf.text
        elif leading or (self.pending is not None and leaf.text != ","):
            for comment in leading:
                self._line(self.level + 1, False)
                self.text += comment.text
            self._line(self.level + 1, False)
            self.text += leaf.text
        else:
            space = self.space if self.space is not None else int(spaced(self.last, leaf))
            self.text += " " * space + leaf.text
        self.space = None
        if not self.comments:
            self.columns[id(leaf)] = len(self.text) - len(leaf.text)
        if self.comments and leaf.trailing is not None:
            if self.pending is not None:
                self._line(self.level + 1, False)
            self.pending = leaf.trailing
        self.last = leaf

    def comma(self) -> None:
        """A comma the source left out (after a list's last item laid out one a line)."""
        self.text += ","

    def close(self, leaf: Leaf, level: int) -> None:
        """A closing bracket on a line of its own at `level`, comments before it one deeper."""
        if self.comments:
            for comment in leaf.leading:
                self._line(level + 1, comment.blank)
                self.text += comment.text
        self.begin(level)
        self.put(leaf, own_comments=False)

    def finish(self, end: Leaf) -> list[str]:
        if self.comments:
            for comment in end.leading:
                self._line(0, comment.blank)
                self.text += comment.text
        self._line(0, False)
        return self.lines

    def _line(self, level: int, blank: bool) -> None:
        if self.started:
            self.lines.append(self.text.rstrip() + ("" if self.pending is None else "  " + self.pending))
            if blank and (self.last is None or self.last.text not in _OPENERS) and self.lines[-1]:
                self.lines.append("")
        self.pending = None
        self.started = True
        self.text = INDENT * level


def lay_out(decls: list[Node], end: Leaf) -> str:
    out = Writer()
    for decl in decls:
        out.begin(0)
        emit(out, decl)
    lines = out.finish(end)
    while lines and not lines[0]:
        lines.pop(0)
    return "\n".join(lines) + "\n" if lines else ""


def emit(out: Writer, item: Child) -> None:
    if isinstance(item, Leaf):
        out.put(item)
        return
    special = _RULES.get(item.rule)
    if special is not None:
        special(out, item)
        return
    _generic(out, item)


def _generic(out: Writer, item: Node) -> None:
    """A rule's children in the common layout: the text before its braces fitted (`_fit`), the
    braces' items laid out in the rule's style."""
    children = item.children
    braces = [i for i, c in enumerate(children) if isinstance(c, Leaf) and c.text in ("{", "}")]
    first, last = (braces[0], braces[-1]) if braces else (len(children), len(children))
    if out.fresh is not None and out.comments:
        _fit(out, children[:first], item.rule if first == len(children) else "")
    _in_line(out, children[:first])
    if braces:
        _braced(out, children[first], children[first + 1:last], children[last], _STYLE.get(item.rule, _BLOCK))
        _in_line(out, children[last + 1:])


def _in_line(out: Writer, children: list[Child]) -> None:
    """Children one after another; a list between brackets one item a line where `_fit` chose it
    or a comment stands in it."""
    skip = False
    for i, child in enumerate(children):
        if skip:
            skip = False
            continue
        if isinstance(child, Node) and child.rule in _LISTS and 0 < i < len(children) - 1 and out.comments:
            opening, closing = children[i - 1], children[i + 1]
            assert isinstance(opening, Leaf) and isinstance(closing, Leaf)
            if id(child) in out.spread or _inner_comments([opening, *child.leaves(), closing]):
                _spread(out, child, closing)
                skip = True
                continue
        emit(out, child)


def _spread(out: Writer, items: Node, closing: Leaf) -> None:
    level = out.level
    for group, comma in _split(items.children):
        out.begin(level + 1)
        for child in group:
            emit(out, child)
        if comma is None:
            out.comma()
        else:
            out.put(comma)
    out.close(closing, level)


def _fit(out: Writer, children: list[Child], rule: str = "") -> None:
    """The one wrapping rule. A line of the layout (a declaration, a block's item, a wrapped clause,
    a list's item, or the head of a block or of a primitive before its first clause) with no block
    in it, longer than WIDTH, is written with one bracketed list spread one item a line; each item
    is then such a line of its own. The list: of those that hold more of the line than the text
    before and after them together, and whose spreading leaves that text within WIDTH, the first
    of two items or more, else the first (first: whose bracket opens leftmost, so the outermost
    of nested lists). None such: the line breaks before its lowest-precedence operators
    (`_operators`), or stays as it is when it has none of them."""
    leaves = _leaves(children)
    column = out.column()
    if column + sum(len(leaf.text) + 1 for leaf in leaves) <= WIDTH or any(leaf.text == "{" for leaf in leaves):
        return  # fits, even with a space before each token; or holds a block
    scratch = Writer(comments=False)
    scratch.begin(0)
    for child in children:
        emit(scratch, child)
    line = scratch.finish(_END)[-1]
    if column + len(line) <= WIDTH:
        return
    found: list[tuple[int, int, int]] = []  # (where the list opens, its item count, its id)
    stack: list[Child] = [Node("", children)]
    while stack:
        node = stack.pop()
        if isinstance(node, Leaf):
            continue
        for i, child in enumerate(node.children):
            if isinstance(child, Node) and child.rule in _LISTS and 0 < i < len(node.children) - 1:
                opening, closing = node.children[i - 1], node.children[i + 1]
                head = scratch.columns[id(opening)] + 1
                tail = len(line) - scratch.columns[id(closing)]
                inside = len(line) - head - tail
                if column + head <= WIDTH and column + tail <= WIDTH and inside > head + tail:
                    found.append((head, len(_split(child.children)), id(child)))
        stack.extend(node.children)
    found.sort()
    chosen = next((key for _, count, key in found if count >= 2), found[0][2] if found else None)
    if chosen is not None:
        out.spread.add(chosen)
        return
    level = (out.fresh if out.fresh is not None else out.level) + 1
    for leaf in _breaks(Node(rule, children)):
        out.breaks[id(leaf)] = level


def _breaks(line: Node) -> list[Leaf]:
    """Where a line too long for WIDTH with no list to spread breaks: where the writer broke it when
    that was before an operator no rule chooses (as in a long arithmetic expression), else before
    `_operators`' operators and the `else`s, `or`s and `and`s the writer started a line with."""
    written = [leaf for leaf in line.leaves() if leaf.broken and leaf.rule in ("chain", "conditional")
               and leaf.kind in _BINARY]
    if any(leaf.kind not in ("ELSE", "OR", "AND") for leaf in written):
        return written
    return _operators(line) + written


_LOWEST = (("conditional", "ELSE"), ("chain", "OR"), ("chain", "AND"))  # arithmetic stays on its line


def _operators(line: Node) -> list[Leaf]:
    """Where a long expression with no list to spread breaks: before each of its lowest-precedence
    operators (`else` of an `if ... else` chain, then `or`, then `and`), in the outermost
    expression that has any; the continuation lines one level in."""
    nodes: list[Node] = []
    stack: list[Child] = [line]
    while stack:  # pre-order: the outermost first
        item = stack.pop()
        if isinstance(item, Node):
            nodes.append(item)
            stack.extend(reversed(item.children))
    for node in nodes:
        for rule, kind in _LOWEST:
            if node.rule != rule:
                continue
            found = [c for c in node.children if isinstance(c, Leaf) and c.kind == kind]
            if rule == "conditional":  # the chain goes on in the `else` branch
                branch = node.children[-1]
                while isinstance(branch, Node) and branch.rule == "conditional":
                    found += [c for c in branch.children if isinstance(c, Leaf) and c.kind == kind]
                    branch = branch.children[-1]
            if found:
                return found
    return []


_BINARY = ("ELSE", "OR", "AND", "COMP_OP", "IN", "BAR", "CARET", "AMP", "SHIFT_OP", "ADD_OP", "MUL_OP", "POW")
_END = Leaf("", "$END", "", 0, 0)
_LISTS = ("args", "params")


def _inner_comments(leaves: list[Leaf]) -> bool:
    """Whether a comment stands between the first and the last of `leaves`."""
    return any(leaf.leading for leaf in leaves[1:]) or any(leaf.trailing is not None for leaf in leaves[:-1])


def _leaves(items: list[Child]) -> list[Leaf]:
    return [leaf for item in items for leaf in ([item] if isinstance(item, Leaf) else item.leaves())]


def _braced(out: Writer, opening: Child, items: list[Child], closing: Child, style: str) -> None:
    assert isinstance(opening, Leaf) and isinstance(closing, Leaf)
    inner = _inner_comments([opening, *_leaves(items), closing])
    written = style
    if style == _ACTIONS and not inner and sum(isinstance(i, Node) for i in items) == 1:
        style = _INLINE
    elif style == _INLINE and inner:
        style = _LIST if any(isinstance(i, Leaf) and i.text == "," for i in items) else _BLOCK
    elif style == _ACTIONS:
        style = _BLOCK
    if style == _INLINE and out.comments and not _inline_fits(out, opening, items, closing):
        style = _BLOCK  # a run too long for its line: one part a line
    if style == _INLINE:
        _inline(out, opening, items, closing)
        return
    if not items and not inner:
        out.put(opening)
        out.space = 0
        out.put(closing)
        return
    if written in (_BLOCK, _LIST) and not inner and _one_line(out, opening, items, closing, style):
        _flat(out, opening, items, closing, style)
        return
    out.put(opening)
    level = out.level
    if style == _LIST:
        for group, comma in _split(items):
            out.begin(level + 1)
            for child in group:
                emit(out, child)
            if comma is None:
                out.comma()
            else:
                out.put(comma)
    else:
        for item in items:
            out.begin(level + 1)
            emit(out, item)
    out.close(closing, level)


def _inline(out: Writer, opening: Leaf, items: list[Child], closing: Leaf) -> None:
    out.put(opening)
    for i, item in enumerate(items):
        if i and isinstance(item, Node) and isinstance(items[i - 1], Node):
            out.space = 2  # parts of a run, one after another
        emit(out, item)
    out.put(closing)


def _inline_fits(out: Writer, opening: Leaf, items: list[Child], closing: Leaf) -> bool:
    """Whether a run on one line (`{ header "\\xAA"  payload }`) ends within WIDTH columns."""
    scratch = Writer(comments=False)
    scratch.started, scratch.last = True, out.last
    scratch.text = " " * out.column() if out.fresh is not None else out.text
    _inline(scratch, opening, items, closing)
    lines = scratch.finish(_END)
    return len(lines) == 1 and len(lines[0]) <= WIDTH


def _one_line(out: Writer, opening: Leaf, items: list[Child], closing: Leaf, style: str) -> bool:
    """Whether a block or list stays on one line: it was written on one line (no line break
    between its braces) and, on one line, its line fits in WIDTH columns."""
    leaves = [*_leaves(items), closing]
    if any(leaf.broken for leaf in leaves):
        return False
    scratch = Writer(comments=False)
    scratch.started, scratch.last = True, out.last
    scratch.text = " " * out.column() if out.fresh is not None else out.text
    _flat(scratch, opening, items, closing, style)
    lines = scratch.finish(_END)
    return len(lines) == 1 and len(lines[0]) <= WIDTH


def _flat(out: Writer, opening: Leaf, items: list[Child], closing: Leaf, style: str) -> None:
    """A block on one line: `{ a = 1, b = 2 }`, `{ at [0, 0, 1]  axis [0, 1, 0] }` (its items two
    spaces apart, as the parts of a run)."""
    out.put(opening)
    for i, item in enumerate(items):
        if style != _LIST and i and isinstance(item, Node):
            out.space = 2  # a block's items, as the parts of a run
        emit(out, item)
    out.put(closing)


def _split(items: list[Child]) -> list[tuple[list[Child], Leaf | None]]:
    """Items of a comma-separated list, each with the comma after it (None: the last has none)."""
    groups: list[tuple[list[Child], Leaf | None]] = []
    group: list[Child] = []
    for item in items:
        if isinstance(item, Leaf) and item.text == ",":
            groups.append((group, item))
            group = []
        else:
            group.append(item)
    if group:
        groups.append((group, None))
    return groups


def _widest(item: Node, level: int, lay: Callable[[Writer, Node], None]) -> int:
    """The longest line of `item` laid out by `lay` at `level`, its comments left out."""
    out = Writer(comments=False)
    out.begin(level)
    lay(out, item)
    return max(len(line) for line in out.finish(_END))


def _primitive(out: Writer, node: Node) -> None:
    """On one line when it fits (blocks inside spread as usual), else one clause a line."""
    head = next(i for i, c in enumerate(node.children) if isinstance(c, Leaf) and c.text == ")") + 1
    def flat(scratch: Writer, primitive: Node) -> None:
        _clauses(scratch, primitive, head, False)

    wrapped = out.comments and (_inner_comments(node.leaves()) or _widest(node, out.fresh or 0, flat) > WIDTH)
    if wrapped:
        _fit(out, node.children[:head])
    _clauses(out, node, head, wrapped)


def _clauses(out: Writer, node: Node, head: int, wrapped: bool) -> None:
    _in_line(out, node.children[:head])
    level = out.level
    for clause in node.children[head:]:
        if wrapped and not (isinstance(clause, Node) and clause.rule == "actions"):
            out.begin(level + 1)
        emit(out, clause)


def _either(out: Writer, node: Node) -> None:
    """On one line when it fits, else each `or` starting a line at the `either`'s level (a run
    still too long for its line then one part a line)."""
    if out.comments and out.fresh is not None and _widest(node, out.fresh, _generic) > WIDTH:
        level = out.fresh
        for child in node.children:
            if isinstance(child, Leaf) and child.kind == "OR":
                out.begin(level)
            emit(out, child)
        return
    _generic(out, node)


_RULES: dict[str, Callable[[Writer, Node], None]] = {
    "primitive_decl": _primitive,
    "f_either": _either,
}
