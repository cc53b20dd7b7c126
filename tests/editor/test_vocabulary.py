"""The highlighters' words are the grammar's: the written vocabulary and TextMate grammar are what
`python -m rdisc.highlight.writer` makes of grammar/rdis.lark now, their keywords are exactly the
words of the parser's tables, and the Pygments lexer reads each of them as a keyword."""

from __future__ import annotations

import json
import re

from pygments.token import Keyword, Name, Operator

from rdisc.highlight import writer
from rdisc.highlight.pygments_lexer import RdisLexer
from rdisc.highlight.vocabulary import WORDS
from rdisc.syntax import tables
from rdisc.syntax.parse import DECL_KEYWORDS

KEYWORD_KINDS = ("declaration", "constant", "operator", "control", "unit", "keyword")
# The grammar's keywords as the parser's written tables hold them: terminals whose pattern is a word.
GRAMMAR_WORDS = {p for p in tables.TERMINALS.values() if re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", p)}


def test_the_written_files_are_what_the_writer_makes_of_the_grammar() -> None:
    made = writer.derive()
    assert writer.VOCABULARY.read_text(encoding="utf-8") == writer.write_vocabulary(*made)
    assert writer.TEXTMATE.read_text(encoding="utf-8") == writer.write_textmate(*made)
    assert writer.main(["--check"]) == 0


def test_the_keywords_are_the_grammars_each_of_one_kind() -> None:
    listed = [w for kind in KEYWORD_KINDS for w in WORDS[kind]]
    assert len(listed) == len(set(listed)) > 100
    assert set(listed) == GRAMMAR_WORDS
    assert WORDS["declaration"] == DECL_KEYWORDS  # where the parser cuts a file into declarations
    assert (WORDS["constant"], WORDS["unit"], WORDS["control"]) == (("True", "False"), ("ms", "s", "Hz"),
                                                                    ("for", "if", "else"))
    assert set(WORDS["operator"]) == {"and", "or", "not", "in"}


def test_the_textmate_grammar_matches_exactly_the_keywords() -> None:
    grammar = json.loads(writer.TEXTMATE.read_text(encoding="utf-8"))
    matched: list[str] = []
    for rule in grammar["repository"]["names"]["patterns"]:
        if rule.get("name", "").startswith(("keyword.", "constant.language.")):
            found = re.fullmatch(r"\\b\(\?:([A-Za-z|]+)\)\\b", rule["match"])
            assert found is not None, rule
            matched += found.group(1).split("|")
    assert sorted(matched) == sorted(GRAMMAR_WORDS)
    declared = [re.match(r"\^\((\w+)\)", rule["match"]).group(1)  # type: ignore[union-attr]
                for rule in grammar["repository"]["declarations"]["patterns"]]
    assert tuple(declared) == DECL_KEYWORDS


def test_the_pygments_lexer_reads_every_keyword_as_one_and_other_words_as_names() -> None:
    lexer = RdisLexer()
    for word in sorted(GRAMMAR_WORDS):
        (kind, value), _newline = list(lexer.get_tokens(f" {word}"))[1:]
        assert value == word and (kind in Keyword or kind in Operator.Word), (word, kind)
    for word in ("position", "payloads", "ifx", "Hzz", "s2"):
        assert list(lexer.get_tokens(f" {word}"))[1][0] is Name, word
