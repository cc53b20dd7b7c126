"""The driver writer's shared state and its plan functions: each expression list or condition a `def`."""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from rdisc import lower as lowering
from rdisc.emit.python_expr import Compiler, Py, quoted
from rdisc.emit.python_expr import call as function_call
from rdisc.emit.python_frame import OneStep
from rdisc.emit.python_names import (
    _body_names,
    _constant_name,
    _escape,
    _identifier,
    _params,
    _robot_members,
    class_name,
)
from rdisc.emit.python_text import _emit, _wrapped
from rdisc.emit.writer import Writer
from rdisc.engine import carry
from rdisc.semantics import model as m
from rdisc.semantics.operators import surely_float
from rdisc.source import SourceFile, Span, place
from rdisc.syntax import precedence as p

# The most items a dict display is built from at its full size (CPython's BUILD_CONST_KEY_MAP); a larger
# one grows an item at a time, and a copy of its keys, filled in, costs half as much.
_DISPLAYED = 16


class _DriverBase:
    """What the parts of the driver's writer share: the Model, the names it gave, and plan functions' text."""

    def __init__(self, model: m.Model, source_name: str, sources: Mapping[str, SourceFile]) -> None:
        for names in (model.settings, model.states, model.connections, model.primitives, model.interfaces, model.adapters,
                      model.inputs, model.outputs, model.frames):
            for name in names:
                _identifier(name)  # names enter the text as identifiers: only checked names can
        for params in (*(e.params for e in model.primitives.values()), *(e.params for e in model.interfaces.values()),
                       *(e.params for e in model.frames.values())):
            for param in params:
                _identifier(param.name)
        for adapter in model.adapters.values():
            for field in adapter.fields:
                _identifier(field.name)
        self.model = model
        self.source_name = source_name
        self.sources = sources
        self.main_path = model.robot.span.path if model.robot.span else None
        self.cls = class_name(model.robot.name)
        self.exprs = Compiler()
        taken: set[str] = {"_DEVICE", "_SETTINGS", *carry.names()}  # a plan's constant takes none of these
        self.taken = taken
        self.plan = {
            (kind, name): _constant_name(f"{prefix}_{name}", taken)
            for kind, prefix, names in (("primitive", "P", model.primitives), ("output", "O", model.outputs),
                                        ("interface", "I", model.interfaces), ("input", "IN", model.inputs),
                                        ("connection", "C", model.connections), ("frame", "FRAME", model.frames))
            for name in names
        }
        self.names: dict[object, str] = {}  # each plan and Code written: the name it has in the module
        self.state_order: tuple[str, ...] = ()  # the state variables, in the order of the robot's state
        self.renewing: set[lowering.Code] = set()  # post-actions written to give the whole new state
        self.one_step: dict[tuple[str, str], OneStep] = {}  # ("input" or "primitive", name): its request in one step
        self.slots: dict[tuple[str, str], str] = {}  # ("input" or "primitive", name): the engine's one-step function
        self.input_methods: dict[str, str] = {}
        self.dispatched: dict[str, tuple[str, int]] = {}  # primitive: its typed method making its request, its arity
        for name in model.inputs:
            self.input_methods[name] = _escape(name, _robot_members() | set(self.input_methods.values()))

    # -- helpers ---------------------------------------------------------------------------------

    def where(self, span: Span | None) -> str | None:
        return place(span, self.sources, self.main_path, self.source_name)

    def comment(self, w: Writer, span: Span | None, what: str = "") -> None:
        """`# file:line  what` before a block that came from the description."""
        where = self.where(span)
        if where is not None:
            w.comment(f"{where}" + (f"  {what}" if what else ""))

    def function(self, w: Writer, name: str, signature: str, params: tuple[m.Parameter, ...] | None,
                 values: Iterable[lowering.Item], returns: str, whole: tuple[str, ...] = ()) -> None:
        """`def name(signature) -> returns:` whose body unpacks `args` into the parameters'
        names and returns a list (keys None) or a dict of the expressions' values, each bound
        to its type where one is given. `whole`, a dict's keys: every one in that order, those
        of no item read from `state` (the items computed first, in their order, each its name).
        A dict of more than `_DISPLAYED` keys is a copy of them, filled in (in the items' order)."""
        local = _params([(prm.name, prm.type) for prm in params or ()])
        items = list(values)
        keyed = returns.startswith("dict")
        given_keys = dict.fromkeys(key for key, _, _ in items)
        keys = list(whole or given_keys)
        filled = _constant_name(f"{name.lstrip('_')}_keys", self.taken) if keyed and len(keys) > _DISPLAYED else None
        if filled is not None:
            w.line(f"{filled}: dict[str, Value] = dict.fromkeys((")
            with w.indented():
                w.lines(_wrapped([f"{quoted(key)}," for key in keys], w.width()))
            w.line("), 0)")
            w.line(f'"""The keys of what {name} gives, in order: a copy filled in is made quicker than a display."""')
            w.blank(2)
        with w.block(f"def {name}({signature}) -> {returns}:"):
            used = set().union(*(_names(e) for _, e, _ in items))
            if used & {prm.name for prm in params or ()}:
                targets = [local[prm.name] if prm.name in used else "_" for prm in params or ()]
                w.line(f"({targets[0]},) = args" if len(targets) == 1 else f"{', '.join(targets)} = args")
            opening, closing = ("{", "}") if keyed else ("[", "]")
            rendered = []
            for key, e, type_ in items:
                py = self.exprs.bound(e, type_, local) if type_ is not None else self.exprs.expr(e, local)
                rendered.append((f"{quoted(key)}: " if keyed else key, py))  # key "*": an array given element by element
            if filled is not None:  # the keys' order is the copy's: the values are computed in the items' order
                made = _escape("changes", _body_names() | set(local.values()))
                w.line(f"{made} = {filled}.copy()")
                for (key, _, _), (_, py) in zip(items, rendered):
                    _emit(w, f"{made}[{quoted(key)}] = ", py)
                for key in whole:
                    if key not in given_keys:
                        w.line(f"{made}[{quoted(key)}] = state[{quoted(key)}]")
                w.line(f"return {made}")
                return
            if whole:  # each value computed first, in the items' order (the first to fail fails), unless none can
                given = {key: py for (key, _, _), (_, py) in zip(items, rendered)}
                if not all(_cannot_fail(e, type_) for _, e, type_ in items):
                    named = _params([(key, m.Type.INT) for key in given], _body_names() | frozenset(local.values()))
                    for key, py in given.items():
                        _emit(w, f"{named[key]} = ", py)
                    given = {key: Py(name, p.ATOM) for key, name in named.items()}
                rendered = [(f"{quoted(key)}: ", given.get(key) or Py(f"state[{quoted(key)}]", p.ATOM)) for key in whole]
            flat = "return " + opening + ", ".join(prefix + py.text for prefix, py in rendered) + closing
            if len(flat) <= w.width() and "\n" not in flat:
                w.line(flat)
                return
            w.line(f"return {opening}")
            with w.indented():
                for prefix, py in rendered:
                    _emit(w, prefix, py, ",")
            w.line(closing)

    def predicate(self, w: Writer, name: str, signature: str, params: tuple[m.Parameter, ...], e: m.Expr) -> None:
        """`def name(signature) -> bool:` whose body unpacks `args` and returns the condition, as a
        bool (a reply's or an argument's value is `Any` to mypy, and so would the comparison be)."""
        local = _params([(prm.name, prm.type) for prm in params])
        with w.block(f"def {name}({signature}) -> bool:"):
            used = _names(e)
            if used & {prm.name for prm in params}:
                targets = [local[prm.name] if prm.name in used else "_" for prm in params]
                w.line(f"({targets[0]},) = args" if len(targets) == 1 else f"{', '.join(targets)} = args")
            _emit(w, "return ", function_call("bool", [self.exprs.expr(e, local)]))  # broken inside its own `(`


def _cannot_fail(e: m.Expr, declared: m.AnyType | None = None) -> bool:
    """Whether computing `e` (bound to `declared`) raises nothing, whatever the values: a constant,
    a variable, a reply's value, `&`, `|`, `^`, `==` and `!=` of those that are ints or bools, and
    `bool` of a number (what post-actions that only take a reply's values apart are made of)."""
    if declared is m.Type.FLOAT and not surely_float(e):
        return False  # made a float: a huge int cannot be
    match e:
        case m.Const() | m.Var() | m.ReplyValue():
            return True
        case m.BinaryOp(op="&" | "|" | "^" | "==" | "!=", left=left, right=right):
            return (left.type in (m.Type.INT, m.Type.BOOL) and right.type in (m.Type.INT, m.Type.BOOL)
                    and _cannot_fail(left) and _cannot_fail(right))
        case m.FuncCall(func="bool", args=(number,)):
            return number.type in (m.Type.INT, m.Type.BOOL) and _cannot_fail(number)
    return False


def _names(e: m.Expr) -> set[str]:
    """The parameters and fields an expression reads."""
    return {v.name for v in m.variables(e) if v.scope is not m.Scope.STATE}
