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


def printable(text: str, keep: str = "") -> str:
    """`text` with every character that is not printable escaped as Python escapes it, so
    that nothing a description or a file name says can end a comment or a string early (a
    CR or LF would end a comment and start a statement); `keep` is kept as is. Every text
    that reaches generated code other than through `repr` goes through here."""
    out = []
    for ch in text:
        if ch.isprintable() or ch in keep:
            out.append(ch)
        elif ord(ch) <= 0xFF:
            out.append(f"\\x{ord(ch):02x}")
        elif ord(ch) <= 0xFFFF:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(f"\\U{ord(ch):08x}")
    return "".join(out)


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

    def comment(self, text: str) -> None:
        """`# text` on one line, whatever `text` holds (escaped by `printable`)."""
        self.line("# " + printable(text))

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
        """Everything written, with one newline at the end. A carriage return or a NUL in it is
        a bug of the emitter (Python would end a line or refuse the module there), never written."""
        text = "\n".join(self._lines).rstrip("\n") + "\n"
        if "\r" in text or "\x00" in text:
            raise ValueError("generated code would hold a carriage return or a NUL: text not escaped")
        return text
