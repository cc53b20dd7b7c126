"""A frame: its request side written part by part or in one struct pack, its reply side read
(resynchronising on its header) with every part checked.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Sequence
from typing import Any

from rdisc.engine.errors import RdisValueError
from rdisc.engine.values import Args, Param, _check_ranges, _ranged
from rdisc.engine.wire import (
    MAX_FRAME,
    MAX_SKIP,
    Bits,
    Bytes,
    Check,
    ChecksumError,
    Escaping,
    Field,
    FrameError,
    Incoming,
    Length,
    MissingSeed,
    OptionalParts,
    Part,
    Payload,
    Reader,
    Side,
    Stuffing,
)

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
        if part.struct.size > 1:
            if part.order not in ("<", ">", "!") or order not in ("", part.order.replace("!", ">")):
                return None
            order = part.order.replace("!", ">")
        codes.append(part.code)
        picks.append((len(template), part.index, 0) if isinstance(part, Field) else (len(template), -1, part.adjust))
        template.append(0)
    head = struct.Struct((order or "<") + "".join(codes))
    starts = [0]  # each part's first byte: before the payload from the frame's start, after it from the payload's end
    for i, size in enumerate(side.sizes):
        starts.append(0 if i == side.payload else starts[-1] + size)
    after = side.payload + 1  # the first part whose start counts from the payload's end
    tail: list[tuple[bytes, Check | None, int, int]] = []  # a constant, or a checksum of [start, stop)
    for at, part in enumerate(side.parts[after:], after):
        if isinstance(part, Check) and part.last < at and not part.with_request and part.seed < 0:
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

    __slots__ = ("answer", "choose", "escaping", "fields", "fill", "headers", "name", "params", "quick", "ranged",
                 "replies", "reply", "requests", "stuffing", "trim", "vouched")

    def __init__(self, name: str, request: Sequence[Part], reply: Sequence[Part], stuffing: Stuffing | None = None,
                 params: tuple[Param, ...] = (), fields: Callable[[Args], list[Any]] | None = None,
                 more_requests: Sequence[Sequence[Part]] = (), more_replies: Sequence[Sequence[Part]] = (),
                 escaping: Escaping | None = None, choose: Callable[[Args], list[Any]] | None = None,
                 answer: Callable[[Args], list[Any]] | None = None) -> None:
        """`more_requests` and `more_replies`: the other layouts of a side (`either`), in order;
        `escaping`: the bytes between the header and the terminator escaped (one layout each way);
        `choose`: the truth of each request layout's condition (`either when`) over the arguments;
        `answer`: each reply layout's (the reply is then read with the one chosen, not by its header)."""
        self.name = name
        self.choose = choose
        self.answer = answer
        self.requests = tuple(Side(parts) for parts in (request, *more_requests))
        self.replies = tuple(Side(parts) for parts in (reply, *more_replies))
        self.reply = self.replies[0]
        self.headers = tuple(side.header for side in self.replies)  # a reply's layout is known by its header
        # Every layout of a reply has a checksum: a reply read whole is a frame, every byte of it,
        # and no other starts inside it (`skip unmatched` reads past it whole, not from its second byte).
        self.vouched = all(any(isinstance(part, Check) for part in side.parts) for side in self.replies)
        self.stuffing = stuffing
        self.escaping = escaping
        self.params = params
        self.ranged = _ranged(params)
        self.fields = fields
        self.quick = tuple(_quick_wrap(side) for side in self.requests)
        # `payload trimmed` (MAVLink 2): trailing zero bytes dropped when written, put back when read
        self.trim = any(isinstance(part, Payload) and part.trimmed for side in self.requests for part in side.parts)
        self.fill = any(isinstance(part, Payload) and part.trimmed for side in self.replies for part in side.parts)

    def values(self, owner: str, args: Args) -> list[Any]:
        """The field values for the frame's arguments; an argument outside its parameter's
        range is an RdisValueError of `owner`, before anything is sent. When settings choose the
        reply's layout (`either when`), the index of the one chosen comes last, for `read`."""
        if self.ranged:
            _check_ranges(f"{owner}: frame {self.name}", self.params, self.ranged, args)
        fields = [] if self.fields is None else self.fields(args)
        if self.answer is not None:
            fields.append(self._chosen(owner, "reply layout", self.answer(args), len(self.replies)))
        return fields

    def layout(self, owner: str, args: Args) -> int:
        """The request layout the arguments choose (`either when`): the first whose condition
        holds, else a plain last one; -1 when the frame chooses by the payload's size."""
        if self.choose is None:
            return -1
        return self._chosen(owner, "layout", self.choose(args), len(self.requests))

    def _chosen(self, owner: str, what: str, conditions: Sequence[Any], count: int) -> int:
        """The first of `count` layouts (`what`: "layout", "reply layout") whose condition holds, else a
        plain last one (no more conditions than layouts); none is an RdisValueError of `owner`."""
        for index, holds in enumerate(conditions):
            if holds:
                return index
        if count > len(conditions):
            return len(conditions)
        raise RdisValueError(f"{owner}: frame {self.name}: no {what}'s condition holds")

    def wrap(self, payload: bytes, fields: Sequence[int], layout: int = -1) -> bytes:
        """The request: `payload` framed (stuffed first, when the frame stuffs), with the
        frame's field values; when it escapes, what comes between its flags escaped. `layout`:
        the one `layout` chose, else the first that can state the payload's size."""
        if self.trim:  # its trailing zero bytes dropped, its first byte kept (MAVLink 2)
            payload = payload.rstrip(b"\0") or payload[:1]
        if self.stuffing is not None:
            payload = self.stuffing.stuff(payload)
        chosen = zip(self.requests, self.quick) if layout < 0 else ((self.requests[layout], self.quick[layout]),)
        for side, quick in chosen:  # the first layout that can state its size
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

    def read(self, port: Reader, fields: Sequence[int], request: bytes, size: int,
             whole: bool = False) -> tuple[bytes, bytes]:
        """Read one reply frame from `port`; (the bytes read, the payload).

        `size` is the payload's size when the decoding fixes it, else -1. Bytes
        before the header are skipped; every constant, field and checksum is
        checked. FrameError says what is wrong. `whole`: a frame found wrong gives
        back every byte taken, for another frame to be read from its first (an error
        reply tried before the reply).
        """
        data = bytearray()
        try:
            raw, payload = self._read(port, data, fields, request, size)
        except FrameError:
            kept = 0 if whole else 1
            if len(data) > kept and isinstance(port, Incoming):  # look for the next header in what was taken
                port.put_back(bytes(data[kept:]))
            raise
        if self.fill and len(payload) < size:  # a trimmed payload's zero bytes put back (MAVLink 2)
            payload += bytes(size - len(payload))
        return raw, payload

    def _read(self, port: Reader, data: bytearray, fields: Sequence[int], request: bytes,
              size: int) -> tuple[bytes, bytes]:
        if self.escaping is not None:
            return self._read_escaped(port, data, fields, request)
        side = self.reply
        if self.answer is not None:  # the settings chose the layout (`values` put its index last)
            side = self.replies[fields[-1]]
            if side.header:
                data += self._sync(port, (side.header,))
        elif len(self.replies) > 1:  # the header that comes says which layout
            head = self._sync(port, self.headers)
            data += head
            side = self.replies[self.headers.index(head)]
        elif side.header:
            data += self._sync(port, self.headers)
        self._take(port, data, side.prefix, bool(data))
        if side.payload < 0:
            return self._check(side, bytes(data), 0, fields, request, measured=True), b""
        if side.length >= 0:
            at = sum(side.sizes[: side.length])
            length = side.parts[side.length]
            assert isinstance(length, (Length, Bits))
            size = length.stated(data, at)
            if not 0 <= size <= MAX_FRAME:
                raise FrameError(f"{self.name}: length field says {size + length.adjust}, which no payload fits")
        present = True  # the optional parts came
        measured = size >= 0  # its length was known before its end came: it ran into no other frame
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
        return raw, self._check(side, raw, size, fields, request, present, measured)

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
               present: bool = True, measured: bool = False) -> bytes:
        """Every constant, field and checksum of a complete reply (the optional parts when they
        are `present`); its payload. The checksums last: a wrong constant or field is another
        frame, or none (a FrameError); a wrong checksum after them, in a frame whose length was
        `measured` (a length field, or the decoding's size), is this device's reply corrupted (a
        ChecksumError). One ended by a delimiter may have run into the next frame: a FrameError."""
        absent = range(0) if present else side.group
        starts: list[int] = []
        at = 0
        for i, part_size in enumerate(side.sizes):
            starts.append(at)
            at += size if i == side.payload else 0 if i in absent else part_size
        starts.append(at)
        for i in side.checked:
            part = side.parts[i]
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
            elif i == side.again and isinstance(part, Length) and (stated := part.stated(chunk, 0)) != size:
                raise FrameError(f"{self.name}: the second length field says {stated + part.adjust}, but the "
                                 f"payload is {size} bytes")
            elif isinstance(part, Check):
                covered = raw[starts[part.first] : starts[part.last + 1]]
                try:
                    expected = part.encode(part.summed(request + covered if part.with_request else covered, fields))
                except MissingSeed:  # a message this description does not know: another frame
                    table, field = part.seeded
                    raise FrameError(f"{self.name}: reply {field} is {fields[part.seed]}, which seed table "
                                     f"{table} lacks") from None
                if (chunk if part.struct is not None else chunk.upper()) != expected:
                    error = ChecksumError if measured else FrameError
                    came, summed = (f'"{chunk.decode("latin-1")}"', f'"{expected.decode("latin-1")}"') \
                        if part.struct is None else (chunk.hex(" "), expected.hex(" "))  # text digits, or bytes in hex
                    raise error(f"{self.name}: checksum {came} does not match the reply, which sums to {summed}")
        if side.payload < 0:
            return b""
        payload = raw[starts[side.payload] : starts[side.payload + 1]]
        return self.stuffing.unstuff(payload, self.name) if self.stuffing is not None else payload
