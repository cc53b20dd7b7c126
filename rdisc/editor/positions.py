"""LSP positions (0-based line, UTF-16 column) and ranges to and from character offsets."""

from __future__ import annotations

import bisect
import pathlib

from lsprotocol import types

from rdisc.source import SourceFile, Span


def offset(source: SourceFile, position: types.Position) -> int:
    """The character offset of an LSP position (a column past the line's end: its end)."""
    starts = source.line_starts()
    if position.line >= len(starts):
        return len(source.text)
    start = starts[position.line]
    end = starts[position.line + 1] - 1 if position.line + 1 < len(starts) else len(source.text)
    if source.text[start:end].isascii():
        return start + min(position.character, end - start)
    units, at = 0, start
    while at < end and units < position.character:
        units += 2 if ord(source.text[at]) > 0xFFFF else 1
        at += 1
    return at


def utf16_length(text: str) -> int:
    """How many UTF-16 code units `text` is (what LSP columns count), in time the C code takes."""
    return len(text) if text.isascii() else len(text.encode("utf-16-le", "surrogatepass")) // 2


def position(source: SourceFile, at: int) -> types.Position:
    """The LSP position of an offset (as `SourceFile.position`, without a Python loop over the line:
    a long line's many names are many positions)."""
    starts = source.line_starts()
    at = max(0, min(at, len(source.text)))
    line = bisect.bisect_right(starts, at) - 1
    return types.Position(line=line, character=utf16_length(source.text[starts[line] : at]))


def to_range(source: SourceFile, span: Span) -> types.Range:
    return types.Range(start=position(source, span.start), end=position(source, span.end))


def uri_of(path: str) -> str:
    return pathlib.Path(path).resolve().as_uri()


def path_of(uri: str) -> str:
    """The file a `file:` URI names (another scheme's URI, or one naming no path a file can have,
    a NUL in it, stands for itself, as a name)."""
    from pygls.uris import to_fs_path

    path = to_fs_path(uri) if uri.startswith("file:") else None
    return path if path and "\0" not in path else uri
