"""Text → AST: the one entry point of the syntax stage is `parse`.

The file is cut into top-level declarations at lines that begin with a
declaration keyword in column 0, and each piece is parsed on its own. A syntax
error therefore costs only the declaration it is in: the rest of the file is
still parsed and checked. A declaration that parses cleanly is built into AST nodes as
Lark's tables are run (rdisc.syntax.reduce); any other is parsed by Lark into a tree
(iteratively), whose depth is bounded before the recursive transformation into AST nodes.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from functools import lru_cache

from rdisc import TYPE_CHECKING, patterns
from rdisc.diagnostics import Diagnostics
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.build import MAX_EXPR_DEPTH, Builder, TooDeep, build_expression, build_tree

if TYPE_CHECKING:
    from types import ModuleType

    import lark

MAX_FILE_CHARS = 8 * 1024 * 1024
MAX_TREE_DEPTH = 120  # of Lark's tree; expressions are bounded by MAX_EXPR_DEPTH
MAX_SYNTAX_ERRORS = 100
MAX_LINE_CHARS = 65536  # of one line, and so of a string literal (strings do not span lines)
MAX_DECL_TOKENS = 20000  # of one declaration: more is not a description a person wrote
# The tokens of RDIS, roughly (a string is cut at an escaped quote): enough to count them in linear time.
_TOKEN = re.compile(r'r?"[^"\n]*"?|[A-Za-z_][A-Za-z0-9_]*|\d[\w.]*|#[^\n]*|\S')
_TOKEN_BLOCK = 1 << 14  # characters of text whose tokens token_count finds at once (then to the line's end)
# Patterns only a long, damaged or misread declaration needs, compiled when first used (rdisc.patterns).
_LONG_LINE = rf"[^\n]{{{MAX_LINE_CHARS + 1},}}"

DECL_KEYWORDS = (
    "import",
    "robot",
    "state",
    "sensor",
    "setting",
    "connection",
    "primitive",
    "interface",
    "adapter",
    "input",
    "output",
    "const",
    "enum",
    "frame",
    "link",
    "joint",
    "transmission",
    "actuator",
)
# A declaration keyword at the start of a line: DECL_START, compiled when first asked for (`__getattr__`:
# the editor's completion reads it, a check does not).
_DECL_START = r"^(?:{})\b".format("|".join(DECL_KEYWORDS))
if TYPE_CHECKING:
    DECL_START: re.Pattern[str]
# The same starts after the first line, found from each line break (a search for a pattern that begins
# with `^` tries every character of the text; one that begins with `\n` skips to the next).
_LATER_DECL_START = re.compile(r"\n(?:{})\b".format("|".join(DECL_KEYWORDS)))


def __getattr__(name: str) -> re.Pattern[str]:
    if name == "DECL_START":
        return patterns.pattern(_DECL_START, re.MULTILINE)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
_DOC_RUN = re.compile(r"(?:^[ \t]*///[^\n]*\n?)+", re.MULTILINE)
_DOC_LINE = re.compile(r"^[ \t]*/// ?([^\n]*)$", re.MULTILINE)
_BLANK_OR_COMMENT = re.compile(r"(?:\s+|#[^\n]*)*")
_DECL_NAME = r"({})\s+([A-Za-z][A-Za-z0-9_]*)".format("|".join(DECL_KEYWORDS))


@lru_cache(maxsize=1)
def parser() -> lark.Lark:
    """The grammar's parser, its states' lexers sharing one pattern (rdisc/syntax/lexing.py)."""
    from rdisc.syntax.lexing import share_scanners

    made = lark_parser()
    share_scanners(made)
    return made


def lark_parser() -> lark.Lark:
    """The grammar's parser as Lark makes it; Lark is imported only now: start-up time matters
    for `rdisc check`."""
    import lark

    from rdisc.resources import grammar_path

    return lark.Lark.open(
        str(grammar_path()),
        parser="lalr",
        lexer="contextual",
        start=["start", "expr_start"],
        propagate_positions=True,
        maybe_placeholders=True,
        cache=True,
    )


def parse(path: str, text: str, diagnostics: Diagnostics) -> ast.Module:
    """Parse one file; every problem found goes to `diagnostics`."""
    if len(text) > MAX_FILE_CHARS:
        diagnostics.report(
            "E005",
            Span(path, 0, 0),
            f"file is too large ({len(text)} characters; the limit is {MAX_FILE_CHARS})",
        )
        return ast.Module(path, (), refused=True)
    builder = Builder(path, _doc_comments(text), diagnostics)
    decls: list[ast.Decl] = []
    damaged: list[ast.Damaged] = []
    errors = 0
    bounds = declaration_bounds(text)
    for i, (start, end) in enumerate(bounds):
        if parse_declaration(text, start, end, builder, decls, damaged, errors < MAX_SYNTAX_ERRORS,
                             i == len(bounds) - 1):
            errors += 1
    return ast.Module(path, tuple(decls), tuple(damaged))


def pieces(text: str) -> tuple[list[tuple[int, int]], dict[int, str]]:
    """Where `parse` cuts a file into top-level declarations, and its doc comments by the offset
    of what each documents."""
    return declaration_bounds(text), _doc_comments(text)


# rdisc.syntax.reduce, the fast loop, once imported (when first used: what only cuts a file into its
# declarations, the formatter and the editor's completion, does not load the parser's tables).
_FAST_LOOP: list[ModuleType] = []


def parse_declaration(text: str, start: int, end: int, builder: Builder, decls: list[ast.Decl],
                      damaged: list[ast.Damaged], report: bool, last: bool) -> bool:
    """Parse the top-level declaration `text[start:end]` (one piece `parse` cut the file into)
    with the file's builder, adding what it gives to `decls` and `damaged`; whether it had a
    syntax error (reported if `report`). What it gives depends on the piece's text, where it
    starts and the doc comment before it only (rdisc.syntax.incremental reuses it)."""
    if not _FAST_LOOP:  # imported once, not at each declaration (a `from ... import` each time was 1% of a check)
        from rdisc.syntax import reduce

        _FAST_LOOP.append(reduce)
    loop = _FAST_LOOP[0]
    path, diagnostics = builder.path, builder.diagnostics
    chunk = text[start:end]
    too_long = _too_long(path, chunk, start)
    if too_long is not None:  # refused before the parser, whose time and memory would grow with it
        diagnostics.report("E005", *too_long)
        damaged.extend(_damaged(path, chunk, start))
        return False
    try:  # built as it is parsed, where that is clean; else Lark's tree, built after (rdisc.syntax.reduce)
        decls.extend(loop.parse_built(chunk, builder, start, MAX_TREE_DEPTH))
        return False
    except loop.Retry:
        pass
    import lark  # only for a declaration the loop leaves: start-up time matters for `rdisc check`

    try:
        tree = parser().parse(chunk, start="start", on_error=keyword_as_name)
    except lark.exceptions.UnexpectedInput as err:
        damaged.extend(_damaged(path, chunk, start))
        if report:
            _report_syntax_error(err, path, text, start, end, last, diagnostics)
        return True
    depth, deepest = _depth(tree)
    too_deep = None
    if depth > MAX_TREE_DEPTH:
        meta = deepest.meta
        too_deep = Span(path, start + meta.start_pos, start + meta.end_pos)
    else:
        try:
            decls.extend(build_tree(builder, tree, start))
        except lark.exceptions.VisitError as err:
            if not isinstance(err.orig_exc, TooDeep):
                raise
            too_deep = err.orig_exc.span
    if too_deep is not None:
        diagnostics.report(
            "E005", too_deep, f"expression is nested too deeply (the limit is {MAX_EXPR_DEPTH} levels)"
        )
        damaged.extend(_damaged(path, chunk, start))
    return False


_NAME = r"[A-Za-z][A-Za-z0-9_]*"


def keyword_as_name(err: lark.exceptions.UnexpectedInput) -> bool:
    """Keywords are contextual: a clause keyword (`baud`, `length`, `mask`, ...) where the
    parser wants a name is that name. LALR merges the states after an expression, so the
    lexer offers every keyword that may follow an expression anywhere; this undoes that."""
    import lark

    token = getattr(err, "token", None)
    if (not isinstance(err, lark.exceptions.UnexpectedToken) or token is None or token.type == "NAME"
            or "NAME" not in err.accepts or not patterns.pattern(_NAME).fullmatch(str(token))):
        return False
    err.interactive_parser.feed_token(lark.Token.new_borrow_pos("NAME", str(token), token))
    return True


def _damaged(path: str, chunk: str, start: int) -> list[ast.Damaged]:
    m = patterns.pattern(_DECL_NAME).match(chunk)
    if not m:
        return []
    return [ast.Damaged(m.group(1), ast.Ident(m.group(2), Span(path, start + m.start(2), start + m.end(2))))]


def parse_expression(path: str, text: str, base_offset: int, diagnostics: Diagnostics) -> ast.Expr | None:
    """Parse one expression embedded in another format (a JSON string); spans are
    offsets into `path` counted from `base_offset`. None after a reported error."""
    import lark

    try:
        tree = parser().parse(text, start="expr_start", on_error=keyword_as_name)
    except lark.exceptions.UnexpectedInput as err:
        from rdisc.syntax.errors import describe_unexpected  # for a syntax error only: start-up time

        code, offset, length, message, label, help = describe_unexpected(err, text, True)
        at = base_offset + offset
        message = message.replace("the end of the file", "the end of the expression")
        diagnostics.report(code, Span(path, at, at + length), message, label=label, help=help)
        return None
    depth, deepest = _depth(tree)
    if depth > MAX_TREE_DEPTH:
        meta = deepest.meta
        too_deep = Span(path, base_offset + meta.start_pos, base_offset + meta.end_pos)
    else:
        try:  # built from the `expr_start` rule: one expression
            return build_expression(Builder(path, {}, diagnostics), tree, base_offset)
        except lark.exceptions.VisitError as err:
            if not isinstance(err.orig_exc, TooDeep):
                raise
            too_deep = err.orig_exc.span
    diagnostics.report("E005", too_deep, f"expression is nested too deeply (the limit is {MAX_EXPR_DEPTH} levels)")
    return None


def token_count(text: str, most: int) -> int:
    """The tokens of `text`, counted up to `most + 1` (so in time bounded by `most`, and by the
    longest line): found a block of lines at a time, as no token spans a line."""
    count, pos, length = 0, 0, len(text)
    find = _TOKEN.findall
    while pos < length and count <= most:
        cut = text.find("\n", pos + _TOKEN_BLOCK)
        cut = length if cut < 0 else cut + 1
        count += len(find(text, pos, cut))
        pos = cut
    return min(count, most + 1)


def _too_long(path: str, chunk: str, start: int) -> tuple[Span, str] | None:
    """Where and why a declaration is too long to parse: a line over the limit (a string
    literal is on one line), or more tokens than a declaration may have."""
    if len(chunk) <= min(MAX_LINE_CHARS, MAX_DECL_TOKENS):  # a token and a line are a character or more
        return None
    long_line = patterns.pattern(_LONG_LINE).search(chunk)
    if long_line is not None:
        return (Span(path, start + long_line.start(), start + long_line.end()),
                f"line of {len(long_line.group())} characters; the limit is {MAX_LINE_CHARS}")
    if token_count(chunk, MAX_DECL_TOKENS) > MAX_DECL_TOKENS:
        return (Span(path, start, start + len(chunk)),
                f"declaration has more than {MAX_DECL_TOKENS} tokens; split it, or make it simpler")
    return None


def declaration_bounds(text: str) -> list[tuple[int, int]]:
    """Where `parse` cuts `text` into top-level declarations: at each declaration keyword that
    starts a line (the formatter and the editor cut it the same way)."""
    starts = [m.start() + 1 for m in _LATER_DECL_START.finditer(text)]
    starts.insert(0, 0)  # a declaration at 0 starts the first piece, as does anything else there
    ends = starts[1:] + [len(text)]
    return list(zip(starts, ends))


def _doc_comments(text: str) -> dict[int, str]:
    """Doc comment text keyed by the offset of the code that follows it."""
    docs: dict[int, str] = {}
    if "///" not in text:
        return docs
    for run in _doc_runs(text):
        lines = _DOC_LINE.findall(run.group())
        after = _BLANK_OR_COMMENT.match(text, run.end())
        target = after.end() if after else run.end()
        docs[target] = "\n".join(line.rstrip() for line in lines).strip()
    return docs


def _doc_runs(text: str) -> Iterator[re.Match[str]]:
    """What `_DOC_RUN.finditer(text)` finds, found from each `///` (a search for a pattern that
    begins with `^` tries every character of the text)."""
    pos = 0
    while (at := text.find("///", pos)) >= 0:
        line = text.rfind("\n", 0, at) + 1
        if text[line:at].strip(" \t"):  # not at the start of its line
            pos = at + 3
            continue
        run = _DOC_RUN.match(text, line)
        assert run is not None  # a line of blanks, then `///`
        yield run
        pos = run.end()


def _depth(tree: lark.Tree[lark.Token]) -> tuple[int, lark.Tree[lark.Token]]:
    """Maximum depth of a Lark tree, computed without recursion."""
    import lark

    best, deepest = 0, tree
    stack = [(tree, 1)]
    while stack:
        node, depth = stack.pop()
        if depth > best:
            best, deepest = depth, node
        for child in node.children:
            if isinstance(child, lark.Tree):
                stack.append((child, depth + 1))
    return best, deepest


def _report_syntax_error(err: lark.exceptions.UnexpectedInput, path: str, text: str, start: int, end: int,
                         last: bool, diagnostics: Diagnostics) -> None:
    from rdisc.syntax.errors import describe_unexpected  # for a syntax error only: start-up time

    code, offset, length, message, label, help = describe_unexpected(err, text[start:end], last)
    at = start + offset
    diagnostics.report(code, Span(path, at, min(at + length, len(text))), message, label=label, help=help)
