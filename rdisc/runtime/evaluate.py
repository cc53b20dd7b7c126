"""The expression interpreter: evaluates the checked, typed IR of the Model.

It walks the IR directly (never source text, never Python's eval). Operators and
functions come from rdisc.semantics.operators, the same definitions the checker
folds constants with, so a constant means the same thing at check and at run time.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from rdisc.semantics import model as m
from rdisc.semantics.operators import BINARY, FUNCTIONS, UNARY, EvalError

__all__ = ["EvalError", "coerce", "evaluate"]


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
