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

import functools
import math
import struct
from collections.abc import Callable, Mapping
from typing import Any

from rdisc import engine
from rdisc import lower as plans
from rdisc.engine.plans import plainly_given
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
    summed = checksum is not None and partial is not None
    folded = partial or 0  # the covered bytes' sum
    kinds, bounds, one, two, (low, high), (least, most) = _tests(params)

    k, j = (kinds + (object, object))[:2]
    packed = functools.partial(pack, *constants)  # the leading constants put in by C

    def request(state: Mapping[str, m.Value], args: Any) -> bytes | None:
        try:  # one number or two tested here, any other parameters by the engine's own test
            if one:
                (a,) = args
                if type(a) is not k or not low <= a <= high:
                    return None
                payload = packed(a) if values is None else pack(*values(state, args))
            elif two:
                a, b = args
                if type(a) is not k or type(b) is not j or not low <= a <= high or not least <= b <= most:
                    return None
                payload = packed(a, b) if values is None else pack(*values(state, args))
            elif not plainly_given(args, kinds, bounds):
                return None
            else:
                payload = packed(*args) if values is None else pack(*values(state, args))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None
        if summed:  # the covered bytes' sum is folded: the payload's added
            checked = head + payload + pack_check((((folded + sum(payload)) & full) ^ flip) & mask)
            return checked + tail if tail else checked
        if checksum is None:
            return head + payload + tail if head or tail else payload
        return head + payload + pack_check(checksum(covered + payload)) + tail

    return request


_Range = tuple[Any, Any]


def _tests(params: tuple[engine.Param, ...]) -> tuple[tuple[type, ...], tuple[tuple[int, Any, Any], ...], bool, bool,
                                                      _Range, _Range]:
    """How a one-step request tests its values (each of its parameter's own type and within its
    range, else the general way says what is wrong): their kinds and ranges for the engine's own
    test (`plainly_given`), and whether they are one number or two, tested in the closure itself
    against these two ranges (a number without a range is within -inf..inf)."""
    kinds = tuple(prm.kind for prm in params)
    bounds = tuple((i, prm.low, prm.high) for i, prm in enumerate(params) if prm.low is not None)
    numbers = all(kind in (int, float) for kind in kinds)
    ranges: list[_Range] = [(-math.inf, math.inf) if prm.low is None else (prm.low, prm.high) for prm in params]
    ranges += [(-math.inf, math.inf)] * (2 - len(ranges))
    return kinds, bounds, numbers and len(params) == 1, numbers and len(params) == 2, ranges[0], ranges[1]


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
    values = listed([bound(e, type_, slots(call.args)) for _, e, type_ in call.args.items])  # an opcode as it is
    pack = encoder.struct.pack
    kinds, _, one, two, _, _ = _tests(fields)

    k, j = (kinds + (object, object))[:2]

    def request(state: Mapping[str, m.Value], given: Any) -> bytes | None:
        try:  # one number or two tested here, any other fields by their types at once
            if one:
                (a,) = given
                if type(a) is not k:
                    return None
            elif two:
                a, b = given
                if type(a) is not k or type(b) is not j:
                    return None
            elif tuple(map(type, given)) != kinds:
                return None
            return pack(*values(state, arguments(state, given)))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    return request


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
