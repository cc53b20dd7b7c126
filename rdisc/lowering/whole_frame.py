"""A one-step request's frame as one struct: the frame's constant head, the payload, a sum checksum
and the constant tail packed by one precompiled `struct.Struct`, the checksum summed from the
values themselves (not from packed bytes), its constant part folded. Decided once, by the
lowering (`Written.whole`), for the generated driver (rdisc.emit.python_frame writes it as
source) and the runtime (rdisc.runtime.at_once makes it a closure).

A value out of its code's range makes the pack fail, as the general way's would, so the one-step
function says None and the general way says what is wrong: the sum of a value's bytes may be
computed for the values the pack takes only (`(goal >> 8)`, unmasked, is a byte when `H` takes goal).
"""

from __future__ import annotations

import struct
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Protocol

from rdisc.semantics import model as m

__all__ = ["WholeFrame", "whole_frame"]

_INTEGER_CODES = frozenset("bBhHiIlLqQ")
_STANDARD = {"<": "<", ">": ">", "!": ">", "=": "="}  # byte orders with standard sizes and no alignment


@dataclass(frozen=True, slots=True)
class WholeFrame:
    """How one struct packs a one-step request whole."""

    format: str  # the struct module's format: head (`Ns`), the payload's codes, the checksum's, tail (`Ns`)
    partial: int | None  # a sum checksum's constant part: the bytes it covers of the head and of constant values
    slots: tuple[m.Slot, ...]  # the payload's values' codes, in order


class _Values(Protocol):
    @property
    def items(self) -> Sequence[tuple[str, m.Expr, Any]]: ...


class Request(Protocol):
    """What of a one-step request (the lowering's `Written`) its one struct is made from: the
    lowering's plans are above this module, so it names only the parts it reads."""

    @property
    def values(self) -> _Values: ...
    @property
    def checksum(self) -> object | None: ...
    @property
    def check_format(self) -> str: ...
    @property
    def check_size(self) -> int: ...
    @property
    def partial(self) -> int | None: ...
    @property
    def head(self) -> bytes: ...
    @property
    def tail(self) -> bytes: ...


def whole_frame(encoding: m.Pack | m.Format | None, written: Request) -> WholeFrame | None:
    """The one struct of `written`'s head, payload, checksum and tail; None where its payload's
    layout has host order, groups, bit fields or a code not an integer's (with a checksum), or
    where the checksum is not a sum or not packed in the payload's byte order."""
    if not isinstance(encoding, m.Pack) or (written.checksum is None and not written.head and not written.tail):
        return None
    layout = encoding.layout
    order = _STANDARD.get(layout.order)
    if order is None or layout.bits or layout.groups or layout.rest or layout.varying is not None:
        return None
    if len(layout.slots) != len(written.values.items):
        return None
    check = ""
    partial = None
    if written.checksum is not None:
        if written.partial is None or not all(slot.code in _INTEGER_CODES for slot in layout.slots):
            return None
        check = written.check_format.lstrip("<>!=@")
        prefix = written.check_format[: len(written.check_format) - len(check)]
        if check not in _INTEGER_CODES or (written.check_size > 1 and _STANDARD.get(prefix) != order):
            return None
        partial = written.partial
        for (_, value, _), slot in zip(written.values.items, layout.slots):
            if isinstance(value, m.Const):
                try:
                    partial += sum(struct.pack(layout.order + slot.code, value.value))
                except struct.error:
                    return None  # the general way says what is wrong, each time
    head = f"{len(written.head)}s" if written.head else ""
    tail = f"{len(written.tail)}s" if written.tail else ""
    return WholeFrame(f"{layout.order}{head}{layout.codes}{check}{tail}", partial, layout.slots)
