"""JSON text -> values that keep their places (Lark, grammar/json.lark), so a diagnostic about
an imported description points at the JSON line. Size, nesting and the number of values are
bounded (E005) before Lark sees the text; a syntax error is said in words (E008)."""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING

from rdisc.diagnostics import Diagnostics, Label, abbreviate
from rdisc.limits import MAX_INT
from rdisc.source import Span
from rdisc.syntax.build import MAX_INT_DIGITS
from rdisc.syntax.parse import MAX_FILE_CHARS

if TYPE_CHECKING:
    from lark import Lark, Token, Tree
    from lark.exceptions import UnexpectedInput

MAX_DEPTH = 100  # nesting of JSON arrays and objects
MAX_VALUES = 200_000  # a description has thousands; parsing costs about 15 µs a value


@dataclass(frozen=True, slots=True)
class JString:
    value: str
    raw: str  # the token as written, quotes and escapes included
    span: Span


@dataclass(frozen=True, slots=True)
class JNumber:
    value: float  # or int
    span: Span


@dataclass(frozen=True, slots=True)
class JBool:
    value: bool
    span: Span


@dataclass(frozen=True, slots=True)
class JNull:
    span: Span


@dataclass(frozen=True, slots=True)
class JArray:
    items: tuple[JValue, ...]
    span: Span


@dataclass(frozen=True, slots=True)
class JObject:
    members: tuple[tuple[JString, JValue], ...]  # duplicates already reported and dropped
    span: Span


JValue = JString | JNumber | JBool | JNull | JArray | JObject


def read_json(path: str, text: str, diagnostics: Diagnostics) -> JValue | None:
    """Any JSON text, with places; None after an E005/E008 diagnostic."""
    if len(text) > MAX_FILE_CHARS:
        diagnostics.report(
            "E005",
            Span(path, 0, 0),
            f"file is too large ({len(text)} characters; the limit is {MAX_FILE_CHARS})",
        )
        return None
    if not _bounded(path, text, diagnostics):
        return None
    import lark

    try:
        tree = _json_parser().parse(text)
    except lark.exceptions.UnexpectedInput as err:
        _report_json_error(err, path, text, diagnostics)
        return None
    return _Values(path, diagnostics).value(tree)


@lru_cache(maxsize=1)
def _json_parser() -> Lark:  # imported lazily like the RDIS parser
    import lark

    from rdisc.resources import grammar_path

    return lark.Lark.open(
        str(grammar_path().with_name("json.lark")),
        parser="lalr",
        lexer="contextual",
        propagate_positions=True,
        cache=True,
    )


# A string (closed or not: each is scanned once), a bracket or a comma.
_STRUCTURE = re.compile(r'"(?:[^"\\\n]|\\.)*"?|[\[\]{},]')


def _bounded(path: str, text: str, diagnostics: Diagnostics) -> bool:
    """Bound the nesting and the number of values before parsing, so that neither
    building values (recursive) nor parsing (time) can be made to explode."""
    depth = values = 0
    for m in _STRUCTURE.finditer(text):
        c = m.group()
        if c in "[{,":
            values += 1
            if values > MAX_VALUES:
                message = f"JSON has too many values (the limit is {MAX_VALUES})"
                diagnostics.report("E005", Span(path, m.start(), m.end()), message)
                return False
        if c in "[{":
            depth += 1
            if depth > MAX_DEPTH:
                message = f"JSON is nested too deeply (the limit is {MAX_DEPTH} levels)"
                diagnostics.report("E005", Span(path, m.start(), m.end()), message)
                return False
        elif c in "]}":
            depth -= 1
    return True


_TOKEN_WORDS = {
    "STRING": "a string",
    "NUMBER": "a number",
    "TRUE": "`true`",
    "FALSE": "`false`",
    "NULL": "`null`",
    "LBRACE": "`{`",
    "RBRACE": "`}`",
    "LSQB": "`[`",
    "RSQB": "`]`",
    "COMMA": "`,`",
    "COLON": "`:`",
    "$END": "the end of the file",
}
_VALUE_START = {"STRING", "NUMBER", "TRUE", "FALSE", "NULL", "LBRACE", "LSQB"}
_STRING_PREFIX = re.compile(r'"(?:[^"\\\x00-\x1f]|\\["\\/bfnrt]|\\u[0-9a-fA-F]{4})*')


def _report_json_error(err: UnexpectedInput, path: str, text: str, diagnostics: Diagnostics) -> None:
    import lark

    if isinstance(err, lark.exceptions.UnexpectedCharacters):
        begin, end, message = _character_error(text, err.pos_in_stream or 0)
        diagnostics.report("E008", Span(path, begin, end), message)
        return
    if not isinstance(err, lark.exceptions.UnexpectedToken):  # UnexpectedEOF, which only Earley raises
        diagnostics.report("E008", Span(path, len(text), len(text)), "invalid JSON: expected more, found the end "
                           "of the file")
        return
    token = err.token
    expected = set(err.interactive_parser.accepts()) if err.interactive_parser else set(err.expected)
    words = ["a value"] if _VALUE_START <= expected else []
    words += sorted(
        _TOKEN_WORDS[t] for t in expected - (_VALUE_START if words else set()) if t in _TOKEN_WORDS
    )
    wanted = words[0] if len(words) == 1 else ", ".join(words[:-1]) + " or " + words[-1]
    if token.type == "$END":
        found, span = "the end of the file", Span(path, len(text), len(text))
    else:
        shown = str(token) if len(token) <= 30 else str(token)[:27] + "..."
        found, span = f"`{shown}`", Span(path, token.start_pos or 0, token.end_pos or 0)
    trailing = token.type in ("RBRACE", "RSQB") and text[: span.start].rstrip().endswith(",")
    help = "JSON allows no comma after the last member or item" if trailing else None
    diagnostics.report("E008", span, f"invalid JSON: expected {wanted}, found {found}", help=help)


def _character_error(text: str, at: int) -> tuple[int, int, str]:
    """Where and why no token starts at `at`: in a string, the character that ends it."""
    if text[at] != '"':
        shown = text[at] if text[at].isprintable() else repr(text[at])[1:-1]
        return at, at + 1, f"invalid JSON: unexpected character `{shown}`"
    prefix = _STRING_PREFIX.match(text, at)
    bad = prefix.end() if prefix else at
    char = text[bad] if bad < len(text) else ""
    if char == "\\":
        return bad, bad + 2, f"invalid JSON: unknown escape `{text[bad : bad + 2]}` in a string"
    if char in ("", "\n", "\r"):
        return at, bad, "invalid JSON: unterminated string"
    return (
        bad,
        bad + 1,
        f"invalid JSON: control character U+{ord(char):04X} in a string (write it as an escape)",
    )


class _Values:
    """Lark tree → JSON values (recursion bounded by `_bounded`)."""

    def __init__(self, path: str, diagnostics: Diagnostics) -> None:
        self.path = path
        self.d = diagnostics

    def value(self, node: Tree[Token] | Token) -> JValue:
        import lark

        if isinstance(node, lark.Token):
            span = Span(self.path, node.start_pos or 0, node.end_pos or 0)
            if node.type == "STRING":
                text = json.loads(node)
                if any(0xD800 <= ord(ch) <= 0xDFFF for ch in text):  # a lone surrogate escape: no character
                    self.d.report("E008", span, "a string holds half of a surrogate pair (`\\udXXX` alone), "
                                                "which is not a character")
                    text = "".join("\ufffd" if 0xD800 <= ord(ch) <= 0xDFFF else ch for ch in text)
                return JString(text, str(node), span)
            if node.type == "NUMBER":
                return JNumber(self.number(str(node), span), span)
            if node.type == "NULL":
                return JNull(span)
            return JBool(node.type == "TRUE", span)
        span = Span(self.path, node.meta.start_pos, node.meta.end_pos)
        if node.data == "array":
            return JArray(tuple(self.value(c) for c in node.children), span)
        members: dict[str, tuple[JString, JValue]] = {}
        for member in node.children:
            assert isinstance(member, lark.Tree)  # the grammar's `member`: a key and its value
            key, value = self.value(member.children[0]), self.value(member.children[1])
            assert isinstance(key, JString)
            if key.value in members:
                first = members[key.value][0].span
                self.d.report(
                    "E008",
                    key.span,
                    f"duplicate member `{key.value}`",
                    labels=(Label(first, "first given here"),),
                )
                continue
            members[key.value] = (key, value)
        return JObject(tuple(members.values()), span)

    def number(self, token: str, span: Span) -> float:
        integral = not any(c in token for c in ".eE")
        if integral and len(token.lstrip("-")) > MAX_INT_DIGITS:
            self.d.report("E004", span, f"integer with more than {MAX_INT_DIGITS} digits")
            return 0
        value: int | float = json.loads(token)
        if integral and abs(value) > MAX_INT:
            self.d.report("E004", span, f"integer {abbreviate(token)} is too large: integers are limited to 64 bits "
                                        f"and a sign (at most {MAX_INT} either way)")
            return 0
        if not integral and math.isinf(value):
            self.d.report("E004", span, "number too large for a float")
            return 0.0
        return value


_KINDS = {JString: "a string", JNumber: "a number", JBool: "true/false", JNull: "null", JArray: "an array",
          JObject: "an object"}  # fmt: skip


def kind_of(v: JValue) -> str:
    return _KINDS[type(v)]
