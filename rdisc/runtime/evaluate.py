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

import operator
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from rdisc.semantics import model as m
from rdisc.semantics.operators import BINARY, FUNCTIONS, UNARY, EvalError

__all__ = ["EvalError", "Prepared", "coerce", "evaluate", "prepare"]


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
    raise AssertionError(f"unknown expression node {expr!r}")


def coerce(value: m.Value, type_: m.Type) -> m.Value:
    """A value as the type it is declared with: ints widen to floats, nothing else changes."""
    if type_ is m.Type.FLOAT and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    return value


Prepared = Callable[[Mapping[str, m.Value], Mapping[str, m.Value], Sequence[m.Value]], m.Value]
"""A prepared expression: `f(state, local, reply)`, local holding parameters or fields."""


def prepare(expr: m.Expr) -> Prepared:
    """`expr` as a closure computing what `evaluate` computes, given values of the declared types.

    Names are read from `state` or `local` by the scope the checker gave them.
    Every value there must already be of its declared type (the runtime binds
    them so: ints made floats where a float is declared), so no name is widened
    here as `evaluate` does.
    """
    folded = _fold(expr)
    if folded is not None:
        value = folded.value
        return lambda s, loc, r: value
    match expr:
        case m.Var(name=name, scope=m.Scope.STATE):
            return lambda s, loc, r: s[name]
        case m.Var(name=name):
            return lambda s, loc, r: loc[name]
        case m.ReplyValue(index=index):
            return lambda s, loc, r: r[index]
        case m.UnaryOp(op=op, operand=operand):
            unary, a = UNARY[op], prepare(operand)
            return lambda s, loc, r: unary(a(s, loc, r))
        case m.BinaryOp(op="and", left=left, right=right):
            a, b = prepare(left), prepare(right)
            return lambda s, loc, r: a(s, loc, r) and b(s, loc, r)
        case m.BinaryOp(op="or", left=left, right=right):
            a, b = prepare(left), prepare(right)
            return lambda s, loc, r: a(s, loc, r) or b(s, loc, r)
        case m.BinaryOp(op=op, left=left, right=right):
            return _binary(_operator(expr), left, right)
        case m.IfElse(cond=cond, then=then, orelse=orelse):
            return _if_else(prepare(cond), then, orelse)
        case m.FuncCall(func=func, args=args):
            return _call(FUNCTIONS[func], args)
    raise AssertionError(f"unknown expression node {expr!r}")


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


def _constant(expr: m.Expr) -> bool:
    match expr:
        case m.Const():
            return True
        case m.Var() | m.ReplyValue():
            return False
        case m.UnaryOp(operand=operand):
            return _constant(operand)
        case m.BinaryOp(left=left, right=right):
            return _constant(left) and _constant(right)
        case m.IfElse(cond=cond, then=then, orelse=orelse):
            return _constant(cond) and _constant(then) and _constant(orelse)
        case m.FuncCall(args=args):
            return all(_constant(a) for a in args)
    return False


def _if_else(c: Prepared, then: m.Expr, orelse: m.Expr) -> Prepared:
    t, o = _fold(then), _fold(orelse)
    if t is not None and o is not None:
        tv, ov = t.value, o.value
        return lambda s, loc, r: tv if c(s, loc, r) else ov
    if t is not None:
        tv, of = t.value, prepare(orelse)
        return lambda s, loc, r: tv if c(s, loc, r) else of(s, loc, r)
    if o is not None:
        tf, ov = prepare(then), o.value
        return lambda s, loc, r: tf(s, loc, r) if c(s, loc, r) else ov
    tf, of = prepare(then), prepare(orelse)
    return lambda s, loc, r: tf(s, loc, r) if c(s, loc, r) else of(s, loc, r)


def _call(function: Callable[..., Any], args: tuple[m.Expr, ...]) -> Prepared:
    """A function call; constant arguments after the first are passed as they are."""
    first = prepare(args[0]) if args else None
    rest = [_fold(a) for a in args[1:]]
    if first is not None and all(c is not None for c in rest):
        constants = tuple(c.value for c in rest)  # type: ignore[union-attr]
        if not constants:
            return lambda s, loc, r: function(first(s, loc, r))
        if len(constants) == 2:
            lo, hi = constants
            return lambda s, loc, r: function(first(s, loc, r), lo, hi)
        return lambda s, loc, r: function(first(s, loc, r), *constants)
    prepared = tuple(prepare(a) for a in args)
    if len(prepared) == 2:
        a, b = prepared
        return lambda s, loc, r: function(a(s, loc, r), b(s, loc, r))
    return lambda s, loc, r: function(*[p(s, loc, r) for p in prepared])


# On two ints these operators of BINARY compute exactly what the plain ones do
# (their checks are for floats and strings), and a plain one is a C call.
_PLAIN_ON_INTS = {"+": operator.add, "-": operator.sub, "*": operator.mul}


def _operator(expr: m.BinaryOp) -> Callable[[Any, Any], Any]:
    if expr.op in _PLAIN_ON_INTS and expr.left.type is m.Type.INT and expr.right.type is m.Type.INT:
        return _PLAIN_ON_INTS[expr.op]
    return BINARY[expr.op]


def _binary(binary: Callable[[Any, Any], Any], left: m.Expr, right: m.Expr) -> Prepared:
    """A binary operation, with its most common shapes (a name or a constant on either side) unrolled."""
    match left, right:
        case _, _ if _fold(right) is not None and not isinstance(right, m.Const):
            return _binary(binary, left, _fold(right))  # type: ignore[arg-type]
        case _, _ if _fold(left) is not None and not isinstance(left, m.Const):
            return _binary(binary, _fold(left), right)  # type: ignore[arg-type]
        case m.Var(name=name, scope=m.Scope.STATE), m.Const(value=constant):
            return lambda s, loc, r: binary(s[name], constant)
        case m.Var(name=name), m.Const(value=constant):
            return lambda s, loc, r: binary(loc[name], constant)
        case _, m.Const(value=constant):
            a = prepare(left)
            return lambda s, loc, r: binary(a(s, loc, r), constant)
        case m.Const(value=constant), _:
            b = prepare(right)
            return lambda s, loc, r: binary(constant, b(s, loc, r))
    a, b = prepare(left), prepare(right)
    return lambda s, loc, r: binary(a(s, loc, r), b(s, loc, r))
