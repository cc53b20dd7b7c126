"""Typed expression IR → Python expression source, for the generated driver.

Precedence and parentheses come from the parser's table (rdisc.syntax.precedence),
which orders the operators as Python does. The text computes what the runtime
computes, with the same functions: every driver carries rdisc.engine.operations, and
an operation is written as the call of its function there (`_mul(x, y)`, `_round(x)`),
or as Python's own operator where rdisc.semantics.operators says that computes exactly
the same (`a + b` of two ints, `x * 0.5`, `x % 256`), errors and their messages included.

A `Py` keeps the shape of its text, so a long expression can be laid out over
several lines at its calls and operator chains (`lines`), the way a person would
break it; the generated code always has an expression inside brackets, where a
line break is free.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import NoReturn

from rdisc.semantics import model as m
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.operators import (
    binary_operation,
    call_operation,
    surely_float,
    unchecked,
    unchecked_operand,
)
from rdisc.syntax import precedence as p

INDENT = "    "


@dataclass(frozen=True, slots=True)
class Call:
    head: str  # the function, `(` excluded
    args: tuple[Py, ...]


@dataclass(frozen=True, slots=True)
class Chain:
    """`first sep1 operand1 sep2 operand2 ...`: breaks before each separator."""

    first: Py
    rest: tuple[tuple[str, Py], ...]  # (separator with its trailing space, operand)


@dataclass(frozen=True, slots=True)
class Paren:
    inner: Py


Shape = Call | Chain | Paren | None


@dataclass(frozen=True, slots=True)
class Py:
    """Python expression text, the precedence level of its outermost operator, and its shape."""

    text: str
    level: int
    shape: Shape = None

    def at(self, minimum: int) -> Py:
        """This expression where an operand of level `minimum` is expected: parenthesised if lower."""
        if self.level >= minimum:
            return self
        return Py(f"({self.text})", p.ATOM, Paren(self))


def lines(e: Py, width: int) -> list[str]:
    """`e` over lines no longer than `width` where its shape allows (indentation relative)."""
    if len(e.text) <= width or e.shape is None:
        return [e.text]
    match e.shape:
        case Paren(inner):
            return ["(", *(INDENT + line for line in lines(inner, width - 4)), ")"]
        case Call(head, args):
            together = ", ".join(a.text for a in args)
            if len(head) + 1 <= width and len(together) <= width - 4:  # the arguments on one line of their own
                return [head + "(", INDENT + together, ")"]
            out = [head + "("]
            for arg in args:  # else one argument a line
                sub = lines(arg, width - 5)
                sub[-1] += ","
                out += [INDENT + line for line in sub]
            return [*out, ")"]
        case Chain(first, rest):
            out = lines(first, width)
            for sep, operand in rest:
                sub = lines(operand, width - len(sep))
                out += [sep + sub[0], *sub[1:]]
            return out
    raise AssertionError(f"unknown shape {e.shape!r}")


# ---- building text ----------------------------------------------------------------------------------


def call(head: str, args: list[Py]) -> Py:
    args = [a.at(p.CONDITIONAL) for a in args]
    return Py(f"{head}({', '.join(a.text for a in args)})", p.ATOM, Call(head, tuple(args)))


def binary(op: str, left: Py, right: Py, spelling: str | None = None) -> Py:
    """`left op right` as the precedence table has it (`spelling` replaces the operator's text)."""
    o = p.BINARY[op]
    low, high = o.operands
    if o.level == p.COMPARISON:  # as rdisc.syntax.precedence.binary: readers used to C
        low = high = p.ARITH
    a, b = left.at(low), right.at(high)
    word = spelling if spelling is not None else o.spelling.strip()
    rest: tuple[tuple[str, Py], ...] = ((word + " ", b),)
    # `a + b - c` is one chain (the left operand is not parenthesised, so it has this level).
    if isinstance(a.shape, Chain) and a.level == o.level and a is left:
        first, rest = a.shape.first, a.shape.rest + rest
    else:
        first = a
    return Py(f"{a.text} {word} {b.text}", o.level, Chain(first, rest))


def unary(op: str, operand: Py) -> Py:
    o = p.UNARY_OPERATORS[op]
    inner = operand.at(o.operands[0])
    return Py(o.spelling + inner.text, o.level)


def conditional(then: Py, cond: Py, orelse: Py) -> Py:
    """`then if cond else orelse`, a chain of `else` branches when it is broken."""
    t, c, e = (x.at(level) for x, level in zip((then, cond, orelse), p.CONDITIONAL_OPERANDS))
    head = Py(f"{t.text} if {c.text}", p.CONDITIONAL)
    rest: tuple[tuple[str, Py], ...]
    if isinstance(e.shape, Chain) and e.level == p.CONDITIONAL and e is orelse:
        rest = (("else ", e.shape.first), *e.shape.rest)  # x if a else y if b else z: one chain
    else:
        rest = (("else ", e),)
    return Py(f"{t.text} if {c.text} else {e.text}", p.CONDITIONAL, Chain(head, rest))


def float_literal(value: float) -> Py:
    if math.isnan(value):
        return Py("math.nan", p.ATOM)
    text = "math.inf" if math.isinf(value) else repr(abs(value))
    if math.copysign(1.0, value) < 0:
        return Py("-" + text, p.UNARY)
    return Py(text, p.ATOM)


def literal(value: m.Value, type_: m.AnyType) -> Py:
    """A constant as Python source, spelled by its declared type, through repr."""
    if isinstance(type_, m.Array):
        assert isinstance(value, tuple)
        return tuple_py([literal(v, type_.element) for v in value])
    match type_:
        case Type.BOOL:
            return Py(repr(bool(value)), p.ATOM)
        case Type.INT:
            number = int(value)  # type: ignore[arg-type]
            return Py(repr(number), p.UNARY if number < 0 else p.ATOM)
        case Type.FLOAT:
            return float_literal(float(value))  # type: ignore[arg-type]
        case Type.STRING:
            return Py(quoted(str(value)), p.ATOM)
        case Type.BYTES:
            return Py(quoted(bytes(value)), p.ATOM)  # type: ignore[arg-type]
    _unreachable(type_)


def tuple_py(items: list[Py]) -> Py:
    """A tuple display: `(a, b)`, `(a,)`."""
    if len(items) == 1:
        return Py(f"({items[0].at(p.CONDITIONAL).text},)", p.ATOM)
    return call("", items)


def quoted(value: str | bytes) -> str:
    """repr(value), with double quotes where that needs no other change."""
    text = repr(value)
    prefix = "b" if isinstance(value, bytes) else ""
    body = text[len(prefix) + 1 : -1]
    if text[len(prefix)] == "'" and '"' not in body and "\\'" not in body:
        return f'{prefix}"{body}"'
    return text


# ---- the compiler -----------------------------------------------------------------------------------


def table_name(table: str) -> str:
    """The module constant a driver keeps a lookup table in."""
    return f"_TABLE_{table.upper()}"


class Compiler:
    """Compiles expressions: each operation as the call of its function in rdisc.engine.operations
    (which the driver carries), or as Python's own operator where that computes exactly the same."""

    def expr(self, e: m.Expr, names: Mapping[str, str]) -> Py:
        """`e` as Python. `names`: local names of parameters and fields (state is read from
        the mapping `state`)."""
        match e:
            case m.Const(value=value, type=type_):
                return literal(value, type_)
            case m.Var(name=name, scope=scope):
                if scope is Scope.STATE:
                    return Py(f"state[{quoted(name)}]", p.ATOM)
                return Py(names[name], p.ATOM)
            case m.ReplyValue(index=index):
                return Py(f"reply[{index!r}]", p.ATOM)
            case m.UnaryOp(op=op, operand=operand):
                return unary(op, self.expr(operand, names))
            case m.BinaryOp():
                return self.binary(e, names)
            case m.IfElse(cond=cond, then=then, orelse=orelse):
                return conditional(self.expr(then, names), self.expr(cond, names), self.expr(orelse, names))
            case m.FuncCall(func="clamp", args=(m.Var(scope=scope) as x, low, high)) if (
                    scope is not Scope.STATE and _signed_constant(low) and _signed_constant(high)):
                # `_clamp`'s own test, its value a local name read twice: what it computes, without the
                # call (`not x > high`, which a NaN passes as it does there, rather than what linters offer, min())
                clamped, least, most = self.expr(x, names), self.expr(low, names), self.expr(high, names)
                return conditional(least, binary("<", clamped, least),
                                   conditional(clamped, unary("not", binary(">", clamped, most)), most))
            case m.FuncCall(func="bool", args=(number,)) if number.type in (Type.INT, Type.FLOAT):
                return binary("!=", self.expr(number, names), Py("0", p.ATOM))  # bool() of a number, without the call
            case m.FuncCall(args=args):
                return call(call_operation(e), [self.expr(a, names) for a in args])
            case m.Lookup(table=table, key=key, default=default) if default is not None:
                return Py(f"{table_name(table)}.get({self.expr(key, names).text}, {self.expr(default, names).text})",
                          p.ATOM)
            case m.InTable(table=table, key=key):
                return binary("in", self.expr(key, names), Py(table_name(table), p.ATOM))
            case m.Lookup(table=table, key=key):
                return Py(f"lookup({quoted(table)}, {table_name(table)}, {self.expr(key, names).text})", p.ATOM)
            case m.ArrayValue(items=items, type=type_):
                return tuple_py([self.bound(item, type_.element, names) for item in items])
            case m.Element(array=m.Var(type=m.Array(size=size)) as array, index=m.Const(value=int(at))) if 0 <= at < size:
                return Py(f"{self.expr(array, names).text}[{at}]", p.ATOM)  # its size was checked as it was bound
            case m.Element(array=array, index=index):
                return call("element", [Py(quoted(m.array_name(array)), p.ATOM), self.expr(array, names),
                                        self.expr(index, names)])
            case m.Replaced(array=array, index=index, value=value, type=type_):
                return call("replaced", [Py(quoted(m.array_name(array)), p.ATOM), self.expr(array, names),
                                         self.expr(index, names), self.bound(value, type_.element, names)])
        _unreachable(e)

    def bound(self, e: m.Expr, declared: m.AnyType, names: Mapping[str, str]) -> Py:
        """`e` as the value of a parameter, field or state variable of type `declared`: as the
        contract binds values, an int becomes a float where a float is declared."""
        if isinstance(declared, m.Array):
            py = self.expr(e, names)
            if declared.element is Type.FLOAT and isinstance(e.type, m.Array) and e.type.element is Type.INT:
                return call("tuple", [Py(f"float(v) for v in {py.at(p.CONDITIONAL).text}", p.ATOM)])
            return py
        if declared is Type.FLOAT and isinstance(e, m.Const) and isinstance(e.value, int) and e.type is Type.INT:
            try:
                return literal(float(e.value), Type.FLOAT)  # 0 bound to a float is 0.0, known now
            except OverflowError:
                pass  # too large for a float: refused when it runs, as the runtime refuses it
        py = self.expr(e, names)
        if declared is Type.FLOAT and not surely_float(e):
            return call("float", [py])
        return py

    def packed(self, e: m.Expr, declared: m.AnyType | None, names: Mapping[str, str]) -> Py:
        """`e` as a value a one-step request packs (bound to `declared`, if given), where any error
        sends the call the general way, which says what is wrong: `round(x)` and `int(x)` of float
        arithmetic take Python's own `+`, `-` and `*`. Where the operations would refuse a result
        too large for a float, Python's gives an infinity or a NaN, which every later `+`, `-`
        and `*` keeps, and which round() and int() refuse: an error either way."""
        arg = unchecked_operand(e)  # the rule, `rdisc.semantics.operators`'s: the runtime's too
        if arg is not None and isinstance(e, m.FuncCall):
            return call(e.func, [self.arithmetic(arg, names)])
        return self.expr(e, names) if declared is None else self.bound(e, declared, names)

    def arithmetic(self, e: m.Expr, names: Mapping[str, str]) -> Py:
        """Float `+`, `-`, `*` and negation with Python's operators (see `packed`), the rest as `expr`."""
        if unchecked(e):
            match e:
                case m.BinaryOp(op=op, left=left, right=right):
                    return binary(op, self.arithmetic(left, names), self.arithmetic(right, names))
                case m.UnaryOp(operand=operand):
                    return unary("-", self.arithmetic(operand, names))
        return self.expr(e, names)

    def binary(self, e: m.BinaryOp, names: Mapping[str, str]) -> Py:
        operation = binary_operation(e)
        if operation is None and (e.op in _COMPARISONS or e.type is Type.FLOAT and e.op in _FLOAT_ARITHMETIC):
            twins = _as_float(e.left, e.right), _as_float(e.right, e.left)
            if twins != (None, None):
                return binary(e.op, twins[0] or self.expr(e.left, names), twins[1] or self.expr(e.right, names))
        a, b = self.expr(e.left, names), self.expr(e.right, names)
        if operation is not None:
            return call(operation, [a, b])
        if e.op in ("==", "!=") and (_bool_constant(e.left) or _bool_constant(e.right)):
            # A bool against True or False: `is`, as linters want it (both sides are bools).
            return binary(e.op, a, b, "is" if e.op == "==" else "is not")
        return binary(e.op, a, b)


_COMPARISONS = frozenset({"==", "!=", "<", "<=", ">", ">="})
_FLOAT_ARITHMETIC = frozenset({"+", "-", "*", "/"})


def _as_float(e: m.Expr, other: m.Expr) -> Py | None:
    """An int constant (or a negated one) met by a surely-float `other` in a comparison or in
    float arithmetic of Python's operators, as the float it equals exactly; else None. The result
    is the same (Python compares an int and a float exactly, and turns an int so small into that
    float before arithmetic), but CPython runs float-with-float in its specialised instructions,
    float-with-int in the generic ones: several times slower on every command's path."""
    negated = isinstance(e, m.UnaryOp) and e.op == "-"
    constant = e.operand if isinstance(e, m.UnaryOp) and negated else e
    if not (isinstance(constant, m.Const) and constant.type is Type.INT and type(constant.value) is int
            and surely_float(other)):
        return None
    try:
        twin = float(constant.value)
    except OverflowError:
        return None
    if twin != constant.value:  # (compared exactly) not one float: the int is kept
        return None
    return literal(-twin if negated else twin, Type.FLOAT)


def _signed_constant(e: m.Expr) -> bool:
    """Whether `e` is a constant, or a negated one (`-0.5`)."""
    return isinstance(e, m.Const) or (isinstance(e, m.UnaryOp) and e.op == "-" and isinstance(e.operand, m.Const))


def _bool_constant(e: m.Expr) -> bool:
    return isinstance(e, m.Const) and e.type is Type.BOOL


def _unreachable(node: NoReturn) -> NoReturn:
    raise AssertionError(f"unhandled case {node!r}")
