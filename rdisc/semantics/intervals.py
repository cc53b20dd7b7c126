"""Bounds of a conversion over a whole range, by interval arithmetic (issue 26), so a value wrong
only between the 33 samples of E606 is found too.

Only the rules are here: each bound is computed by the operation itself (rdisc.engine.operations,
the one copy of what an operator does) at the ends of its operands' intervals, for the
operators that are monotone in each operand there. An expression with any other operator has
no bounds (None), and is checked at its samples only. Bounds may be wider than the values
(`x - x`): `witness` therefore looks for a value of the range that truly falls outside, halving
the range where the bounds do not rule it out, so nothing is reported that the runtime would
not compute.
"""

from __future__ import annotations

from collections.abc import Callable

from rdisc.engine.operations import BINARY, FUNCTIONS, UNARY
from rdisc.semantics import model as m

Interval = tuple[float, float]
MONOTONE = ("round", "int", "float", "abs", "min", "max", "clamp", "sqrt")  # in each argument, or in pieces (abs)
MAX_PIECES = 4096  # sub-ranges `witness` looks at: a conversion of 50 operations, a few ms


def bounds(expr: m.Expr, names: dict[str, Interval]) -> Interval | None:
    """Lowest and highest value of a number expression, or None where no rule is known."""
    match expr:
        case m.Const(value=value) if type(value) in (int, float):
            return float(value), float(value)  # type: ignore[arg-type]
        case m.Var(name=name) if name in names:
            return names[name]
        case m.UnaryOp(op="-" | "+", operand=operand):
            a = bounds(operand, names)
            return None if a is None else _ends(UNARY[expr.op], a)
        case m.BinaryOp(op="+" | "-" | "*" | "/", left=left, right=right):
            a, b = bounds(left, names), bounds(right, names)
            if a is None or b is None or (expr.op == "/" and b[0] <= 0 <= b[1]):
                return None  # a divisor that may be 0: the samples show it
            op = BINARY[expr.op]
            values = [op(x, y) for x in a for y in b]
            return min(values), max(values)
        case m.IfElse(cond=cond, then=then, orelse=orelse):
            taken = truth(cond, names)
            if taken is None:
                return None
            found = [bounds(branch, names) for branch, when in ((then, True), (orelse, False)) if when in taken]
            if any(f is None for f in found):
                return None
            return min(f[0] for f in found if f), max(f[1] for f in found if f)
        case m.FuncCall(func=func, args=args) if func in MONOTONE:
            parts = [bounds(a, names) for a in args]
            if any(p is None for p in parts):
                return None
            given = [p for p in parts if p is not None]
            if func == "abs":
                low, high = given[0]
                return (0.0 if low <= 0 <= high else min(abs(low), abs(high))), max(abs(low), abs(high))
            function = FUNCTIONS[func]
            try:
                return float(function(*(p[0] for p in given))), float(function(*(p[1] for p in given)))
            except (ArithmeticError, ValueError, TypeError):
                return None
    return None


def truth(cond: m.Expr, names: dict[str, Interval]) -> set[bool] | None:
    """The values a comparison (or `and`, `or`, `not` of them) may take over the intervals."""
    match cond:
        case m.BinaryOp(op="and" | "or", left=left, right=right):
            first, second = truth(left, names), truth(right, names)
            if first is None or second is None:
                return None
            both = cond.op == "and"
            return {(x and y) if both else (x or y) for x in first for y in second}
        case m.UnaryOp(op="not", operand=operand):
            inner = truth(operand, names)
            return None if inner is None else {not x for x in inner}
        case m.BinaryOp(op="<" | "<=" | ">" | ">=", left=left, right=right):
            a, b = bounds(left, names), bounds(right, names)
            if a is None or b is None:
                return None
            compare = BINARY[cond.op]
            return {bool(compare(x, y)) for x in a for y in b} | ({True, False} if _overlap(a, b) else set())
    return None


def witness(expr: m.Expr, name: str, low: float, high: float, allowed: Interval,
            value: Callable[[float], float]) -> float | None:
    """A value of `name` in low..high whose result (by `value`, the runtime's) is outside
    `allowed`; None when the bounds rule every one out, or none is found within MAX_PIECES."""
    pending = [(low, high)]
    looked = 0
    while pending and looked < MAX_PIECES:
        a, b = pending.pop()
        looked += 1
        found = bounds(expr, {name: (a, b)})
        if found is not None and allowed[0] <= found[0] and found[1] <= allowed[1]:
            continue
        for x in (a, (a + b) / 2, b):
            result = value(x)
            if not allowed[0] <= result <= allowed[1]:
                return x
        if found is None or b - a <= (high - low) * 1e-9:
            continue  # no rule, or as narrow as it is worth: its samples were looked at
        middle = (a + b) / 2
        pending.extend(((middle, b), (a, middle)))
    return None


def _ends(op: Callable[[float], float], a: Interval) -> Interval:
    x, y = op(a[0]), op(a[1])
    return min(x, y), max(x, y)


def _overlap(a: Interval, b: Interval) -> bool:
    return a[0] <= b[1] and b[0] <= a[1]
