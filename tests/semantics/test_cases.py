"""Checker case files (tests/semantics/cases/*.rdis), starlark-go's testdata style.

A file holds one description, or several split by lines of `---` (chunks), each checked on
its own, all in this process. Each diagnostic a chunk must produce is written on its
offending line, at the end (`# E102 W101`: codes only) or, for one diagnostic with what it
says, as `# E403: exact message`, `# E403 ~ regex` (searched in the message), either with
` = help: exact help` after it. A line of its own starting `#^` holds one more expectation for
the nearest line above that is not one. A diagnostic with no place in the chunk (none, or in
another file) is written on the chunk's first line.

The produced (line, code) pairs, counted, must equal those written, so a missed fault and a
cascade of follow-on errors both fail; a message or help written must be what one diagnostic
of that code on that line says.
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import pytest

from rdisc.compile import compile_text
from rdisc.diagnostics.core import Diagnostic

CASES = sorted((Path(__file__).parent / "cases").glob("*.rdis"))

_CODE = r"[EW]\d{3}"
_COMMENT = re.compile(rf"#(?P<below>\^)?\s*(?={_CODE}\b)")
_CODES = re.compile(rf"{_CODE}(?:\s+{_CODE})*")
_ONE = re.compile(rf"(?P<code>{_CODE})(?:(?P<how>:|\s*~)\s*(?P<text>.*))?")
_HELP = " = help: "


@dataclass(frozen=True)
class Expected:
    line: int
    code: str
    exact: str | None = None  # the message, word for word
    pattern: str | None = None  # a regex the message matches
    help: str | None = None

    def says(self, d: Diagnostic) -> bool:
        if self.exact is not None and d.message != self.exact:
            return False
        if self.pattern is not None and not re.search(self.pattern, d.message):
            return False
        return self.help is None or d.help == self.help

    def __str__(self) -> str:
        said = f": {self.exact}" if self.exact is not None else f" ~ {self.pattern}" if self.pattern is not None else ""
        helped = f"{_HELP}{self.help}" if self.help is not None else ""
        return f"line {self.line}: {self.code}{said}{helped}"


@dataclass(frozen=True)
class Chunk:
    first: int  # 1-based line of the case file where the chunk starts
    last: int
    text: str  # the chunk after as many empty lines as precede it, so lines keep their numbers
    expected: tuple[Expected, ...]


def _expectations(number: int, body: str, where: str) -> list[Expected]:
    """The expectations of one comment's text (after the `#`)."""
    head, _, help_ = body.partition(_HELP)
    head = head.strip()
    if help_ == "" and _CODES.fullmatch(head):
        return [Expected(number, code) for code in head.split()]
    one = _ONE.fullmatch(head)
    if one is None:
        raise ValueError(f"{where}: cannot read the expectation `#{body}`")
    text = one["text"]
    exact = text if one["how"] == ":" else None
    pattern = text if one["how"] is not None and one["how"] != ":" else None
    return [Expected(number, one["code"], exact, pattern, help_ or None)]


def chunks(path: Path) -> list[Chunk]:
    """The chunks of a case file and what each must produce."""
    lines = path.read_text(encoding="utf-8").split("\n")
    found: list[Chunk] = []
    start = 0
    for end in [i for i, line in enumerate(lines) if line.strip() == "---"] + [len(lines)]:
        expected: list[Expected] = []
        target = start + 1
        for index in range(start, end):
            comment = _COMMENT.search(lines[index])
            if comment is None or (comment["below"] and lines[index][:comment.start()].strip()):
                if comment is None and lines[index].strip():
                    target = index + 1
                continue
            if not comment["below"]:
                target = index + 1
            where = f"{path.name}:{index + 1}"
            expected += _expectations(target, lines[index][comment.start() + 1:].lstrip("^"), where)
        text = "\n" * start + "\n".join(lines[start:end]) + ("\n" if end < len(lines) else "")
        found.append(Chunk(start + 1, end, text, tuple(expected)))
        start = end + 1
    return found


def produced(path: Path, chunk: Chunk) -> list[tuple[int, Diagnostic]]:
    """Each diagnostic of the chunk, with the line it is on."""
    compilation = compile_text(str(path), chunk.text)
    source = compilation.sources[str(path)]
    out = []
    for d in compilation.diagnostics.items:
        line = chunk.first
        if d.span is not None and d.span.path == str(path):
            line = min(max(source.position(d.span.start).line + 1, chunk.first), chunk.last)
        out.append((line, d))
    return out


def problems(path: Path, chunk: Chunk) -> list[str]:
    """What differs between what a chunk must produce and what it produces (nothing: it passes)."""
    made = produced(path, chunk)
    have = Counter((line, d.code) for line, d in made)
    want = Counter((e.line, e.code) for e in chunk.expected)
    out = [f"{path.name}:{line}: {code} expected, not produced" for line, code in sorted((want - have).elements())]
    out += [f"{path.name}:{line}: {d.code} produced, not expected: {d.message}" for line, d in made
            if (have - want)[line, d.code]]
    for e in chunk.expected:
        if (e.exact, e.pattern, e.help) != (None, None, None) and (e.line, e.code) in have \
                and not any(e.says(d) for line, d in made if (line, d.code) == (e.line, e.code)):
            said = [f"{d.message}" + (f"{_HELP}{d.help}" if d.help else "") for line, d in made
                    if (line, d.code) == (e.line, e.code)]
            out.append(f"{path.name}: expected {e}; it says {said}")
    return out


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_case_file(path: Path) -> None:
    found = [problem for chunk in chunks(path) for problem in problems(path, chunk)]
    assert not found, "\n".join(found)


FAULTY = """\
robot r { author "t" }
state unused: int = 0  # W103
---
robot r { author "t" }
connection link: serial { baud 0 }
#^ E204: the baud rate must be a positive integer, not 1
---
robot r { author "t" }
connection link: serial { baud 0 }  # E204 E204
state spare: int = 0
---
robot r { author "t" }
connection link: serial { baud 0 }  # E204 ~ ^the baud rate = help: none
"""


def test_what_a_case_file_may_get_wrong_is_each_said(tmp_path: Path) -> None:
    """A right chunk passes; a message, a count, a diagnostic not written and a help each fail,
    at their lines of the case file."""
    path = tmp_path / "faulty.rdis"
    path.write_text(FAULTY, encoding="utf-8")
    found = [problem for chunk in chunks(path) for problem in problems(path, chunk)]
    assert found == [
        ("faulty.rdis: expected line 5: E204: the baud rate must be a positive integer, not 1; it says "
         "['the baud rate must be a positive integer, not 0']"),
        "faulty.rdis:9: E204 expected, not produced",
        "faulty.rdis:10: W103 produced, not expected: state variable `spare` is never used",
        ("faulty.rdis: expected line 13: E204 ~ ^the baud rate = help: none; it says "
         "['the baud rate must be a positive integer, not 0']"),
    ]
