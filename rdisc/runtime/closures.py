"""The plans' Codes (`rdisc.lower.Code`) as closures over the expressions prepared by
`rdisc.semantics.evaluate.prepare`: what the runtime hands the engine where a driver
writes a function.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from types import MappingProxyType
from typing import Any

from rdisc import lower as plans
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import Prepared, coerce, prepare
from rdisc.semantics.operators import surely_float

__all__ = ["bound", "closure", "listed", "slots"]

_EMPTY: Mapping[str, m.Value] = MappingProxyType({})


def closure(code: plans.Code) -> Any:
    """The function a Code says."""
    made = {plans.Gives.LIST: _list, plans.Gives.DICT: _dict, plans.Gives.BOOL: _predicate}[code.gives]
    return made(code)


def slots(code: plans.Code) -> dict[str, int]:
    return {p.name: i for i, p in enumerate(code.params)}


def _list(code: plans.Code) -> Any:
    """A LIST code as a closure taking what it takes: its items' values, bound to their
    types, arrays marked "*" given element by element."""
    where = slots(code)
    values = listed([bound(e, type_, where) for _, e, type_ in code.items])
    values = _spread(values, tuple(i for i, (key, _, _) in enumerate(code.items) if key == "*"))
    match code.takes:
        case ("state", "args"):
            return values
        case ("args",):
            return lambda args: values(_EMPTY, args)
        case ("state",):
            return lambda state: values(state, _EMPTY)
    raise AssertionError(code.takes)


def _dict(code: plans.Code) -> Any:
    """A DICT code as a closure: its items' values by key, each bound to its type if it has one
    (as `bound` binds a list's: made a float only where it may be an int when it runs)."""
    where = slots(code)
    items = [(key, _prepared(bound(e, type_, where))) for key, e, type_ in code.items]
    match code.takes:
        case ("state", "args", "reply"):
            return lambda s, loc, r: {key: f(s, loc, r) for key, f in items}
        case ("state", "args"):
            return lambda s, loc: {key: f(s, loc, ()) for key, f in items}
        case ("state",):
            return lambda s: {key: f(s, _EMPTY, ()) for key, f in items}
    raise AssertionError(code.takes)


def _predicate(code: plans.Code) -> Any:
    """A BOOL code as a closure: its one item's value (the engine tests its truth)."""
    ((_, e, _),) = code.items
    holds = prepare(e, slots(code))
    match code.takes:
        case ("state", "args", "reply"):
            return holds
        case ("state", "args"):
            return lambda state, local: holds(state, local, ())
    raise AssertionError(code.takes)


def bound(e: m.Expr, type_: m.AnyType | None, slots: dict[str, int]) -> Prepared | m.Const:
    """`e` prepared, bound to `type_` as the contract binds values (an int made a float where a
    float is declared); a constant given as it is, which `listed` puts in as it is."""
    if type_ is None and isinstance(e, m.Const):
        return e
    if type_ is m.Type.FLOAT and isinstance(e, m.Const) and type(e.value) is int:
        try:
            return m.Const(float(e.value), m.Type.FLOAT)  # 0 bound to a float is 0.0, known now
        except OverflowError:
            pass  # too large for a float: refused when it runs
    f = prepare(e, slots)
    if type_ is m.Type.FLOAT and not surely_float(e):  # the emitter's rule (`bound`): a float-typed
        return _widened(f)  # expression may be an int when it runs (`x if c else 0`)
    if isinstance(type_, m.Array) and type_.element is m.Type.FLOAT and isinstance(e.type, m.Array) \
            and e.type.element is m.Type.INT:
        return lambda s, loc, r: coerce(f(s, loc, r), type_)
    return f


def _prepared(f: Prepared | m.Const) -> Prepared:
    """What `bound` gives, as a closure: a constant's too."""
    return prepare(f) if isinstance(f, m.Const) else f


def _widened(f: Prepared) -> Prepared:
    def widened(s: Mapping[str, m.Value], loc: Any, r: Any) -> m.Value:
        value = f(s, loc, r)
        return float(value) if type(value) is int else value

    return widened


def _spread(values: Callable[[Mapping[str, m.Value], Any], list[m.Value]],
            arrays: tuple[int, ...]) -> Callable[[Mapping[str, m.Value], Any], list[m.Value]]:
    """Format values with the arrays among them (at `arrays`) given element by element."""
    if not arrays:
        return values

    def spread(s: Mapping[str, m.Value], loc: Any) -> list[m.Value]:
        flat: list[m.Value] = []
        for i, v in enumerate(values(s, loc)):
            flat.extend(v) if i in arrays else flat.append(v)  # type: ignore[arg-type]
        return flat

    return spread


def listed(fs: Sequence[Prepared | m.Const]) -> Callable[[Mapping[str, m.Value], Any], list[m.Value]]:
    """The prepared expressions (or constants) `fs` evaluated in turn, as a list.

    For speed, up to three are unrolled (a list comprehension costs more than
    the calls themselves), and a leading constant (an opcode) is put in as it is.
    """
    prepared = [_prepared(f) for f in fs]
    if fs and isinstance(fs[0], m.Const):
        c = fs[0].value
        match prepared:
            case [_, f]:
                return lambda s, loc: [c, f(s, loc, ())]
            case [_, f, g]:
                return lambda s, loc: [c, f(s, loc, ()), g(s, loc, ())]
    match prepared:
        case []:
            return lambda s, loc: []
        case [f]:
            return lambda s, loc: [f(s, loc, ())]
        case [f, g]:
            return lambda s, loc: [f(s, loc, ()), g(s, loc, ())]
        case [f, g, h]:
            return lambda s, loc: [f(s, loc, ()), g(s, loc, ()), h(s, loc, ())]
    return lambda s, loc: [f(s, loc, ()) for f in prepared]
