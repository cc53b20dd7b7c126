"""The rdisc engine: the run-time semantics of RDIS, written once.

Everything that happens between a host and its devices lives in this module:
ports and their locks, frames, writing requests and reading every kind of reply,
deadlines, I/O callbacks, the connections' threads and schedules, hooks, the
lifecycle, signals, the error types and the command line. What a description
specialises is data and small functions, the *plans* below (per primitive its
values, encoder, decoder, frame, post-actions; per interface its calls, delays
and output; per input its arguments). The runtime (`rdisc.runtime.device`)
builds plans from a checked Model with its expression interpreter; `rdisc
emit-python` writes them as Python source into a driver that carries this
module's text verbatim, from its `from __future__` line to its end. So the
runtime and every driver run the same code. It needs only the standard library,
and pyserial to open a port by name. The semantics are the contract in the
docstring of `rdisc.runtime`.
"""

from __future__ import annotations

import argparse
import difflib
import json
import logging
import math
import numbers
import os
import re
import signal
import struct
import sys
import threading
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Protocol

Value = int | float | bool | str | bytes | tuple[Any, ...]  # an array is a tuple
"""The value of a state variable, a parameter, a field or an output field."""

StateValues = Mapping[str, Any]
"""The state variables by name: a snapshot, never changed in place. (Each value is of
its variable's declared type, which the checker knows and Python's types cannot say.)"""

Args = list[Any]
"""The values of a call's parameters (or an input's fields), by position."""

OutputCallback = Callable[[dict[str, Any]], object]
ErrorCallback = Callable[[BaseException], object]
IoCallback = Callable[[str, str, bytes], object]
"""`(direction, connection, data)`: "write" or "read" and the bytes, or "lines" and the modem
lines a primitive set, as ASCII text such as b"dtr=0 rts=1"."""

MAX_INT = (1 << 64) - 1  # the largest int a state variable holds (and its negation the smallest)
MAX_ARRAY = 1024  # the most elements an array holds, and rounds a group repeated as a message says
MAX_LINE = 4096
"""Bytes of one reply line, terminator included."""

EVAL_ERRORS = (ArithmeticError, ValueError, TypeError, IndexError, OverflowError)
"""What evaluating an expression can raise; each becomes an RdisValueError of the element at fault."""

_log = logging.getLogger("rdisc")


# ---- errors ------------------------------------------------------------------------------------


class RdisError(Exception):
    """Any failure while a description runs."""


class RdisTimeout(RdisError, TimeoutError):
    """The device sent no reply within the timeout."""


class RdisProtocolError(RdisError):
    """The device replied, but not as described: short, unterminated or unmatched."""


class RdisConnectionError(RdisError, ConnectionError):
    """A port could not be opened, failed, or disappeared."""


class RdisValueError(RdisError, ValueError):
    """A value could not be computed or encoded (division by zero, out of range for its code)."""


class RdisCallbackError(RdisError):
    """A user callback raised; the exception is the cause."""


# ---- frames on the wire ----------------------------------------------------------------------------
#
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


class Reader(Protocol):
    timeout: float | None

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
            value &= full
        else:
            value = self._crc(data)
        if self.inverted:
            value ^= full
        return value if self.mask is None else value & self.mask

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
            self.port.timeout = self.timeout
            self.shortened = False
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
    """The frame's `index`-th field value, packed with a one-integer struct format."""

    __slots__ = ("index", "name", "struct")

    def __init__(self, name: str, fmt: str, index: int) -> None:
        self.name = name
        self.struct = struct.Struct(fmt)
        self.index = index

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return self.struct.pack(fields[self.index])


class Length:
    """The payload's size plus `adjust`; `most`, the largest size its format states."""

    __slots__ = ("adjust", "most", "struct")

    def __init__(self, fmt: str, adjust: int) -> None:
        self.struct = struct.Struct(fmt)
        self.adjust = adjust
        bits = 8 * self.struct.size
        self.most = ((1 << (bits - 1)) - 1 if fmt[-1].islower() else (1 << bits) - 1) - adjust

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

    __slots__ = ("adjust", "fields", "has_length", "most", "struct")

    def __init__(self, fmt: str, fields: Sequence[tuple[str, int, int]], adjust: int = 0) -> None:
        """`fields`: (name, width, index) from the lowest bits up."""
        self.struct = struct.Struct(fmt)
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
        return self.struct.pack(self.join([len(payload) + self.adjust if index < 0 else fields[index]
                                           for _, _, _, index in self.fields]))

    def join(self, values: Sequence[int]) -> int:
        """The integer holding `values`, one a field from the lowest bits up; a value that does
        not fit its field is a ValueError."""
        joined = 0
        for (name, shift, width, _), value in zip(self.fields, values):
            if not 0 <= value < 1 << width:
                raise ValueError(f"field {name} is {value}, which does not fit its {width} bits (0 to {(1 << width) - 1})")
            joined |= value << shift
        return joined

    def split(self, value: int) -> list[int]:
        """The integer's fields, from its lowest bits up."""
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
    __slots__ = ()

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return payload


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

    def put(self, payload: bytes, fields: Sequence[int], chunks: list[bytes]) -> bytes:
        return self.encode(self.checksum(b"".join(chunks[self.first : self.last + 1])))

    def encode(self, value: int) -> bytes:
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

    __slots__ = ("delimiter", "extra", "group", "header", "length", "marker", "most", "parts", "payload", "prefix",
                 "sizes", "suffix", "terminator")

    def __init__(self, parts: Sequence[Part]) -> None:
        self.parts = tuple(parts)
        self.sizes = tuple(_size(p) for p in self.parts)
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


Wrap = Callable[[bytes, Sequence[int]], bytes]
"""A request side's parts around a payload, with the frame's field values."""


def _quick_wrap(side: Side) -> Wrap | None:
    """The request side as one struct pack of the parts before the payload, then the
    payload, then the constants and checksums after it: what `Frame.wrap` does part by
    part, in a few steps. None when a part before the payload is a checksum or two
    multi-byte parts there disagree on byte order (the part-by-part way then runs)."""
    if side.payload < 0:
        return None
    order = ""
    codes: list[str] = []
    template: list[Any] = []
    picks: list[tuple[int, int, int]] = []  # (position in the pack, field index or -1 for the length, adjust)
    for part in side.parts[: side.payload]:
        if isinstance(part, Bytes):
            codes.append(f"{len(part.data)}s")
            template.append(part.data)
            continue
        if not isinstance(part, (Field, Length)):
            return None
        fmt = part.struct.format
        prefix, code = (fmt[0], fmt[1:]) if fmt[:1] in "<>!=@" else ("", fmt)
        if part.struct.size > 1:
            if prefix not in ("<", ">", "!") or order not in ("", prefix.replace("!", ">")):
                return None
            order = prefix.replace("!", ">")
        codes.append(code)
        picks.append((len(template), part.index, 0) if isinstance(part, Field) else (len(template), -1, part.adjust))
        template.append(0)
    head = struct.Struct((order or "<") + "".join(codes))
    starts = [0]  # each part's first byte: before the payload from the frame's start, after it from the payload's end
    for i, size in enumerate(side.sizes):
        starts.append(0 if i == side.payload else starts[-1] + size)
    after = side.payload + 1  # the first part whose start counts from the payload's end
    tail: list[tuple[bytes, Check | None, int, int]] = []  # a constant, or a checksum of [start, stop)
    for at, part in enumerate(side.parts[after:], after):
        if isinstance(part, Check) and part.last < at and not part.with_request:
            first, stop = part.first, part.last + 1
            tail.append((b"", part, ~starts[first] if first >= after else starts[first],
                         ~starts[stop] if stop >= after else starts[stop]))
        elif isinstance(part, Bytes):
            tail.append((part.data, None, 0, 0))
        elif not isinstance(part, OptionalParts):  # its parts are written as any others
            return None

    def wrap(payload: bytes, fields: Sequence[int]) -> bytes:
        values = template.copy()
        for at, index, adjust in picks:
            values[at] = fields[index] if index >= 0 else len(payload) + adjust
        out = head.pack(*values) + payload
        end = len(out)  # where the payload ends
        for data, check, start, stop in tail:  # ~offset: counted from the payload's end
            if check is None:
                out += data
            else:
                out += check.encode(check.checksum(out[start if start >= 0 else end + ~start :
                                                       stop if stop >= 0 else end + ~stop]))
        return out

    return wrap


class Frame:
    """A request side and a reply side (empty when the device answers nothing framed), and
    the values of its fields over its parameters."""

    __slots__ = ("escaping", "fields", "headers", "name", "params", "quick", "ranged", "replies", "reply", "requests",
                 "stuffing")

    def __init__(self, name: str, request: Sequence[Part], reply: Sequence[Part], stuffing: Stuffing | None = None,
                 params: tuple[Param, ...] = (), fields: Callable[[Args], list[Any]] | None = None,
                 more_requests: Sequence[Sequence[Part]] = (), more_replies: Sequence[Sequence[Part]] = (),
                 escaping: Escaping | None = None) -> None:
        """`more_requests` and `more_replies`: the other layouts of a side (`either`), in order;
        `escaping`: the bytes between the header and the terminator escaped (one layout each way)."""
        self.name = name
        self.requests = tuple(Side(parts) for parts in (request, *more_requests))
        self.replies = tuple(Side(parts) for parts in (reply, *more_replies))
        self.reply = self.replies[0]
        self.headers = tuple(side.header for side in self.replies)  # a reply's layout is known by its header
        self.stuffing = stuffing
        self.escaping = escaping
        self.params = params
        self.ranged = _ranged(params)
        self.fields = fields
        self.quick = tuple(_quick_wrap(side) for side in self.requests)

    def values(self, owner: str, args: Args) -> list[Any]:
        """The field values for the frame's arguments; an argument outside its parameter's
        range is an RdisValueError of `owner`, before anything is sent."""
        if self.ranged:
            _in_ranges(f"{owner}: frame {self.name}", self.params, self.ranged, args)
        return [] if self.fields is None else self.fields(args)

    def wrap(self, payload: bytes, fields: Sequence[int]) -> bytes:
        """The request: `payload` framed (stuffed first, when the frame stuffs), with the
        frame's field values; when it escapes, what comes between its flags escaped."""
        if self.stuffing is not None:
            payload = self.stuffing.stuff(payload)
        for side, quick in zip(self.requests, self.quick):  # the first layout that can state its size
            if len(payload) <= side.most:
                out = quick(payload, fields) if quick is not None else self.wrap_parts(side, payload, fields)
                if self.escaping is None:
                    return out
                end = len(out) - len(side.terminator)
                return out[: len(side.header)] + self.escaping.escaped(out[len(side.header) : end]) + out[end:]
        most = max(side.most for side in self.requests)
        raise ValueError(f"frame {self.name}: a {len(payload)}-byte payload is more than its length field"
                         f"{' states' if len(self.requests) == 1 else 's state'} ({most} bytes)")

    @staticmethod
    def wrap_parts(side: Side, payload: bytes, fields: Sequence[int]) -> bytes:
        """A request layout put together part by part, each after the ones before it."""
        chunks: list[bytes] = []
        for part in side.parts:
            chunks.append(part.put(payload, fields, chunks))
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
            if len(data) > 1 and isinstance(port, Incoming):  # look for the next header in what was taken
                port.put_back(bytes(data[1:]))
            raise

    def _read(self, port: Reader, data: bytearray, fields: Sequence[int], request: bytes,
              size: int) -> tuple[bytes, bytes]:
        if self.escaping is not None:
            return self._read_escaped(port, data, fields, request)
        side = self.reply
        if len(self.replies) > 1:  # the header that comes says which layout
            head = self._sync(port, self.headers)
            data += head
            side = self.replies[self.headers.index(head)]
        elif side.header:
            data += self._sync(port, self.headers)
        self._take(port, data, side.prefix, bool(data))
        if side.payload < 0:
            return self._check(side, bytes(data), 0, fields, request), b""
        if side.length >= 0:
            at = sum(side.sizes[: side.length])
            length = side.parts[side.length]
            assert isinstance(length, (Length, Bits))
            size = length.stated(data, at)
            if not 0 <= size <= MAX_FRAME:
                raise FrameError(f"{self.name}: length field says {size + length.adjust}, which no payload fits")
        present = True  # the optional parts came
        if size >= 0 and not side.group:
            self._take(port, data, size + side.suffix, bool(data))
        elif size >= 0:  # one byte after the payload tells whether they came
            self._take(port, data, size + 1, bool(data))
            present = data[-1:] == side.marker[:1]
            self._take(port, data, side.suffix - 1 - (0 if present else side.extra), True)
        else:
            found = port.read_until(side.delimiter, MAX_FRAME)
            started = bool(data or found)
            data += found
            if not found.endswith(side.delimiter):
                raise FrameError(f"{self.name}: reply not delimited by {side.delimiter!r}: {bytes(data)!r}",
                                 timeout=not started)
            size = len(found) - len(side.delimiter)
            if side.group:  # they came when their first bytes stand where they would end
                at = len(data) - len(side.delimiter) - side.extra
                present = size >= side.extra and data[at : at + len(side.marker)] == side.marker
                size -= side.extra if present else 0
            self._take(port, data, side.suffix - side.extra - len(side.delimiter), True)
        raw = bytes(data)
        return raw, self._check(side, raw, size, fields, request, present)

    def _read_escaped(self, port: Reader, data: bytearray, fields: Sequence[int],
                      request: bytes) -> tuple[bytes, bytes]:
        """A reply between flags: the bytes up to the first terminator (which the escaping keeps
        out of those before it), unescaped, then taken apart by the sizes of its parts."""
        side = self.reply
        assert self.escaping is not None
        end = side.terminator
        if side.header:
            data += self._sync(port, self.headers)
        while True:
            found = port.read_until(end, MAX_FRAME)
            started = bool(data or found)
            data += found
            if not found.endswith(end):
                raise FrameError(f"{self.name}: reply not delimited by {end!r}: {bytes(data)!r}", timeout=not started)
            if len(found) > len(end) or side.header not in (b"", end):
                break
            if len(data) > MAX_SKIP:  # flags, flags: no packet
                raise FrameError(f"{self.name}: no packet in {MAX_SKIP} bytes")
            # two flags in a row hold an empty packet, which RFC 1055 and RFC 1662 drop: the second may open the next
        raw = side.header + self.escaping.unescaped(found[: -len(end)], self.name) + end
        fixed = sum(side.sizes)  # every part's but the payload's
        size = len(raw) - fixed
        if size < 0 or (side.payload < 0 and size):
            raise FrameError(f"{self.name}: a {len(raw)}-byte packet, unescaped, where its parts take "
                             f"{fixed} bytes{' and the payload' if side.payload >= 0 else ''}: {raw!r}")
        if side.length >= 0:
            length = side.parts[side.length]
            assert isinstance(length, (Length, Bits))
            stated = length.stated(raw, sum(side.sizes[: side.length]))
            if stated != size:
                raise FrameError(f"{self.name}: length field says {stated + length.adjust}, but the payload is "
                                 f"{size} bytes: {raw!r}")
        return bytes(data), self._check(side, raw, size, fields, request)

    def _sync(self, port: Reader, headers: tuple[bytes, ...]) -> bytes:
        """Read up to the first of `headers` to come, skipping the bytes before it; that header."""
        shortest, longest = min(len(h) for h in headers), max(len(h) for h in headers)
        window = bytearray(port.read(shortest))
        if not window:
            raise FrameError(f"{self.name}: no reply", timeout=True)
        said = " or ".join(repr(h) for h in headers)
        skipped = 0
        while (found := next((h for h in headers if window.endswith(h)), None)) is None:
            byte = port.read(1) if len(window) >= shortest else b""
            if not byte:
                raise FrameError(f"{self.name}: no header {said} in the reply (after {skipped} bytes)")
            window += byte
            if len(window) > longest:
                del window[0]
                skipped += 1
            if skipped > MAX_SKIP:
                raise FrameError(f"{self.name}: no header {said} in {MAX_SKIP} bytes")
        return found

    def _take(self, port: Reader, data: bytearray, size: int, started: bool) -> None:
        if size <= 0:
            return
        got = port.read(size)
        data += got
        if len(got) < size:
            if not started and not got:
                raise FrameError(f"{self.name}: no reply", timeout=True)
            raise FrameError(f"{self.name}: short reply, {len(data)} bytes: {bytes(data)!r}")

    def _check(self, side: Side, raw: bytes, size: int, fields: Sequence[int], request: bytes,
               present: bool = True) -> bytes:
        """Every constant, field and checksum of a complete reply (the optional parts when they
        are `present`); its payload."""
        absent = range(0) if present else side.group
        starts: list[int] = []
        at = 0
        for i, part_size in enumerate(side.sizes):
            starts.append(at)
            at += size if i == side.payload else 0 if i in absent else part_size
        starts.append(at)
        for i, part in enumerate(side.parts):
            if i in absent:
                continue
            chunk = raw[starts[i] : starts[i + 1]]
            if isinstance(part, Bytes):
                if chunk != part.data:
                    raise FrameError(f"{self.name}: expected {part.data!r} as the {part.role}, got {chunk!r}")
            elif isinstance(part, Field):
                value = part.struct.unpack(chunk)[0]
                if value != fields[part.index]:
                    raise FrameError(f"{self.name}: reply {part.name} is {value}, expected {fields[part.index]}")
            elif isinstance(part, Bits) and (wrong := part.wrong(chunk, fields)) is not None:
                raise FrameError(f"{self.name}: {wrong}")
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


# ---- requests and replies ----------------------------------------------------------------------


def _latin1(owner: str, value: object) -> bytes:
    if isinstance(value, bytes):
        return value
    try:
        return str(value).encode("latin-1")
    except UnicodeEncodeError as err:
        raise RdisValueError(f"{owner}: {err.object[err.start:err.end]!r} is not a latin-1 character") from None


def _string_sizes(fmt: str) -> dict[int, int]:
    """The most bytes each `s` or `p` value of a struct format holds, by the value's position."""
    sizes: dict[int, int] = {}
    at = 0
    for count, code in re.findall(r"(\d*)([a-zA-Z?])", fmt):
        n = int(count) if count else 1
        if code in "sp":
            sizes[at] = n if code == "s" else max(0, min(n - 1, 255))
            at += 1
        elif code != "x":
            at += n
    return sizes


Group = tuple[int, int, int]
"""A repeated group of a struct format: its first value, its number of codes, its count (0:
as many as the message says)."""

Varying = tuple[str, str, int]
"""A group repeated as many times as the message says: its codes once, the format after it,
and the index of its count field among the values before it (-1: until the message ends)."""


Split = tuple[int, str, tuple[int, ...]]
"""An integer of a struct format split into bit fields (`B{1,1,6}`): the index of its first field
among the values, its code with the byte order, its fields' widths from its lowest bit up."""


def _splitters(splits: tuple[Split, ...]) -> tuple[tuple[int, Bits], ...]:
    """Each split integer's first value and its `Bits`, whose fields are named by their values' indexes."""
    return tuple((first, Bits(fmt, [(f"value {first + k}", width, k) for k, width in enumerate(widths)]))
                 for first, fmt, widths in splits)


def _joined(values: Sequence[Any], splitters: tuple[tuple[int, Bits], ...]) -> list[Any]:
    """Values with each split integer's fields joined into it (a ValueError where one does not fit)."""
    out = list(values)
    for first, bits in reversed(splitters):
        end = first + len(bits.fields)
        out[first:end] = [bits.join(out[first:end])]
    return out


def _split(values: Sequence[Any], splitters: tuple[tuple[int, Bits], ...]) -> tuple[Any, ...]:
    """Decoded values with each split integer in its fields."""
    out = list(values)
    for first, bits in splitters:  # in order: the integers before one are split already
        out[first : first + 1] = bits.split(out[first])
    return tuple(out)


def _counted(groups: tuple[Group, ...], rounds: int) -> tuple[Group, ...]:
    """The groups with the varying one's count set."""
    return tuple((first, codes, count or rounds) for first, codes, count in groups)


def _interleaved(owner: str, values: Sequence[Value], groups: tuple[Group, ...]) -> list[Any]:
    """Values with each group's arrays given element by element: `6(BH)` takes two arrays of
    6 and packs their first elements, then their second, ..."""
    flat: list[Any] = []
    at = 0
    for first, codes, count in groups:
        flat.extend(values[at:first])
        arrays: Sequence[Any] = values[first : first + codes]
        for array in arrays:
            if len(array) != count:
                raise RdisValueError(f"{owner}: a group of {count} takes arrays of {count}, not {len(array)}")
        for row in zip(*arrays):
            flat.extend(row)
        at = first + codes
    flat.extend(values[at:])
    return flat


def _regrouped(values: Sequence[Any], groups: tuple[Group, ...]) -> tuple[Any, ...]:
    """Unpacked values with each group's values gathered into one array a code."""
    out: list[Any] = []
    at = 0
    for first, codes, count in groups:
        take = first - len(out)
        out.extend(values[at : at + take])
        at += take
        block = values[at : at + codes * count]
        out.extend(tuple(block[k::codes]) for k in range(codes))
        at += codes * count
    out.extend(values[at:])
    return tuple(out)


class Pack:
    """A request packed with a struct format: the values at `strings` as latin-1 bytes
    (refused when longer than their `Ns` holds: struct would cut them short), the arrays
    of repeated `groups` element by element, and, with `rest` (a format ending in `*`),
    the last value, bytes, appended as it is. With `varying`, `fixed` is the format before
    that group, repeated as many times as its arrays hold values, and its count field
    computed. The fields of each integer split into `bits` are joined into it first; the
    other indexes count it as one value."""

    __slots__ = ("bits", "groups", "rest", "sizes", "splitters", "strings", "struct", "varying")

    def __init__(self, fixed: str, strings: tuple[int, ...] = (), rest: bool = False,
                 groups: tuple[Group, ...] = (), varying: Varying | None = None, bits: tuple[Split, ...] = ()) -> None:
        self.struct = struct.Struct(fixed)
        self.strings = strings
        self.rest = rest
        self.sizes = _string_sizes(fixed)
        self.groups = groups
        self.varying = varying
        self.bits = bits
        self.splitters = _splitters(bits)

    def encode(self, owner: str, values: Sequence[Value]) -> bytes:
        if self.splitters:
            try:
                values = _joined(values, self.splitters)
            except (ValueError, TypeError) as err:  # a value too wide for its bits
                raise RdisValueError(f"{owner}: {err}") from None
        try:
            if self.varying is not None:
                return self._varying(owner, values, self.varying)
            if self.groups:
                values = _interleaved(owner, values, self.groups)
            if not self.strings and not self.rest:
                return self.struct.pack(*values)
            packed = list(values[:-1] if self.rest else values)
            for i in self.strings:
                packed[i] = data = _latin1(owner, packed[i])
                if len(data) > self.sizes.get(i, len(data)):
                    raise RdisValueError(f"{owner}: {len(data)} bytes of text do not fit the {self.sizes[i]} "
                                         f"that value {i} is packed in")
            fixed = self.struct.pack(*packed)
        except (struct.error, OverflowError) as err:  # OverflowError: a float too large for `e` or `f`
            raise RdisValueError(f"{owner}: {err}") from None
        if self.rest:
            tail = values[-1]
            assert isinstance(tail, bytes)
            return fixed + tail
        return fixed

    def _varying(self, owner: str, values: Sequence[Value], varying: Varying) -> bytes:
        """The arrays of the varying group, all of one length, give its rounds and its count."""
        unit, tail, count_at = varying
        first, codes = next((first, codes) for first, codes, count in self.groups if not count)
        lengths = {len(array) for array in values[first : first + codes]}  # type: ignore[arg-type]
        if len(lengths) > 1:
            raise RdisValueError(f"{owner}: the arrays of a repeated group have one length, not "
                                 f"{' and '.join(map(str, sorted(lengths)))}")
        rounds = lengths.pop()
        if rounds > MAX_ARRAY:
            raise RdisValueError(f"{owner}: a group is repeated at most {MAX_ARRAY} times, not {rounds}")
        flat = _interleaved(owner, values, _counted(self.groups, rounds))
        if count_at >= 0:
            flat.insert(count_at, rounds)
        try:
            return struct.pack(self.struct.format + unit * rounds + tail, *flat)
        except struct.error as err:  # a value out of its code's range, the count field's among them
            raise RdisValueError(f"{owner}: {err} ({rounds} groups)") from None


class Format:
    """A request written with a PEP 3101 format string, as latin-1 text."""

    __slots__ = ("template",)

    def __init__(self, template: str) -> None:
        self.template = template

    def encode(self, owner: str, values: Sequence[Value]) -> bytes:
        try:
            text = self.template.format(*values)
        except (ValueError, TypeError, IndexError, KeyError) as err:
            raise RdisValueError(f"{owner}: {err}") from None
        return _latin1(owner, text)


class Unpack:
    """A reply decoded with a struct format: exactly its size or, with `rest`, its fixed
    part and then the rest as bytes; the values at `strings` as latin-1 text, each repeated
    group's values as one array a code. With `varying`, `fixed` is the format before that
    group, repeated as many times as its count field says or as fill the reply. Each integer
    split into `bits` is then given as its fields. With `until`, an unframed tagged reply's
    entry is read to those bytes (Firmata's sysex end), which are dropped."""

    __slots__ = ("bits", "groups", "rest", "size", "splitters", "strings", "struct", "until", "varying")

    def __init__(self, fixed: str, strings: tuple[int, ...] = (), rest: bool = False,
                 groups: tuple[Group, ...] = (), varying: Varying | None = None, bits: tuple[Split, ...] = (),
                 until: bytes | None = None) -> None:
        self.struct = struct.Struct(fixed)
        self.strings = strings
        self.rest = rest
        self.size = -1 if rest or varying else self.struct.size  # -1: the frame says where the reply ends
        self.groups = groups
        self.varying = varying
        self.bits = bits
        self.splitters = _splitters(bits)
        self.until = until

    def decode(self, owner: str, data: bytes) -> tuple[Value, ...]:
        values = self._decode(owner, data)
        return _split(values, self.splitters) if self.splitters else values

    def _decode(self, owner: str, data: bytes) -> tuple[Value, ...]:
        layout = self.struct
        values: tuple[Any, ...]
        if self.varying is not None:
            return self._varying(owner, data, self.varying)
        if self.rest:
            if len(data) < layout.size:
                raise RdisProtocolError(f"{owner}: expected {layout.size} bytes or more, got {len(data)}")
            values = (*layout.unpack_from(data), data[layout.size :])
        elif len(data) != layout.size:
            raise RdisProtocolError(f"{owner}: expected {layout.size} bytes, got {len(data)}")
        else:
            values = layout.unpack(data)
        if self.groups:  # a format with groups has no strings
            return _regrouped(values, self.groups)
        if self.strings:
            decoded = list(values)
            for i in self.strings:
                decoded[i] = decoded[i].decode("latin-1")
            return tuple(decoded)
        return values

    def _varying(self, owner: str, data: bytes, varying: Varying) -> tuple[Value, ...]:
        """The rounds the count field says, or as many as the bytes after the head and before
        the tail hold whole; the count field's own value dropped."""
        unit, tail, count_at = varying
        order = self.struct.format[:1]
        unit_size, tail_size = struct.calcsize(order + unit), struct.calcsize(order + tail)
        head = self.struct.size
        if len(data) < head + tail_size:
            raise RdisProtocolError(f"{owner}: expected {head + tail_size} bytes or more, got {len(data)}")
        if count_at >= 0:
            rounds = self.struct.unpack_from(data)[count_at]
            if rounds > MAX_ARRAY:
                raise RdisProtocolError(f"{owner}: the reply counts {rounds} groups; at most {MAX_ARRAY} are read")
            if len(data) != head + unit_size * rounds + tail_size:
                raise RdisProtocolError(f"{owner}: {rounds} groups make {head + unit_size * rounds + tail_size} "
                                        f"bytes, got {len(data)}")
        else:
            rounds, extra = divmod(len(data) - head - tail_size, unit_size)
            if extra:
                raise RdisProtocolError(f"{owner}: {len(data) - head} bytes after the first {head} are not whole "
                                        f"groups of {unit_size}")
            if rounds > MAX_ARRAY:
                raise RdisProtocolError(f"{owner}: the reply holds {rounds} groups; at most {MAX_ARRAY} are read")
        values = list(struct.unpack(self.struct.format + unit * rounds + tail, data))
        if count_at >= 0:
            del values[count_at]
        return _regrouped(values, _counted(self.groups, rounds))


class Match:
    """A reply matched from its start by a regular expression: its groups, "" for a group
    that took no part."""

    __slots__ = ("pattern", "regex", "size")

    def __init__(self, pattern: str) -> None:
        self.pattern = pattern
        self.regex = re.compile(pattern)
        self.size = -1

    def decode(self, owner: str, data: bytes) -> tuple[Value, ...]:
        text = data.decode("latin-1")
        found = self.regex.match(text)
        if found is None:
            raise RdisProtocolError(f"{owner}: reply {text!r} does not match {self.pattern!r}")
        groups: tuple[str, ...] = found.groups("")
        return groups


# ---- plans: what a description specialises ---------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Param:
    """A parameter of an interface or a primitive, or a field of an input's adapter."""

    name: str
    kind: type  # int, float, bool, str or bytes; an array's elements'
    low: float | None = None  # the declared range (for bytes, of the length; for an array, of each element)
    high: float | None = None
    default: Value | None = None  # the value when a call leaves it out
    size: int | None = None  # an array's: its number of elements (0: any); None: not an array


@dataclass(frozen=True, slots=True)
class FrameUse:
    """A primitive's frame, and the frame's arguments over the primitive's parameters."""

    frame: Frame
    args: Callable[[StateValues, Args], Args]


Request = Callable[[StateValues, Args], bytes | None]
"""An input's fields' or a primitive's parameters' values to its request bytes in one step;
None where the general way must decide."""


@dataclass(frozen=True, slots=True)
class Primitive:
    """One device command: its format values (over state and its parameters), how they are
    encoded and framed (no encoder: no request, only modem lines), how its reply is read and
    decoded, and its post-actions (the new values of state variables, over state, its
    parameters and the reply)."""

    name: str
    connection: str
    params: tuple[Param, ...]
    values: Callable[[StateValues, Args], Args]
    encoder: Pack | Format | None
    decoder: Unpack | Match | None = None
    actions: Callable[[StateValues, Args, Sequence[Any]], dict[str, Value]] | None = None
    frame: FrameUse | None = None
    skip: bool = False  # `skip unmatched`: read past replies that do not decode
    timeout: float | None = None  # seconds its reply may take, instead of the robot's
    table: Mapping[int, Primitive] | None = None  # a reply table: the plan for each key or tag
    key: int = -1  # the position of the parameter that chooses from `table` (-1: the reply's tag does)
    tag: str | None = None  # the struct format of the tag that starts the reply
    each: bool = False  # the framed payload is sub-payloads, each a tag and its entry's bytes, until it ends
    length: str | None = None  # `each`: the struct format of each sub-payload's length, after its tag
    records: bytes | None = None  # the marker ending each record of the framed payload, each decoded by `decoder`
    checked: tuple[str, ...] = ()  # state variables its post-actions may make too wide (checked as they are set)
    request: Request | None = None  # its parameters' values to the bytes, when it is only written (`_sent_at_once`)
    expect: Callable[[StateValues, Args, Sequence[Any]], object] | None = None  # a condition its decoded reply meets
    lines: Callable[[StateValues, Args], dict[str, Value]] | None = None  # "dtr"/"rts": levels, set before the request
    replies: int = 0  # `replies N`: N replies to one request, collected value by value into arrays (0: one)
    reply_frames: tuple[FrameUse, ...] = ()  # each reply's own frame (`replies id in IDS frame status(id)`)
    answers: tuple[Primitive, ...] = ()  # the replies read in turn, a plan each: `replies { }`'s, each its own
    # frame, decoder, expect and post-actions; `replies N`'s made here, this plan's (through `reply_frames`)
    expects_reply: bool = field(init=False)
    framed_reply: bool = field(init=False)
    in_parts: bool = field(init=False)  # read as sub-payloads or records, each its plan, values and post-actions
    floats: tuple[int, ...] = field(init=False)
    ranged: tuple[int, ...] = field(init=False)
    tag_struct: struct.Struct | None = field(init=False)
    length_struct: struct.Struct | None = field(init=False)

    def __post_init__(self) -> None:
        reply = self.frame.frame.reply if self.frame is not None else None
        framed = reply is not None and bool(reply.parts)
        acknowledged = framed and reply is not None and reply.payload < 0  # constant parts only
        object.__setattr__(self, "framed_reply", framed)
        object.__setattr__(self, "in_parts", self.each or self.records is not None)
        object.__setattr__(self, "expects_reply", self.decoder is not None or self.table is not None or acknowledged
                           or bool(self.answers))
        object.__setattr__(self, "floats", _floats(self.params))
        object.__setattr__(self, "ranged", _ranged(self.params))
        object.__setattr__(self, "tag_struct", None if self.tag is None else struct.Struct(self.tag))
        object.__setattr__(self, "length_struct", None if self.length is None else struct.Struct(self.length))
        if self.replies:  # one plan for each reply, all alike but for their frames
            one = replace(self, replies=0, reply_frames=())
            object.__setattr__(self, "answers", tuple(replace(one, frame=use) for use in self.reply_frames)
                               or (one,) * self.replies)
        if not _sent_at_once(self):
            object.__setattr__(self, "request", None)
        elif self.request is None:
            object.__setattr__(self, "request", _composed_write(self))


def _plain(encoder: Pack | Format | None) -> bool:
    """Whether an encoder is one struct module's `pack` of its values as they are: no string,
    rest or bit fields to prepare first."""
    return isinstance(encoder, Pack) and not encoder.strings and not encoder.rest and not encoder.bits


def _sent_at_once(plan: Primitive) -> bool:
    """Whether running the primitive is only packing its values, framing them and writing
    them: no reply, reply table, post-action, modem line or string in the way."""
    return _plain(plan.encoder) and not plan.expects_reply and plan.actions is None and plan.table is None and plan.lines is None


def _composed_write(plan: Primitive) -> Request:
    """The general way of a primitive only written (`Robot._primitive`), as one function of its
    parameters' values. Like `Input.request` it returns None for anything but the parameters'
    own types in their ranges, and on any error: the general way then says what is wrong."""
    kinds = tuple(p.kind for p in plan.params)
    bounds = tuple((i, plan.params[i].low, plan.params[i].high) for i in plan.ranged)
    values_of = plan.values
    assert isinstance(plan.encoder, Pack)
    pack = plan.encoder.struct.pack
    use = plan.frame

    def request(state: StateValues, args: Args) -> bytes | None:
        if len(args) != len(kinds):
            return None
        for value, kind in zip(args, kinds):
            if type(value) is not kind:
                return None
        for i, low, high in bounds:
            if not low <= args[i] <= high:
                return None
        try:
            payload = pack(*values_of(state, args))
            return payload if use is None else use.frame.wrap(payload, use.frame.values("", use.args(state, args)))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    return request


@dataclass(frozen=True, slots=True)
class Output:
    """A domain output: its fields over state, in its adapter's order."""

    name: str
    fields: Callable[[StateValues], dict[str, Value]]
    adapter: str = ""


@dataclass(frozen=True, slots=True)
class Call:
    """A call of an interface: of a primitive or of another interface, its arguments over
    state and the interface's parameters, and the delay after it. `direct`: the arguments
    are the primitive's format values (it has no frame, table, ranges or post-actions)."""

    target: Primitive | Interface
    args: Callable[[StateValues, Args], Args]
    delay: float = 0.0  # seconds
    direct: bool = False
    when: Callable[[StateValues, Args], object] | None = None  # the call is made only when this holds


@dataclass(frozen=True, slots=True)
class Interface:
    """A host-side operation: its calls in run order, then the outputs it triggers."""

    name: str
    params: tuple[Param, ...]
    calls: tuple[Call, ...]
    outputs: tuple[Output, ...] = ()
    floats: tuple[int, ...] = field(init=False)
    ranged: tuple[int, ...] = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "floats", _floats(self.params))
        object.__setattr__(self, "ranged", _ranged(self.params))


@dataclass(frozen=True, slots=True)
class Input:
    """A domain input: its adapter's fields, and the interface's arguments over them.

    When its interface is one plain write (`_written_at_once`), `request` goes from the
    fields' values straight to the bytes: a generated driver gives one compiled from the
    expressions, else the general way is composed into one here. It returns None for
    anything but the fields' own types and on any error, and the general way then runs
    and says what is wrong, so both ways behave alike."""

    name: str
    adapter: str
    fields: tuple[Param, ...]
    interface: Interface
    args: Callable[[StateValues, Args], Args]
    request: Request | None = None
    primitive: Primitive | None = field(init=False)  # where `request` goes, when there is one
    kinds: tuple[type, ...] = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "kinds", tuple(f.kind for f in self.fields))
        call = _written_at_once(self.interface)
        object.__setattr__(self, "primitive", call.target if call is not None else None)
        request = None if call is None else self.request or _composed(self, call)
        object.__setattr__(self, "request", request)


def _written_at_once(interface: Interface) -> Call | None:
    """The interface's one call, when running it is only packing its values and writing them:
    no delay, range, output, frame, reply, post-action, modem line or string in the way."""
    if len(interface.calls) != 1 or interface.ranged or interface.outputs:
        return None
    call = interface.calls[0]
    prim = call.target
    if not isinstance(prim, Primitive):
        return None
    if not call.direct or call.delay or call.when or not _plain(prim.encoder) or prim.expects_reply or prim.frame is not None:
        return None
    return call if prim.actions is None and prim.table is None and prim.lines is None and not prim.ranged else None


def _composed(plan: Input, call: Call) -> Request:
    """The general way of an input written at once (`Robot._input`), as one function."""
    kinds, args_of, floats, values_of = plan.kinds, plan.args, plan.interface.floats, call.args
    assert isinstance(call.target, Primitive)  # `_written_at_once`
    encoder = call.target.encoder
    assert isinstance(encoder, Pack)
    pack = encoder.struct.pack

    def request(state: StateValues, values: Args) -> bytes | None:
        for value, kind in zip(values, kinds):
            if type(value) is not kind:
                return None
        try:
            args = args_of(state, values)
            for i in floats:
                if type(args[i]) is int:
                    args[i] = float(args[i])
            return pack(*values_of(state, args))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    return request


@dataclass(frozen=True, slots=True)
class Hook:
    """A connection's startup, terminate or keepalive call: an interface, arguments over state."""

    interface: Interface
    args: Callable[[StateValues], Args]


@dataclass(frozen=True, slots=True)
class Connection:
    """A transport and what runs on it: hooks, periodic interfaces, its thread's frequency."""

    name: str
    baud: int
    address: str | None = None  # opened when no port is given
    terminator: bytes = b"\n"  # ends a reply line
    frequency: float = 0.0  # ticks a second
    periodic: tuple[Interface, ...] = ()
    startup: Hook | None = None
    terminate: Hook | None = None
    keepalive: Hook | None = None
    interval: float = 0.0  # seconds between keepalives
    baud_setting: str | None = None  # the setting that gives the baud rate (`baud` is its default)


@dataclass(frozen=True, slots=True)
class Device:
    """A whole description, planned: what a Robot runs."""

    name: str
    state: Mapping[str, Value]  # the initial values, and the settings' defaults
    connections: Mapping[str, Connection]
    primitives: Mapping[str, Primitive]
    interfaces: Mapping[str, Interface]
    inputs: Mapping[str, Input]
    settings: tuple[Param, ...] = ()  # given when connecting; read as state is, never written
    messages: Mapping[str, Message] = field(default_factory=dict)  # by adapter: how a recording carries it


@dataclass(frozen=True, slots=True)
class Message:
    """The ROS 2 message a recording (`--record`) carries an adapter's values as: its type
    (`geometry_msgs/msg/Twist`), its definition with those of the messages it uses (the
    `ros2msg` schema text), the adapter's fields and where each goes (`linear.x`, `position[0]`,
    `pose.pose.orientation:yaw` for a quaternion given by its yaw)."""

    type: str
    definition: str
    fields: tuple[str, ...]
    paths: tuple[str, ...]


def _floats(params: tuple[Param, ...]) -> tuple[int, ...]:
    return tuple(i for i, p in enumerate(params) if p.kind is float)


def lookup(table: str, entries: Mapping[Any, Any], key: Any) -> Any:
    """`table[key]` of a description's lookup table: a key it lacks is an error, never a default."""
    try:
        return entries[key]
    except (KeyError, TypeError):
        raise ValueError(f"table {table} has no entry for {key!r}") from None


def element(array: str, values: tuple[Any, ...], index: int) -> Any:
    """`array[index]`: an index outside the array is an error, never wrapped (`a[-1]` too)."""
    if not 0 <= index < len(values):
        raise ValueError(f"index {index} is outside {array}, which has {len(values)} values")
    return values[index]


def replaced(array: str, values: tuple[Any, ...], index: int, value: Any) -> tuple[Any, ...]:
    """The array with `values[index]` made `value` (`array[index] = value` in a post-action)."""
    element(array, values, index)
    if type(value) is int and not -MAX_INT <= value <= MAX_INT:
        raise ValueError(f"{array}[{index}] would be a {value.bit_length()}-bit integer; "
                         "integers are limited to 64 bits and a sign")
    return values[:index] + (value,) + values[index + 1 :]


def _ranged(params: tuple[Param, ...]) -> tuple[int, ...]:
    return tuple(i for i, p in enumerate(params) if p.low is not None)


# ---- values given by the host --------------------------------------------------------------------------

_KIND_NAMES: dict[type, str] = {int: "int", float: "float", bool: "bool", str: "string", bytes: "bytes"}


def _accept(value: Any, kind: type, what: str) -> Any:
    """A value given for a parameter or field of type `kind`, made that type; else TypeError.

    An int is taken for a float; bytes are bytes, a bytearray, a list of ints 0..255 or
    hex text ("3c20")."""
    if type(value) is kind:
        return value
    if kind is float and isinstance(value, numbers.Real) and not isinstance(value, bool):
        return float(value)
    if kind is int and isinstance(value, numbers.Integral) and not isinstance(value, bool):
        return int(value)
    if kind is str and isinstance(value, str):
        return value
    if kind is bytes and isinstance(value, str):
        try:
            return bytes.fromhex(value)
        except ValueError:
            raise TypeError(f"{what} must be bytes, as hex such as 3c20 (two digits a byte), not {value!r}") from None
    if kind is bytes:
        try:
            if isinstance(value, (bytes, bytearray, memoryview, list, tuple)):
                return bytes(value)
        except (ValueError, TypeError) as err:
            raise TypeError(f"{what} must be bytes: {err}") from None
    raise TypeError(f"{what} must be {_KIND_NAMES[kind]}, not {type(value).__name__} {value!r}")


def _bind(what: str, params: tuple[Param, ...], args: tuple[Any, ...], kwargs: dict[str, Any]) -> Args:
    """Arguments by position and by name, as Python binds them."""
    if len(args) > len(params):
        raise TypeError(f"{what} takes {len(params)} arguments, {len(args)} given")
    if not kwargs and len(args) == len(params):  # every argument by position: nothing to bind
        return list(args)
    return [*args, *bind_named(what, params[len(args) :], kwargs).values()]


def _accepted(what: str, params: tuple[Param, ...], values: Args) -> Args:
    """Values given by position, each made its parameter's type (TypeError if it cannot be); the
    parameters left out take their defaults."""
    if len(values) != len(params):
        left_out = params[len(values) :]
        if len(values) > len(params) or any(p.default is None for p in left_out):
            required = next((i for i, p in enumerate(params) if p.default is not None), len(params))
            takes = len(params) if required == len(params) else f"{required} to {len(params)}"
            raise TypeError(f"{what} takes {takes} arguments, {len(values)} given")
        values.extend(p.default for p in left_out)
    for i, param in enumerate(params):
        if type(values[i]) is not param.kind or param.size is not None:
            values[i] = _accept_param(values[i], param, f"{what}: parameter {param.name}")
    return values


def _accept_param(value: Any, param: Param, what: str) -> Any:
    """A value given for a parameter or an input's field, made its type (TypeError if it cannot be)."""
    if param.size is not None:
        return _accept_array(value, param, what)
    return _accept(value, param.kind, what)


def _accept_array(value: Any, param: Param, what: str) -> tuple[Any, ...]:
    """A list or tuple of the array's size (any size if open), each element made its type."""
    if not isinstance(value, (list, tuple)):
        raise TypeError(f"{what} must be a list of {param.size or 'any number of'} "
                        f"{_KIND_NAMES[param.kind]}s, not {type(value).__name__}")
    if param.size and len(value) != param.size:
        raise TypeError(f"{what} must have {param.size} values, not {len(value)}")
    return tuple(v if type(v) is param.kind else _accept(v, param.kind, f"{what}[{i}]") for i, v in enumerate(value))


def _widen(owner: str, floats: tuple[int, ...], values: Args) -> None:
    """Computed values bound to float parameters: an int made a float, in place."""
    try:
        for i in floats:
            if type(values[i]) is int:
                values[i] = float(values[i])
            elif type(values[i]) is tuple:  # an array of floats computed from ints
                values[i] = tuple(float(v) for v in values[i])
    except OverflowError as err:  # an int too large for a float
        raise RdisValueError(f"{owner}: {err}") from None


def _in_ranges(owner: str, params: tuple[Param, ...], ranged: tuple[int, ...], values: Args,
               role: str = "parameter") -> None:
    """A value outside its parameter's (or setting's) declared range is refused before anything is sent."""
    for i in ranged:
        p, value = params[i], values[i]
        low, high = p.low, p.high
        assert low is not None and high is not None  # `ranged` holds the parameters with a range
        if isinstance(value, bytes):
            if not low <= len(value) <= high:
                raise RdisValueError(f"{owner}: {role} {p.name} has {len(value)} bytes, outside {low!r}..{high!r}")
        elif isinstance(value, tuple):
            for k, item in enumerate(value):
                if not low <= item <= high:
                    raise RdisValueError(f"{owner}: {role} {p.name}[{k}] is {item!r}, outside {low!r}..{high!r}")
        elif not low <= value <= high:
            raise RdisValueError(f"{owner}: {role} {p.name} is {value!r}, outside {low!r}..{high!r}")


def bind_settings(device: Device, given: Mapping[str, Any] | None) -> dict[str, Value]:
    """The settings given when connecting, by name, each made its type (an int taken for a float)
    and checked against its range and the width of integers; the others keep their defaults.
    A name the description does not declare, or a value that does not fit, is an RdisValueError
    naming the setting, raised before any port is opened."""
    bound = {p.name: device.state[p.name] for p in device.settings}
    declared = {p.name: p for p in device.settings}
    for name, value in (given or {}).items():
        param = declared.get(name)
        if param is None:
            known = ", ".join(declared) or "none"
            raise RdisValueError(f"{device.name}: no setting named {name!r} (its settings: {known})")
        try:
            accepted = _accept_param(value, param, f"{device.name}: setting {name}")
        except TypeError as err:
            raise RdisValueError(str(err)) from None
        for item in accepted if param.size is not None else (accepted,):
            _within_width(item, f"{device.name}: setting {name}")
        if param.low is not None:
            _in_ranges(device.name, (param,), (0,), [accepted], "setting")
        bound[name] = accepted
    return bound


def _within_width(value: Any, what: str) -> None:
    if type(value) is int and not -MAX_INT <= value <= MAX_INT:
        raise RdisValueError(f"{what} is a {value.bit_length()}-bit integer; integers are limited to 64 bits and a sign")


class Unbound(TypeError):
    """Values given by name that do not bind to the parameters: the first name of none of them
    (`unknown`), else the first parameter given no value and without a default (`missing`)."""

    def __init__(self, what: str, unknown: str | None, missing: str | None) -> None:
        super().__init__(f"{what}: unexpected argument {unknown!r}" if unknown is not None
                         else f"{what}: missing argument {missing!r}")
        self.unknown = unknown
        self.missing = missing


def bind_named(what: str, params: tuple[Param, ...], given: Mapping[str, Any],
               read: Callable[[Any, Param], Any] | None = None) -> dict[str, Any]:
    """Values given by name bound to the parameters (or fields), in their order, each made its type
    by `read` if given; a parameter left out takes its default. The one binding of the typed API,
    `--call`, the console and a replay."""
    values: dict[str, Any] = {}
    missing = None
    found = 0
    for param in params:
        if param.name in given:
            values[param.name] = given[param.name]
            found += 1
        elif param.default is not None:
            values[param.name] = param.default
        elif missing is None:
            missing = param.name
    if found < len(given):
        raise Unbound(what, next(name for name in given if name not in values), None)
    if missing is not None:
        raise Unbound(what, None, missing)
    if read is not None:
        for param in params:
            if param.name in given:
                values[param.name] = read(values[param.name], param)
    return values


def call_values(device: Device, kind: object, name: str, given: Mapping[str, Any],
                read: Callable[[Any, Param, str], Any] | None = None) -> dict[str, Value]:
    """The values given by name (text, or JSON) of a call of the input, interface or primitive
    `name`: `bind_named` with `read_value` (or `read`, which calls it). KeyError if there is no
    such element; Unbound, TypeError or RdisValueError (naming the parameter) if they do not fit."""
    if kind not in ("input", "interface", "primitive"):
        raise ValueError(f"a call is of an input, an interface or a primitive, not {kind!r}")
    plans: Mapping[str, Input | Interface | Primitive] = (
        device.inputs if kind == "input" else device.interfaces if kind == "interface" else device.primitives)
    plan = plans.get(name)
    if plan is None:
        raise KeyError(f"{device.name} has no {kind} named {name!r}")
    reader = read_value if read is None else read
    if isinstance(plan, Input):
        return bind_named(f"input {name}", plan.fields, given,
                          lambda value, p: reader(value, p, f"input {name}: field {p.name}"))
    return bind_named(f"{kind} {name}", plan.params, given,
                      lambda value, p: reader(value, p, f"{kind} {name}: parameter {p.name}"))


def read_value(given: Any, param: Param, what: str) -> Any:
    """A value given from outside Python for a parameter, field or setting, made its type: text (a
    `--call` or `--set` K=V, a console's form) or a JSON value (a recording). A number is written as
    a description writes one (`42`, `0x2A`, `-1.5e3`), in ASCII, finite and within 64 bits and a
    sign, else it is an RdisValueError naming `what`; an array is `[a, b]` (or `a, b`) or a list;
    bytes are hex; an empty text is the default, if there is one, of any type but string and bytes.
    Any other value is taken as the typed API takes it (a TypeError if it does not fit)."""
    if given == "" and param.default is not None and (param.size is not None or param.kind not in (str, bytes)):
        return param.default
    if param.size is None:
        return _accept(_read_item(given, param.kind, what), param.kind, what)
    if isinstance(given, str):
        inner = given.strip()
        inner = inner[1:-1] if inner.startswith("[") and inner.endswith("]") else inner
        given = [item.strip() for item in inner.split(",")] if inner.strip() else []
    if isinstance(given, (list, tuple)):
        given = tuple(_read_item(item, param.kind, f"{what}[{i}]") for i, item in enumerate(given))
    return _accept_array(given, param, what)


def _read_item(given: Any, kind: type, what: str) -> Any:
    """One value (or an array's element) read: a number's text as its number, checked; a text that
    is no number is left for the type check to refuse."""
    if isinstance(given, float) and not math.isfinite(given):
        raise RdisValueError(f"{what} is {given!r}: a number must be finite")
    if not isinstance(given, str) or kind in (str, bytes):
        _within_width(given, what)
        return given
    text = given.strip()
    if text in ("True", "true", "False", "false"):
        return text in ("True", "true")
    shown = repr(text) if len(text) <= 40 else f"{text[:30]!r}... ({len(text)} characters)"
    if kind is not bool and not text.isascii():  # Python would read '٣٣' as 33
        raise RdisValueError(f"{what} is {shown}: a number is written in ASCII")
    digits = text.lstrip("+-").replace("_", "")
    number: int | float
    try:
        number = float(text) if kind is float and digits[:2].lower() not in ("0x", "0b", "0o") else int(text, 0)
    except ValueError:
        if digits.isdigit():  # `010` is no number, as in a description; or too many digits to read
            if len(digits) > 20:
                raise RdisValueError(f"{what} is {shown}: integers are limited to 64 bits and a sign") from None
            return given
        if kind is float:
            return given
        try:  # `1.5` or `1e400` for an int
            number = float(text)
        except ValueError:
            return given
    if not math.isfinite(number):
        raise RdisValueError(f"{what} is {shown}: a number must be finite")
    _within_width(number, what)
    return number


class State(Mapping[str, Value]):
    """The state variables at one moment: `state["name"]` or `state.name`. Immutable: the
    robot publishes a new snapshot after each primitive's post-actions."""

    __slots__ = ("_values",)

    def __init__(self, values: StateValues) -> None:
        self._values = values

    def __getitem__(self, name: str) -> Value:
        value: Value = self._values[name]
        return value

    def __getattr__(self, name: str) -> Value:
        try:
            value: Value = self._values[name]
            return value
        except KeyError:
            raise AttributeError(f"no state variable {name!r}") from None

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __repr__(self) -> str:
        return f"State({dict(self._values)!r})"


class Calls:
    """`robot.inputs`, `robot.interfaces` or `robot.primitives`: each element of that kind
    as a method of its name (an input takes its fields by name, the others their
    parameters by position or name)."""

    __slots__ = ("_kind", "_robot")

    def __init__(self, robot: Robot, kind: str) -> None:
        self._robot = robot
        self._kind = kind

    def _plans(self) -> Mapping[str, Input | Interface | Primitive]:
        device = self._robot.device
        if self._kind == "input":
            return device.inputs
        return device.interfaces if self._kind == "interface" else device.primitives

    def __getattr__(self, name: str) -> Callable[..., None]:
        plan = self._plans().get(name)
        if plan is None:
            raise AttributeError(f"{self._robot.name} has no {self._kind} named {name!r}")
        robot = self._robot
        if isinstance(plan, Input):
            return lambda **fields: robot.call_input(name, **fields)
        if isinstance(plan, Interface):
            interface = plan
            return lambda *args, **kwargs: robot._call_interface(
                interface, _bind(f"interface {name}", interface.params, args, kwargs))
        primitive = plan
        return lambda *args, **kwargs: robot._call_primitive(
            primitive, _bind(f"primitive {name}", primitive.params, args, kwargs))

    def __dir__(self) -> list[str]:
        return sorted(self._plans())


# ---- ports --------------------------------------------------------------------------------------------


class Port(Protocol):
    """What the robot needs of an open port; pyserial's `Serial` has all of it (`dtr` and `rts`,
    its modem lines, only a primitive with `lines` sets)."""

    timeout: float | None
    dtr: bool
    rts: bool

    def write(self, data: bytes, /) -> int | None: ...

    def read(self, size: int = 1, /) -> bytes: ...

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes: ...

    def reset_input_buffer(self) -> None: ...

    def close(self) -> None: ...


PortSpec = str | os.PathLike[str] | Port | Mapping[str, "str | os.PathLike[str] | Port"]
"""A port for every connection (a pyserial port name or URL, or an open port), or a dict
from connection name to port."""


class Simulator(Protocol):
    """A simulated device in place of the ports (`Robot.open(sim=...)`; `rdisc.sim` gives one
    over MuJoCo): it takes what the host commands, by primitive and interface with their
    parameters' values, and answers a primitive's reply with its values (`replies N` or
    `replies { }`: a list of a reply for each of its `answers`, each its values). In simulated time
    (`realtime` False) the robot runs no threads: its schedule and delays advance the simulation."""

    realtime: bool

    def interface(self, plan: Interface, args: Args, /) -> None: ...

    def exchange(self, plan: Primitive, local: Args, /) -> Sequence[Any]: ...

    def advance(self, seconds: float, /) -> None: ...

    def now(self) -> float: ...


class _Port:
    """One open port, shared by the connections given the same one, with its exchange lock."""

    __slots__ = ("input", "io", "lock", "owned")

    def __init__(self, io: Port, owned: bool) -> None:
        self.io = io
        self.input = Incoming(io)  # what replies are read from: bytes put back, bytes taken, the deadline
        self.owned = owned  # opened by the robot, so closed by it too
        # Re-entrant: a signal landing between a command's `acquire` and its `try` leaves the lock
        # held by the interrupted thread, which must still write the terminate hook's stop command.
        self.lock = threading.RLock()


class _Link:
    """A connection and its port."""

    __slots__ = ("connection", "port")

    def __init__(self, connection: Connection, port: _Port) -> None:
        self.connection = connection
        self.port = port


def _open_port(connection: Connection, url: str, timeout: float, baud: int) -> Port:
    """A port opened with pyserial (any port name or URL it knows) at `baud`, 8N1."""
    try:
        import serial  # type: ignore[import-untyped, import-not-found, unused-ignore]
    except ImportError as err:
        raise RdisConnectionError(f"{connection.name}: opening {url} needs pyserial (pip install pyserial)") from err
    try:
        port: Port = serial.serial_for_url(url, baudrate=baud, bytesize=8, parity="N", stopbits=1,
                                           timeout=timeout, write_timeout=timeout)
    except (serial.SerialException, OSError, ValueError) as err:
        raise RdisConnectionError(f"{connection.name}: cannot open {url}: {err}") from err
    return port


def _write_timed_out(err: BaseException) -> bool:
    """Whether a port's exception is pyserial's for a write that could not complete in time."""
    serial = sys.modules.get("serial")  # a port that raises it has imported it
    timeout_type = getattr(serial, "SerialTimeoutException", None) if serial is not None else None
    return timeout_type is not None and isinstance(err, timeout_type)


# ---- the schedule of a connection ----------------------------------------------------------------


class _Worker:
    """One connection's own work (its periodic interfaces, its keepalive) and when it is due.

    Tick k is due at start + k / frequency; a tick already past when the previous one
    ends is skipped, not run in a burst. The keepalive is due one interval after start,
    then every interval after the time it was due (or one interval after now, if that is
    past too). The thread waits on an Event between ticks, so it never spins, and wakes
    at once when stopped.
    """

    def __init__(self, robot: Robot, connection: Connection) -> None:
        self.robot = robot
        self.connection = connection
        self.period = 1.0 / connection.frequency if connection.frequency > 0 else math.inf
        self.interval = connection.interval if connection.keepalive is not None else 0.0
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self.restart_clock()

    def restart_clock(self) -> None:
        """Make now the start of the schedule."""
        with self._lock:
            self._start = self.robot._clock()
            self._keepalive_due = self._start + self.interval

    def tick(self) -> None:
        """One iteration: each periodic interface, then the keepalive if it is due. Errors go
        to the error callbacks, and the schedule goes on."""
        robot = self.robot
        for interface in self.connection.periodic:
            if self._stop.is_set():
                return
            if robot._run_callbacks:
                robot._notify_run(self.connection.name, "periodic", interface.name)
            try:
                robot._interface(interface, [])
            except Exception as err:  # noqa: BLE001 - reported; the schedule goes on
                robot._report(err)
        keepalive = self.connection.keepalive
        if keepalive is None or not self.interval:
            return
        with self._lock:
            now = robot._clock()
            if now < self._keepalive_due:
                return
            due = self._keepalive_due + self.interval
            self._keepalive_due = due if due > now else now + self.interval
        if robot._run_callbacks:
            robot._notify_run(self.connection.name, "keepalive", keepalive.interface.name)
        try:
            robot._hook(keepalive)
        except Exception as err:  # noqa: BLE001 - reported; the schedule goes on
            robot._report(err)

    def start(self) -> None:
        self.restart_clock()
        # Kept before it starts: a signal may interrupt `start()` once the thread exists.
        self._thread = threading.Thread(target=self._loop, name=f"{self.robot.name} {self.connection.name}",
                                        daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop the thread; it finishes the interface it is running first."""
        self._stop.set()
        thread = self._thread
        if thread is not None and thread is not threading.current_thread():
            try:
                thread.join()
            except RuntimeError:  # its start was interrupted before it ran: it will see the stop and end
                pass

    def _loop(self) -> None:
        periodic = bool(self.connection.periodic)
        if not periodic and not self.interval:
            self._stop.wait()
            return
        k = 0
        while not self._stop.is_set():
            self.tick()
            if periodic:
                k = max(k + 1, math.ceil((time.monotonic() - self._start) / self.period))
                wake = self._start + k * self.period
            else:  # only a keepalive: wake when it is due
                wake = self._keepalive_due
            delay = wake - time.monotonic()
            if delay > 0 and self._stop.wait(delay):
                return


# ---- the robot ------------------------------------------------------------------------------------------


class Robot:
    """A description's devices, driven: `open()` opens the ports, runs the startup hooks
    and starts one thread per connection; `close()` (or leaving a `with` block) stops
    them, runs the terminate hooks and closes the ports.

    State lives in a dict that is never changed in place: post-actions build a new one
    under the state lock and publish it with one assignment, so any reader sees a
    consistent snapshot without locking.
    """

    def __init__(self, device: Device, *, timeout: float = 1.0) -> None:
        """A robot not connected yet; `timeout`: seconds a reply may take."""
        self.device = device
        self.name = device.name
        self.timeout = timeout
        self._state: dict[str, Value] = dict(device.state)
        self._state_lock = threading.Lock()
        self._callback_lock = threading.RLock()  # callbacks run one at a time
        self._output_callbacks: list[OutputCallback] = []
        self._error_callbacks: list[ErrorCallback] = []
        self._io_callbacks: list[IoCallback] = []
        self._run_callbacks: list[Callable[[str, str, str], object]] = []  # a Recorder's: what a thread runs
        self._links: dict[str, _Link] = {}
        self._workers: list[_Worker] = []
        self._close_lock = threading.Lock()
        self._running = False
        self._direct = False  # running on ports: a plain write may skip the general way
        self._closed = False
        self._sim: Simulator | None = None
        self._clock: Callable[[], float] = time.monotonic  # the schedule's time, and the delays'
        self._sleep: Callable[[float], None] = time.sleep

    # ---- callbacks --------------------------------------------------------------------------------

    def on_output(self, callback: OutputCallback) -> OutputCallback:
        """Call `callback({"name": ..., "contents": {...}})` for every output triggered."""
        with self._callback_lock:
            self._output_callbacks.append(callback)
        return callback

    def on_error(self, callback: ErrorCallback) -> ErrorCallback:
        """Call `callback(error)` for every error of periodic work, keepalives, terminate hooks
        and callbacks (with none registered, errors are logged to the "rdisc" logger)."""
        with self._callback_lock:
            self._error_callbacks.append(callback)
        return callback

    def on_io(self, callback: IoCallback) -> IoCallback:
        """Call `callback("write" | "read", connection, data)` for every write, and for every
        byte read, whatever became of it; `callback("lines", connection, b"dtr=False")` for the
        modem lines a primitive set, before its write."""
        with self._callback_lock:
            self._io_callbacks.append(callback)
        return callback

    # ---- what the host can see and call -------------------------------------------------------------

    @property
    def state(self) -> State:
        """The state variables now: an immutable snapshot, `robot.state["name"]` or `.name`."""
        return State(self._state)

    @property
    def closed(self) -> bool:
        return self._closed

    @property
    def inputs(self) -> Any:  # a Calls; a generated driver gives a class of typed methods
        """The domain inputs, by name: `robot.inputs.NAME(field=value, ...)`."""
        return Calls(self, "input")

    @property
    def interfaces(self) -> Any:  # a Calls, or a driver's typed methods
        """The interfaces, by name: `robot.interfaces.NAME(param, ...)`."""
        return Calls(self, "interface")

    @property
    def primitives(self) -> Any:  # a Calls, or a driver's typed methods
        """The primitives (device commands), by name: `robot.primitives.NAME(param, ...)`."""
        return Calls(self, "primitive")

    def call_input(self, name: str, /, **fields: Any) -> None:
        """Run a domain input with its adapter's fields by name, on this thread; errors are raised."""
        plan = self.device.inputs.get(name)
        if plan is None:
            raise KeyError(f"{self.name} has no input named {name!r}")
        try:
            if len(fields) != len(plan.fields):
                raise KeyError(name)
            values = [fields[f.name] for f in plan.fields]
        except KeyError:
            expected = ", ".join(f.name for f in plan.fields)
            raise TypeError(f"input {name} takes the fields {expected} ({plan.adapter}); "
                            f"given: {', '.join(fields) or 'none'}") from None
        self._input(plan, values)

    def call_interface(self, name: str, /, *args: Any) -> None:
        """Run an interface with positional arguments, on this thread; errors are raised."""
        plan = self.device.interfaces.get(name)
        if plan is None:
            raise KeyError(f"{self.name} has no interface named {name!r}")
        self._call_interface(plan, list(args))

    def call_primitive(self, name: str, /, *args: Any) -> None:
        """Send one device command (a primitive) with positional arguments, read its reply and
        run its post-actions, on this thread; errors are raised."""
        plan = self.device.primitives.get(name)
        if plan is None:
            raise KeyError(f"{self.name} has no primitive named {name!r}")
        values = list(args)
        request = plan.request
        if request is not None and self._direct:  # one plain write: every command's path
            data = request(self._state, values)
            if data is not None:
                self._write(plan, data)
                return
        self._call_primitive(plan, values)

    # ---- lifecycle ----------------------------------------------------------------------------------

    def open(self, port: PortSpec | None = None, *, threads: bool = True,
             settings: Mapping[str, Any] | None = None, sim: Simulator | None = None) -> None:
        """Bind the settings, open the ports, run the startup hooks, then start the connections' threads.

        `port`: a pyserial port name or URL ("/dev/ttyUSB0", "COM3", "socket://host:4000")
        or an open port object, for every connection; or a dict {connection: port}; a
        connection given none opens its address from the description. `settings`: values
        of the description's settings by name (the others keep their defaults); one that
        does not fit is an RdisValueError, before anything is opened. With
        `threads=False` no thread is started: call `tick()` from your own loop. If any of
        it fails, what was opened is closed again (terminate hooks included) and the
        error is raised. `sim`: a simulated device in place of the ports (no port is
        opened); in simulated time no thread is started either: `run_for` runs the schedule.
        """
        if self._running or self._closed:
            raise RdisConnectionError(f"{self.name}: already opened")
        self._state = {**self._state, **bind_settings(self.device, settings)}
        try:
            if sim is None:
                self._open_links(port)
            else:
                self._simulate(sim)
                threads = threads and sim.realtime
            self._running = True
            self._direct = sim is None
            self.startup()
            self._workers = [_Worker(self, c) for c in self.device.connections.values()]
            for worker in self._workers:
                if threads:
                    worker.start()
        except BaseException:
            self.close()
            raise

    def startup(self) -> None:
        """Run the startup hooks, in declaration order (`open()` does); errors are raised."""
        for connection in self.device.connections.values():
            if connection.startup is not None:
                self._hook(connection.startup)

    def terminate(self) -> None:
        """Run the terminate hooks of the connections that are open, in declaration order
        (`close()` does): they leave the robot stopped. Errors are reported, not raised."""
        for connection in self.device.connections.values():
            if connection.terminate is not None and (connection.name in self._links or self._sim is not None):
                try:
                    self._hook(connection.terminate)
                except Exception as err:  # noqa: BLE001 - reported, and the others run
                    self._report(err)

    def tick(self) -> None:
        """One iteration of every connection's work on this thread, in declaration order: its
        periodic interfaces, then its keepalive if due. Errors are reported, as the threads' are."""
        if not self._running:
            raise self._not_running()
        for worker in self._workers:
            worker.tick()

    def run_for(self, seconds: float | None) -> None:
        """Run the connections' schedules for `seconds` of simulated time (None: for ever), on
        this thread: each connection's tick when it is due, as its thread would run it, the
        simulation advanced up to it (and by the delays within it)."""
        sim = self._sim
        if sim is None or sim.realtime or not self._running:
            raise RdisConnectionError(f"{self.name}: not running in simulated time")
        end = math.inf if seconds is None else sim.now() + seconds
        ticks = dict.fromkeys(self._workers, 0)  # each periodic connection's next tick
        while True:
            due = {w: w._start + k * w.period if w.connection.periodic else w._keepalive_due if w.interval else math.inf
                   for w, k in ticks.items()}
            wake = min(due.values(), default=math.inf)
            if wake > end:
                sim.advance(end - sim.now())
                return
            sim.advance(max(wake - sim.now(), 0.0))
            for worker, when in due.items():
                if when <= wake:
                    worker.tick()  # as the thread's loop: a tick already past is skipped
                    if worker.connection.periodic:
                        late = math.ceil((sim.now() - worker._start) / worker.period - 1e-9)
                        ticks[worker] = max(ticks[worker] + 1, late)

    def close(self) -> None:
        """Stop the threads (each finishes the interface it is running, delays included), run
        the terminate hooks (errors reported, not raised) and close the ports `open` opened.
        Idempotent; the robot does nothing more afterwards."""
        with self._close_lock:
            if self._closed:
                return
            self._closed = True
            self._running = False
            self._direct = False
        for worker in self._workers:
            worker.stop()
        self.terminate()
        for port in {id(link.port): link.port for link in self._links.values()}.values():
            if port.owned:
                try:
                    port.io.close()
                except Exception:  # noqa: BLE001, S110 - a port that fails to close is closed enough
                    pass

    def __enter__(self) -> Robot:  # noqa: PYI034 - typing.Self needs Python 3.11
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _not_running(self) -> RdisConnectionError:
        return RdisConnectionError(f"{self.name}: {'closed' if self._closed else 'not open'}")

    def _open_links(self, port: PortSpec | None) -> None:
        """A port for each connection: one name or URL is opened once and shared, with one
        lock; an open port object is used as it is and never closed here; a connection
        given no port opens its address."""
        connections = self.device.connections
        given: dict[str, Any]
        if isinstance(port, Mapping):
            unknown = [name for name in port if name not in connections]
            if unknown:
                raise ValueError(f"{self.name} has no connection named {unknown[0]!r} "
                                 f"(its connections: {', '.join(connections) or 'none'})")
            given = dict(port)
        else:
            given = dict.fromkeys(connections, port) if port is not None else {}
        for name, connection in connections.items():
            if name not in given:
                if connection.address is None:
                    raise ValueError(f"no port given for connection {name!r}, which has no `address`")
                given[name] = connection.address
        opened: dict[object, _Port] = {}
        for name, where in given.items():
            by_name = isinstance(where, (str, os.PathLike))
            key: object = os.fspath(where) if by_name else id(where)
            if key not in opened:
                connection = connections[name]
                setting = connection.baud_setting  # an int setting: the checker holds it to that type
                baud: Any = self._state[setting] if setting is not None else connection.baud
                io = _open_port(connection, os.fspath(where), self.timeout, baud) if by_name else where
                opened[key] = _Port(io, owned=by_name)
            self._links[name] = _Link(connections[name], opened[key])

    # ---- running the plans --------------------------------------------------------------------------

    def _input(self, plan: Input, values: Args) -> None:
        """Run an input with its fields' values by position (each made its type here)."""
        if not self._running:
            raise self._not_running()
        request = plan.request
        if request is not None:  # one plain write: every command's path
            data = request(self._state, values)
            if data is not None:
                assert plan.primitive is not None
                self._write(plan.primitive, data)
                return
        self._input_in_full(plan, values)

    def _input_in_full(self, plan: Input, values: Args) -> None:
        """An input the general way: its fields made their types, its interface's arguments."""
        if not self._running:
            raise self._not_running()
        for i, param in enumerate(plan.fields):
            if type(values[i]) is not param.kind or param.size is not None:
                values[i] = _accept_param(values[i], param, f"input {plan.name}: field {param.name}")
        try:
            args = plan.args(self._state, values)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        for param, value in zip(plan.interface.params, args):
            if param.size and len(value) != param.size:  # an adapter's array, of any size, into one of a fixed size
                raise RdisValueError(f"{plan.name}: {plan.interface.name} takes {param.size} values for "
                                     f"{param.name}, not {len(value)}")
        self._interface(plan.interface, args)

    def _call_interface(self, plan: Interface, values: Args) -> None:
        """Run an interface the host called, with its parameters' values by position."""
        if not self._running:
            raise self._not_running()
        self._interface(plan, _accepted(f"interface {plan.name}", plan.params, values))

    def _call_primitive(self, plan: Primitive, values: Args) -> None:
        """Run a primitive the host called, with its parameters' values by position."""
        if not self._running:
            raise self._not_running()
        self._primitive(plan, _accepted(f"primitive {plan.name}", plan.params, values))

    def _hook(self, hook: Hook) -> None:
        try:
            args = hook.args(self._state)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{hook.interface.name}: {err}") from None
        self._interface(hook.interface, args)

    def _interface(self, plan: Interface, args: Args) -> None:
        """Run an interface with its parameters' values: its calls in order, each followed by
        its delay, then its output. An error stops it where it happened."""
        for i in plan.floats:  # (inline: this is every command's path)
            if type(args[i]) is int:
                _widen(plan.name, plan.floats, args)
                break
        if plan.ranged:
            _in_ranges(plan.name, plan.params, plan.ranged, args)
        for call in plan.calls:
            try:
                if call.when is not None and not call.when(self._state, args):
                    continue  # not made, and so no delay after it
                values = call.args(self._state, args)
            except EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
            target = call.target
            if isinstance(target, Interface):
                self._interface(target, values)
            elif call.direct:  # the call's values are the primitive's format values
                self._exchange(target, values, values)
            else:
                self._primitive(target, values)
            if call.delay:
                self._sleep(call.delay)
        for output in plan.outputs:
            self._deliver(output)

    def _primitive(self, plan: Primitive, args: Args) -> None:
        """Run a primitive with its parameters' values: its reply table's entry, if it has
        one, then the exchange."""
        request = plan.request
        if request is not None:  # one plain write
            data = request(self._state, args)
            if data is not None:
                self._write(plan, data)
                return
        self._primitive_in_full(plan, args)

    def _primitive_in_full(self, plan: Primitive, args: Args) -> None:
        """A primitive the general way: its parameters checked, its reply table's entry chosen."""
        for i in plan.floats:
            if type(args[i]) is int:
                _widen(plan.name, plan.floats, args)
                break
        if plan.ranged:
            _in_ranges(plan.name, plan.params, plan.ranged, args)
        if plan.key >= 0:
            assert plan.table is not None  # and the key's range holds every key of it
            plan = plan.table[args[plan.key]]
        try:
            values = plan.values(self._state, args)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        self._exchange(plan, values, args)

    def _write(self, plan: Primitive, request: bytes, levels: dict[str, Value] | None = None) -> None:
        """Under the port's lock set the modem lines, if any, then write a request that has no
        reply (if the primitive has one); then show the I/O callbacks."""
        link = self._links.get(plan.connection)
        if link is None:
            raise RdisConnectionError(f"{plan.connection}: not open")
        port = link.port
        lock = port.lock
        lock.acquire()  # acquire/release rather than `with`: cheaper, and this is every command's path
        try:
            if levels is not None:
                self._set_lines(plan, port.io, levels)
            if plan.encoder is not None:
                port.io.write(request)
        except RdisError:
            raise
        except Exception as err:  # whatever the port raises, it failed
            raise self._port_error(plan, err) from err
        finally:
            lock.release()
        if self._io_callbacks:
            if levels is not None:
                self._notify_io("lines", plan.connection, _lines_text(levels))
            if plan.encoder is not None:
                self._notify_io("write", plan.connection, request)

    @staticmethod
    def _set_lines(plan: Primitive, io: Port, levels: dict[str, Value]) -> None:
        """Set the primitive's modem lines in the order written (pyserial's `dtr` and `rts`). A
        port that refuses (a pty, a port with no modem lines) is an RdisConnectionError."""
        for line, level in levels.items():
            try:
                if line == "dtr":
                    io.dtr = bool(level)
                else:
                    io.rts = bool(level)
            except Exception as err:  # whatever the port raises, it refused
                raise RdisConnectionError(f"{plan.connection}: {plan.name}: cannot set {line} = {bool(level)}: "
                                          f"{err}") from err

    def _exchange(self, plan: Primitive, values: Args, local: Args) -> None:
        """Encode and frame the request; under the port's lock write it and read the reply;
        then show the I/O callbacks every byte written and read, and run the post-actions.

        `local` is the primitive's parameters' values (a direct call passes its values)."""
        request, fields, levels = self._request(plan, values, local)
        if not plan.expects_reply:
            self._write(plan, request, levels)
            if plan.actions is not None:
                self._assign(plan, local, ())
            return
        link = self._links.get(plan.connection)
        if link is None:
            raise RdisConnectionError(f"{plan.connection}: not open")
        port = link.port
        io = port.io
        lock = port.lock
        reader = port.input
        wait = plan.timeout or self.timeout
        reply: Sequence[Any] = ()
        failed: BaseException | None = None
        lines_set = written = False
        lock.acquire()
        try:
            if levels is not None:
                self._set_lines(plan, io, levels)
                lines_set = True
            if request:  # a listener (no request) keeps what has arrived: its reply is the next one
                io.reset_input_buffer()
                reader.clear()
                io.write(request)
                written = True
            if plan.timeout is not None:
                io.timeout = plan.timeout
            reader.begin(wait)
            if plan.answers:
                reply = self._read_replies(plan, link, reader, fields, request, wait, local)
            else:
                plan, local, reply = self._read_reply(plan, link, reader, fields, request, wait, local)
        except RdisError as err:
            failed = err
        except Exception as err:  # noqa: BLE001 - whatever the port raises, it failed
            failed = self._port_error(plan, err)
            failed.__cause__ = err
        finally:
            data = reader.end()
            if plan.timeout is not None:
                io.timeout = self.timeout
            lock.release()
        # I/O callbacks run once the port is free again: one that calls the robot (or
        # waits for a thread that does) cannot deadlock against this exchange.
        if self._io_callbacks:
            if lines_set and levels is not None:
                self._notify_io("lines", plan.connection, _lines_text(levels))
            if written:
                self._notify_io("write", plan.connection, request)
            if data:
                self._notify_io("read", plan.connection, data)
        if failed is not None:
            raise failed
        self._store(plan, local, reply)

    def _store(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> None:
        """Run the post-actions on a reply read whole (every part decoded and met, so a bad one
        changed no state): each sub-payload's, record's or listed reply's in the order they came,
        published together; or the primitive's (`replies N`: value i of the replies as one array)."""
        if plan.in_parts:
            self._assign_each([part for part in reply if part[0].actions is not None])
        elif plan.answers and not plan.replies:
            self._assign_each([(answer, local, one) for answer, one in zip(plan.answers, reply)
                               if answer.actions is not None])
        elif plan.actions is not None:
            self._assign(plan, local, tuple(zip(*reply)) if plan.replies else reply)

    def _request(self, plan: Primitive, values: Args,
                 local: Args) -> tuple[bytes, list[Any], dict[str, Value] | None]:
        """The request encoded and framed, the frame's fields, and the modem lines' levels."""
        request = plan.encoder.encode(plan.name, values) if plan.encoder is not None else b""
        use = plan.frame
        fields: list[Any] = []
        if use is not None:
            try:
                fields = use.frame.values(plan.name, use.args(self._state, local))
                request = use.frame.wrap(request, fields)
            except RdisError:
                raise
            except (struct.error, *EVAL_ERRORS) as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
        levels = None
        if plan.lines is not None:
            try:
                levels = plan.lines(self._state, local)
            except EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
        return request, fields, levels

    # ---- a simulated device: `open(sim=...)` puts these in place of the ports' ways ------------------

    def _simulate(self, sim: Simulator) -> None:
        """Run against `sim`: every primitive the general way (the simulator takes parameters'
        values, which a plain write's shortcut never has), its exchange with the simulator, and
        in simulated time the schedule's clock and the delays the simulation's. Instance
        attributes, so that a robot on ports runs exactly the code it runs without them."""
        self._sim = sim
        self._input = self._input_in_full  # type: ignore[method-assign]
        self._primitive = self._primitive_in_full  # type: ignore[method-assign]
        self._interface = self._simulated_interface  # type: ignore[method-assign]
        self._exchange = self._simulated_exchange  # type: ignore[method-assign]
        if not sim.realtime:
            self._clock = sim.now
            self._sleep = sim.advance

    def _simulated_interface(self, plan: Interface, args: Args) -> None:
        """An interface: the simulator sees its parameters' values first (a transmission may
        command one), then it runs as it always does."""
        assert self._sim is not None
        self._sim.interface(plan, args)
        Robot._interface(self, plan, args)

    def _simulated_exchange(self, plan: Primitive, values: Args, local: Args) -> None:
        """A primitive against the simulator: its request is encoded as for a port (the I/O
        callbacks see it written, and what a port refuses is refused), the simulator takes the
        parameters' values and gives the reply's, which meet the `expect` and go to the
        post-actions as a reply read from a port would."""
        assert self._sim is not None
        request, _fields, levels = self._request(plan, values, local)
        reply = self._sim.exchange(plan, local)
        if self._io_callbacks:
            if levels is not None:
                self._notify_io("lines", plan.connection, _lines_text(levels))
            if request:
                self._notify_io("write", plan.connection, request)
        if plan.answers:  # one reply for each, meeting its own expect
            reply = [self._met(answer, local, one) for answer, one in zip(plan.answers, reply)]
        elif plan.expects_reply and not plan.in_parts:
            reply = self._met(plan, local, reply)
        self._store(plan, local, reply)

    def _read_reply(self, plan: Primitive, link: _Link, reader: Incoming, fields: list[Any], request: bytes,
                    wait: float, local: Args) -> tuple[Primitive, Args, Sequence[Any]]:
        """The plan whose post-actions take the reply (a tag's entry), what they read besides
        it (the parameters' values, and a tag's after them), and the reply, decoded and meeting
        its `expect`."""
        decoder = plan.decoder
        use = plan.frame
        if use is None or not plan.framed_reply:
            if plan.tag_struct is not None:
                return self._read_tagged(plan, reader, wait, local)
            if isinstance(decoder, Match):  # one line
                end = link.connection.terminator
                line = reader.read_until(end, MAX_LINE)
                if not line:
                    raise RdisTimeout(f"{plan.name}: no reply within {wait:g} s")
                if not line.endswith(end):
                    raise RdisProtocolError(f"{plan.name}: reply line not terminated: {line.decode('latin-1')!r}")
                text = line[: -len(end)]
                if end == b"\n" and text.endswith(b"\r"):  # the default takes CR LF as well as LF
                    text = text[:-1]
                return plan, local, self._met(plan, local, decoder.decode(plan.name, text))
            assert decoder is not None
            data = reader.read(decoder.size)
            if not data:
                raise RdisTimeout(f"{plan.name}: no reply within {wait:g} s")
            return plan, local, self._met(plan, local, decoder.decode(plan.name, data))
        # The decoding's size is the payload's, unless a tag comes first or stuffing may have lengthened
        # it on the wire (then the constant after the payload ends it).
        stuffed = use.frame.stuffing is not None and any(side.delimiter for side in use.frame.replies)
        size = decoder.size if decoder is not None and plan.tag is None and plan.records is None and not stuffed else -1
        while True:  # once, or until a reply decodes when the primitive skips the others
            try:
                payload = use.frame.read(reader, fields, request, size)[1]
                if plan.each:
                    return plan, local, self._sub_payloads(plan, payload, local)
                if plan.records is not None:
                    return plan, local, self._records(plan, payload, local)
                if plan.tag_struct is not None:
                    return self._tagged(plan, payload, local)
                return plan, local, self._met(plan, local, decoder.decode(plan.name, payload)) if decoder else ()
            except (FrameError, RdisProtocolError) as err:
                nothing = isinstance(err, FrameError) and err.timeout
                if plan.skip and not nothing and reader.deadline is not None and time.monotonic() < reader.deadline:
                    continue
                if nothing or plan.skip:
                    raise RdisTimeout(f"{plan.name}: no {'matching reply' if plan.skip else 'reply'} "
                                      f"within {wait:g} s") from None
                if isinstance(err, RdisProtocolError):
                    raise
                raise RdisProtocolError(f"{plan.name}: {err}") from None

    def _read_replies(self, plan: Primitive, link: _Link, reader: Incoming, fields: list[Any], request: bytes,
                      wait: float, local: Args) -> list[Sequence[Any]]:
        """`replies N` and `replies { }`: a reply for each of the plan's answers, read in turn as
        one is (each decoded and meeting its `expect`; through its own frame, with its own field
        values, where it has one), all within the one deadline, in the order they came."""
        got: list[Sequence[Any]] = []
        count = len(plan.answers)
        for n, answer in enumerate(plan.answers):
            use = answer.frame
            if use is not None and use is not plan.frame:
                try:
                    fields = use.frame.values(plan.name, use.args(self._state, local))
                except (struct.error, *EVAL_ERRORS) as err:
                    raise RdisValueError(f"{plan.name}: {err}") from None
            try:
                got.append(self._read_reply(answer, link, reader, fields, request, wait, local)[2])
            except RdisTimeout:
                if not n:
                    raise
                raise RdisTimeout(f"{plan.name}: {n} of {count} replies within {wait:g} s") from None
            except RdisProtocolError as err:
                raise RdisProtocolError(f"{plan.name}: reply {n + 1} of {count}: "
                                        f"{str(err).removeprefix(plan.name + ': ')}") from None
        return got

    def _met(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> Sequence[Any]:
        """The reply, when it meets the primitive's `expect` (else, like a reply that does not
        decode, an RdisProtocolError, which `skip unmatched` reads past)."""
        if plan.expect is None:
            return reply
        try:
            met = plan.expect(self._state, local, reply)
        except EVAL_ERRORS as err:
            raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r}: its `expect` failed: {err}") from None
        if not met:
            raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r} does not meet its `expect`")
        return reply

    @staticmethod
    def _tagged(plan: Primitive, payload: bytes, local: Args) -> tuple[Primitive, Args, Sequence[Any]]:
        """The entry a framed reply's tag chooses, the tag after the parameters' values, and
        the rest of the payload decoded by the entry."""
        tag = plan.tag_struct
        assert tag is not None and plan.table is not None
        if len(payload) < tag.size:
            raise RdisProtocolError(f"{plan.name}: expected {tag.size} bytes or more, got {len(payload)}")
        value = tag.unpack_from(payload)[0]
        case = plan.table.get(value)
        if case is None:
            raise RdisProtocolError(f"{plan.name}: no reply entry for tag {value}")
        rest = payload[tag.size :]
        return case, [*local, value], case.decoder.decode(plan.name, rest) if case.decoder is not None else ()

    def _records(self, plan: Primitive, payload: bytes, local: Args) -> list[tuple[Primitive, Args, Sequence[Any]]]:
        """A payload of records, each ended by the marker where it first comes (Firmata's capability
        report: a pin's mode and resolution pairs, then 7F), each decoded by the primitive's decoder
        and meeting its `expect`, its position after the parameters' values (`index`). At most
        MAX_ARRAY of them; a payload whose end is not a marker is refused, as is a record that does
        not decode. All are decoded before any post-action runs, so a bad one changes no state."""
        marker = plan.records
        decoder = plan.decoder
        assert marker is not None and decoder is not None
        parts: list[tuple[Primitive, Args, Sequence[Any]]] = []
        at = 0
        while at < len(payload):
            end = payload.find(marker, at)
            if end < 0:
                raise RdisProtocolError(f"{plan.name}: the reply's last {len(payload) - at} bytes end in no "
                                        f"{marker.hex(' ')}, so they are no record")
            if len(parts) == MAX_ARRAY:
                raise RdisProtocolError(f"{plan.name}: more than {MAX_ARRAY} records")
            index: Args = [*local, len(parts)]
            name = f"{plan.name}: record {len(parts)}"
            parts.append((plan, index, self._met(plan, index, decoder.decode(name, payload[at:end]))))
            at = end + len(marker)
        return parts

    @staticmethod
    def _sub_payloads(plan: Primitive, payload: bytes, local: Args) -> list[tuple[Primitive, Args, Sequence[Any]]]:
        """A payload of sub-payloads (Kobuki's feedback), in any order and any subset, until it
        ends: each its tag, its length when the table gives one, and its bytes, decoded by the
        entry the tag chooses (its plan, the tag after the parameters' values, its values). With
        a length, a tag without an entry is skipped (a newer firmware's) and a length that is
        not its entry's size refused; without one, the entry's size says where the next starts.
        All are decoded before any post-action runs, so a bad one changes no state."""
        tag = plan.tag_struct
        size = plan.length_struct
        assert tag is not None and plan.table is not None
        head = tag.size + (size.size if size is not None else 0)
        parts: list[tuple[Primitive, Args, Sequence[Any]]] = []
        at = 0
        while at < len(payload):
            if len(payload) - at < head:
                raise RdisProtocolError(f"{plan.name}: {len(payload) - at} bytes at offset {at} are no "
                                        f"sub-payload (its head is {head})")
            value = tag.unpack_from(payload, at)[0]
            case = plan.table.get(value)
            if case is None and size is None:
                raise RdisProtocolError(f"{plan.name}: no reply entry for tag {value} at offset {at}")
            decoder = case.decoder if case is not None else None
            if size is not None:
                length = size.unpack_from(payload, at + tag.size)[0]
            else:
                assert decoder is not None
                length = decoder.size
            start = at + head
            if start + length > len(payload):
                raise RdisProtocolError(f"{plan.name}: the sub-payload of tag {value} at offset {at} is {length} "
                                        f"bytes, but {len(payload) - start} remain")
            at = start + length
            if case is None or decoder is None:
                continue
            if size is not None and decoder.size >= 0 and length != decoder.size:
                raise RdisProtocolError(f"{plan.name}: the sub-payload of tag {value} at offset {start - head} "
                                        f"is {length} bytes; its entry decodes {decoder.size}")
            parts.append((case, [*local, value], decoder.decode(plan.name, payload[start:at])))
        return parts

    @staticmethod
    def _read_tagged(plan: Primitive, reader: Incoming, wait: float,
                     local: Args) -> tuple[Primitive, Args, Sequence[Any]]:
        """A tagged reply without a frame (Firmata's stream): the tag, then exactly the bytes its
        entry decodes (a fixed size: checked). Under `skip unmatched` a tag without an entry is
        read past one byte at a time, the next tag looked for from the byte after its first,
        until the reply's deadline."""
        tag = plan.tag_struct
        assert tag is not None and plan.table is not None
        missed = f"{plan.name}: no {'matching reply' if plan.skip else 'reply'} within {wait:g} s"
        while True:
            head = reader.read(tag.size)
            if len(head) < tag.size:  # the deadline passed
                if not head or plan.skip:
                    raise RdisTimeout(missed)
                raise RdisProtocolError(f"{plan.name}: expected {tag.size} bytes, got {len(head)}")
            value = tag.unpack(head)[0]
            case = plan.table.get(value)
            if case is None:
                if not plan.skip:
                    raise RdisProtocolError(f"{plan.name}: no reply entry for tag {value}")
                if reader.deadline is not None and time.monotonic() >= reader.deadline:
                    raise RdisTimeout(missed)
                reader.put_back(head[1:])
                continue
            decoder = case.decoder
            assert isinstance(decoder, Unpack)
            if decoder.until is not None:  # to its end marker, which is not the reply's
                body = reader.read_until(decoder.until)
                if not body.endswith(decoder.until):
                    if plan.skip:
                        raise RdisTimeout(missed)
                    raise RdisProtocolError(f"{plan.name}: no end {decoder.until.hex(' ')} after tag {value} "
                                            f"within {wait:g} s")
                return case, [*local, value], decoder.decode(plan.name, body[: -len(decoder.until)])
            body = reader.read(decoder.size)
            if len(body) < decoder.size:
                if plan.skip:
                    raise RdisTimeout(missed)
                raise RdisProtocolError(f"{plan.name}: expected {decoder.size} bytes after tag {value}, "
                                        f"got {len(body)}")
            return case, [*local, value], decoder.decode(plan.name, body)

    def _port_error(self, plan: Primitive, err: BaseException) -> RdisError:
        """The typed error for what a port raised: a write that timed out, or a failed port."""
        if _write_timed_out(err):
            return RdisTimeout(f"{plan.name}: write not completed within {self.timeout:g} s")
        return RdisConnectionError(f"{plan.connection}: {err}")

    def _assign(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> None:
        """The post-actions: all values computed from one snapshot, then published together."""
        self._assign_each([(plan, local, reply)])

    def _assign_each(self, parts: Sequence[tuple[Primitive, Args, Sequence[Any]]]) -> None:
        """The post-actions of each part in turn (sub-payloads, records), each part's computed from
        the state the one before left; all published together, or none when one fails."""
        with self._state_lock:
            state = self._state
            for plan, local, reply in parts:
                assert plan.actions is not None
                try:
                    changes = plan.actions(state, local, reply)
                except EVAL_ERRORS as err:
                    raise RdisValueError(f"{plan.name}: {err}") from None
                for name in plan.checked:
                    value = changes[name]
                    if type(value) is int and not -MAX_INT <= value <= MAX_INT:
                        raise RdisValueError(f"{plan.name}: {name} would be a {value.bit_length()}-bit integer; "
                                             "integers are limited to 64 bits and a sign")
                state = {**state, **changes}
            self._state = state

    # ---- delivering to callbacks: one at a time, a failing one reported -----------------------------

    def _deliver(self, plan: Output) -> None:
        try:
            contents = plan.fields(self._state)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        message: dict[str, Any] = {"name": plan.name, "contents": contents}
        with self._callback_lock:
            for callback in list(self._output_callbacks):
                try:
                    callback(message)
                except Exception as err:  # noqa: BLE001 - a user's callback must not stop delivery
                    error = RdisCallbackError(f"{plan.name}: output callback raised {type(err).__name__}: {err}")
                    error.__cause__ = err
                    self._report(error)

    def _notify_io(self, direction: str, connection: str, data: bytes) -> None:
        """Show the I/O callbacks one event: "write" or "read" and the bytes, or "lines" and
        the modem lines set (`_lines_text`)."""
        with self._callback_lock:
            for callback in list(self._io_callbacks):
                try:
                    callback(direction, connection, data)
                except Exception as err:  # noqa: BLE001 - a user's callback must not stop the I/O
                    error = RdisCallbackError(f"{connection}: I/O callback raised {type(err).__name__}: {err}")
                    error.__cause__ = err
                    self._report(error)

    def _notify_run(self, connection: str, kind: str, name: str) -> None:
        """Tell a recorder that a connection's thread starts a periodic interface or its keepalive."""
        with self._callback_lock:
            for callback in list(self._run_callbacks):
                callback(connection, kind, name)

    def _report(self, error: BaseException) -> None:
        with self._callback_lock:
            callbacks = list(self._error_callbacks)
            if not callbacks:
                _log.warning("%s: %s: %s", self.name, type(error).__name__, error)
            for callback in callbacks:
                try:
                    callback(error)
                except Exception:  # noqa: BLE001, S110 - the contract: an error callback's failure is ignored
                    pass


def _lines_text(levels: Mapping[str, Value]) -> bytes:
    """The modem lines a primitive set, as the I/O callbacks see them: b"dtr=False rts=True"."""
    return " ".join(f"{line}={bool(level)}" for line, level in levels.items()).encode("ascii")


# ---- recordings: a session in MCAP ------------------------------------------------------------------


_SEPARATOR = "=" * 80  # between a ros2msg schema's message and each message it uses
_HEADER = "std_msgs/Header header"  # a message's field, which a recording stamps
_TEXT = "std_msgs/msg/String"
_TEXT_SCHEMA = "string data\n"
_BYTES = "std_msgs/msg/UInt8MultiArray"
_BYTES_SCHEMA = ("MultiArrayLayout layout\nuint8[] data\n" + _SEPARATOR + "\nMSG: std_msgs/MultiArrayLayout\n"
                 "MultiArrayDimension[] dim\nuint32 data_offset\n" + _SEPARATOR
                 + "\nMSG: std_msgs/MultiArrayDimension\nstring label\nuint32 size\nuint32 stride\n")
_LOG = "rcl_interfaces/msg/Log"
_LOG_SCHEMA = ("byte DEBUG=10\nbyte INFO=20\nbyte WARN=30\nbyte ERROR=40\nbyte FATAL=50\n"
               "builtin_interfaces/Time stamp\nuint8 level\nstring name\nstring msg\nstring file\n"
               "string function\nuint32 line\n" + _SEPARATOR + "\nMSG: builtin_interfaces/Time\n"
               "int32 sec\nuint32 nanosec\n")
RUNS_TOPIC = "/rdisc/runs"


def _time(stamp: int) -> dict[str, int]:
    """Nanoseconds since the epoch as a builtin_interfaces/Time."""
    return {"sec": stamp // 1_000_000_000, "nanosec": stamp % 1_000_000_000}


class Recorder:
    """A session written to an MCAP file of ROS 2 messages in the `ros2` profile (the tests
    read it back with rosbags, an independent reader; `rdisc replay` runs it again through a
    description).

    Topics: each input called and each output delivered on `/NAME`, as its adapter's ROS 2
    message (`Device.messages`), or, for an adapter without one, its fields as JSON in a
    std_msgs/String; the bytes each way on `/rdisc/CONNECTION/write` and `/read`
    (std_msgs/UInt8MultiArray), the modem lines a primitive set on `/rdisc/CONNECTION/lines`;
    what ran, in order, on `/rdisc/runs` (JSON: each call of the host with its values, each
    periodic interface and keepalive a connection's thread started), which is what a replay
    repeats; errors on `/rosout` (rcl_interfaces/Log). Times are the host's clock, in order.
    Needs the `mcap` and `mcap-ros2-support` packages, imported here only (ImportError without).
    """

    def __init__(self, robot: Robot, output: Any, settings: Mapping[str, Any] | None = None) -> None:
        from mcap_ros2.writer import Writer  # only a recording needs it

        self._writer: Any = Writer(output)
        self._device = robot.device
        self._adapters = {o.name: o.adapter for i in robot.device.interfaces.values() for o in i.outputs}
        self._lock = threading.Lock()
        self._time = 0
        self._schemas: dict[str, Any] = {}
        self._writer.add_metadata("rdisc", {"robot": robot.name, "timeout": json.dumps(robot.timeout),
                                            "settings": json.dumps(dict(settings or {}), default=list)})
        robot.on_output(self.output)
        robot.on_error(self.error)
        robot.on_io(self.io)
        robot._run_callbacks.append(self.run)

    def call(self, kind: str, name: str, values: Mapping[str, Any]) -> None:
        """The host calls an input, an interface or a primitive with these values by name."""
        self._write(RUNS_TOPIC, _TEXT, _TEXT_SCHEMA, {"data": json.dumps({"call": kind, "name": name,
                                                                         "values": dict(values)}, default=bytes.hex)})
        plan = self._device.inputs.get(name) if kind == "input" else None
        if plan is not None:
            self._adapted(name, plan.adapter, dict(values))

    def run(self, connection: str, kind: str, name: str) -> None:
        """A connection's thread starts a periodic interface or its keepalive."""
        self._write(RUNS_TOPIC, _TEXT, _TEXT_SCHEMA, {"data": json.dumps({kind: name, "connection": connection})})

    def output(self, message: dict[str, Any]) -> None:
        self._adapted(message["name"], self._adapters.get(message["name"], ""), message["contents"])

    def error(self, error: BaseException) -> None:
        stamp = self._stamp()
        self._write("/rosout", _LOG, _LOG_SCHEMA, {
            "stamp": _time(stamp), "level": 40,
            "name": self._device.name, "msg": f"{type(error).__name__}: {error}"}, stamp)

    def io(self, direction: str, connection: str, data: bytes) -> None:
        if direction == "lines":
            self._write(f"/rdisc/{connection}/lines", _TEXT, _TEXT_SCHEMA, {"data": data.decode("ascii")})
        else:
            self._write(f"/rdisc/{connection}/{direction}", _BYTES, _BYTES_SCHEMA, {"data": list(data)})

    def finish(self) -> None:
        """Write the file's index and close it: call it once the robot is closed."""
        with self._lock:
            self._writer.finish()

    def _adapted(self, name: str, adapter: str, contents: Mapping[str, Any]) -> None:
        """An adapter's values on `/NAME`: its ROS 2 message, or JSON text. A message with a
        std_msgs/Header is stamped with the time it is recorded at, as a ROS 2 publisher's is."""
        message = self._device.messages.get(adapter)
        if message is None:
            self._write(f"/{name}", _TEXT, _TEXT_SCHEMA, {"data": json.dumps(dict(contents), default=list)})
            return
        stamp = self._stamp()
        members = ros_message(message, contents)
        if _HEADER in message.definition.partition(_SEPARATOR)[0].splitlines():
            members.setdefault("header", {})["stamp"] = _time(stamp)
        self._write(f"/{name}", message.type, message.definition, members, stamp)

    def _stamp(self) -> int:
        """Now in nanoseconds, later than every time written before: the file keeps the order."""
        with self._lock:
            self._time = max(time.time_ns(), self._time + 1)
            return self._time

    def _write(self, topic: str, kind: str, schema: str, message: dict[str, Any], stamp: int | None = None) -> None:
        stamp = self._stamp() if stamp is None else stamp
        with self._lock:
            registered = self._schemas.get(kind)
            if registered is None:
                registered = self._schemas[kind] = self._writer.register_msgdef(kind, schema)
            self._writer.write_message(topic, registered, message, log_time=stamp)


def ros_message(message: Message, values: Mapping[str, Any]) -> dict[str, Any]:
    """An adapter's values by field name as the nested members of its ROS 2 message (what
    `mcap-ros2-support` encodes); members no field names keep their defaults."""
    out: dict[str, Any] = {}
    for name, path in zip(message.fields, message.paths):
        value = values[name]
        steps, _, conversion = path.partition(":")
        if conversion == "yaw":
            value = {"x": 0.0, "y": 0.0, "z": math.sin(value / 2), "w": math.cos(value / 2)}
        elif isinstance(value, tuple):
            value = list(value)
        where = out
        names = steps.split(".")
        for step in names[:-1]:
            where = where.setdefault(step, {})
        last, bracket, index = names[-1].partition("[")
        if bracket:
            items = where.setdefault(last, [])
            position = int(index[:-1])
            items.extend([None] * (position + 1 - len(items)))
            items[position] = value
        else:
            where[last] = value
    return out


# ---- the command line: `rdisc run` and every driver's ------------------------------------------------

EXIT_OK, EXIT_ERROR, EXIT_USAGE, EXIT_SIGINT, EXIT_SIGTERM = 0, 1, 2, 130, 143


class _Terminated(BaseException):
    """SIGTERM, turned into an exception so that the terminate hooks run on the way out."""


def add_arguments(parser: argparse.ArgumentParser, device: Device | None = None, *, ports: bool = True) -> None:
    """The options of `rdisc run` (and of a driver's command line), on `parser`; without
    `--port` for a simulated device (`rdisc sim`)."""
    connections = f" (connections: {', '.join(device.connections)})" if device is not None else ""
    inputs = f" (inputs: {', '.join(device.inputs)})" if device is not None and device.inputs else ""
    if ports:
        parser.add_argument("--port", action="append", default=[], metavar="[CONN=]PORT",
                            help="a pyserial port or URL (/dev/ttyUSB0, COM3, socket://host:port); "
                                 f"CONN=PORT for one connection of several{connections}")
    parser.add_argument("--call", action="append", nargs="+", default=[], metavar="NAME [K=V ...]",
                        help="call an input (or an interface, or a primitive) with named values; repeat for "
                             f"several calls, in order{inputs}")
    settings = f" (settings: {', '.join(p.name for p in device.settings)})" if device and device.settings else ""
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help=f"give a setting of the description its value; repeat for several{settings}")
    parser.add_argument("--watch", action="store_true", help="print each output as a JSON line as it arrives")
    parser.add_argument("--trace", action="store_true",
                        help="print every byte written and read, in hex, on stderr, after the seconds since the "
                             "run started: `0.1234 CONN > 89 00 c8 80 00`")
    parser.add_argument("--duration", type=float, metavar="S",
                        help="run for S seconds, counted from the end of the startup hooks (default: until the "
                             "calls are done; with --watch, until Ctrl-C)")
    parser.add_argument("--timeout", type=float, default=1.0, metavar="S",
                        help="reply timeout in seconds (default 1)")
    parser.add_argument("--record", metavar="FILE.mcap",
                        help="record the session in MCAP: inputs and outputs as ROS 2 messages, the bytes "
                             "each way, errors (needs the mcap and mcap-ros2-support packages)")


def run_command(args: argparse.Namespace, robot: Robot, prog: str, sim: Simulator | None = None) -> int:
    """What `rdisc run` does with its options: connect, make the --call calls in order, then
    run until --duration seconds after the startup hooks ended (or, with --watch, until
    Ctrl-C; else end when the calls are done). It always ends by closing the robot, which
    runs the terminate hooks. Exit status: 0 done; 1 the device failed; 2 a usage error;
    130 after SIGINT; 143 after SIGTERM. With `sim` (`rdisc sim`) the robot runs against
    the simulated device; in simulated time the seconds, the trace's included, are its."""
    simulated = sim is not None and not sim.realtime
    clock = sim.now if sim is not None and simulated else time.monotonic
    began = clock()
    try:
        port = None if sim is not None else parse_ports(args.port, robot.device)
        settings = bind_settings(robot.device, parse_settings(args.set, robot.device))
        calls = [parse_call(words, robot.device) for words in args.call]
    except (TypeError, ValueError) as err:
        print(f"{prog}: {err}", file=sys.stderr)
        return EXIT_USAGE
    recorder = start_recording(robot, args.record, settings, prog) if args.record else None
    if args.record and recorder is None:
        return EXIT_USAGE
    robot.on_error(_print_error)
    if args.watch:
        robot.on_output(_print_output)
    if args.trace:
        robot.on_io(lambda direction, connection, data: _print_io(clock() - began, direction, connection, data))
    previous = _install_signal_handlers()
    status = EXIT_OK
    try:
        robot.open(port, settings=settings, sim=sim)
        started = clock()  # the startup hooks are done: --duration counts from here
        for name, kind, values in calls:
            if recorder is not None:
                recorder.call(kind, name, values)
            make_call(robot, kind, name, values)
        if simulated and (args.duration is not None or args.watch):
            robot.run_for(None if args.duration is None else args.duration - (clock() - started))
        elif args.duration is not None:
            _sleep(args.duration - (time.monotonic() - started))
        elif args.watch:
            _sleep(None)
    except RdisError as err:
        _print_error(err)
        if recorder is not None:
            recorder.error(err)
        status = EXIT_ERROR
    except (TypeError, ValueError) as err:  # values of the wrong type for a call, or a bad port
        print(f"{prog}: {err}", file=sys.stderr)
        status = EXIT_USAGE
    except KeyboardInterrupt:
        status = EXIT_SIGINT
    except _Terminated:
        status = EXIT_SIGTERM
    finally:
        while not _shutting_down[0]:  # from here on a signal must not cut the terminate hooks short
            try:
                _shutting_down[0] = True
            except KeyboardInterrupt:
                status = EXIT_SIGINT
            except _Terminated:
                status = EXIT_SIGTERM
        try:
            robot.close()
            if recorder is not None:
                recorder.finish()
        finally:
            interrupted = status in (EXIT_SIGINT, EXIT_SIGTERM)
            for signum, handler in previous.items():  # after a signal, later ones are ignored to the exit
                signal.signal(signum, signal.SIG_IGN if interrupted else handler)
    return status


def start_recording(robot: Robot, path: str, settings: Mapping[str, Any], prog: str) -> Recorder | None:
    """`--record PATH` (of `rdisc run`, a driver and `rdisc console`): a Recorder attached to
    `robot`, or None once stderr says why there is none (the mcap packages are missing, the
    file cannot be written), which is a usage error."""
    try:
        return Recorder(robot, path, settings)
    except ImportError:
        print(f"{prog}: --record needs the mcap and mcap-ros2-support packages "
              "(pip install mcap mcap-ros2-support)", file=sys.stderr)
    except OSError as err:
        print(f"{prog}: cannot write {path}: {err.strerror or err}", file=sys.stderr)
    return None


def parse_ports(given: list[str], device: Device) -> str | dict[str, str] | None:
    """`--port P` for every connection, `--port CONN=P` for one; a plain port is the default for
    the others, and a connection given none opens its `address`."""
    connections = device.connections
    addresses = {name: c.address for name, c in connections.items() if c.address is not None}
    if not given:
        if len(addresses) == len(connections):
            return None
        raise ValueError("give the device's port: --port /dev/ttyUSB0 (or CONN=PORT for each connection)")
    default: str | None = None
    named: dict[str, str] = {}
    for value in given:
        name, sep, port = value.partition("=")
        if sep and name in connections:
            if name in named:
                raise ValueError(f"two ports for connection `{name}`")
            named[name] = port
        elif sep and name.isidentifier():
            raise ValueError(f"`{name}` is not a connection of {device.name} "
                             f"(its connections: {', '.join(connections) or 'none'})")
        elif default is not None:
            raise ValueError(f"two ports without a connection name: `{default}` and `{value}`")
        else:
            default = value
    if not named:
        assert default is not None
        return default
    for name in connections:
        if name not in named:
            fallback = default if default is not None else addresses.get(name)
            if fallback is None:
                raise ValueError(f"no port for connection `{name}`: add --port {name}=PORT")
            named[name] = fallback
    return named


def parse_settings(given: list[str], device: Device) -> dict[str, Any]:
    """--set NAME=VALUE ...: each value read as its setting's type says (`read_value`), for
    `bind_settings` to check; one that does not fit is an RdisValueError naming the setting."""
    declared = {p.name: p for p in device.settings}
    values: dict[str, Any] = {}
    for pair in given:
        name, sep, text = pair.partition("=")
        if not sep or not name:
            raise ValueError(f"--set `{pair}` is not NAME=VALUE")
        if name in values:
            raise ValueError(f"--set {name} given twice")
        param = declared.get(name)
        try:
            values[name] = text if param is None else read_value(text, param, f"{device.name}: setting {name}")
        except TypeError as err:
            raise RdisValueError(str(err)) from None
    return values


def parse_call(words: list[str], device: Device) -> tuple[str, str, dict[str, Value]]:
    """--call NAME K=V ...: (name, "input" | "interface" | "primitive", values in declaration
    order, each read as its parameter's or field's type says, `read_value`; those left out take
    their defaults); an input is preferred to an interface of the same name, an interface to a
    primitive. An unknown name is answered with the nearest known one. A value that does not fit
    is refused here, before anything is opened (TypeError, or RdisValueError naming it)."""
    name, *pairs = words
    plan: Input | Interface | Primitive | None = None
    for kind, plan in (("input", device.inputs.get(name)), ("interface", device.interfaces.get(name)),
                       ("primitive", device.primitives.get(name))):
        if plan is not None:
            break
    else:
        known = list(dict.fromkeys([*device.inputs, *device.interfaces, *device.primitives]))
        near = difflib.get_close_matches(name, known, n=1)
        hint = f"did you mean `{near[0]}`?" if near else f"there are: {', '.join(known) or 'none'}"
        raise ValueError(f"{device.name} has no input, interface or primitive `{name}`; {hint}")
    given: dict[str, str] = {}
    for pair in pairs:
        key, sep, text = pair.partition("=")
        if not sep or not key:
            raise ValueError(f"--call {name}: `{pair}` is not KEY=VALUE")
        if key in given:
            raise ValueError(f"--call {name}: `{key}` given twice")
        given[key] = text
    try:
        return name, kind, call_values(device, kind, name, given)
    except Unbound:
        params = plan.fields if isinstance(plan, Input) else plan.params
        wanted = " ".join(f"{p.name}=..." if p.default is None else f"[{p.name}={p.default!r}]" for p in params)
        raise ValueError(f"--call {name} takes {wanted or 'no values'}") from None


def make_call(robot: Robot, kind: str, name: str, values: Mapping[str, Value]) -> None:
    """A call of an input, interface or primitive with its values by name, in declaration order
    (`call_values`'): how `--call`, the console and a replay make theirs."""
    if kind == "input":
        robot.call_input(name, **values)
    elif kind == "interface":
        robot.call_interface(name, *values.values())
    else:
        robot.call_primitive(name, *values.values())


def _print_output(message: dict[str, Any]) -> None:
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def _print_error(error: BaseException) -> None:
    print(f"rdisc run: {type(error).__name__}: {error}", file=sys.stderr, flush=True)


def _print_io(elapsed: float, direction: str, connection: str, data: bytes) -> None:
    """One --trace line: the seconds since the run began, the connection, then `>` and
    the bytes written, `<` and the bytes read, or `lines` and the modem lines set."""
    if direction == "lines":
        shown = f"lines {data.decode('ascii')}"
    else:
        shown = f"{'>' if direction == 'write' else '<'} {data.hex(' ')}"
    print(f"{elapsed:.4f} {connection} {shown}", file=sys.stderr, flush=True)


_shutting_down = [False]


def _on_signal(signum: int, frame: object) -> None:
    if _shutting_down[0]:
        return  # the first signal already started the shutdown: the terminate hooks run in peace
    _shutting_down[0] = True
    raise KeyboardInterrupt if signum == signal.SIGINT else _Terminated()


def _install_signal_handlers() -> dict[int, Any]:
    _shutting_down[0] = False
    previous: dict[int, Any] = {}
    for signum in (signal.SIGINT, signal.SIGTERM):
        try:
            previous[signum] = signal.signal(signum, _on_signal)
        except ValueError:  # not the main thread: leave the handlers alone
            pass
    return previous


def _sleep(seconds: float | None) -> None:
    """Sleep (forever if None); a signal ends it through its handler."""
    if seconds is None:
        while True:
            time.sleep(3600)
    elif seconds > 0:
        time.sleep(seconds)
