"""The tokens of a description as rdisc's parser reads them: the ground truth the highlighters
are held to. Keywords are contextual (`state error: int`, `error = out[1]`): Lark's contextual
lexer offers every keyword that may follow an expression, and the parser reads one where it
wants a name as that name (rdisc.syntax.parse.keyword_as_name); this does the same, token by
token, so a word is a keyword here exactly where the parser takes it as one."""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import lark

from rdisc.syntax import parse

ROOT = Path(__file__).resolve().parents[2]
FILES = (*sorted((ROOT / "examples").glob("*.rdis")), ROOT / "stdlib" / "adapters.rdis")
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
lark_parser = lru_cache(maxsize=1)(parse.lark_parser)  # Lark's own, without rdisc's shared scanners


@dataclass(frozen=True)
class Token:
    kind: str  # the terminal: NAME, INT, STRING, or a keyword's (ROBOT, TRUE, OR)
    text: str
    line: int  # from 0
    column: int  # from 0, in characters

    @property
    def end(self) -> int:
        return self.column + len(self.text)


def keyword_kinds() -> frozenset[str]:
    """The terminals that are keywords: a word of the grammar."""
    return frozenset(t.name for t in lark_parser().terminals
                     if t.pattern.type == "str" and _NAME.fullmatch(str(t.pattern.value)))


@lru_cache(maxsize=64)
def tokens(text: str) -> tuple[Token, ...]:
    """Every token of `text` (a whole description that parses), as the parser reads it."""
    interactive = lark_parser().parse_interactive(text, start="start")
    found: list[Token] = []
    for token in interactive.lexer_thread.lex(interactive.parser_state):
        try:
            interactive.feed_token(token)
        except lark.exceptions.UnexpectedToken:
            if not _NAME.fullmatch(str(token)):
                raise
            token = lark.Token.new_borrow_pos("NAME", str(token), token)
            interactive.feed_token(token)
        found.append(Token(token.type, str(token), token.line - 1, token.column - 1))
    interactive.feed_eof()
    return tuple(found)
