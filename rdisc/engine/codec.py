"""Requests encoded and replies decoded, with struct formats, format strings and regular
expressions; a value that does not fit is a typed error naming the element at fault.
"""

from __future__ import annotations

import re
import struct
from collections.abc import Sequence
from typing import Any

from rdisc.engine.errors import RdisProtocolError, RdisValueError
from rdisc.engine.operations import MAX_ARRAY
from rdisc.engine.values import Value
from rdisc.engine.wire import Bits


def _latin1(owner: str, value: object) -> bytes:
    if isinstance(value, bytes):
        return value
    try:
        return str(value).encode("latin-1")
    except UnicodeEncodeError as err:
        raise RdisValueError(f"{owner}: {err.object[err.start:err.end]!r} is not a latin-1 character") from None


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
        out[first:end] = [bits.word(out[first:end])]
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
    (refused when longer than `rooms` says their `Ns` holds: struct would cut them short), the arrays
    of repeated `groups` element by element, and, with `rest` (a format ending in `*`),
    the last value, bytes, appended as it is. With `varying`, `fixed` is the format before
    that group, repeated as many times as its arrays hold values, and its count field
    computed. The fields of each integer split into `bits` are joined into it first; the
    other indexes count it as one value. With `width`, the index of a width field (`%H`) and of
    the groups' arrays of `%` codes: each of their ints is packed unsigned in as many bytes as
    the width field's value, 1 to 8 (a Dynamixel sync write of N bytes a servo)."""

    __slots__ = ("bits", "fixed", "groups", "rest", "sizes", "splitters", "strings", "struct", "varying", "width")

    def __init__(self, fixed: str, strings: tuple[int, ...] = (), rest: bool = False,
                 groups: tuple[Group, ...] = (), varying: Varying | None = None, bits: tuple[Split, ...] = (),
                 rooms: tuple[tuple[int, int], ...] = (), width: tuple[int, tuple[int, ...]] | None = None) -> None:
        """`rooms`: each `Ns` or `Np` value's index among the values, and the most bytes it holds."""
        self.fixed = fixed
        self.struct = struct.Struct(fixed.replace("%", "Q"))  # a `%` code at its widest
        self.width = width
        self.strings = strings
        self.rest = rest
        self.sizes = dict(rooms)
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
        layout, code = self.struct, ""
        if self.width is not None:
            values, code = self._widths(owner, values, self.width)
            layout = struct.Struct(self.fixed.replace("%", code))
        try:
            if self.varying is not None:
                return self._varying(owner, values, self.varying, code)
            if self.groups:
                values = _interleaved(owner, values, self.groups)
            if not self.strings and not self.rest:
                return layout.pack(*values)
            packed = list(values[:-1] if self.rest else values)
            for i in self.strings:
                packed[i] = data = _latin1(owner, packed[i])
                if len(data) > self.sizes.get(i, len(data)):
                    raise RdisValueError(f"{owner}: {len(data)} bytes of text do not fit the {self.sizes[i]} "
                                         f"that value {i} is packed in")
            fixed = layout.pack(*packed)
        except (struct.error, OverflowError) as err:  # OverflowError: a float too large for `e` or `f`
            raise RdisValueError(f"{owner}: {err}") from None
        if self.rest:
            tail = values[-1]
            assert isinstance(tail, bytes)
            return fixed + tail
        return fixed

    def _widths(self, owner: str, values: Sequence[Value], width: tuple[int, tuple[int, ...]]) -> tuple[list[Any], str]:
        """The values with each `%` code's ints as the bytes the width field states, and the
        struct code (`4s`) that writes them."""
        width_at, sized = width
        bytes_each = values[width_at]
        assert isinstance(bytes_each, int)
        if not 1 <= bytes_each <= 8:
            raise RdisValueError(f"{owner}: a width field states 1 to 8 bytes, not {bytes_each}")
        order = "big" if self.fixed[:1] in ">!" else "little"
        out: list[Any] = list(values)
        for i in sized:
            array: Sequence[Any] = out[i]
            for number in array:
                if not 0 <= number < 1 << 8 * bytes_each:
                    raise RdisValueError(f"{owner}: {number} is not an unsigned integer of {bytes_each} bytes "
                                         f"(value {i}, sized by value {width_at})")
            out[i] = [number.to_bytes(bytes_each, order) for number in array]
        return out, f"{bytes_each}s"

    def _varying(self, owner: str, values: Sequence[Value], varying: Varying, code: str = "") -> bytes:
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
            layout = (self.fixed + unit * rounds + tail).replace("%", code) if code else \
                self.struct.format + unit * rounds + tail
            return struct.pack(layout, *flat)
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
        except (ValueError, TypeError, IndexError, KeyError, OverflowError) as err:  # `{:c}` of 2**40: overflow
            raise RdisValueError(f"{owner}: {err}") from None
        return _latin1(owner, text)


class Unpack:
    """A reply decoded with a struct format: exactly its size or, with `rest`, its fixed
    part and then the rest as bytes; the values at `strings` as latin-1 text, each repeated
    group's values as one array a code. With `varying`, `fixed` is the format before that
    group, repeated as many times as its count field says or as fill the reply. Each integer
    split into `bits` is then given as its fields. With `until`, an unframed tagged reply's
    entry is read to those bytes (Firmata's sysex end), which are dropped. The strings at
    `padded` (`NZ`) end at their first NUL byte: the padding is not text."""

    __slots__ = ("bits", "groups", "padded", "plain", "rest", "size", "splitters", "strings", "struct", "until",
                 "varying", "varying_sizes")

    def __init__(self, fixed: str, strings: tuple[int, ...] = (), rest: bool = False,
                 groups: tuple[Group, ...] = (), varying: Varying | None = None, bits: tuple[Split, ...] = (),
                 until: bytes | None = None, varying_sizes: tuple[int, int] = (0, 0),
                 padded: tuple[int, ...] = ()) -> None:
        """`varying_sizes`: the bytes of one round of the `varying` group and of the format after it."""
        self.padded = padded
        self.varying_sizes = varying_sizes
        self.struct = struct.Struct(fixed)
        self.strings = strings
        self.rest = rest
        self.size = -1 if rest or varying else self.struct.size  # -1: the frame says where the reply ends
        self.groups = groups
        self.varying = varying
        self.bits = bits
        self.splitters = _splitters(bits)
        self.until = until
        # Its values are the struct's unpack of exactly `size` bytes, as they come (a plain exchange's
        # reply is unpacked so at once; anything else, and any error, is `decode`'s).
        self.plain = not (strings or rest or groups or varying or bits or padded or until)

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
            for i in self.padded:
                decoded[i] = decoded[i].partition("\0")[0]
            return tuple(decoded)
        return values

    def _varying(self, owner: str, data: bytes, varying: Varying) -> tuple[Value, ...]:
        """The rounds the count field says, or as many as the bytes after the head and before
        the tail hold whole; the count field's own value dropped."""
        unit, tail, count_at = varying
        unit_size, tail_size = self.varying_sizes
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
