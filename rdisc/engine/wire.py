"""Bytes on the wire: a port's input as an exchange reads it (one deadline for a whole reply,
bytes put back to look for the next header in), and the parts a frame's side is made of, each
part's size worked out once.
"""

from __future__ import annotations

import math
import struct
import time
from collections.abc import Sequence
from typing import Literal, Protocol

from rdisc.engine.checksums import Checksum

# A frame is a sequence of parts: constant bytes (a header, a literal, a
# terminator), fields computed from the frame's arguments, a length field, the
# payload and checksums. Every part has a fixed size but the payload, so a reply
# is read in at most four reads: the header (sliding over garbage until it
# matches), the parts before the payload, the payload (its size from the length
# field, from the decoding, or up to the constant that follows it) and the parts
# after it.

MAX_FRAME = 65536  # bytes of one frame; more is garbage, not a reply
MAX_SKIP = 4096  # bytes discarded while looking for a header


class FrameError(Exception):
    """A reply that is not the frame described; `timeout` when nothing at all came."""

    def __init__(self, message: str, timeout: bool = False) -> None:
        super().__init__(message)
        self.timeout = timeout


class ChecksumError(FrameError):
    """A reply frame whose constants and fields are right but whose checksum is wrong: this
    device's reply, corrupted. An error even under `skip unmatched`, as drivers report it."""


class MissingSeed(ValueError):
    """A frame field's value that its checksum's seed table lacks (known only at run time): a
    request that cannot be framed, or a reply of a message this description does not know."""


class Reader(Protocol):
    timeout: float | None

    def read(self, size: int = 1, /) -> bytes: ...

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes: ...


class Incoming:
    """A port's input as an exchange reads it: bytes put back, every byte taken from
    the port kept for the I/O callbacks, and one deadline for the whole reply.

    A reply frame found wrong gives back all but its first byte, so that the next
    header is looked for in them (a frame whose checksum failed may have swallowed
    the start of the next one). The first read of an exchange waits the port's own
    timeout, which is the whole deadline; a later one waits only what is left of it.
    """

    __slots__ = ("deadline", "pending", "port", "reads", "shortened", "taken", "timeout")

    def __init__(self, port: Reader) -> None:
        self.port = port
        self.pending = bytearray()
        self.taken = bytearray()  # what the port gave during this exchange
        self.deadline: float | None = None  # None: reads wait as the port does
        self.shortened = False  # a read shortened the port's timeout: `timeout` is restored
        self.timeout: float | None = None
        self.reads = 0

    def begin(self, wait: float) -> None:
        """Start an exchange that may wait `wait` seconds for its whole reply."""
        self.reads = 0
        self.deadline = time.monotonic() + wait

    def end(self) -> bytes:
        """Finish an exchange: the port's timeout as it was; the bytes it gave."""
        self.deadline = None
        if self.shortened:
            self.shortened = False
            try:
                self.port.timeout = self.timeout
            except Exception:  # noqa: BLE001, S110 - a port gone mid-reply: its read's failure is the one to tell
                pass
        taken = bytes(self.taken)
        self.taken.clear()  # an exchange that fails before it reads shows nothing of an earlier one
        return taken

    def put_back(self, data: bytes) -> None:
        self.pending[:0] = data

    def clear(self) -> None:
        self.pending.clear()

    def _wait(self) -> bool:
        """Before a read from the port: whether time is left, the port told how much."""
        self.reads += 1
        if self.reads == 1 or self.deadline is None:
            return True
        left = self.deadline - time.monotonic()
        if left <= 0:
            return False
        if not self.shortened:
            self.timeout = getattr(self.port, "timeout", None)
            self.shortened = True
        self.port.timeout = left
        return True

    def _port_read(self, size: int) -> bytes:
        if size <= 0 or not self._wait():
            return b""
        got = self.port.read(size)
        self.taken += got
        return got

    def read(self, size: int = 1, /) -> bytes:
        if not self.pending:
            return self._port_read(size)
        taken = bytes(self.pending[:size])
        del self.pending[:size]
        return taken + self._port_read(size - len(taken)) if len(taken) < size else taken

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes:
        limit = MAX_FRAME if size is None else size
        if not self.pending:
            if not self._wait():
                return b""
            got = self.port.read_until(expected, limit)
            self.taken += got
            return got
        found = self.pending.find(expected)
        end = min(found + len(expected) if found >= 0 else len(self.pending), limit)
        taken = bytearray(self.pending[:end])
        del self.pending[:end]
        while not taken.endswith(expected) and len(taken) < limit:  # the rest from the port, byte by byte
            byte = self._port_read(1)
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

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        """This part's bytes in a request, after `chunks` (the parts before it)."""
        return self.data


class Field:
    """The frame's `index`-th field value, packed as one integer: its struct `code` in byte `order`."""

    __slots__ = ("code", "index", "name", "order", "struct")

    def __init__(self, name: str, order: str, code: str, index: int) -> None:
        self.name = name
        self.order = order
        self.code = code
        self.struct = struct.Struct(order + code)
        self.index = index

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return self.struct.pack(fields[self.index])


class Length:
    """The payload's size plus `adjust`, packed as one integer: its struct `code` in byte
    `order`, `high` the largest value the code holds; `most`, the largest size it states."""

    __slots__ = ("adjust", "code", "most", "order", "struct")

    def __init__(self, order: str, code: str, adjust: int, high: int) -> None:
        self.order = order
        self.code = code
        self.struct = struct.Struct(order + code)
        self.adjust = adjust
        self.most = high - adjust

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return self.struct.pack(len(payload) + self.adjust)

    def stated(self, data: bytes | bytearray, at: int) -> int:
        """The payload's size this field says, read at `at` in `data`."""
        return int(self.struct.unpack_from(data, at)[0]) - self.adjust


class Bits:
    """One unsigned integer, packed with a one-integer struct format, holding fields from its
    lowest bit up: each (name, shift, width, the frame's field index or -1 for the length,
    whose value is the payload's size plus `adjust`). A frame's `bits` part, and an integer of
    a primitive's struct format split into bit fields (`Split`)."""

    __slots__ = ("adjust", "fields", "has_length", "most", "order", "struct")

    def __init__(self, fmt: str, fields: Sequence[tuple[str, int, int]], adjust: int = 0) -> None:
        """`fields`: (name, width, index) from the lowest bits up. A format of bytes (`<22s`) holds
        the integer those bytes make in its byte order (`order`)."""
        self.struct = struct.Struct(fmt)
        self.order: Literal["little", "big"] | None = (
            ("big" if fmt.startswith((">", "!")) else "little") if fmt.endswith("s") else None)
        self.adjust = adjust
        out = []
        shift = 0
        for name, width, index in fields:
            out.append((name, shift, width, index))
            shift += width
        self.fields = tuple(out)
        widths = [width for _, _, width, index in self.fields if index < 0]
        self.has_length = bool(widths)
        self.most = (1 << widths[0]) - 1 - adjust if widths else math.inf

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return self.struct.pack(self.word([len(payload) + self.adjust if index < 0 else fields[index]
                                           for _, _, _, index in self.fields]))

    def word(self, values: Sequence[int]) -> int | bytes:
        """What the struct module packs for these fields: their integer, or its bytes."""
        joined = self.join(values)
        return joined if self.order is None else joined.to_bytes(self.struct.size, self.order)

    def join(self, values: Sequence[int]) -> int:
        """The integer holding `values`, one a field from the lowest bits up; a value that does
        not fit its field is a ValueError."""
        joined = 0
        for (name, shift, width, _), value in zip(self.fields, values):
            if not 0 <= value < 1 << width:
                raise ValueError(f"field {name} is {value}, which does not fit its {width} bits (0 to {(1 << width) - 1})")
            joined |= value << shift
        return joined

    def split(self, value: int | bytes) -> list[int]:
        """The integer's fields, from its lowest bits up."""
        if not isinstance(value, int):
            value = int.from_bytes(value, self.order or "little")
        return [(value >> shift) & ((1 << width) - 1) for _, shift, width, _ in self.fields]

    def stated(self, data: bytes | bytearray, at: int) -> int:
        """The payload's size its length field says, read at `at` in `data`."""
        values = self.split(self.struct.unpack_from(data, at)[0])
        return next(value for value, (_, _, _, index) in zip(values, self.fields) if index < 0) - self.adjust

    def wrong(self, chunk: bytes, fields: Sequence[int]) -> str | None:
        """What is wrong with a reply's integer (a field that is not its request's value), if anything."""
        for (name, _, _, index), value in zip(self.fields, self.split(self.struct.unpack(chunk)[0])):
            if index >= 0 and value != fields[index]:
                return f"reply {name} is {value}, expected {fields[index]}"
        return None


class Payload:
    """Where a primitive's bytes go; `trimmed`: without their trailing zero bytes (MAVLink 2), which
    the frame drops when it writes them and puts back when it reads them (`Frame.wrap`, `read`)."""

    __slots__ = ("trimmed",)

    def __init__(self, trimmed: bool = False) -> None:
        self.trimmed = trimmed

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return payload


class Check:
    """A checksum of the parts `first` to `last` (indexes into its side), packed
    with a struct format (`>3s{24}`: the integer three bytes hold, in the format's byte order,
    as RTCM 3 sends its CRC-24Q) or written as upper-case hex digits (`fmt` None); `seed`: (the
    index of a frame field, (value, byte) pairs, the table's name, the field's name): the byte
    for the field's value summed after the parts, never sent (MAVLink 2's CRC_EXTRA)."""

    __slots__ = ("checksum", "digits", "first", "last", "order", "seed", "seeded", "seeds", "struct", "with_request")

    def __init__(self, checksum: Checksum, fmt: str | None, first: int, last: int, with_request: bool = False,
                 seed: tuple[int, Sequence[tuple[int, int]], str, str] | None = None,
                 byte_order: Literal["little", "big"] | None = None) -> None:
        self.checksum = checksum
        # bytes holding one integer (`>3s{24}`, stored as `>3s`): packed as bytes, in their byte order
        self.order = byte_order
        self.struct = struct.Struct(fmt) if fmt is not None else None
        self.digits = (checksum.width + 3) // 4
        self.first = first
        self.last = last
        self.with_request = with_request
        self.seed = -1 if seed is None else seed[0]
        self.seeds = {} if seed is None else {key: bytes((byte,)) for key, byte in seed[1]}
        self.seeded = ("", "") if seed is None else (seed[2], seed[3])  # the table's name, the field's

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return self.encode(self.summed(b"".join(chunks[self.first : self.last + 1]), fields))

    def summed(self, covered: bytes, fields: Sequence[int]) -> int:
        """The checksum of `covered`, then of the seed for the frame's `fields` (a value the
        table lacks: MissingSeed)."""
        if self.seed < 0:
            return self.checksum(covered)
        key = fields[self.seed]
        seed = self.seeds.get(key)
        if seed is None:
            raise MissingSeed(f"the checksum's seed table has no entry for {key}")
        return self.checksum(covered + seed)

    def encode(self, value: int) -> bytes:
        if self.order is not None and self.struct is not None:
            return value.to_bytes(self.struct.size, self.order)
        if self.struct is not None:
            return self.struct.pack(value)
        return b"%0*X" % (self.digits, value)


class OptionalParts:
    """The `count` parts after it (right after the payload), which a reply may lack, all
    together: they came when their first constant bytes did. A request writes them."""

    __slots__ = ("count",)

    def __init__(self, count: int) -> None:
        self.count = count

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return b""


Part = Bytes | Field | Length | Payload | Check | OptionalParts | Bits


def _size(part: Part) -> int:
    """Bytes of a part other than the payload."""
    if isinstance(part, Bytes):
        return len(part.data)
    if isinstance(part, Check):
        return part.struct.size if part.struct is not None else part.digits
    if isinstance(part, (Field, Length, Bits)):
        return part.struct.size
    return 0


class Side:
    """The parts of one direction, with their sizes worked out once."""

    __slots__ = ("again", "checked", "delimiter", "extra", "group", "header", "length", "marker", "most", "parts",
                 "payload", "prefix", "sizes", "suffix", "terminator")

    def __init__(self, parts: Sequence[Part]) -> None:
        self.parts = tuple(parts)
        self.sizes = tuple(_size(p) for p in self.parts)
        # the order a reply's parts are checked in: the checksums after every other part
        self.checked = tuple(sorted(range(len(self.parts)), key=lambda i: isinstance(self.parts[i], Check)))
        self.payload = next((i for i, p in enumerate(self.parts) if isinstance(p, Payload)), -1)
        first = self.parts[0] if self.parts else None
        self.header = first.data if isinstance(first, Bytes) and first.role == "header" else b""
        last = self.parts[-1] if self.parts else None
        self.terminator = last.data if isinstance(last, Bytes) and last.role == "terminator" else b""
        at = self.payload if self.payload >= 0 else len(self.parts)
        self.prefix = sum(self.sizes[:at]) - len(self.header)  # after the header, before the payload
        self.suffix = sum(self.sizes[at + 1 :]) if self.payload >= 0 else 0
        self.length = next((i for i, p in enumerate(self.parts)
                            if isinstance(p, Length) or (isinstance(p, Bits) and p.has_length)), -1)
        length = self.parts[self.length] if self.length >= 0 else None
        self.most = length.most if isinstance(length, (Length, Bits)) else math.inf  # the largest payload it carries
        # a second length field (a sub-payload's): it states the payload again, checked against the first
        self.again = next((i for i, p in enumerate(self.parts) if isinstance(p, Length) and i > self.length), -1)
        after = self.payload + 1
        group = self.parts[after] if 0 <= self.payload and after < len(self.parts) else None
        self.group = range(after + 1, after + 1 + group.count) if isinstance(group, OptionalParts) else range(0)
        self.extra = sum(self.sizes[i] for i in self.group)  # bytes of the optional parts, when they come
        first = self.parts[self.group[0]] if self.group else None
        self.marker = first.data if isinstance(first, Bytes) else b""  # they came: these bytes are there
        after += 1 + len(self.group) if self.group else 0
        follow = self.parts[after] if 0 <= self.payload and after < len(self.parts) else None
        self.delimiter = follow.data if isinstance(follow, Bytes) else b""


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


class Escaping:
    """Escaping between a frame's flags (SLIP, HDLC, PPP): each byte of the table is sent as
    `escape` and its code, so that no flag comes between them; the checker made sure the
    escape is escaped itself and no code is an escaped byte."""

    __slots__ = ("codes", "escape", "sent")

    def __init__(self, escape: bytes, table: Sequence[tuple[bytes, bytes]]) -> None:
        self.escape = escape
        self.sent = [bytes([byte]) for byte in range(256)]  # each byte as it is sent
        for byte, code in table:
            self.sent[byte[0]] = escape + code
        self.codes = {code[0]: byte for byte, code in table}

    def escaped(self, data: bytes) -> bytes:
        return b"".join([self.sent[byte] for byte in data])

    def unescaped(self, data: bytes, name: str) -> bytes:
        """`data` as it was before escaping; an escape before a byte that is no code, or at the
        end, is a FrameError."""
        pieces = data.split(self.escape)
        out = bytearray(pieces[0])
        for at, piece in enumerate(pieces[1:], 2):
            if not piece and at == len(pieces):
                raise FrameError(f"{name}: the packet ends in the escape {self.escape!r}: {data!r}")
            code = piece[0] if piece else self.escape[0]
            if code not in self.codes:
                raise FrameError(f"{name}: the escape {self.escape!r} comes before {bytes([code])!r}, "
                                 f"which is no code: {data!r}")
            out += self.codes[code]
            out += piece[1:]
        return bytes(out)
