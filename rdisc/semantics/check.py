"""Types and rules of every declaration, and the Model built from them.

`check` walks the declarations once, typing every expression (rdisc.semantics.types)
and checking the rules of the thesis model: clauses, arity, message templates,
value ranges, scopes and writes, adapters' fields, unused elements. The Model is
returned only when no error was found.
"""

from __future__ import annotations

import math
from collections import ChainMap
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING, Protocol, TypeVar

from rdisc.diagnostics import Diagnostics, Label, abbreviate
from rdisc.frozen import field_names, replace
from rdisc.limits import MAX_ARRAY, MAX_INT
from rdisc.semantics import bounds, formats, ros
from rdisc.semantics import model as m
from rdisc.semantics.body import BodyRules
from rdisc.semantics.frames import (
    FrameRules,
    length_part,
    length_range,
    length_words,
    payload_end_known,
    unseeded,
)
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.operators import shown
from rdisc.semantics.resolve import Symbols, Unit, check_name, suggest
from rdisc.semantics.types import Env, Names, Typer, describe, unify
from rdisc.semantics.units import UNITS
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.printer import print_type

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.check_methods import dataclass

FLOAT_LIMITS = {"e": 65504.0, "f": 3.4028234663852886e38}  # the largest finite half and single floats
MAX_BAUD = 100_000_000  # bit/s: no serial line is faster
MAX_FREQUENCY_HZ = 10_000  # ticks a second of a connection's thread
MAX_DURATION_MS = 3_600_000  # a delay, a timeout or a keepalive interval: an hour
MAX_PRIORITY = 1_000_000  # either way; priorities only order the calls of one interface
STANDARD_BAUDS = frozenset(
    (50, 75, 110, 134, 150, 200, 300, 600, 1200, 1800, 2400, 4800, 9600, 14400, 19200, 28800, 38400, 57600,
     76800, 115200, 230400, 250000, 460800, 500000, 576000, 921600, 1000000, 1152000, 1500000, 2000000,
     2500000, 3000000, 3500000, 4000000,
     100000, 420000)  # S.BUS's and CRSF's own rates
)
CONNECTION_KINDS = ("serial", "tcp")
PARITIES = ("none", "even", "odd", "mark", "space")  # pyserial's, each its first letter there
DATA_BITS = (5, 6, 7, 8)
STOP_BITS = (1, 1.5, 2)
DEFAULT_BAUD = 9600
DEFAULT_FREQUENCY_HZ = 10.0
MAX_TERMINATOR = 8
MAX_BREAK_MS = 10_000  # a serial break held longer is a line left low, not a break
MAX_POLLS = 100_000  # calls of one `until`: its limit over its interval, plus the first
MAX_RETRIES = 10  # resends of one request: each may wait a whole timeout
MAX_TABLE = 4096  # entries of a reply table
MAX_UNROLLED = 4096  # calls an interface's body makes, its loops written out
MAX_UNROLLED_ALL = 65_536  # the same for all interfaces: the work loops cause stays bounded
_TYPES = {t.value: t for t in Type}
_NOTHING = Env({}, "where a constant is needed", "")


class _Spanned(Protocol):
    @property
    def span(self) -> Span: ...


_Clause = TypeVar("_Clause", bound=_Spanned)


@dataclass(frozen=True, slots=True)
class _Unrolling:
    """What the statements of one interface's body are checked against, and the calls made."""

    decl: ast.InterfaceDecl
    env: Env
    interface_params: dict[str, tuple[m.Parameter, ...]]
    primitives: dict[str, m.Primitive]
    calls: list[m.PrimitiveCall]


def check(units: list[Unit], symbols: Symbols, diagnostics: Diagnostics) -> m.Model | None:
    return _Checker(units, symbols, diagnostics).run()


class _Checker:
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

    # -- the whole description ----------------------------------------------------------

    def run(self) -> m.Model | None:
        adapters = {name: self.adapter(decl) for name, decl in self.s.adapters.items()}
        states = {name: self.state(decl) for name, decl in self.s.states.items()}
        self.typer.settings = set(self.s.settings)
        settings = self.settings = {name: self.user_setting(decl) for name, decl in self.s.settings.items()}
        self.state_env = {n: (Scope.STATE, s.type) for n, s in settings.items()}
        self.state_env.update({n: (Scope.STATE, s.type) for n, s in states.items()})
        for keyword, name in self.s.damaged:  # lost to a syntax error: readable, of unknown type
            if keyword in ("state", "setting"):
                self.state_env.setdefault(name, (Scope.STATE, None))  # type: ignore[arg-type]
        tables = {name: self.table(name, decl) for name, decl in self.s.constants.items()
                  if isinstance(decl.value, ast.TableLit)}
        constants = {name: self.constant(decl) for name, decl in self.s.constants.items()
                     if not isinstance(decl.value, ast.TableLit)}
        enums = {name: self.enum(decl) for name, decl in self.s.enums.items()}
        rules = FrameRules(self.d, self.typer, self.setting)
        self.frames = {name: rules.frame(decl, self.params(decl.params, "frame"))
                       for name, decl in self.s.frames.items()}
        interface_params = {name: self.params(decl.params, "interface") for name, decl in self.s.interfaces.items()}
        primitives = self.primitives = {name: self.primitive(decl) for name, decl in self.s.primitives.items()}
        connections = {name: self.connection(decl, interface_params) for name, decl in self.s.connections.items()}
        interfaces = {
            name: self.interface(decl, interface_params, primitives) for name, decl in self.s.interfaces.items()
        }
        self.interface_cycles(interfaces)
        inputs = {name: self.input(decl, adapters, interface_params) for name, decl in self.s.inputs.items()}
        outputs = {name: self.output(decl, adapters) for name, decl in self.s.outputs.items()}
        body = BodyRules(self.d, self.typer, self.s, self.setting)
        links = {name: body.link(decl) for name, decl in self.s.links.items()}
        joints = {j.name: j for j in (body.joint(decl) for decl in self.s.joints.values()) if j is not None}
        joints = body.tree(links, joints)
        transmissions = {name: body.transmission(decl, joints, primitives, interface_params, states)
                         for name, decl in self.s.transmissions.items()}
        robot = self.robot()
        self.unused(interfaces)
        unseeded(self.frames, primitives, self.s.primitives, self.d)
        if self.d.has_errors() or robot is None:
            return None
        return m.Model(
            robot=robot,
            states=states,
            connections=connections,
            primitives=primitives,
            interfaces=interfaces,
            adapters=adapters,
            inputs=inputs,
            outputs=outputs,
            frames=self.frames,
            constants={n: v for n, v in constants.items() if v is not None},
            tables={n: t for n, t in tables.items() if t is not None},
            enums=enums,
            constant_docs={n: d.doc for n, d in self.s.constants.items() if d.doc and constants.get(n) is not None},
            enum_docs={n: d.doc for n, d in self.s.enums.items() if d.doc and n in enums},
            settings=settings,
            links=links,
            joints=joints,
            transmissions={n: t for n, t in transmissions.items() if t is not None},
        )

    # -- shared pieces ---------------------------------------------------------------------

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
            if low is not None and high is not None and not _in_range(item, low, high):
                self.d.report("E403", p.default.span, f"{_ranged(item)} is outside the range of {what} "
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
        return Env(ChainMap(extra, self.state_env), where, sees, reply, reply_note, reply_known)

    def flow(self, value: m.Expr, target: m.AnyType | None, span: Span, into: str) -> None:
        """A value of value.type goes into something of type `target` (int widens to float)."""
        source = value.type
        if source is None or target is None or source == target or (source, target) == (Type.INT, Type.FLOAT):
            return
        if isinstance(source, m.Array) and isinstance(target, m.Array) and 0 in (source.size, target.size) \
                and unify(source.element, target.element) == target.element:
            return  # an adapter's open array: its size is checked when it runs
        if isinstance(source, m.Array) or isinstance(target, m.Array):
            element = unify(source, target) == target
            kind = target.element if isinstance(target, m.Array) else target
            example = f"{kind.value}[{target.size if isinstance(target, m.Array) else 6}]"  # the target's own type
            self.d.report("E401", span, f"{into} takes {describe(target)}, but this is {describe(source)}",
                          help=f"an array's size and type are fixed: `{example}` takes "
                          f"{'an' if kind is Type.INT else 'a'} {example}"
                          if not element and not (isinstance(target, m.Array) and target.size == 0) else None)
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
            takes = _count(len(params), "argument") if required == len(params) else \
                f"{required} to {len(params)} arguments"
            self.d.report("E201", call.span, f"{kind} `{name}` takes {takes}, but {len(args)} given", labels=labels)
            return args
        args += tuple(self.typer.const(p.default, p.type, call.span) for p in params[len(args):])  # type: ignore[arg-type]
        for arg, expr, param in zip(args, call.args, params):
            self.flow(arg, param.type, expr.span, f"parameter `{param.name}` of {kind} `{name}`")
            value = self.typer.constant(arg)
            if param.low is not None and param.high is not None and value is not None \
                    and not _in_range(value, param.low, param.high):
                self.d.report("E403", expr.span, f"{_ranged(value)} is outside the range of parameter "
                              f"`{param.name}` of {kind} `{name}`", label=f"in {param.range_text()}")
        return args

    # -- elements ----------------------------------------------------------------------

    def robot(self) -> m.Robot | None:
        decl = self.s.robot
        if decl is None:
            return None
        attrs: dict[str, str] = {}
        for key in ("author", "description", "version"):
            found = self.once([a for a in decl.attrs if a.key == key], f"`{key}`", decl.name)
            if found is not None:
                attrs[key] = found.value
        return m.Robot(decl.name.text, doc=decl.doc, span=decl.span, **attrs)

    def table(self, name: str, decl: ast.ConstDecl) -> m.Table | None:
        """`const T = {key: value, ...}`: constant keys of one type (int or string), each once, and
        constant values of one type."""
        assert isinstance(decl.value, ast.TableLit)
        env = Env({}, "in a table", "constants declared before it")
        entries: dict[m.Value, m.Value] = {}
        spans: dict[m.Value, Span] = {}
        key_types: set[m.AnyType] = set()
        value_type: m.AnyType | None = None
        errors = self.d.error_count
        if not decl.value.entries:
            self.d.report("E204", decl.value.span, f"table `{name}` is empty", help="give it `key: value` entries")
        for key_expr, value_expr in decl.value.entries:
            for_entry = self.d.error_count
            key, value = self.typer.expr(key_expr, env), self.typer.expr(value_expr, env)
            for node, expr in ((key, key_expr), (value, value_expr)):
                if node.type is not None and not self.typer.is_constant(node) and self.d.error_count == for_entry:
                    self.d.report("E204", expr.span, "a table's keys and values are constants")
            if key.type is not None and key.type not in (Type.INT, Type.STRING):
                self.d.report("E401", key_expr.span, f"a table's keys are ints or strings, not {describe(key.type)}")
            if key.type is not None:
                key_types.add(key.type)
            if value.type is not None:
                joined = value.type if value_type is None else unify(value_type, value.type)
                if joined is None and value_type is not None:
                    self.d.report("E401", value_expr.span, f"a table's values are of one type: this is "
                                  f"{describe(value.type)}, the ones before are {describe(value_type)}")
                value_type = joined or value_type
            k = self.typer.constant(key)
            if k in spans:
                self.d.report("E101", key_expr.span, f"key {shown(k)} is in table `{name}` twice",
                              labels=(Label(spans[k], "first given here"),))
            elif k is not None:
                spans[k] = key_expr.span
                known = self.typer.constant(value)
                if known is not None:  # else reported
                    entries[k] = known
        if len(key_types) > 1:
            self.d.report("E401", decl.value.span, f"the keys of table `{name}` are of one type")
        key_type = next(iter(key_types), None)  # one, or more than one reported
        if self.d.error_count != errors or not isinstance(key_type, Type) or value_type is None:
            self.typer.failed.add(name)  # reported: its lookups are not reported again
            return None
        if value_type is Type.FLOAT:
            entries = {k: m.coerce(v, Type.FLOAT) for k, v in entries.items()}
        self.typer.tables[name] = (key_type, value_type, entries)
        # A table's values may be arrays, which m.Table.value_type (a Type) does not say.
        return m.Table(name, key_type, value_type, tuple(entries.items()), decl.doc)  # type: ignore[arg-type]

    def constant(self, decl: ast.ConstDecl) -> m.Value | None:
        """A named constant, visible to every expression declared after it."""
        errors, failed_reads = self.d.error_count, self.typer.failed_reads
        assert not isinstance(decl.value, ast.TableLit)  # `table`
        node = self.typer.expr(decl.value, Env({}, "in a constant", "constants declared before it"))
        value = self.typer.constant(node)
        if value is None or node.type is None or not self.typer.kept(value, decl.value.span):
            if self.d.error_count == errors and self.typer.failed_reads == failed_reads:
                self.d.report("E204", decl.value.span, "a constant's value must be a constant expression")
            self.typer.failed.add(decl.name.text)
            return None
        self.typer.named[decl.name.text] = (node.type, value)
        return value

    def enum(self, decl: ast.EnumDecl) -> dict[str, int]:
        members: dict[str, int] = {}
        self.typer.enums[decl.name.text] = members
        first: dict[str, ast.EnumMember] = {}
        for member in decl.members:
            if member.name.text in first:
                self.d.report("E101", member.name.span, f"member `{member.name.text}` is declared twice",
                              labels=(Label(first[member.name.text].name.span, "first declared here"),))
                continue
            first[member.name.text] = member
            node = self.typer.expr(member.value, Env({}, "in an enum", "constants"))
            value = self.typer.constant(node)
            if node.type is not Type.INT or not isinstance(value, int) or isinstance(value, bool):
                if node.type is not None:
                    self.d.report("E204", member.value.span, "an enum member's value is a constant integer")
                continue
            if not self.typer.kept(value, member.value.span):  # 64 bits and a sign: it must go through JSON
                continue
            members[member.name.text] = value
        return members

    def adapter(self, decl: ast.AdapterDecl) -> m.Adapter:
        fields: list[m.AdapterField] = []
        seen: dict[str, ast.FieldDecl] = {}
        for f in decl.fields:
            check_name(f.name, "field", self.d)
            if f.name.text in seen:
                self.d.report(
                    "E101", f.name.span, f"field `{f.name.text}` is declared twice in adapter `{decl.name.text}`",
                    labels=(Label(seen[f.name.text].name.span, "first declared here"),),
                )
                continue
            seen[f.name.text] = f
            path = None
            if f.ros is not None:
                problem = ros.path_problem(f.ros.value)
                if problem is not None:
                    self.d.report("E108", f.ros.span, problem)
                path = f.ros.value
            field_type = self.type_name(f.type, "an adapter field", True)  # None: reported
            fields.append(m.AdapterField(f.name.text, field_type, f.unit, path, f.doc))  # type: ignore[arg-type]
        message = None
        if decl.ros is not None:
            problem = ros.message_problem(decl.ros.value)
            if problem is not None:
                self.d.report("E108", decl.ros.span, problem)
            message = decl.ros.value
        return m.Adapter(decl.name.text, tuple(fields), message, id(decl) in self.s.standard, decl.doc, decl.span)

    def state(self, decl: ast.StateDecl) -> m.StateVariable:
        type_ = self.type_name(decl.type, open_size=True)
        initial: object = type_.default() if type_ else None
        if decl.init is not None:
            errors = self.d.error_count
            node = self.typer.expr(decl.init, Env({}, "in an initial value", ""))
            value = self.typer.constant(node)
            if value is None:
                if self.d.error_count == errors:  # not already explained
                    self.d.report("E204", decl.init.span, "an initial value must be a constant")
            elif type_ is not None and node.type is not None and self.typer.kept(value, decl.init.span):
                before = self.d.error_count
                self.flow(node, type_, decl.init.span, f"state variable `{decl.name.text}`")
                if self.d.error_count == before:
                    initial = m.coerce(value, type_)
        return m.StateVariable(decl.name.text, type_, initial, decl.doc, decl.span)  # type: ignore[arg-type]

    def user_setting(self, decl: ast.SettingDecl) -> m.Setting:
        """`setting NAME: TYPE in LOW..HIGH = DEFAULT`: a parameter of the whole description, given
        when connecting. Its default is required: the checks and the link budget use it."""
        check_name(decl.name, "setting", self.d)
        state = self.s.states.get(decl.name.text)
        if state is not None:
            self.d.report("E101", decl.name.span, f"`{decl.name.text}` is declared as a state variable and as a "
                          "setting", labels=(Label(state.name.span, "the state variable"),),
                          help="expressions read both by name: rename one")
        type_ = self.type_name(decl.type)
        param = ast.Param(decl.name, decl.type, decl.span, decl.low, decl.high, decl.default)
        low, high = self.param_range(param, type_.element if isinstance(type_, m.Array) else type_, "setting")
        default = self.param_default(param, type_, low, high, "setting")
        if decl.default is None:
            self.d.report("E213", decl.name.span, f"setting `{decl.name.text}` has no default",
                          help=f"give the value it has when none is given: `setting {decl.name.text}: "
                          f"{print_type(decl.type)} = ...`; the checks and the link budget use it")
        return m.Setting(decl.name.text, type_, default, low, high, decl.doc, decl.span)  # type: ignore[arg-type]

    def baud_setting(self, ref: ast.Ref) -> float | None:
        """`baud NAME` of an int setting: its default is checked as a baud rate, and is what the
        link budget assumes; the value given when connecting is the port's."""
        setting = self.settings[ref.name]
        declared = (Label(self.s.settings[ref.name].name.span, "declared here"),)
        self.typer.reads.add(ref.name)
        if setting.type is None or setting.default is None:  # reported
            return None
        if setting.type is not Type.INT:
            self.d.report("E213", ref.span, f"the baud rate is an int, but setting `{ref.name}` is "
                          f"{describe(setting.type)}", labels=declared)
            return None
        baud = int(setting.default)  # type: ignore[arg-type]  # an int: its type is
        if not 0 < baud <= MAX_BAUD:
            self.d.report("E204", ref.span, f"the baud rate must be a positive integer at most {MAX_BAUD}, but "
                          f"the default of setting `{ref.name}` is {baud}", labels=declared)
            return None
        if baud not in STANDARD_BAUDS:
            self.d.report("W201", ref.span, f"{baud} (the default of setting `{ref.name}`) is not a standard "
                          "baud rate", help="standard rates include 9600, 19200, 38400, 57600, 115200")
        return baud

    def connection(self, decl: ast.ConnectionDecl,
                   interface_params: dict[str, tuple[m.Parameter, ...]]) -> m.Connection:
        name = decl.name
        if decl.kind.text not in CONNECTION_KINDS:
            self.d.report("E209", decl.kind.span, f"unknown connection kind `{decl.kind.text}`",
                          help="connections are `serial` or `tcp` (a `socket://host:port` port)")
        baud_clause = self.once([a for a in decl.attrs if isinstance(a, ast.Baud)], "`baud`", name)
        baud: float | None = DEFAULT_BAUD
        given = baud_clause.value if isinstance(baud_clause, ast.Baud) else None
        baud_setting = given.name if isinstance(given, ast.Ref) and given.name in self.settings else None
        if baud_setting is not None:
            baud = self.baud_setting(given)  # type: ignore[arg-type]
        elif isinstance(baud_clause, ast.Baud):
            baud = self.setting(baud_clause.value, "the baud rate", MAX_BAUD)
            if baud is not None:
                if baud != int(baud) or baud <= 0:
                    self.d.report("E204", baud_clause.value.span, f"the baud rate must be a positive integer, not {baud:g}")
                elif int(baud) not in STANDARD_BAUDS:
                    self.d.report("W201", baud_clause.value.span, f"{int(baud)} is not a standard baud rate",
                                  help="standard rates include 9600, 19200, 38400, 57600, 115200")
        threading = self.once([a for a in decl.attrs if isinstance(a, ast.Threading)], "`threading`", name)
        frequency: float | None = DEFAULT_FREQUENCY_HZ
        if isinstance(threading, ast.Threading):
            if threading.model.text != "single":
                self.d.report("E209", threading.model.span, f"unknown threading model `{threading.model.text}`",
                              help="threading is `single`: one thread per connection")
            frequency = self.setting(threading.frequency, "the frequency", MAX_FREQUENCY_HZ, " Hz")
            if frequency is not None and frequency <= 0:
                self.d.report("E204", threading.frequency.span, f"the frequency must be positive, not {frequency:g} Hz")
        hooks: dict[str, m.HookCall | None] = {}
        interval: float | None = None
        env = Env(self.state_env, "in a hook argument", "state variables")
        for event in ("startup", "terminate", "keepalive"):
            hook = self.once([a for a in decl.attrs if isinstance(a, ast.Hook) and a.event == event], f"`{event}`", name)
            hooks[event] = None
            if not isinstance(hook, ast.Hook):
                continue
            target = self.s.interfaces.get(hook.call.target.text)
            params = interface_params.get(hook.call.target.text)
            args = self.call(hook.call, params, env, "interface", target.name if target else None)
            hooks[event] = m.HookCall(m.InterfaceRef(hook.call.target.text), args, hook.span)
            if hook.every is not None:
                interval = self.duration(hook.every, "the keepalive interval")
                if interval is not None and interval <= 0:
                    self.d.report("E204", hook.every.span, "the keepalive interval must be positive")
        keepalive = m.Keepalive(hooks["keepalive"], interval) if hooks["keepalive"] and interval else None
        terminator = "\n"
        clause = self.once([a for a in decl.attrs if isinstance(a, ast.Terminator)], "`terminator`", name)
        if isinstance(clause, ast.Terminator):
            text = clause.value.value
            if not 1 <= len(text) <= MAX_TERMINATOR or any(ord(ch) > 0xFF for ch in text):
                self.d.report("E204", clause.value.span,
                              f"a terminator is 1 to {MAX_TERMINATOR} bytes (characters up to \\xff)")
            else:
                terminator = text
        address_clause = self.once([a for a in decl.attrs if isinstance(a, ast.Address)], "`address`", name)
        address = address_clause.value.value if isinstance(address_clause, ast.Address) else None
        if decl.kind.text == "tcp" and address_clause is not None and not address_clause.value.value.startswith("socket://"):
            self.d.report("E204", address_clause.value.span, "a tcp connection's address is `socket://HOST:PORT`")
        data_bits, parity, stop_bits = self.serial_line(decl)
        return m.Connection(
            name.text, decl.kind.text, int(baud or 0), float(frequency or 0), hooks["startup"], hooks["terminate"],
            keepalive, decl.doc, decl.span, terminator, address, baud_setting, data_bits, parity, stop_bits,
        )

    def serial_line(self, decl: ast.ConnectionDecl) -> tuple[int, str, float]:
        """A serial line's character, `databits`, `parity` and `stopbits` (8N1 unless said): the
        settings a UART has, stated only on a `serial` connection (E215)."""
        name = decl.name
        data = self.once([a for a in decl.attrs if isinstance(a, ast.DataBits)], "`databits`", name)
        parity = self.once([a for a in decl.attrs if isinstance(a, ast.Parity)], "`parity`", name)
        stop = self.once([a for a in decl.attrs if isinstance(a, ast.StopBits)], "`stopbits`", name)
        if decl.kind.text == "tcp":
            for clause in (data, parity, stop):
                if clause is not None:
                    self.d.report("E215", clause.span, f"`{name.text}` is a tcp connection, which has no serial line "
                                  "to set", help="data bits, parity and stop bits are a `serial` connection's")
        data_bits, parity_name, stop_bits = 8, "none", 1.0
        if isinstance(data, ast.DataBits):
            value = self.setting(data.value, "the data bits")
            if value is not None and value not in DATA_BITS:
                self.d.report("E215", data.value.span, f"a character has 5, 6, 7 or 8 data bits, not {value:g}")
            elif value is not None:
                data_bits = int(value)
        if isinstance(parity, ast.Parity):
            if parity.value.text not in PARITIES:
                self.d.report("E215", parity.value.span, f"unknown parity `{parity.value.text}`",
                              help="parity is none, even, odd, mark or space")
            else:
                parity_name = parity.value.text
        if isinstance(stop, ast.StopBits):
            value = self.setting(stop.value, "the stop bits")
            if value is not None and value not in STOP_BITS:
                self.d.report("E215", stop.value.span, f"a character ends with 1, 1.5 or 2 stop bits, not {value:g}")
            elif value is not None:
                stop_bits = value  # 2 stays an int: the driver says `stop_bits=2`
        if stop_bits == 1.5 and data_bits != 5:
            assert isinstance(stop, ast.StopBits)  # 1.5 is only ever stated
            self.d.report("E215", stop.value.span, f"1.5 stop bits go with 5 data bits, not {data_bits}",
                          help="a UART sends 1.5 stop bits only after 5 data bits: say `stopbits 1` or `2`")
        return data_bits, parity_name, stop_bits

    def duration(self, d: ast.Duration, what: str) -> float | None:
        """A duration in ms: at most an hour (a longer one could only hang)."""
        return self.setting(d.value, what, MAX_DURATION_MS, " ms", 1000 if d.unit == "s" else 1)

    def primitive(self, decl: ast.PrimitiveDecl) -> m.Primitive:
        name = decl.name
        params = self.params(decl.params, "primitive")
        on = self.once([c for c in decl.clauses if isinstance(c, ast.On)], "`on`", name)
        if on is None:
            self.d.report("E202", name.span, f"primitive `{name.text}` has no connection",
                          help=f"add `on CONNECTION` after `{name.text}(...)`")
        encodings = [c for c in decl.clauses if isinstance(c, ast.Encoding)]
        decodings = [c for c in decl.clauses if isinstance(c, ast.Decoding)]
        action_blocks = [c for c in decl.clauses if isinstance(c, ast.Actions)]
        lines_clause = self.once([c for c in decl.clauses if isinstance(c, ast.Lines)], "`lines`", name)
        replied = any(isinstance(c, ast.Decoding | ast.Framed | ast.ReplyTable | ast.ReplyList) for c in decl.clauses)
        if not encodings and (lines_clause is None or replied):
            self.d.report("E202", name.span, f"primitive `{name.text}` has neither `pack` nor `format`",
                          help='say how the request is written: `pack ">Bhh" (...)` or `format "D,{},{}\\n" (...)`'
                          if lines_clause is None else "a primitive that only sets `lines` writes no request, "
                          "so it has no reply and no frame")
        for extra in encodings[1:]:
            self.d.report("E203", extra.span, f"primitive `{name.text}` has more than one of `pack`/`format`",
                          labels=(Label(encodings[0].span, "first given here"),))
        for repeated in decodings[1:]:
            self.d.report("E203", repeated.span, f"primitive `{name.text}` has more than one of `unpack`/`regex`",
                          labels=(Label(decodings[0].span, "first given here"),))
        for block in action_blocks[1:]:
            self.d.report("E203", block.span, f"primitive `{name.text}` has more than one post-action block",
                          labels=(Label(action_blocks[0].span, "first given here"),))
        scope = {p.name: (Scope.PARAM, p.type) for p in params}  # one of a type in error: known, of type None
        env = self.env_with(scope, "in a primitive", "its parameters and state variables",
                            reply_note="`out`, the reply, is in scope only in post-actions")
        encoding: m.Pack | m.Format | None = None
        args: tuple[m.Expr, ...] = ()
        if encodings:
            encoding, args = self.encoding(encodings[0], env)
        decoding: m.Unpack | m.Regex | None = None
        reply: tuple[m.AnyType, ...] | None = ()
        if decodings:
            decoding, reply = self.decoding(decodings[0])
        records_clause = self.once([c for c in decl.clauses if isinstance(c, ast.Records)], "`reply each until`", name)
        if isinstance(records_clause, ast.Records):  # each record's post-actions read its position as `index`
            self.not_a_param(decl, m.INDEX, "the position of a record of the reply")
            scope = {**scope, m.INDEX: (Scope.PARAM, Type.INT)}
        replies_clause = self.once([c for c in decl.clauses if isinstance(c, ast.Replies)], "`replies`", name)
        count, reply_frames = self.reply_count(replies_clause, decl, reply, decoding, env, encoding) \
            if isinstance(replies_clause, ast.Replies) else (0, ())
        list_clause = self.once([c for c in decl.clauses if isinstance(c, ast.ReplyList)], "`replies { }`", name)
        listed = self.listed_replies(list_clause, decl, scope, env, encoding) \
            if isinstance(list_clause, ast.ReplyList) else ()
        actions: tuple[m.PostAction, ...] = ()
        if action_blocks:
            note = None if decodings else f"primitive `{name.text}` reads no reply: add `unpack` or `regex`"
            # A count only with scalar values (E401 for arrays): out[i] is the array of the i-th values.
            each_array = self.array_parameter(replies_clause, env) if isinstance(replies_clause, ast.Replies) else None
            size = count if each_array is None else each_array.size
            collected = tuple(m.Array(t, size) if isinstance(t, Type) else t for t in reply) \
                if count and reply is not None else reply
            refused = isinstance(replies_clause, ast.Replies) and not count  # reported: `out` unknown, no cascade
            action_env = self.env_with(
                scope, "in a post-action", "`out`, parameters and state variables",
                reply=None if refused else collected if decodings else None, reply_note=note,
                reply_known=reply is not None and not refused,
            )
            actions = self.actions(action_blocks[0], action_env, {p.name for p in params})
        expect = self.expect(decl, scope, reply, bool(decodings))
        connection = m.ConnectionRef(on.connection.text) if isinstance(on, ast.On) else m.ConnectionRef("")
        framed = self.once([c for c in decl.clauses if isinstance(c, ast.Framed)], "`frame`", name)
        # Read without a frame: none, or one whose reply is empty (a frame in error: neither)
        unframed = framed is None or (isinstance(framed, ast.Framed) and framed.frame.text in self.frames
                                      and not self.frames[framed.frame.text].reply)
        lines = self.modem_lines(lines_clause, env, name, connection) if isinstance(lines_clause, ast.Lines) else ()
        table_clause = self.once([c for c in decl.clauses if isinstance(c, ast.ReplyTable)], "a reply table", name)
        table = None
        if isinstance(table_clause, ast.ReplyTable):
            if decodings or action_blocks:
                self.d.report("E203", table_clause.span, f"primitive `{name.text}` has a reply table and also "
                              "`unpack`/`regex` or post-actions", help="give each of its replies in the table")
            if table_clause.tag is not None:
                self.not_a_param(decl, m.TAG, "the tag of the reply")
            table = self.reply_table(table_clause, params, scope, name, unframed)
        tagged = table is not None and table.tag is not None
        replies = [decoding] if decoding is not None else [c.decoding for c in table.cases] if table else \
            [r.decoding for r in listed if r.frame is None]  # read through the primitive's frame, or none
        frame = (self.frame_use(framed, env, decl, encoding, replies, self.request_sizes(encoding, args, params))
                 if isinstance(framed, ast.Framed) else None)
        records = self.records(records_clause, name, decodings, decoding, frame, count or len(listed), table) \
            if isinstance(records_clause, ast.Records) else None
        open_ends = [why for r in replies if isinstance(r, m.Unpack) and (why := _open_end(r))]
        if (open_ends and (frame is None or not self.frames[frame.frame].reply) and not tagged  # tagged: E505
                and records_clause is None):  # records: E509
            self.d.report("E503", decodings[0].span if decodings else name.span,
                          f"the reply of `{name.text}` {open_ends[0]}, but no frame says where the reply ends",
                          help="read it through a frame with a `length` field or constant bytes after its payload")
        if (isinstance(table_clause, ast.ReplyTable) and tagged and frame is not None and self.frames[frame.frame].reply
                and not payload_end_known(self.frames[frame.frame], False)):
            self.d.report("E505", table_clause.span, f"the reply of `{name.text}` is chosen by its tag, so its frame "
                          "must say where the reply ends",
                          help="give the frame's reply a `length` field or constant bytes after its payload, "
                          "or read the reply without a frame")
        skip = self.once([c for c in decl.clauses if isinstance(c, ast.SkipUnmatched)], "`skip unmatched`", name)
        framed_all = bool(listed) and all(r.frame is not None or (frame and self.frames[frame.frame].reply)
                                          for r in listed)
        if skip is not None and not (tagged and unframed) and not framed_all and (
                not replies or frame is None or not self.frames[frame.frame].reply):
            self.d.report("E504", skip.span, f"`skip unmatched` reads past frames that do not decode, but "
                          f"`{name.text}` does not decode a framed reply",
                          help="give it a frame with a reply, and `unpack` or `regex`")
        timeout_clause = self.once([c for c in decl.clauses if isinstance(c, ast.ReplyTimeout)], "`timeout`", name)
        timeout = None
        if isinstance(timeout_clause, ast.ReplyTimeout):
            timeout = self.duration(timeout_clause.duration, "a timeout")
            if timeout is not None and timeout <= 0:
                self.d.report("E204", timeout_clause.span, "a timeout must be positive")
                timeout = None
            elif not replies and not listed and not (frame and self.frames[frame.frame].reply):
                self.d.report("E204", timeout_clause.span, f"`{name.text}` reads no reply, so it has no timeout")
        retry = self.once([c for c in decl.clauses if isinstance(c, ast.Retry)], "`retry`", name)
        replied = bool(replies or listed or (frame and self.frames[frame.frame].reply))
        writes = encoding is not None and (frame is not None or encoding != m.Format(""))  # `format "" ()` listens
        retries = self.retries(retry, name, writes, replied) if isinstance(retry, ast.Retry) else 0
        if expect is not None and table is not None:
            self.d.report("E203", expect.span, f"primitive `{name.text}` has a reply table and also `expect`",
                          help="`expect` checks the reply of a primitive with one decoding")
        error_clause = self.once([c for c in decl.clauses if isinstance(c, ast.ErrorReply)], "`error`", name)
        error = None
        if isinstance(error_clause, ast.ErrorReply):
            one = table is None and not count and not listed and records is None
            error = (self.error_when(error_clause, error_clause.when, decl, scope, reply, decoding, one)
                     if error_clause.when is not None else
                     self.error_reply(error_clause, decl, env, encoding, frame if one else None, decoding, one))
        return m.Primitive(name.text, params, connection, encoding, args, decoding, actions, decl.doc, decl.span,
                           frame, skip is not None, table, timeout, expect, lines, count, reply_frames, records,
                           listed, retries, error, self.replies_each(replies_clause, env, count))

    def replies_each(self, clause: object, env: Env, count: int) -> m.RepliesEach | None:
        """`replies id in ids` over an array parameter, when it was taken (`count`)."""
        if not count or not isinstance(clause, ast.Replies) or self.array_parameter(clause, env) is None:
            return None
        assert clause.var is not None and isinstance(clause.over, ast.Ref)  # array_parameter's
        return m.RepliesEach(clause.var.text, clause.over.name)

    def error_reply(self, clause: ast.ErrorReply, decl: ast.PrimitiveDecl, env: Env,
                    encoding: m.Pack | m.Format | None, frame: m.FrameUse | None,
                    decoding: m.Unpack | m.Regex | None, one: bool) -> m.ErrorReply | None:
        """`error [frame F(args)] ["MARKER"] unpack FORMAT [code ENUM]`: the reply the device may
        send instead of the one asked for, of a primitive that reads one reply (decoded, or a
        frame that acknowledges). It must be told apart from that reply before it is read: by its
        own frame, or by its first bytes; unframed, it has a fixed size. None where refused."""
        name = decl.name.text
        framed_reply = frame is not None and bool(self.frames[frame.frame].reply)
        if not one or not (framed_reply or isinstance(decoding, m.Unpack)):
            self.d.report("E511", clause.span, f"`{name}` does not read one reply that an error could stand in for",
                          help="an `error` reply goes with `unpack` (read with or without a frame) or a frame "
                          "that acknowledges, not with `regex`, `replies` or a reply table")
            return None
        marker = ""
        if clause.marker is not None:
            marker = clause.marker.value
            if not 1 <= len(marker) <= MAX_TERMINATOR or any(ord(ch) > 0xFF for ch in marker):
                self.d.report("E204", clause.marker.span,
                              f"an error's marker is 1 to {MAX_TERMINATOR} bytes (characters up to \\xff)")
                return None
        assert clause.decoding is not None  # `error when` has none: `error_when`
        if clause.decoding.kind != "unpack":
            self.d.report("E511", clause.decoding.span, "an error reply is bytes: decode it with `unpack`",
                          help='such as `unpack "B"`, the device\'s code')
            return None
        unpack, values = self.decoding(clause.decoding)
        if not isinstance(unpack, m.Unpack) or values is None:
            return None
        if clause.codes is not None and (not values or values[0] is not Type.INT):
            self.d.report("E511", clause.decoding.span, f"the first value of an error reply is the device's code, "
                          f"named by `{clause.codes.text}`, so it is an int",
                          help='decode it first with an integer code: `unpack "B"`')
            return None
        own = None
        if clause.frame is not None:
            own = self.frame_use(clause.frame, env, decl, encoding, [unpack], None)
            if own is None:
                return None
            reply = self.frames[own.frame].reply
            if not any(isinstance(part, m.FramePayload) for part in reply):
                if not reply:  # else `frame_use` said so
                    self.d.report("E504", clause.frame.span, f"the error reply of `{name}` is read through frame "
                                  f"`{own.frame}`, whose reply is empty",
                                  help="read it through a frame whose reply has a `payload`")
                return None
        elif not marker:
            self.d.report("E511", clause.span, f"the error reply of `{name}` cannot be told from its reply",
                          help='give it its own frame (`error frame rtu(unit, 0x83) ...`) or the bytes it starts '
                          'with (`error "\\x15" ...`)')
            return None
        elif framed_reply:
            assert frame is not None
            if not any(isinstance(part, m.FramePayload) for part in self.frames[frame.frame].reply):
                self.d.report("E511", clause.span, f"the error reply of `{name}` is known by its first bytes, but "
                              f"the reply of frame `{frame.frame}` has no payload to start with them",
                              help="give the error its own frame (`error frame nak() unpack \"B\"`)")
                return None
            if not payload_end_known(self.frames[frame.frame], False):
                self.d.report("E511", clause.span, f"the error reply of `{name}` is known by its first bytes, so "
                              f"frame `{frame.frame}` must say where a payload ends without its decoding",
                              help="give the frame's reply a `length` field or constant bytes after its payload, "
                              "or give the error its own frame")
                return None
        if own is None and not framed_reply and _open_end(unpack):
            self.d.report("E511", clause.decoding.span, f"the error reply of `{name}` is read without a frame, "
                          "so its size is fixed: no `*`")
            return None
        return m.ErrorReply(unpack, own, marker, None if clause.codes is None else clause.codes.text)

    def error_when(self, clause: ast.ErrorReply, when: ast.Expr, decl: ast.PrimitiveDecl, scope: Names,
                   reply: tuple[m.AnyType, ...] | None, decoding: m.Unpack | m.Regex | None,
                   one: bool) -> m.ErrorReply | None:
        """`error when COND [code ENUM]`: the reply itself, decoded by the primitive's `unpack`, is
        the device's error when COND (a bool over `out`, the parameters and state) holds, its first
        value the code (a TMCL status below 100). None where refused."""
        name = decl.name.text
        if not one or not isinstance(decoding, m.Unpack):
            self.d.report("E511", clause.span, f"`{name}` does not decode one reply that could say it is an error",
                          help="`error when` goes with `unpack` (read with or without a frame), not with `regex`, "
                          "`replies` or a reply table")
            return None
        env = self.env_with(scope, "in an `error when`", "`out`, parameters and state variables", reply=reply,
                            reply_known=reply is not None)
        condition = self.typer.expr(when, env)
        if condition.type is not None and condition.type is not Type.BOOL:
            self.d.report("E401", when.span, f"`error when` takes a bool, but this is {describe(condition.type)}")
            return None
        if clause.codes is not None and reply is not None and (not reply or reply[0] is not Type.INT):
            self.d.report("E511", clause.span, f"the first value of `{name}`'s reply is the device's code when it "
                          f"is an error, named by `{clause.codes.text}`, so it is an int",
                          help='decode it first with an integer code: `unpack ">BBi"`')
            return None
        return m.ErrorReply(decoding, codes=None if clause.codes is None else clause.codes.text, when=condition)

    def retries(self, clause: ast.Retry, name: ast.Ident, writes: bool, replied: bool) -> int:
        """`retry N`: resends of a request whose reply timed out or did not match, a constant
        int from 1 to MAX_RETRIES, of a primitive that writes a request and reads a reply. 0
        where it is refused."""
        value = self.setting(clause.count, "a retry count", MAX_RETRIES)
        if value is None:
            return 0
        if not isinstance(value, int) or isinstance(value, bool) or value < 1:
            self.d.report("E204", clause.count.span,
                          f"a retry count is a constant int from 1 to {MAX_RETRIES}, not {shown(value)}")
            return 0
        if not replied:
            self.d.report("E204", clause.span, f"`{name.text}` reads no reply, so it has nothing to retry",
                          help="`retry` resends a request whose reply timed out or did not match")
            return 0
        if not writes:
            self.d.report("E204", clause.span, f"`{name.text}` writes no request, so it has nothing to resend",
                          help="a primitive that only listens waits for its reply within its `timeout`")
            return 0
        return value

    def listed_replies(self, clause: ast.ReplyList, decl: ast.PrimitiveDecl, scope: dict[str, tuple[Scope, m.AnyType]],
                       env: Env, encoding: m.Pack | m.Format | None) -> tuple[m.ListedReply, ...]:
        """`replies { ... }`: 2 to MAX_ARRAY replies in a fixed order, each decoded its own way,
        held by its own `expect` and stored by its own post-actions, through its own frame (one
        whose reply carries a payload) or the primitive's. () where it is refused."""
        name = decl.name.text
        given = ((ast.Decoding, "`unpack`/`regex`"), (ast.Actions, "post-actions"), (ast.Expect, "`expect`"),
                 (ast.ReplyTable, "a reply table"), (ast.Replies, "`replies N`"))
        other = next((what for kind, what in given if any(isinstance(c, kind) for c in decl.clauses)), None)
        if other is not None:
            self.d.report("E203", clause.span, f"primitive `{name}` has `replies {{ }}` and also {other}",
                          help="each reply of `replies { }` has its own decoding, `expect` and post-actions: "
                          "write them there")
            return ()
        if not 2 <= len(clause.replies) <= MAX_ARRAY:
            self.d.report("E204", clause.span, f"a primitive reads 2 to {MAX_ARRAY} replies, not "
                          f"{len(clause.replies)}", help="a primitive that reads one reply says how with `unpack` "
                          "or `regex` alone")
            return ()
        sees = "`out`, parameters and state variables"
        listed: list[m.ListedReply] = []
        for n, r in enumerate(clause.replies, 1):
            decoding, reply = self.decoding(r.decoding)
            expect = None
            if r.expect is not None:
                expect = self.typer.expr(r.expect, self.env_with(scope, "in an `expect`", sees, reply=reply,
                                                                 reply_known=reply is not None))
                if expect.type is not None and expect.type is not Type.BOOL:
                    self.d.report("E401", r.expect.span, f"`expect` takes a bool, but this is {describe(expect.type)}")
            actions: tuple[m.PostAction, ...] = ()
            if r.actions is not None:
                action_env = self.env_with(scope, "in a post-action", sees, reply=reply, reply_known=reply is not None)
                actions = self.actions(r.actions, action_env, set(scope))
            frame = None
            if r.frame is not None:
                frame = self.frame_use(r.frame, env, decl, encoding, [decoding] if decoding else [], None)
                if frame is not None and not self.frames[frame.frame].reply:
                    self.d.report("E504", r.frame.span, f"reply {n} of `{name}` is read through frame "
                                  f"`{frame.frame}`, whose reply is empty",
                                  help="read it through a frame whose reply has a `payload`, or through the "
                                  "primitive's frame (leave out its `frame`)")
            if decoding is not None:
                listed.append(m.ListedReply(decoding, frame, expect, actions))
        return tuple(listed) if len(listed) == len(clause.replies) else ()

    def records(self, clause: ast.Records, name: ast.Ident, decodings: list[ast.Decoding],
                decoding: m.Unpack | m.Regex | None, frame: m.FrameUse | None, count: int,
                table: m.ReplyTable | None) -> str | None:
        """`reply each until "\\x7F"`: a framed payload of records, each ended by the marker (1 to
        8 constant bytes) and decoded by the primitive's one `unpack`; not with `replies` or a
        reply table, which read replies otherwise. The marker, or None where refused."""
        marker = clause.marker
        said = f"`{name.text}` reads its reply as records"
        if not 1 <= len(marker.value) <= MAX_TERMINATOR or any(ord(ch) > 0xFF for ch in marker.value):
            self.d.report("E509", marker.span, f"a record's end marker is 1 to {MAX_TERMINATOR} bytes "
                          "(characters up to \\xff)")
            return None
        if count or table is not None:
            self.d.report("E509", clause.span, f"{said}, so it reads one reply, not "
                          + ("several (`replies`)" if count else "one chosen by a reply table"),
                          help="each record is decoded by the primitive's `unpack`")
            return None
        if not isinstance(decoding, m.Unpack):
            if decodings and decoding is None:  # its template was reported
                return None
            self.d.report("E509", decodings[0].span if decodings else clause.span,
                          f"{said}, each decoded by an `unpack`" + (", not a `regex`" if decodings else ""),
                          help='e.g. `reply each until "\\x7F" unpack "<*(BB)"`, pairs of bytes until the marker')
            return None
        if frame is None or not self.frames[frame.frame].reply or not payload_end_known(self.frames[frame.frame], False):
            self.d.report("E509", clause.span, f"{said} until its payload ends, so it is read through a frame "
                          "that says where that is",
                          help="give the primitive a frame whose reply has a `length` field or constant bytes "
                          "after its payload")
            return None
        return marker.value

    def reply_count(self, clause: ast.Replies, decl: ast.PrimitiveDecl, reply: tuple[m.AnyType, ...] | None,
                    decoding: m.Unpack | m.Regex | None, env: Env,
                    encoding: m.Pack | m.Format | None) -> tuple[int, tuple[m.FrameUse, ...]]:
        """`replies N` (a constant int) or `replies id in IDS frame status(id)` (a reply, with its
        own frame, a value): 2 to MAX_ARRAY replies, of a primitive with one decoding whose values
        are not arrays (each value of the replies is one, of N). (0, ()) where it is refused."""
        name = decl.name.text
        frames: tuple[m.FrameUse, ...] = ()
        array = self.array_parameter(clause, env)
        if clause.var is None:
            value = self.setting(clause.over, "a reply count", MAX_ARRAY)
        elif array is not None:  # as many as the caller gives: the most, for the link budget
            found = self.reply_frame_each(clause, decl, decoding, env, encoding, array)
            if found is None:
                return 0, ()
            value, frames = array.size or MAX_ARRAY, (found,)
        else:
            found_all = self.reply_frames(clause, decl, decoding, env, encoding)
            if found_all is None:
                return 0, ()
            value, frames = len(found_all), found_all
        if value is None:
            return 0, ()
        if array is None and (not isinstance(value, int) or isinstance(value, bool) or not 2 <= value <= MAX_ARRAY):
            said = f"a reply count is a constant int from 2 to {MAX_ARRAY}, not {shown(value)}" \
                if clause.var is None else f"a primitive reads 2 to {MAX_ARRAY} replies, not {value}"
            self.d.report("E204", clause.over.span if clause.var is None else clause.span, said)
            return 0, ()
        if decoding is None:
            self.d.report("E202", clause.span, f"`{name}` reads {value} replies, but decodes none",
                          help="say how each reply is read: `unpack` or `regex` (a reply table chooses one reply)")
            return 0, ()
        if reply is not None and any(isinstance(t, m.Array) for t in reply):
            self.d.report("E401", clause.span, f"`{name}` reads {value} replies, whose values are arrays: "
                          "each value of the replies would be an array of arrays",
                          help="read a reply of single values, or one reply with a repeated group")
            return 0, ()
        assert isinstance(value, int)  # a constant int from 2 to MAX_ARRAY, or an array's size
        return value, frames

    @staticmethod
    def array_parameter(clause: ast.Replies, env: Env) -> m.Array | None:
        """The type of the array parameter `replies id in ids` goes over, if it goes over one."""
        if clause.var is None or clause.high is not None or not isinstance(clause.over, ast.Ref):
            return None
        scope, type_ = env.names.get(clause.over.name, (None, None))
        return type_ if scope is Scope.PARAM and isinstance(type_, m.Array) else None

    def reply_frame_each(self, clause: ast.Replies, decl: ast.PrimitiveDecl, decoding: m.Unpack | m.Regex | None,
                         env: Env, encoding: m.Pack | m.Format | None, array: m.Array) -> m.FrameUse | None:
        """`replies id in ids frame status(id)` over an array parameter: the one reply frame, its
        arguments over the parameters and the element, `id`, known when it runs; None in error."""
        assert clause.var is not None and clause.frame is not None
        if not self.loop_variable(clause.var, decl.params, {}):
            return None
        own = replace(env, names={**env.names, clause.var.text: (Scope.PARAM, array.element)})
        errors = self.d.error_count
        use = self.frame_use(clause.frame, own, decl, encoding, [decoding] if decoding else [], None)
        return None if use is None or self.d.error_count > errors else use

    def reply_frames(self, clause: ast.Replies, decl: ast.PrimitiveDecl, decoding: m.Unpack | m.Regex | None,
                     env: Env, encoding: m.Pack | m.Format | None) -> tuple[m.FrameUse, ...] | None:
        """`replies id in IDS frame status(id)`: each reply's frame, written out with the variable
        a constant in each (its arguments, constant ones as their values); None where in error."""
        assert clause.var is not None and clause.frame is not None
        if not self.loop_variable(clause.var, decl.params, {}):
            return None
        found = self.constant_values(clause.over, clause.high, env, replies=True)
        if found is None:
            return None
        type_, values = found
        if len(values) > MAX_ARRAY:  # before any is written out
            self.d.report("E204", clause.span, f"a primitive reads 2 to {MAX_ARRAY} replies, not {len(values)}")
            return None
        frames: list[m.FrameUse] = []
        name = clause.var.text  # no constant has it (loop_variable): bound as one, then gone
        for value in values:
            self.typer.named[name] = (type_, value)
            errors = self.d.error_count
            use = self.frame_use(clause.frame, env, decl, encoding, [decoding] if decoding else [], None)
            if use is None or self.d.error_count > errors:
                break
            frames.append(replace(use, args=tuple(self.value_of(a) for a in use.args)))
        del self.typer.named[name]
        return tuple(frames) if len(frames) == len(values) else None

    def modem_lines(self, clause: ast.Lines, env: Env, name: ast.Ident,
                    connection: m.ConnectionRef) -> tuple[m.LineLevel, ...]:
        """`lines dtr = COND, rts = COND`: each line of a serial port once, a bool over the
        parameters and state; a `tcp` connection has no modem lines."""
        conn = self.s.connections.get(connection)
        if conn is not None and conn.kind.text == "tcp":
            self.d.report("E211", clause.span, f"`{name.text}` sets modem lines, but connection `{connection}` is "
                          "`tcp`, which has none", help="DTR and RTS are a serial port's: use a `serial` connection")
        levels: list[m.LineLevel] = []
        seen: dict[str, ast.Assign | ast.LineBreak] = {}
        for setting in clause.settings:
            if isinstance(setting, ast.LineBreak):
                if m.BREAK in seen:
                    self.d.report("E203", setting.span, f"`break` is given twice in `{name.text}`",
                                  labels=(Label(seen[m.BREAK].span, "first given here"),))
                    continue
                seen[m.BREAK] = setting
                held = self.duration(setting.duration, "a break")
                if held is not None and not 0 < held <= MAX_BREAK_MS:
                    self.d.report("E211", setting.duration.span, f"a break is held from more than 0 to "
                                  f"{MAX_BREAK_MS} ms, not {shown(held)} ms",
                                  help="a serial break holds TX low for a few character times to a few "
                                  "hundred ms (pyserial's `send_break` holds it 250 ms)")
                elif held is not None:
                    levels.append(m.LineLevel(m.BREAK, m.Const(float(held), Type.FLOAT), setting.span))
                continue
            line = setting.target.text
            value = self.typer.expr(setting.value, env)
            if line not in m.MODEM_LINES:
                self.d.report("E211", setting.target.span, f"`{line}` is not a modem line a primitive sets",
                              help="a primitive sets `dtr` or `rts` (CTS, DSR, RI and CD are the device's)")
                continue
            if line in seen:
                self.d.report("E203", setting.target.span, f"`{line}` is given twice in `{name.text}`",
                              labels=(Label(seen[line].span, "first given here"),))
                continue
            seen[line] = setting
            if value.type is not None and value.type is not Type.BOOL:
                self.d.report("E401", setting.value.span, f"`{line}` takes a bool, but this is {describe(value.type)}")
            levels.append(m.LineLevel(line, value, setting.span))
        return tuple(levels)

    def expect(self, decl: ast.PrimitiveDecl, scope: Names, reply: tuple[m.AnyType, ...] | None,
               decodes: bool) -> m.Expr | None:
        """`expect COND`: a bool over the parameters, state and the decoded reply `out`
        (`reply`, its types: None when its template was reported)."""
        clause = self.once([c for c in decl.clauses if isinstance(c, ast.Expect)], "`expect`", decl.name)
        if not isinstance(clause, ast.Expect):
            return None
        note = None if decodes else f"primitive `{decl.name.text}` decodes no reply: add `unpack` or `regex`"
        env = self.env_with(scope, "in an `expect`", "`out`, parameters and state variables",
                            reply=reply if decodes else None, reply_note=note, reply_known=reply is not None)
        condition = self.typer.expr(clause.condition, env)
        if not decodes and not any(isinstance(c, ast.ReplyTable) for c in decl.clauses):  # a table: E203
            self.d.report("E202", clause.span, f"`expect` checks a decoded reply, but `{decl.name.text}` decodes none",
                          help="add `unpack` or `regex`")
        elif condition.type is not None and condition.type is not Type.BOOL:
            self.d.report("E401", clause.condition.span, f"`expect` takes a bool, but this is {describe(condition.type)}")
        return condition

    def not_a_param(self, decl: ast.PrimitiveDecl, local: str, what: str) -> None:
        """A name the post-actions read besides the parameters (a tagged reply's `tag`, a
        record's `index`): no parameter may have it."""
        for param in decl.params:
            if param.name.text == local:
                self.d.report("E104", param.name.span, f"`{local}` names {what} of `{decl.name.text}` "
                              "and cannot name a parameter of it", help="rename the parameter")

    def reply_table(self, clause: ast.ReplyTable, params: tuple[m.Parameter, ...], scope: Names,
                    name: ast.Ident, unframed: bool, nested: bool = False) -> m.ReplyTable | None:
        """`reply KEY { VALUE: unpack ... }`: one reply per value of an int parameter with a range,
        every value of the range with its entry. `reply tag "fmt" { ... }`: one per tag value; read
        without a frame, each entry's size fixed (the tag says how much follows it)."""
        key = clause.key.text
        tag_slot = None
        tag_layout: m.StructLayout | None = None
        length_layout: m.StructLayout | None = None  # `each`'s length field, if given
        param: m.Parameter | None
        if clause.tag is not None:
            try:
                tag_layout = formats.struct_layout(clause.tag.value)
            except formats.TemplateError as err:
                self.d.report("E301", clause.tag.span, err.message)
                return None
            if len(tag_layout.slots) != 1 or tag_layout.slots[0].type is not Type.INT:
                self.d.report("E505", clause.tag.span, "a reply tag is one integer: a struct format such as "
                              f"\"B\" or \">H\", not \"{abbreviate(clause.tag.value)}\"")
                return None
            tag_slot = tag_layout.slots[0]
            param = m.Parameter(key, Type.INT, tag_slot.low, tag_slot.high)
            if not self.sub_payloads(clause, name, unframed):
                return None
            if clause.each and clause.length is not None:
                length_layout = self.length_field(clause.length)
                if length_layout is None:
                    return None
        else:
            param = next((p for p in params if p.name == key), None)
        if param is None:
            self.d.report("E103", clause.key.span, f"`{key}` is not a parameter of `{name.text}`",
                          help=suggest(key, [p.name for p in params]) or "a reply table's key is a parameter")
            return None
        if param.type is not Type.INT:
            self.d.report("E401", clause.key.span, f"a reply table's key is an int parameter; `{key}` is not")
            return None
        cases: list[m.ReplyCase] = []
        seen: dict[int, ast.ReplyEntry] = {}
        if clause.tag is not None:  # its entries see the tag's value
            scope = {**scope, m.TAG: (Scope.PARAM, Type.INT)}
        sees = ("`out`, `tag`, " if clause.tag is not None else "`out`, ") + "parameters and state variables"
        for entry in clause.entries:
            bounds = self.entry_values(entry, tag_slot)
            if bounds is None:
                continue
            low, high = bounds
            if len(seen) + high - low >= MAX_TABLE:
                self.d.report("E505", entry.span, f"the reply table of `{name.text}` has entries for more than "
                              f"{MAX_TABLE} values", help="a reply table holds a few thousand values at most")
                continue
            twice = next((v for v in range(low, high + 1) if v in seen), None)
            if twice is not None:
                self.d.report("E203", _values_span(entry), f"{twice} has two entries in the reply table",
                              labels=(Label(_values_span(seen[twice]), "first given here"),))
                continue
            seen.update(dict.fromkeys(range(low, high + 1), entry))
            if entry.table is not None:
                cases.extend(self.nested_table(clause, entry, entry.table, low, params, scope, name, unframed, nested))
                continue
            assert entry.decoding is not None  # the grammar's: an entry decodes, or has a table
            decoding, reply = self.decoding(entry.decoding)
            if entry.until is not None:
                decoding = self.until(entry, decoding, name, clause.tag is not None and unframed)
            elif clause.each:
                self.sub_payload_entry(clause, entry, decoding, low, high, length_layout)
            elif clause.tag is not None and unframed:
                self.sized_entry(entry, decoding, name, low, high)
            actions: tuple[m.PostAction, ...] = ()
            if entry.actions is not None:
                action_env = self.env_with(scope, "in a post-action", sees, reply=reply, reply_known=reply is not None)
                actions = self.actions(entry.actions, action_env, {p.name for p in params})
            if decoding is not None:
                cases.append(m.ReplyCase(low, decoding, actions, None if entry.last is None else high))
        if clause.tag is not None:  # an unknown tag is a protocol error when it comes: no coverage to check
            return m.ReplyTable("", tuple(cases), clause.tag.value, clause.each,
                                None if clause.length is None else clause.length.value, tag_layout=tag_layout,
                                length_layout=length_layout)
        if param.low is None:
            self.d.report("E505", clause.key.span, f"`{key}` has no range, so the reply table of `{name.text}` "
                          "cannot have an entry for each of its values",
                          help=f"declare its range: `{key}: int in LOW..HIGH`")
        elif param.high - param.low >= MAX_TABLE:  # type: ignore[operator]
            self.d.report("E505", clause.key.span, f"the range of `{key}` has {param.high - param.low + 1} values, "  # type: ignore[operator]
                          f"more than a reply table holds ({MAX_TABLE})", label=f"in {param.range_text()}")
        else:
            missing = [v for v in range(int(param.low), int(param.high) + 1) if v not in seen]  # type: ignore[arg-type]
            if missing:
                shown_ = ", ".join(map(str, missing[:6])) + (f" and {len(missing) - 6} more" if len(missing) > 6 else "")
                self.d.report("E505", clause.key.span, f"the reply table of `{name.text}` has no entry for "
                              f"{key} = {shown_}", label=f"in {param.range_text()}",
                              help="give every value of the range its reply, or narrow the range")
        return m.ReplyTable(key, tuple(cases))

    def nested_table(self, clause: ast.ReplyTable, entry: ast.ReplyEntry, table: ast.ReplyTable, value: int,
                     params: tuple[m.Parameter, ...], scope: Names, name: ast.Ident, unframed: bool,
                     nested: bool) -> list[m.ReplyCase]:
        """`VALUE: tag "fmt" { ... }`: after the tag VALUE, the next tag chooses among the nested
        table's entries (Firmata's sysex: F0, then the sub-command). One level, of a tagged reply
        read without a frame, for one value; its entries checked as the table's own."""
        assert table.tag is not None  # the grammar's
        if clause.tag is None or not unframed or clause.each or nested or entry.last is not None:
            why = ("a nested table is for one tag value, not a range" if entry.last is not None
                   else "a nested table holds no nested table" if nested
                   else f"`{name.text}` reads no tagged reply without a frame")
            self.d.report("E505", table.tag.span, f"a nested tag table is an entry of a tagged reply read without a "
                          f"frame, one level deep: {why}",
                          help='e.g. `0xF0: tag "B" { 0x79: unpack "BB*" until "\\xF7" }`, Firmata\'s sysex')
            return []
        inner = self.reply_table(table, params, scope, name, unframed, nested=True)
        if inner is None:
            return []
        return [replace(c, under=value, under_tag=table.tag.value, under_layout=inner.tag_layout) for c in inner.cases]

    def sub_payloads(self, clause: ast.ReplyTable, name: ast.Ident, unframed: bool) -> bool:
        """`reply each tag "B" length "B"`: sub-payloads until the framed payload ends, each its
        length an unsigned integer after its tag. Whether the table can be read so."""
        if not clause.each:
            return True
        if unframed:
            self.d.report("E505", clause.span, f"the reply of `{name.text}` is a sequence of sub-payloads until its "
                          "payload ends, so it is read through a frame", help="give the primitive a frame whose reply "
                          "has a `length` field or constant bytes after its payload")
            return False
        return True

    def length_field(self, length: ast.StrLit) -> m.StructLayout | None:
        """The layout of a sub-payload's length field (`length "B"`): one unsigned integer."""
        try:
            layout = formats.struct_layout(length.value)
        except formats.TemplateError as err:
            self.d.report("E301", length.span, err.message)
            return None
        if len(layout.slots) != 1 or layout.slots[0].type is not Type.INT or (layout.slots[0].low or 0) < 0:
            self.d.report("E505", length.span, "a sub-payload's length is one unsigned integer: a struct "
                          f"format such as \"B\" or \"<H\", not \"{abbreviate(length.value)}\"")
            return None
        return layout

    def sub_payload_entry(self, clause: ast.ReplyTable, entry: ast.ReplyEntry, decoding: m.Unpack | m.Regex | None,
                          low: int, high: int, length: m.StructLayout | None) -> None:
        """An entry of sub-payloads decodes its bytes with an `unpack`: of a fixed size without a
        length field (the size says where the next tag starts), one the length field can state."""
        which = f"tag {low}" if low == high else f"tags {low}..{high}"
        if isinstance(decoding, m.Regex):
            self.d.report("E505", _decoding_span(entry), f"the sub-payload of {which} is bytes: decode it with `unpack`")
            return
        if not isinstance(decoding, m.Unpack):
            return
        open_end = _open_end(decoding)
        if clause.length is None and open_end:
            self.d.report("E505", _decoding_span(entry), f"the sub-payloads have no length field, so the entry for "
                          f"{which} needs a fixed size, but it {open_end}",
                          help='give each sub-payload its length: `reply each tag "B" length "B" { ... }`')
        elif clause.length is not None and length is not None and not open_end:
            size = decoding.layout.size
            most = length.slots[0].high or 0
            if size > most:
                self.d.report("E505", _decoding_span(entry), f"the entry for {which} decodes {size} bytes, more than "
                              f"a sub-payload's length field \"{clause.length.value}\" states ({most})")

    def sized_entry(self, entry: ast.ReplyEntry, decoding: m.Unpack | m.Regex | None, name: ast.Ident,
                    low: int, high: int) -> None:
        """A tagged reply read without a frame: the entry's decoding says how many bytes follow the tag."""
        if isinstance(decoding, m.Regex):
            why = "it is a `regex`"
        elif isinstance(decoding, m.Unpack) and (open_end := _open_end(decoding)):
            why = f"it {open_end}"
        else:
            return
        which = f"tag {low}" if low == high else f"tags {low}..{high}"
        self.d.report("E505", _decoding_span(entry), f"`{name.text}` reads its reply without a frame, so its entry for "
                      f"{which} needs a fixed size, but {why}",
                      help="decode it with an `unpack` of a fixed size, or read the reply through a frame that says "
                      "where it ends")

    def until(self, entry: ast.ReplyEntry, decoding: m.Unpack | m.Regex | None, name: ast.Ident,
              unframed_tag: bool) -> m.Unpack | None:
        """`until "\\xF7"`: an unframed tagged reply's entry read to its end marker (Firmata's sysex),
        the marker dropped and what is before it decoded by an `unpack` ending in `*`."""
        until = entry.until
        assert until is not None
        if not unframed_tag:
            self.d.report("E505", until.span, f"`until` is for a tagged reply read without a frame, and `{name.text}`"
                          " does not read one", help="a frame, or a reply table's key, already says where it ends")
            return None
        if not 1 <= len(until.value) <= MAX_TERMINATOR or any(ord(ch) > 0xFF for ch in until.value):
            self.d.report("E505", until.span, f"`until` is 1 to {MAX_TERMINATOR} bytes (characters up to \\xff)")
            return None
        if not isinstance(decoding, m.Unpack):
            if decoding is not None:
                self.d.report("E505", _decoding_span(entry), "an entry read `until` its end is decoded by an `unpack`")
            return None
        layout = decoding.layout
        if not layout.rest or layout.varying is not None:
            self.d.report("E505", _decoding_span(entry), "an entry read `until` its end takes what comes before the "
                          "end as bytes: its `unpack` ends in `*`",
                          help='e.g. `0xF0: unpack "B*" until "\\xF7"`, the bytes of a Firmata sysex message')
            return None
        return m.Unpack(decoding.format, layout, until.value)

    def entry_values(self, entry: ast.ReplyEntry, tag_slot: formats.Slot | None) -> tuple[int, int] | None:
        """The first and last value a reply table's entry is for (`VALUE`, or `LOW..HIGH`),
        each an int constant that fits the tag's code; None when reported."""
        ends: list[int] = []
        for expr in (entry.value,) if entry.last is None else (entry.value, entry.last):
            value = self.setting(expr, "a reply table's value")
            if value is None:
                return None
            if value != int(value):
                self.d.report("E204", expr.span, "a reply table's value is an int")
                return None
            if tag_slot is not None and not tag_slot.low <= value <= tag_slot.high:  # type: ignore[operator]
                self.d.report("E403", expr.span, f"{int(value)} does not fit the tag's `{tag_slot.code}`")
                return None
            ends.append(int(value))
        if ends[-1] < ends[0]:
            self.d.report("E204", _values_span(entry), f"the range {ends[0]}..{ends[-1]} is empty")
            return None
        return ends[0], ends[-1]

    def request_sizes(self, encoding: m.Pack | m.Format | None, args: tuple[m.Expr, ...],
                      params: tuple[m.Parameter, ...]) -> tuple[int, int, str] | None:
        """The fewest and most bytes a packed request can have, and what decides them: a
        `*` rest of constant bytes or of a `bytes` parameter with a range (None otherwise)."""
        if not isinstance(encoding, m.Pack):
            return None
        layout = encoding.layout
        if layout.varying is not None:
            rounds = formats.most_rounds(layout, [args[i].type for i in formats.varying_args(layout, encoding.grouped)])
            return layout.size, layout.most(rounds), f"a repeated group of up to {rounds} rounds"
        if not layout.rest:
            return layout.size, layout.size, ""
        rest = args[-1] if args else None
        value = self.typer.constant(rest) if rest is not None else None
        if isinstance(value, bytes):
            return layout.size + len(value), layout.size + len(value), ""
        if isinstance(rest, m.Var) and rest.scope is Scope.PARAM:
            param = next(p for p in params if p.name == rest.name)
            if param.low is not None and param.high is not None:
                return layout.size + int(param.low), layout.size + int(param.high), f"parameter `{param.name}`"
        return None

    def frame_use(self, clause: ast.Framed, env: Env, decl: ast.PrimitiveDecl, encoding: m.Pack | m.Format | None,
                  replies: Sequence[m.Unpack | m.Regex], request: tuple[int, int, str] | None) -> m.FrameUse | None:
        """`frame NAME(args)`: its arguments, and whether the frame can carry this primitive."""
        frame = self.frames.get(clause.frame.text)
        target = self.s.frames.get(clause.frame.text)
        args = self.call(ast.Call(clause.frame, clause.args, clause.span), frame.params if frame else None, env,
                         "frame", target.name if target else None)
        if frame is None:
            return None
        self.frame_fields_fit(frame, clause, args)
        has_payload = any(isinstance(p, m.FramePayload) for p in frame.reply)
        if replies and frame.reply and not has_payload:
            self.d.report("E504", clause.span, f"primitive `{decl.name.text}` decodes a reply, but the reply of "
                          f"frame `{frame.name}` has no `payload`")
        reply_sizes = []
        for decoding in replies:
            layout = decoding.layout if isinstance(decoding, m.Unpack) else None
            reply_sizes.append(layout.size if layout is not None and not layout.open_end else None)
        if any(not payload_end_known(frame, size is not None) for size in reply_sizes):
            self.d.report("E503", clause.span, f"the reply of frame `{frame.name}` gives no way to find where the "
                          f"payload of `{decl.name.text}` ends",
                          help="add a `length` field, constant bytes after the payload, or decode with `unpack`")
        sizes = [(frame.requests, request, bool(frame.request_when)),
                 *((frame.replies, None if n is None else (n, n, ""), False) for n in reply_sizes)]
        for layouts, payload, chosen in sizes:
            found = [length_part(parts) for parts in layouts]
            if chosen:  # `either when`: any layout with a length field may be the one written
                found = [length for length in found if length is not None]
            if not found or None in found or payload is None:  # a layout without a length field carries any payload
                continue
            lengths = [length for length in found if length is not None]
            ranges = [length_range(length) for length in lengths]
            low, high = min(r[0] for r in ranges), max(r[1] for r in ranges)  # the writer takes the first that fits
            if chosen:
                low, high = max(r[0] for r in ranges), min(r[1] for r in ranges)
            fewest, most, by = payload
            if low <= fewest and most <= high:
                continue
            field = (f"the length field {length_words(lengths[0])}" if len(lengths) == 1 else
                     "the length fields " + ", ".join(length_words(length) for length in lengths))
            states = f"{'it states' if len(lengths) == 1 else 'they state'} payloads of {low} to {high} bytes"
            if not by:
                self.d.report("E503", clause.span, f"{field} of frame `{frame.name}` "
                              f"cannot state the {fewest}-byte payload of `{decl.name.text}`", help=states)
            else:
                self.d.report("E503", clause.span, f"{field} of frame `{frame.name}` "
                              f"cannot state every payload of `{decl.name.text}`: {fewest} to {most} bytes, as "
                              f"{by} allows", help=f"{states}; " + (f"narrow the range of {by}" if "parameter" in by else
                                                                   "give the group's arrays a fixed size, or fewer"))
        return m.FrameUse(m.FrameRef(frame.name), args)

    def frame_fields_fit(self, frame: m.Frame, clause: ast.Framed, args: tuple[m.Expr, ...]) -> None:
        """Each field of a frame over its parameters, computed from the constant arguments of
        this use (those in their ranges: one outside is reported already), must fit its code."""
        known: dict[str, object] = {}
        for param, arg in zip(frame.params, args):
            value = self.typer.constant(arg)
            if arg.type is not param.type or value is None:  # a mismatch is reported already
                continue
            if param.low is None or param.low <= value <= param.high:  # type: ignore[operator]
                known[param.name] = value
        spans = {p.name: expr.span for p, expr in zip(frame.params, clause.args)}
        seen: set[tuple[str, m.Expr]] = set()
        parts = [part for layout in (*frame.requests, *frame.replies) for part in layout]
        for part in [*parts, *(bit for bits in parts if isinstance(bits, m.FrameBits) for bit in bits.fields)]:
            if (not isinstance(part, (m.FrameField, m.BitField)) or part.value is None
                    or (part.name, part.value) in seen
                    or self.typer.is_constant(part.value)):  # a constant field is checked with its frame
                continue
            seen.add((part.name, part.value))
            computed = self.typer.value_over(part.value, known)
            direct = isinstance(part.value, m.Var) and part.value.name in spans
            span = spans[part.value.name] if isinstance(part.value, m.Var) and direct else clause.span
            where = f" of frame `{frame.name}`" if direct else f" as field `{part.name}` of frame `{frame.name}`"
            if isinstance(part, m.BitField):
                if isinstance(computed, int) and not isinstance(computed, bool) and not 0 <= computed < 1 << part.width:
                    self.d.report("E403", span, f"{computed} does not fit the {part.width} bits of field "
                                  f"`{part.name}`{where}", label=f"field `{part.name}` is {part.width} bits, "
                                  f"0 to {(1 << part.width) - 1}")
                continue
            if not part.layout.slots:  # refused: the frame's own check reported it
                continue
            slot = part.layout.slots[0]
            self.fits(computed, slot, span, where,
                      f"field `{part.name}` is packed as `{slot.code}`, {slot.low} to {slot.high}")

    def template_span(self, lit: ast.StrLit, offset: int, length: int) -> Span:
        """The span of characters inside a template, exact when the literal has no escapes."""
        s = lit.span
        prefix = s.end - s.start - len(lit.value) - 1  # 1 for `"`, 2 for `r"`
        if prefix in (1, 2):
            start = s.start + prefix + offset
            return Span(s.path, start, min(start + max(length, 1), s.end - 1))
        return s

    def encoding(self, enc: ast.Encoding, env: Env) -> tuple[m.Pack | m.Format | None, tuple[m.Expr, ...]]:
        args = tuple(self.typer.expr(a, env) for a in enc.args)
        template = enc.template.value
        try:
            layout = None
            if enc.kind == "pack":
                layout = formats.struct_layout(template)
                slots: tuple[formats.Slot | formats.FormatField, ...] = layout.slots
                if layout.native:
                    self.native_warning(enc.template)
            else:
                slots = formats.format_fields(template)
        except formats.TemplateError as err:
            code = "E301" if enc.kind == "pack" else "E303"
            self.d.report(code, self.template_span(enc.template, err.offset, err.length), err.message)
            return None, args
        arrays = [(arg, expr) for arg, expr in zip(args, enc.args) if isinstance(arg.type, m.Array)]
        if arrays and enc.kind == "format":
            array, written = arrays[0]
            self.d.report("E401", written.span, f"a format field cannot format {describe(array.type)}",
                          help="format its elements: `position[0]`")
            return None, args
        values: list[m.Expr] = []  # one a slot: an array spread into its elements, except into a group
        exprs: list[ast.Expr] = []
        grouped: list[int] = []
        for i, (arg, expr) in enumerate(zip(args, enc.args)):
            slot = slots[len(values)] if len(values) < len(slots) else None
            if isinstance(slot, formats.Slot) and slot.repeat:
                grouped.append(i)
                values.append(arg)
                exprs.append(expr)
                continue
            spread = m.spread((arg,))
            values.extend(spread)
            exprs.extend([expr] * len(spread))
        if len(slots) != len(values):
            given = _count(len(args), "argument") + (f" giving {_count(len(values), 'value')}" if arrays else " given")
            self.d.report(
                "E302", enc.span,
                f"`{enc.kind} \"{abbreviate(template)}\"` takes {_count(len(slots), 'value')}, but {given}",
                help="an array gives each of its elements" if arrays else None,
            )
            return None, args
        for arg, expr, slot in zip(values, exprs, slots):
            if isinstance(slot, formats.FormatField):  # `format`: every slot is one; `pack`: none is
                self.format_value(arg, expr, slot)
            elif slot.repeat:
                self.group_value(arg, expr, slot)
            else:
                self.pack_value(self.typer.folded(arg), expr, slot)
        if layout is not None and layout.width >= 0:
            self.widths_fit(layout, values, exprs)
        if layout is not None and layout.varying is not None:
            self.rounds_fit(layout, [(args[i], enc.args[i]) for i in formats.varying_args(layout, tuple(grouped))])
        if layout is not None:
            return m.Pack(template, layout, tuple(grouped)), args
        return m.Format(template), args

    def widths_fit(self, layout: formats.StructLayout, values: list[m.Expr], exprs: list[ast.Expr]) -> None:
        """A constant given to a `%` code fits the bytes a constant width field states (the run
        refuses one that does not, where either is known only then)."""
        width = self.typer.constant(values[layout.width])
        if not isinstance(width, int) or isinstance(width, bool) or not 1 <= width <= formats.MOST_WIDTH:
            return
        sized = replace(layout.slots[layout.width], code="%", low=0, high=(1 << 8 * width) - 1)
        for value, expr, slot in zip(values, exprs, layout.slots):
            constant = self.typer.constant(value) if slot.code == "%" else None
            for item in constant if isinstance(constant, tuple) else ():
                self.fits(item, sized, expr.span, "", f"the width field `{layout.slots[layout.width].code}` states "
                          f"{width} bytes: 0 to {sized.high}")

    def rounds_fit(self, layout: formats.StructLayout, arrays: list[tuple[m.Expr, ast.Expr]]) -> None:
        """The arrays of a group repeated as the message says: of one size where their sizes are
        fixed, and no more than its count field holds."""
        assert layout.varying is not None
        sized = [(t.size, expr) for arg, expr in arrays if isinstance(t := arg.type, m.Array) and t.size]
        if any(size != sized[0][0] for size, _ in sized):
            size, expr = next((size, expr) for size, expr in sized if size != sized[0][0])
            self.d.report("E403", expr.span, f"the arrays of a repeated group have one size, but this one has {size} "
                          f"values and the first {sized[0][0]}", labels=(Label(sized[0][1].span, "the first"),))
        high = layout.varying.count_high
        if high and sized and max(size for size, _ in sized) > high:
            size, expr = max(sized, key=lambda item: item[0])
            self.d.report("E403", expr.span, f"the count field `#{layout.varying.count_code}` holds at most {high}, but this array "
                          f"has {size} values", help="count the group with a wider field: `#H`")

    def native_warning(self, lit: ast.StrLit) -> None:
        self.d.report(
            "W301", lit.span, f"struct format \"{abbreviate(lit.value)}\" has no byte order",
            label="host byte order and alignment", help=f"write \">{lit.value.lstrip('@')}\" (big-endian) or "
            f"\"<{lit.value.lstrip('@')}\" (little-endian), as the device expects",
        )

    def group_value(self, arg: m.Expr, expr: ast.Expr, slot: formats.Slot) -> None:
        """A repeated group's code takes an array of the group's count (of any size when the
        message says it), each element as the code takes a value."""
        code = f"`{slot.code}` of a group of {slot.repeat}" if slot.repeat > 0 else f"`{slot.code}` of a repeated group"
        self.flow(arg, m.Array(slot.type, max(slot.repeat, 0)), expr.span, f"pack code {code}")
        value = self.typer.constant(arg)
        if isinstance(value, tuple) and slot.low is not None:
            for item in value:
                self.fits(item, slot, expr.span, "", f"{code} holds {slot.low} to {slot.high}")

    def pack_value(self, arg: m.Expr, expr: ast.Expr, slot: formats.Slot) -> None:
        self.flow(arg, slot.type, expr.span, f"pack code {slot.shown}")
        value = self.typer.constant(arg)
        if arg.type is Type.INT:
            self.fits(value, slot, expr.span, "", f"{slot.shown} holds {slot.low} to {slot.high}")
        if slot.code == "c" and isinstance(value, str) and len(value) != 1:
            self.d.report("E403", expr.span, "pack code `c` takes a string of exactly one character")
        elif slot.code[-1:] in ("s", "p", "Z") and isinstance(value, str):
            room = formats.text_room(slot.code)
            if len(value) > room:
                self.d.report("E403", expr.span, f"{shown(value)} is {len(value)} characters; `{slot.code}` holds "
                              f"{room}, and struct would cut the rest")
        elif slot.code in FLOAT_LIMITS and isinstance(value, (int, float)) and not isinstance(value, bool) \
                and math.isfinite(value) and abs(value) > FLOAT_LIMITS[slot.code]:
            self.d.report("E403", expr.span, f"{shown(value)} is too large for pack code `{slot.code}` "
                          f"(at most {FLOAT_LIMITS[slot.code]:g})")

    def format_value(self, arg: m.Expr, expr: ast.Expr, field: formats.FormatField) -> None:
        if arg.type is None or formats.spec_accepts(field.spec, arg.type):
            return
        written = f"{{:{field.spec}}}" if field.spec else "{}"
        if arg.type is Type.FLOAT and formats.spec_accepts(field.spec, Type.INT):
            self.d.report(
                "E402", expr.span, f"format field `{written}` takes an int, but this is a float",
                help="convert it: `round(...)` to the nearest integer, `int(...)` towards zero",
            )
        else:
            self.d.report("E401", expr.span, f"format field `{written}` cannot format {describe(arg.type)}",
                          help="write bytes as text with `ascii(...)` or `hex(...)`" if arg.type is Type.BYTES
                          else None)

    def decoding(self, dec: ast.Decoding) -> tuple[m.Unpack | m.Regex | None, tuple[m.AnyType, ...] | None]:
        """The decoding and the types of its values; None for a template already reported."""
        template = dec.template.value
        try:
            if dec.kind == "unpack":
                layout = formats.struct_layout(template)
                if layout.width >= 0:
                    raise formats.TemplateError("a width field `%H` and its `%` codes are for requests (`pack`): "
                                                "a reply's are read as `*` bytes", template.index("%"))
                if layout.native:
                    self.native_warning(dec.template)
                types = tuple(m.Array(s.type, max(s.repeat, 0)) if s.repeat else s.type for s in layout.slots)
                return m.Unpack(template, layout), types
            groups = formats.regex_groups(template)
            return m.Regex(template), (Type.STRING,) * groups
        except formats.TemplateError as err:
            code = "E301" if dec.kind == "unpack" else "E304"
            self.d.report(code, self.template_span(dec.template, err.offset, err.length), err.message)
            return None, None

    def actions(self, block: ast.Actions, env: Env, params: set[str]) -> tuple[m.PostAction, ...]:
        """Post-actions; the elements stored into one array (`position[id] = out[0]`) are one
        action, the array with each element replaced in turn."""
        out: list[m.PostAction] = []
        written: dict[str, ast.Assign] = {}
        for assign in block.assigns:
            value = self.typer.expr(assign.value, env)
            target = assign.target.text
            when = None
            if assign.when is not None:  # made only if it holds: the state variable is read to keep it
                when = self.typer.expr(assign.when, env)
                if when.type is not None and when.type is not Type.BOOL:
                    self.d.report("E401", assign.when.span, f"`when` takes a bool, but this is {describe(when.type)}")
                self.typer.reads.add(target)
            state = self.s.states.get(target)
            if state is None and target in self.settings:
                self.d.report("E207", assign.target.span, f"cannot assign `{target}`: it is a setting, given when "
                              "connecting", help="a setting is read-only: keep what the device reports in a "
                              "state variable")
                continue
            if state is None:
                what = "it is a parameter" if target in params else "it is not a state variable"
                self.d.report(
                    "E207", assign.target.span, f"cannot assign `{target}`: {what}",
                    help=suggest(target, self.s.states) or "post-actions write state variables, and only they do",
                )
                continue
            declared = self.state_env.get(target, (None, None))[1]
            first = written.get(target)
            if first is not None and (assign.index is None or first.index is None):
                self.d.report("E203", assign.target.span, f"state variable `{target}` is assigned twice",
                              labels=(Label(first.target.span, "first assigned here"),))
            if assign.index is None:
                written[target] = assign
                if isinstance(declared, m.Array) and declared.size and isinstance(value.type, m.Array) \
                        and not value.type.size:  # nothing would check its size when it runs
                    self.d.report("E401", assign.value.span, f"state variable `{target}` holds {describe(declared)}, "
                                  "but this array has any size", help=f"declare it `{declared.element.value}[]`")
                    continue
                self.flow(value, declared, assign.value.span, f"state variable `{target}`")
                out.append(m.PostAction(m.StateRef(target), value, assign.span, when))
                continue
            if not isinstance(declared, m.Array):
                if declared is not None:
                    self.d.report("E404", assign.index.span, f"`{target}` is not an array: it is {describe(declared)}")
                continue
            index = self.typer.expr(assign.index, env)
            if index.type is not None and index.type is not Type.INT:
                self.d.report("E404", assign.index.span, f"an index is an int, not {describe(index.type)}")
            self.typer.in_array(declared, index, target, assign.index.span)
            self.flow(value, declared.element, assign.value.span, f"an element of `{target}`")
            self.typer.reads.add(target)
            if first is not None and first.index is not None:  # replace one more element of the same array
                before = next(k for k, a in enumerate(out) if a.target == target)
                out[before] = m.PostAction(m.StateRef(target), m.Replaced(out[before].value, index, value, declared,
                                                                          assign.span, when), out[before].span)
            else:
                written[target] = assign
                whole = m.Var(target, Scope.STATE, declared, assign.target.span)
                out.append(m.PostAction(m.StateRef(target), m.Replaced(whole, index, value, declared, assign.span,
                                                                       when), assign.span))
        return tuple(out)

    def interface(self, decl: ast.InterfaceDecl, interface_params: dict[str, tuple[m.Parameter, ...]],
                  primitives: dict[str, m.Primitive]) -> m.Interface:
        name = decl.name
        params = interface_params[name.text]
        kind = self.once([c for c in decl.clauses if isinstance(c, ast.Kind)], "the kind (`periodic`/`adhoc`)", name)
        periodic = isinstance(kind, ast.Kind) and kind.word == "periodic"
        triggers = self.once([c for c in decl.clauses if isinstance(c, ast.Triggers)], "`triggers`", name)
        if periodic and decl.params:
            self.d.report(
                "E205", decl.params[0].span.to(decl.params[-1].span),
                f"periodic interface `{name.text}` cannot take parameters",
                help="nobody passes arguments on a tick: read state variables instead, or make it `adhoc`",
            )
        scope = {p.name: (Scope.PARAM, p.type) for p in params}  # one of a type in error: known, of type None
        env = self.env_with(scope, "in an interface", "its parameters and state variables")
        calls: list[m.PrimitiveCall] = []
        self.body(decl.body, _Unrolling(decl, env, interface_params, primitives, calls), {})
        if periodic:
            self.periodic_connection(decl)
        outputs: dict[str, ast.Ident] = {}
        for output in triggers.outputs if isinstance(triggers, ast.Triggers) else ():
            if output.text in outputs:
                self.d.report("E203", output.span, f"`{output.text}` is triggered twice",
                              labels=(Label(outputs[output.text].span, "first given here"),))
            outputs.setdefault(output.text, output)
        out_ref = tuple(m.OutputRef(o) for o in outputs)
        return m.Interface(name.text, params, periodic, tuple(calls), out_ref, decl.doc, decl.span)

    def body(self, stmts: tuple[ast.BodyStmt, ...], u: _Unrolling, loops: dict[str, ast.Ident]) -> None:
        """An interface's statements as plain calls: each loop written out, its variable a constant
        in each round, so the Model, the budget and every emitter see only calls. A round that
        reports an error ends its loop: the next rounds would repeat the fault."""
        for stmt in stmts:
            if isinstance(stmt, ast.CallStmt):
                call = self.call_stmt(stmt, u.env, u.interface_params, u.primitives)
                if loops:  # `IDS[i] + 1` of this round is known: the call says its value
                    call = replace(call, args=tuple(self.value_of(a) for a in call.args),
                                   when=None if call.when is None else self.value_of(call.when),
                                   until=None if call.until is None else self.value_of(call.until))
                u.calls.append(call)
                self.written += 1
                continue
            found = self.loop_values(stmt, u, loops)
            if found is None:
                continue
            type_, values = found
            name = stmt.var.text  # no constant has it (loop_variable): bound as one, then gone
            for value in values:
                self.typer.named[name] = (type_, value)
                errors = self.d.error_count
                self.body(stmt.body, u, {**loops, name: stmt.var})
                if self.d.error_count > errors:
                    break
            del self.typer.named[name]

    def value_of(self, expr: m.Expr) -> m.Expr:
        """A constant expression as its value; any other as it is."""
        value = self.typer.constant(expr)
        if value is None or expr.type is None:  # not constant (a constant's value is never None)
            return expr
        return self.typer.const(value, expr.type, expr.span)

    def loop_values(self, stmt: ast.ForStmt, u: _Unrolling,
                    loops: dict[str, ast.Ident]) -> tuple[Type, Sequence[m.Value]] | None:
        """The values a loop's variable takes, or None when the loop is in error (reported)."""
        head = Span(stmt.span.path, stmt.span.start, (stmt.high or stmt.low).span.end)  # `for i in 0..5`
        if not self.loop_variable(stmt.var, u.decl.params, loops):
            return None
        if not stmt.body:
            self.d.report("E212", head, "a loop without calls", help="write the calls it makes in its `{ }`")
            return None
        found = self.constant_values(stmt.low, stmt.high, u.env)
        if found is None:
            return None
        type_, values = found
        # Each round makes a call or more, so these bound the work before any is done.
        rounds = len(values)
        too_many = f"interface `{u.decl.name.text}` unrolls into more than {MAX_UNROLLED} calls" \
            if len(u.calls) + rounds > MAX_UNROLLED else \
            f"the description's interfaces unroll into more than {MAX_UNROLLED_ALL} calls" \
            if self.written + rounds > MAX_UNROLLED_ALL else None
        if too_many is not None:
            self.d.report("E212", head, too_many, help="every round of a loop makes its calls: loop over fewer values")
            return None
        return type_, values

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

    def call_stmt(self, stmt: ast.CallStmt, env: Env, interface_params: dict[str, tuple[m.Parameter, ...]],
                  primitives: dict[str, m.Primitive]) -> m.PrimitiveCall:
        """One call as the Model has it (in a loop, with the loop variables of this round)."""
        callee = stmt.call.target.text
        calls_interface = callee not in self.s.primitives and callee in self.s.interfaces
        if calls_interface:
            args = self.call(stmt.call, interface_params[callee], env, "interface",
                             self.s.interfaces[callee].name)
        else:
            target = self.s.primitives.get(callee)
            prim = primitives.get(callee)
            args = self.call(stmt.call, prim.params if prim else None, env, "primitive",
                             target.name if target else None)
            if prim is not None:
                self.constants_into_pack(prim, args, stmt.call.args)
        delay_clause = self.once(list(stmt.delays), "`delay`", stmt.call.target)
        delay = self.duration(delay_clause, "a delay") if isinstance(delay_clause, ast.Duration) else 0
        if delay_clause is not None and delay is not None and delay < 0:
            self.d.report("E204", delay_clause.span, f"a delay must be zero or more, not {delay:g} ms")
        priority_expr = self.once(list(stmt.priorities), "`priority`", stmt.call.target)
        priority = self.setting(priority_expr, "a priority", MAX_PRIORITY) if priority_expr is not None else 0
        if priority_expr is not None and priority is not None and priority != int(priority):
            self.d.report("E204", priority_expr.span, "a priority must be an integer")
        self.once(list(stmt.conditions), "`when`", stmt.call.target)
        when = self.typer.expr(stmt.conditions[0], env) if stmt.conditions else None
        if when is not None and when.type is not None and when.type is not Type.BOOL:
            self.d.report("E401", stmt.conditions[0].span, f"`when` takes a bool, but this is {describe(when.type)}")
        until, every, within = self.poll(stmt, env)
        return m.PrimitiveCall(
            m.PrimitiveRef(callee), args, delay or 0, int(priority or 0), stmt.span, calls_interface, when,
            until, every, within,
        )

    def poll(self, stmt: ast.CallStmt, env: Env) -> tuple[m.Expr | None, float, float]:
        """`until COND every P within T`: COND a bool over state and the interface's parameters,
        0 < P <= T, at most MAX_POLLS calls. (None, 0, 0) without one, or where it is refused."""
        clause = self.once(list(stmt.polls), "`until`", stmt.call.target)
        if not isinstance(clause, ast.Poll):
            return None, 0, 0
        until = self.typer.expr(clause.condition, env)
        if until.type is not None and until.type is not Type.BOOL:
            self.d.report("E401", clause.condition.span, f"`until` takes a bool, but this is {describe(until.type)}")
            return None, 0, 0
        every = self.duration(clause.every, "a poll's interval")
        within = self.duration(clause.within, "a poll's limit")
        if until.type is None or every is None or within is None:
            return None, 0, 0
        if not 0 < every <= within:
            self.d.report("E204", clause.span, f"a poll's interval must be positive and at most its limit, not "
                          f"every {every:g} ms within {within:g} ms",
                          help="`until COND every 10 ms within 2 s` calls again every 10 ms, for at most 2 s")
            return None, 0, 0
        if within / every >= MAX_POLLS:
            self.d.report("E204", clause.span, f"a poll makes at most {MAX_POLLS} calls, not "
                          f"{int(within / every) + 1} (every {every:g} ms within {within:g} ms)",
                          help="poll less often")
            return None, 0, 0
        return until, every, within

    def constants_into_pack(self, prim: m.Primitive, args: tuple[m.Expr, ...], exprs: tuple[ast.Expr, ...]) -> None:
        """A constant argument whose parameter goes straight into a pack code must fit it."""
        if not isinstance(prim.encoding, m.Pack) or len(args) != len(prim.params):
            return
        slots = prim.encoding.layout.slots
        for slot, packed in zip(slots, prim.format_values()):
            if not isinstance(packed, m.Var) or packed.scope is not Scope.PARAM or slot.low is None:
                continue
            i = next(i for i, p in enumerate(prim.params) if p.name == packed.name)
            if i >= len(exprs):  # its default, checked where it is declared
                continue
            self.fits(
                self.typer.constant(args[i]), slot, exprs[i].span, f" of primitive `{prim.name}`",
                f"parameter `{packed.name}` is packed as {slot.shown}, {slot.low} to {slot.high}",
            )

    def fits(self, value: object, slot: formats.Slot, span: Span, where: str, label: str) -> None:
        """A constant integer must fit the range of the pack code it is written with."""
        if slot.low is None or not isinstance(value, int) or isinstance(value, bool):
            return
        if not slot.low <= value <= slot.high:  # type: ignore[operator]
            self.d.report("E403", span, f"{shown(value)} does not fit pack code {slot.shown}{where}", label=label)

    def interface_cycles(self, interfaces: dict[str, m.Interface]) -> None:
        """Calls between interfaces form no cycle, so every call ends and its cost is known:
        each cycle is reported once, at the call that closes it in the interface first declared."""
        done: set[str] = set()

        def visit(name: str, path: list[tuple[str, m.PrimitiveCall]]) -> None:
            if name in done:
                return
            for call in interfaces[name].calls:
                if not call.interface or call.primitive not in interfaces:
                    continue
                on_path = [n for n, _ in path] + [name]
                if call.primitive in on_path:
                    ring = on_path[on_path.index(call.primitive):]
                    through = " -> ".join(f"`{n}`" for n in [*ring, call.primitive])
                    self.d.report("E210", call.span, f"interface `{name}` calls `{call.primitive}`, which leads "
                                  f"back to it: {through}",
                                  help="calls between interfaces must end: break the cycle")
                    continue
                visit(call.primitive, [*path, (name, call)])
            done.add(name)

        for name in interfaces:
            visit(name, [])

    def periodic_connection(self, decl: ast.InterfaceDecl) -> None:
        used: dict[str, ast.Ident] = {}
        for stmt, prim in self.primitives_called(decl, set()):
            on = next((c for c in prim.clauses if isinstance(c, ast.On)), None)
            if on is not None:
                used.setdefault(on.connection.text, stmt.call.target)
        if len(used) > 1:
            first, second = list(used.items())[:2]
            self.d.report(
                "E208", decl.name.span, f"periodic interface `{decl.name.text}` uses two connections",
                labels=(Label(first[1].span, f"on `{first[0]}`"), Label(second[1].span, f"on `{second[0]}`")),
                help="split it into one periodic interface per connection",
            )
        elif not used and len(self.s.connections) > 1 and not decl.body:
            self.d.report("E208", decl.name.span,
                          f"periodic interface `{decl.name.text}` calls no primitive, so its connection is unknown")

    def primitives_called(self, decl: ast.InterfaceDecl,
                          seen: set[str]) -> Iterator[tuple[ast.CallStmt, ast.PrimitiveDecl]]:
        """The primitive declarations an interface calls, through the interfaces it calls (each
        once: a cycle is reported on its own), with the statement in `decl` that leads there."""
        seen.add(decl.name.text)
        for stmt in ast.call_stmts(decl.body):
            callee = stmt.call.target.text
            prim = self.s.primitives.get(callee)
            if prim is not None:
                yield stmt, prim
            elif callee in self.s.interfaces and callee not in seen:
                yield from ((stmt, p) for _, p in self.primitives_called(self.s.interfaces[callee], seen))

    def input(self, decl: ast.InputDecl, adapters: dict[str, m.Adapter],
              interface_params: dict[str, tuple[m.Parameter, ...]]) -> m.DomainInput:
        adapter = adapters.get(decl.adapter.text)
        if adapter is None:  # unknown adapter, already reported: do not report its fields as unknown
            return m.DomainInput(decl.name.text, m.AdapterRef(decl.adapter.text), m.InterfaceRef(decl.call.target.text),
                                 (), decl.doc, decl.span)
        scope = {f.name: (Scope.FIELD, f.type) for f in adapter.fields}
        env = self.env_with(scope, "in an input", f"the fields of `{adapter.name}` and state variables")
        self.hidden_state(decl, adapter, scope)
        target = self.s.interfaces.get(decl.call.target.text)
        args = self.call(decl.call, interface_params.get(decl.call.target.text), env, "interface",
                         target.name if target else None)
        return m.DomainInput(decl.name.text, m.AdapterRef(adapter.name), m.InterfaceRef(decl.call.target.text),
                             args, decl.doc, decl.span)

    def hidden_state(self, decl: ast.InputDecl, adapter: m.Adapter, fields: Names) -> None:
        """W104 where an input reads a name that is both a field of its adapter and a state
        variable (or setting): the field hides it, once a name. Not for a standard adapter, whose
        fields are a message's (JointState's `position`), read by design beside state so named."""
        declared = self.s.adapters.get(adapter.name)
        if declared is None or id(declared) in self.s.standard:
            return
        seen: set[str] = set()
        for ref in _refs(decl.call.args):
            if ref.name not in fields or ref.name in seen:
                continue
            hidden = self.s.states.get(ref.name) or self.s.settings.get(ref.name)
            if hidden is None:
                continue
            seen.add(ref.name)
            kind = "state variable" if isinstance(hidden, ast.StateDecl) else "setting"
            self.d.report("W104", ref.span, f"`{ref.name}` here is the field of adapter `{adapter.name}`, "
                          f"which hides {kind} `{ref.name}`",
                          labels=(Label(hidden.name.span, f"{kind} `{ref.name}`, not read by input "
                                        f"`{decl.name.text}`"),),
                          help=f"rename the {kind} to read it in this input, or the field")

    def output(self, decl: ast.OutputDecl, adapters: dict[str, m.Adapter]) -> m.DomainOutput:
        adapter = adapters.get(decl.adapter.text)
        frame = None if decl.frame is None else decl.frame.text
        env = Env(self.state_env, "in an output", "state variables")
        values: dict[str, m.Expr] = {}
        first: dict[str, ast.Assign] = {}
        for assign in decl.fields:
            value = self.typer.expr(assign.value, env)
            if adapter is None:
                continue
            field = adapter.field(assign.target.text)
            if field is None:
                self.d.report(
                    "E206", assign.target.span,
                    f"adapter `{adapter.name}` has no field `{assign.target.text}`",
                    help=suggest(assign.target.text, [f.name for f in adapter.fields]) or
                    "its fields are " + ", ".join(f"`{f.name}`" for f in adapter.fields),
                )
                continue
            if field.name in first:
                self.d.report("E206", assign.target.span, f"field `{field.name}` is defined twice",
                              labels=(Label(first[field.name].target.span, "first defined here"),))
                continue
            first[field.name] = assign
            self.flow(value, field.type, assign.value.span, f"field `{field.name}` of `{adapter.name}`")
            values[field.name] = value
        if adapter is None:
            return m.DomainOutput(decl.name.text, m.AdapterRef(decl.adapter.text), (), decl.doc, decl.span, frame)
        missing = [f.name for f in adapter.fields if f.name not in values and f.name not in first]
        if missing and len(first) == len(decl.fields):  # a misspelt field already explains the gap
            self.d.report(
                "E206", decl.name.span,
                f"output `{decl.name.text}` does not define {', '.join(f'`{n}`' for n in missing)} "
                f"of adapter `{adapter.name}`",
                help="an output defines every field of its adapter",
            )
        fields = tuple((f.name, values[f.name]) for f in adapter.fields if f.name in values)
        return m.DomainOutput(decl.name.text, m.AdapterRef(adapter.name), fields, decl.doc, decl.span, frame)

    # -- what is declared and never used ----------------------------------------------------

    def unused(self, interfaces: dict[str, m.Interface]) -> None:
        """Outputs never delivered and state nothing uses. (Primitives and interfaces are the
        host's to call, through `call_primitive` and `call_interface`, so none is unused.)"""
        if self.s.damaged:  # what the lost declarations used is unknown
            return
        triggered = {o for i in interfaces.values() for o in i.triggers}
        for name, decl in self.s.outputs.items():
            if name not in triggered and id(decl) in self.main_decls and ("output", name) not in self.s.suggested:
                self.d.report("W102", decl.name.span, f"output `{name}` is never triggered",
                              help=f"add `triggers {name}` to the interface that reads its state")
        written = {a.target for p in self.primitives.values() for a in p.post_actions()}
        for name, state in self.s.states.items():
            known = self.state_env.get(name, (None, None))[1] is not None  # else its type is reported
            if name not in self.typer.reads and name not in written and known and id(state) in self.main_decls:
                self.d.report("W103", state.name.span, f"state variable `{name}` is never used",
                              help="read it in an expression, write it in a post-action, or remove it")


def _refs(node: object) -> Iterator[ast.Ref]:
    """The names an expression (or a tuple of them) reads, in order."""
    if isinstance(node, ast.Ref):
        yield node
    elif isinstance(node, tuple):
        for item in node:
            yield from _refs(item)
    elif not isinstance(node, Span):
        for name in field_names(node):
            yield from _refs(getattr(node, name))


def _in_range(value: object, low: float, high: float) -> bool:
    """Whether a constant is within a parameter's range: a number by its value, bytes by their
    length (a value of another type is reported as such, not here)."""
    if isinstance(value, bytes):
        return low <= len(value) <= high
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return low <= value <= high
    return True


def _ranged(value: object) -> str:
    """A constant as a range message names it: bytes by their length."""
    if isinstance(value, bytes):
        return f"{shown(value)} ({len(value)} byte{'s' if len(value) != 1 else ''})"
    return shown(value)


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def _decoding_span(entry: ast.ReplyEntry) -> Span:
    """Where an entry's decoding is written (the entry, for a nested table's)."""
    return entry.span if entry.decoding is None else entry.decoding.span


def _values_span(entry: ast.ReplyEntry) -> Span:
    """Where a reply table's entry says its value, or its range of values."""
    return entry.value.span if entry.last is None else entry.value.span.to(entry.last.span)


def _open_end(decoding: m.Unpack) -> str:
    """What makes a reply's size unknown until it is read ("" when nothing does)."""
    layout = decoding.layout
    if layout.rest:
        return "ends in `*` (the rest of the message)"
    if layout.varying is not None:
        return "repeats a group as many times as the message says"
    return ""
