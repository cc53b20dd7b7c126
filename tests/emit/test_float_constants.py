"""An int constant beside a surely-float value is written as the float it equals exactly
(`linear == 0.0`, `x / 2.0`): the same results, which CPython computes in its
specialised float instructions instead of the generic ones (set_velocity's arithmetic took a
third of its time in them). An int that no float equals, and one beside an int, stay as written."""

from __future__ import annotations

import math

import pytest

from rdisc.emit.python_expr import Compiler
from rdisc.semantics import model as m
from rdisc.semantics.model import Scope, Type

X = m.Var("x", Scope.PARAM, Type.FLOAT)
N = m.Var("n", Scope.PARAM, Type.INT)
NAMES = {"x": "x", "n": "n"}
NOT_A_FLOAT = 2**53 + 1  # no float equals it


def _int(value: int) -> m.Expr:
    return m.UnaryOp("-", m.Const(-value, Type.INT), Type.INT) if value < 0 else m.Const(value, Type.INT)


@pytest.mark.parametrize(("e", "text"), [
    (m.BinaryOp("==", X, _int(0), Type.BOOL), "x == 0.0"),
    (m.BinaryOp(">", _int(0), X, Type.BOOL), "0.0 > x"),
    (m.BinaryOp("<", X, _int(-2), Type.BOOL), "x < -2.0"),
    (m.BinaryOp("==", N, _int(0), Type.BOOL), "n == 0"),
    (m.BinaryOp("==", X, _int(NOT_A_FLOAT), Type.BOOL), f"x == {NOT_A_FLOAT}"),
    (m.BinaryOp("==", X, m.Const(True, Type.BOOL), Type.BOOL), "x is True"),
])
def test_an_int_constant_beside_a_float_is_that_float(e: m.Expr, text: str) -> None:
    assert Compiler().expr(e, NAMES).text == text


def _outcome(text: str, x: float) -> object:
    """What `text` gives for `x`: its value, or the type of its error."""
    try:
        value = eval(text, {"x": x})  # the compiler's own text
    except Exception as err:  # noqa: BLE001 - the outcome compared
        return type(err)
    return ("nan", type(value)) if isinstance(value, float) and math.isnan(value) else (value, type(value))


VALUES = (0.0, -0.0, 2.5, -7.0, 1e300, -1e-300, float(2**52 + 1), math.inf, -math.inf, math.nan)


@pytest.mark.parametrize("op", ["==", "!=", "<", "<=", ">", ">="])
@pytest.mark.parametrize("constant", [0, 3, -7, 1000, 2**52 + 1])
def test_a_float_comparison_is_the_int_comparison(op: str, constant: int) -> None:
    folded = Compiler().expr(m.BinaryOp(op, X, _int(constant), Type.BOOL), NAMES).text
    assert folded == f"x {op} {float(constant)!r}"
    assert [_outcome(folded, x) for x in VALUES] == [_outcome(f"x {op} {constant}", x) for x in VALUES]


@pytest.mark.parametrize("constant", [3, 1000, 2**52 + 1])
def test_a_float_quotient_is_the_int_quotient(constant: int) -> None:
    """`x / 2` is Python's own `/` (its divisor a constant other than 0): `x / 2.0`."""
    folded = Compiler().expr(m.BinaryOp("/", X, _int(constant), Type.FLOAT), NAMES).text
    assert folded == f"x / {float(constant)!r}"
    assert [_outcome(folded, x) for x in VALUES] == [_outcome(f"x / {constant}", x) for x in VALUES]
