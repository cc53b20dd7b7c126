"""The expression interpreter: evaluates the checked, typed IR of the Model.

It walks the IR directly (never source text, never Python's eval). Operators and
functions come from rdisc.semantics.operators, the same definitions the checker
folds constants with, so a constant means the same thing at check and at run time.

`evaluate` is the reference walk. `prepare` does the same walk once, ahead of
time, and returns a closure per node (the runtime calls an expression thousands
of times a second); it reads each name from where the checker bound it (state or
the local parameters/fields), and it is tested against `evaluate`.
"""

from __future__ import annotations

import math
import operator
import sys
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from rdisc.engine import element, lookup, replaced
from rdisc.semantics import model as m
from rdisc.semantics.model import coerce
from rdisc.semantics.operators import BINARY, FUNCTIONS, UNARY, EvalError

__all__ = ["EvalError", "Prepared", "always_float", "coerce", "evaluate", "prepare"]


def evaluate(expr: m.Expr, names: Mapping[str, m.Value], reply: Sequence[m.Value] = ()) -> m.Value:
    """The value of `expr` where `names` holds parameters, fields and state, `reply` is `out`."""
    match expr:
        case m.Const(value=value):
            return value
        case m.Var(name=name, type=type_):
            return coerce(names[name], type_)
        case m.ReplyValue(index=index):
            return reply[index]
        case m.UnaryOp(op=op, operand=operand):
            return UNARY[op](evaluate(operand, names, reply))
        case m.BinaryOp(op="and", left=left, right=right):
            return evaluate(left, names, reply) and evaluate(right, names, reply)
        case m.BinaryOp(op="or", left=left, right=right):
            return evaluate(left, names, reply) or evaluate(right, names, reply)
        case m.BinaryOp(op=op, left=left, right=right):
            return BINARY[op](evaluate(left, names, reply), evaluate(right, names, reply))
        case m.IfElse(cond=cond, then=then, orelse=orelse):
            return evaluate(then if evaluate(cond, names, reply) else orelse, names, reply)
        case m.FuncCall(func=func, args=args):
            return FUNCTIONS[func](*(evaluate(a, names, reply) for a in args))
        case m.Lookup(table=table, entries=entries, key=key):
            return lookup(table, dict(entries), evaluate(key, names, reply))  # type: ignore[no-any-return]
        case m.ArrayValue(items=items, type=type_):
            return tuple(coerce(evaluate(i, names, reply), type_.element) for i in items)
        case m.Element(array=array, index=at):
            return element(m.array_name(array), evaluate(array, names, reply), evaluate(at, names, reply))  # type: ignore[arg-type, no-any-return]
        case m.Replaced(array=array, index=at, value=new, type=type_):
            return replaced(m.array_name(array), evaluate(array, names, reply), evaluate(at, names, reply),  # type: ignore[arg-type]
                            coerce(evaluate(new, names, reply), type_.element))
    raise AssertionError(f"unknown expression node {expr!r}")


Prepared = Callable[[Mapping[str, m.Value], Any, Sequence[m.Value]], m.Value]
"""A prepared expression: `f(state, local, reply)`, local holding parameters or fields."""


def prepare(expr: m.Expr, slots: Mapping[str, int] | None = None) -> Prepared:
    """`expr` as a closure computing what `evaluate` computes, given values of the declared types.

    Names are read from `state` or `local` by the scope the checker gave them.
    `local` is a mapping by name, or, when `slots` is given (parameter name ->
    position), a sequence read by position. Every value there must already be
    of its declared type (the runtime binds them so: ints made floats where a
    float is declared), so no name is widened here as `evaluate` does.
    """
    folded = _fold(expr)
    if folded is not None:
        value = folded.value
        return lambda s, loc, r: value
    match expr:
        case m.Var(name=name, scope=m.Scope.STATE):
            return lambda s, loc, r: s[name]
        case m.Var(name=name):
            key = _key(name, slots)
            return lambda s, loc, r: loc[key]
        case m.ReplyValue(index=index):
            return lambda s, loc, r: r[index]
        case m.UnaryOp(op=op, operand=operand):
            unary, a = UNARY[op], prepare(operand, slots)
            return lambda s, loc, r: unary(a(s, loc, r))
        case m.BinaryOp(op="and", left=left, right=right):
            a, b = prepare(left, slots), prepare(right, slots)
            return lambda s, loc, r: a(s, loc, r) and b(s, loc, r)
        case m.BinaryOp(op="or", left=left, right=right):
            a, b = prepare(left, slots), prepare(right, slots)
            return lambda s, loc, r: a(s, loc, r) or b(s, loc, r)
        case m.BinaryOp(op=op, left=left, right=right):
            ints = left.type is m.Type.INT and right.type is m.Type.INT
            if op in _CHECKED and left.type in _NUMBERS and right.type in _NUMBERS and _operator(expr) is BINARY[op] \
                    and not (op == "*" and ints):  # an int product keeps BINARY's bound
                return _checked(op, _folded(left), _folded(right), slots)
            return _binary(_operator(expr), left, right, slots)
        case m.IfElse(cond=cond, then=then, orelse=orelse):
            return _if_else(prepare(cond, slots), then, orelse, slots)
        case m.FuncCall(func=func, args=args):
            return _call(func, args, slots)
        case m.Lookup(table=table, entries=entries, key=key):
            found, k = dict(entries), prepare(key, slots)
            return lambda s, loc, r: lookup(table, found, k(s, loc, r))
        case m.ArrayValue(items=items, type=type_):
            floats = type_.element is m.Type.FLOAT
            parts = [prepare(i, slots) for i in items]
            if floats:
                return lambda s, loc, r: tuple(float(f(s, loc, r)) for f in parts)  # type: ignore[arg-type]
            return lambda s, loc, r: tuple(f(s, loc, r) for f in parts)
        case m.Element(array=array, index=at):
            name, a, i = m.array_name(array), prepare(array, slots), prepare(at, slots)
            return lambda s, loc, r: element(name, a(s, loc, r), i(s, loc, r))  # type: ignore[arg-type]
        case m.Replaced(array=array, index=at, value=new, type=type_):
            name, a, i, v = m.array_name(array), prepare(array, slots), prepare(at, slots), prepare(new, slots)
            widen = type_.element is m.Type.FLOAT
            return lambda s, loc, r: replaced(name, a(s, loc, r), i(s, loc, r),  # type: ignore[arg-type]
                                              float(v(s, loc, r)) if widen else v(s, loc, r))
    raise AssertionError(f"unknown expression node {expr!r}")


_FLOAT_FUNCTIONS = frozenset({"float", "sqrt", "sin", "cos", "atan2", "hypot"})  # always return a float


def always_float(expr: m.Expr) -> bool:
    """Whether `expr` certainly evaluates to a float (or fails), its local names being floats where declared so.

    Conservative: False says nothing. The runtime uses it to skip widening a
    value that is a float already.
    """
    match expr:
        case m.Const(value=value):
            return type(value) is float
        case m.Var(scope=scope, type=type_):
            return scope is not m.Scope.STATE and type_ is m.Type.FLOAT
        case m.UnaryOp(op="-" | "+", operand=operand):
            return always_float(operand)
        case m.BinaryOp(op="/", left=left, right=right):
            return left.type in _NUMBERS and right.type in _NUMBERS
        case m.BinaryOp(op="+" | "-" | "*", left=left, right=right):
            return (left.type in _NUMBERS and right.type in _NUMBERS
                    and (always_float(left) or always_float(right)))
        case m.IfElse(then=then, orelse=orelse):
            return always_float(then) and always_float(orelse)
        case m.FuncCall(func="abs" | "min" | "max" | "clamp", args=args):
            return bool(args) and all(always_float(a) for a in args)
        case m.FuncCall(func="round", args=args):
            return len(args) == 2
        case m.FuncCall(func=func):
            return func in _FLOAT_FUNCTIONS
    return False


def _key(name: str, slots: Mapping[str, int] | None) -> str | int:
    """Where a parameter or field is read in `local`: its name, or its position."""
    return name if slots is None else slots[name]


def _fold(expr: m.Expr) -> m.Const | None:
    """The value of an expression that reads no name and no reply, if it has one."""
    if isinstance(expr, m.Const):
        return expr
    if not _constant(expr):
        return None
    try:
        return m.Const(evaluate(expr, {}), expr.type)
    except (EvalError, ArithmeticError, ValueError, TypeError):
        return None  # left to fail when it runs, as `evaluate` would


def _folded(expr: m.Expr) -> m.Expr:
    """`expr`, or the constant it folds to."""
    folded = _fold(expr)
    return expr if folded is None else folded


def _constant(expr: m.Expr) -> bool:
    """Whether `expr` reads no name and no reply (a replaced element is never folded)."""
    match expr:
        case m.Const():
            return True
        case m.Var() | m.ReplyValue() | m.Replaced():
            return False
    return all(_constant(o) for o in m.operands(expr))


def _if_else(c: Prepared, then: m.Expr, orelse: m.Expr, slots: Mapping[str, int] | None) -> Prepared:
    t, o = _fold(then), _fold(orelse)
    if t is not None and o is not None:
        tv, ov = t.value, o.value
        return lambda s, loc, r: tv if c(s, loc, r) else ov
    if t is not None:
        tv, of = t.value, prepare(orelse, slots)
        return lambda s, loc, r: tv if c(s, loc, r) else of(s, loc, r)
    if o is not None:
        tf, ov = prepare(then, slots), o.value
        return lambda s, loc, r: tf(s, loc, r) if c(s, loc, r) else ov
    tf, of = prepare(then, slots), prepare(orelse, slots)
    return lambda s, loc, r: tf(s, loc, r) if c(s, loc, r) else of(s, loc, r)


def _call(func: str, args: tuple[m.Expr, ...], slots: Mapping[str, int] | None) -> Prepared:
    """A function call; constant arguments after the first are passed as they are."""
    function = FUNCTIONS[func]
    first = prepare(args[0], slots) if args else None
    rest = [_fold(a) for a in args[1:]]
    if first is not None and all(c is not None for c in rest):
        constants = tuple(c.value for c in rest)  # type: ignore[union-attr]
        if not constants:
            if func == "round":
                return _round(args[0], first, slots)
            return lambda s, loc, r: function(first(s, loc, r))
        if len(constants) == 2:
            lo, hi = constants
            if func == "clamp":
                return _clamp(args[0], first, lo, hi, slots)
            return lambda s, loc, r: function(first(s, loc, r), lo, hi)
        return lambda s, loc, r: function(first(s, loc, r), *constants)
    prepared = tuple(prepare(a, slots) for a in args)
    if len(prepared) == 2:
        a, b = prepared
        return lambda s, loc, r: function(a(s, loc, r), b(s, loc, r))
    return lambda s, loc, r: function(*[p(s, loc, r) for p in prepared])


# For speed, `round(x)` and `clamp(x, lo, hi)` with constant bounds are computed
# in the closure, without the call to FUNCTIONS' Python function.
_ROUND = FUNCTIONS["round"]


def _round(arg: m.Expr, a: Prepared, slots: Mapping[str, int] | None) -> Prepared:
    scaled = _scaled(arg)
    if scaled is not None:
        # round(name * constant), a unit conversion: the whole of it in one closure.
        binary, name, c = scaled
        key = _key(name, slots)

        def rounded_scaled(s: Mapping[str, m.Value], loc: Any, r: Sequence[m.Value]) -> m.Value:
            v = loc[key]
            x: Any = binary(v, c)
            if not _MIN <= x <= _MAX:
                x = _overflow(v, c, x)
            try:
                return round(x)
            except (ValueError, OverflowError):
                return _ROUND(x)  # raises the EvalError FUNCTIONS' round raises

        return rounded_scaled

    def rounded(s: Mapping[str, m.Value], loc: Any, r: Sequence[m.Value]) -> m.Value:
        x: Any = a(s, loc, r)
        try:
            return round(x)
        except (ValueError, OverflowError):
            return _ROUND(x)  # raises the EvalError FUNCTIONS' round raises

    return rounded


def _scaled(expr: m.Expr) -> tuple[Callable[[Any, Any], Any], str, m.Value] | None:
    """(operator, local name, constant) of `name op constant` that `_checked` computes, if `expr` is one."""
    match expr:
        case m.BinaryOp(op=op, left=m.Var(name=name, scope=scope), right=m.Const(value=c)) if (
            op in _CHECKED and scope is not m.Scope.STATE and expr.left.type in _NUMBERS
            and expr.right.type in _NUMBERS and _operator(expr) is BINARY[op] and not (op == "/" and c == 0)
        ):
            return _CHECKED[op], name, c
    return None


def _clamp(arg: m.Expr, a: Prepared, lo: m.Value, hi: m.Value, slots: Mapping[str, int] | None) -> Prepared:
    if isinstance(arg, m.Var) and arg.scope is not m.Scope.STATE:
        key = _key(arg.name, slots)
        return lambda s, loc, r: lo if loc[key] < lo else hi if loc[key] > hi else loc[key]  # noqa: FURB136

    def clamped(s: Mapping[str, m.Value], loc: Any, r: Sequence[m.Value]) -> m.Value:
        x: Any = a(s, loc, r)
        return lo if x < lo else hi if x > hi else x  # noqa: FURB136 - as FUNCTIONS["clamp"]

    return clamped


# On two ints these operators of BINARY compute exactly what the plain ones do
# (their checks are for floats and strings), and a plain one is a C call.
_PLAIN_ON_INTS = {"+": operator.add, "-": operator.sub}  # `*` keeps its bound on ints


def _operator(expr: m.BinaryOp) -> Callable[[Any, Any], Any]:
    if expr.op in _PLAIN_ON_INTS and expr.left.type is m.Type.INT and expr.right.type is m.Type.INT:
        return _PLAIN_ON_INTS[expr.op]
    return BINARY[expr.op]


def _binary(binary: Callable[[Any, Any], Any], left: m.Expr, right: m.Expr,
            slots: Mapping[str, int] | None) -> Prepared:
    """A binary operation, with its most common shapes (a name or a constant on either side) unrolled."""
    match left, right:
        case _, _ if _fold(right) is not None and not isinstance(right, m.Const):
            return _binary(binary, left, _fold(right), slots)  # type: ignore[arg-type]
        case _, _ if _fold(left) is not None and not isinstance(left, m.Const):
            return _binary(binary, _fold(left), right, slots)  # type: ignore[arg-type]
        case m.Var(name=name, scope=m.Scope.STATE), m.Const(value=constant):
            if binary in _STATE_COMPARE:
                return _STATE_COMPARE[binary](name, constant)
            return lambda s, loc, r: binary(s[name], constant)
        case m.Var(name=name), m.Const(value=constant):
            key = _key(name, slots)
            if binary in _LOCAL_COMPARE:
                return _LOCAL_COMPARE[binary](key, constant)
            return lambda s, loc, r: binary(loc[key], constant)
        case _, m.Const(value=constant):
            a = prepare(left, slots)
            return lambda s, loc, r: binary(a(s, loc, r), constant)
        case m.Const(value=constant), _:
            b = prepare(right, slots)
            return lambda s, loc, r: binary(constant, b(s, loc, r))
    a, b = prepare(left, slots), prepare(right, slots)
    return lambda s, loc, r: binary(a(s, loc, r), b(s, loc, r))


# A name compared with a constant, for speed: the comparison is made in the
# closure rather than by calling BINARY's, which are these operator functions.
_STATE_COMPARE: dict[Callable[[Any, Any], Any], Callable[[Any, Any], Prepared]] = {
    operator.eq: lambda key, c: lambda s, loc, r: s[key] == c,
    operator.ne: lambda key, c: lambda s, loc, r: s[key] != c,
    operator.lt: lambda key, c: lambda s, loc, r: s[key] < c,
    operator.le: lambda key, c: lambda s, loc, r: s[key] <= c,
    operator.gt: lambda key, c: lambda s, loc, r: s[key] > c,
    operator.ge: lambda key, c: lambda s, loc, r: s[key] >= c,
}
_LOCAL_COMPARE: dict[Callable[[Any, Any], Any], Callable[[Any, Any], Prepared]] = {
    operator.eq: lambda key, c: lambda s, loc, r: loc[key] == c,
    operator.ne: lambda key, c: lambda s, loc, r: loc[key] != c,
    operator.lt: lambda key, c: lambda s, loc, r: loc[key] < c,
    operator.le: lambda key, c: lambda s, loc, r: loc[key] <= c,
    operator.gt: lambda key, c: lambda s, loc, r: loc[key] > c,
    operator.ge: lambda key, c: lambda s, loc, r: loc[key] >= c,
}
assert all(BINARY[op] in _LOCAL_COMPARE for op in ("==", "!=", "<", "<=", ">", ">="))


# Float arithmetic, for speed: BINARY's `+ - * /` on numbers with the overflow
# check of `_checked_float` (rdisc.semantics.operators) done in the closure, no
# wrapper frame. A result within +-_MAX is finite and needs no check; any other
# (an infinity, NaN, a huge int) goes through `_overflow`, the check as written there.
_NUMBERS = (m.Type.INT, m.Type.FLOAT)
_CHECKED = {"+": operator.add, "-": operator.sub, "*": operator.mul, "/": operator.truediv}
_MAX = sys.float_info.max
_MIN = -_MAX


def _overflow(a: Any, b: Any, result: Any) -> Any:
    if isinstance(result, float) and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise EvalError("the result is too large for a float")
    return result


def _checked(op: str, left: m.Expr, right: m.Expr, slots: Mapping[str, int] | None) -> Prepared:
    """`left op right` on two numbers, as BINARY[op] computes it (its checks inlined)."""
    binary = _CHECKED[op]
    if isinstance(right, m.Const) and not (op == "/" and right.value == 0):
        c = right.value  # a constant divisor that is not 0 needs no zero check
        if isinstance(left, m.Var):
            name = left.name
            if left.scope is m.Scope.STATE:
                def state_const(s: Mapping[str, m.Value], loc: Any, r: Sequence[m.Value]) -> m.Value:
                    a = s[name]
                    result = binary(a, c)
                    return result if _MIN <= result <= _MAX else _overflow(a, c, result)

                return state_const
            key = _key(name, slots)

            def local_const(s: Mapping[str, m.Value], loc: Any, r: Sequence[m.Value]) -> m.Value:
                a = loc[key]
                result = binary(a, c)
                return result if _MIN <= result <= _MAX else _overflow(a, c, result)

            return local_const
        fa = prepare(left, slots)

        def expr_const(s: Mapping[str, m.Value], loc: Any, r: Sequence[m.Value]) -> m.Value:
            a = fa(s, loc, r)
            result = binary(a, c)
            return result if _MIN <= result <= _MAX else _overflow(a, c, result)

        return expr_const
    fa, fb = prepare(left, slots), prepare(right, slots)
    if op == "/":
        def divide(s: Mapping[str, m.Value], loc: Any, r: Sequence[m.Value]) -> m.Value:
            a: Any = fa(s, loc, r)
            b: Any = fb(s, loc, r)
            if b == 0:
                raise EvalError("division by zero")  # as operators._div
            result = a / b
            return result if _MIN <= result <= _MAX else _overflow(a, b, result)

        return divide

    def exprs(s: Mapping[str, m.Value], loc: Any, r: Sequence[m.Value]) -> m.Value:
        a, b = fa(s, loc, r), fb(s, loc, r)
        result = binary(a, b)
        return result if _MIN <= result <= _MAX else _overflow(a, b, result)

    return exprs
