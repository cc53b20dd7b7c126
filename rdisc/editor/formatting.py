"""Formatting (whole document and range) through `rdisc.format.format_text`, as the fewest edits.

Why edits by a line diff, not one edit replacing the text: an editor keeps the cursor, the
selection and the undo history of every line an edit does not touch, so only the lines the
formatter changes are replaced. A document that does not parse gets no edits (an empty answer,
not an error: formatting on save must not pop up a message while the user is typing).
"""

from __future__ import annotations

import difflib

from lsprotocol import types

from rdisc.editor import positions
from rdisc.format import FormatError, declarations, format_text
from rdisc.source import SourceFile


def format_document(path: str, text: str) -> list[types.TextEdit]:
    """The edits turning `text` into `rdisc fmt`'s text of it."""
    return _edits(path, text, 0, SourceFile(path, text))


def format_range(path: str, text: str, where: types.Range) -> list[types.TextEdit]:
    """The edits formatting the declarations `where` touches, none outside their lines: those lines
    (with any other declaration sharing them) are formatted as a text of their own, as each
    declaration stands on its own in the grammar."""
    source = SourceFile(path, text)
    first, last = positions.offset(source, where.start), positions.offset(source, where.end)
    spans = [(positions.position(source, start).line, positions.position(source, end).line)
             for start, end in declarations(text) if start <= last and first <= end]
    if not spans:
        return []
    top, bottom = spans[0][0], spans[-1][1]
    for start, end in declarations(text):  # a declaration sharing a line with them joins them
        start_line, end_line = positions.position(source, start).line, positions.position(source, end).line
        if start_line <= bottom and top <= end_line:
            top, bottom = min(top, start_line), max(bottom, end_line)
    lines = text.splitlines(keepends=True)
    return _edits(path, "".join(lines[top : bottom + 1]), top, source)


def _edits(path: str, text: str, top: int, source: SourceFile) -> list[types.TextEdit]:
    """Each changed run of lines of `text` as an edit; `text` is the whole lines of `source` from
    line `top` on."""
    try:
        formatted = format_text(text, path)
    except FormatError:
        return []
    old, new = text.splitlines(keepends=True), formatted.splitlines(keepends=True)
    starts = source.line_starts()

    def start_of(line: int) -> types.Position:
        return positions.position(source, starts[line] if line < len(starts) else len(source.text))

    found = []
    for tag, old_first, old_end, new_first, new_end in difflib.SequenceMatcher(
            None, old, new, autojunk=False).get_opcodes():
        if tag != "equal":
            place = types.Range(start=start_of(top + old_first), end=start_of(top + old_end))
            found.append(types.TextEdit(range=place, new_text="".join(new[new_first:new_end])))
    return found
