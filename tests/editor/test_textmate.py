"""The TextMate grammar (editors/vscode/syntaxes/rdis.tmLanguage.json) as VS Code runs it: every
example and the standard library tokenised once by vscode-textmate on vscode-oniguruma (npm,
tests/editor/package.json; `npm ci --prefix tests/editor`), and the scopes held to what rdisc's
parser reads (tests/editor/parsed_tokens.py) and to exact scopes at chosen places."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from tests.editor.parsed_tokens import FILES, ROOT, keyword_kinds, tokens

HERE = Path(__file__).resolve().parent
GRAMMAR = ROOT / "editors" / "vscode" / "syntaxes" / "rdis.tmLanguage.json"
ON_CI = os.environ.get("CI", "").lower() in ("1", "true", "yes")
KEYWORD_SCOPES = ("keyword.", "storage.type.rdis", "constant.language.")

Lines = list[list[tuple[int, int, list[str]]]]


@pytest.fixture(scope="module")
def scoped() -> dict[str, Lines]:
    """Each file's lines, each a list of (start, end, scopes), from one run of node."""
    node = shutil.which("node")
    missing = "node is not installed" if node is None else None
    if missing is None and not (HERE / "node_modules" / "vscode-textmate").is_dir():
        missing = "the npm packages are not installed: npm ci --prefix tests/editor"
    if missing is not None:
        if ON_CI:
            pytest.fail(missing, pytrace=False)
        pytest.skip(missing)
    done = subprocess.run([str(node), str(HERE / "tokenise.js"), str(GRAMMAR), *map(str, FILES)],
                          capture_output=True, text=True, encoding="utf-8", check=False, timeout=120)
    assert done.returncode == 0, done.stderr
    made: dict[str, Lines] = json.loads(done.stdout)
    return {Path(file).name: [[(s, e, scopes) for s, e, scopes in line] for line in lines]
            for file, lines in made.items()}


def scopes_at(scoped: dict[str, Lines], file: str, line: int, column: int) -> tuple[tuple[int, int], list[str]]:
    """The span and scopes (after source.rdis) of the TextMate token at a place (both from 1)."""
    for start, end, scopes in scoped[file][line - 1]:
        if start <= column - 1 < end:
            return (start + 1, end + 1), scopes[1:]
    raise AssertionError(f"{file}:{line}:{column} is past the line's tokens")


def find(file: str, line: int, text: str) -> int:
    """The column (from 1) of `text` on a line of an example, after checking it is there once."""
    found = FILES_TEXT[file][line - 1]
    assert found.count(text) == 1, (file, line, found)
    return found.index(text) + 1


FILES_TEXT = {f.name: f.read_text(encoding="utf-8").split("\n") for f in FILES}


def test_every_file_is_tokenised_line_by_line(scoped: dict[str, Lines]) -> None:
    assert sorted(scoped) == sorted(f.name for f in FILES)
    for file, lines in scoped.items():
        assert len(lines) == len(FILES_TEXT[file])
        for text, tokens_of_line in zip(FILES_TEXT[file], lines):
            assert (tokens_of_line[0][0], tokens_of_line[-1][1]) == (0, len(text)) or not text


def test_every_word_the_parser_reads_as_a_keyword_is_a_keyword(scoped: dict[str, Lines]) -> None:
    """Whole words, never part of a name: 2,500 keywords of the examples and the standard library."""
    kinds = keyword_kinds()
    seen = 0
    wrong = []
    for file in FILES:
        for token in tokens(file.read_text(encoding="utf-8")):
            if token.kind not in kinds:
                continue
            seen += 1
            span, scopes = scopes_at(scoped, file.name, token.line + 1, token.column + 1)
            if span != (token.column + 1, token.end + 1) or not any(s.startswith(KEYWORD_SCOPES) for s in scopes):
                wrong.append((file.name, token.line + 1, token.text, span, scopes))
    assert seen > 2000
    assert wrong == []


def test_numbers_strings_and_bytes_have_their_scopes_wherever_the_parser_reads_them(scoped: dict[str, Lines]) -> None:
    expected = {"INT": "constant.numeric.integer.", "FLOAT": "constant.numeric.float.rdis",
                "STRING": "string.", "RAW_STRING": "string.", "BYTES_STRING": "string.quoted.double.bytes.rdis"}
    counted = dict.fromkeys(expected, 0)
    wrong = []
    for file in FILES:
        for token in tokens(file.read_text(encoding="utf-8")):
            if token.kind not in expected:
                continue
            counted[token.kind] += 1
            for column in range(token.column + 1, token.end + 1):  # every character of it
                _, scopes = scopes_at(scoped, file.name, token.line + 1, column)
                if not any(s.startswith(expected[token.kind]) for s in scopes):
                    wrong.append((file.name, token.line + 1, token.text, column, scopes))
    assert wrong == []
    assert counted["INT"] > 1000 and counted["FLOAT"] > 100 and counted["STRING"] > 500
    assert counted["BYTES_STRING"] >= 3 and counted["RAW_STRING"] >= 10


def test_comment_lines_are_comments_and_doc_comments_documentation(scoped: dict[str, Lines]) -> None:
    lines = {"///": 0, "#": 0}
    for file, texts in FILES_TEXT.items():
        for number, text in enumerate(texts, 1):
            opening = text.lstrip()
            kind = "///" if opening.startswith("///") else "#" if opening.startswith("#") else None
            if kind is None:
                continue
            lines[kind] += 1
            scope = "comment.line.documentation.rdis" if kind == "///" else "comment.line.number-sign.rdis"
            for start, end, scopes in scoped[file][number - 1]:
                if end > len(text) - len(opening):
                    assert scope in scopes, (file, number, text[start:end], scopes)
    assert lines["///"] > 500 and lines["#"] > 200


def test_chosen_places_have_exact_scopes(scoped: dict[str, Lines]) -> None:
    def at(file: str, line: int, text: str, offset: int = 0) -> tuple[str, list[str]]:
        column = find(file, line, text) + offset
        (start, end), scopes = scopes_at(scoped, file, line, column)
        return FILES_TEXT[file][line - 1][start - 1:end - 1], scopes

    assert at("arm.rdis", 14, "robot") == ("robot", ["storage.type.rdis"])
    assert at("arm.rdis", 14, "arm") == ("arm", ["entity.name.type.robot.rdis"])
    assert at("arm.rdis", 19, "///") == ("///", ["comment.line.documentation.rdis",
                                                  "punctuation.definition.comment.rdis"])
    assert at("arm.rdis", 19, "Instructions") == (" Instructions of protocol 2.0.", ["comment.line.documentation.rdis"])
    first = "# A six-joint arm of Dynamixel X-series servos (XL430, XM430: protocol 2.0, ROBOTIS"
    assert at("arm.rdis", 1, "A six-joint") == (first, ["comment.line.number-sign.rdis"])
    assert at("arm.rdis", 24, "0x82") == ("0x82", ["constant.numeric.integer.hexadecimal.rdis"])
    assert at("arm.rdis", 33, "BROADCAST") == ("BROADCAST", ["entity.name.constant.const.rdis"])
    assert at("arm.rdis", 40, "3.141592653589793") == ("3.141592653589793", ["constant.numeric.float.rdis"])
    assert at("arm.rdis", 43, "present") == ("present", ["entity.name.variable.state.rdis"])
    assert at("arm.rdis", 43, "int") == ("int", ["support.type.rdis"])
    assert at("arm.rdis", 51, "Hz") == ("Hz", ["keyword.other.unit.rdis"])
    assert at("arm.rdis", 52, "True") == ("True", ["constant.language.boolean.rdis"])
    assert at("arm.rdis", 58, r"\xFD") == (r"\xFD", ["string.quoted.double.rdis", "constant.character.escape.rdis"])
    # a struct format: its byte order, its codes and their counts
    assert at("arm.rdis", 83, "pack") == ("pack", ["keyword.other.rdis"])
    assert at("arm.rdis", 83, "<BHH6(BI)") == ("<", ["string.quoted.double.struct.rdis",
                                                     "keyword.operator.byte-order.rdis"])
    assert at("arm.rdis", 83, "6(BI)") == ("6", ["string.quoted.double.struct.rdis",
                                                 "constant.numeric.integer.decimal.rdis"])
    assert at("arm.rdis", 83, "(BI)") == ("(", ["string.quoted.double.struct.rdis",
                                                "punctuation.section.group.struct.rdis"])
    assert at("arm.rdis", 83, "I)") == ("I", ["string.quoted.double.struct.rdis", "constant.character.format.struct.rdis"])
    assert at("arm.rdis", 100, "error") == ("error", ["variable.other.assignment.rdis"])  # a name here, not `error`
    assert at("arm.rdis", 100, "out") == ("out", [])  # the reply's values, a name where it is indexed
    assert at("arm.rdis", 122, "on: bool") == ("on", ["variable.parameter.rdis"])  # a parameter, not `on`
    assert at("arm.rdis", 122, ")") == (")", ["punctuation.section.parens.end.rdis"])
    assert at("arm.rdis", 123, "on bus") == ("on", ["keyword.other.rdis"])
    assert at("ax12.rdis", 339, "limit)") == (" limit", [])  # an argument alone is a name
    assert at("ax12.rdis", 339, ", limit)") == (",", ["punctuation.separator.comma.rdis"])
    assert at("arm.rdis", 99, "==") == ("==", ["keyword.operator.rdis"])
    assert at("arm.rdis", 125, "if") == ("if", ["keyword.control.rdis"])
    assert at("arm.rdis", 122, "..") == ("..", ["keyword.operator.range.rdis"])
    assert at("arm.rdis", 134, "clamp") == ("clamp", ["support.function.builtin.rdis"])
    assert at("arm.rdis", 160, "->") == ("->", ["keyword.operator.arrow.rdis"])
    # bytes literals, a format's placeholders, a regular expression, bit fields of a struct code
    assert at("slcan.rdis", 63, 'b"') == ("b", ["string.quoted.double.bytes.rdis", "storage.type.string.rdis"])
    assert at("slcan.rdis", 63, 'b"', 1) == ('"', ["string.quoted.double.bytes.rdis",
                                                   "punctuation.definition.string.begin.rdis"])
    assert at("slcan.rdis", 110, "{:03X}") == ("{:03X}", ["string.quoted.double.format.rdis",
                                                         "constant.other.placeholder.rdis"])
    assert at("slcan.rdis", 110, "hex") == ("hex", ["support.function.builtin.rdis"])
    assert at("koala.rdis", 85, r"\s") == (r"\s", ["string.regexp.rdis", "constant.character.escape.regexp.rdis"])
    assert at("crsf.rdis", 100, "{11*16}", 3) == ("*", ["string.quoted.double.struct.rdis", "keyword.operator.struct.rdis"])
    assert at("crsf.rdis", 100, "22s") == ("22", ["string.quoted.double.struct.rdis",
                                                 "constant.numeric.integer.decimal.rdis"])
