"""Bytes and values of one primitive: encoding its request, decoding its reply.

A `Codec` is built once per primitive, with its `struct.Struct` and compiled
regular expression ready, so a call does no parsing. It does no I/O: the device
layer writes what `encode` gives and hands the reply to `decode` or `match`.
"""

from __future__ import annotations

import re
import struct
from collections.abc import Callable

from rdisc.runtime import framing
from rdisc.runtime.errors import RdisProtocolError, RdisValueError
from rdisc.semantics import formats
from rdisc.semantics import model as m

MAX_LINE = 4096  # bytes of one reply line, terminator included (the runtime contract)

__all__ = ["MAX_LINE", "Codec", "frame_fields", "wire_frame"]


def wire_frame(frame: m.Frame) -> framing.Frame:
    """The Model's frame as the framing module reads and writes it."""
    fields = {name: i for i, name in enumerate(frame_fields(frame))}
    stuffing = None
    if frame.stuffing is not None:
        reserved, escape = frame.stuffing
        stuffing = framing.Stuffing(reserved.encode("latin-1"), escape.encode("latin-1"))
    return framing.Frame(frame.name, [_part(p, fields) for p in frame.request], [_part(p, fields) for p in frame.reply],
                         stuffing)


def frame_fields(frame: m.Frame) -> dict[str, m.Expr]:
    """The frame's fields by name, in the order their values are passed (first appearance)."""
    fields: dict[str, m.Expr] = {}
    for part in frame.request + frame.reply:
        if isinstance(part, m.FrameField):
            fields.setdefault(part.name, part.value)
    return fields


def checksum(a: m.ChecksumAlgorithm) -> framing.Checksum:
    return framing.Checksum(a.kind, a.width, a.poly, a.init, a.reflect_in, a.reflect_out, a.xorout, a.inverted, a.mask)


def _part(part: m.FramePart, fields: dict[str, int]) -> framing.Part:
    match part:
        case m.FrameBytes(role=role, data=data):
            return framing.Bytes(role, data.encode("latin-1"))
        case m.FrameField(name=name, format=fmt):
            return framing.Field(name, fmt, fields[name])
        case m.FrameLength(format=fmt, adjust=adjust):
            return framing.Length(fmt, adjust)
        case m.FramePayload():
            return framing.Payload()
        case m.FrameChecksum():
            return framing.Check(checksum(part.algorithm), part.format, part.first, part.last, part.with_request)
    raise AssertionError(part)


class Codec:
    """How one primitive's request is written and its reply read.

    `encode(*values)` gives the request bytes; a value the encoding refuses
    raises RdisValueError, or `struct.error` from the fast path of a plain
    `pack` (the caller turns that into RdisValueError with `refused`).
    """

    __slots__ = (
        "_pack",
        "_regex",
        "_rest",
        "_strings",
        "_template",
        "_unpack",
        "_unpack_strings",
        "encode",
        "expects_reply",
        "name",
        "pattern",
        "reads_line",
        "reply_size",
        "terminator",
    )

    def __init__(self, primitive: m.Primitive, terminator: bytes = b"\n") -> None:
        self.name = primitive.name
        self.terminator = terminator  # ends a reply line (its connection's)
        self._pack: struct.Struct | None = None
        self._strings: tuple[int, ...] = ()  # indexes of values packed as bytes
        self._rest = False  # the request ends in `*`: its last value is bytes, appended as it is
        self._template: str | None = None
        self.encode: Callable[..., bytes]
        match primitive.encoding:
            case m.Pack(format=fmt):
                layout = formats.struct_layout(fmt)
                self._pack = struct.Struct(layout.fixed)
                self._strings = _string_slots(fmt)
                self.encode = self._pack.pack if not self._strings and not layout.rest else self._pack_strings
                self._rest = layout.rest
            case m.Format(template=template):
                self._template = template
                self.encode = self._format
        self.reply_size = 0  # bytes of an `unpack` reply (-1: it ends in `*`); 0 when there is none
        self._unpack: struct.Struct | None = None
        self._unpack_strings: tuple[int, ...] = ()
        self.pattern: str | None = None
        self._regex: re.Pattern[str] | None = None
        match primitive.decoding:
            case m.Unpack(format=fmt):
                layout = formats.struct_layout(fmt)
                self._unpack = struct.Struct(layout.fixed)
                self._unpack_strings = _string_slots(fmt)
                self.reply_size = -1 if layout.rest else self._unpack.size
            case m.Regex(pattern=pattern):
                self.pattern = pattern
                self._regex = re.compile(pattern)
        self.reads_line = self._regex is not None
        self.expects_reply = self._unpack is not None or self._regex is not None

    def refused(self, err: Exception) -> RdisValueError:
        """The error for a value `encode` refused."""
        return RdisValueError(f"{self.name}: {err}")

    def _pack_strings(self, *values: m.Value) -> bytes:
        packed: list[object] = list(values[:-1] if self._rest else values)
        for i in self._strings:
            packed[i] = _latin1(self.name, packed[i])
        assert self._pack is not None
        try:
            fixed = self._pack.pack(*packed)
        except struct.error as err:
            raise self.refused(err) from None
        return fixed + values[-1] if self._rest else fixed  # type: ignore[operator]

    def _format(self, *values: m.Value) -> bytes:
        assert self._template is not None
        try:
            text = self._template.format(*values)
        except (ValueError, TypeError) as err:
            raise self.refused(err) from None
        return _latin1(self.name, text)

    def decode(self, data: bytes) -> tuple[m.Value, ...]:
        """The values of an `unpack` reply; fewer bytes than its size is RdisProtocolError."""
        assert self._unpack is not None
        if self.reply_size < 0:  # a fixed part, then the rest as bytes
            if len(data) < self._unpack.size:
                raise RdisProtocolError(f"{self.name}: expected {self._unpack.size} bytes or more, got {len(data)}")
            values = (*self._unpack.unpack_from(data), data[self._unpack.size :])
        elif len(data) != self.reply_size:
            raise RdisProtocolError(f"{self.name}: expected {self.reply_size} bytes, got {len(data)}")
        else:
            values = self._unpack.unpack(data)
        if self._unpack_strings:
            decoded = list(values)
            for i in self._unpack_strings:
                decoded[i] = decoded[i].decode("latin-1")
            return tuple(decoded)
        return values

    def match_payload(self, payload: bytes) -> tuple[m.Value, ...]:
        """The groups of a framed text payload (no terminator); unmatched is RdisProtocolError."""
        assert self._regex is not None
        decoded = payload.decode("latin-1")
        found = self._regex.match(decoded)
        if found is None:
            raise RdisProtocolError(f"{self.name}: reply {decoded!r} does not match {self.pattern!r}")
        return found.groups("")

    def match(self, line: bytes) -> tuple[m.Value, ...]:
        """The groups of a reply line (terminator included); unterminated or unmatched is RdisProtocolError."""
        assert self._regex is not None
        end = self.terminator
        if not line.endswith(end):
            raise RdisProtocolError(f"{self.name}: reply line not terminated: {line.decode('latin-1')!r}")
        text = line[: -len(end)]
        if end == b"\n" and text.endswith(b"\r"):  # the default takes CR LF as well as LF
            text = text[:-1]
        decoded = text.decode("latin-1")
        found = self._regex.match(decoded)
        if found is None:
            raise RdisProtocolError(f"{self.name}: reply {decoded!r} does not match {self.pattern!r}")
        return found.groups("")


def _latin1(name: str, text: object) -> bytes:
    if isinstance(text, bytes):
        return text
    try:
        return str(text).encode("latin-1")
    except UnicodeEncodeError as err:
        raise RdisValueError(f"{name}: {err.object[err.start:err.end]!r} is not a latin-1 character") from None


def _string_slots(fmt: str) -> tuple[int, ...]:
    """Indexes of the values a struct format packs or unpacks as bytes (`s`, `p`, `c`)."""
    slots = formats.struct_layout(fmt).slots
    return tuple(i for i, slot in enumerate(slots) if slot.type is m.Type.STRING)
