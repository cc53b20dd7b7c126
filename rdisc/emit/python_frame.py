"""A one-step request's frame as one struct (`rdisc.lowering.whole_frame`), written for the generated
driver: the frame's constant head, the payload, a sum checksum and the constant tail packed by one
precompiled `struct.Struct`, the checksum summed from the values themselves (not from packed
bytes), its constant part folded.

`goto_all(512)` of the AX-12 (`FF FF FE 05 | 03 1E 00 02 | D9`) becomes one call:

    _PACK_GOTO_ALL(b"\\xff\\xff\\xfe\\x05", 3, 30, goal, ((0x124 + (goal & 0xff) + (goal >> 8)) & 0xff) ^ 0xff)

A value out of its code's range makes the pack fail, as the general way's would, so the one-step
function says None and the general way says what is wrong: the sum of a value's bytes may be
written for the values the pack takes only (`(goal >> 8)`, unmasked, is a byte when `H` takes goal).
"""

from __future__ import annotations

from rdisc.lowering.whole_frame import WholeFrame, whole_frame
from rdisc.semantics import model as m

__all__ = ["WholeFrame", "byte_terms", "whole_frame"]  # the struct decided by the lowering; its terms written here


def byte_terms(name: str, slot: m.Slot) -> list[str]:
    """The bytes the struct code of `slot` packs `name`'s value into, as Python terms to sum
    (for an integer the code takes: a larger one fails the pack): `goal`, or `(goal & 0xff)`
    and `(goal >> 8)`."""
    size = slot.size
    signed = slot.code.islower()
    terms = [name if size == 1 and not signed else f"({name} & 0xff)"]
    for byte in range(1, size):
        last = byte == size - 1 and not signed
        terms.append(f"({name} >> {8 * byte})" if last else f"({name} >> {8 * byte} & 0xff)")
    return terms
