"""The Pygments lexer (`pygmentize -l rdis`) over every example and the standard library: no
Error token, every keyword, number, string and bytes literal the parser reads has its token type,
and chosen places have exact ones; no Error token in the docs' RDIS blocks either, and any text
at all lexes into tokens that give it back."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pygments.token import Comment, Error, Keyword, Name, Number, Operator, Punctuation, String, _TokenType

from rdisc.highlight.pygments_lexer import RdisLexer
from tests.editor.parsed_tokens import FILES, ROOT, keyword_kinds, tokens

LEXER = RdisLexer()


def lexed(text: str) -> dict[tuple[int, int], tuple[_TokenType, str]]:
    """Each token by where it starts: (line, column), both from 0."""
    starts = [0]
    for line in text.split("\n"):
        starts.append(starts[-1] + len(line) + 1)
    found: dict[tuple[int, int], tuple[_TokenType, str]] = {}
    line = 0
    for offset, kind, value in LEXER.get_tokens_unprocessed(text):
        while starts[line + 1] <= offset:
            line += 1
        found[line, offset - starts[line]] = (kind, value)
    return found


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_no_error_token_and_every_parsed_token_has_its_type(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    assert [value for _, kind, value in LEXER.get_tokens_unprocessed(text) if kind in Error] == []
    found = lexed(text)
    keywords = keyword_kinds()
    wrong = []
    for token in tokens(text):
        kind, value = found.get((token.line, token.column), (None, ""))
        if token.kind in keywords:
            right = kind in Keyword or kind in Operator.Word
            whole = value == token.text
        elif token.kind in ("INT", "FLOAT"):
            right, whole = kind in Number, value == token.text
        elif token.kind in ("STRING", "RAW_STRING", "BYTES_STRING"):
            right, whole = kind in String, True  # a string's parts: affix, quote, escapes, codes
        else:
            continue
        if not (right and whole):
            wrong.append((token.line + 1, token.text, kind, value))
    assert wrong == []


def kinds(text: str) -> list[tuple[_TokenType, str]]:
    return [(kind, value) for kind, value in LEXER.get_tokens(text) if not value.isspace()]


def test_declarations_comments_numbers_and_units() -> None:
    assert kinds("/// The bus.\nconnection bus: serial { baud 115_200  threading single at 20 Hz }  # fast") == [
        (String.Doc, "/// The bus."), (Keyword.Declaration, "connection"), (Name.Class, "bus"), (Punctuation, ":"),
        (Name, "serial"), (Punctuation, "{"), (Keyword, "baud"), (Number.Integer, "115_200"),
        (Keyword, "threading"), (Name, "single"), (Keyword, "at"), (Number.Integer, "20"), (Keyword.Pseudo, "Hz"),
        (Punctuation, "}"), (Comment.Single, "# fast")]
    assert kinds("const K = [0x1F, 0b101, 0o17, 2.5e-3, .5] if True else []") == [
        (Keyword.Declaration, "const"), (Name.Constant, "K"), (Operator, "="), (Punctuation, "["),
        (Number.Hex, "0x1F"), (Punctuation, ","), (Number.Bin, "0b101"), (Punctuation, ","), (Number.Oct, "0o17"),
        (Punctuation, ","), (Number.Float, "2.5e-3"), (Punctuation, ","), (Number.Float, ".5"), (Punctuation, "]"),
        (Keyword, "if"), (Keyword.Constant, "True"), (Keyword, "else"), (Punctuation, "["), (Punctuation, "]")]


def test_state_names_types_assignments_and_calls() -> None:
    assert kinds("state error: int[6] = [0] * 6") == [
        (Keyword.Declaration, "state"), (Name.Variable, "error"), (Punctuation, ":"), (Keyword.Type, "int"),
        (Punctuation, "["), (Number.Integer, "6"), (Punctuation, "]"), (Operator, "="), (Punctuation, "["),
        (Number.Integer, "0"), (Punctuation, "]"), (Operator, "*"), (Number.Integer, "6")]
    assert kinds("    error = hex(out[1]) and not x in 0..3") == [
        (Name.Variable, "error"), (Operator, "="), (Name.Builtin, "hex"), (Punctuation, "("), (Name, "out"),
        (Punctuation, "["), (Number.Integer, "1"), (Punctuation, "]"), (Punctuation, ")"), (Operator.Word, "and"),
        (Operator.Word, "not"), (Name, "x"), (Operator.Word, "in"), (Number.Integer, "0"), (Operator, ".."),
        (Number.Integer, "3")]


def test_strings_bytes_struct_codes_placeholders_and_regexes() -> None:
    assert kinds('primitive p(d: bytes) on bus pack "<B%H 3(Bh)" (b"\\x01", r"a\\d") unpack "B{1,7}"') == [
        (Keyword.Declaration, "primitive"), (Name.Function, "p"), (Punctuation, "("), (Name.Variable, "d"), (Punctuation, ":"),
        (Keyword.Type, "bytes"), (Punctuation, ")"), (Keyword, "on"), (Name, "bus"), (Keyword, "pack"),
        (String.Double, '"'), (Operator, "<"), (String.Interpol, "B"), (Operator, "%"), (String.Interpol, "H"),
        (Number.Integer, "3"), (Punctuation, "("), (String.Interpol, "B"), (String.Interpol, "h"), (Punctuation, ")"),
        (String.Double, '"'), (Punctuation, "("), (String.Affix, "b"), (String.Double, '"'),
        (String.Escape, "\\x01"), (String.Double, '"'), (Punctuation, ","), (String.Affix, "r"),
        (String.Double, '"'), (String.Double, "a"), (String.Double, "\\d"), (String.Double, '"'),
        (Punctuation, ")"), (Keyword, "unpack"), (String.Double, '"'), (String.Interpol, "B"), (Punctuation, "{"),
        (Number.Integer, "1"), (Punctuation, ","), (Number.Integer, "7"), (Punctuation, "}"), (String.Double, '"')]
    assert kinds('format "V{:03X}\\r" (v) regex r"^v(\\d+)$"') == [
        (Keyword, "format"), (String.Double, '"'), (String.Double, "V"), (String.Interpol, "{:03X}"),
        (String.Escape, "\\r"), (String.Double, '"'), (Punctuation, "("), (Name, "v"), (Punctuation, ")"),
        (Keyword, "regex"), (String.Regex, 'r"'), (String.Regex, "^v(") , (String.Regex, "\\d"),
        (String.Regex, "+)$"), (String.Regex, '"')]


def test_an_unterminated_string_ends_with_its_line() -> None:
    assert kinds('const S = "open\nconst T = 1') == [
        (Keyword.Declaration, "const"), (Name.Constant, "S"), (Operator, "="), (String.Double, '"'),
        (String.Double, "open"), (Keyword.Declaration, "const"), (Name.Constant, "T"), (Operator, "="),
        (Number.Integer, "1")]


# Pieces of RDIS and of what breaks it: unterminated strings and escapes, stray symbols, deep brackets.
_PIECES = st.sampled_from(['"', 'b"', 'r"', "\\", "\n", " ", "///", "#", "{", "}", "(", ")", "[", "]", ",", ":", "=",
                           "==", "..", "->", ".", "0x", "1.5e3", "_", "$", "@", "`", "é", "pack", "unpack", "format",
                           "regex", "field", "checksum", "state", "robot", "out", "True", "x", "<B%H", "{11*16}"])


@settings(max_examples=300, deadline=None)
@given(st.lists(_PIECES, max_size=40).map("".join))
def test_any_text_lexes_into_tokens_that_give_it_back(text: str) -> None:
    assert "".join(value for _, _, value in LEXER.get_tokens_unprocessed(text)) == text


def test_the_rdis_blocks_of_the_readme_and_the_docs_have_no_error_token() -> None:
    """What Sphinx or MkDocs colours: each ```rdis block of the README and docs/."""
    blocks = [block for doc in (ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")))
              for block in re.findall(r"```rdis[^\n]*\n(.*?)```", doc.read_text(encoding="utf-8"), re.DOTALL)]
    assert len(blocks) > 40
    assert [(block[:40], value) for block in blocks for _, kind, value in LEXER.get_tokens_unprocessed(block)
            if kind in Error] == []
