"""Which operation computes a node of a typed expression, decided once for the runtime and the emitter.

The operations themselves are rdisc.engine.operations. Both the runtime's interpreter
(rdisc.semantics.evaluate) and the expression compiler (rdisc.emit.python_expr) ask here which
of its functions a node needs, or whether Python's own operator or builtin computes exactly
the same (results and errors alike), which is then the faster thing to use: the sum of two
ints (bounded where it is kept, not here), `x * 0.5` (which cannot overflow), `x % 256`
(whose divisor is not zero). They also share here the one rule of when an expression is
surely a float, and the checker how its messages show a value.
"""

from __future__ import annotations

import math

from rdisc.engine import operations
from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.syntax.precedence import quote_bytes

_ARITHMETIC = {"+": "_add", "-": "_sub", "*": "_mul", "/": "_div"}
_DIVIDING = {"//": "_floordiv", "%": "_mod"}
_PYTHON_FUNCTIONS = frozenset({"abs", "min", "max", "bool", "str", "len"})  # their builtins are the operation
FLOAT_BYTES = ("f32le", "f32be", "f64le", "f64be")
"""The functions from a number to the bytes of an IEEE 754 float; `from_` and the name is the way back."""
FLOAT_FUNCTIONS = frozenset({"float", "sqrt", "sin", "cos", "atan2", "hypot", *("from_" + name for name in FLOAT_BYTES)})
"""The functions whose value is always a float."""


def shown(value: object) -> str:
    """A value as the checker's messages show it: bytes as the language writes them, `b"\\x01"`."""
    return operations.shown(value, quote_bytes(value) if isinstance(value, bytes) else None)


def binary_operation(e: m.BinaryOp) -> str | None:
    """The name of the function of rdisc.engine.operations that computes `e`, or None where
    Python's operator computes exactly the same (`and` and `or` are never functions)."""
    op, left, right = e.op, e.left, e.right
    if op == "+" and e.type in (Type.STRING, Type.BYTES):
        return "_concat"
    if op in _ARITHMETIC:
        if op in ("+", "-") and e.type is Type.INT:
            return None  # bounded where it is kept
        if e.type is Type.FLOAT and _cannot_overflow(op, left, right):
            return None
        return _ARITHMETIC[op]
    if op in _DIVIDING:
        divisor = _number(right)
        return None if divisor is not None and divisor != 0 else _DIVIDING[op]
    if op == "**":
        return "_pow"
    if op == "<<":
        return "_lshift"
    if op == ">>":
        count = _number(right)
        return None if count is not None and 0 <= count <= operations.MAX_RESULT_BITS + 1 else "_rshift"
    return None


def call_operation(e: m.FuncCall) -> str:
    """The name of what computes the call `e`: a function of rdisc.engine.operations (`_round`),
    or Python's builtin of the function's name where that computes exactly the same (`abs`)."""
    func = e.func
    if func in _PYTHON_FUNCTIONS:
        return func
    if func == "int" and e.args[0].type in (Type.INT, Type.BOOL):
        return "int"  # no int or bool fails to convert
    if func == "float" and e.args[0].type in (Type.FLOAT, Type.BOOL):
        return "float"
    return "_" + func


def _number(e: m.Expr) -> int | float | None:
    """The value of a constant int, or of a finite constant float."""
    if not isinstance(e, m.Const) or e.type not in (Type.INT, Type.FLOAT) or not isinstance(e.value, (int, float)):
        return None
    return e.value if e.type is Type.INT or math.isfinite(e.value) else None


def _cannot_overflow(op: str, left: m.Expr, right: m.Expr) -> bool:
    """Whether a finite float result is certain from finite operands (`x * 0.5`, `x / 2`, with
    no division by zero, `x + 0`); an infinite operand gives an infinite result, which passes."""
    constants = [abs(n) if n is not None else None for n in (_number(left), _number(right))]
    match op:
        case "*":
            return any(c is not None and c <= 1.0 for c in constants)
        case "/":
            return constants[1] is not None and constants[1] >= 1.0
        case "+" | "-":
            return 0 in constants
    return False


def surely_float(e: m.Expr) -> bool:
    """Whether `e` is a float whenever it has a value, its names being of their declared types.
    A float-typed expression may be an int when it runs (`min(1, 2.0)` is 1); binding makes it a float."""
    match e:
        case m.Const(type=type_) | m.Var(type=type_) | m.ReplyValue(type=type_):
            return type_ is Type.FLOAT
        case m.UnaryOp(op="-" | "+", operand=operand):
            return surely_float(operand)
        case m.BinaryOp(op="/"):
            return True
        case m.BinaryOp(op="+" | "-" | "*" | "%" | "//" | "**", left=left, right=right, type=Type.FLOAT):
            return surely_float(left) or surely_float(right)
        case m.IfElse(then=then, orelse=orelse):
            return surely_float(then) and surely_float(orelse)
        case m.FuncCall(func="abs" | "min" | "max" | "clamp", args=args):
            return all(surely_float(a) for a in args)
        case m.FuncCall(func="round", args=args):
            return len(args) == 2
        case m.FuncCall(func=func):
            return func in FLOAT_FUNCTIONS
    return False


def unchecked_operand(e: m.Expr) -> m.Expr | None:
    """The float argument of `round(x)` or `int(x)`, which a one-step request (one that sends the
    call the general way on any error, which then says what is wrong) may compute with Python's own
    `+`, `-`, `*` and negation (`unchecked`). Where the operations would refuse a result too large
    for a float, Python's gives an infinity or a NaN, which every later `+`, `-` and `*` keeps, and
    which round() and int() refuse: an error either way. None for any other expression."""
    match e:
        case m.FuncCall(func="round" | "int", args=(arg,)) if arg.type is Type.FLOAT:
            return arg
    return None


def unchecked(e: m.Expr) -> bool:
    """Whether `e`, within an `unchecked_operand`, is float arithmetic Python's own operator computes."""
    match e:
        case m.BinaryOp(op="+" | "-" | "*", left=left, right=right, type=Type.FLOAT):
            return left.type in _NUMBERS and right.type in _NUMBERS
        case m.UnaryOp(op="-", type=Type.FLOAT):
            return True
    return False


_NUMBERS = (Type.INT, Type.FLOAT)
