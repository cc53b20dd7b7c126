"""What every declaration's rules use: the checker's state, types by name, parameters
(ranges, defaults, units), a value flowing into a slot, constant settings and durations, a
call's arguments, and the constant values a loop or a repeated reply runs over."""

from __future__ import annotations

import math
from collections.abc import Sequence

from rdisc import TYPE_CHECKING
from rdisc.diagnostics import Diagnostics, Label
from rdisc.limits import MAX_ARRAY, MAX_INT
from rdisc.semantics import model as m
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.operators import shown
from rdisc.semantics.resolve import Symbols, Unit, check_name, suggest
from rdisc.semantics.types import Env, Layered, Names, Typer, describe, unify
from rdisc.source import Span
from rdisc.syntax import ast

MAX_DURATION_MS = 3_600_000  # a delay, a timeout or a keepalive interval: an hour
MAX_TERMINATOR = 8
_TYPES = {t.value: t for t in Type}
_NOTHING = Env({}, "where a constant is needed", "")


if TYPE_CHECKING:
    from typing import Protocol, TypeVar

    class _Spanned(Protocol):
        @property
        def span(self) -> Span: ...

    _Clause = TypeVar("_Clause", bound=_Spanned)


class Pieces:
    """The checker's state, and the pieces each kind of declaration is checked with."""

    def __init__(self, units: list[Unit], symbols: Symbols, diagnostics: Diagnostics) -> None:
        self.units = units
        self.s = symbols
        self.d = diagnostics
        self.typer = Typer(diagnostics)
        self.main_decls = {id(decl) for unit in units if unit.main for decl in unit.module.decls}
        self.state_env: dict[str, tuple[Scope, m.AnyType]] = {}
        self.frames: dict[str, m.Frame] = {}
        self.primitives: dict[str, m.Primitive] = {}
        self.written = 0  # calls in the interfaces' bodies, loops written out
        self.settings: dict[str, m.Setting] = {}
        self.given: dict[str, m.Value] = {}  # settings' values given when connecting, for their defaults

    def type_name(self, ref: ast.TypeRef, what: str = "", open_size: bool = False) -> m.AnyType | None:
        """A type by name; `what` names a place that crosses to a framework (an adapter's
        field), where bytes cannot go. An array's size is a constant; an adapter's field, a
        state variable and a parameter (`open_size`) may leave it out: an array of any size,
        such as a reply's group repeated as the message says."""
        if isinstance(ref, ast.ArrayOf):
            return self.array_type(ref, what, open_size)
        return self.scalar_type(ref, what)

    def scalar_type(self, ref: ast.Ident, what: str) -> Type | None:
        """A type named by a word (`int`), as `type_name` says."""
        found = _TYPES.get(ref.text)
        if found is None:
            self.d.report(
                "E105", ref.span, f"unknown type `{ref.text}`", help=suggest(ref.text, _TYPES) or
                "types are int, float, bool, string and bytes, and arrays of the first four: `int[6]`"
            )
        elif found is Type.BYTES and what:
            self.d.report("E105", ref.span, f"{what} cannot be bytes",
                          help="give the framework text or numbers: `hex(firmware)`, `len(firmware)`")
            return None
        return found

    def array_type(self, ref: ast.ArrayOf, what: str, open_size: bool) -> m.Array | None:
        element = self.scalar_type(ref.element, what)
        if element is None:
            return None
        if element is Type.BYTES:
            self.d.report("E105", ref.element.span, "an array holds ints, floats, bools or strings, not `bytes`")
            return None
        if ref.size is None:
            if not open_size:
                self.d.report("E105", ref.span, "an array's size is given: `int[6]`",
                              help="only an adapter's field, a state variable and a parameter leave it out")
                return None
            return m.Array(element, 0)
        size = self.setting(ref.size, "an array's size", MAX_ARRAY)
        if size is None:
            return None
        if size != int(size) or size < 1:
            self.d.report("E204", ref.size.span, f"an array's size is a whole number, 1 or more, not {size:g}")
            return None
        return m.Array(element, int(size))

    def params(self, params: tuple[ast.Param, ...], owner: str) -> tuple[m.Parameter, ...]:
        seen: dict[str, ast.Param] = {}
        out: list[m.Parameter] = []
        for p in params:
            check_name(p.name, "parameter", self.d)
            if p.name.text in seen:
                self.d.report(
                    "E101", p.name.span, f"parameter `{p.name.text}` is declared twice",
                    labels=(Label(seen[p.name.text].name.span, "first declared here"),),
                )
            seen[p.name.text] = p
            type_ = self.type_name(p.type, open_size=owner in ("primitive", "interface"))
            element = type_.element if isinstance(type_, m.Array) else type_
            dependent = self.dependent_range(p, element, tuple(out))
            low, high = self.param_range(p, element) if dependent is None else dependent[:2]
            limits = None if dependent is None else dependent[2]
            default = self.param_default(p, type_, low, high)
            if default is None and p.default is None and any(q.default is not None for q in params[: len(out)]):
                self.d.report("E204", p.name.span, f"parameter `{p.name.text}` needs a default: it follows one "
                              "that has one", help="put the parameters with defaults last")
            out.append(m.Parameter(p.name.text, type_, low, high, default,  # type: ignore[arg-type]
                                   self.param_unit(p, type_), limits))
        return tuple(out)

    def param_unit(self, p: ast.Param, type_: m.AnyType | None) -> str | None:
        """`unit "mm/s"`: one of the table's units, on a number (or an array of numbers)."""
        if p.unit is None:
            return None
        # Imported here: most descriptions give no unit, and a check starts cold.
        from rdisc.semantics.units import UNITS

        if p.unit.value not in UNITS:
            self.d.report("E109", p.unit.span, f"unknown unit `{p.unit.value}`",
                          help=suggest(p.unit.value, UNITS) or f"the units are {', '.join(UNITS)}")
            return None
        element = type_.element if isinstance(type_, m.Array) else type_
        if element not in (Type.INT, Type.FLOAT):
            if type_ is not None:
                self.d.report("E109", p.unit.span, f"parameter `{p.name.text}` is {describe(type_)}: only a "
                              "number has a unit")
            return None
        return p.unit.value

    def param_default(self, p: ast.Param, type_: m.AnyType | None, low: float | None,
                      high: float | None, what: str = "parameter") -> m.Value | None:
        """`= value`: a constant of the parameter's (or setting's) type (an int made a float for
        a float parameter), within its range."""
        if p.default is None:
            return None
        value = self.typer.expr(p.default, _NOTHING)
        self.flow(value, type_, p.default.span, f"the default of {what} `{p.name.text}`")
        constant = self.typer.constant(value)
        if constant is None:
            if value.type is not None:
                self.d.report("E204", p.default.span, "a default is a constant")
            return None
        if not self.typer.kept(constant, p.default.span):  # 64 bits and a sign, as a float can hold
            return None
        if type_ is not None:
            constant = m.coerce(constant, type_)
        for item in constant if isinstance(constant, tuple) else (constant,):
            if low is not None and high is not None and not in_range(item, low, high):
                self.d.report("E403", p.default.span, f"{ranged(item)} is outside the range of {what} "
                              f"`{p.name.text}`", label=f"in {low!r}..{high!r}")
                return None
        return constant

    def dependent_range(self, p: ast.Param, type_: Type | None, earlier: tuple[m.Parameter, ...]
                        ) -> tuple[int | None, int | None, tuple[m.Expr, m.Expr] | None] | None:
        """`in 0..count - 1`: bounds that read earlier parameters, each a sum of constants and
        earlier int parameters with ranges (`rdisc.semantics.bounds`), checked at each call; the
        range is then the widest they give. None when both bounds are constants (`param_range`)."""
        if p.low is None or p.high is None or type_ is None or not earlier:
            return None
        names = {q.name: (Scope.PARAM, q.type) for q in earlier if q.type is not None}
        env = Env(names, "in a range", "constants and the parameters before it")
        errors = self.d.error_count
        nodes = self.typer.expr(p.low, env), self.typer.expr(p.high, env)
        if self.d.error_count > errors:
            return None, None, None
        if all(self.typer.constant(node) is not None for node in nodes):
            return None
        span = p.low.span.to(p.high.span)
        if type_ is not Type.INT:
            self.d.report("E214", span, f"only an int parameter has a range that reads another parameter, "
                          f"not {describe(type_)}", help="give it constant bounds")
            return None, None, None
        # Imported here: most descriptions have no such range, and a check starts cold.
        from rdisc.semantics import bounds

        widest: list[int] = []
        for node, bound, high in ((nodes[0], p.low, False), (nodes[1], p.high, True)):
            form = bounds.linear(node, earlier)
            if form is None:
                self.d.report("E214", bound.span, "a range's bound is a sum of constants and the int parameters "
                              "before it, each added or taken away",
                              help="write it as `count - 1` or `MAX - offset`")
                return None, None, None
            for i, _ in form[1]:
                read = earlier[i]
                if read.type is not Type.INT or read.low is None:
                    why = f"is {describe(read.type)}" if read.type is not Type.INT else "has no range"
                    self.d.report("E214", bound.span, f"parameter `{read.name}` {why}, so the range of "
                                  f"`{p.name.text}` cannot be bounded by it",
                                  help=f"a range reads int parameters with ranges: `{read.name}: int in 0..255`")
                    return None, None, None
            found = bounds.widest(*form, earlier, high)
            assert found is not None  # each term's parameter has a range
            widest.append(found)
        if widest[0] > widest[1]:
            self.d.report("E204", span, f"the range {widest[0]}..{widest[1]} is empty for every value of the "
                          "parameters it reads")
            return None, None, None
        return widest[0], widest[1], nodes

    def param_range(self, p: ast.Param, type_: Type | None,
                    what: str = "parameter") -> tuple[float | None, float | None]:
        """`in low..high`: constant numbers of the parameter's type, low <= high; for bytes, the
        number of bytes."""
        if p.low is None or p.high is None or type_ is None:  # None: its type is in error, reported
            return None, None
        if type_ not in (Type.INT, Type.FLOAT, Type.BYTES):
            self.d.report("E204", p.low.span.to(p.high.span), "only a number (or bytes, by length) has a range, "
                          f"not {describe(type_)}")
            return None, None
        low, high = self.setting(p.low, "a range's bound"), self.setting(p.high, "a range's bound")
        if low is None or high is None:
            return None, None
        if type_ is Type.INT and (low != int(low) or high != int(high)):
            self.d.report("E204", p.low.span.to(p.high.span), f"an int {what}'s range has int bounds")
            return None, None
        if type_ is Type.INT and not (-MAX_INT <= low and high <= MAX_INT):  # `0..1e308` is an int, not a 64-bit one
            self.d.report("E204", p.low.span.to(p.high.span), f"an int {what}'s range has bounds of 64 bits and a sign")
            return None, None
        if type_ is Type.BYTES and (low != int(low) or high != int(high) or low < 0):
            self.d.report("E204", p.low.span.to(p.high.span), "a length's range has int bounds, 0 or more")
            return None, None
        if low > high:
            self.d.report("E204", p.low.span.to(p.high.span), f"the range {shown(low)}..{shown(high)} is empty")
            return None, None
        return (int(low), int(high)) if type_ is not Type.FLOAT else (float(low), float(high))

    def env_with(self, extra: Names, where: str, sees: str, reply: tuple[m.AnyType, ...] | None = None,
                 reply_note: str | None = None, reply_known: bool = True) -> Env:
        """`extra` over the state variables, a layered view: a copy of them each would cost time in
        proportion to their number, so a check time in proportion to its square."""
        return Env(Layered(extra, self.state_env), where, sees, reply, reply_note, reply_known)

    def flow(self, value: m.Expr, target: m.AnyType | None, span: Span, into: str) -> None:
        """A value of value.type goes into something of type `target` (int widens to float)."""
        source = value.type
        if source is None or target is None or source == target or (source, target) == (Type.INT, Type.FLOAT):
            return
        if isinstance(source, m.Array) and isinstance(target, m.Array) and 0 in (source.size, target.size) \
                and unify(source.element, target.element) == target.element:
            return  # an adapter's open array: its size is checked when it runs
        if isinstance(source, m.Array) or isinstance(target, m.Array):
            self.d.report("E401", span, f"{into} takes {describe(target)}, but this is {describe(source)}",
                          help=_array_help(source, target))
            return
        if (source, target) == (Type.FLOAT, Type.INT):
            self.d.report(
                "E402", span, f"{into} takes an int, but this is a float",
                label="a float", help="convert it: `round(...)` to the nearest integer, `int(...)` towards zero",
            )
        else:
            self.d.report("E401", span, f"{into} takes {describe(target)}, but this is {describe(source)}")

    def setting(self, expr: ast.Expr, what: str, most: float | None = None, unit: str = "",
                scale: float = 1) -> float | None:
        """A numeric setting (baud, Hz, ms, priority): a constant expression, times `scale`, at
        most `most` (every wait and rate is bounded: a huge one would hang or overflow later)."""
        errors = self.d.error_count
        node = self.typer.expr(expr, _NOTHING)
        value = self.typer.constant(node)
        if node.type is None or self.d.error_count > errors:
            return None
        if node.type not in (Type.INT, Type.FLOAT) or not isinstance(value, (int, float)):
            self.d.report("E204", expr.span, f"{what} must be a constant number")
            return None
        if isinstance(value, float) and not math.isfinite(value):  # float("inf") folds to one
            self.d.report("E204", expr.span, f"{what} must be a finite number, not {value!r}")
            return None
        if most is not None and not abs(value) * scale <= most:
            self.d.report("E204", expr.span, f"{what} must be at most {most:g}{unit}")
            return None
        return value * scale

    def once(self, items: Sequence[_Clause], what: str, where: ast.Ident) -> _Clause | None:
        """The single clause of a kind; a repeat is reported at the repeat."""
        for extra in items[1:]:
            self.d.report(
                "E203", extra.span, f"{what} is given twice in `{where.text}`",
                labels=(Label(items[0].span, "first given here"),),
            )
        return items[0] if items else None

    def call(self, call: ast.Call, params: tuple[m.Parameter, ...] | None, env: Env, kind: str,
             target: ast.Ident | None = None) -> tuple[m.Expr, ...]:
        """Arguments of a call of a declared element, typed and checked against its parameters."""
        args = tuple(self.typer.expr(a, env) for a in call.args)
        if params is None:
            return args
        name = call.target.text
        required = next((i for i, p in enumerate(params) if p.default is not None), len(params))
        if not required <= len(args) <= len(params):
            labels = (Label(target.span, f"{kind} `{name}` declared here"),) if target else ()
            takes = counted(len(params), "argument") if required == len(params) else \
                f"{required} to {len(params)} arguments"
            self.d.report("E201", call.span, f"{kind} `{name}` takes {takes}, but {len(args)} given", labels=labels)
            return args
        args += tuple(self.typer.const(p.default, p.type, call.span) for p in params[len(args):])  # type: ignore[arg-type]
        for arg, expr, param in zip(args, call.args, params):
            self.flow(arg, param.type, expr.span, f"parameter `{param.name}` of {kind} `{name}`")
            value = self.typer.constant(arg)
            if param.low is not None and param.high is not None and value is not None \
                    and not in_range(value, param.low, param.high):
                self.d.report("E403", expr.span, f"{ranged(value)} is outside the range of parameter "
                              f"`{param.name}` of {kind} `{name}`", label=f"in {param.range_text()}")
        return args

    def duration(self, d: ast.Duration, what: str) -> float | None:
        """A duration in ms: at most an hour (a longer one could only hang)."""
        return self.setting(d.value, what, MAX_DURATION_MS, " ms", 1000 if d.unit == "s" else 1)

    def value_of(self, expr: m.Expr) -> m.Expr:
        """A constant expression as its value; any other as it is."""
        value = self.typer.constant(expr)
        if value is None or expr.type is None:  # not constant (a constant's value is never None)
            return expr
        return self.typer.const(value, expr.type, expr.span)

    def constant_values(self, low_expr: ast.Expr, high_expr: ast.Expr | None, env: Env,
                        replies: bool = False) -> tuple[Type, Sequence[m.Value]] | None:
        """The values of a loop's (or a `replies`') variable: a constant array's, or those of a
        range of constant ints, both ends included; None when they are in error (reported)."""
        if high_expr is None:
            over = self.typer.expr(low_expr, env)
            if over.type is None:
                return None
            if not isinstance(over.type, m.Array):
                self.d.report("E212", low_expr.span, "a loop goes over a constant array or a range, not "
                              f"{describe(over.type)}", help="write a range: `for i in 0..5`")
                return None
            if not self.typer.is_constant(over) and replies:  # an array parameter is taken: not this one
                self.d.report("E212", low_expr.span, "`replies` goes over a constant array, a range or an array "
                              "parameter, not an array known only when it runs",
                              help="pass the array to the primitive as a parameter: `replies id in ids` over "
                              "`ids: int[]` reads a reply for each element the caller gives")
                return None
            if not self.typer.is_constant(over):
                name = low_expr.name if isinstance(low_expr, ast.Ref) else "values"
                size = over.type.size or 6  # an open size: any, so one to give it
                indexed = f"for i in 0..{size - 1} {{ ... {name}[i] ... }}"
                sized = "" if over.type.size else \
                    f"its rounds are fixed when the description is checked: give `{name}` a size " \
                    f"(`{over.type.element.value}[{size}]`), then "
                self.d.report("E212", low_expr.span, "a loop goes over a constant array or a range, not an array "
                              "known only when it runs", help=f"{sized}loop over its indexes and read its "
                              f"elements: `{indexed}`")
                return None
            values = self.typer.constant(over)
            assert isinstance(values, tuple)  # a constant array's value
            return over.type.element, values
        ends = [self.typer.expr(end, env) for end in (low_expr, high_expr)]
        if any(end.type is None for end in ends):
            return None
        for end, written in zip(ends, (low_expr, high_expr)):
            if end.type is not Type.INT or not self.typer.is_constant(end):
                what = describe(end.type) if end.type is not Type.INT else "an int known only when it runs"
                self.d.report("E212", written.span, f"a loop's bounds are constant ints, not {what}",
                              help="its rounds are fixed when the description is checked: write its bounds "
                              "with numbers and constants")
                return None
        low, high = (self.typer.constant(end) for end in ends)
        assert isinstance(low, int) and isinstance(high, int)  # constant ints: checked above
        if low > high:
            self.d.report("E204", low_expr.span.to(high_expr.span), f"the range {low}..{high} is empty",
                          help="a loop counts up, from its first bound to its last, both included")
            return None
        return Type.INT, range(low, high + 1)

    def loop_variable(self, var: ast.Ident, params: tuple[ast.Param, ...], loops: dict[str, ast.Ident]) -> bool:
        """A loop variable's name is its own: a parameter, state variable, constant or outer
        loop variable of the name would be hidden in the loop, and its reader misled."""
        errors = self.d.error_count
        check_name(var, "loop variable", self.d)
        name = var.text
        param = next((p.name for p in params if p.name.text == name), None)
        state, constant = self.s.states.get(name), self.s.constants.get(name)
        first, what = (loops[name], "an outer loop's variable") if name in loops else \
            (param, "a parameter") if param is not None else \
            (state.name, "a state variable") if state is not None else \
            (constant.name, "a constant") if constant is not None else (None, "")
        if first is not None:
            self.d.report("E101", var.span, f"loop variable `{name}` has the name of {what}",
                          labels=(Label(first.span, f"{what} `{name}`"),),
                          help="give the loop variable a name of its own")
        return self.d.error_count == errors


def in_range(value: object, low: float, high: float) -> bool:
    """Whether a constant is within a parameter's range: a number by its value, bytes by their
    length (a value of another type is reported as such, not here)."""
    if isinstance(value, bytes):
        return low <= len(value) <= high
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return low <= value <= high
    return True


def ranged(value: object) -> str:
    """A constant as a range message names it: bytes by their length."""
    if isinstance(value, bytes):
        return f"{shown(value)} ({len(value)} byte{'s' if len(value) != 1 else ''})"
    return shown(value)


def counted(n: int, noun: str) -> str:
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def _array_help(source: m.AnyType, target: m.AnyType) -> str | None:
    """What to write when an array meets a scalar, or an array of another size or type."""
    if unify(source, target) == target or isinstance(target, m.Array) and target.size == 0:
        return None
    if isinstance(target, m.Array):
        example = f"{target.element.value}[{target.size}]"
        return f"an array's size and type are fixed: `{example}` takes {'an' if target.element is Type.INT else 'a'} {example}"
    assert isinstance(source, m.Array)
    whole = f"{source.element.value}[{source.size}]" if source.size else f"{source.element.value}[]"
    return f"take one of its values (`[0]`), or declare the target `{whole}` to keep them all"
