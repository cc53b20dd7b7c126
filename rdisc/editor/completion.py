"""Completion: the keywords the grammar accepts where the cursor is (the LALR parser run over
the declaration up to it), the names of the kind that place takes (a connection after `on`, a
frame after `frame`, an adapter after `input NAME:`), in an expression the parameters of the
declaration and what expressions read, an enum's members after `Enum.`, and inside a string the
units, struct codes or checksum algorithms it may hold.

Work is bounded: by the line (its last MAX_LINE characters are read) and by the declaration (one
longer than MAX_CHARS gets names, not keywords); nothing is matched by a pattern that backtracks.
"""

from __future__ import annotations

import re

from lsprotocol import types

from rdisc.editor import positions
from rdisc.editor.documents import Analysis
from rdisc.editor.index import READ, Index, Symbol
from rdisc.syntax import ast
from rdisc.syntax.parse import DECL_KEYWORDS, DECL_START

MAX_CHARS = 20_000  # of the declaration before the cursor that the parser is run over
MAX_LINE = 4096  # of the line before the cursor that is read (a longer line is refused by the parser)
_KEYWORD = re.compile(r"[a-z]+|True|False")
_EXPRESSION = {"INT", "FLOAT", "STRING", "True", "not", "LPAR"}  # accepted where an expression starts
# What follows a name in a struct format (`pack`, `unpack`, a frame's fields): Python's struct
# codes and rdisc's own.
STRUCT_CODES = {
    "<": "little-endian", ">": "big-endian", "!": "network order (big-endian)", "=": "native order, standard sizes",
    "x": "a pad byte", "c": "a char (1 byte)", "b": "s8", "B": "u8", "?": "bool (1 byte)", "h": "s16", "H": "u16",
    "i": "s32", "I": "u32", "l": "s32", "L": "u32", "q": "s64", "Q": "u64", "e": "f16", "f": "f32", "d": "f64",
    "s": "bytes (Ns: N of them)", "Z": "text padded with NULs (NZ)", "*": "bytes: the rest of the message",
    "#": "a count field, and `#(...)` the group it counts", "%": "a width field for the `%` codes of its groups",
}
_STRING_PLACES = (  # the words before a string, and what it holds
    (re.compile(r"\bunit\s*$"), "unit"),
    (re.compile(r"\bchecksum\s*$"), "algorithm"),
    (re.compile(r"(\b(pack|unpack|length|tag|bits)|\bfield\s+[A-Za-z]\w*|\bchecksum\s+\"[^\"]*\")\s*$"), "struct"),
)


def complete(analysis: Analysis, at: types.Position, good: Analysis | None = None) -> types.CompletionList:
    source = analysis.source
    offset = positions.offset(source, at)
    text = source.text
    line_start = max(text.rfind("\n", 0, offset) + 1, offset - MAX_LINE)
    line = text[line_start:offset]
    before = line[: len(line) - _name_before(line, len(line))]
    items: list[types.CompletionItem] = []
    opened = _open_string(line)
    if opened is not None:
        return types.CompletionList(is_incomplete=False, items=_in_string(line[max(0, opened - 100) : opened]))
    index = analysis.index
    if before.endswith("."):  # `Enum.`: its members
        name = before[len(before) - 1 - _name_before(before, len(before) - 1) : -1]
        items = [_item(s) for s in _members(_lookup(analysis, good, ("enum",), name))]
        return types.CompletionList(is_incomplete=False, items=items)
    starts = [m.start() for m in DECL_START.finditer(text, max(0, line_start - MAX_CHARS), offset - len(line) + len(before))]
    start = starts[-1] if starts else None
    head = re.match(r"([a-z]+)\s+([A-Za-z]\w*)?", text[start:offset]) if start is not None else None
    keyword = head.group(1) if head else None
    owner = _lookup(analysis, good, _OWNER_KINDS.get(keyword or "", ()), head.group(2)) if head and head.group(2) else None
    cut = line_start + len(before)
    state = _state(text[start:cut]) if start is not None and cut - start <= MAX_CHARS else None
    if start is None or (state is None and not before.strip()):
        items += [_keyword(k) for k in DECL_KEYWORDS]
    if state is None:
        return types.CompletionList(is_incomplete=False, items=items + _expression_names(index, owner, keyword, good))
    accepted, last = state
    items += [_keyword(k) for k in sorted(accepted) if _KEYWORD.fullmatch(k)]
    if "NAME" in accepted:
        items += _names(analysis, good, index, accepted, last, keyword, owner)
    return types.CompletionList(is_incomplete=False, items=items)


_OWNER_KINDS = {"primitive": ("primitive",), "interface": ("interface",), "frame": ("frame",),
                "input": ("input",), "output": ("output",)}
_AFTER = {"ON": ("connection",), "TRIGGERS": ("output",), "STARTUP": ("interface",), "TERMINATE": ("interface",),
          "KEEPALIVE": ("interface",), "CODE": ("enum",), "TO": ("primitive", "interface"),
          "FROM": ("state variable",)}


def _names(analysis: Analysis, good: Analysis | None, index: Index, accepted: set[str], last: str | None,
           keyword: str | None, owner: Symbol | None) -> list[types.CompletionItem]:
    """The names the place takes, by the keyword before it and the declaration it is in."""
    if last in _AFTER:
        return _globals(index, _AFTER[last])
    if last == "FRAME" and keyword != "frame":
        return _globals(index, ("frame",))
    if last == "COLON" and keyword in ("input", "output") and not accepted & _EXPRESSION:
        return _globals(index, ("adapter",))
    if accepted & _EXPRESSION:
        return _expression_names(index, owner, keyword, good)
    if keyword == "interface" and last in ("LBRACE", "RBRACE", "RPAR", "INT", "NAME", "FLOAT", "MS", "S"):
        return _globals(index, ("primitive", "interface"))
    if keyword == "primitive":  # a post-action's target (or a reply table's key)
        return _globals(index, ("state variable",)) + [_item(s) for s in _members(owner)]
    if keyword == "output" and owner is not None:
        return [_item(s) for s in _members(_adapter_of(index, good, owner))]
    if last == "COLON":  # a parameter's or variable's type
        from rdisc.semantics.model import Type

        return [types.CompletionItem(label=t.value, kind=types.CompletionItemKind.TypeParameter) for t in Type]
    return []


def _expression_names(index: Index, owner: Symbol | None, keyword: str | None,
                      good: Analysis | None = None) -> list[types.CompletionItem]:
    from rdisc.engine.operations import FUNCTIONS

    items = []
    if owner is not None and keyword == "input":  # its call's arguments read the adapter's fields
        adapter = _adapter_of(index, good, owner)
        items += [_item(s) for s in _members(adapter)]
    items += [_item(s) for s in _members(owner)]
    items += _globals(index, (*READ, "enum"))
    items += [types.CompletionItem(label=name, kind=types.CompletionItemKind.Function, detail="built-in function")
              for name in sorted(FUNCTIONS)]
    if keyword == "primitive":
        items.append(types.CompletionItem(label="out", kind=types.CompletionItemKind.Variable,
                                          detail="the reply's values, in post-actions"))
    return items


def _adapter_of(index: Index, good: Analysis | None, owner: Symbol) -> Symbol | None:
    """The adapter an input or output declaration takes."""
    node = owner.declaration
    name = node.adapter.text if isinstance(node, (ast.InputDecl, ast.OutputDecl)) else ""
    found = index.globals["adapter"].get(name)
    return found if found is not None or good is None else good.index.globals["adapter"].get(name)


def _lookup(analysis: Analysis, good: Analysis | None, kinds: tuple[str, ...], name: str) -> Symbol | None:
    """A declaration in this check, or else in the last good one (a declaration being typed may not parse)."""
    found = analysis.index.lookup(kinds, name)
    if found is None and good is not None:
        found = good.index.lookup(kinds, name)
    return found


def _members(owner: Symbol | None) -> list[Symbol]:
    return [] if owner is None else list(owner.members.values())


def _globals(index: Index, kinds: tuple[str, ...]) -> list[types.CompletionItem]:
    return [_item(s) for kind in kinds for s in index.globals[kind].values()]


_ITEM_KINDS = {
    "primitive": types.CompletionItemKind.Function, "interface": types.CompletionItemKind.Method,
    "state variable": types.CompletionItemKind.Variable, "setting": types.CompletionItemKind.Property,
    "sensor": types.CompletionItemKind.Variable,
    "constant": types.CompletionItemKind.Constant, "enum": types.CompletionItemKind.Enum,
    "enum member": types.CompletionItemKind.EnumMember, "adapter": types.CompletionItemKind.Struct,
    "field": types.CompletionItemKind.Field, "parameter": types.CompletionItemKind.Variable,
    "frame": types.CompletionItemKind.Class, "connection": types.CompletionItemKind.Module,
    "output": types.CompletionItemKind.Event, "input": types.CompletionItemKind.Event,
}


def _item(symbol: Symbol) -> types.CompletionItem:
    owner = f" of {symbol.owner.name}" if symbol.owner is not None else ""
    return types.CompletionItem(label=symbol.name, kind=_ITEM_KINDS.get(symbol.kind, types.CompletionItemKind.Text),
                                detail=f"{symbol.kind}{owner}")


def _keyword(word: str) -> types.CompletionItem:
    return types.CompletionItem(label=word, kind=types.CompletionItemKind.Keyword)


def _name_before(text: str, end: int) -> int:
    """The length of the name (letters, digits, `_`) that ends at `end` of `text`: read backwards,
    in time linear in it."""
    start = end
    while start > 0 and (text[start - 1].isascii() and (text[start - 1].isalnum() or text[start - 1] == "_")):
        start -= 1
    return end - start


def _open_string(line: str) -> int | None:
    """Where the string the line ends inside opens, if it does."""
    opened = None
    escaped = False
    for i, char in enumerate(line):
        if opened is not None and char == "\\" and not escaped:
            escaped = True
            continue
        if char == '"' and not escaped:
            opened = i if opened is None else None
        elif char == "#" and opened is None:
            return None  # a comment
        escaped = False
    return opened


def _in_string(before: str) -> list[types.CompletionItem]:
    what = next((name for pattern, name in _STRING_PLACES if pattern.search(before)), None)
    if what == "unit":
        from rdisc.semantics.units import UNITS

        return [types.CompletionItem(label=unit, kind=types.CompletionItemKind.Unit) for unit in UNITS]
    if what == "algorithm":
        from rdisc.semantics.checksums import ALGORITHMS

        return [types.CompletionItem(label=name, kind=types.CompletionItemKind.Value, detail="checksum algorithm")
                for name in ALGORITHMS]
    if what == "struct":
        return [types.CompletionItem(label=code, kind=types.CompletionItemKind.Value, detail=meaning)
                for code, meaning in STRUCT_CODES.items()]
    return []


def warm() -> None:
    """Make the grammar's parser (Lark's, about a tenth of a second) before the first completion needs it."""
    from rdisc.syntax.parse import parser

    parser()


def _state(chunk: str) -> tuple[set[str], str | None] | None:
    """The terminals the grammar accepts after `chunk` (a declaration's start), by their keyword
    for keywords, and the last terminal read; None when the chunk has a syntax error."""
    from lark.exceptions import LarkError

    from rdisc.syntax.parse import parser

    made = parser()
    interactive = made.parse_interactive(chunk, start="start")
    last = None
    try:
        for token in interactive.iter_parse():
            last = token.type
        accepted = interactive.accepts()
    except LarkError:
        return None
    words = set()
    for name in accepted:
        try:
            pattern = made.get_terminal(name).pattern
        except KeyError:
            words.add(name)
            continue
        words.add(pattern.value if type(pattern).__name__ == "PatternStr" and _KEYWORD.fullmatch(pattern.value)
                  else name)
    return words, last
