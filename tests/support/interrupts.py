"""Where CPython runs a signal's handler: before the instruction after a call, after a function's
start and at a loop's turn (its eval breaker: RESUME, CALL, JUMP_BACKWARD), and nowhere else. A
test or benchmark that calls a handler from a trace function at each of these places, in turn,
meets every moment a signal can really land at, deterministically (tests/runtime/test_signals.py,
benchmarks/signal_sweep.py)."""

from __future__ import annotations

import dis
from types import CodeType

_FOUND: dict[CodeType, frozenset[int]] = {}


def check_points(code: CodeType) -> frozenset[int]:
    """The offsets of `code`'s instructions before which a handler can run (a trace function's
    "opcode" event at `frame.f_lasti` is one of them)."""
    found = _FOUND.get(code)
    if found is None:
        points: set[int] = set()
        previous = None
        for instruction in dis.get_instructions(code):
            if previous in ("RESUME", "CALL", "CALL_FUNCTION_EX"):
                points.add(instruction.offset)
            if instruction.opname == "JUMP_BACKWARD":
                points.add(instruction.argval)
            if instruction.opname != "CACHE":
                previous = instruction.opname
        found = _FOUND[code] = frozenset(points)
    return found
