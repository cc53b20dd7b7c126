"""A range bound that depends on earlier parameters (`channel: int in 0..count - 1`): a sum of
constants and earlier int parameters, each added or taken away. So a bound is a constant and
some terms, data the engine checks at each call without running an expression, and the widest
range it can give follows from the earlier parameters' own ranges.
"""

from __future__ import annotations

from rdisc.semantics import model as m

Terms = tuple[tuple[int, int], ...]
"""(index of an earlier parameter, +1 or -1): each added to the bound's constant."""


def linear(expr: m.Expr, params: tuple[m.Parameter, ...]) -> tuple[int, Terms] | None:
    """The bound as its constant and its terms over `params` (the earlier parameters), or None
    when it reads anything else or uses another operator."""
    match expr:
        case m.Const(value) if type(value) is int:
            return value, ()
        case m.Var(name, m.Scope.PARAM):
            index = next((i for i, p in enumerate(params) if p.name == name), None)
            return None if index is None else (0, ((index, 1),))
        case m.UnaryOp("-" | "+" as op, operand):
            inner = linear(operand, params)
            if inner is None or op == "+":
                return inner
            return -inner[0], tuple((i, -sign) for i, sign in inner[1])
        case m.BinaryOp("+" | "-" as op, left, right):
            first, second = linear(left, params), linear(right, params)
            if first is None or second is None:
                return None
            sign = 1 if op == "+" else -1
            return first[0] + sign * second[0], first[1] + tuple((i, sign * s) for i, s in second[1])
    return None


def widest(constant: int, terms: Terms, params: tuple[m.Parameter, ...], high: bool) -> int | None:
    """The lowest (or highest) value the bound takes over the earlier parameters' ranges; None
    when a term's parameter has no range."""
    total = constant
    for i, sign in terms:
        low, top = params[i].low, params[i].high
        if low is None or top is None:
            return None
        total += int(top if (sign > 0) == high else low) * sign
    return total
