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
import operator
import struct
from collections.abc import Callable, Mapping
from typing import Any

from rdisc import engine
from rdisc import lower as plans
from rdisc.engine.plans import plainly_given
from rdisc.lowering.whole_frame import WholeFrame
from rdisc.runtime.closures import bound, listed, slots
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import Prepared, clamped, prepare
from rdisc.semantics.operators import surely_float, unchecked, unchecked_operand

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
    if leading is not None and w.whole is not None and w.whole.partial is not None and checksum is not None:
        whole = _whole(w, w.whole, constants, checksum, kinds, (low, high), (least, most), one, two)
        if whole is not None:
            return whole
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


def _whole(w: plans.Written, whole: WholeFrame, constants: tuple[m.Value, ...], checksum: engine.Checksum,
           kinds: tuple[type, ...], first: _Range, second: _Range, one: bool, two: bool) -> engine.Request | None:
    """A framed request with a sum checksum packed whole by one struct (`Written.whole`): head,
    constants, the parameters' values, the checksum summed from the constant part and the values'
    own bytes (`(goal & 0xff) + (goal >> 8 & 0xff)`), tail. For one or two parameters of one or two
    bytes each; None for any other (the request is then packed, then framed)."""
    sizes = [slot.size for slot in whole.slots[len(constants):]]
    if not (one or two) or any(size > 2 for size in sizes):
        return None
    pack = functools.partial(struct.Struct(whole.format).pack, *((w.head,) if w.head else ()), *constants)
    tail = w.tail
    full, flip, mask = _sum_finish(checksum)
    partial = whole.partial or 0
    k: Any
    j: Any
    k, j = (kinds + (object, object))[:2]
    (low, high), (least, most) = first, second
    upper, other = [0xff if size == 2 else 0 for size in sizes + [1]][:2]  # a value's second byte, if it has one

    def one_value(state: Mapping[str, m.Value], args: Any) -> bytes | None:
        try:
            (a,) = args
            if type(a) is not k or not low <= a <= high:
                return None
            check = (((partial + (a & 0xff) + (a >> 8 & upper)) & full) ^ flip) & mask
            return pack(a, check, tail) if tail else pack(a, check)
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    def two_values(state: Mapping[str, m.Value], args: Any) -> bytes | None:
        try:
            a, b = args
            if type(a) is not k or type(b) is not j or not low <= a <= high or not least <= b <= most:
                return None
            check = (((partial + (a & 0xff) + (a >> 8 & upper) + (b & 0xff) + (b >> 8 & other)) & full) ^ flip) & mask
            return pack(a, b, check, tail) if tail else pack(a, b, check)
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    return one_value if one else two_values


_Range = tuple[Any, Any]


def _tests(params: tuple[engine.Param, ...]) -> tuple[tuple[type, ...], tuple[tuple[int, Any, Any], ...], bool, bool,
                                                      _Range, _Range]:
    """How a one-step request tests its values (each of its parameter's own type and within its
    range, else the general way says what is wrong): their kinds and ranges for the engine's own
    test (`plainly_given`), and whether they are one number or two, tested in the closure itself
    against these two ranges (`held_to`: a float without a range within the finite floats, an int
    within -inf..inf)."""
    kinds = tuple(prm.kind for prm in params)
    bounds = engine.one_step_bounds(params)
    numbers = all(kind in (int, float) for kind in kinds)
    ranges: list[_Range] = [engine.held_to(prm) or (-math.inf, math.inf) for prm in params]
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
    arguments = [_prepared(bound(e, prm.type, slots(i.args))) for (_, e, _), prm in zip(i.args.items, call.args.params)]
    leading = 0  # the call's values: its leading constants (an opcode) put in by C, then the rest
    while leading < len(call.args.items) and _constant(call.args.items[leading]) is not None:
        leading += 1
    constants = tuple(_constant(item) for item in call.args.items[:leading])
    where = slots(call.args)
    rest = [_prepared(packed(e, type_, where)) for _, e, type_ in call.args.items[leading:]]
    scales = [scaled(e, where) for _, e, _ in call.args.items[leading:]]
    pack = functools.partial(encoder.struct.pack, *constants) if constants else encoder.struct.pack
    kinds, bounds, one, two, first_range, second_range = _tests(fields)
    first = i.args.items[0][1] if i.args.items else None
    unwidened = bool(call.args.params) and (call.args.params[0].type is not m.Type.FLOAT or
                                            (first is not None and surely_float(first)))
    read = clamped(first, slots(i.args)) if first is not None and unwidened else None
    return _fused((kinds, bounds, one, two, first_range, second_range), arguments, rest, scales, pack, read)


def _fused(tests: tuple[tuple[type, ...], tuple[tuple[int, Any, Any], ...], bool, bool, _Range, _Range],
           arguments: list[Prepared], rest: list[Prepared], scales: list[Scaled | None], pack: Callable[..., bytes],
           read: tuple[Callable[..., Any], Any, Any, Any] | None) -> engine.Request:
    """An input's request as one closure: its fields' types compared, the interface's arguments
    computed into a tuple, the call's values from them packed; the commonest shapes (two fields
    or one, two values or one, two values each an argument scaled) unrolled, since each call of a
    closure made costs as much as the arithmetic it does; a first argument that is a function of
    a field and two constants (`clamp(linear, -0.5, 0.5)`: `read`) called here. The fields are
    tested as `_tests` says (`tests`): a float's NaN or infinity goes the general way."""
    kinds, bounds, one, two, (low, high), (least, most) = tests
    k, j = (kinds + (object, object))[:2]
    values = listed(rest)  # the general shape's
    if two and len(arguments) == 2 and len(rest) == 2 and None not in scales:
        x, y = arguments
        (fa, ka, ca), (fb, kb, cb) = scales  # type: ignore[misc]  # none is None
        if read is not None and (ka, kb) == (0, 1):  # each value its own argument's, in order
            fx, kx, lx, hx = read

            def two_read_scaled(state: Mapping[str, m.Value], given: Any) -> bytes | None:
                try:
                    a, b = given
                    if type(a) is not k or type(b) is not j or not low <= a <= high or not least <= b <= most:
                        return None
                    return pack(fa(fx(given[kx], lx, hx) * ca), fb(y(state, given, ()) * cb))
                except Exception:  # noqa: BLE001 - the general way says what is wrong
                    return None

            return two_read_scaled

        def two_scaled(state: Mapping[str, m.Value], given: Any) -> bytes | None:
            try:
                a, b = given
                if type(a) is not k or type(b) is not j or not low <= a <= high or not least <= b <= most:
                    return None
                inner = (x(state, given, ()), y(state, given, ()))
                return pack(fa(inner[ka] * ca), fb(inner[kb] * cb))
            except Exception:  # noqa: BLE001 - the general way says what is wrong
                return None

        return two_scaled
    if two and len(arguments) == 2 and len(rest) == 2:
        x, y = arguments
        f, g = rest

        def two_two(state: Mapping[str, m.Value], given: Any) -> bytes | None:
            try:
                a, b = given
                if type(a) is not k or type(b) is not j or not low <= a <= high or not least <= b <= most:
                    return None
                inner = (x(state, given, ()), y(state, given, ()))
                return pack(f(state, inner, ()), g(state, inner, ()))
            except Exception:  # noqa: BLE001 - the general way says what is wrong
                return None

        return two_two
    if one and len(arguments) == 1 and len(rest) == 1:
        (x,), (f,) = arguments, rest

        def one_one(state: Mapping[str, m.Value], given: Any) -> bytes | None:
            try:
                (a,) = given
                if type(a) is not k or not low <= a <= high:
                    return None
                return pack(f(state, (x(state, given, ()),), ()))
            except Exception:  # noqa: BLE001 - the general way says what is wrong
                return None

        return one_one

    def request(state: Mapping[str, m.Value], given: Any) -> bytes | None:
        try:  # one number or two tested here, any other fields by their types at once
            if one:
                (a,) = given
                if type(a) is not k or not low <= a <= high:
                    return None
            elif two:
                a, b = given
                if type(a) is not k or type(b) is not j or not low <= a <= high or not least <= b <= most:
                    return None
            elif not plainly_given(given, kinds, bounds):
                return None
            return pack(*values(state, tuple([x(state, given, ()) for x in arguments])))
        except Exception:  # noqa: BLE001 - the general way says what is wrong
            return None

    return request


def _constant(item: tuple[str, m.Expr, m.AnyType | None]) -> m.Value | None:
    """A call's value that is a constant put in as it is (an opcode), else None."""
    _, e, type_ = item
    return e.value if isinstance(e, m.Const) and type_ is None and e.value is not None else None


def _prepared(f: Prepared | m.Const) -> Prepared:
    """A bound value as a closure (a constant one too)."""
    return prepare(f) if isinstance(f, m.Const) else f


def packed(e: m.Expr, declared: m.AnyType | None, where: dict[str, int]) -> Prepared | m.Const:
    """`e` as a value a one-step request packs (bound to `declared`, if given): `round(x)` and
    `int(x)` of float arithmetic with Python's own operators (`unchecked_operand`), as the
    generated driver's request computes it; `round(velocity * 1000)` one closure, calling nothing."""
    arg = unchecked_operand(e)
    if arg is None or not unchecked(arg):
        return bound(e, declared, where)
    assert isinstance(e, m.FuncCall)
    function: Callable[[Any], Any] = round if e.func == "round" else int
    scale = scaled(e, where)
    if scale is not None:
        _, key, c = scale
        return lambda s, loc, r: function(loc[key] * c)
    a = _arithmetic(arg, where)
    return lambda s, loc, r: function(a(s, loc, r))


Scaled = tuple[Callable[[Any], Any], int, Any]
"""`round(x * c)` (or `int`) of a parameter: the function, where the parameter is read, the constant."""


def scaled(e: m.Expr, where: dict[str, int]) -> Scaled | None:
    """A packed value (`packed`) that is a parameter times a constant, rounded or made an int
    with Python's own `*` (`round(velocity * 1000)`: a unit's scale), as what its closure computes."""
    arg = unchecked_operand(e)
    if arg is None or not unchecked(arg) or not isinstance(e, m.FuncCall):
        return None
    function: Callable[[Any], Any] = round if e.func == "round" else int
    match arg:
        case m.BinaryOp(op="*", left=m.Var(name=name, scope=scope), right=m.Const(value=c)) \
                | m.BinaryOp(op="*", left=m.Const(value=c), right=m.Var(name=name, scope=scope)) \
                if scope is not m.Scope.STATE:
            return function, where[name], c
    return None


def _arithmetic(e: m.Expr, where: dict[str, int]) -> Prepared:
    """Float `+`, `-`, `*` and negation with Python's operators (`packed`), the rest prepared."""
    if not unchecked(e):
        return prepare(e, where)
    if isinstance(e, m.UnaryOp):
        a = _arithmetic(e.operand, where)

        def negated(s: Mapping[str, m.Value], loc: Any, r: Any) -> m.Value:
            value: Any = a(s, loc, r)
            return -value  # type: ignore[no-any-return]

        return negated
    assert isinstance(e, m.BinaryOp)
    operation = _OPERATORS[e.op]
    a, b = _arithmetic(e.left, where), _arithmetic(e.right, where)
    return lambda s, loc, r: operation(a(s, loc, r), b(s, loc, r))


_OPERATORS: dict[str, Callable[[Any, Any], Any]] = {"+": operator.add, "-": operator.sub, "*": operator.mul}


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
