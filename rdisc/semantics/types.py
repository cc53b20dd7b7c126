"""Typing of expressions: AST expression + scope → typed IR (rdisc.semantics.model).

A node whose type cannot be known (its error is already reported) gets the type
None, and every rule accepts None silently: one fault, one diagnostic.
Constant subexpressions are evaluated as they are typed, so a resource bomb
(`2 ** 10 ** 9`) is rejected when the description is loaded, not when it runs.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from functools import partial

from rdisc import TYPE_CHECKING
from rdisc.diagnostics import Diagnostics
from rdisc.engine.operations import BINARY, FUNCTIONS, UNARY, EvalError, fits, lookup_or
from rdisc.limits import MAX_ARRAY, MAX_INT
from rdisc.semantics import model as m
from rdisc.semantics.model import AnyType, Array, Scope, Type
from rdisc.semantics.operators import FLOAT_BYTES, shown
from rdisc.semantics.resolve import suggest
from rdisc.source import Span
from rdisc.syntax import ast

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.types_methods import dataclass

from rdisc.frozen import Frozen

T = AnyType | None  # None: unknown, already reported
NUMERIC = (Type.INT, Type.FLOAT)
Names = dict[str, tuple[Scope, AnyType]]  # what an expression may read: its scope and type, by name

_ARITHMETIC = {"+", "-", "*", "/", "//", "%", "**"}
_BITWISE = {"&", "|", "^", "<<", ">>"}
_ORDER = {"<", "<=", ">", ">="}
_EQUALITY = {"==", "!="}
_LOGIC = {"and", "or"}

# Built-in functions: (min args, max args).
ARITY = {
    "abs": (1, 1),
    "min": (2, 8),
    "max": (2, 8),
    "round": (1, 2),
    "int": (1, 1),
    "float": (1, 1),
    "bool": (1, 1),
    "str": (1, 1),
    "clamp": (3, 3),
    "sqrt": (1, 1),
    "sin": (1, 1),
    "cos": (1, 1),
    "atan2": (2, 2),
    "hypot": (2, 2),
    "len": (1, 1),
    "byte": (2, 2),
    "hex": (1, 1),
    "ascii": (1, 1),
    "encode": (1, 1),
    "pack7": (1, 1),
    "unpack7": (1, 1),
    "bitset": (1, 1),
    "unhex": (1, 1),
    "upper": (1, 1),
    "int_le": (1, 2),
    "int_be": (1, 2),
    "nibbles": (2, 2),
    "from_nibbles": (1, 1),
    **{name: (1, 1) for name in FLOAT_BYTES},
    **{"from_" + name: (1, 1) for name in FLOAT_BYTES},
}


class Layered(Mapping[str, tuple[Scope, AnyType]]):
    """`top` over `base`: what `ChainMap(top, base)` holds, in its order, read for less (the
    checker reads a name in one at each reference: a ChainMap's `get` asks each map twice, through
    a generator, which was a hundredth of a large description's check)."""

    __slots__ = ("base", "top")

    def __init__(self, top: Mapping[str, tuple[Scope, AnyType]], base: Mapping[str, tuple[Scope, AnyType]]) -> None:
        self.top, self.base = top, base

    def __getitem__(self, name: str) -> tuple[Scope, AnyType]:
        found = self.top.get(name)  # a name's (scope, type) is never None
        return self.base[name] if found is None else found

    def get(self, name: str, default: object = None) -> tuple[Scope, AnyType] | None:  # type: ignore[override]
        found = self.top.get(name)
        return self.base.get(name, default) if found is None else found  # type: ignore[arg-type]

    def __contains__(self, name: object) -> bool:
        return name in self.top or name in self.base

    def __iter__(self) -> Iterator[str]:
        return iter({**dict.fromkeys(self.base), **dict.fromkeys(self.top)})

    def __len__(self) -> int:
        return len({**dict.fromkeys(self.base), **dict.fromkeys(self.top)})


@dataclass(frozen=True, slots=True)
class Env(metaclass=Frozen):
    """What an expression may read, and how to explain what it may not."""

    names: Mapping[str, tuple[Scope, AnyType]]  # a layered view where the state variables are shared (Checker.env_with)
    where: str  # "in a hook argument", ...
    sees: str  # "state variables", ...
    reply: tuple[AnyType, ...] | None = None  # types of out[i], in post-actions
    reply_note: str | None = None  # why `out` is not available, when it is not
    reply_known: bool = True  # False when the reply's template was already reported
    setting_note: str | None = None  # how to read a setting here after all, when one is refused (E213)


def unify(a: T, b: T) -> T:
    """The type of a value that is either a or b; int widens to float."""
    if a is None or b is None:
        return None
    if a == b:
        return a
    if {a, b} == {Type.INT, Type.FLOAT}:
        return Type.FLOAT
    if isinstance(a, Array) and isinstance(b, Array) and a.size == b.size:
        element = unify(a.element, b.element)
        return Array(element, a.size) if isinstance(element, Type) else None
    return None


def describe(t: AnyType) -> str:
    if isinstance(t, Array):
        return f"an array {t.value}"
    return {Type.INT: "an int", Type.FLOAT: "a float", Type.BOOL: "a bool", Type.STRING: "a string",
            Type.BYTES: "bytes"}[t]


class Typer:
    """Types expressions and folds their constant parts."""

    def __init__(self, diagnostics: Diagnostics) -> None:
        self.diagnostics = diagnostics
        # id(node) → (node, value); holding the node keeps its id from being reused.
        self._constants: dict[int, tuple[m.Expr, m.Value]] = {}
        self.reads: set[str] = set()  # state variables read by any expression
        self.named: dict[str, tuple[AnyType, m.Value]] = {}  # `const` declarations: (type, value)
        self.tables: dict[str, tuple[Type, AnyType, dict[m.Value, m.Value]]] = {}  # lookup tables: key and value types
        self.failed: set[str] = set()  # constants whose value has an error already reported
        self.failed_reads = 0  # reads of those: each one's fault is reported once, at the constant
        self.enums: dict[str, dict[str, int]] = {}  # enumerations: member → value
        self.settings: set[str] = set()  # names of settings: given when connecting, so never constant

    def constant(self, expr: m.Expr) -> m.Value | None:
        """The value of a constant expression, or None when it is not constant."""
        found = self._constants.get(id(expr))
        return None if found is None else found[1]

    def is_constant(self, expr: m.Expr) -> bool:
        return id(expr) in self._constants

    def folded(self, expr: m.Expr) -> m.Expr:
        """An element of a constant array known as its value (`IDS[2]`, as a format value)."""
        if isinstance(expr, m.Element) and self.is_constant(expr.array) and isinstance(expr.index, m.Const):
            values, index = self.constant(expr.array), expr.index.value
            if isinstance(values, tuple) and type(index) is int and 0 <= index < len(values):  # else reported
                return self._const(m.Const(values[index], expr.type, expr.span))
        return expr

    # -- the rules ------------------------------------------------------------

    def expr(self, e: ast.Expr, env: Env) -> m.Expr:
        """The typed IR of `e`; problems are reported, never raised."""
        match e:  # the commonest first: each case is a class test, and no node is of two
            case ast.IntLit():
                return self._const(m.Const(e.value, Type.INT, e.span))
            case ast.Ref():
                return self._ref(e, env)
            case ast.BinOp():
                return self._binary(e, env)
            case ast.FloatLit():
                return self._const(m.Const(e.value, Type.FLOAT, e.span))
            case ast.CallExpr():
                return self._call(e, env)
            case ast.Index():
                return self._index(e, env)
            case ast.Conditional():
                return self._conditional(e, env)
            case ast.StrLit():
                return self._const(m.Const(e.value, Type.STRING, e.span))
            case ast.BoolLit():
                return self._const(m.Const(e.value, Type.BOOL, e.span))
            case ast.Unary():
                return self._unary(e, env)
            case ast.ArrayLit():
                return self._array(e, env)
            case ast.BytesLit():
                return self._const(m.Const(e.value, Type.BYTES, e.span))
            case ast.Member():
                return self._member(e)
            case ast.MethodCall():
                return self._get(e, env)
        raise AssertionError(f"unknown expression node {e!r}")

    def const(self, value: m.Value, type_: AnyType, span: Span | None) -> m.Expr:
        """A constant the checker puts in (a parameter's default, in a call that leaves it out)."""
        return self._const(m.Const(value, type_, span))

    def _const(self, node: m.Const) -> m.Expr:
        self._constants[id(node)] = (node, node.value)
        return node

    def _ref(self, e: ast.Ref, env: Env) -> m.Expr:
        if e.name == "out":
            if env.reply is None:
                self.diagnostics.report(
                    "E103", e.span, f"`out` is not in scope {env.where}", help=env.reply_note or
                    "`out`, the reply, is in scope only in a primitive's post-actions"
                )
            else:
                self.diagnostics.report("E305", e.span, "the reply `out` must be indexed: `out[0]`")
            return m.Var(e.name, Scope.STATE, None, e.span)  # type: ignore[arg-type]
        found = env.names.get(e.name)
        if found is None and e.name in self.named:  # a constant, unless a local name hides it
            type_, value = self.named[e.name]
            return self._const(m.Const(value, type_, e.span))
        if found is None and e.name in self.failed:
            self.failed_reads += 1
            return m.Var(e.name, Scope.STATE, None, e.span)  # type: ignore[arg-type]
        if found is None and e.name in self.settings:
            self.diagnostics.report(
                "E213", e.span, f"setting `{e.name}` is given only when connecting, so it cannot stand {env.where}",
                help=env.setting_note or "a setting is read where state is: in arguments, format values, "
                "conditions, post-actions and outputs; a connection's `baud` may be one",
            )
            return m.Var(e.name, Scope.STATE, None, e.span)  # type: ignore[arg-type]
        if found is None:
            self.diagnostics.report(
                "E103",
                e.span,
                f"unknown name `{e.name}` {env.where}",
                label=f"{env.where} only {env.sees} are in scope" if env.sees else "nothing is in scope here",
                help=suggest(e.name, [*env.names, "True", "False"]),
            )
            return m.Var(e.name, Scope.STATE, None, e.span)  # type: ignore[arg-type]
        scope, type_ = found
        if scope is Scope.STATE:
            self.reads.add(e.name)
        return m.Var(e.name, scope, type_, e.span)

    def _member(self, e: ast.Member) -> m.Expr:
        members = self.enums.get(e.enum.text)
        if members is None:
            self.diagnostics.report("E102", e.enum.span, f"unknown enum `{e.enum.text}`",
                                    label="no enum of this name", help=suggest(e.enum.text, self.enums))
            return m.Const(0, None, e.span)  # type: ignore[arg-type]
        value = members.get(e.member.text)
        if value is None:
            self.diagnostics.report(
                "E102", e.member.span, f"enum `{e.enum.text}` has no member `{e.member.text}`",
                help=suggest(e.member.text, members) or "its members are " + ", ".join(f"`{n}`" for n in members),
            )
            return m.Const(0, None, e.span)  # type: ignore[arg-type]
        return self._const(m.Const(value, Type.INT, e.span))

    def _index(self, e: ast.Index, env: Env) -> m.Expr:
        if isinstance(e.base, (ast.ArrayLit, ast.Index)):
            return self._element(e, env)
        if e.base.name in self.tables and e.base.name not in env.names:
            return self._lookup(e, env)
        declared = env.names.get(e.base.name, (None, self.named.get(e.base.name, (None,))[0]))[1]
        if isinstance(declared, Array):
            return self._element(e, env)
        if e.base.name in self.failed and e.base.name not in env.names:  # a table or constant in error
            self.expr(e.index, env)
            return m.ReplyValue(0, None, e.span)  # type: ignore[arg-type]
        if e.base.name != "out":
            self.diagnostics.report("E404", e.span, f"`{e.base.name}` cannot be indexed", help="the reply `out`, arrays and lookup tables can be indexed")
            return m.ReplyValue(0, None, e.span)  # type: ignore[arg-type]
        index = self.expr(e.index, env)
        if not env.reply_known:
            return m.ReplyValue(0, None, e.span)  # type: ignore[arg-type]
        if env.reply is None:
            self.diagnostics.report(
                "E103", e.base.span, f"`out` is not in scope {env.where}",
                help=env.reply_note or "`out`, the reply, is in scope only in a primitive's post-actions",
            )
            return m.ReplyValue(0, None, e.span)  # type: ignore[arg-type]
        value = self.constant(index)
        if index.type is None:
            return m.ReplyValue(0, None, e.span)
        if index.type is not Type.INT or not isinstance(value, int) or isinstance(value, bool):
            self.diagnostics.report("E305", e.index.span, "the index of `out` must be a constant integer")
            return m.ReplyValue(0, None, e.span)  # type: ignore[arg-type]
        if not 0 <= value < len(env.reply):
            count = len(env.reply)
            self.diagnostics.report(
                "E305",
                e.span,
                f"`out[{value}]` is outside the reply, which has {count} value{'s' if count != 1 else ''}",
                help=f"valid indexes are 0 to {count - 1}" if count else "this reply has no values",
            )
            return m.ReplyValue(value, None, e.span)  # type: ignore[arg-type]
        # A value of replies read N times is an array, which m.ReplyValue.type (a Type) does not say.
        return m.ReplyValue(value, env.reply[value], e.span)  # type: ignore[arg-type]

    def _element(self, e: ast.Index, env: Env) -> m.Expr:
        """`array[index]`: an int index; a constant one within the array."""
        # The printer, for a nested index only: a clean check rarely needs it (start-up time).
        from rdisc.syntax.printer import print_expr

        array = self.expr(e.base, env)
        index = self.expr(e.index, env)
        if isinstance(e.base, ast.Index) and array.type is not None and not isinstance(array.type, Array):
            self.diagnostics.report("E404", e.span, f"`{print_expr(e.base)}` is {describe(array.type)}, not an "
                                    "array, and cannot be indexed", help="a reply's value read by a repeated "
                                    "group (`unpack \"<B6(Hb)\"`) or by `replies N` is an array, as a table's "
                                    "array entry is")
        if not isinstance(array.type, Array):  # an array literal in error, already reported
            return m.Element(array, index, None, e.span)  # type: ignore[arg-type]
        node = m.Element(array, index, array.type.element, e.span)
        if index.type is not None and index.type is not Type.INT:
            self.diagnostics.report("E404", e.index.span, f"an index is an int, not {describe(index.type)}")
            return m.Element(array, index, None, e.span)  # type: ignore[arg-type]
        self.in_array(array.type, index, e.base.name if isinstance(e.base, ast.Ref) else
                      print_expr(e.base) if isinstance(e.base, ast.Index) else "the array", e.index.span)
        folded = self._fold(node, (array, index), lambda a, i: a[i])
        if self.is_constant(folded) and fits(self.constant(folded)):  # `IDS[2]`: the element itself
            return self._const(m.Const(self.constant(folded), array.type.element, e.span))  # type: ignore[arg-type]
        return folded

    def in_array(self, array: Array, index: m.Expr, name: str, span: Span) -> None:
        """A constant index must be one of the array's (it is checked again when it runs)."""
        value = self.constant(index)
        if self.is_constant(index) and array.size and not 0 <= value < array.size:  # type: ignore[operator]
            self.diagnostics.report("E403", span, f"index {shown(value)} is outside `{name}`, which has "
                                    f"{array.size} values", label=f"in 0..{array.size - 1}")
            self._constants.pop(id(index))  # reported: nothing folds on it

    def _array(self, e: ast.ArrayLit, env: Env) -> m.Expr:
        """`[a, b, c]`: one or more values of one scalar type (ints in a float array widen)."""
        items = tuple(self.expr(i, env) for i in e.items)
        if not items:
            self.diagnostics.report("E404", e.span, "an array has one value or more",
                                    help="an array's size is fixed: `[0, 0, 0]`")
            return m.ArrayValue(items, None, e.span)  # type: ignore[arg-type]
        if len(items) > MAX_ARRAY:
            self.diagnostics.report("E404", e.span, f"an array holds at most {MAX_ARRAY} values, not {len(items)}")
            return m.ArrayValue(items, None, e.span)  # type: ignore[arg-type]
        element: T = items[0].type
        for item, written in zip(items, e.items):
            if item.type is None:
                return m.ArrayValue(items, None, e.span)
            if item.type not in (Type.INT, Type.FLOAT, Type.BOOL, Type.STRING):
                self.diagnostics.report("E404", written.span, f"an array holds ints, floats, bools or strings, not "
                                        f"{describe(item.type)}")
                return m.ArrayValue(items, None, e.span)  # type: ignore[arg-type]
            joined = unify(element, item.type)
            if joined is None:
                self.diagnostics.report("E401", written.span, f"the values of an array have one type: this is "
                                        f"{describe(item.type)}, after {describe(element)}")  # type: ignore[arg-type]
                return m.ArrayValue(items, None, e.span)  # type: ignore[arg-type]
            element = joined
        assert isinstance(element, Type)
        node = m.ArrayValue(items, Array(element, len(items)), e.span)
        widen = float if element is Type.FLOAT else (lambda v: v)
        folded = self._fold(node, items, lambda *values: tuple(widen(v) for v in values))
        if self.is_constant(folded) and fits(self.constant(folded)):  # `[1, 2, 3]`, as a named one is
            return self._const(m.Const(self.constant(folded), node.type, e.span))  # type: ignore[arg-type]
        return folded

    def _lookup(self, e: ast.Index, env: Env) -> m.Expr:
        """`TABLE[key]`: a key of the table's key type; a constant key must be in the table."""
        assert isinstance(e.base, ast.Ref)  # `_index` sends an array literal's elements elsewhere
        key_type, value_type, entries = self.tables[e.base.name]
        key = self.expr(e.index, env)
        # A table's values may be arrays, which m.Lookup.type (a Type) does not say.
        node = m.Lookup(e.base.name, tuple(entries.items()), key, value_type, e.span)  # type: ignore[arg-type]
        if key.type is not None and key.type is not key_type:
            self.diagnostics.report("E401", e.index.span, f"table `{e.base.name}` is keyed by {key_type.value}, "
                                    f"but this is {describe(key.type)}")
        elif self.is_constant(key):
            value = self.constant(key)
            if value not in entries:
                self.diagnostics.report("E403", e.index.span, f"table `{e.base.name}` has no entry for {shown(value)}",
                                        help=f"its keys: {', '.join(shown(k) for k in list(entries)[:8])}"
                                        + (", ..." if len(entries) > 8 else ""))
            else:
                self._constants[id(node)] = (node, entries[value])
        return node

    def _unary(self, e: ast.Unary, env: Env) -> m.Expr:
        operand = self.expr(e.operand, env)
        t = operand.type
        result: T
        if t is None:
            result = None
        elif e.op == "not":
            result = Type.BOOL if t is Type.BOOL else self._bad_operand(e, t, "`not` needs a bool")
        elif e.op == "~":
            result = Type.INT if t is Type.INT else self._bad_operand(e, t, "`~` needs an int")
        else:
            result = t if t in NUMERIC else self._bad_operand(e, t, f"unary `{e.op}` needs a number")
        node = m.UnaryOp(e.op, operand, result, e.span)  # type: ignore[arg-type]
        return self._fold(node, (operand,), lambda a: UNARY[e.op](a))

    def _bad_operand(self, e: ast.Expr, t: AnyType, need: str) -> T:
        """Report an operand of the wrong type: the result is unknown (None), so nothing cascades."""
        self.diagnostics.report("E404", e.span, f"{need}, not {describe(t)}")
        return None

    def _table_named(self, name: str, span: Span, env: Env, what: str) -> tuple[Type, AnyType, dict[m.Value, m.Value]] | None:
        """The lookup table `name` (its key type, value type and entries) that `what` needs;
        None, reported unless its own fault was, where there is no such table."""
        if name in self.tables and name not in env.names:
            return self.tables[name]
        if name not in self.failed or name in env.names:
            self.diagnostics.report("E404", span, f"{what} needs a lookup table, and `{name}` is not one",
                                    help=suggest(name, self.tables) or "a lookup table is a constant such as "
                                    "`const HEALTH = { 0: \"ok\", 1: \"hot\" }`")
        return None

    def _keyed(self, table: str, key_type: Type, key: m.Expr, span: Span) -> bool:
        """Whether `key` is of the table's key type (reported where it is not)."""
        if key.type is None or key.type is key_type:
            return key.type is not None
        self.diagnostics.report("E401", span, f"table `{table}` is keyed by {key_type.value}, but this is "
                                f"{describe(key.type)}")
        return False

    def _membership(self, e: ast.BinOp, env: Env) -> m.Expr:
        """`key in TABLE`: whether the table has an entry for the key (a bool)."""
        key = self.expr(e.left, env)
        name = e.right.name if isinstance(e.right, ast.Ref) else None
        if name is None:
            self.expr(e.right, env)
            self.diagnostics.report("E404", e.right.span, "`in` needs a lookup table on its right",
                                    help="a lookup table is a constant such as `const HEALTH = { 0: \"ok\" }`")
            return m.InTable("", (), key, None, e.span)  # type: ignore[arg-type]
        found = self._table_named(name, e.right.span, env, "`in`")
        if found is None:
            return m.InTable(name, (), key, None, e.span)  # type: ignore[arg-type]
        key_type, _, entries = found
        node = m.InTable(name, tuple(entries), key, Type.BOOL, e.span)
        if not self._keyed(name, key_type, key, e.left.span):
            return m.InTable(name, tuple(entries), key, None, e.span)  # type: ignore[arg-type]
        return self._fold(node, (key,), lambda value: value in entries)

    def _get(self, e: ast.MethodCall, env: Env) -> m.Expr:
        """`TABLE.get(key, default)`: the table's value for the key, or the default where it has none."""
        args = tuple(self.expr(a, env) for a in e.args)
        unknown = m.Lookup(e.base.text, (), args[0] if args else m.Const(0, Type.INT), None, e.span)  # type: ignore[arg-type]
        if e.method.text != "get":
            self.diagnostics.report("E106", e.method.span, f"unknown method `{e.method.text}`",
                                    help="a lookup table has one method: `TABLE.get(key, default)`")
            return unknown
        found = self._table_named(e.base.text, e.base.span, env, "`.get`")
        if found is None:
            return unknown
        if len(args) != 2:
            self.diagnostics.report("E201", e.span, f"`get` takes 2 arguments (a key and a default), but {len(args)} given")
            return unknown
        key_type, value_type, entries = found
        key, default = args
        if not self._keyed(e.base.text, key_type, key, e.args[0].span):
            return unknown
        if default.type is None:
            return unknown
        if unify(value_type, default.type) != value_type:
            self.diagnostics.report("E401", e.args[1].span, f"the default of `{e.base.text}.get` is "
                                    f"{describe(value_type)}, as the table's values are, not {describe(default.type)}")
            return unknown
        # A table's values may be arrays, which m.Lookup.type (a Type) does not say.
        node = m.Lookup(e.base.text, tuple(entries.items()), key, value_type, e.span, default)  # type: ignore[arg-type]
        return self._fold(node, (key, default), partial(lookup_or, entries))

    def _binary(self, e: ast.BinOp, env: Env) -> m.Expr:
        if e.op == "in":
            return self._membership(e, env)
        left = self.expr(e.left, env)
        right = self.expr(e.right, env)
        a, b = left.type, right.type
        result: T = None
        op = e.op
        if a is not None and b is not None:
            if op in _LOGIC:
                ok = a is Type.BOOL and b is Type.BOOL
                result = Type.BOOL if ok else None
                need = f"`{op}` needs two bools"
            elif op in _EQUALITY:
                ok = unify(a, b) is not None
                result = Type.BOOL if ok else None
                need = f"`{op}` compares values of the same type"
            elif op in _ORDER:
                ok = (a in NUMERIC and b in NUMERIC) or a == b == Type.STRING
                result = Type.BOOL if ok else None
                need = f"`{op}` compares two numbers or two strings"
            elif op in _BITWISE:
                ok = a is Type.INT and b is Type.INT
                result = Type.INT if ok else None
                need = f"`{op}` needs two ints"
            elif op == "+" and a == b and a in (Type.STRING, Type.BYTES):
                ok, result, need = True, a, ""
            else:  # arithmetic
                ok = a in NUMERIC and b in NUMERIC
                result = (Type.FLOAT if op == "/" else unify(a, b)) if ok else None
                need = "`+` needs two numbers, two strings or two bytes" if op == "+" else f"`{op}` needs two numbers"
            if not ok:
                self.diagnostics.report(
                    "E404", e.span, f"{need}, not {describe(a)} and {describe(b)}", label="these operands"
                )
        node = m.BinaryOp(op, left, right, result, e.span)  # type: ignore[arg-type]
        if op in _LOGIC:
            return self._fold(node, (left, right), lambda x, y: (x and y) if op == "and" else (x or y))
        return self._fold(node, (left, right), BINARY[op])

    def _conditional(self, e: ast.Conditional, env: Env) -> m.Expr:
        cond = self.expr(e.cond, env)
        then = self.expr(e.then, env)
        orelse = self.expr(e.orelse, env)
        if cond.type is not None and cond.type is not Type.BOOL:
            self.diagnostics.report("E404", e.cond.span, f"the condition must be a bool, not {describe(cond.type)}")
        result = unify(then.type, orelse.type)
        if result is None and then.type is not None and orelse.type is not None:
            self.diagnostics.report(
                "E401",
                e.span,
                f"the two branches have different types: {describe(then.type)} and {describe(orelse.type)}",
            )
        node = m.IfElse(cond, then, orelse, result, e.span)  # type: ignore[arg-type]
        if result is not None and self.is_constant(cond):
            chosen = then if self.constant(cond) else orelse
            found = self._constants.get(id(chosen))
            if found is not None:
                self._constants[id(node)] = (node, found[1])
        return node

    def _call(self, e: ast.CallExpr, env: Env) -> m.Expr:
        args = tuple(self.expr(a, env) for a in e.args)
        name = e.func.text
        if name not in FUNCTIONS:
            self.diagnostics.report(
                "E106",
                e.func.span,
                f"unknown function `{name}`",
                label="not a built-in function",
                help=suggest(name, FUNCTIONS) or "functions: " + ", ".join(sorted(FUNCTIONS)),
            )
            return m.FuncCall(name, args, None, e.span)  # type: ignore[arg-type]
        low, high = ARITY[name]
        if not low <= len(args) <= high:
            count = str(low) if low == high else f"{low} to {high}"
            self.diagnostics.report(
                "E201", e.span, f"`{name}` takes {count} argument{'s' if high != 1 else ''}, but {len(args)} given"
            )
            return m.FuncCall(name, args, None, e.span)  # type: ignore[arg-type]
        result = self._function_type(name, e, args)
        node = m.FuncCall(name, args, result, e.span)  # type: ignore[arg-type]
        return self._fold(node, args, FUNCTIONS[name])

    def _function_type(self, name: str, e: ast.CallExpr, args: tuple[m.Expr, ...]) -> T:
        types = [a.type for a in args]
        if any(t is None for t in types):
            return None

        def need(what: str, accepted: tuple[Type, ...]) -> bool:
            for arg, t in zip(e.args, types):
                if t is not None and t not in accepted:
                    self.diagnostics.report("E404", arg.span, f"`{name}` needs {what}, not {describe(t)}")
                    return False
            return True

        match name:
            case "abs":
                return types[0] if need("a number", NUMERIC) else None
            case "min" | "max" | "clamp":
                if not need("numbers", NUMERIC):
                    return None
                return Type.FLOAT if Type.FLOAT in types else Type.INT
            case "round":
                if not need("numbers", NUMERIC):
                    return None
                if len(types) == 2 and types[1] is not Type.INT:
                    self.diagnostics.report("E404", e.args[1].span, "the digits of `round` must be an int")
                    return None
                return Type.INT if len(types) == 1 else Type.FLOAT
            case "int" | "float":
                if not need("a number, bool or string", (*NUMERIC, Type.BOOL, Type.STRING)):
                    return None
                return Type.INT if name == "int" else Type.FLOAT
            case "bool":
                return Type.BOOL if need("a number or bool", (Type.INT, Type.FLOAT, Type.BOOL)) else None
            case "str":
                return Type.STRING if need("a number, bool or string", (*NUMERIC, Type.BOOL, Type.STRING)) else None
            case "len" if isinstance(types[0], Array):
                return Type.INT
            case "len":
                return Type.INT if need("bytes, a string or an array", (Type.BYTES, Type.STRING)) else None
            case "byte":
                if types[0] is not Type.BYTES or types[1] is not Type.INT:
                    self.diagnostics.report("E404", e.span, "`byte` takes bytes and an int index: `byte(out[1], 0)`")
                    return None
                return Type.INT
            case "hex" | "ascii":
                return Type.STRING if need("bytes", (Type.BYTES,)) else None
            case "pack7" | "unpack7":
                return Type.BYTES if need("bytes", (Type.BYTES,)) else None
            case "encode":
                return Type.BYTES if need("a string", (Type.STRING,)) else None
            case "unhex":
                return Type.BYTES if need("a string of hex digits", (Type.STRING,)) else None
            case "upper":
                return types[0] if need("a string or bytes", (Type.STRING, Type.BYTES)) else None
            case "int_le" | "int_be":
                if types[0] is not Type.BYTES or tuple(types[1:]) not in ((), (Type.BOOL,)):
                    self.diagnostics.report("E404", e.span, f"`{name}` takes bytes and, if signed, `True`: "
                                            f"`{name}(out[1])`, `{name}(out[1], True)`")
                    return None
                return Type.INT
            case "nibbles":
                if types != [Type.INT, Type.INT]:
                    self.diagnostics.report("E404", e.span, "`nibbles` takes an int and a count of nibbles: "
                                            "`nibbles(position, 4)`")
                    return None
                return Type.BYTES
            case "from_nibbles":
                return Type.INT if need("bytes", (Type.BYTES,)) else None
            case _ if name in FLOAT_BYTES:
                return Type.BYTES if need("a number", NUMERIC) else None
            case _ if name.startswith("from_"):  # from_f32le and the other floats from bytes
                return Type.FLOAT if need("bytes", (Type.BYTES,)) else None
            case "bitset" if isinstance(types[0], Array) and types[0].element is Type.INT:
                return Type.INT
            case "bitset":
                self.diagnostics.report("E404", e.args[0].span, f"`bitset` needs an int array, not {describe(types[0])}")
                return None
            case _:  # sqrt sin cos atan2 hypot
                return Type.FLOAT if need("numbers", NUMERIC) else None

    def _fold(self, node: m.Expr, operands: tuple[m.Expr, ...], compute: Callable[..., m.Value]) -> m.Expr:
        """Evaluate a node whose operands are all constant; report what cannot be."""
        if node.type is None or not all(self.is_constant(o) for o in operands):
            return node
        try:
            value = compute(*(self.constant(o) for o in operands))
        except (EvalError, ValueError) as err:  # an operation refused, saying why
            self.diagnostics.report("E405", node.span, str(err))
            return node
        except (ArithmeticError, TypeError) as err:
            self.diagnostics.report("E405", node.span, f"cannot evaluate: {err}")
            return node
        self._constants[id(node)] = (node, value)
        return node

    def value_over(self, expr: m.Expr, params: Mapping[str, object]) -> object | None:
        """The value of an expression over given values of its parameters (a frame's field for
        the constant arguments of one use), or None when it needs anything else or fails."""
        if self.is_constant(expr):
            return self.constant(expr)
        compute: Callable[..., object]
        operands: tuple[m.Expr, ...]
        match expr:
            case m.Var(scope=Scope.PARAM, name=name):
                return params.get(name)
            case m.UnaryOp(op=op, operand=operand):
                compute, operands = UNARY[op], (operand,)
            case m.BinaryOp(op="and", left=left, right=right):
                compute, operands = (lambda x, y: x and y), (left, right)
            case m.BinaryOp(op="or", left=left, right=right):
                compute, operands = (lambda x, y: x or y), (left, right)
            case m.BinaryOp(op=op, left=left, right=right):
                compute, operands = BINARY[op], (left, right)
            case m.IfElse(cond=cond, then=then, orelse=orelse):
                chosen = self.value_over(cond, params)
                return None if chosen is None else self.value_over(then if chosen else orelse, params)
            case m.FuncCall(func=func, args=args):
                compute, operands = FUNCTIONS[func], args
            case _:
                return None
        values = [self.value_over(o, params) for o in operands]
        if any(v is None for v in values):
            return None
        try:
            result: object = compute(*values)
        except (EvalError, ArithmeticError, ValueError, TypeError):
            return None
        return result

    def kept(self, value: object, span: Span | None) -> bool:
        """Whether a constant value fits where it is kept (a constant, a state variable): ints in
        64 bits and a sign. Inside an expression, results are only bounded so that none explodes."""
        if fits(value):
            return True
        self.diagnostics.report("E405", span, f"{shown(value)} is too large: integers are limited to 64 bits "
                                f"and a sign ({-MAX_INT}..{MAX_INT})")
        return False
