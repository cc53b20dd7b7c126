"""Writes the highlighting vocabulary (rdisc/highlight/vocabulary.py), the TextMate grammar
(editors/vscode/syntaxes/rdis.tmLanguage.json) and VS Code's language configuration
(editors/vscode/language-configuration.json) from the grammar, so none drifts from it.

The words are read from Lark's grammar (grammar/rdis.lark): every keyword, sorted into kinds by
the rules that use it (the first word of each declaration, the operators of expressions, the
boolean literals, the words of a conditional and a `for`, the time units); the number, name,
comment and operator patterns are the grammar's terminals. The type names are the Model's, the
built-in functions the engine's, the struct codes those the checker's struct formats read.
`python -m rdisc.highlight.writer --check` (and a test) hold the files equal to what this writes.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path
from typing import Any

from rdisc.highlight import textmate

VOCABULARY = Path(__file__).resolve().parent / "vocabulary.py"
VSCODE = Path(__file__).resolve().parents[2] / "editors" / "vscode"
TEXTMATE = VSCODE / "syntaxes" / "rdis.tmLanguage.json"
LANGUAGE_CONFIGURATION = VSCODE / "language-configuration.json"

Words = dict[str, tuple[str, ...]]

HEADER = '''\
"""The words and token patterns of RDIS, read from grammar/rdis.lark (and the Model's types, the
engine's functions, the struct codes of rdisc's formats), for the TextMate grammar and the Pygments lexer.

Written by `python -m rdisc.highlight.writer`: do not edit; rerun it after changing the grammar
(a test holds this file equal to what it writes).
"""

# fmt: off
'''


def _unique(items: list[str]) -> tuple[str, ...]:
    return tuple(dict.fromkeys(items))


def derive() -> tuple[Words, dict[str, str], tuple[str, ...]]:
    """The grammar's words by kind, its token patterns, and its punctuation (longest first)."""
    from rdisc.engine.operations import FUNCTIONS
    from rdisc.semantics.formats import struct_codes
    from rdisc.semantics.model import Type
    from rdisc.syntax.parse import lark_parser

    made = lark_parser()
    terminals = {t.name: t for t in made.terminals}
    name = re.compile(terminals["NAME"].pattern.to_regexp())

    def word(symbol: Any) -> str | None:
        """The text of a keyword terminal, None for any other symbol."""
        found = terminals.get(symbol.name) if symbol.is_term else None
        if found is None or found.pattern.type != "str" or not name.fullmatch(found.pattern.value):
            return None
        return str(found.pattern.value)

    def words_of(*names: str) -> list[str]:
        """The keywords of the rules of these origins or aliases, in the grammar's order."""
        return [w for rule in made.rules if rule.origin.name in names or rule.alias in names
                for w in map(word, rule.expansion) if w is not None]

    first = {rule.origin.name: word(rule.expansion[0]) for rule in made.rules if rule.expansion}
    declaration = _unique([w for rule in made.rules if rule.origin.name == "decl"
                           if (w := first.get(rule.expansion[0].name)) is not None])
    constant = _unique(words_of("bool_lit"))
    operator = _unique(words_of("_binary_op", "_prefix_op"))
    threading = [rule.expansion[-1] for rule in made.rules if rule.alias == "threading"]
    unit = _unique(words_of("time_unit") + [w for w in map(word, threading) if w is not None])
    control = _unique([w for w in words_of("conditional", "for_stmt") if w not in operator])
    every = _unique(sorted(w for rule in made.rules for w in map(word, rule.expansion) if w is not None))
    sorted_out = set(declaration + constant + operator + unit + control)
    words: Words = {
        "declaration": declaration,
        "constant": constant,
        "operator": operator,
        "control": control,
        "unit": unit,
        "keyword": tuple(w for w in every if w not in sorted_out),
        "type": tuple(t.value for t in Type),
        "function": tuple(sorted(FUNCTIONS)),
        "struct_code": tuple(struct_codes()),
    }

    integer = terminals["INT"].pattern.to_regexp().split("|")  # hexadecimal, binary, octal, decimal
    if len(integer) != 4 or not integer[0].startswith("0[xX]") or not integer[1].startswith("0[bB]"):
        raise TypeError(f"INT is no longer hexadecimal | binary | octal | decimal: {integer}")
    symbols = [t for rule in made.rules if rule.origin.name in ("_binary_op", "_prefix_op")
               for t in (terminals[s.name] for s in rule.expansion) if not name.fullmatch(str(t.pattern.value))]
    symbols = sorted(dict.fromkeys(symbols), key=lambda t: (-t.priority, -t.pattern.max_width))
    patterns = {
        "name": terminals["NAME"].pattern.to_regexp(),
        "hexadecimal": integer[0],
        "binary": integer[1],
        "octal": integer[2],
        "decimal": integer[3],
        "float": terminals["FLOAT"].pattern.to_regexp(),
        "doc_comment": terminals["DOC_COMMENT"].pattern.to_regexp(),
        "comment": terminals["COMMENT"].pattern.to_regexp(),
        "operator": "|".join(t.pattern.to_regexp() for t in symbols),
    }
    punctuation = sorted({str(t.pattern.value) for t in made.terminals
                          if t.pattern.type == "str" and t.name not in {s.name for s in symbols}
                          and not name.fullmatch(str(t.pattern.value))}, key=lambda s: (-len(s), s))
    return words, patterns, tuple(punctuation)


def write_vocabulary(words: Words, patterns: dict[str, str], punctuation: tuple[str, ...]) -> str:
    """The text of rdisc/highlight/vocabulary.py."""
    out = [HEADER, "# The grammar's keywords by kind, and the other words a description reads.\n",
           "WORDS: dict[str, tuple[str, ...]] = {\n"]
    out += [f"    {kind!r}: {tuple(listed)!r},\n" for kind, listed in words.items()]
    out.append("}\n\n# The grammar's terminals, as regular expressions.\nPATTERNS: dict[str, str] = {\n")
    out += [f"    {kind!r}: {pattern!r},\n" for kind, pattern in patterns.items()]
    out.append("}\n\n# The grammar's punctuation, longest first.\n")
    out.append(f"PUNCTUATION: tuple[str, ...] = {punctuation!r}\n")
    return "".join(out)


def write_textmate(words: Words, patterns: dict[str, str], punctuation: tuple[str, ...]) -> str:
    """The text of editors/vscode/syntaxes/rdis.tmLanguage.json."""
    return json.dumps(textmate.grammar(words, patterns, punctuation), indent=2, ensure_ascii=False) + "\n"


def write_language_configuration(words: Words, patterns: dict[str, str], punctuation: tuple[str, ...]) -> str:
    """The text of editors/vscode/language-configuration.json."""
    return json.dumps(textmate.language_configuration(patterns, punctuation), indent=2, ensure_ascii=False) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m rdisc.highlight.writer",
                                     description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="only say whether a written file is stale (exit 1)")
    args = parser.parse_args(argv)
    made = derive()
    stale = 0
    written = ((VOCABULARY, write_vocabulary(*made)), (TEXTMATE, write_textmate(*made)),
               (LANGUAGE_CONFIGURATION, write_language_configuration(*made)))
    for target, text in written:
        if target.is_file() and target.read_text(encoding="utf-8") == text:
            continue
        if args.check:
            print(f"{target} is stale: run python -m rdisc.highlight.writer", file=sys.stderr)
            stale = 1
            continue
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8", newline="\n")
        print(f"wrote {target}")
    return stale


if __name__ == "__main__":
    sys.exit(main())
