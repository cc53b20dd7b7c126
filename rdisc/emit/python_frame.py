"""A one-step request's frame as one struct, for the generated driver: the frame's constant head,
the payload, a sum checksum and the constant tail packed by one precompiled `struct.Struct`,
the checksum summed from the values themselves (not from packed bytes), its constant part folded.

`goto_all(512)` of the AX-12 (`FF FF FE 05 | 03 1E 00 02 | D9`) becomes one call:

    _PACK_GOTO_ALL(b"\\xff\\xff\\xfe\\x05", 3, 30, goal, ((0x124 + (goal & 0xff) + (goal >> 8)) & 0xff) ^ 0xff)

A value out of its code's range makes the pack fail, as the general way's would, so the one-step
function says None and the general way says what is wrong: the sum of a value's bytes may be
written for the values the pack takes only (`(goal >> 8)`, unmasked, is a byte when `H` takes goal).
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

from rdisc import lower as lowering
from rdisc.emit.python_expr import literal
from rdisc.semantics import model as m
from rdisc.semantics.model import Type

_INTEGER_CODES = frozenset("bBhHiIlLqQ")
_STANDARD = {"<": "<", ">": ">", "!": ">", "=": "="}  # byte orders with standard sizes and no alignment


@dataclass(frozen=True, slots=True)
class WholeFrame:
    """How one struct packs a one-step request whole."""

    format: str  # the struct module's format: head (`Ns`), the payload's codes, the checksum's, tail (`Ns`)
    partial: int | None  # a sum checksum's constant part: the bytes it covers of the head and of constant values
    slots: tuple[m.Slot, ...]  # the payload's values' codes, in order


def whole_frame(encoding: m.Pack | m.Format | None, written: lowering.Written) -> WholeFrame | None:
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


@dataclass(frozen=True, slots=True)
class OneStep:
    """A request a typed method makes in one step and hands to the engine's write (`Robot._write`)
    or plain exchange (`Robot._ask`), as the lowering planned it: a primitive's (`written`, with
    its struct constants), or an interface's that is one plain write (`call`, its one call packed
    by `pack`), or an input's of such an interface (`binding` besides).
    Values it does not take go the general way (`general`, with the values as a list), which says
    what is wrong."""

    way: str  # "_write" or "_ask": the robot's method the request goes to
    target: str  # the constant of the primitive written
    general: str  # the robot's method of the general way: "_call_primitive" or "_input_in_full"
    plan: str  # the constant of the plan the general way takes
    params: tuple[m.Parameter, ...]  # the values' parameters (or fields), each tested for its type and range
    pack: str = ""  # the precompiled struct's `pack`
    written: lowering.Written | None = None
    whole: WholeFrame | None = None
    checked: tuple[str, str] = ("", "")  # a checksum not in the whole struct: its value, around the payload's name
    call: lowering.Call | None = None  # an interface's one call, its arguments packed by `pack`
    binding: lowering.Code | None = None  # an input's: its fields to the interface's parameters


_TYPES = {Type.INT: "int", Type.FLOAT: "float", Type.BOOL: "bool", Type.STRING: "str", Type.BYTES: "bytes"}


def type_tests(names: list[str], params: tuple[m.Parameter, ...], *, refused: bool) -> list[str]:
    """The test of each value the one step takes: of its parameter's own type (an array a tuple),
    within its range (bytes by their length); `refused`, the test of a value it does not take."""
    tests = []
    for name, prm in zip(names, params):
        kind = _TYPES[prm.type] if isinstance(prm.type, Type) else "tuple"
        test = f"type({name}) is {'not ' if refused else ''}{kind}"
        if prm.low is not None and prm.high is not None:
            measured, bound = (f"len({name})", Type.INT) if prm.type == Type.BYTES else (name, prm.type)
            test += f" {'or not' if refused else 'and'} {literal(prm.low, bound).text} <= {measured} <= " \
                    f"{literal(prm.high, bound).text}"
        tests.append(test)
    return tests


def reads_state(exprs: list[m.Expr]) -> bool:
    """Whether any of the expressions reads a state variable (`state["name"]`)."""
    return any(v.scope is m.Scope.STATE for e in exprs for v in m.variables(e))
