"""The runtime's requests in one step: a primitive only written (`plans.Written`) and an input
written at once (`plans.Input.request`), each one closure over the prepared expressions.

They are what a generated driver writes as one function per primitive or input, made here
from the same plans: the values' types compared at once (`tuple(map(type, args))`), a
range tested in the closure, the format's leading constants and the frame's constant bytes
folded, the checksum of a sum finished from the constant bytes' sum. Each returns None for
anything but the parameters' (or fields') own types within their ranges, and on any error:
the engine's general way then runs and says what is wrong, so both ways behave alike.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Callable, Mapping
from typing import Any

from rdisc import engine
from rdisc import lower as plans
from rdisc.runtime.closures import bound, listed, slots
from rdisc.semantics import model as m

__all__ = ["input_request", "primitive_request"]

Values = Callable[[Mapping[str, m.Value], Any], Any]
"""A closure of the values a request packs after its leading constants: f(state, args)."""


def primitive_request(w: plans.Written, params: tuple[engine.Param, ...],
                      closure: Callable[[plans.Code], Any]) -> engine.Request:
    """A primitive's request in one step, as the lowering describes it (`plans.Written`)."""
    if w.constant is not None:
        constant = w.constant
        return lambda state, args: None if args else constant
    leading = leading_constants(w.values)  # the values: these, then the parameters' in order
    constants = leading or ()
    values: Callable[[Mapping[str, m.Value], Any], Any] | None = None if leading is not None else closure(w.values)
    pack = struct.Struct(w.format).pack
    head, tail, covered, partial = w.head, w.tail, w.covered, w.partial
    checksum: engine.Checksum | None = None if w.checksum is None else w.checksum.value
    pack_check = struct.Struct(w.check_format or "B").pack
    full, flip, mask = _sum_finish(checksum)
    framed = _framed(pack, constants, values, head, tail, covered, partial, checksum, pack_check, full, flip, mask)
    return typed(params, framed)


def _framed(pack: Callable[..., bytes], constants: tuple[m.Value, ...], values: Values | None, head: bytes,
            tail: bytes, covered: bytes, partial: int | None, checksum: engine.Checksum | None,
            pack_check: Callable[..., bytes], full: int, flip: int, mask: int) -> engine.Request:
    """The values packed and framed, the parameters' values taken as they are (`_generally_given`
    tests them first)."""

    def framed(state: Mapping[str, m.Value], args: Any) -> bytes | None:
        try:
            payload = pack(*constants, *args) if values is None else pack(*values(state, args))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None
        if checksum is None:
            return head + payload + tail
        if partial is not None:
            return head + payload + pack_check((((partial + sum(payload)) & full) ^ flip) & mask) + tail
        return head + payload + pack_check(checksum(covered + payload)) + tail

    return framed


def typed(params: tuple[engine.Param, ...], then: engine.Request) -> engine.Request:
    """`then` of values each of its parameter's own type and within its range (else None, and
    the general way says what is wrong): one or two numbers tested in the closure itself, any
    other parameters by the engine's own test (`plainly_given`)."""
    kinds = tuple(prm.kind for prm in params)
    bounds = tuple((i, prm.low, prm.high) for i, prm in enumerate(params) if prm.low is not None)
    if len(params) > 2 or any(kind not in (int, float) for kind in kinds):
        test = engine.plainly_given
        return lambda state, args: then(state, args) if test(args, kinds, bounds) else None
    ranges: list[tuple[Any, Any]] = [(-math.inf, math.inf) if prm.low is None else (prm.low, prm.high) for prm in params]
    match kinds, ranges:
        case (), _:
            return lambda state, args: None if args else then(state, args)
        case (k,), [(low, high)]:
            return lambda state, args: (
                then(state, args) if len(args) == 1 and type(args[0]) is k and low <= args[0] <= high else None)
        case (k, j), [(low, high), (least, most)]:
            return lambda state, args: (
                then(state, args) if len(args) == 2 and type(args[0]) is k and type(args[1]) is j
                and low <= args[0] <= high and least <= args[1] <= most else None)
    raise AssertionError(kinds)


def input_request(i: plans.Input, fields: tuple[engine.Param, ...],
                  params: tuple[engine.Param, ...]) -> engine.Request | None:
    """An input written at once (`plans.Input.request`) in one step: its fields' types compared,
    its interface's arguments computed (an int made a float where a float is declared), the
    call's values packed after their leading constants. None where a field or an argument is an
    array or spread (the engine composes its general way into one then)."""
    (call,) = i.interface.calls
    target = call.target
    assert isinstance(target, plans.Primitive) and target.encoder is not None  # `Input.request`
    encoder = target.encoder.value
    assert isinstance(encoder, engine.Pack)
    codes = (i.args, call.args)
    if any(prm.size is not None or prm.low is not None for prm in (*fields, *params)) \
            or any(key for code in codes for key, _, _ in code.items):
        return None
    arguments = listed([bound(e, prm.type, slots(i.args)) for (_, e, _), prm in zip(i.args.items, call.args.params)])
    items, at = call.args.items, 0
    while at < len(items) and isinstance(items[at][1], m.Const) and items[at][2] is None:
        at += 1  # the leading constants (an opcode), put in as they are
    constants = tuple(e.value for _, e, _ in items[:at] if isinstance(e, m.Const))
    values = listed([bound(e, type_, slots(call.args)) for _, e, type_ in items[at:]])
    pack = encoder.struct.pack

    def request(state: Mapping[str, m.Value], given: Any) -> bytes | None:
        try:
            return pack(*constants, *values(state, arguments(state, given)))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    return typed(fields, request)


def leading_constants(code: plans.Code) -> tuple[m.Value, ...] | None:
    """The constants a primitive's format values start with, when the parameters' values follow
    them as they are, in order (an opcode and the parameters: `pack(*constants, *args)`)."""
    count = len(code.items) - len(code.params)
    if count < 0 or any(not isinstance(e, m.Const) or type_ is not None for _, e, type_ in code.items[:count]):
        return None
    for (_, e, type_), prm in zip(code.items[count:], code.params):
        if not isinstance(e, m.Var) or e.scope is not m.Scope.PARAM or e.name != prm.name or type_ is not None:
            return None
    return tuple(e.value for _, e, _ in code.items[:count] if isinstance(e, m.Const))


def _sum_finish(checksum: engine.Checksum | None) -> tuple[int, int, int]:
    """A "sum" checksum's last steps, as masks: kept to its width, inverted (XOR), masked."""
    if checksum is None:
        return 0, 0, 0
    full = (1 << checksum.width) - 1
    return full, full if checksum.inverted else 0, full if checksum.mask is None else checksum.mask
