"""An indent-aware writer for generated source: emitters say what to write, the
writer decides how it is laid out.

Lines are written at the current depth (four spaces a level); `block()` opens a
level for the lines written inside it; `blank()` asks for blank lines between
definitions and collapses requests, so emitters never count newlines. The text
depends only on the calls made: no clock, no hashing, no platform newline.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

INDENT = "    "


class Writer:
    def __init__(self) -> None:
        self._lines: list[str] = []
        self._depth = 0
        self._blanks = 0  # blank lines requested before the next line

    def line(self, text: str = "") -> None:
        """One line at the current depth; an empty `text` is a blank line."""
        if not text:
            self.blank()
            return
        if self._lines and self._blanks:
            self._lines.extend([""] * self._blanks)
        self._blanks = 0
        for part in text.split("\n"):
            self._lines.append(INDENT * self._depth + part if part else "")

    def lines(self, texts: list[str] | tuple[str, ...]) -> None:
        for text in texts:
            self.line(text)

    def raw(self, text: str) -> None:
        """Lines written as they are, without indentation (the inside of a multi-line string)."""
        if self._lines and self._blanks:
            self._lines.extend([""] * self._blanks)
        self._blanks = 0
        self._lines.extend(text.split("\n"))

    def blank(self, count: int = 1) -> None:
        """At least `count` blank lines before the next line (none at the start of a block)."""
        self._blanks = max(self._blanks, count)

    @contextmanager
    def indented(self) -> Iterator[None]:
        self._depth += 1
        self._blanks = 0
        try:
            yield
        finally:
            self._depth -= 1

    @contextmanager
    def block(self, header: str) -> Iterator[None]:
        """`header` (ending in a colon), then the lines written inside, one level deeper."""
        self.line(header)
        with self.indented():
            yield

    def width(self, limit: int = 100) -> int:
        """Columns left on a line at the current depth, in a file of `limit` columns."""
        return limit - len(INDENT) * self._depth

    def text(self) -> str:
        """Everything written, with one newline at the end."""
        return "\n".join(self._lines).rstrip("\n") + "\n"
