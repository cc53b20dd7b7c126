"""`prepare` (closures, for the runtime's speed) computes exactly what `evaluate`
(the reference walk of the IR) computes, errors included."""

from __future__ import annotations

import math

from conftest import fuzz_examples
from hypothesis import given, settings
from hypothesis import strategies as st
from runtime_support import CREATE, DATA, KOALA

from rdisc.compile import compile_path
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import EvalError, evaluate, prepare

INT, FLOAT, BOOL = m.Type.INT, m.Type.FLOAT, m.Type.BOOL

STATE = {"a": (INT, 0), "b": (FLOAT, 0.0), "flag": (BOOL, False)}
LOCAL = {"x": INT, "y": FLOAT}


def _leaf(type_: m.Type) -> st.SearchStrategy[m.Expr]:
    consts = {INT: st.integers(-300, 300), FLOAT: st.floats(-1e3, 1e3, allow_nan=False), BOOL: st.booleans()}[type_]
    names = [m.Var(n, m.Scope.STATE, t) for n, (t, _) in STATE.items() if t is type_]
    names += [m.Var(n, m.Scope.PARAM, t) for n, t in LOCAL.items() if t is type_]
    options = [consts.map(lambda v: m.Const(v, type_))]
    if names:
        options.append(st.sampled_from(names))
    if type_ is not BOOL:
        options.append(st.just(m.ReplyValue(0 if type_ is INT else 1, type_)))
    return st.one_of(options)


def _number_type(left: m.Expr, right: m.Expr) -> m.Type:
    return INT if left.type is INT and right.type is INT else FLOAT


def _as(expr: m.Expr, type_: m.Type) -> m.Expr:
    """`expr` made of type `type_` by one more node, if it is not already."""
    if expr.type is type_:
        return expr
    if type_ is BOOL:
        return m.BinaryOp(">", expr, m.Const(0, INT), BOOL)
    if expr.type is BOOL:
        return m.IfElse(expr, m.Const(1, INT), m.Const(0, INT), INT) if type_ is INT else \
            m.IfElse(expr, m.Const(0.5, FLOAT), m.Const(-2.0, FLOAT), FLOAT)
    return m.FuncCall("round", (expr,), INT) if type_ is INT else m.FuncCall("float", (expr,), FLOAT)


def _number(expr: m.Expr) -> m.Expr:
    return _as(expr, INT) if expr.type is BOOL else expr


@st.composite
def _node(draw, children: st.SearchStrategy[m.Expr]) -> m.Expr:
    kind = draw(st.sampled_from(["arith", "bits", "compare", "logic", "unary", "if", "call"]))
    left, right = draw(children), draw(children)
    if kind == "arith":
        left, right = _number(left), _number(right)
        op = draw(st.sampled_from(["+", "-", "*", "/", "//", "%", "**"]))
        return m.BinaryOp(op, left, right, FLOAT if op == "/" else _number_type(left, right))
    if kind == "bits":
        return m.BinaryOp(draw(st.sampled_from(["&", "|", "^", "<<", ">>"])), _as(left, INT), _as(right, INT), INT)
    if kind == "compare":
        return m.BinaryOp(draw(st.sampled_from(["==", "!=", "<", "<=", ">", ">="])), _number(left), _number(right),
                          BOOL)
    if kind == "logic":
        return m.BinaryOp(draw(st.sampled_from(["and", "or"])), left, _as(right, left.type), left.type)
    if kind == "unary":
        if left.type is BOOL:
            return m.UnaryOp("not", left, BOOL)
        return m.UnaryOp(draw(st.sampled_from(["-", "+"] + (["~"] if left.type is INT else []))), left, left.type)
    if kind == "if":
        return m.IfElse(_as(draw(children), BOOL), left, _as(right, left.type), left.type)
    left, right = _number(left), _number(right)
    func = draw(st.sampled_from(["abs", "round", "min", "max", "clamp", "float", "int", "sqrt", "atan2"]))
    if func == "abs":
        return m.FuncCall(func, (left,), left.type)
    if func in ("round", "int"):
        return m.FuncCall(func, (left,), INT)
    if func in ("float", "sqrt"):
        return m.FuncCall(func, (left,), FLOAT)
    if func == "atan2":
        return m.FuncCall(func, (left, right), FLOAT)
    if func == "clamp":
        return m.FuncCall(func, (left, right, draw(_leaf(left.type))), _number_type(left, right))
    return m.FuncCall(func, (left, right), _number_type(left, right))


expressions = st.recursive(st.sampled_from([INT, FLOAT, BOOL]).flatmap(_leaf), _node, max_leaves=12)


def _outcome(f):
    try:
        value = f()
    except (EvalError, ArithmeticError, ValueError, TypeError) as err:
        return ("error", type(err).__name__)
    return ("nan",) if isinstance(value, float) and math.isnan(value) else ("value", value, type(value))


@settings(max_examples=fuzz_examples(150), deadline=None)
@given(expressions, st.integers(-50, 50), st.floats(-100, 100), st.booleans(),
       st.integers(-50, 50), st.floats(-100, 100), st.integers(-9, 9), st.floats(-9, 9))
def test_prepare_agrees_with_evaluate(expr, a, b, flag, x, y, r0, r1) -> None:
    state = {"a": a, "b": b, "flag": flag}
    local = {"x": x, "y": y}
    reply = (r0, r1)
    expected = _outcome(lambda: evaluate(expr, {**state, **local}, reply))
    assert _outcome(lambda: prepare(expr)(state, local, reply)) == expected


def test_constant_folding_keeps_errors_for_run_time() -> None:
    division = m.BinaryOp("/", m.Const(1, INT), m.Const(0, INT), FLOAT)
    f = prepare(m.IfElse(m.Var("flag", m.Scope.STATE, BOOL), division, m.Const(2.0, FLOAT), FLOAT))
    assert f({"flag": False}, {}, ()) == 2.0
    try:
        f({"flag": True}, {}, ())
    except EvalError as err:
        assert "division by zero" in str(err)
    else:
        raise AssertionError("1 / 0 was evaluated")


def _expressions(model: m.Model) -> list[m.Expr]:
    found: list[m.Expr] = []
    for p in model.primitives.values():
        found += list(p.args) + [a.value for a in p.actions]
    for i in model.interfaces.values():
        found += [a for c in i.calls for a in c.args]
    for d in model.inputs.values():
        found += list(d.args)
    for o in model.outputs.values():
        found += [e for _, e in o.fields]
    return found


def test_every_expression_of_the_examples() -> None:
    for path in (CREATE, KOALA, DATA / "fast_create.rdis"):
        model = compile_path(str(path)).model
        assert model is not None
        state = {s.name: s.initial for s in model.states.values()}
        state.update({s.name: s.default for s in model.settings.values()})  # read where state is
        state.update({name: 3 if s.type is INT else 0.5 for name, s in model.states.items()
                      if s.type in (INT, FLOAT) and s.initial == 0})
        state.update({s.name: 3 if s.type is INT else 0.5 for s in model.sensors.values()})  # read where state is
        for expr in _expressions(model):
            local = {"linear": 0.3, "angular": -0.2, "velocity": 0.25, "radius": -1.5, "left": 12, "right": -7}
            reply = ("120", "-40") + ("5",) * 14 if path == KOALA else (3, 7)
            assert _outcome(lambda: prepare(expr)(state, local, reply)) == _outcome(  # noqa: B023
                lambda: evaluate(expr, {**state, **local}, reply))  # noqa: B023
