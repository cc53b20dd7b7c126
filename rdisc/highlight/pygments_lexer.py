"""The Pygments lexer of RDIS (`pygmentize -l rdis`, Sphinx and MkDocs code blocks), registered
as the entry point `pygments.lexers: rdis`.

Its words and patterns are the grammar's (rdisc.highlight.vocabulary, written from grammar/rdis.lark)
and its rules follow the TextMate grammar's (rdisc.highlight.textmate): a declaration's keyword in
column 0 and its name, the places where any word is a name, struct codes in the strings after `pack`, `unpack` and the frame words,
placeholders after `format`, a regular expression after `regex`. Text a description could not
hold (a stray `$`) is an Error token; no valid description has one.
"""

from __future__ import annotations

import re
from typing import Any, ClassVar

from pygments.lexer import RegexLexer, bygroups, default, include, words
from pygments.token import (
    Comment,
    Keyword,
    Name,
    Number,
    Operator,
    Punctuation,
    String,
    Whitespace,
    _TokenType,
)

from rdisc.highlight.textmate import ALONE, ASSIGNED, CALLED, NAME_KINDS, OWNER, PARAMETER, STRUCT_WORDS
from rdisc.highlight.vocabulary import PATTERNS, PUNCTUATION, WORDS

_NAME = PATTERNS["name"]
_NOT_CONSTANT = rf"(?!(?:{'|'.join(WORDS['constant'])})\b)"
_NAMES: dict[str, _TokenType] = {"function": Name.Function, "variable": Name.Variable, "constant": Name.Constant,
                                  "type": Name.Class}
_STRING_BODY = r'[^"\\\n]+'
_ESCAPE = r"\\(?:x[0-9A-Fa-f]{2}|[^\n])"


def _declarations() -> list[Any]:
    return [(rf"^({re.escape(word)})\b(?:(\s+)({_NAME}))?",
             bygroups(Keyword.Declaration, Whitespace, _NAMES[NAME_KINDS.get(word, "type")]))
            for word in WORDS["declaration"]]


def _quoted(token: _TokenType, escape: _TokenType) -> list[Any]:
    """The rest of a string: escapes, the closing quote, or the line's end (strings do not span lines)."""
    return [(_ESCAPE, escape), (_STRING_BODY, token), ('"', token, "#pop"), default("#pop")]


class RdisLexer(RegexLexer):
    """RDIS, the Robot Device Interface Specification language."""

    name = "RDIS"
    aliases: ClassVar[list[str]] = ["rdis"]
    filenames: ClassVar[list[str]] = ["*.rdis"]
    mimetypes: ClassVar[list[str]] = ["text/x-rdis"]

    tokens: ClassVar[dict[str, list[Any]]] = {
        "root": [
            (r"[ \t\f\r\n]+", Whitespace),
            (PATTERNS["doc_comment"], String.Doc),
            (PATTERNS["comment"], Comment.Single),
            *_declarations(),
            (rf"\b({'|'.join(STRUCT_WORDS)})\b(\s*)(\")", bygroups(Keyword, Whitespace, String.Double), "struct"),
            (rf'\b(field)(\s+)({_NAME})(\s*)(")', bygroups(Keyword, Whitespace, Name, Whitespace, String.Double),
             "struct"),
            (r'\b(checksum)(\s+)("(?:[^"\\\n]|\\[^\n])*")(\s*)(")',
             bygroups(Keyword, Whitespace, String.Double, Whitespace, String.Double), "struct"),
            (r'\b(format)(\s*)(")', bygroups(Keyword, Whitespace, String.Double), "format"),
            (r'\b(regex)(\s*)(r?")', bygroups(Keyword, Whitespace, String.Regex), "regex"),
            (r'(b)(")', bygroups(String.Affix, String.Double), "bytes"),
            (r'(r)(")', bygroups(String.Affix, String.Double), "raw"),
            (r'"', String.Double, "string"),
            include("names"),
            (PATTERNS["float"], Number.Float),
            (PATTERNS["hexadecimal"], Number.Hex),
            (PATTERNS["binary"], Number.Bin),
            (PATTERNS["octal"], Number.Oct),
            (PATTERNS["decimal"], Number.Integer),
            (words([p for p in PUNCTUATION if len(p) > 1]), Operator),
            (PATTERNS["operator"], Operator),
            (words(["="]), Operator),
            (words([p for p in PUNCTUATION if len(p) == 1 and p != "="]), Punctuation),
        ],
        "names": [
            (rf"(:)(\s*)({'|'.join(WORDS['type'])})\b", bygroups(Punctuation, Whitespace, Keyword.Type)),
            (words(WORDS["function"], prefix=r"\b", suffix=CALLED), Name.Builtin),
            (rf"\b{_NAME}{ASSIGNED}", Name.Variable),
            (rf"([(,])(\s*)({_NOT_CONSTANT}{_NAME}){PARAMETER}", bygroups(Punctuation, Whitespace, Name.Variable)),
            (rf"([(,])(\s*)({_NOT_CONSTANT}{_NAME}){ALONE}", bygroups(Punctuation, Whitespace, Name)),
            (rf"{_NAME}{OWNER}", Name),
            (words(WORDS["constant"], prefix=r"\b", suffix=r"\b"), Keyword.Constant),
            (words(WORDS["operator"], prefix=r"\b", suffix=r"\b"), Operator.Word),
            (words(WORDS["unit"], prefix=r"\b", suffix=r"\b"), Keyword.Pseudo),
            (words(WORDS["control"] + WORDS["keyword"] + WORDS["declaration"], prefix=r"\b", suffix=r"\b"),
             Keyword),
            (_NAME, Name),
        ],
        "string": _quoted(String.Double, String.Escape),
        "bytes": _quoted(String.Double, String.Escape),
        "raw": [(r"\\[^\n]", String.Double), *_quoted(String.Double, String.Double)],
        "regex": [(r"\\[^\n]", String.Regex), *_quoted(String.Regex, String.Regex)],
        "format": [(r"\{\{|\}\}", String.Escape), (r'\{[^{}"\n]*\}', String.Interpol), (r'[^"\\\n{}]+', String.Double),
                   (r"[{}]", String.Double), *_quoted(String.Double, String.Escape)],
        "struct": [
            (r"[@=<>!]", Operator),
            (rf"([0-9]*)(\s*)([{''.join(re.escape(c) for c in WORDS['struct_code'])}])",
             bygroups(Number.Integer, Whitespace, String.Interpol)),
            (r"[#%*]", Operator),
            (r"[0-9]+", Number.Integer),
            (r"[(){},]", Punctuation),
            (r"[ \t]+", Whitespace),
            (r'[^"\\\n]', String.Double),
            *_quoted(String.Double, String.Escape),
        ],
    }
