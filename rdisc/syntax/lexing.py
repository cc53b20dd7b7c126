"""One compiled pattern for every parser state's lexer, where Lark compiles one per state.

Lark's contextual lexer gives each LALR state a lexer of the terminals that state accepts,
and compiles its alternation of their patterns (and of their keywords) when the state is
first met: 57 compilations, about 9 ms of a cold check of the Create. The whole grammar's
lexer (Lark's root lexer) tries the same terminals in the same order, so wherever the
terminal it finds is one the state accepts, the state's own lexer would have found that
terminal and that text too: the first alternative to match is the first of any subset that
contains it. Only where it finds one the state does not accept is the state's own pattern
compiled and asked. A keyword the root lexer reads as a name (`primitive`) is turned into
the keyword, or not, by the state's own table, as Lark's `UnlessCallback` does.
"""

from __future__ import annotations

from typing import Any

import lark
import lark.lexer

_NAMES_ITSELF: dict[tuple[str, str], bool] = {}  # (a pattern, a keyword): the pattern matches all of it


class _Keywords:
    """Lark's UnlessCallback for keywords without flags: a dict in place of a pattern."""

    def __init__(self, types: dict[str, str]) -> None:
        self.types = types

    def __call__(self, token: lark.Token) -> lark.Token:
        found = self.types.get(token.value)
        if found is not None:
            token.type = found
        return token


class SharedScanner:
    """A state's scanner: the root lexer's match when the state accepts its terminal."""

    def __init__(self, root: Any, lexer: Any, terminals: list[Any]) -> None:
        self.root, self.lexer, self.terminals = root, lexer, terminals
        self.allowed_types = {t.name for t in terminals}
        self.own: Any = None

    def match(self, text: Any, pos: int) -> tuple[str, str] | None:
        found: tuple[str, str] | None = self.root.match(text, pos)
        if found is None or found[1] in self.allowed_types:
            return found  # nothing matches here, or what the state's own pattern finds first
        if self.own is None:
            self.own = lark.lexer.Scanner(self.terminals, self.lexer.g_regex_flags,
                                          self.lexer.re, self.lexer.use_bytes)
        own: tuple[str, str] | None = self.own.match(text, pos)
        return own


def _keywords(lexer: Any) -> tuple[list[Any], dict[str, Any]] | None:
    """The terminals left in a state lexer's pattern and its callbacks, as Lark's
    `_create_unless` makes them, without compiling; None for what this does not handle."""
    patterns = [t for t in lexer.terminals if isinstance(t.pattern, lark.lexer.PatternRE)]
    strings = [t for t in lexer.terminals if isinstance(t.pattern, lark.lexer.PatternStr)]
    if lexer.g_regex_flags or lexer.user_callbacks or any(t.pattern.flags for t in lexer.terminals) \
            or len(patterns) + len(strings) != len(lexer.terminals):
        return None
    embedded: set[str] = set()
    callbacks: dict[str, Any] = {}
    for pattern in patterns:
        types: dict[str, str] = {}
        regexp = pattern.pattern.to_regexp()
        for string in strings:
            value = string.pattern.value
            if string.priority != pattern.priority:
                continue
            whole = _NAMES_ITSELF.get((regexp, value))
            if whole is None:
                match = lexer.re.match(regexp, value)
                whole = _NAMES_ITSELF[regexp, value] = match is not None and match.group(0) == value
            if whole:
                types.setdefault(value, string.name)
                embedded.add(string.name)
        if types:
            callbacks[pattern.name] = _Keywords(types)
    return [t for t in lexer.terminals if t.name not in embedded], callbacks


class _SharedLexer(lark.lexer.BasicLexer):
    """A state's lexer whose scanner, made when the state is first met, shares the root's pattern."""

    root: lark.lexer.BasicLexer

    def _build_scanner(self) -> Any:
        made = _keywords(self)
        if made is None:
            return super()._build_scanner()
        terminals, self.callback = made
        return SharedScanner(self.root.scanner, self, terminals)


def share_scanners(parser: lark.Lark) -> None:
    """Make each state lexer of `parser` share the root lexer's pattern (in place; nothing
    changes for a lexer or a version of Lark this does not handle)."""
    contextual = getattr(parser.parser, "lexer", None)
    if not isinstance(contextual, lark.lexer.ContextualLexer) or not hasattr(lark.lexer.BasicLexer, "_build_scanner"):
        return
    root = contextual.root_lexer
    if type(root) is not lark.lexer.BasicLexer:
        return
    for lexer in contextual.lexers.values():
        if type(lexer) is lark.lexer.BasicLexer and getattr(lexer, "_scanner", True) is None:
            lexer.__class__ = _SharedLexer
            lexer.root = root  # type: ignore[attr-defined]
