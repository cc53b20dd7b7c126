"""The TextMate grammar of RDIS (scope `source.rdis`), made of the grammar's words and patterns.

TextMate grammars match line by line with regular expressions, so a word the contextual parser
reads as a name where it stands (`state error`, `error = out[1]`) is a keyword here unless a rule
sees its place: a declaration's name after its keyword in column 0 (where the parser cuts
declarations), an assignment's target, a parameter, an argument alone, an indexed name or a
member's owner, a built-in function's call, a type after `:`. The
language server's semantic tokens refine the rest. Strings after `pack`, `unpack` and the frame
words that take a struct format show its codes; after `format` its placeholders; after `regex`
a regular expression.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from typing import Any

# The scopes of the grammar's keywords by kind (rdisc.highlight.writer sorts them).
WORD_SCOPES = {
    "declaration": "keyword.other.rdis",  # in column 0 the declaration rule scopes it storage.type
    "constant": "constant.language.boolean.rdis",
    "operator": "keyword.operator.word.rdis",
    "control": "keyword.control.rdis",
    "unit": "keyword.other.unit.rdis",
    "keyword": "keyword.other.rdis",
}
# What a declaration's name is: entity.name.<kind>.<keyword>.rdis (any other: a type).
NAME_KINDS = {"primitive": "function", "interface": "function", "input": "function", "output": "function",
              "state": "variable", "setting": "variable", "const": "constant"}
PUNCTUATION_SCOPES = {
    "=": "keyword.operator.assignment.rdis",
    "..": "keyword.operator.range.rdis",
    "->": "keyword.operator.arrow.rdis",
    ",": "punctuation.separator.comma.rdis",
    ":": "punctuation.separator.colon.rdis",
    ".": "punctuation.accessor.rdis",
    "(": "punctuation.section.parens.begin.rdis",
    ")": "punctuation.section.parens.end.rdis",
    "[": "punctuation.section.brackets.begin.rdis",
    "]": "punctuation.section.brackets.end.rdis",
    "{": "punctuation.section.braces.begin.rdis",
    "}": "punctuation.section.braces.end.rdis",
}
# What follows a name where the parser reads any word as a name (lookaheads, shared with the
# Pygments lexer): an assignment's target (`x =`, `x[i] =`, not `x ==`), a parameter or a table's
# key (`(on: bool`), an argument alone (`(137, velocity)`), an indexed name or a member's owner.
ASSIGNED = r"(?=\s*(?:\[[^\]\n]{0,200}\])?\s*=(?!=))"
PARAMETER = r"(?=\s*:)"
ALONE = r"(?=\s*[,)])"
OWNER = r"(?=\[|\.[A-Za-z])"
CALLED = r"(?=\s*\()"
# Clause words followed by a struct format (`pack "<BH"`, `length "<H" = payload`, `tag "B"`).
STRUCT_WORDS = ("pack", "unpack", "length", "tag", "bits")

_BEGIN_QUOTE = {"name": "punctuation.definition.string.begin.rdis"}
_END_QUOTE = {"1": {"name": "punctuation.definition.string.end.rdis"}}
_ESCAPE: dict[str, Any] = {"name": "constant.character.escape.rdis", "match": r"\\(?:x[0-9A-Fa-f]{2}|[^\n])"}
_STRING_END = '(")|$'  # strings do not span lines


def alternatives(words: Iterable[str]) -> str:
    """A regular expression matching any of `words` as a whole word."""
    return r"\b(?:" + "|".join(re.escape(w) for w in words) + r")\b"


def grammar(words: Mapping[str, tuple[str, ...]], patterns: Mapping[str, str],
            punctuation: tuple[str, ...]) -> dict[str, Any]:
    """The TextMate grammar, as the JSON object VS Code reads."""
    keywords = {w: WORD_SCOPES[kind] for kind in ("keyword", "declaration", "unit", "control", "operator", "constant")
                for w in words[kind]}
    missing = [w for w in ("format", "regex", "field", "checksum", *STRUCT_WORDS) if w not in keywords]
    if missing:
        raise TypeError(f"the grammar no longer has the keywords {missing}")
    name = patterns["name"]
    not_constant = f"(?!{alternatives(words['constant'])})"

    def declaration(word: str) -> dict[str, Any]:
        kind = NAME_KINDS.get(word, "type")
        return {"match": rf"^({re.escape(word)})\b(?:\s+({name}))?",
                "captures": {"1": {"name": "storage.type.rdis"}, "2": {"name": f"entity.name.{kind}.{word}.rdis"}}}

    def quoted(begin: str, captures: dict[str, Any], scope: str, inside: list[dict[str, Any]]) -> dict[str, Any]:
        """A string from `begin` (its last group the opening quote) to its closing quote or the line's end;
        only the quotes and what is between them are `scope`: not a keyword `begin` also matches."""
        opening = str(max(map(int, captures)))
        captures = {**captures, opening: {"name": f"{scope} {_BEGIN_QUOTE['name']}"}}
        return {"contentName": scope, "begin": begin, "beginCaptures": captures, "end": _STRING_END,
                "endCaptures": {"1": {"name": f"{scope} {_END_QUOTE['1']['name']}"}}, "patterns": inside}

    struct_codes = "".join(re.escape(c) for c in words["struct_code"])
    struct_inside = [
        _ESCAPE,
        {"name": "keyword.operator.byte-order.rdis", "match": "[@=<>!]"},
        {"match": rf"([0-9]*)\s*([{struct_codes}])",
         "captures": {"1": {"name": "constant.numeric.integer.decimal.rdis"},
                      "2": {"name": "constant.character.format.struct.rdis"}}},
        {"name": "keyword.operator.struct.rdis", "match": "[#%*]"},
        {"name": "constant.numeric.integer.decimal.rdis", "match": "[0-9]+"},
        {"name": "punctuation.section.group.struct.rdis", "match": "[(){}]"},
    ]
    struct_string = "string.quoted.double.struct.rdis"
    rules: dict[str, Any] = {
        "comments": {"patterns": [
            {"name": "comment.line.documentation.rdis", "begin": "///", "end": "$",
             "beginCaptures": {"0": {"name": "punctuation.definition.comment.rdis"}},
             "patterns": [{"name": "markup.inline.raw.rdis", "match": "`[^`]*`"}]},
            {"name": "comment.line.number-sign.rdis", "match": patterns["comment"]},
        ]},
        "declarations": {"patterns": [declaration(w) for w in words["declaration"]]},
        "templates": {"patterns": [
            quoted(rf"\b({alternatives(STRUCT_WORDS)})\s*(\")",
                   {"1": {"name": keywords["pack"]}, "2": _BEGIN_QUOTE}, struct_string, struct_inside),
            quoted(rf"\b(field)\s+({name})\s*(\")",
                   {"1": {"name": keywords["field"]}, "3": _BEGIN_QUOTE}, struct_string, struct_inside),
            quoted(r'\b(checksum)\s+("(?:[^"\\\n]|\\[^\n])*")\s*(")',
                   {"1": {"name": keywords["checksum"]}, "2": {"name": "string.quoted.double.rdis"},
                    "3": _BEGIN_QUOTE}, struct_string, struct_inside),
            quoted(r'\b(format)\s*(")', {"1": {"name": keywords["format"]}, "2": _BEGIN_QUOTE},
                   "string.quoted.double.format.rdis",
                   [_ESCAPE, {"name": "constant.character.escape.rdis", "match": r"\{\{|\}\}"},
                    {"name": "constant.other.placeholder.rdis", "match": r'\{[^{}"\n]*\}'}]),
            quoted(r'\b(regex)\s*(r?")', {"1": {"name": keywords["regex"]}, "2": _BEGIN_QUOTE},
                   "string.regexp.rdis", [{"name": "constant.character.escape.regexp.rdis", "match": r"\\[^\n]"}]),
        ]},
        "strings": {"patterns": [
            quoted('(b)(")', {"1": {"name": "string.quoted.double.bytes.rdis storage.type.string.rdis"},
                              "2": _BEGIN_QUOTE}, "string.quoted.double.bytes.rdis", [_ESCAPE]),
            quoted('(r)(")', {"1": {"name": "string.quoted.double.raw.rdis storage.type.string.rdis"},
                              "2": _BEGIN_QUOTE}, "string.quoted.double.raw.rdis", [{"match": r"\\[^\n]"}]),
            quoted('(")', {"1": _BEGIN_QUOTE}, "string.quoted.double.rdis", [_ESCAPE]),
        ]},
        "names": {"patterns": [
            {"match": rf"(:)\s*({alternatives(words['type'])})",
             "captures": {"1": {"name": PUNCTUATION_SCOPES[":"]}, "2": {"name": "support.type.rdis"}}},
            {"name": "support.function.builtin.rdis", "match": alternatives(words["function"]) + CALLED},
            {"name": "variable.other.assignment.rdis",
             "match": rf"\b{name}{ASSIGNED}"},
            # Where the parser reads any word as a name: a parameter (`(on: bool`), an argument alone
            # (`(137, velocity)`), an indexed or a member's owner (`out[0]`, `Op.read`).
            {"match": rf"([(,])\s*{not_constant}({name}){PARAMETER}",
             "captures": {"1": {"patterns": [{"include": "#operators"}]}, "2": {"name": "variable.parameter.rdis"}}},
            {"match": rf"([(,])\s*{not_constant}({name}){ALONE}",
             "captures": {"1": {"patterns": [{"include": "#operators"}]}}},
            {"match": rf"\b{name}{OWNER}"},
            *({"name": WORD_SCOPES[kind], "match": alternatives(words[kind])}
              for kind in ("constant", "operator", "control", "unit")),
            {"name": WORD_SCOPES["keyword"], "match": alternatives(words["keyword"] + words["declaration"])},
            {"match": rf"\b{name}"},  # any other name: no scope, and no number inside it
        ]},
        "numbers": {"patterns": [
            {"name": "constant.numeric.float.rdis", "match": patterns["float"]},
            {"name": "constant.numeric.integer.hexadecimal.rdis", "match": patterns["hexadecimal"]},
            {"name": "constant.numeric.integer.binary.rdis", "match": patterns["binary"]},
            {"name": "constant.numeric.integer.octal.rdis", "match": patterns["octal"]},
            {"name": "constant.numeric.integer.decimal.rdis", "match": patterns["decimal"]},
        ]},
        "operators": {"patterns": [
            *({"name": PUNCTUATION_SCOPES.get(p, "punctuation.other.rdis"), "match": re.escape(p)}
              for p in punctuation if len(p) > 1),
            {"name": "keyword.operator.rdis", "match": patterns["operator"]},
            *({"name": PUNCTUATION_SCOPES.get(p, "punctuation.other.rdis"), "match": re.escape(p)}
              for p in punctuation if len(p) == 1),
        ]},
    }
    return {
        "$schema": "https://raw.githubusercontent.com/martinring/tmlanguage/master/tmlanguage.json",
        "name": "RDIS",
        "scopeName": "source.rdis",
        "fileTypes": ["rdis"],
        "comment": "Written by `python -m rdisc.highlight.writer` from grammar/rdis.lark: do not edit.",
        "patterns": [{"include": f"#{rule}"} for rule in rules],
        "repository": rules,
    }


def language_configuration(patterns: Mapping[str, str], punctuation: tuple[str, ...]) -> dict[str, Any]:
    """VS Code's language configuration: `#` comments (Toggle Line Comment), the grammar's
    brackets, quotes closed as typed, a line ending in an open bracket indenting the next, a
    doc comment continued on Enter, and a word is a name of the grammar."""
    brackets = [[o, c] for o, c in ("{}", "[]", "()") if o in punctuation and c in punctuation]
    closing = "".join(re.escape(c) for _, c in brackets)
    opening = "".join(re.escape(o) for o, _ in brackets)
    if not patterns["comment"].startswith("#"):
        raise TypeError(f"a comment no longer starts with #: {patterns['comment']}")
    return {
        "comments": {"lineComment": "#"},
        "brackets": brackets,
        "autoClosingPairs": [*({"open": o, "close": c} for o, c in brackets),
                             {"open": '"', "close": '"', "notIn": ["string", "comment"]}],
        "surroundingPairs": [*brackets, ['"', '"'], ["`", "`"]],
        "wordPattern": patterns["name"],
        "indentationRules": {
            "increaseIndentPattern": rf"^.*[{opening}]\s*(#.*)?$",
            "decreaseIndentPattern": rf"^\s*[{closing}]",
        },
        "onEnterRules": [{"beforeText": r"^\s*///", "action": {"indent": "none", "appendText": "/// "}}],
    }
