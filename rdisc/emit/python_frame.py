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

from dataclasses import dataclass

from rdisc import lower as lowering
from rdisc.emit.python_expr import literal
from rdisc.lowering.whole_frame import WholeFrame, whole_frame
from rdisc.semantics import model as m
from rdisc.semantics.model import Type

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
    connection: str = ""  # the written primitive's connection: whose lane a write goes through


_TYPES = {Type.INT: "int", Type.FLOAT: "float", Type.BOOL: "bool", Type.STRING: "str", Type.BYTES: "bytes"}


def type_tests(names: list[str], params: tuple[m.Parameter, ...], *, refused: bool) -> list[str]:
    """The test of each value the one step takes: of its parameter's own type (an array a tuple),
    within its range (bytes by their length; a float without one finite, as the engine's
    `held_to` says: NaN and the infinities go the general way, which refuses them);
    `refused`, the test of a value it does not take."""
    tests = []
    for name, prm in zip(names, params):
        kind = _TYPES[prm.type] if isinstance(prm.type, Type) else "tuple"
        test = f"type({name}) is {'not ' if refused else ''}{kind}"
        joined = "or not" if refused else "and"
        if prm.low is not None and prm.high is not None:
            measured, bound = (f"len({name})", Type.INT) if prm.type == Type.BYTES else (name, prm.type)
            test += f" {joined} {literal(prm.low, bound).text} <= {measured} <= {literal(prm.high, bound).text}"
        elif prm.type == Type.FLOAT:
            test += f" {joined} isfinite({name})"
        tests.append(test)
    return tests


def reads_state(exprs: list[m.Expr]) -> bool:
    """Whether any of the expressions reads a state variable (`state["name"]`)."""
    return any(v.scope is m.Scope.STATE for e in exprs for v in m.variables(e))
