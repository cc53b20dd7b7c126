"""Frames on the wire: the bytes a protocol puts around a payload, built for a
request and read back, checked and resynchronised, from a reply.

A frame is a sequence of parts: constant bytes (a header, a literal, a
terminator), fields computed from the frame's arguments, a length field, the
payload and checksums. Every part has a fixed size but the payload, so a reply
is read in at most four reads: the header (sliding over garbage until it
matches), the parts before the payload, the payload (its size from the length
field, from the decoding, or up to the constant that follows it) and the parts
after it.

This module needs nothing but the standard library: the runtime uses it, and
`rdisc emit-python` copies its text into every driver whose description has
frames, so that both read the same bytes the same way.
"""

from __future__ import annotations

import struct
from collections.abc import Sequence
from typing import Protocol

MAX_FRAME = 65536  # bytes of one frame; more is garbage, not a reply
MAX_SKIP = 4096  # bytes discarded while looking for a header


class FrameError(Exception):
    """A reply that is not the frame described; `timeout` when nothing at all came."""

    def __init__(self, message: str, timeout: bool = False) -> None:
        super().__init__(message)
        self.timeout = timeout


class Reader(Protocol):
    def read(self, size: int = 1, /) -> bytes: ...

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes: ...


def _reflect(value: int, width: int) -> int:
    result = 0
    for _ in range(width):
        result = (result << 1) | (value & 1)
        value >>= 1
    return result


class Checksum:
    """A sum, an XOR or a table-driven CRC over bytes, in `width` bits, then
    optionally inverted and masked."""

    __slots__ = ("_init", "_reflect_in", "_reflect_out", "_table", "_xorout", "inverted", "kind", "mask", "width")

    def __init__(self, kind: str, width: int, poly: int = 0, init: int = 0, reflect_in: bool = False,
                 reflect_out: bool = False, xorout: int = 0, inverted: bool = False, mask: int | None = None) -> None:
        self.kind = kind
        self.width = width
        self.inverted = inverted
        self.mask = mask
        self._reflect_in = reflect_in
        self._reflect_out = reflect_out
        self._xorout = xorout
        self._init = _reflect(init, width) if reflect_in else init
        self._table: tuple[int, ...] = _crc_table(width, poly, reflect_in) if kind == "crc" else ()

    def __call__(self, data: bytes) -> int:
        full = (1 << self.width) - 1
        if self.kind == "sum":
            value = sum(data) & full
        elif self.kind == "xor":
            value = 0
            for byte in data:
                value ^= byte
        else:
            value = self._crc(data)
        if self.inverted:
            value = ~value & full
        if self.mask is not None:
            value &= self.mask
        return value

    def _crc(self, data: bytes) -> int:
        table, width, reg = self._table, self.width, self._init
        full = (1 << width) - 1
        if self._reflect_in:
            for byte in data:
                reg = table[(reg ^ byte) & 0xFF] ^ (reg >> 8)
            if not self._reflect_out:
                reg = _reflect(reg, width)
        else:
            shift = width - 8
            for byte in data:
                reg = table[((reg >> shift) ^ byte) & 0xFF] ^ ((reg << 8) & full)
            if self._reflect_out:
                reg = _reflect(reg, width)
        return reg ^ self._xorout


def _crc_table(width: int, poly: int, reflected: bool) -> tuple[int, ...]:
    full = (1 << width) - 1
    table = []
    if reflected:
        rpoly = _reflect(poly, width)
        for byte in range(256):
            reg = byte
            for _ in range(8):
                reg = (reg >> 1) ^ rpoly if reg & 1 else reg >> 1
            table.append(reg)
    else:
        top = 1 << (width - 1)
        for byte in range(256):
            reg = byte << (width - 8)
            for _ in range(8):
                reg = ((reg << 1) ^ poly) & full if reg & top else (reg << 1) & full
            table.append(reg)
    return tuple(table)


class Input:
    """A port's input, with bytes put back: a reply frame found wrong gives back all
    but its first byte, so that the next header is looked for in them (a frame whose
    checksum failed may have swallowed the start of the next one)."""

    __slots__ = ("pending", "port")

    def __init__(self, port: Reader) -> None:
        self.port = port
        self.pending = bytearray()

    def put_back(self, data: bytes) -> None:
        self.pending[:0] = data

    def clear(self) -> None:
        self.pending.clear()

    def read(self, size: int = 1, /) -> bytes:
        if not self.pending:
            return self.port.read(size)
        taken = bytes(self.pending[:size])
        del self.pending[:size]
        return taken + self.port.read(size - len(taken)) if len(taken) < size else taken

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes:
        limit = MAX_FRAME if size is None else size
        if not self.pending:
            return self.port.read_until(expected, limit)
        found = self.pending.find(expected)
        end = min(found + len(expected) if found >= 0 else len(self.pending), limit)
        taken = bytearray(self.pending[:end])
        del self.pending[:end]
        while not taken.endswith(expected) and len(taken) < limit:  # the rest from the port, byte by byte
            byte = self.port.read(1)
            if not byte:
                break
            taken += byte
        return bytes(taken)


# ---- parts ------------------------------------------------------------------------------------


class Bytes:
    """Constant bytes: a header (the reader synchronises on it), a literal or a terminator."""

    __slots__ = ("data", "role")

    def __init__(self, role: str, data: bytes) -> None:
        self.role = role
        self.data = data


class Field:
    """The frame's `index`-th field value, packed with a one-integer struct format."""

    __slots__ = ("index", "name", "struct")

    def __init__(self, name: str, fmt: str, index: int) -> None:
        self.name = name
        self.struct = struct.Struct(fmt)
        self.index = index


class Length:
    """The payload's size plus `adjust`."""

    __slots__ = ("adjust", "struct")

    def __init__(self, fmt: str, adjust: int) -> None:
        self.struct = struct.Struct(fmt)
        self.adjust = adjust


class Payload:
    __slots__ = ()


class Check:
    """A checksum of the parts `first` to `last` (indexes into its side), packed
    with a struct format or written as upper-case hex digits (`fmt` None)."""

    __slots__ = ("checksum", "digits", "first", "last", "struct", "with_request")

    def __init__(self, checksum: Checksum, fmt: str | None, first: int, last: int,
                 with_request: bool = False) -> None:
        self.checksum = checksum
        self.struct = struct.Struct(fmt) if fmt is not None else None
        self.digits = (checksum.width + 3) // 4
        self.first = first
        self.last = last
        self.with_request = with_request

    def encode(self, value: int) -> bytes:
        if self.struct is not None:
            return self.struct.pack(value)
        return b"%0*X" % (self.digits, value)


Part = Bytes | Field | Length | Payload | Check


def _size(part: Part) -> int:
    """Bytes of a part other than the payload."""
    if isinstance(part, Bytes):
        return len(part.data)
    if isinstance(part, Check):
        return part.struct.size if part.struct is not None else part.digits
    if isinstance(part, (Field, Length)):
        return part.struct.size
    return 0


class Side:
    """The parts of one direction, with their sizes worked out once."""

    __slots__ = ("delimiter", "header", "length", "parts", "payload", "prefix", "sizes", "suffix")

    def __init__(self, parts: Sequence[Part]) -> None:
        self.parts = tuple(parts)
        self.sizes = tuple(_size(p) for p in self.parts)
        self.payload = next((i for i, p in enumerate(self.parts) if isinstance(p, Payload)), -1)
        first = self.parts[0] if self.parts else None
        self.header = first.data if isinstance(first, Bytes) and first.role == "header" else b""
        at = self.payload if self.payload >= 0 else len(self.parts)
        self.prefix = sum(self.sizes[:at]) - len(self.header)  # after the header, before the payload
        self.suffix = sum(self.sizes[at + 1 :]) if self.payload >= 0 else 0
        self.length = next((i for i, p in enumerate(self.parts) if isinstance(p, Length)), -1)
        after = self.parts[self.payload + 1] if 0 <= self.payload < len(self.parts) - 1 else None
        self.delimiter = after.data if isinstance(after, Bytes) else b""


class Stuffing:
    """Byte stuffing of a payload: `escape` inserted after every `reserved` sequence
    (so that the payload never shows the sequence a header starts with)."""

    __slots__ = ("escape", "reserved")

    def __init__(self, reserved: bytes, escape: bytes) -> None:
        self.reserved = reserved
        self.escape = escape

    def stuff(self, data: bytes) -> bytes:
        return data.replace(self.reserved, self.reserved + self.escape)

    def unstuff(self, data: bytes, name: str) -> bytes:
        out = bytearray()
        start = 0
        while (found := data.find(self.reserved, start)) >= 0:
            after = found + len(self.reserved)
            if data[after : after + len(self.escape)] != self.escape:
                raise FrameError(f"{name}: {self.reserved!r} in the payload is not followed by {self.escape!r}")
            out += data[start:after]
            start = after + len(self.escape)
        out += data[start:]
        return bytes(out)


class Frame:
    """A request side and a reply side (empty when the device answers nothing framed)."""

    __slots__ = ("name", "reply", "request", "stuffing")

    def __init__(self, name: str, request: Sequence[Part], reply: Sequence[Part],
                 stuffing: Stuffing | None = None) -> None:
        self.name = name
        self.request = Side(request)
        self.reply = Side(reply)
        self.stuffing = stuffing

    def wrap(self, payload: bytes, fields: Sequence[int]) -> bytes:
        """The request: `payload` framed (stuffed first, when the frame stuffs), with the
        frame's field values."""
        if self.stuffing is not None:
            payload = self.stuffing.stuff(payload)
        side = self.request
        chunks: list[bytes] = []
        for part in side.parts:
            if isinstance(part, Bytes):
                chunks.append(part.data)
            elif isinstance(part, Field):
                chunks.append(part.struct.pack(fields[part.index]))
            elif isinstance(part, Length):
                chunks.append(part.struct.pack(len(payload) + part.adjust))
            elif isinstance(part, Payload):
                chunks.append(payload)
            else:
                chunks.append(part.encode(part.checksum(b"".join(chunks[part.first : part.last + 1]))))
        return b"".join(chunks)

    def read(self, port: Reader, fields: Sequence[int], request: bytes, size: int) -> tuple[bytes, bytes]:
        """Read one reply frame from `port`; (the bytes read, the payload).

        `size` is the payload's size when the decoding fixes it, else -1. Bytes
        before the header are skipped; every constant, field and checksum is
        checked. FrameError says what is wrong.
        """
        data = bytearray()
        try:
            return self._read(port, data, fields, request, size)
        except FrameError:
            if len(data) > 1 and isinstance(port, Input):  # look for the next header in what was taken
                port.put_back(bytes(data[1:]))
            raise

    def _read(self, port: Reader, data: bytearray, fields: Sequence[int], request: bytes,
              size: int) -> tuple[bytes, bytes]:
        side = self.reply
        data += self._sync(port, side.header) if side.header else b""
        self._take(port, data, side.prefix, bool(data))
        if side.payload < 0:
            return self._check(side, bytes(data), 0, fields, request), b""
        if side.length >= 0:
            at = sum(side.sizes[: side.length])
            length = side.parts[side.length]
            assert isinstance(length, Length)
            size = length.struct.unpack_from(data, at)[0] - length.adjust
            if not 0 <= size <= MAX_FRAME:
                raise FrameError(f"{self.name}: length field says {size + length.adjust}, which no payload fits")
        if size >= 0:
            self._take(port, data, size + side.suffix, bool(data))
        else:
            found = port.read_until(side.delimiter, MAX_FRAME)
            started = bool(data or found)
            data += found
            if not found.endswith(side.delimiter):
                raise FrameError(f"{self.name}: reply not delimited by {side.delimiter!r}: {bytes(data)!r}",
                                 timeout=not started)
            size = len(found) - len(side.delimiter)
            self._take(port, data, side.suffix - len(side.delimiter), True)
        raw = bytes(data)
        return raw, self._check(side, raw, size, fields, request)

    def _sync(self, port: Reader, header: bytes) -> bytes:
        window = bytearray(port.read(len(header)))
        if not window:
            raise FrameError(f"{self.name}: no reply", timeout=True)
        skipped = 0
        while window != header:
            byte = port.read(1) if len(window) == len(header) else b""
            if not byte:
                raise FrameError(f"{self.name}: no header {header!r} in the reply (after {skipped} bytes)")
            del window[0]
            window += byte
            skipped += 1
            if skipped > MAX_SKIP:
                raise FrameError(f"{self.name}: no header {header!r} in {MAX_SKIP} bytes")
        return bytes(window)

    def _take(self, port: Reader, data: bytearray, size: int, started: bool) -> None:
        if size <= 0:
            return
        got = port.read(size)
        data += got
        if len(got) < size:
            if not started and not got:
                raise FrameError(f"{self.name}: no reply", timeout=True)
            raise FrameError(f"{self.name}: short reply, {len(data)} bytes: {bytes(data)!r}")

    def _check(self, side: Side, raw: bytes, size: int, fields: Sequence[int], request: bytes) -> bytes:
        """Every constant, field and checksum of a complete reply; its payload."""
        starts: list[int] = []
        at = 0
        for i, part_size in enumerate(side.sizes):
            starts.append(at)
            at += size if i == side.payload else part_size
        starts.append(at)
        for i, part in enumerate(side.parts):
            chunk = raw[starts[i] : starts[i + 1]]
            if isinstance(part, Bytes):
                if chunk != part.data:
                    raise FrameError(f"{self.name}: expected {part.data!r} as the {part.role}, got {chunk!r}")
            elif isinstance(part, Field):
                value = part.struct.unpack(chunk)[0]
                if value != fields[part.index]:
                    raise FrameError(f"{self.name}: reply {part.name} is {value}, expected {fields[part.index]}")
            elif isinstance(part, Check):
                covered = raw[starts[part.first] : starts[part.last + 1]]
                expected = part.encode(part.checksum(request + covered if part.with_request else covered))
                if (chunk if part.struct is not None else chunk.upper()) != expected:
                    raise FrameError(f"{self.name}: checksum {chunk!r} does not match the reply, "
                                     f"which sums to {expected!r}")
        if side.payload < 0:
            return b""
        payload = raw[starts[side.payload] : starts[side.payload + 1]]
        return self.stuffing.unstuff(payload, self.name) if self.stuffing is not None else payload
