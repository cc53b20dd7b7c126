"""Syntax errors in words: what was expected and what was found, never grammar names."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from lark import Token
    from lark.exceptions import UnexpectedInput

# Named terminals of grammar/rdis.lark, in words.
_WORDS = {
    "NAME": "a name",
    "INT": "an integer",
    "FLOAT": "a number",
    "STRING": "a string",
    "RAW_STRING": "a string",
    "BYTES_STRING": "a bytes literal",
    "TRUE": "`True`",
    "FALSE": "`False`",
    "NOT": "`not`",
    "UNARY_OP": "an expression",
    "LPAR": "an opening `(`",
    "RPAR": "a closing `)`",
    "LBRACE": "an opening `{`",
    "RBRACE": "a closing `}`",
    "LSQB": "an opening `[`",
    "RSQB": "a closing `]`",
    "COMMA": "`,`",
    "COLON": "`:`",
    "EQUAL": "`=`",
    "$END": "the end of the file",
    "DECLARATION": "a new declaration",
}
_DECLARATIONS = {"IMPORT", "ROBOT", "STATE", "CONNECTION", "PRIMITIVE", "INTERFACE", "ADAPTER", "INPUT", "OUTPUT"}
# Terminals that can only continue an expression: listed as one phrase.
_OPERATORS = {"POW", "SHIFT_OP", "COMP_OP", "MUL_OP", "ADD_OP", "BAR", "CARET", "AMP", "OR", "AND", "IF"}
_EXPRESSION_START = {"INT", "FLOAT", "STRING", "RAW_STRING", "BYTES_STRING", "TRUE", "FALSE", "NOT",
                     "UNARY_OP"}

# An output's optional `noise` and `filter` clauses: where a field's name or the closing `}` may
# come, they are left unnamed (the message says what an output's body needs, not all it may hold).
_OPTIONAL_CLAUSES = {"NOISE", "FILTER"}


def _phrase(terminal: str) -> str | None:
    if terminal in _WORDS:
        return _WORDS[terminal]
    if re.fullmatch(r"[A-Z]+", terminal):  # an anonymous keyword terminal, e.g. DELAY
        return f"`{terminal.lower()}`"
    if terminal == "__ANON_0" or terminal.startswith("__ANON"):
        return None
    return f"`{terminal.lower()}`"


def expected_words(expected: set[str]) -> str:
    """'a name, `,` or a closing `)`' for a set of terminal names."""
    phrases: list[str] = []
    names = set(expected)
    if {"NAME", "RBRACE"} <= names:
        names -= _OPTIONAL_CLAUSES
    if "NAME" in names and names & _EXPRESSION_START:
        phrases.append("an expression")
        names -= _EXPRESSION_START | {"NAME", "LPAR", "LSQB", "ADD_OP"}  # `[`: an array
    if names & _OPERATORS:
        phrases.append("an operator")
        names -= _OPERATORS | {"IN"}  # `in` is one too where they are (alone it is `for`'s, and named)
    for name in sorted(names):
        word = _phrase(name)
        if word and word not in phrases:
            phrases.append(word)
    if not phrases:
        return "something else"
    if len(phrases) == 1:
        return phrases[0]
    return ", ".join(phrases[:-1]) + " or " + phrases[-1]


def _found(token: Token) -> str:
    if token.type == "$END":
        return "the end of the file"
    text = str(token)
    if token.type in ("STRING", "RAW_STRING"):
        return f"the string {text}" if len(text) <= 30 else "a string"
    if token.type == "BYTES_STRING":
        return f"the bytes {text}" if len(text) <= 30 else "a bytes literal"
    if len(text) > 30:
        text = text[:27] + "..."
    return f"`{text}`"


def _hint(token: object, accepted: set[str], after: str) -> str | None:
    """Help for a likely slip: a misspelt keyword, or a comment written as in C (`after`:
    the text from the token on)."""
    text = str(token)
    if after.startswith(("//", "/*")):
        return "comments start with `#`, and doc comments with `///`"
    if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", text):
        return None
    keywords = {t.lower() for t in accepted if re.fullmatch(r"[A-Z]+", t) and t not in _WORDS}
    if "DECLARATION" in accepted:
        keywords |= {t.lower() for t in _DECLARATIONS}
    from rdisc.engine.errors import nearest  # only for a misspelt word: `check` imports little of the engine

    close = nearest(text, sorted(keywords))
    return f"did you mean `{close}`?" if close else None


def describe_unexpected(err: UnexpectedInput, chunk: str,
                        last: bool) -> tuple[str, int, int, str, str | None, str | None]:
    """(code, offset in chunk, length, message, label, help) for a Lark error."""
    import lark

    if isinstance(err, lark.exceptions.UnexpectedCharacters):
        offset = err.pos_in_stream or 0  # the lexer always sets it; Lark's class declares it None
        char = chunk[offset] if offset < len(chunk) else ""
        if char == '"' or chunk[offset : offset + 2] == 'r"':
            line_end = chunk.find("\n", offset)
            line_end = len(chunk) if line_end == -1 else line_end
            return ("E002", offset, line_end - offset, "unterminated string", "this string is not closed on its line",
                    None)
        if char == "'":
            return ("E002", offset, 1, "unexpected character `'`", "strings are written in double quotes", None)
        if char == "_":
            return ("E002", offset, 1, "names cannot start with `_`", "a name starts with a letter", None)
        shown = repr(char)[1:-1] if not char.isprintable() or char.isspace() else char
        return ("E002", offset, 1, f"unexpected character `{shown}`", "no token starts with this character", None)

    if not isinstance(err, lark.exceptions.UnexpectedToken):  # UnexpectedEOF, which only Earley raises
        return ("E001", len(chunk), 0, "expected more, found the end of the file", None, None)
    token = err.token
    accepted = set(err.expected)
    if err.interactive_parser is not None:  # exact: LALR merges lookaheads of similar states
        accepted = set(err.interactive_parser.accepts())
    if len(accepted & _DECLARATIONS) > 2:
        accepted = (accepted - _DECLARATIONS - {"$END"}) | {"DECLARATION"}
    expected = expected_words(accepted)
    if token.type == "$END":
        if last:
            return ("E001", len(chunk), 0, f"expected {expected}, found the end of the file", None, None)
        return (
            "E001",
            len(chunk),
            0,
            f"expected {expected} before the next declaration",
            "the declaration before this one is not finished",
            None,
        )
    start = token.start_pos or 0
    length = max(1, (token.end_pos or start + 1) - start)
    return ("E001", start, length, f"expected {expected}, found {_found(token)}", None, _hint(token, accepted, chunk[start : start + 2]))
