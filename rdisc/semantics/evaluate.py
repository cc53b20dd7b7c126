"""The expression interpreter: evaluates the checked, typed IR of the Model.

It walks the IR directly (never source text, never Python's eval). Every operator and
function is computed by rdisc.engine.operations, the same functions the checker folds
constants with and every generated driver carries, so an expression means the same thing,
errors included, at check time, in the runtime and in a driver.

`evaluate` is the reference walk. `prepare` does the same walk once, ahead of
time, and returns a closure per node (the runtime calls an expression thousands
of times a second); it reads each name from where the checker bound it (state or
the local parameters/fields), calls Python's own operator where rdisc.semantics.operators
says it computes exactly what the operation does, and it is tested against `evaluate`.
"""

from __future__ import annotations

import builtins
import operator
from collections.abc import Callable, Mapping, Sequence
from dataclasses import replace
from typing import Any

from rdisc.engine import operations
from rdisc.engine.operations import BINARY, FUNCTIONS, UNARY, EvalError, element, lookup, lookup_or, replaced
from rdisc.semantics import model as m
from rdisc.semantics.model import coerce
from rdisc.semantics.operators import binary_operation, call_operation

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
            return UNARY[op](evaluate(operand, names, reply))  # type: ignore[no-any-return]
        case m.BinaryOp(op="and", left=left, right=right):
            return evaluate(left, names, reply) and evaluate(right, names, reply)
        case m.BinaryOp(op="or", left=left, right=right):
            return evaluate(left, names, reply) or evaluate(right, names, reply)
        case m.BinaryOp(op=op, left=left, right=right):
            return BINARY[op](evaluate(left, names, reply), evaluate(right, names, reply))  # type: ignore[no-any-return]
        case m.IfElse(cond=cond, then=then, orelse=orelse):
            return evaluate(then if evaluate(cond, names, reply) else orelse, names, reply)
        case m.FuncCall(func=func, args=args):
            return FUNCTIONS[func](*(evaluate(a, names, reply) for a in args))  # type: ignore[no-any-return]
        case m.Lookup(entries=entries, key=key, default=default) if default is not None:
            return lookup_or(dict(entries), evaluate(key, names, reply), evaluate(default, names, reply))  # type: ignore[no-any-return]
        case m.Lookup(table=table, entries=entries, key=key):
            return lookup(table, dict(entries), evaluate(key, names, reply))  # type: ignore[no-any-return]
        case m.InTable(keys=keys, key=key):
            return evaluate(key, names, reply) in keys
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
            unary, a = _PYTHON_UNARY[op], prepare(operand, slots)  # no unary operation can fail
            return lambda s, loc, r: unary(a(s, loc, r))
        case m.BinaryOp(op="and" | "or", left=left, right=right):
            return _logic(expr.op, left, right, slots)
        case m.BinaryOp(op=op, left=left, right=right):
            left, right = _folded(left), _folded(right)  # `x % (2 + 1)` is `x % 3`: Python's own `%`
            return _binary(_operation(replace(expr, left=left, right=right)), left, right, slots)
        case m.IfElse(cond=cond, then=then, orelse=orelse):
            return _if_else(cond, then, orelse, slots)
        case m.FuncCall():
            return _call(expr, slots)
        case m.Lookup(entries=entries, key=key, default=default) if default is not None:
            found, k, otherwise = dict(entries), prepare(key, slots), prepare(default, slots)
            return lambda s, loc, r: lookup_or(found, k(s, loc, r), otherwise(s, loc, r))
        case m.Lookup(table=table, entries=entries, key=key):
            found, k = dict(entries), prepare(key, slots)
            return lambda s, loc, r: lookup(table, found, k(s, loc, r))
        case m.InTable(keys=keys, key=key):
            present, k = frozenset(keys), prepare(key, slots)
            return lambda s, loc, r: k(s, loc, r) in present
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
            if type_.element is m.Type.FLOAT:
                return lambda s, loc, r: replaced(name, a(s, loc, r), i(s, loc, r), float(v(s, loc, r)))  # type: ignore[arg-type]
            return lambda s, loc, r: replaced(name, a(s, loc, r), i(s, loc, r), v(s, loc, r))  # type: ignore[arg-type]
    raise AssertionError(f"unknown expression node {expr!r}")


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


_Test = tuple[Callable[[Any, Any], Any], str | int, Any]
"""What compares, where the name is read in `local`, and the constant."""


def _test(expr: m.Expr, slots: Mapping[str, int] | None) -> _Test | None:
    """A parameter or field compared with a constant (`linear == 0`), as what compares, where the
    name is read in `local` and the constant: a test a closure makes with no closure of its own."""
    if isinstance(expr, m.BinaryOp) and expr.op in _COMPARISONS:
        right = _folded(expr.right)
        if isinstance(expr.left, m.Var) and expr.left.scope is not m.Scope.STATE and isinstance(right, m.Const):
            return _operation(replace(expr, right=right)), _key(expr.left.name, slots), right.value
    return None


def _tests(expr: m.Expr, slots: Mapping[str, int] | None) -> tuple[str, _Test, _Test] | None:
    """`and` or `or` of two tests (`_test`), as the operator and the two."""
    if isinstance(expr, m.BinaryOp) and expr.op in ("and", "or"):
        first, second = _test(expr.left, slots), _test(expr.right, slots)
        if first is not None and second is not None:
            return expr.op, first, second
    return None


def _logic(op: str, left: m.Expr, right: m.Expr, slots: Mapping[str, int] | None) -> Prepared:
    """`and` or `or`; of two tests (`linear == 0 and angular == 0`), one closure making both."""
    first, second = _test(left, slots), _test(right, slots)
    if first is not None and second is not None:
        (f, j, c), (g, k, d) = first, second
        if op == "and":
            return lambda s, loc, r: f(loc[j], c) and g(loc[k], d)
        return lambda s, loc, r: f(loc[j], c) or g(loc[k], d)
    a, b = prepare(left, slots), prepare(right, slots)
    if op == "and":
        return lambda s, loc, r: a(s, loc, r) and b(s, loc, r)
    return lambda s, loc, r: a(s, loc, r) or b(s, loc, r)


def _if_else(cond: m.Expr, then: m.Expr, orelse: m.Expr, slots: Mapping[str, int] | None) -> Prepared:
    """A conditional; a constant branch given as it is, a test (`_test`) made in the closure itself."""
    t, o = _fold(then), _fold(orelse)
    tf, of = prepare(then, slots), prepare(orelse, slots)
    tv: Any = None if t is None else t.value
    ov: Any = None if o is None else o.value
    test = _test(cond, slots)
    if test is not None:
        f, k, c = test
        if t is not None and f in _LOCAL_CHOSEN:  # the comparison made in the closure itself
            return _LOCAL_CHOSEN[f](k, c, tv, (lambda s, loc, r: ov) if o is not None else of, o is not None, ov)
        if f is operator.eq and o is None:  # `(...) if linear == 0 else (...)`: the test made here too
            return lambda s, loc, r: tf(s, loc, r) if loc[k] == c else of(s, loc, r)
        if t is not None and o is not None:
            return lambda s, loc, r: tv if f(loc[k], c) else ov
        if t is not None:
            return lambda s, loc, r: tv if f(loc[k], c) else of(s, loc, r)
        if o is not None:
            return lambda s, loc, r: tf(s, loc, r) if f(loc[k], c) else ov
        return lambda s, loc, r: tf(s, loc, r) if f(loc[k], c) else of(s, loc, r)
    both = _tests(cond, slots)
    if both is not None and both[0] == "and":  # `linear == 0 and angular == 0`: both made here
        _, (f, j, c), (g, k, d) = both
        if t is not None and f is operator.eq and g is operator.eq:  # the comparisons too
            return lambda s, loc, r: tv if loc[j] == c and loc[k] == d else of(s, loc, r)
        if t is not None:
            return lambda s, loc, r: tv if f(loc[j], c) and g(loc[k], d) else of(s, loc, r)
        return lambda s, loc, r: tf(s, loc, r) if f(loc[j], c) and g(loc[k], d) else of(s, loc, r)
    if both is not None:
        _, (f, j, c), (g, k, d) = both
        if t is not None:
            return lambda s, loc, r: tv if f(loc[j], c) or g(loc[k], d) else of(s, loc, r)
        return lambda s, loc, r: tf(s, loc, r) if f(loc[j], c) or g(loc[k], d) else of(s, loc, r)
    holds = prepare(cond, slots)
    if t is not None and o is not None:
        return lambda s, loc, r: tv if holds(s, loc, r) else ov
    if t is not None:
        return lambda s, loc, r: tv if holds(s, loc, r) else of(s, loc, r)
    if o is not None:
        return lambda s, loc, r: tf(s, loc, r) if holds(s, loc, r) else ov
    return lambda s, loc, r: tf(s, loc, r) if holds(s, loc, r) else of(s, loc, r)


def clamped(expr: m.Expr, slots: Mapping[str, int] | None) -> tuple[Callable[..., Any], str | int, Any, Any] | None:
    """A call of a function of a parameter or field and two constants (`clamp(linear, -0.5, 0.5)`),
    as the function, where the name is read in `local`, and the two constants; else None."""
    if not isinstance(expr, m.FuncCall) or len(expr.args) != 3:
        return None
    first, low, high = expr.args[0], _fold(expr.args[1]), _fold(expr.args[2])
    if not isinstance(first, m.Var) or first.scope is m.Scope.STATE or low is None or high is None:
        return None
    return _function(expr), _key(first.name, slots), low.value, high.value


def _function(expr: m.FuncCall) -> Callable[..., Any]:
    """What computes a call: its function of rdisc.engine.operations, or Python's builtin."""
    name = call_operation(expr)
    function: Callable[..., Any] = getattr(operations if name.startswith("_") else builtins, name)
    return function


def _call(expr: m.FuncCall, slots: Mapping[str, int] | None) -> Prepared:
    """A function call; constant arguments after the first are passed as they are."""
    function = _function(expr)
    args = expr.args
    rest = [_fold(a) for a in args[1:]]
    if args and all(c is not None for c in rest):
        constants = tuple(c.value for c in rest)  # type: ignore[union-attr]
        if not constants:
            return _applied(function, args[0], slots)
        first = prepare(args[0], slots)
        if len(constants) == 2:
            low, high = constants
            if isinstance(args[0], m.Var) and args[0].scope is not m.Scope.STATE:
                key = _key(args[0].name, slots)
                return lambda s, loc, r: function(loc[key], low, high)
            match _folded(args[0]):
                case m.BinaryOp(left=m.Var(name=one, scope=scope), right=m.Var(name=other, scope=other_scope)) as e if (
                    e.op not in ("and", "or") and m.Scope.STATE not in (scope, other_scope)
                ):  # of two parameters or fields (`clamp(linear / angular, -2.0, 2.0)`), read here
                    binary, j, k = _operation(e), _key(one, slots), _key(other, slots)
                    return lambda s, loc, r: function(binary(loc[j], loc[k]), low, high)
            return lambda s, loc, r: function(first(s, loc, r), low, high)
        return lambda s, loc, r: function(first(s, loc, r), *constants)
    prepared = tuple(prepare(a, slots) for a in args)
    if len(prepared) == 2:
        a, b = prepared
        return lambda s, loc, r: function(a(s, loc, r), b(s, loc, r))
    return lambda s, loc, r: function(*[p(s, loc, r) for p in prepared])


def _applied(function: Callable[[Any], Any], arg: m.Expr, slots: Mapping[str, int] | None) -> Prepared:
    """`function(arg)`, the commonest shapes of the argument (a parameter or field, or one of
    them with a constant: `round(velocity * 1000)`) read in the closure itself."""
    match arg:
        case m.Var(name=name, scope=m.Scope.STATE):
            return lambda s, loc, r: function(s[name])
        case m.Var(name=name):
            key = _key(name, slots)
            return lambda s, loc, r: function(loc[key])
        case m.BinaryOp(left=m.Var(name=name, scope=scope), right=m.Const(value=c)) if (
            arg.op not in ("and", "or") and scope is not m.Scope.STATE
        ):
            binary, key = _operation(arg), _key(name, slots)
            return lambda s, loc, r: function(binary(loc[key], c))
        case m.BinaryOp(left=m.ReplyValue(index=index), right=m.Const(value=c)) if arg.op not in ("and", "or"):
            binary = _operation(arg)  # a reply's value with a constant: `bool(out[0] & 4)`, a bit of it
            return lambda s, loc, r: function(binary(r[index], c))
    a = prepare(arg, slots)
    return lambda s, loc, r: function(a(s, loc, r))


def _operation(e: m.BinaryOp) -> Callable[[Any, Any], Any]:
    """What computes `e`: its function in rdisc.engine.operations, or Python's operator."""
    operation = binary_operation(e)
    return _PYTHON[e.op] if operation is None else getattr(operations, operation)


# Python's operators, where rdisc.semantics.operators says one computes exactly what the
# operation does: a C call, not a Python function's frame.
_PYTHON: dict[str, Callable[[Any, Any], Any]] = {
    "+": operator.add, "-": operator.sub, "*": operator.mul, "/": operator.truediv,
    "//": operator.floordiv, "%": operator.mod, ">>": operator.rshift,
    "&": operator.and_, "|": operator.or_, "^": operator.xor,
    "==": operator.eq, "!=": operator.ne, "<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge,
}
_PYTHON_UNARY: dict[str, Callable[[Any], Any]] = {
    "-": operator.neg, "+": operator.pos, "~": operator.invert, "not": operator.not_,
}


def _binary(binary: Callable[[Any, Any], Any], left: m.Expr, right: m.Expr,
            slots: Mapping[str, int] | None) -> Prepared:
    """A binary operation of folded operands, its most common shapes (a name or a constant on
    either side) unrolled."""
    match left, right:
        case m.Var(name=name, scope=m.Scope.STATE), m.Const(value=constant):
            if binary in _STATE_COMPARE:
                return _STATE_COMPARE[binary](name, constant)
            return lambda s, loc, r: binary(s[name], constant)
        case m.Var(name=name), m.Const(value=constant):
            key = _key(name, slots)
            if binary in _LOCAL_COMPARE:
                return _LOCAL_COMPARE[binary](key, constant)
            return lambda s, loc, r: binary(loc[key], constant)
        case m.Var(name=one, scope=scope), m.Var(name=other, scope=other_scope) if (
            scope is not m.Scope.STATE and other_scope is not m.Scope.STATE
        ):  # two parameters or fields (`linear / angular`)
            j, k = _key(one, slots), _key(other, slots)
            return lambda s, loc, r: binary(loc[j], loc[k])
        case m.ReplyValue(index=index), m.Const(value=constant):  # a reply's value: `out[3] * 0.1`
            return lambda s, loc, r: binary(r[index], constant)
        case _, m.Const(value=constant):
            a = prepare(left, slots)
            return lambda s, loc, r: binary(a(s, loc, r), constant)
        case m.Const(value=constant), _:
            b = prepare(right, slots)
            return lambda s, loc, r: binary(constant, b(s, loc, r))
    a, b = prepare(left, slots), prepare(right, slots)
    return lambda s, loc, r: binary(a(s, loc, r), b(s, loc, r))


# A name compared with a constant, for speed: the comparison is made in the closure
# rather than by calling Python's operator function.
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
# A conditional whose test is a name compared with a constant and whose `then` is a constant
# (`-0.001 if angular > 0 else 0.001`), for speed: the comparison made in the closure. Given
# where the name is read, the constant compared with, the `then` value, the `else` closure, and
# whether the `else` is the constant `ov` (given as it is then).
_Chosen = Callable[[Any, Any, Any, Prepared, bool, Any], Prepared]
_LOCAL_CHOSEN: dict[Callable[[Any, Any], Any], _Chosen] = {
    operator.eq: lambda k, c, tv, of, constant, ov: (
        (lambda s, loc, r: tv if loc[k] == c else ov) if constant else
        (lambda s, loc, r: tv if loc[k] == c else of(s, loc, r))),
    operator.ne: lambda k, c, tv, of, constant, ov: (
        (lambda s, loc, r: tv if loc[k] != c else ov) if constant else
        (lambda s, loc, r: tv if loc[k] != c else of(s, loc, r))),
    operator.lt: lambda k, c, tv, of, constant, ov: (
        (lambda s, loc, r: tv if loc[k] < c else ov) if constant else
        (lambda s, loc, r: tv if loc[k] < c else of(s, loc, r))),
    operator.le: lambda k, c, tv, of, constant, ov: (
        (lambda s, loc, r: tv if loc[k] <= c else ov) if constant else
        (lambda s, loc, r: tv if loc[k] <= c else of(s, loc, r))),
    operator.gt: lambda k, c, tv, of, constant, ov: (
        (lambda s, loc, r: tv if loc[k] > c else ov) if constant else
        (lambda s, loc, r: tv if loc[k] > c else of(s, loc, r))),
    operator.ge: lambda k, c, tv, of, constant, ov: (
        (lambda s, loc, r: tv if loc[k] >= c else ov) if constant else
        (lambda s, loc, r: tv if loc[k] >= c else of(s, loc, r))),
}
_COMPARISONS = frozenset({"==", "!=", "<", "<=", ">", ">="})
assert all(_PYTHON[op] in _LOCAL_COMPARE for op in ("==", "!=", "<", "<=", ">", ">="))
