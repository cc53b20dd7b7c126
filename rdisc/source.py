"""Source files and spans.

A span stores byte-free character offsets only; lines and columns are computed
when a diagnostic is rendered, so building spans costs nothing on the hot path.
"""

from __future__ import annotations

import bisect
import os
import posixpath
from collections.abc import Mapping

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.source_methods import dataclass

from rdisc.frozen import Frozen


@dataclass(frozen=True, slots=True)
class Span(metaclass=Frozen):
    """A half-open range of character offsets in one source file."""

    path: str
    start: int
    end: int

    def to(self, other: Span) -> Span:
        """The span covering this one and `other` (same file)."""
        return Span(self.path, min(self.start, other.start), max(self.end, other.end))


@dataclass(frozen=True, slots=True)
class Position(metaclass=Frozen):
    line: int  # 0-based
    column: int  # 0-based, in code points
    utf16_column: int  # 0-based, in UTF-16 code units (what LSP counts)


class SourceFile:
    """One file's text, and where its lines start (found when first asked)."""

    __slots__ = ("_line_starts", "path", "text")

    def __init__(self, path: str, text: str) -> None:
        self.path = path
        self.text = text
        self._line_starts: list[int] = []

    def line_starts(self) -> list[int]:
        if not self._line_starts:
            starts = [0]
            find = self.text.find
            i = find("\n")
            while i != -1:
                starts.append(i + 1)
                i = find("\n", i + 1)
            self._line_starts = starts
        return self._line_starts

    def position(self, offset: int) -> Position:
        offset = max(0, min(offset, len(self.text)))
        starts = self.line_starts()
        line = bisect.bisect_right(starts, offset) - 1
        prefix = self.text[starts[line] : offset]
        # Counted by C code, not a loop over the line: a long line's many diagnostics are many positions.
        utf16 = len(prefix) if prefix.isascii() else len(prefix.encode("utf-16-le", "surrogatepass")) // 2
        return Position(line, len(prefix), utf16)

    def line_text(self, line: int) -> str:
        starts = self.line_starts()
        start = starts[line]
        end = starts[line + 1] - 1 if line + 1 < len(starts) else len(self.text)
        return self.text[start:end].rstrip("\r")


class Sources(dict[str, SourceFile]):
    """Every file read during one run, by path, for rendering diagnostics."""

    def add(self, path: str, text: str) -> SourceFile:
        source = SourceFile(path, text)
        self[path] = source
        return source


def place(span: Span | None, sources: Mapping[str, SourceFile], main_path: str | None, main_name: str) -> str | None:
    """`file:line` of a span, as generated files cite their description: the main file by the
    name it was given, another by its path relative to the main file's folder (or its name,
    when it is elsewhere)."""
    if span is None or span.path not in sources:
        return None
    line = sources[span.path].position(span.start).line + 1
    if span.path == main_path:
        return f"{main_name}:{line}"
    name = posixpath.basename(span.path.replace(os.sep, "/"))
    if main_path is not None:
        relative = os.path.relpath(span.path, os.path.dirname(main_path) or ".").replace(os.sep, "/")
        if not relative.startswith("../"):
            name = relative
    return f"{name}:{line}"
