"""Captured serial traffic read into messages, for `rdisc decode`: hex lines, a pyserial `spy://`
hex dump, or an rdisc recording (MCAP). Input is bounded (MAX_TEXT characters, MAX_LINE a line);
what cannot be read is a CaptureError, said in a line.

Hex lines: one message a line, `>` (host to device) or `<` (device to host), then its bytes as
hex, spaces optional (`> 89 00 c8 7f ff`, `<01`); an optional connection name before the marker
(`bus > ff ff 01 02 01 fb`); blank lines and `#` comments are skipped.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import IO

MAX_TEXT = 16 * 2**20
"""The characters a capture of text may hold."""
MAX_LINE = 64 * 2**10
"""The characters a line of it may hold."""
MAX_MESSAGES = 100_000
"""The messages a capture may hold: each is held against every primitive (about 0.3 ms each for
the AX-12's 38), so that a decode ends within a minute."""

_SPY = re.compile(r"\d+\.\d{3} (TX|RX)\s+([0-9A-F]{4})  ")


class CaptureError(Exception):
    """A capture that cannot be read; the message says where and why."""


@dataclass(frozen=True, slots=True)
class Message:
    """Bytes that crossed the wire at once, one way: `write` host to device, else device to host."""

    write: bool
    data: bytes
    connection: str | None = None


def read_text(stream: IO[str], name: str) -> list[Message]:
    """Hex lines or a spy log (known by its first line of traffic), within the bounds."""
    text = stream.read(MAX_TEXT + 1)
    if len(text) > MAX_TEXT:
        raise CaptureError(f"{name}: more than {MAX_TEXT // 2**20} MiB of text")
    lines = text.splitlines()
    for number, line in enumerate(lines, 1):
        if len(line) > MAX_LINE:
            raise CaptureError(f"{name}:{number}: a line of {len(line)} characters, more than {MAX_LINE}")
    if any(_SPY.match(line) for line in lines):
        return _counted(_spy(lines, name), name)
    return _counted([m for number, line in enumerate(lines, 1)
                     if (m := _hex_line(line, f"{name}:{number}")) is not None], name)


def _counted(messages: list[Message], name: str) -> list[Message]:
    if len(messages) > MAX_MESSAGES:
        raise CaptureError(f"{name}: {len(messages)} messages, more than {MAX_MESSAGES}")
    return messages


def _hex_line(line: str, where: str) -> Message | None:
    words = line.split("#", 1)[0].strip()
    if not words:
        return None
    connection, marker, data = None, words[:1], words[1:]
    if marker not in "<>":
        connection, _, rest = words.partition(" ")
        marker, data = rest.strip()[:1], rest.strip()[1:]
    if marker not in ("<", ">") or not marker:
        raise CaptureError(f"{where}: a message starts with > (host to device) or < (device to host): "
                           f"{_cut(words)}")
    digits = "".join(data.split())
    try:
        return Message(marker == ">", bytes.fromhex(digits), connection)
    except ValueError:
        raise CaptureError(f"{where}: not hex bytes (two digits a byte): {_cut(data.strip())}") from None


def _spy(lines: list[str], name: str) -> list[Message]:
    """pyserial's `spy://` hex dump (FormatHexdump): `TX`/`RX` rows of 16 bytes, a message's
    rows numbered on from 0000; control lines (`RTS`, `Q-RX`...) are skipped."""
    messages: list[Message] = []
    for number, line in enumerate(lines, 1):
        found = _SPY.match(line)
        if found is None:
            continue
        write, offset = found.group(1) == "TX", int(found.group(2), 16)
        cells = line[found.end() : found.end() + 49]  # 16 bytes, a space after each and after the 8th
        try:
            data = bytes.fromhex(cells)
        except ValueError:
            raise CaptureError(f"{name}:{number}: not a row of pyserial's hex dump: {_cut(line)}") from None
        if offset and messages and messages[-1].write == write:
            messages[-1] = Message(write, messages[-1].data + data)
        else:
            messages.append(Message(write, data))
    return messages


def read_recording(path: str) -> list[Message]:
    """An rdisc recording's bytes (`/rdisc/CONN/write` and `/read`), each connection's in order,
    read by the replay's bounded reader."""
    from rdisc.recordings import RecordingError
    from rdisc.recordings import read_recording as read

    try:
        recording = read(path)
    except RecordingError as err:
        raise CaptureError(f"{path}: {err}") from None
    return _counted([Message(write, data, connection)
                     for connection, exchanges in recording.exchanges.items()
                     for written, reply in exchanges
                     for write, data in ((True, written), (False, reply)) if data], path)


def _cut(text: str) -> str:
    return repr(text) if len(text) <= 40 else f"{text[:30]!r}... ({len(text)} characters)"
