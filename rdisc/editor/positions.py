"""LSP positions (0-based line, UTF-16 column) and ranges to and from character offsets."""

from __future__ import annotations

import pathlib
from urllib.parse import unquote, urlparse

from lsprotocol import types

from rdisc.source import SourceFile, Span


def offset(source: SourceFile, position: types.Position) -> int:
    """The character offset of an LSP position (a column past the line's end: its end)."""
    starts = source.line_starts()
    if position.line >= len(starts):
        return len(source.text)
    start = starts[position.line]
    end = starts[position.line + 1] - 1 if position.line + 1 < len(starts) else len(source.text)
    units, at = 0, start
    while at < end and units < position.character:
        units += 2 if ord(source.text[at]) > 0xFFFF else 1
        at += 1
    return at


def position(source: SourceFile, at: int) -> types.Position:
    place = source.position(at)
    return types.Position(line=place.line, character=place.utf16_column)


def to_range(source: SourceFile, span: Span) -> types.Range:
    return types.Range(start=position(source, span.start), end=position(source, span.end))


def uri_of(path: str) -> str:
    return pathlib.Path(path).resolve().as_uri()


def path_of(uri: str) -> str:
    """The file a `file:` URI names (another scheme's URI stands for itself, as a name)."""
    parsed = urlparse(uri)
    if parsed.scheme != "file":
        return uri
    return str(pathlib.Path(unquote(parsed.path)))
