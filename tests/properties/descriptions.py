"""Random RDIS descriptions, valid by construction, and what a device answers them.

A description is drawn as a tree of frozen specs (states, frames, primitives,
interfaces, connections, inputs, outputs) that renders to `.rdis` text
(`Description.text`). The specs keep what the text means, so that for any
primitive and its parameters' values `reply_for` can encode the reply a device
would send, without rdisc: the frame's constants, fields, length, checksums
(sums, XORs and CRCs computed bit by bit here, not by the engine's tables),
stuffing, hex digits, a tag, a payload that the primitive's `unpack` or `regex`
decodes. A `ReplyPlan` then spoils it or not (a flipped byte, cut short,
garbage before it, another frame first...), so that readers are probed with
valid and corrupt replies alike.

Every draw stays inside what `rdisc.compile` accepts: names come from disjoint
pools, a constant expression is folded here first and replaced by a literal when
the checker would refuse it (division by zero, overflow, out of a pack code's or
a range's bounds), a frame is given only to primitives whose replies it can
delimit, and so on. Delays are 0 ms (nothing to wait for), reply timeouts a few
ms (a scripted port answers at once).
"""

from __future__ import annotations

import dataclasses
import math
import re
import struct
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import partial
from typing import Any

from hypothesis import strategies as st

from rdisc.semantics.checksums import CATALOGUE

INT, FLOAT, BOOL, STRING, BYTES = "int", "float", "bool", "string", "bytes"
NUMBERS = (INT, FLOAT)
INTS = "int[]"  # an array parameter of any size: `replies eid in ids` goes over its elements
EACH_VAR = "eid"  # the variable of `replies eid in ids`: each element, in the reply frame's arguments

# The standard adapters (stdlib/adapters.rdis): field names and types, in order.
ADAPTERS: dict[str, tuple[tuple[str, str], ...]] = {
    "DifferentialSpeed": (("linear", FLOAT), ("angular", FLOAT)),
    "Range": (("distance", FLOAT),),
    "Contact": (("contact", BOOL),),
    "Battery": (("voltage", FLOAT), ("current", FLOAT), ("charge", FLOAT), ("capacity", FLOAT),
                ("percentage", FLOAT)),
    "Pose2D": (("x", FLOAT), ("y", FLOAT), ("theta", FLOAT)),
    "JointPosition": (("name", STRING), ("position", FLOAT)),
    "Temperature": (("temperature", FLOAT), ("variance", FLOAT)),
}


class Unknown(Exception):
    """An expression this module cannot evaluate (a name not bound, an operation that fails)."""


# ---- values as RDIS text -------------------------------------------------------------------------


def string_literal(text: str) -> str:
    """`text` as an RDIS string literal: quotes, backslashes and non-printing characters escaped."""
    out = []
    for ch in text:
        if ch in '"\\':
            out.append("\\" + ch)
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\r":
            out.append("\\r")
        elif 0x20 <= ord(ch) < 0x7F:
            out.append(ch)
        elif ord(ch) <= 0xFF:
            out.append(f"\\x{ord(ch):02X}")
        else:
            out.append(f"\\u{ord(ch):04X}")
    return '"' + "".join(out) + '"'


def bytes_literal(data: bytes) -> str:
    """Constant frame bytes: every byte as \\xHH, as protocol manuals write them."""
    return '"' + "".join(f"\\x{b:02X}" for b in data) + '"'


def number_text(value: float) -> str:
    """A number as an RDIS literal; negative ones in parentheses so they nest anywhere."""
    text = repr(float(value)) if isinstance(value, float) else str(value)
    return f"({text})" if text.startswith("-") else text


# ---- expressions: rendered as RDIS, evaluated as Python (to predict, never to compare) -----------


@dataclass(frozen=True)
class Expr:
    """An expression node: its RDIS text, its type, whether the checker folds it to a constant."""

    type: str

    def text(self) -> str:
        raise NotImplementedError

    @property
    def const(self) -> bool:
        raise NotImplementedError

    def value(self, env: Mapping[str, Any]) -> Any:
        raise NotImplementedError


@dataclass(frozen=True)
class Lit(Expr):
    v: Any = 0

    def text(self) -> str:
        if self.type == BOOL:
            return "True" if self.v else "False"
        if self.type == STRING:
            return string_literal(self.v)
        return number_text(self.v)

    @property
    def const(self) -> bool:
        return True

    def value(self, env: Mapping[str, Any]) -> Any:
        return self.v


@dataclass(frozen=True)
class Name(Expr):
    """A state variable, a parameter or an adapter field."""

    name: str = ""

    def text(self) -> str:
        return self.name

    @property
    def const(self) -> bool:
        return False

    def value(self, env: Mapping[str, Any]) -> Any:
        if self.name not in env:
            raise Unknown(self.name)
        return env[self.name]


@dataclass(frozen=True)
class Named(Expr):
    """A `const` declaration or an enum member (`E0.m1`): a constant with a name."""

    name: str = ""
    v: Any = 0

    def text(self) -> str:
        return self.name

    @property
    def const(self) -> bool:
        return True

    def value(self, env: Mapping[str, Any]) -> Any:
        return self.v


@dataclass(frozen=True)
class Out(Expr):
    """`out[i]`, a decoded reply value, in post-actions."""

    index: int = 0

    def text(self) -> str:
        return f"out[{self.index}]"

    @property
    def const(self) -> bool:
        return False

    def value(self, env: Mapping[str, Any]) -> Any:
        raise Unknown("out")


MODE = ("MODE", 1)  # a setting (`setting MODE: int in 0..3 = 1`) that chooses frames' layouts (`either when`)
LOOK = {key: key + 1 for key in range(0x80)}  # `const LOOK`, which post-actions look a reply's byte up in


@dataclass(frozen=True)
class Setting(Expr):
    """MODE, as a frame's argument: its default, since sessions connect without settings."""

    def text(self) -> str:
        return MODE[0]

    @property
    def const(self) -> bool:
        return False

    def value(self, env: Mapping[str, Any]) -> Any:
        return MODE[1]


@dataclass(frozen=True)
class Looked(Expr):
    """`LOOK[out[i]]` in post-actions, out[i] a reply's last byte: one the table lacks is a lookup miss,
    a protocol error (`skip unmatched` reads past it)."""

    index: int = 0

    def text(self) -> str:
        return f"LOOK[out[{self.index}]]"

    @property
    def const(self) -> bool:
        return False

    def value(self, env: Mapping[str, Any]) -> Any:
        raise Unknown("out")


def _checked(result: Any) -> Any:
    """Python's result where rdisc's operators refuse it: infinities, huge ints, long strings."""
    if isinstance(result, float) and not math.isfinite(result):
        raise Unknown("not finite")
    if isinstance(result, complex):
        raise Unknown("complex")
    if isinstance(result, int) and not isinstance(result, bool) and result.bit_length() > 4000:
        raise Unknown("huge")
    if isinstance(result, str) and len(result) > 1000:
        raise Unknown("long")
    return result


def _power(a: Any, b: Any) -> Any:
    if isinstance(a, int) and isinstance(b, int) and not isinstance(a, bool):
        if b < 0 or (abs(a) > 1 and b * max(1, abs(a).bit_length()) > 4096):
            raise Unknown("power")
        return a**b
    return float(a) ** float(b)


def _shift(a: int, b: int, left: bool) -> int:
    if b < 0 or b > 1024:
        raise Unknown("shift")
    return a << b if left else a >> b


_BINARY: dict[str, Callable[[Any, Any], Any]] = {
    "+": lambda a, b: a + b, "-": lambda a, b: a - b, "*": lambda a, b: a * b, "/": lambda a, b: a / b,
    "//": lambda a, b: a // b, "%": lambda a, b: a % b, "**": _power,
    "<<": lambda a, b: _shift(a, b, True), ">>": lambda a, b: _shift(a, b, False),
    "&": lambda a, b: a & b, "|": lambda a, b: a | b, "^": lambda a, b: a ^ b,
    "==": lambda a, b: a == b, "!=": lambda a, b: a != b, "<": lambda a, b: a < b,
    "<=": lambda a, b: a <= b, ">": lambda a, b: a > b, ">=": lambda a, b: a >= b,
    "and": lambda a, b: a and b, "or": lambda a, b: a or b,
}


@dataclass(frozen=True)
class Binary(Expr):
    op: str = "+"
    left: Expr = Lit(INT, 0)
    right: Expr = Lit(INT, 0)

    def text(self) -> str:
        return f"({self.left.text()} {self.op} {self.right.text()})"

    @property
    def const(self) -> bool:
        return self.left.const and self.right.const

    def value(self, env: Mapping[str, Any]) -> Any:
        try:
            return _checked(_BINARY[self.op](self.left.value(env), self.right.value(env)))
        except (ArithmeticError, ValueError, TypeError) as err:
            raise Unknown(str(err)) from None


@dataclass(frozen=True)
class Unary(Expr):
    op: str = "-"
    operand: Expr = Lit(INT, 0)

    def text(self) -> str:
        space = " " if self.op == "not" else ""
        return f"({self.op}{space}{self.operand.text()})"

    @property
    def const(self) -> bool:
        return self.operand.const

    def value(self, env: Mapping[str, Any]) -> Any:
        x = self.operand.value(env)
        return not x if self.op == "not" else -x if self.op == "-" else ~x


_FLOAT_LAYOUTS = {"f32le": "<f", "f32be": ">f", "f64le": "<d", "f64be": ">d"}
"""The expression functions from a number to the bytes of a float, by their struct codes."""


def _int(x: Any) -> int:
    if isinstance(x, str) and x.strip()[:2].lower() in ("0x", "0b", "0o"):
        return int(x.strip(), 0)
    return int(x)


def _byte(data: bytes, i: int) -> int:
    if not 0 <= i < len(data):
        raise Unknown("byte")
    return data[i]


def _from_bytes(order: str) -> Callable[..., int]:
    def read(data: bytes, signed: bool = False) -> int:
        if len(data) > 8:
            raise Unknown("more than 8 bytes")
        return int.from_bytes(data, order, signed=signed)  # type: ignore[arg-type]
    return read


def _unpacked(layout: struct.Struct, data: bytes) -> float:
    value: float = layout.unpack(data)[0]
    return value


def _nibbles(value: int, count: int) -> bytes:
    if not 1 <= count <= 16 or not 0 <= value < 16**count:
        raise Unknown("nibbles")
    return bytes.fromhex("".join("0" + digit for digit in f"{value:0{count}x}"))


_FUNCTIONS: dict[str, Callable[..., Any]] = {
    "abs": abs, "min": min, "max": max, "int": _int, "float": float, "bool": bool, "str": str,
    "round": lambda x, n=None: round(x) if n is None else round(float(x), n),
    "clamp": lambda x, lo, hi: lo if x < lo else min(x, hi),
    "sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "atan2": math.atan2, "hypot": math.hypot,
    "len": len, "byte": _byte,
    "int_le": _from_bytes("little"), "int_be": _from_bytes("big"), "hex": bytes.hex, "upper": str.upper,
    "nibbles": _nibbles, "from_nibbles": lambda data: int(data.hex()[1::2] or "0", 16),
    **{name: struct.Struct(code).pack for name, code in _FLOAT_LAYOUTS.items()},
    **{"from_" + name: partial(_unpacked, struct.Struct(code)) for name, code in _FLOAT_LAYOUTS.items()},
}


@dataclass(frozen=True)
class Call(Expr):
    func: str = "abs"
    args: tuple[Expr, ...] = ()

    def text(self) -> str:
        return f"{self.func}({', '.join(a.text() for a in self.args)})"

    @property
    def const(self) -> bool:
        return all(a.const for a in self.args)

    def value(self, env: Mapping[str, Any]) -> Any:
        try:
            return _checked(_FUNCTIONS[self.func](*(a.value(env) for a in self.args)))
        except (ArithmeticError, ValueError, TypeError) as err:
            raise Unknown(str(err)) from None


@dataclass(frozen=True)
class IfElse(Expr):
    cond: Expr = Lit(BOOL, True)
    then: Expr = Lit(INT, 0)
    orelse: Expr = Lit(INT, 0)

    def text(self) -> str:
        return f"({self.then.text()} if {self.cond.text()} else {self.orelse.text()})"

    @property
    def const(self) -> bool:  # as the checker folds it: a constant condition and a constant chosen branch
        if not self.cond.const:
            return False
        try:
            return (self.then if self.cond.value({}) else self.orelse).const
        except Unknown:
            return False

    def value(self, env: Mapping[str, Any]) -> Any:
        return self.then.value(env) if self.cond.value(env) else self.orelse.value(env)


@dataclass(frozen=True)
class Elements(Expr):
    """An array literal `[a, b]`: a repeated group's values (its type is the element's)."""

    items: tuple[Expr, ...] = ()

    def text(self) -> str:
        return "[" + ", ".join(i.text() for i in self.items) + "]"

    @property
    def const(self) -> bool:
        return all(i.const for i in self.items)

    def value(self, env: Mapping[str, Any]) -> Any:
        return [i.value(env) for i in self.items]


def names_read(e: Expr) -> list[str]:
    """The names `e` reads, in the order the model's `variables` gives them (operands left to right)."""
    if isinstance(e, Name):
        return [e.name]
    found: list[str] = []
    for f in dataclasses.fields(e):
        value = getattr(e, f.name)
        for item in value if isinstance(value, tuple) else (value,):
            if isinstance(item, Expr):
                found += names_read(item)
    return found


def constant_value(e: Expr) -> Any:
    """The value the checker folds `e` to; Unknown if it would refuse to (a diagnostic)."""
    try:
        return _checked(e.value({}))
    except (ArithmeticError, ValueError, TypeError, OverflowError) as err:
        raise Unknown(str(err)) from None


def flows(source: str, target: str) -> bool:
    """Whether a value of type `source` may go where `target` is declared (int widens to float)."""
    return source == target or (source, target) == (INT, FLOAT)


# ---- drawing expressions ----------------------------------------------------------------------------

Scope = tuple[Expr, ...]
"""What an expression may read: Name, Out and Named leaves, each with its type."""

Draw = Callable[..., Any]
"""The `draw` of a composite strategy."""

_SMALL_FLOATS = (0.0, 0.5, 1.0, -1.0, 2.5, 0.001, 100.0, 1e300, -1e300, 3.141592653589793)
_STRINGS = st.text(alphabet="ab1-, Z", max_size=4) | st.sampled_from(["", "0x1f", "12", "-3", "é", "\u20ac"])


def sometimes(draw: Draw, one_in: int) -> bool:
    """True about once in `one_in` draws; shrinking goes to False, the plainer case."""
    return draw(st.integers(0, one_in - 1)) == one_in - 1


def literal(draw: Draw, type_: str) -> Expr:
    if type_ == INT:
        return Lit(INT, draw(st.integers(-3, 300) | st.sampled_from([0, 1, 255, 256, -1, 65535, 65536, 2**31, -2**15])))
    if type_ == FLOAT:
        return Lit(FLOAT, draw(st.sampled_from(_SMALL_FLOATS) | st.floats(-500, 500).map(lambda f: round(f, 3))))
    if type_ == BOOL:
        return Lit(BOOL, draw(st.booleans()))
    if type_ == STRING:
        return Lit(STRING, draw(_STRINGS))
    raise Unknown("no literal of bytes")


def _fallback(type_: str) -> Expr:
    return {INT: Lit(INT, 3), FLOAT: Lit(FLOAT, 1.5), BOOL: Lit(BOOL, True), STRING: Lit(STRING, "x")}[type_]


def guarded(e: Expr) -> Expr:
    """`e`, or a literal of its type where the checker would refuse to fold it."""
    if not e.const:
        return e
    try:
        constant_value(e)
    except Unknown:
        return _fallback(e.type)
    return e


def _leaves(scope: Scope, type_: str) -> list[Expr]:
    return [leaf for leaf in scope if flows(leaf.type, type_)]


def expression(draw: Draw, type_: str, scope: Scope, depth: int = 2) -> Expr:
    """A random well-typed expression of `type_` (an int where a float is asked, sometimes)."""
    leaves = _leaves(scope, type_)
    if type_ == BYTES:
        return draw(st.sampled_from(leaves))
    if depth <= 0 or draw(st.integers(0, 2)) == 0:  # a leaf (what shrinking goes to)
        if leaves and draw(st.integers(0, 2)):
            return draw(st.sampled_from(leaves))
        return literal(draw, type_)
    build = draw(st.sampled_from(_BUILDERS[type_]))
    return guarded(build(draw, scope, depth - 1))


def _variable(draw: Draw, type_: str, scope: Scope) -> Expr | None:
    """An expression reading a variable, so that it can fail at run time, not at check time."""
    leaves = [leaf for leaf in scope if leaf.type == type_ and not leaf.const]
    return draw(st.sampled_from(leaves)) if leaves else None


def _int_arith(draw: Draw, scope: Scope, depth: int) -> Expr:
    op = draw(st.sampled_from(["+", "-", "*", "//", "%", "&", "|", "^"]))
    return Binary(INT, op, expression(draw, INT, scope, depth), expression(draw, INT, scope, depth))


def _int_shift(draw: Draw, scope: Scope, depth: int) -> Expr:
    op = draw(st.sampled_from(["<<", ">>"]))
    count: Expr = Lit(INT, draw(st.integers(0, 12)))
    var = _variable(draw, INT, scope)
    if var is not None and draw(st.booleans()):  # a count read at run time, bounded (or not: may be negative)
        count = Binary(INT, draw(st.sampled_from(["&", "%"])), var, Lit(INT, draw(st.sampled_from([7, 15, -9]))))
    return Binary(INT, op, expression(draw, INT, scope, depth), count)


def _int_power(draw: Draw, scope: Scope, depth: int) -> Expr:
    exponent: Expr = Lit(INT, draw(st.integers(0, 3)))
    var = _variable(draw, INT, scope)
    if var is not None and sometimes(draw, 4):  # may be negative at run time
        exponent = Binary(INT, "%", var, Lit(INT, 5))
        if draw(st.booleans()):
            exponent = Binary(INT, "-", exponent, Lit(INT, 2))
    return Binary(INT, "**", expression(draw, INT, scope, depth), exponent)


def _int_unary(draw: Draw, scope: Scope, depth: int) -> Expr:
    return Unary(INT, draw(st.sampled_from(["-", "~"])), expression(draw, INT, scope, depth))


def _int_call(draw: Draw, scope: Scope, depth: int) -> Expr:
    which = draw(st.sampled_from(["abs", "min", "max", "clamp", "round", "int", "len", "int_le", "int_be",
                                  "from_nibbles"]))
    if which == "abs":
        return Call(INT, "abs", (expression(draw, INT, scope, depth),))
    if which in ("min", "max"):
        count = draw(st.integers(2, 3))
        return Call(INT, which, tuple(expression(draw, INT, scope, depth) for _ in range(count)))
    if which == "clamp":
        low = draw(st.integers(-10, 100))
        return Call(INT, "clamp", (expression(draw, INT, scope, depth), Lit(INT, low), Lit(INT, low + draw(st.integers(0, 200)))))
    if which == "round":
        return Call(INT, "round", (expression(draw, FLOAT, scope, depth),))
    if which == "int":
        text = _variable(draw, STRING, scope)
        source = text if text is not None and draw(st.booleans()) else expression(draw, draw(st.sampled_from([FLOAT, BOOL, INT])), scope, depth)
        return Call(INT, "int", (source,))
    if which in ("int_le", "int_be"):  # a float's bytes read as an int, of either sign
        return Call(INT, which, (_float_bytes(draw, scope, depth), Lit(BOOL, draw(st.booleans()))))
    if which == "from_nibbles":
        spread = Binary(INT, "&", expression(draw, INT, scope, depth), Lit(INT, 0xFFFF))
        return Call(INT, "from_nibbles", (Call(BYTES, "nibbles", (spread, Lit(INT, 4))),))
    sized = [leaf for leaf in scope if leaf.type in (STRING, BYTES)]
    return Call(INT, "len", (draw(st.sampled_from(sized)) if sized and draw(st.booleans()) else expression(draw, STRING, scope, depth),))


def _if(type_: str) -> Callable[..., Expr]:
    def build(draw: Draw, scope: Scope, depth: int) -> Expr:
        return IfElse(type_, expression(draw, BOOL, scope, depth), expression(draw, type_, scope, depth), expression(draw, type_, scope, depth))
    return build


def _float_arith(draw: Draw, scope: Scope, depth: int) -> Expr:
    op = draw(st.sampled_from(["+", "-", "*", "/", "//", "%"]))
    left = expression(draw, FLOAT, scope, depth)
    right = expression(draw, draw(st.sampled_from(NUMBERS)), scope, depth)
    if draw(st.booleans()):
        left, right = right, left
    if FLOAT not in (left.type, right.type) and op != "/":
        left = Call(FLOAT, "float", (left,))
    return Binary(FLOAT, op, left, right)


def _float_power(draw: Draw, scope: Scope, depth: int) -> Expr:
    exponent = Lit(FLOAT, draw(st.sampled_from([2.0, 0.5, -1.0]))) if draw(st.booleans()) else Lit(INT, 2)
    return Binary(FLOAT, "**", expression(draw, FLOAT, scope, depth), exponent)


def _float_bytes(draw: Draw, scope: Scope, depth: int) -> Expr:
    """The bytes of a float (which a float too large for 32 bits makes an error)."""
    return Call(BYTES, draw(st.sampled_from(list(_FLOAT_LAYOUTS))), (expression(draw, FLOAT, scope, depth),))


def _float_call(draw: Draw, scope: Scope, depth: int) -> Expr:
    which = draw(st.sampled_from(["abs", "min", "max", "float", "sqrt", "sin", "atan2", "hypot", "round", "clamp",
                                  "from_bytes"]))
    if which == "from_bytes":  # a float through its bytes: those of 32 bits round it
        spelt = _float_bytes(draw, scope, depth)
        assert isinstance(spelt, Call)
        return Call(FLOAT, "from_" + spelt.func, (spelt,))
    if which == "abs":
        return Call(FLOAT, "abs", (expression(draw, FLOAT, scope, depth),))
    if which in ("min", "max"):  # one float among ints: Python may still return the int
        return Call(FLOAT, which, (expression(draw, INT, scope, depth), expression(draw, FLOAT, scope, depth)))
    if which == "float":
        text = _variable(draw, STRING, scope)
        source = text if text is not None and draw(st.booleans()) else expression(draw, draw(st.sampled_from([INT, BOOL])), scope, depth)
        return Call(FLOAT, "float", (source,))
    if which == "round":
        return Call(FLOAT, "round", (expression(draw, FLOAT, scope, depth), Lit(INT, draw(st.integers(0, 3)))))
    if which == "clamp":
        return Call(FLOAT, "clamp", (expression(draw, FLOAT, scope, depth), Lit(FLOAT, -1.0), Lit(FLOAT, 1.0)))
    if which == "sqrt":
        var = _variable(draw, FLOAT, scope) or _variable(draw, INT, scope)
        return Call(FLOAT, "sqrt", (var if var is not None else Lit(FLOAT, 2.0),))
    count = 2 if which in ("atan2", "hypot") else 1
    return Call(FLOAT, which, tuple(expression(draw, FLOAT, scope, depth) for _ in range(count)))


def _compare(draw: Draw, scope: Scope, depth: int) -> Expr:
    kind = draw(st.sampled_from([INT, FLOAT, STRING, BOOL]))
    ops = ["==", "!="] if kind == BOOL else ["==", "!=", "<", "<=", ">", ">="]
    return Binary(BOOL, draw(st.sampled_from(ops)), expression(draw, kind, scope, depth), expression(draw, kind, scope, depth))


def _logic(draw: Draw, scope: Scope, depth: int) -> Expr:
    if sometimes(draw, 3):
        return Unary(BOOL, "not", expression(draw, BOOL, scope, depth))
    return Binary(BOOL, draw(st.sampled_from(["and", "or"])), expression(draw, BOOL, scope, depth), expression(draw, BOOL, scope, depth))


def _bool_call(draw: Draw, scope: Scope, depth: int) -> Expr:
    return Call(BOOL, "bool", (expression(draw, draw(st.sampled_from([INT, FLOAT, BOOL])), scope, depth),))


def _str_call(draw: Draw, scope: Scope, depth: int) -> Expr:
    return Call(STRING, "str", (expression(draw, draw(st.sampled_from([INT, FLOAT, BOOL, STRING])), scope, depth),))


def _str_hex(draw: Draw, scope: Scope, depth: int) -> Expr:
    """The hex digits of a float's bytes, in upper case."""
    return Call(STRING, "upper", (Call(STRING, "hex", (_float_bytes(draw, scope, depth),)),))


def _str_concat(draw: Draw, scope: Scope, depth: int) -> Expr:
    return Binary(STRING, "+", expression(draw, STRING, scope, depth), expression(draw, STRING, scope, depth))


_BUILDERS: dict[str, list[Callable[..., Expr]]] = {
    INT: [_int_arith, _int_arith, _int_shift, _int_power, _int_unary, _int_call, _int_call, _if(INT)],
    FLOAT: [_float_arith, _float_arith, _float_power, _float_call, _float_call, _if(FLOAT)],
    BOOL: [_compare, _compare, _logic, _bool_call, _if(BOOL)],
    STRING: [_str_call, _str_concat, _str_hex, _if(STRING)],
}


def fitting(draw: Draw, e: Expr, ok: Callable[[Any], bool], type_: str,
            low: float, high: float) -> Expr:
    """`e`, unless it is a constant the checker would refuse here (outside a range or a pack
    code): then a literal inside [low, high]."""
    if not e.const:
        return e
    try:
        if ok(constant_value(e)):
            return e
    except Unknown:
        pass
    if type_ == FLOAT:
        return Lit(FLOAT, float(draw(st.sampled_from([low, high, (low + high) / 2]))))
    return Lit(type_, draw(st.integers(int(low), int(high))))


# ---- struct formats ---------------------------------------------------------------------------------

_INT_CODES = "bBhHiIqQ"
_FLOAT_HOLDS = {"e": 65504.0, "f": 3.4028234663852886e38}  # the largest finite half and single floats


def code_range(code: str) -> tuple[int, int] | None:
    """The integers a struct code holds (None: not an integer code); `3s{24}`, bytes as one integer, its field's."""
    wide = re.fullmatch(r"\d+s\{(\d+)\}", code)
    if wide:
        return 0, (1 << int(wide.group(1))) - 1
    if code not in _INT_CODES:
        return None
    bits = 8 * struct.calcsize("<" + code)
    return (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if code.islower() else (0, (1 << bits) - 1)


@dataclass(frozen=True)
class Slot:
    """One value of a struct format: its code as written (`3s` for a string) and its type."""

    code: str
    type: str


def draw_slot(draw: Draw, type_: str | None = None, order: str = "=") -> Slot:
    """A value's code; in a format with a byte order, an integer may be bytes of a size struct lacks
    taken as one integer (`5s{40}`)."""
    if type_ is None:
        type_ = draw(st.sampled_from([INT, INT, INT, FLOAT, BOOL, STRING]))
    if type_ == INT and order in "<>!" and sometimes(draw, 8):
        size = draw(st.sampled_from([3, 5, 6, 7]))
        return Slot(f"{size}s{{{8 * size}}}", INT)
    if type_ == INT:
        return Slot(draw(st.sampled_from(_INT_CODES)), INT)
    if type_ == FLOAT:
        return Slot(draw(st.sampled_from("efd")), FLOAT)
    if type_ == BOOL:
        return Slot("?", BOOL)
    return Slot(f"{draw(st.integers(1, 3))}{draw(st.sampled_from('ssZ'))}", STRING)  # `Z`: read to its first NUL


def _struct_module(template: str) -> str:
    """A struct format as the struct module reads it: `NZ` (text to its first NUL) is `Ns` there, and
    bytes split into bit fields (`3s{24}`) their bytes."""
    return re.sub(r"\{[^{}]*\}", "", re.sub(r"(\d*)Z", r"\1s", template))


def struct_text(order: str, slots: Sequence[Slot], pad: int, rest: bool) -> str:
    return order + "".join(s.code for s in slots) + ("x" * pad) + ("*" if rest else "")


# ---- checksums ----------------------------------------------------------------------------------------

# Other spellings rdisc accepts for some of them.
SPELLINGS = {"crc16-modbus": "CRC-16/MODBUS", "crc16-xmodem": "crc16_xmodem", "crc8-maxim": "crc8-maxim-dow",
             "crc16-ccitt-false": "crc16-autosar", "crc32": "CRC-32/ISO-HDLC"}


def _reflect(value: int, width: int) -> int:
    return int(f"{value:0{width}b}"[::-1], 2)


def crc(data: bytes, width: int, poly: int, init: int, reflect: bool, xorout: int,
        reflect_out: bool | None = None) -> int:
    """A CRC bit by bit, as the Rocksoft model defines it (the output reflected as the input
    unless `reflect_out` says otherwise), one message bit at a time, so any width from 1 up."""
    full = (1 << width) - 1
    reg = init
    for byte in data:
        for bit in f"{byte:08b}"[::-1] if reflect else f"{byte:08b}":
            top = reg >> (width - 1) & 1
            reg = (reg << 1) & full
            if top ^ int(bit):
                reg ^= poly
    reflected = reflect if reflect_out is None else reflect_out
    return (_reflect(reg, width) if reflected else reg) ^ xorout


@dataclass(frozen=True)
class Checksum:
    """A checksum part: its algorithm as written, parameters, options, and the parts it covers."""

    algorithm: str
    kind: str  # sum | xor | lrc | fletcher8 | crc
    width: int
    options: tuple[str, ...]  # as written, `over` excluded
    over: tuple[str, ...]  # the names after `over`, as written
    first: int  # the parts covered, as indexes into the side
    last: int
    with_request: bool
    poly: int = 0
    init: int = 0
    reflect: bool = False
    xorout: int = 0
    inverted: bool = False
    mask: int | None = None
    reflect_out: bool | None = None  # None: as `reflect`
    seed: int = -1  # `seed SEEDS[FIELD]`: the index of the field in the side, whose value's byte is summed last

    def compute(self, data: bytes) -> int:
        full = (1 << self.width) - 1
        if self.kind == "sum":
            value = sum(data) & full
        elif self.kind == "lrc":
            value = -sum(data) & full
        elif self.kind == "fletcher8":
            ck_a = ck_b = 0
            for byte in data:
                ck_a = (ck_a + byte) % 256
                ck_b = (ck_b + ck_a) % 256
            value = ck_a + 256 * ck_b
        elif self.kind == "xor":
            value = 0
            for byte in data:
                value ^= byte
            value &= full
        else:
            value = crc(data, self.width, self.poly, self.init, self.reflect, self.xorout, self.reflect_out)
        if self.inverted:
            value = ~value & full
        if self.mask is not None:
            value &= self.mask
        return value


# ---- frames -------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Part:
    """One part of a frame's side."""

    kind: str  # header | literal | terminator | field | length | payload | checksum
    data: bytes = b""  # header, literal, terminator
    name: str = ""  # field
    fmt: str | None = None  # field, length, checksum (None: hex digits)
    value: Expr | None = None  # field, over the frame's parameters
    adjust: int = 0  # length
    check: Checksum | None = None
    trimmed: bool = False  # payload: `payload trimmed`, its trailing zero bytes not sent

    def text(self) -> str:
        if self.kind in ("header", "literal", "terminator"):
            return f"{self.kind} {bytes_literal(self.data)}"
        if self.kind == "field":
            assert self.value is not None
            return f'field {self.name} "{self.fmt}" = {self.value.text()}'
        if self.kind == "length":
            adjust = f" + {self.adjust}" if self.adjust > 0 else f" - {-self.adjust}" if self.adjust < 0 else ""
            return f'length "{self.fmt}" = payload{adjust}'
        if self.kind == "payload":
            return "payload trimmed" if self.trimmed else "payload"
        c = self.check
        assert c is not None
        fmt = f'"{self.fmt}"' if self.fmt is not None else "hex"
        over = f" over {' .. '.join(c.over)}" if c.over else ""
        options = "".join(" " + o for o in c.options)
        return f'checksum "{c.algorithm}" {fmt}{options}{over}'

    def size(self) -> int:
        if self.kind in ("header", "literal", "terminator"):
            return len(self.data)
        if self.kind == "checksum" and self.fmt is None:
            assert self.check is not None
            return (self.check.width + 3) // 4
        return struct.calcsize(self.fmt) if self.fmt else 0


@dataclass(frozen=True)
class Frame:
    """A frame: its parameters, its request and reply sides (the same parts when `shared`), its stuffing."""

    name: str
    params: tuple[str, ...]
    request: tuple[Part, ...]
    reply: tuple[Part, ...]
    shared: bool  # one list of parts for both directions
    stuffing: tuple[bytes, bytes] | None = None  # (escape, reserved)
    # `either when WHEN { } or { }` over its last parameter, to which primitives pass MODE: `request` and
    # `reply` are the layouts MODE chooses (the first alternatives when WHEN `holds`), the others the rest
    when: str = ""
    holds: bool = True
    other_request: tuple[Part, ...] = ()
    other_reply: tuple[Part, ...] = ()

    def text(self) -> str:
        params = f"({', '.join(f'{p}: int' for p in self.params)})" if self.params else ""
        lines = [f"frame {self.name}{params} {{"]
        if self.stuffing is not None:
            escape, reserved = self.stuffing
            lines.append(f"    stuff {bytes_literal(escape)} after {bytes_literal(reserved)}")
        if self.shared:
            lines += [f"    {p.text()}" for p in self.request]
        else:
            lines.append("    request { " + self._either(self.request, self.other_request) + " }")
            if self.reply:
                lines.append("    reply { " + self._either(self.reply, self.other_reply) + " }")
        return "\n".join(lines + ["}"])

    def _either(self, chosen: tuple[Part, ...], other: tuple[Part, ...]) -> str:
        if not other:
            return "  ".join(p.text() for p in chosen)
        first, second = (chosen, other) if self.holds else (other, chosen)
        return (f"either when {self.when} {{ " + "  ".join(p.text() for p in first) + " } or { "
                + "  ".join(p.text() for p in second) + " }")

    @property
    def acknowledges(self) -> bool:
        """A reply side without payload: read after every request."""
        return bool(self.reply) and not any(p.kind == "payload" for p in self.reply)

    @property
    def delimits(self) -> bool:
        """The reply's payload end is found without knowing its size: a length, or constant bytes after it."""
        kinds = [p.kind for p in self.reply]
        if "payload" not in kinds:
            return True
        at = kinds.index("payload")
        return "length" in kinds or (at + 1 < len(kinds) and kinds[at + 1] in ("literal", "terminator"))

    @property
    def listens(self) -> bool:
        """A request of the payload alone: an empty payload sends nothing."""
        return [p.kind for p in self.request] == ["payload"]

    def length_states(self, side: tuple[Part, ...], size: int) -> bool:
        """Whether the side's length field (if any) can state a payload of `size` bytes."""
        for part in side:
            if part.kind == "length":
                high = code_range(part.fmt.lstrip("<>") if part.fmt else "B")
                assert high is not None
                return max(0, -part.adjust) <= size <= high[1] - part.adjust
        return True

    def field_ranges(self) -> dict[str, tuple[int, int]]:
        """Per parameter, the range a constant argument must fit: the formats of the fields that are it."""
        ranges: dict[str, tuple[int, int]] = {}
        for part in self.request + self.reply:
            if part.kind != "field":
                continue
            low, high = code_range(part.fmt.lstrip("<>") if part.fmt else "B") or (0, 255)
            match part.value:  # the shapes `_field_value` draws
                case Name(name=name):
                    fits = (name, low, high)
                case Binary(op="+", left=Name(name=name), right=Lit(v=k)):
                    fits = (name, low - k, high - k)
                case IfElse(cond=Binary(op="<=", left=Name(name=name), right=Lit(v=most))):
                    fits = (name, low, min(high, most))  # above it, the field is refused
                case _:
                    continue
            name, low, high = fits
            old = ranges.get(name, (low, high))
            ranges[name] = (max(old[0], low), min(old[1], high))
        return ranges


def _pack_int(fmt: str, value: int) -> tuple[bytes, bool]:
    """An integer in a one-code struct format, wrapped into its range if it does not fit (then
    False: a spoilt value stays spoilt)."""
    low, high = code_range(fmt.lstrip("<>!=")) or (0, 255)
    fits = low <= value <= high
    return struct.pack(fmt, value if fits else (value - low) % (high - low + 1) + low), fits


@dataclass(frozen=True)
class Wire:
    """Bytes a device sends, and whether they are a reply the contract says must be accepted."""

    data: bytes
    valid: bool


def encode_side(frame: Frame, side: tuple[Part, ...], payload: bytes, fields: Mapping[str, Any],
                request: bytes = b"", lower_hex: bool = False, size_known: bool = True) -> Wire:
    """A side's bytes around `payload` (stuffed first), as a device writes them; valid unless a field
    or the length does not fit its format, or the payload's end would be found too early (the
    constant after it inside it, when no length or fixed size says where it ends)."""
    valid = True
    if any(part.kind == "payload" and part.trimmed for part in side):  # MAVLink 2: trailing zeros not sent
        kept = payload.rstrip(b"\0") or payload[:1]
        valid = kept == payload or size_known  # else the reader cannot zero-fill it to its decoding's size
        payload = kept
    if frame.stuffing is not None:
        escape, reserved = frame.stuffing
        payload = payload.replace(reserved, reserved + escape)
    chunks: list[bytes] = []
    for i, part in enumerate(side):
        if part.kind in ("header", "literal", "terminator"):
            chunks.append(part.data)
        elif part.kind == "field":
            assert part.value is not None and part.fmt is not None
            try:
                value = part.value.value(fields)
            except Unknown:
                value = None
            packed, fits = _pack_int(part.fmt, value) if isinstance(value, int) else (b"\0" * part.size(), False)
            chunks.append(packed)
            valid = valid and fits
        elif part.kind == "length":
            assert part.fmt is not None
            packed, fits = _pack_int(part.fmt, len(payload) + part.adjust)
            chunks.append(packed)
            valid = valid and fits
        elif part.kind == "payload":
            chunks.append(payload)
            delimiter = side[i + 1].data if i + 1 < len(side) else b""
            if not size_known and not any(p.kind == "length" for p in side) and delimiter:
                valid = valid and (payload + delimiter).find(delimiter) == len(payload)
        else:
            c = part.check
            assert c is not None
            covered = b"".join(chunks[c.first : c.last + 1])
            if c.seed >= 0:  # a byte summed after the parts, never sent; a field value without one is refused
                keyed = side[c.seed].value
                assert keyed is not None
                try:
                    key = keyed.value(fields)
                except Unknown:
                    key = None
                valid = valid and key in SEEDS
                covered += bytes([SEEDS[key]]) if key in SEEDS else b""
            value = c.compute(request + covered if c.with_request else covered)
            if part.fmt is not None:
                chunks.append(_pack_int(part.fmt, value)[0])
            else:
                digits = b"%0*X" % ((c.width + 3) // 4, value)
                chunks.append(digits.lower() if lower_hex else digits)
    return Wire(b"".join(chunks), valid)


_FIELD_FORMATS = ["B", "B", "b", "<H", ">H", ">h", "<I"]
_ROLE_NAMES = {"header", "literal", "terminator", "length", "payload"}


def _constant_bytes(draw: Draw, low: int, high: int) -> bytes:
    favourites = st.sampled_from([b"\xff\xff", b"\xaa", b"$", b"\x55\x55", b"\r\n", b"*", b"\x02", b"\x03",
                                  b"\xff", b"\x7e", b"\xfd", b"\n\x00"])
    data = draw(favourites | st.binary(min_size=low, max_size=high))
    return data[:high] if len(data) >= low else data + b"\x00" * (low - len(data))


def _field_value(draw: Draw, params: tuple[str, ...], fmt: str) -> Expr:
    low, high = code_range(fmt.lstrip("<>")) or (0, 255)
    if params and draw(st.integers(0, 3)):
        name = Name(INT, draw(st.sampled_from(params)))
        shape = draw(st.integers(0, 5))
        if shape == 1:
            return Binary(INT, "+", name, Lit(INT, draw(st.integers(1, 3))))
        if shape == 2:
            return Binary(INT, "&", name, Lit(INT, 0x7F))
        if shape == 3:  # as the AX-12's frame refuses an ID above the broadcast ID
            refused = Lit(INT, (1 << 64) - 1)  # the largest int: no field's format takes it
            return IfElse(INT, Binary(BOOL, "<=", name, Lit(INT, min(high, 253))), name, refused)
        return name
    return Lit(INT, draw(st.integers(max(low, -5), min(high, 300))))


def _checksum(draw: Draw, index: int, side: list[Part], names: dict[str, int],
              reply_side: bool) -> Part | None:
    """A checksum at position `index` over parts already drawn; None if nothing can be covered."""
    first_default = 1 if side and side[0].kind == "header" else 0
    over: tuple[str, ...] = ()
    with_request = False
    style = draw(st.integers(0, 3))
    if style == 1 and names:  # over A .. B, or over A
        a = draw(st.sampled_from(sorted(names)))
        later = sorted(n for n in names if names[n] >= names[a])
        b = draw(st.sampled_from(later))
        over = (a,) if a == b and draw(st.booleans()) else (a, b)
        first, last = names[a], names[b]
    elif style == 2 and reply_side and names:  # over request .. B
        b = draw(st.sampled_from(sorted(names)))
        over, first, last, with_request = ("request", b), 0, names[b], True
    else:
        if first_default > index - 1:
            return None
        first, last = first_default, index - 1
    kind = draw(st.sampled_from(["sum", "sum", "xor", "lrc", "fletcher8", "crc", "catalogue", "catalogue"]))
    hex_digits = sometimes(draw, 5)
    options: list[str] = []
    inverted = sometimes(draw, 4)
    mask = draw(st.sampled_from([0x7F, 0xFF, 0x3FFF, 0x0F])) if sometimes(draw, 6) else None
    if kind == "catalogue":
        name = draw(st.sampled_from(sorted(CATALOGUE)))
        width, poly, init, reflect, xorout = CATALOGUE[name]
        algorithm = SPELLINGS.get(name, name) if sometimes(draw, 4) else name
        fmt = None if hex_digits else draw(st.sampled_from(_formats_holding(width)))
        check = Checksum(algorithm, "crc", width, (), (), 0, 0, False, poly, init, reflect, xorout)
    elif kind == "crc":
        width = draw(st.sampled_from([8, 16, 32, 3, 7, 12, 24, 64]))
        poly = draw(st.sampled_from([0x07, 0x31, 0x1021, 0x8005, 0x04C11DB7, 0x1D])) & ((1 << width) - 1) or 0x03
        init = draw(st.sampled_from([0, (1 << width) - 1, 0x1D0F & ((1 << width) - 1)]))
        xorout = draw(st.sampled_from([0, (1 << width) - 1]))
        reflect, reflect_out = draw(st.booleans()), draw(st.booleans())
        fmt = None if hex_digits else draw(st.sampled_from(_formats_holding(width)))
        options += [f"poly {poly:#x}"]
        options += [f"init {init:#x}"] if init or draw(st.booleans()) else []
        options += [f"xorout {xorout:#x}"] if xorout else []
        options += [{(True, True): "reflect", (True, False): "reflect in", (False, True): "reflect out"}[
            (reflect, reflect_out)]] if reflect or reflect_out else []
        if fmt is None or width != 8 or draw(st.booleans()):
            options.append(f"width {width}")
        check = Checksum("crc", "crc", width, (), (), 0, 0, False, poly, init, reflect, xorout,
                         reflect_out=reflect_out)
    elif kind == "fletcher8":
        fmt = None if hex_digits else draw(st.sampled_from(["<H", ">H", "<I"]))
        check = Checksum(kind, kind, 16, (), (), 0, 0, False)
    else:
        fmt = None if hex_digits else draw(st.sampled_from(["B", "B", ">H", "<H", ">I"]))
        size_bits = 8 * struct.calcsize(fmt) if fmt else 8
        width = size_bits
        if sometimes(draw, 4):
            width = draw(st.integers(4 if fmt is None else 1, size_bits if fmt else 16))
            options.append(f"width {width}")
        check = Checksum(kind, kind, width, (), (), 0, 0, False)
    options += ["inverted"] if inverted else []
    options += [f"mask {mask:#x}"] if mask is not None else []
    keyed = [i for i, part in enumerate(side) if part.kind == "field"]
    seed = draw(st.sampled_from(keyed)) if keyed and sometimes(draw, 5) else -1
    options += [f"seed SEEDS[{side[seed].name}]"] if seed >= 0 else []
    order = draw(st.permutations(options))
    check = Checksum(check.algorithm, check.kind, check.width, tuple(order), over, first, last, with_request,
                     check.poly, check.init, check.reflect, check.xorout, inverted, mask, check.reflect_out, seed)
    return Part("checksum", fmt=fmt, check=check)


SEEDS = {key: (key * 37 + 11) & 0xFF for key in range(256)}  # a checksum's seeds (MAVLink 2's CRC_EXTRA)


def _formats_holding(width: int) -> list[str]:
    """The one-integer struct formats a checksum of `width` bits fits."""
    return [fmt for fmt in ("B", ">H", "<H", ">I", "<I", ">Q", "<Q") if struct.calcsize(fmt) * 8 >= width]


def _side(draw: Draw, params: tuple[str, ...], reply_side: bool, payload: bool, shared: bool,
          field_names: tuple[str, ...] = ("d0", "d1", "d2"), stuffed: bool = False) -> tuple[Part, ...]:
    """One side's parts: [header] parts... [payload parts...] [terminator]. How the payload's end
    is found is drawn first (a length field, constant bytes right after it, or its size alone),
    since a reply's delimiting decides which primitives may use the frame."""
    parts: list[Part] = []
    names: dict[str, int] = {}

    def add(part: Part) -> None:
        if part.kind in _ROLE_NAMES:
            names.setdefault(part.kind, len(parts))
        elif part.kind == "field":
            names[part.name] = len(parts)
        parts.append(part)

    def some(kinds: list[str], count: int) -> None:
        for _ in range(count):
            kind = draw(st.sampled_from(kinds))
            if kind == "field":
                fmt = draw(st.sampled_from(_FIELD_FORMATS))
                add(Part("field", name=draw(st.sampled_from(field_names)), fmt=fmt,
                         value=_field_value(draw, params, fmt)))
            elif kind == "literal":
                add(Part("literal", data=_constant_bytes(draw, 1, 2)))
            else:
                check = _checksum(draw, len(parts), parts, names, reply_side and not shared)
                if check is not None:
                    add(check)

    if draw(st.integers(0, 4)) >= 2:
        add(Part("header", data=_constant_bytes(draw, 1, 3)))
    endings = ["length", "literal", "terminator"] + ["size"] * (not stuffed)  # a stuffed payload's size says nothing
    ending = draw(st.sampled_from(endings)) if payload else "none"
    before = draw(st.integers(0, 2))
    length_at = draw(st.integers(0, before)) if ending == "length" else -1
    for i in range(before + 1):
        if i == length_at:
            add(Part("length", fmt=draw(st.sampled_from(["B", "B", "<H", ">H"])),
                     adjust=draw(st.sampled_from([0, 0, 1, 2, -1]))))
        if i < before:
            some(["field", "field", "field", "literal", "checksum"], 1)
    if length_at >= 0 and sometimes(draw, 4):  # a sub-payload's length too (Kobuki): it states what the first does
        first = next(p for p in parts if p.kind == "length")
        add(draw(st.sampled_from([first, Part("length", fmt="<I")])))
    if payload:
        add(Part("payload", trimmed=ending == "length" and sometimes(draw, 4)))
        if ending == "literal":
            add(Part("literal", data=_constant_bytes(draw, 1, 2)))
        if ending != "terminator":
            some(["field", "literal", "checksum", "checksum"], draw(st.integers(0, 2)))
    elif not parts:
        add(Part("literal", data=_constant_bytes(draw, 1, 2)))
    if ending == "terminator" or (ending != "none" and sometimes(draw, 4)):
        add(Part("terminator", data=_constant_bytes(draw, 1, 2)))
    return tuple(parts)


@st.composite
def frames(draw: Draw, name: str) -> Frame:
    """A frame: shared parts or a request and a reply side (with a payload, or an acknowledgement,
    or none), sometimes stuffed, sometimes a listener's (`request { payload }`)."""
    params = tuple(f"q{i}" for i in range(draw(st.integers(0, 2))))
    stuffing = None
    if sometimes(draw, 4):
        stuffing = (_constant_bytes(draw, 1, 1), _constant_bytes(draw, 1, 2))
    stuffed = stuffing is not None
    if sometimes(draw, 3):
        parts = _side(draw, params, False, True, True, stuffed=stuffed)
        return Frame(name, params, parts, parts, True, stuffing)
    listener = stuffing is None and sometimes(draw, 5)
    request = (Part("payload"),) if listener else _side(draw, params, False, True, False)
    reply_kind = draw(st.sampled_from(["payload", "payload", "payload", "ack", "none"]))
    if listener:
        reply_kind = "payload"
    # a reply's fields often have the request's names, with the same value or another
    names = tuple(sorted({p.name for p in request if p.kind == "field"})) or ("d0", "d1")
    reply = () if reply_kind == "none" else _side(draw, params, True, reply_kind == "payload", False, names, stuffed)
    if listener or not sometimes(draw, 4) or (stuffing is not None and stuffing[1] in _OTHER_HEADER):
        return Frame(name, params, request, reply, False, stuffing)
    # layouts chosen by a setting: the other alternative, another header before the same parts
    sides = draw(st.sampled_from(["request", "reply", "both"] if reply else ["request"]))
    holds, op = draw(st.booleans()), draw(st.sampled_from(["==", "!="]))
    other = draw(st.sampled_from([k for k in range(4) if (k == MODE[1]) == (holds == (op == "=="))]))
    return Frame(name, (*params, "qm"), request, reply, False, stuffing, f"qm {op} {other}", holds,
                 _other_layout(request) if sides != "reply" else (), _other_layout(reply) if sides != "request" else ())


_OTHER_HEADER = b"\xa5\x5a"


def _other_layout(side: tuple[Part, ...]) -> tuple[Part, ...]:
    """An alternative to `side` that MODE does not choose: another header, then the same parts (so the
    same payloads fit it, and its reader would refuse the chosen layout's bytes)."""
    if side and side[0].kind == "header":
        return (Part("header", _OTHER_HEADER if side[0].data != _OTHER_HEADER else b"\x5a\xa5"), *side[1:])
    return (Part("header", _OTHER_HEADER), *side)


# ---- replies: decodings, tables, post-actions ----------------------------------------------------------------


@dataclass(frozen=True)
class RegexToken:
    """A piece of a generated regex: the pattern text and the kind of text it matches."""

    pattern: str
    kind: str  # literal | digits | signed | letters | maybe_digits | word | decimal
    text: str = ""  # a literal's text


_GROUPS = [("(\\d+)", "digits"), ("(-?\\d+)", "signed"), ("([A-Z]+)", "letters"), ("(\\d*)", "maybe_digits"),
           ("(\\w+)", "word"), ("([\\d.]+)", "decimal")]
_SEPARATORS = [",", ";", ":", "=", "#!", " "]  # none matches a group's characters: each one fences
# the groups beside it, so that no regex can backtrack without bound (the checker refuses those)


@dataclass(frozen=True)
class Decoding:
    kind: str  # unpack | regex
    template: str
    types: tuple[str, ...]  # of out[i]
    size: int | None = None  # unpack without `*`: its bytes
    tokens: tuple[RegexToken, ...] = ()

    def text(self) -> str:
        if self.kind == "unpack":
            return f'unpack "{self.template}"'
        return f'regex r"{self.template}"'


@st.composite
def decodings(draw: Draw, fixed: bool = False, rest: bool | None = None) -> Decoding:
    """An `unpack` (fixed size when `fixed`; ending in `*` when `rest`) or a `regex`."""
    if fixed or draw(st.integers(0, 3)):
        order = draw(st.sampled_from(["<", ">", "!", "="]))
        slots = [draw_slot(draw, order=order) for _ in range(draw(st.integers(0 if not fixed else 1, 3)))]
        pad = draw(st.integers(0, 1)) if sometimes(draw, 6) else 0
        tail = False if fixed else (sometimes(draw, 4) if rest is None else rest)
        if not slots and not tail and not pad:
            slots = [Slot("B", INT)]
        template = struct_text(order, slots, pad, tail)
        size = struct.calcsize(_struct_module(template.rstrip("*")))
        types = tuple(s.type for s in slots) + ((BYTES,) if tail else ())
        return Decoding("unpack", template, types, None if tail else size)
    tokens: list[RegexToken] = []
    for i in range(draw(st.integers(1, 4))):
        if i % 2 == 0:
            pattern, kind = draw(st.sampled_from(_GROUPS))
            tokens.append(RegexToken(pattern, kind))
        else:
            text = draw(st.sampled_from(_SEPARATORS))
            tokens.append(RegexToken(re.escape(text), "literal", text))
    anchor = "^" if draw(st.booleans()) else ""
    end = draw(st.sampled_from(["", "\\s*$", "$"]))
    template = anchor + "".join(t.pattern for t in tokens) + end
    groups = sum(1 for t in tokens if t.kind != "literal")
    return Decoding("regex", template, (STRING,) * groups, None, tuple(tokens))


def regex_text(decoding: Decoding, material: bytes) -> bytes:
    """Text the decoding's regex matches, its values taken from `material`."""
    out = []
    data = list(material) or [7]
    for i, token in enumerate(decoding.tokens):
        n = data[i % len(data)]
        if token.kind == "literal":
            out.append(token.text)
        elif token.kind == "digits":
            out.append(str(n * 37 % 1000))
        elif token.kind == "signed":
            out.append(("-" if n & 1 else "") + str(n * 13 % 500))
        elif token.kind == "letters":
            out.append("".join(chr(65 + (n >> k) % 26) for k in range(1 + n % 3)))
        elif token.kind == "maybe_digits":
            out.append("" if n % 3 == 0 else str(n))
        elif token.kind == "word":
            out.append(["0x1f", "abc", "12", "x_1", "inf", "nan", "1_0", "0b11"][n % 8])
        else:
            out.append(["1.5", "12", "3.", ".", "0.25"][n % 5])
    return "".join(out).encode("latin-1")


def payload_for(decoding: Decoding | None, material: bytes) -> bytes:
    """Bytes the decoding decodes: its fixed size (then the rest, for `*`) or regex text."""
    if decoding is None:
        return b""
    if decoding.kind == "regex":
        return regex_text(decoding, material)
    fixed = struct.calcsize(_struct_module(decoding.template.rstrip("*")))
    head = (material * (fixed // max(len(material), 1) + 1))[:fixed] if material else b"\x00" * fixed
    return head + (material[fixed:] if decoding.size is None else b"")


@dataclass(frozen=True)
class Reply:
    """A decoding and its post-actions (state variable, value)."""

    decoding: Decoding
    actions: tuple[tuple[str, Expr], ...] = ()

    def text(self) -> str:
        return self.decoding.text() + actions_text(self.actions)


def actions_text(actions: tuple[tuple[str, Expr], ...]) -> str:
    if not actions:
        return ""
    return " { " + "  ".join(f"{target} = {value.text()}" for target, value in actions) + " }"


@dataclass(frozen=True)
class When(Expr):
    """A post-action's value and its condition: `value when COND` (stored only if COND holds)."""

    stored: Expr
    condition: Expr

    def text(self) -> str:
        return f"{self.stored.text()} when {self.condition.text()}"

    @property
    def const(self) -> bool:
        return False

    def value(self, env: Mapping[str, Any]) -> Any:
        raise NotImplementedError("a post-action's condition is not an expression")


def draw_actions(draw: Draw, states: Mapping[str, str], scope: Scope) -> tuple[tuple[str, Expr], ...]:
    targets = draw(st.lists(st.sampled_from(sorted(states)), max_size=3, unique=True)) if states else []
    return tuple((t, _conditioned(draw, expression(draw, states[t], scope, 2), scope)) for t in targets)


def _conditioned(draw: Draw, value: Expr, scope: Scope) -> Expr:
    """A post-action's value, sometimes made only when a condition holds (`when COND`)."""
    return When(value.type, value, expression(draw, BOOL, scope, 1)) if sometimes(draw, 4) else value


# ---- the elements of a description ------------------------------------------------------------------


@dataclass(frozen=True)
class Param:
    name: str
    type: str
    low: float | None = None
    high: float | None = None

    def text(self) -> str:
        bounds = f" in {number_text(self.low)}..{number_text(self.high)}" if self.low is not None else ""
        return f"{self.name}: {self.type}{bounds}"

    def accepts(self, value: Any) -> bool:
        """Whether a constant argument passes the checker's range check."""
        if self.low is None or self.high is None or self.type not in NUMBERS:
            return True
        return isinstance(value, (int, float)) and self.low <= value <= self.high


@dataclass(frozen=True)
class Primitive:
    name: str
    params: tuple[Param, ...]
    connection: str
    encoding: str  # pack | format
    template: str
    args: tuple[Expr, ...]
    reply: Reply | None = None
    actions: tuple[tuple[str, Expr], ...] = ()  # without a reply (after the write or acknowledgement)
    key: str | None = None  # reply table by this parameter
    tag: str | None = None  # reply table by a tag of this struct format
    entries: tuple[tuple[int, Reply], ...] = ()
    frame: Frame | None = None
    frame_args: tuple[Expr, ...] = ()
    skip: bool = False
    timeout_ms: int | None = None
    lasts: tuple[int | None, ...] = ()  # a tag table's entries' last values (`value..last`), None for one value
    retries: int = 0  # `retry N`: resends after a timeout or a mismatched reply
    error: bytes = b""  # `error "MARKER" unpack "B"`: the bytes an unframed error reply starts with
    nested: tuple[int, int] | None = None  # (an entry, a sub-tag): that entry a nested table `tag "B" { SUB: ... }`
    each_args: tuple[Expr, ...] = ()  # `replies eid in ids frame F(each_args)`: a reply for each element of `ids`
    refused: int | None = None  # `error when out[0] == N`: a reply whose first byte is N is the device's error

    def text(self) -> str:
        clauses = [f"on {self.connection}"]
        if self.frame is not None:
            args = f"({', '.join(a.text() for a in self.frame_args)})" if self.frame.params else ""
            clauses.append(f"frame {self.frame.name}{args}")
        clauses.append(f"{self.encoding} {string_literal(self.template)} ({', '.join(a.text() for a in self.args)})")
        if self.reply is not None:
            clauses.append(self.reply.decoding.text())
        if self.skip:
            clauses.append("skip unmatched")
        if self.timeout_ms is not None:
            clauses.append(f"timeout {self.timeout_ms} ms")
        if self.retries:
            clauses.append(f"retry {self.retries}")
        if self.each_args:
            assert self.frame is not None
            clauses.append(f"replies {EACH_VAR} in {self.params[-1].name} frame {self.frame.name}"
                           f"({', '.join(a.text() for a in self.each_args)})")
        if self.error:
            clauses.append(f'error {bytes_literal(self.error)} unpack "B"')
        if self.refused is not None:
            clauses.append(f"error when out[0] == {self.refused}")
        if self.key is not None or self.tag is not None:
            head = f"reply {self.key}" if self.key is not None else f'reply tag "{self.tag}"'
            entries = "\n".join(f"    {value}{'' if last == value else f'..{last}'}: {self.entry_text(at, reply)}"
                                for at, ((value, last), (_, reply)) in enumerate(zip(self.values(), self.entries)))
            clauses.append(f"{head} {{\n{entries}\n}}")
        actions = self.reply.actions if self.reply is not None else self.actions
        params = ", ".join(p.text() for p in self.params)
        return f"primitive {self.name}({params}) " + " ".join(clauses) + actions_text(actions)

    def entry_text(self, at: int, reply: Reply) -> str:
        """A table entry's reply, or its nested table of one entry."""
        if self.nested is None or self.nested[0] != at:
            return reply.text()
        return f'tag "B" {{\n        {self.nested[1]}: {reply.text()}\n    }}'

    @property
    def framed_reply(self) -> bool:
        return self.frame is not None and bool(self.frame.reply)

    @property
    def listens(self) -> bool:
        """Sends nothing (an empty request, framed by nothing but its payload): its reply is what comes next."""
        return self.template == "" and (self.frame is None or self.frame.listens)

    @property
    def reads(self) -> bool:
        """Whether it reads a reply (a decoding, a table, or an acknowledgement)."""
        return (self.reply is not None or bool(self.entries)
                or (self.frame is not None and self.frame.acknowledges))

    def values(self) -> list[tuple[int, int]]:
        """Each reply table entry's first and last value."""
        lasts = self.lasts or (None,) * len(self.entries)
        return [(v, v if last is None else last) for (v, _), last in zip(self.entries, lasts)]

    def decoding_for(self, values: Mapping[str, Any], choice: int) -> tuple[Decoding | None, bytes]:
        """The decoding of the reply to this call and the tag bytes before it."""
        if self.key is not None:
            key = values.get(self.key)
            found = [reply for value, reply in self.entries if value == key]
            return (found[0].decoding if found else None), b""
        if self.tag is not None:
            values = self.values()
            at = choice % (len(self.entries) + 1)
            if at == len(self.entries):  # a tag with no entry
                return None, _pack_int(self.tag, max(last for _, last in values) + 1)[0]
            (value, last), (_, reply) = values[at], self.entries[at]
            value += choice // (len(self.entries) + 1) % (last - value + 1)  # one of a range's
            if self.nested is not None and self.nested[0] == at:  # then the nested table's tag
                return reply.decoding, struct.pack(self.tag, value) + bytes([self.nested[1]])
            return reply.decoding, struct.pack(self.tag, value)
        return (self.reply.decoding if self.reply is not None else None), b""


@dataclass(frozen=True)
class CallStmt:
    primitive: Primitive
    args: tuple[Expr, ...]
    priority: int = 0

    def text(self) -> str:
        priority = f" priority {self.priority}" if self.priority else ""
        return f"{self.primitive.name}({', '.join(a.text() for a in self.args)}) delay 0 ms{priority}"


@dataclass(frozen=True)
class Interface:
    name: str
    params: tuple[Param, ...]
    calls: tuple[CallStmt, ...]
    periodic: bool = False
    triggers: str | None = None
    adhoc_word: bool = False  # `adhoc` written out (the default)
    rate: int | None = None  # `periodic N Hz`: its own thread's rate, under `threading multiple`

    def text(self) -> str:
        kind = " periodic" if self.periodic else (" adhoc" if self.adhoc_word else "")
        kind += f" {self.rate} Hz" if self.rate is not None else ""
        triggers = f" triggers {self.triggers}" if self.triggers else ""
        body = "\n".join(f"    {c.text()}" for c in self.calls)
        params = ", ".join(p.text() for p in self.params)
        return f"interface {self.name}({params}){kind}{triggers} {{\n{body}\n}}"

    def run_order(self) -> tuple[CallStmt, ...]:
        return tuple(sorted(self.calls, key=lambda c: c.priority))

    def read_names(self) -> list[str]:
        """The names its calls' arguments read, in the order it runs them."""
        return [n for c in self.run_order() for a in c.args for n in names_read(a)]

    @property
    def connection(self) -> str | None:
        """The connection a periodic interface belongs to: its first call's primitive's."""
        return self.calls[0].primitive.connection if self.calls else None


@dataclass(frozen=True)
class Hook:
    interface: Interface
    args: tuple[Expr, ...]

    def text(self) -> str:
        return f"{self.interface.name}({', '.join(a.text() for a in self.args)})"


@dataclass(frozen=True)
class Connection:
    name: str
    terminator: str | None = None
    startup: Hook | None = None
    terminate: Hook | None = None
    keepalive: Hook | None = None
    threading: str = "single"  # single | dual | multiple

    def text(self) -> str:
        lines = ["baud 9600", f"threading {self.threading} at 50 Hz"]
        if self.terminator is not None:
            lines.append(f"terminator {string_literal(self.terminator)}")
        if self.startup is not None:
            lines.append(f"startup {self.startup.text()}")
        if self.terminate is not None:
            lines.append(f"terminate {self.terminate.text()}")
        if self.keepalive is not None:
            lines.append(f"keepalive {self.keepalive.text()} every 3600 s")
        return f"connection {self.name}: serial {{\n" + "\n".join(f"    {x}" for x in lines) + "\n}"

    def line_end(self) -> bytes:
        return (self.terminator or "\n").encode("latin-1")


def matrix_text(rows: Sequence[Sequence[float]]) -> str:
    """A number or a matrix as RDIS writes them: `0.5`, `[1, 0.05; 0, 1]`."""
    if len(rows) == 1 and len(rows[0]) == 1:
        return number_text(rows[0][0]).strip("()")
    return "[" + "; ".join(", ".join(repr(x) for x in row) for row in rows) + "]"


Matrix = tuple[tuple[float, ...], ...]


@dataclass(frozen=True)
class Kalman:
    """`filter FIELD kalman { ... }`: a linear filter of n states over a float field (one value)."""

    field: str
    state: tuple[float, ...]
    transition: Matrix
    process: Matrix
    measurement: Matrix
    noise: float
    covariance: Matrix | None = None

    def text(self) -> str:
        items = [f"state {matrix_text((self.state,))}"]
        if self.covariance is not None:
            items.append(f"covariance {matrix_text(self.covariance)}")
        items += [f"transition {matrix_text(self.transition)}", f"process {matrix_text(self.process)}",
                  f"measurement {matrix_text(self.measurement)}", f"noise {matrix_text(((self.noise,),))}"]
        return f"filter {self.field} kalman {{ {'  '.join(items)} }}"


@dataclass(frozen=True)
class Output:
    name: str
    adapter: str
    fields: tuple[tuple[str, Expr], ...]
    noise: tuple[tuple[str, float], ...] = ()  # `noise FIELD DEVIATION` (thesis §7.2.3)
    filters: tuple[Kalman, ...] = ()

    def text(self) -> str:
        items = [f"{n} = {v.text()}" for n, v in self.fields]
        items += [f"noise {n} {matrix_text(((d,),))}" for n, d in self.noise]
        items += [k.text() for k in self.filters]
        return f"output {self.name}: {self.adapter} {{ {'  '.join(items)} }}"

    def read_names(self) -> list[str]:
        """The names its fields read, in order."""
        return [n for _, e in self.fields for n in names_read(e)]


@dataclass(frozen=True)
class Actuated:
    """A joint of the body driven by an actuator (thesis §7.2.6): a servo's position or a wheel's
    velocity, commanded through a primitive of its own (`pN(a0: int in LOW..HIGH)`, 100 counts a unit)."""

    index: int
    kind: str  # servo | wheel
    primitive: Primitive
    items: tuple[tuple[str, float], ...]  # velocity, acceleration, effort

    def text(self) -> str:
        i, servo = self.index, self.kind == "servo"
        joint = (f"joint j{i}: revolute base -> l{i} {{ axis [0, 0, 1]  limit -1..1  velocity 2  effort 1 }}" if servo
                 else f"joint j{i}: continuous base -> l{i} {{ axis [0, 1, 0]  velocity 10  effort 1 }}")
        quantity, offset = ("position", 500) if servo else ("velocity", 0)
        items = "  ".join(f"{name} {number_text(value)}" for name, value in self.items)
        return "\n".join([
            f"link l{i} {{ mass 0.1  inertia [0.001, 0.001, 0.001] }}", joint,
            f"actuator m{i}: {self.kind} {{ {items} }}",
            f"transmission t{i}: j{i} actuator m{i} {{",
            f"    command {quantity} to {self.primitive.name}.a0 {{",
            f"        raw = round({quantity} * 100) + {offset}",
            f"        {quantity} = (raw - {offset}) / 100.0",
            "    }",
            "}"])


@dataclass(frozen=True)
class Sensor:
    """`sensor NAME: TYPE from PRIMITIVE() cache N ms [noise D]` (thesis §7.2.4): the primitive's one value."""

    name: str
    type: str
    primitive: Primitive
    cache_ms: int
    noise: float | None = None

    def text(self) -> str:
        noise = f" noise {matrix_text(((self.noise,),))}" if self.noise is not None else ""
        return f"sensor {self.name}: {self.type} from {self.primitive.name}() cache {self.cache_ms} ms{noise}"


@dataclass(frozen=True)
class Input:
    name: str
    adapter: str
    interface: Interface
    args: tuple[Expr, ...]

    def text(self) -> str:
        return f"input {self.name}: {self.adapter} -> {self.interface.name}({', '.join(a.text() for a in self.args)})"

    def read_names(self) -> list[str]:
        return [n for a in self.args for n in names_read(a)]


@dataclass(frozen=True)
class Description:
    """A whole description: its specs, and its text."""

    states: tuple[tuple[str, str, Any], ...]  # name, type, initial value
    constants: tuple[Named, ...]
    frames: tuple[Frame, ...]
    connections: tuple[Connection, ...]
    primitives: tuple[Primitive, ...]
    interfaces: tuple[Interface, ...]
    outputs: tuple[Output, ...]
    inputs: tuple[Input, ...]
    sensors: tuple[Sensor, ...] = ()
    state_noise: tuple[tuple[str, float, str], ...] = ()  # a state variable's noise: its deviation, its unit
    actuated: tuple[Actuated, ...] = ()  # the body: a base link, and a joint driven by an actuator each
    text: str = field(default="", compare=False)

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:  # how hypothesis shows a failing example
        printer.text("\n" + self.text)

    def render(self) -> str:
        lines = ['robot generated { author "tests/properties/descriptions.py" }', ""]
        for c in self.constants:
            if "." in c.name:
                continue
            lines.append(f"const {c.name} = {Lit(c.type, c.v).text()}")
        members = [c for c in self.constants if "." in c.name]
        if members:
            lines.append("enum E0 { " + ", ".join(f"{m.name.split('.')[1]} = {m.v}" for m in members) + " }")
        noise = {name: (deviation, unit) for name, deviation, unit in self.state_noise}
        for name, type_, initial in self.states:
            said = ""
            if name in noise:
                deviation, unit = noise[name]
                said = f" noise {matrix_text(((deviation,),))}" + (f" {string_literal(unit)}" if unit else "")
            lines.append(f"state {name}: {type_} = {Lit(type_, initial).text()}{said}")
        if any(frame.when for frame in self.frames):
            lines.append(f"setting {MODE[0]}: int in 0..3 = {MODE[1]}")
        if any(isinstance(e, Looked) for p in self.primitives if p.reply is not None for _, e in p.reply.actions):
            lines.append("const LOOK = { " + ", ".join(f"{key}: {value}" for key, value in LOOK.items()) + " }")
        if any(" seed SEEDS[" in frame.text() for frame in self.frames):
            lines.append("const SEEDS = { " + ", ".join(f"{key}: {byte}" for key, byte in SEEDS.items()) + " }")
        sections = [self.frames, self.connections, self.primitives, self.sensors, self.interfaces, self.outputs,
                    self.inputs]
        for section in sections:
            lines.append("")
            lines += [element.text() for element in section]  # type: ignore[attr-defined]
        if self.actuated:
            lines += ["", "link base { }"] + [a.text() for a in self.actuated]
        return "\n".join(lines) + "\n"

    @property
    def state_types(self) -> dict[str, str]:
        return {name: type_ for name, type_, _ in self.states}

    def primitive(self, name: str) -> Primitive:
        return next(p for p in self.primitives if p.name == name)

    def interface(self, name: str) -> Interface:
        return next(i for i in self.interfaces if i.name == name)

    def input(self, name: str) -> Input:
        return next(i for i in self.inputs if i.name == name)

    def connection(self, name: str) -> Connection:
        return next(c for c in self.connections if c.name == name)

    def output(self, name: str) -> Output:
        return next(o for o in self.outputs if o.name == name)

    def sensor(self, name: str) -> Sensor:
        return next(s for s in self.sensors if s.name == name)

    def sensors_read(self, names: Sequence[str]) -> list[Sensor]:
        """The sensors among `names`, each once, in order: those a reader makes fresh before it runs."""
        known = {s.name: s for s in self.sensors}
        return [known[n] for n in dict.fromkeys(names) if n in known]

    def runs(self, iface: Interface) -> list[Sensor | CallStmt]:
        """What running an interface may exchange, in order: its sensors (each read only when stale),
        its calls, then each sensor the output it triggers reads."""
        outputs = [self.output(iface.triggers)] if iface.triggers else []
        return [*self.sensors_read(iface.read_names()), *iface.run_order(),
                *(s for o in outputs for s in self.sensors_read(o.read_names()))]

    def periodic(self) -> list[Interface]:
        """Periodic interfaces in the order a tick runs them: by connection, then as declared."""
        first = self.connections[0].name
        return [i for c in self.connections for i in self.interfaces
                if i.periodic and (i.connection or first) == c.name]


def constructs(description: Description) -> set[str]:
    """The rarer constructs a description exercises: layouts a setting chooses (`either when`, each
    side), a framed reply's byte looked up in a table (a miss: a protocol error), that under `skip
    unmatched`; and chapter 7's: sensors, threading models, noise, Kalman filters. The search reports
    how many descriptions had each."""
    found = {construct for p in description.primitives for construct in primitive_constructs(p)}
    if description.sensors:
        found.add("sensor")
    if any(c.threading != "single" for c in description.connections):
        found.add("threading dual or multiple")
    if any(i.rate is not None for i in description.interfaces):
        found.add("an interface's own rate")
    if description.state_noise or any(o.noise for o in description.outputs) or any(
            s.noise is not None for s in description.sensors):
        found.add("noise")
    if any(o.filters for o in description.outputs):
        found.add("kalman filter")
    if description.actuated:
        found.add("actuator")
    return found


def primitive_constructs(p: Primitive) -> set[str]:
    """`constructs`, of one primitive."""
    found: set[str] = set()
    if p.frame is not None and p.frame.other_request:
        found.add("either when (request)")
    if p.frame is not None and p.frame.other_reply and p.reads:
        found.add("either when (reply)")
    if p.reply is not None and any(isinstance(e, Looked) for _, e in p.reply.actions):
        found.add("lookup in a framed reply")
        if p.skip:
            found.add("lookup under skip unmatched")
    return found


# ---- drawing a whole description -----------------------------------------------------------------------


def _state_scope(states: Sequence[tuple[str, str, Any]], constants: Sequence[Named]) -> Scope:
    return tuple(Name(t, n) for n, t, _ in states) + tuple(constants)


def _shadowed(scope: Scope, names: Mapping[str, str]) -> Scope:
    """`scope` with `names` (parameters, fields) added; they hide state variables of the same name."""
    kept = tuple(leaf for leaf in scope if not (isinstance(leaf, Name) and leaf.name in names))
    return kept + tuple(Name(t, n) for n, t in names.items())


def _params(draw: Draw, prefix: str, states: Mapping[str, str], max_size: int,
            types: Sequence[str]) -> tuple[Param, ...]:
    params = []
    for i in range(draw(st.integers(0, max_size))):
        type_ = draw(st.sampled_from(types))
        name = f"{prefix}{i}"
        if states and sometimes(draw, 10):  # a parameter that hides a state variable
            name = draw(st.sampled_from(sorted(states)))
            if any(p.name == name for p in params):
                name = f"{prefix}{i}"
        low = high = None
        if type_ == INT and sometimes(draw, 3):
            low = draw(st.integers(-300, 300))
            high = low + draw(st.integers(0, 400))
        elif type_ == FLOAT and sometimes(draw, 3):
            low = draw(st.sampled_from([-1.0, 0.0, -2.5]))
            high = draw(st.sampled_from([1.0, 1.5, 10.0]))
        elif type_ == BYTES and sometimes(draw, 3):
            low = draw(st.integers(0, 2))
            high = low + draw(st.integers(0, 6))
        params.append(Param(name, type_, low, high))
    return tuple(params)


def _request(draw: Draw, params: tuple[Param, ...], scope: Scope,
             listener: bool) -> tuple[str, str, tuple[Expr, ...], int | None]:
    """The request encoding: (`pack` | `format`, template, arguments, fixed size or None)."""
    if listener:
        return "format", "", (), 0
    if sometimes(draw, 4):  # ASCII: PEP 3101 fields and text
        pieces: list[str] = [draw(st.sampled_from(["D", "E,", "G", "", "$"]))]
        args = []
        for i in range(draw(st.integers(0, 3))):
            type_ = draw(st.sampled_from([INT, FLOAT, STRING, BOOL]))
            spec = draw(st.sampled_from({INT: ["", ":d", ":03d", ":x", ":+d", ":.2f"], FLOAT: ["", ":.2f", ":.3g", ":>8"],
                                         STRING: ["", ":>4"], BOOL: ["", ":d"]}[type_]))
            pieces.append(("," if i else "") + "{" + spec + "}")
            args.append(expression(draw, type_, scope, 1))
        pieces.append(draw(st.sampled_from(["\n", "\r", "\r\n", ""])))
        return "format", "".join(pieces), tuple(args), None
    order = draw(st.sampled_from(["<", ">", "!", "="]))
    slots: list[Slot] = []
    args: list[Expr] = []
    if draw(st.booleans()):
        slots.append(Slot("B", INT))
        args.append(Lit(INT, draw(st.integers(0, 255))))
    for p in params:
        if p.type == BYTES or sometimes(draw, 4):
            continue
        slot = draw_slot(draw, p.type, order)
        r = code_range(slot.code)
        if r is not None and p.low is not None and (p.high < r[0] or p.low > r[1]):
            slot = Slot("i", INT)  # a code that holds some of the range, so a constant argument can fit both
        slots.append(slot)
        args.append(Name(p.type, p.name))
    ranges = {p.name: (p.low, p.high) for p in params if p.type == INT and p.low is not None}
    for _ in range(draw(st.integers(0, 2))):
        slot = draw_slot(draw, order=order)
        slots.append(slot)
        value = expression(draw, slot.type, scope, 1)
        r = code_range(slot.code)
        if r is not None:
            if isinstance(value, Name) and value.name in ranges:  # packed directly: its range must meet the code's
                low, high = ranges[value.name]
                value = value if low <= r[1] and high >= r[0] else Lit(INT, 0)
            value = fitting(draw, value, lambda v, r=r: isinstance(v, int) and r[0] <= v <= r[1], INT, r[0], min(r[1], 300))
        elif slot.code in _FLOAT_HOLDS and value.const:  # a constant float the half or single code holds
            try:
                number = constant_value(value)
            except Unknown:
                number = math.inf
            if not isinstance(number, float) or not abs(number) <= _FLOAT_HOLDS[slot.code]:
                value = Lit(FLOAT, 1.5)
        elif slot.code[-1] in "sZ" and value.const:  # a constant string no longer than its code holds
            room = int(slot.code[:-1] or 1)
            try:
                text = constant_value(value)
            except Unknown:
                text = ""
            if not isinstance(text, str) or len(text) > room:
                value = Lit(STRING, "x" * room)
        args.append(value)
    rest = [p for p in params if p.type == BYTES]
    if rest and draw(st.integers(0, 3)):
        args.append(Name(BYTES, rest[0].name))
    template = struct_text(order, slots, 0, bool(rest) and len(args) > len(slots))
    if not slots and not template.endswith("*"):
        template = ""
    numbers = all(s.code in _INT_CODES + "efd?" for s in slots)  # a format with a group holds no text
    if order in "<>" and numbers and not template.endswith("*") and sometimes(draw, 8):
        group, group_args = _sized_group(draw, order, scope)
        return "pack", (template or order) + group, (*args, *group_args), None
    fixed = None if template.endswith("*") else struct.calcsize(_struct_module(template) or "<")
    return "pack", template, tuple(args), fixed


def _sized_group(draw: Draw, order: str, scope: Scope) -> tuple[str, tuple[Expr, ...]]:
    """A width field and a repeated group with `%` codes (`%H*(B%)`): each `%` an unsigned integer of
    as many bytes as the width states; a run-time width outside 1..8, or a value it cannot hold, is
    an error both implementations must raise alike."""
    width: Expr = Lit(INT, draw(st.integers(1, 8)))
    if sometimes(draw, 3):
        width = fitting(draw, expression(draw, INT, scope, 1), lambda v: isinstance(v, int) and 1 <= v <= 8, INT, 1, 8)
    code = draw(st.sampled_from("BHIQ"))
    members = draw(st.sampled_from(["B%", "%", "%B", "H%%"]))
    count = draw(st.integers(1, 3))
    bound = (1 << (8 * constant_value(width))) - 1 if width.const else (1 << 64) - 1
    columns: list[Expr] = []
    for member in members:
        if member == "%":
            items = tuple(fitting(draw, expression(draw, INT, scope, 1),
                                  lambda v, b=bound: isinstance(v, int) and 0 <= v <= b, INT, 0, min(bound, 300))
                          for _ in range(count))
        else:
            high = code_range(member)[1]  # type: ignore[index]
            items = tuple(Lit(INT, draw(st.integers(0, high))) for _ in range(count))
        columns.append(Elements(INT, items))
    return f"%{code}*({members})", (width, *columns)


def _frame_args(draw: Draw, frame: Frame, params: tuple[Param, ...]) -> tuple[Expr, ...]:
    ranges = frame.field_ranges()
    ints = [p.name for p in params if p.type == INT]
    args: list[Expr] = []
    for q in frame.params:
        low, high = ranges.get(q, (0, 255))
        if q == "qm":  # the parameter `either when` reads: the setting, known when connecting
            args.append(Setting(INT))
        elif ints and draw(st.integers(0, 2)):
            name = Name(INT, draw(st.sampled_from(ints)))
            args.append(name if draw(st.integers(0, 3)) else Binary(INT, "+", name, Lit(INT, 1)))
        else:
            args.append(Lit(INT, draw(st.integers(max(low, -3), min(high, 260)))))
    return tuple(args)


def _frame_fits(frame: Frame, request_size: int | None, replies: Sequence[Decoding], table: str) -> bool:
    """Whether a primitive of this request and these replies may use the frame (E503, E504, E505)."""
    if request_size is not None and not frame.length_states(frame.request, request_size):
        return False
    if not frame.reply:  # read unframed: a tag's entries have fixed sizes
        if table == "tag":
            return all(d.kind == "unpack" and d.size is not None for d in replies)
        return not any(d.size is None and d.kind == "unpack" for d in replies)
    if frame.acknowledges:
        return not replies
    for d in replies:
        size_known = d.size is not None and table != "tag" and frame.stuffing is None
        if not frame.delimits and not size_known:
            return False
        if d.size is not None and not frame.length_states(frame.reply, d.size):
            return False
    return True


@st.composite
def primitives(draw: Draw, name: str, states: Mapping[str, str], scope: Scope,
               frames_: tuple[Frame, ...], connections: tuple[str, ...]) -> Primitive:
    """A primitive: parameters (ranges, bytes), a request, a reply of every kind, maybe a frame."""
    frame = draw(st.sampled_from(frames_)) if frames_ and draw(st.integers(0, 2)) else None
    listener = frame is not None and frame.listens and draw(st.integers(0, 2)) > 0
    delimited = frame is not None and bool(frame.reply) and frame.delimits and not frame.acknowledges
    fixed_only = frame is not None and bool(frame.reply) and not delimited
    unframed = frame is None or not frame.reply
    table = draw(st.sampled_from(["plain", "plain", "none", "key"] + ["tag", "tag"] * (delimited or unframed)))
    if frame is not None and frame.acknowledges:
        table = "none"
    params = () if listener else _params(draw, "a", states, 3, [INT, INT, INT, FLOAT, BOOL, STRING, BYTES])
    if table == "key":  # the key: an int parameter with a small range, every value of it with its reply
        low = draw(st.integers(-2, 5))
        key_param = Param(f"a{len(params)}", INT, low, low + draw(st.integers(0, 3)))
        params += (key_param,)
    local = _shadowed(scope, {p.name: p.type for p in params})
    encoding, template, args, size = _request(draw, params, local, listener)
    frame_args = _frame_args(draw, frame, params) if frame is not None else ()
    reply = None
    entries: tuple[tuple[int, Reply], ...] = ()
    key = tag = None
    lasts: tuple[int | None, ...] = ()

    def one_reply(fixed: bool, seen: tuple[Expr, ...] = ()) -> Reply:
        decoding = draw(decodings(fixed=fixed, rest=None if delimited else False))
        outs = tuple(Out(t, i) for i, t in enumerate(decoding.types))
        return Reply(decoding, draw_actions(draw, states, local + seen + outs))

    if table == "plain":
        reply = one_reply(fixed_only)
        if not delimited and reply.decoding.size is None and reply.decoding.kind == "unpack":
            reply = None
    elif table == "key":
        key = key_param.name
        entries = tuple((v, one_reply(fixed_only)) for v in range(int(key_param.low), int(key_param.high) + 1))
    elif table == "tag":
        tag = draw(st.sampled_from(["B", "B", ">H", "<H"]))
        values = sorted(draw(st.lists(st.sampled_from([0, 1, 2, 0x10, 0x11, 0x7F, 0xFE]), min_size=1, max_size=3,
                                      unique=True)))
        ends = [*values[1:], 0xFF]  # a range stops before the next entry, and leaves 0xFF without one
        lasts = tuple(None if not sometimes(draw, 3) or end - v < 2 else v + draw(st.integers(0, min(end - v - 2, 20)))
                      for v, end in zip(values, ends))
        # unframed: fixed sizes; the post-actions see the tag
        entries = tuple((v, one_reply(not delimited, (Name(INT, "tag"),))) for v in values)
    replies = [reply.decoding] if reply is not None else [r.decoding for _, r in entries]
    if frame is not None and not _frame_fits(frame, size, replies, table):
        frame, frame_args = None, ()
        sized = all(d.kind == "unpack" and d.size is not None for d in replies)
        if (table == "tag" and not sized) or any(d.size is None and d.kind == "unpack" for d in replies):
            reply, entries, key, tag, lasts = None, (), None, None, ()
            replies = []
    if listener and (frame is None or not replies):
        return draw(primitives(name, states, scope, (), connections))
    actions: tuple[tuple[str, Expr], ...] = ()
    if reply is None and not entries and sometimes(draw, 4):
        actions = draw_actions(draw, states, local)
    framed_reply = frame is not None and bool(frame.reply)
    skip = (framed_reply or tag is not None) and bool(replies) and sometimes(draw, 4)
    reads = bool(replies) or (frame is not None and frame.acknowledges)
    timeout = draw(st.sampled_from([20, 50, 100])) if reads and sometimes(draw, 3) else None
    writes = not listener and (frame is not None or template != "")
    retries = draw(st.integers(1, 2)) if reads and writes and sometimes(draw, 4) else 0
    error = b""  # a NACK before an unframed reply of a fixed size
    if (reply is not None and not framed_reply and reply.decoding.kind == "unpack" and reply.decoding.size is not None
            and sometimes(draw, 3)):
        error = draw(st.sampled_from([b"\xee", b"\x15\x15"]))
    refused = None  # a reply whose first byte (`B`) says no: `error when out[0] == N`
    if (reply is not None and not error and reply.decoding.kind == "unpack"
            and re.match(r"[<>!=@]?B(?![{\d])", reply.decoding.template) and sometimes(draw, 4)):
        refused = draw(st.sampled_from([0, 1, 0x7F]))
    looked = looked_up(draw, reply, frame, states) if reply is not None and framed_reply and frame is not None else None
    if looked is not None:
        reply = looked
        skip = skip or sometimes(draw, 2)  # a miss read past, or raised
    nested = None  # an entry of one value of a table read unframed: dispatching again on the next byte
    single = [at for at, last in enumerate(lasts or (None,) * len(entries)) if last is None]
    if tag is not None and (frame is None or not frame.reply) and single and sometimes(draw, 3):
        nested = (draw(st.sampled_from(single)), draw(st.integers(0, 0x7F)))
    each_args: tuple[Expr, ...] = ()  # a sync read: a reply for each element of an array parameter, each its own id
    eachable = [i for i, q in enumerate(frame.params) if q != "qm"] if frame is not None else []
    if (reply is not None and framed_reply and frame is not None and eachable and not error and not listener
            and refused is None and sometimes(draw, 2)):  # `error when` reads one reply (E511)
        at = draw(st.sampled_from(eachable))
        each_args = tuple(Name(INT, EACH_VAR) if i == at else a for i, a in enumerate(frame_args))
        params += (Param("ids", INTS),)
        reply = Reply(reply.decoding, ())  # its values are arrays of any size: none of them is stored
    return Primitive(name, params, draw(st.sampled_from(connections)), encoding, template, args, reply, actions,
                     key, tag, entries, frame, frame_args, skip, timeout, lasts, retries, error, nested, each_args,
                     refused)


def looked_up(draw: Draw, reply: Reply, frame: Frame, states: Mapping[str, str]) -> Reply | None:
    """Sometimes, a framed reply of a fixed size with one more byte ("B"), which a post-action looks up
    in LOOK (`s0 = LOOK[out[i]]`): a byte LOOK lacks is a lookup miss, a protocol error."""
    ints = sorted(name for name, type_ in states.items() if type_ == INT)
    size = reply.decoding.size
    if (not ints or reply.decoding.kind != "unpack" or size is None or "%" in reply.decoding.template
            or not all(frame.length_states(side, size + 1) for side in (frame.reply, frame.other_reply))
            or not sometimes(draw, 2)):
        return None
    decoding = dataclasses.replace(reply.decoding, template=reply.decoding.template + "B",
                                   types=(*reply.decoding.types, INT), size=size + 1)
    target = draw(st.sampled_from(ints))
    kept = tuple(action for action in reply.actions if action[0] != target)
    return Reply(decoding, (*kept, (target, Looked(INT, len(decoding.types) - 1))))


def _call_args(draw: Draw, prim: Primitive, scope: Scope) -> tuple[Expr, ...] | None:
    """Arguments for a call of `prim` from `scope`; None if `scope` has no bytes for its bytes parameters."""
    direct: dict[str, tuple[int, int]] = {}
    if prim.encoding == "pack":
        codes = re.findall(r"(\d*)([a-zA-Z?])(\{\d+\})?", prim.template)
        slot_codes = [n + c + bits if bits else c for n, c, bits in codes if c != "x"]  # `3s{24}`: one integer
        for code, arg in zip(slot_codes, prim.args):
            r = code_range(code)
            if r is not None and isinstance(arg, Name) and any(p.name == arg.name for p in prim.params):
                low, high = direct.get(arg.name, r)
                direct[arg.name] = (max(low, r[0]), min(high, r[1]))
    args = []
    for p in prim.params:
        if p.type == BYTES:
            byteses = _leaves(scope, BYTES)
            if not byteses:
                return None
            args.append(draw(st.sampled_from(byteses)))
            continue
        value = expression(draw, p.type, scope, 2)
        r = direct.get(p.name)
        low, high = (p.low, p.high) if p.low is not None else (r if r is not None else (0, 100))
        if r is not None:
            low, high = max(low, r[0]), min(high, r[1])

        def ok(v: Any, p: Param = p, r: tuple[int, int] | None = r) -> bool:
            return p.accepts(v) and (r is None or (isinstance(v, int) and r[0] <= v <= r[1]))

        args.append(fitting(draw, value, ok, p.type, low, high) if p.type in NUMBERS else value)
    return tuple(args)


@st.composite
def interfaces(draw: Draw, name: str, states: Mapping[str, str], scope: Scope,
               prims: tuple[Primitive, ...], outputs: tuple[str, ...], connections: int) -> Interface:
    periodic = sometimes(draw, 4)
    params = () if periodic else _params(draw, "b", states, 3, [INT, FLOAT, FLOAT, BOOL, STRING, BYTES])
    local = _shadowed(scope, {p.name: p.type for p in params})
    candidates = [p for p in prims if not p.each_args]  # an array argument: the host's alone
    if periodic and candidates:
        connection = draw(st.sampled_from(candidates)).connection
        candidates = [p for p in candidates if p.connection == connection]
    calls = []
    for _ in range(draw(st.integers(0 if periodic else 1, 3))):
        if not candidates:
            break
        prim = draw(st.sampled_from(candidates))
        args = _call_args(draw, prim, local)
        if args is not None:
            calls.append(CallStmt(prim, args, draw(st.sampled_from([0, 0, 1, 2, -1]))))
    if periodic and not calls and connections > 1:  # its connection would be unknown (E208)
        periodic = False
    triggers = draw(st.sampled_from(outputs)) if outputs and draw(st.booleans()) else None
    return Interface(name, params, tuple(calls), periodic, triggers, not periodic and sometimes(draw, 5))


def _hook(draw: Draw, interfaces_: Sequence[Interface], scope: Scope) -> Hook | None:
    usable = [i for i in interfaces_ if not any(p.type == BYTES for p in i.params)]
    if not usable or not sometimes(draw, 3):
        return None
    iface = draw(st.sampled_from(usable))
    args = []
    for p in iface.params:
        value = expression(draw, p.type, scope, 1)
        if p.type in NUMBERS and p.low is not None:
            value = fitting(draw, value, p.accepts, p.type, p.low, p.high)
        args.append(value)
    return Hook(iface, tuple(args))


def _senses(p: Primitive) -> bool:
    """Whether a sensor can read `p`: no parameters, and a reply of one value of a fixed size read as it is."""
    if p.params or p.reply is None or p.key is not None or p.tag is not None or p.each_args:
        return False
    decoding = p.reply.decoding
    return decoding.kind == "unpack" and decoding.size is not None and len(decoding.types) == 1 \
        and decoding.types[0] != BYTES


def _sensor_primitive(draw: Draw, name: str, connections: tuple[str, ...]) -> Primitive:
    """A primitive made to be a sensor's: an opcode, and one value back."""
    slot = draw_slot(draw, order="<")
    template = "<" + slot.code
    decoding = Decoding("unpack", template, (slot.type,), struct.calcsize(_struct_module(template)))
    return Primitive(name, (), draw(st.sampled_from(connections)), "pack", "B", (Lit(INT, draw(st.integers(0x40, 0x4F))),),
                     Reply(decoding), timeout_ms=draw(st.sampled_from([None, 20])))


def _output(draw: Draw, name: str, adapter: str, scope: Scope) -> Output:
    """An output of `adapter`, sometimes with noise on its float fields and a Kalman filter over one (§7.2.3)."""
    fields = tuple((f, expression(draw, t, scope, 2)) for f, t in ADAPTERS[adapter])
    floats = [f for f, t in ADAPTERS[adapter] if t == FLOAT]
    noise = tuple((f, draw(st.sampled_from([0.01, 0.5, 2.0]))) for f in floats if sometimes(draw, 4))
    filters = tuple(_kalman(draw, f) for f in floats if sometimes(draw, 3))
    return Output(name, adapter, fields, noise, filters)


def _kalman(draw: Draw, field_: str) -> Kalman:
    """A filter of one or two states (a constant, or a constant velocity), its covariances diagonal."""
    small = st.sampled_from([1e-6, 1e-4, 0.01, 0.5, 1.0])
    if draw(st.booleans()):
        return Kalman(field_, (draw(st.sampled_from([0.0, 1.0, -2.5])),), ((draw(st.sampled_from([1.0, 0.9])),),),
                      ((draw(small),),), ((1.0,),), draw(small),
                      ((draw(small),),) if draw(st.booleans()) else None)
    step = draw(st.sampled_from([0.05, 0.1, 1.0]))
    return Kalman(field_, (0.0, draw(st.sampled_from([0.0, 1.0]))), ((1.0, step), (0.0, 1.0)),
                  ((draw(small), 0.0), (0.0, draw(small))), ((1.0, 0.0),), draw(small),
                  ((1.0, 0.5), (0.5, 1.0)) if draw(st.booleans()) else None)


def _own_rate(draw: Draw, iface: Interface, threading: Mapping[str, str], connections: tuple[str, ...]) -> Interface:
    """A periodic interface on a `threading multiple` connection, sometimes at a rate of its own."""
    if iface.periodic and threading[iface.connection or connections[0]] == "multiple" and not sometimes(draw, 3):
        return dataclasses.replace(iface, rate=draw(st.sampled_from([2, 20, 100])))
    return iface


def _reads_sensors(iface: Interface, sensors: Sequence[Sensor], outputs: Sequence[Output]) -> bool:
    names = {s.name for s in sensors}
    read = iface.read_names() + [n for o in outputs if o.name == iface.triggers for n in o.read_names()]
    return any(n in names for n in read)


@st.composite
def descriptions(draw: Draw) -> Description:
    """A random description that compiles without errors."""
    states = []
    for i in range(draw(st.integers(1, 5))):
        type_ = draw(st.sampled_from([INT, INT, FLOAT, BOOL, STRING]))
        states.append((f"s{i}", type_, literal(draw, type_).value({})))
    constants: list[Named] = []
    if draw(st.booleans()):
        constants.append(Named(INT, "K0", draw(st.integers(0, 300))))
    if sometimes(draw, 4):
        constants.append(Named(FLOAT, "K1", draw(st.sampled_from([0.5, 2.5, 1e-3]))))
    if sometimes(draw, 4):
        constants += [Named(INT, "E0.m0", 2), Named(INT, "E0.m1", 3)]
    state_types = {n: t for n, t, _ in states}
    scope = _state_scope(states, constants)
    connection_names = tuple(f"c{i}" for i in range(draw(st.integers(1, 2))))
    frames_ = tuple(draw(frames(f"f{i}")) for i in range(draw(st.integers(0, 3))))
    prims = tuple(draw(primitives(f"p{i}", state_types, scope, frames_, connection_names))
                  for i in range(draw(st.integers(1, 5))))
    sensors: list[Sensor] = []
    if sometimes(draw, 2):  # sensors (thesis §7.2.4), read by outputs, interfaces and inputs, never by hooks
        for i in range(draw(st.integers(1, 2))):
            fitting_ = [p for p in prims if _senses(p)]
            if not fitting_ or sometimes(draw, 3):
                prims += (_sensor_primitive(draw, f"p{len(prims)}", connection_names),)
                fitting_ = [prims[-1]]
            prim = draw(st.sampled_from(fitting_))
            assert prim.reply is not None
            type_ = prim.reply.decoding.types[0]
            noise = draw(st.sampled_from([0.5, 0.01, 2])) if type_ in NUMBERS and sometimes(draw, 3) else None
            sensors.append(Sensor(f"r{i}", type_, prim, draw(st.sampled_from([10, 50, 100])), noise))
    reading = scope + tuple(Name(s.type, s.name) for s in sensors)
    actuated: list[Actuated] = []
    for i in range(draw(st.integers(1, 2)) if sometimes(draw, 4) else 0):  # actuators, each a joint's
        kind = draw(st.sampled_from(["servo", "wheel"]))
        low, high, code = (0, 1000, "<H") if kind == "servo" else (-1000, 1000, "<h")
        prim = Primitive(f"p{len(prims)}", (Param("a0", INT, low, high),), draw(st.sampled_from(connection_names)),
                         "pack", code, (Name(INT, "a0"),))
        prims += (prim,)
        items = [("velocity", draw(st.sampled_from([0.5, 4.8, 12.0])))]
        items += [("acceleration", draw(st.sampled_from([2.0, 30.0])))] if draw(st.booleans()) else []
        items += [("effort", draw(st.sampled_from([0.5, 4.1])))] if draw(st.booleans()) else []
        actuated.append(Actuated(i, kind, prim, tuple(items)))
    state_noise = tuple((name, draw(st.sampled_from([0.5, 3, 0.01])), draw(st.sampled_from(["", "", "mm"])))
                        for name, type_, _ in states if type_ in NUMBERS and sometimes(draw, 4))
    threading = {name: draw(st.sampled_from(["single", "dual", "multiple"])) for name in connection_names}
    output_specs = []
    output_names = tuple(f"o{i}" for i in range(draw(st.integers(0, 2))))
    for name in output_names:
        adapter = draw(st.sampled_from(sorted(ADAPTERS)))
        output_specs.append(_output(draw, name, adapter, reading))
    ifaces = tuple(_own_rate(draw, draw(interfaces(f"i{i}", state_types, reading, prims, output_names,
                                                   len(connection_names))), threading, connection_names)
                   for i in range(draw(st.integers(0, 4))))
    inputs = []
    usable = [i for i in ifaces if not any(p.type == BYTES for p in i.params)]
    for n in range(draw(st.integers(0, 2)) if usable else 0):
        iface = draw(st.sampled_from(usable))
        adapter = draw(st.sampled_from(sorted(ADAPTERS)))
        local = _shadowed(reading, dict(ADAPTERS[adapter]))
        args = []
        for p in iface.params:
            value = expression(draw, p.type, local, 2)
            if p.type in NUMBERS and p.low is not None:
                value = fitting(draw, value, p.accepts, p.type, p.low, p.high)
            args.append(value)
        inputs.append(Input(f"n{n}", adapter, iface, tuple(args)))
    connections = []
    for name in connection_names:
        terminator = draw(st.sampled_from([None, None, "\r", "\r\n", ";"]))
        keepalive = _hook(draw, [i for i in ifaces if not i.params], scope) if sometimes(draw, 5) else None
        quiet = [i for i in ifaces if not _reads_sensors(i, sensors, output_specs)]  # none read before connect returns
        connections.append(Connection(name, terminator, _hook(draw, quiet, scope), _hook(draw, ifaces, scope), keepalive,
                                      threading[name]))
    description = Description(tuple(states), tuple(constants), frames_, tuple(connections), prims, ifaces,
                              tuple(output_specs), tuple(inputs), tuple(sensors), state_noise, tuple(actuated))
    return dataclasses.replace(description, text=description.render())


# ---- what the device answers ----------------------------------------------------------------------------

REPLY_KINDS = ("valid",) * 9 + ("flip", "truncate", "prefix", "other", "extra", "nothing", "garbage", "twice", "lower",
                                "broken")


@dataclass(frozen=True)
class ReplyPlan:
    """How the device answers one exchange: validly, or spoilt in one way (`broken`: the port fails)."""

    kind: str = "valid"
    material: bytes = b""  # the reply's data (payload bytes, regex values) and garbage
    at: int = 0  # where a byte is flipped or the reply cut
    mask: int = 1  # what a flipped byte is XORed with
    choice: int = 0  # which tagged entry (one more: a tag without entry)
    spiced: bool = False  # the data starts with the frame's own special bytes (stuffed, header, delimiter)


reply_plans = st.builds(ReplyPlan, st.sampled_from(REPLY_KINDS), st.binary(max_size=12), st.integers(0, 40),
                        st.integers(1, 255), st.integers(0, 3), st.booleans())


def spice(prim: Primitive, material: bytes) -> bytes:
    """`material` after the bytes a frame treats specially, which payloads of real devices contain too:
    the stuffed sequence, the header, the constant after the payload (where a length says where the
    payload ends, else it would end it)."""
    frame = prim.frame
    if frame is None:
        return material
    special = frame.stuffing[1] if frame.stuffing is not None else b""
    kinds = [p.kind for p in frame.reply]
    if "payload" in kinds and kinds.index("payload") + 1 < len(kinds) and "length" in kinds:
        special += frame.reply[kinds.index("payload") + 1].data
    if frame.reply and frame.reply[0].kind == "header":
        special += frame.reply[0].data
    return special + material


def frame_fields_env(prim: Primitive, values: Mapping[str, Any]) -> dict[str, Any]:
    """The frame's parameters' values for a call of `prim` with these parameter values (and state)."""
    assert prim.frame is not None
    env: dict[str, Any] = {}
    for q, arg in zip(prim.frame.params, prim.each_args if EACH_VAR in values else prim.frame_args):
        try:
            env[q] = arg.value(values)
        except Unknown:
            pass
    return env


def valid_reply(description: Description, prim: Primitive, values: Mapping[str, Any], request: bytes,
                plan: ReplyPlan, shift_fields: int = 0) -> Wire:
    """The reply a device would send to this call (`shift_fields`: another device's, its fields
    off by that much and its payload a byte longer). Not valid where the plan's choice is a tag
    without entry or the values make a reply that cannot be valid (see `encode_side`)."""
    decoding, tag = prim.decoding_for(values, plan.choice)
    material = spice(prim, plan.material) if plan.spiced else plan.material
    payload = tag + payload_for(decoding, material) + (b"\0" if shift_fields else b"")
    valid = decoding is not None or not (prim.reply or prim.entries)
    if prim.refused is not None and payload[:1] == bytes([prim.refused]):
        valid = False  # the device's error (`error when`)
    looked = prim.reply is not None and any(isinstance(e, Looked) for _, e in prim.reply.actions)
    if looked and decoding is not None and decoding.size is not None and payload[decoding.size - 1] not in LOOK:
        valid = False  # a lookup miss: a protocol error, read past under `skip unmatched`
    if decoding is not None and decoding.kind == "regex":
        valid = valid and re.match(decoding.template, payload[len(tag) :].decode("latin-1")) is not None
    if prim.framed_reply:
        assert prim.frame is not None
        env = {k: v + shift_fields for k, v in frame_fields_env(prim, values).items()}
        fixed = decoding is not None and decoding.size is not None and prim.tag is None and prim.frame.stuffing is None
        wire = encode_side(prim.frame, prim.frame.reply, payload, env, request, plan.kind == "lower", fixed)
        return Wire(wire.data, valid and wire.valid)
    if decoding is not None and decoding.kind == "regex":
        end = description.connection(prim.connection).line_end()
        end = b"\r\n" if end == b"\n" and plan.at % 2 else end
        return Wire(payload + end, valid and end not in payload and b"\n" not in payload)
    return Wire(payload, valid and not (prim.error and payload.startswith(prim.error)))  # else the device's error


def reply_for(description: Description, prim: Primitive, values: Mapping[str, Any], request: bytes,
              plan: ReplyPlan) -> Wire:
    """What the device sends back to this call, as the plan has it."""
    if not prim.reads:
        return Wire(plan.material if plan.kind == "garbage" else b"", False)  # it talks unasked, sometimes
    right = valid_reply(description, prim, values, request, plan)
    if prim.each_args:  # a reply for each element, through the frame of its own id
        elements = values.get(prim.params[-1].name)
        answers = [valid_reply(description, prim, {**values, EACH_VAR: e}, request, plan)
                   for e in elements or ()] if isinstance(elements, (list, tuple)) else []
        right = Wire(b"".join(w.data for w in answers), bool(answers) and all(w.valid for w in answers))
    valid = right.data
    if plan.kind in ("valid", "lower"):
        return right
    if plan.kind == "flip":
        at = plan.at % max(len(valid), 1)
        spoilt = valid[:at] + bytes([valid[at] ^ plan.mask]) + valid[at + 1 :] if valid else b"\0"
    elif plan.kind == "truncate":
        spoilt = valid[: plan.at % max(len(valid), 1)]
    elif plan.kind == "prefix":
        spoilt = plan.material + valid
    elif plan.kind == "other":  # another device's frame first
        other = valid_reply(description, prim, values, request, plan, 1).data if prim.framed_reply else plan.material
        spoilt = other + valid
    elif plan.kind == "extra":
        spoilt = valid + plan.material
    elif plan.kind == "nothing":
        spoilt = b""
    elif plan.kind == "garbage" and prim.error and plan.at % 2:  # the device's error, its code (or none) after it
        spoilt = prim.error + plan.material
    elif plan.kind == "twice":
        spoilt = valid + valid
    else:
        spoilt = plan.material
    return Wire(spoilt, False)


# ---- what the host does: calls with values in and out of range, of the wrong type ----------------------


@dataclass(frozen=True)
class Operation:
    """One thing the host does, and how the device answers each exchange it is expected to make."""

    kind: str  # primitive | interface | input | tick | sensor (robot.sensors.NAME) | wait (the clock moves on)
    name: str = ""
    args: tuple[Any, ...] = ()  # positional; for an input, (field, value) pairs
    plans: tuple[ReplyPlan, ...] = ()

    def label(self) -> str:
        if self.kind == "tick":
            return "tick()"
        if self.kind == "wait":
            return f"wait({self.args[0]} ms)"
        if self.kind == "sensor":
            return f"sensors.{self.name}"
        if self.kind == "input":
            return f"call_input({self.name!r}, {', '.join(f'{k}={v!r}' for k, v in self.args)})"
        return f"call_{self.kind}({', '.join(map(repr, (self.name, *self.args)))})"


@dataclass(frozen=True)
class Script:
    """A session: connect (startup hooks), the operations, close (terminate hooks), maybe a call after it."""

    startup: tuple[ReplyPlan, ...]
    operations: tuple[Operation, ...]
    terminate: tuple[ReplyPlan, ...]
    after_close: Operation | None = None

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        printer.text("\n" + self.text())

    def text(self) -> str:
        lines = [f"connect  (startup replies: {_plans_text(self.startup)})"]
        lines += [f"{op.label()}  (replies: {_plans_text(op.plans)})" for op in self.operations]
        lines.append(f"close  (terminate replies: {_plans_text(self.terminate)})")
        if self.after_close is not None:
            lines.append(f"{self.after_close.label()}  (after close)")
        return "\n".join(lines)


def _plans_text(plans: Sequence[ReplyPlan]) -> str:
    return ", ".join(f"{p.kind}({p.material.hex()}, at={p.at}, mask={p.mask}, choice={p.choice}"
                     f"{', spiced' if p.spiced else ''})" for p in plans) or "none"


_EXTREME = {INT: [255, 256, -1, 65535, 65536, 2**31, -2**31 - 1, 2**63, 2**70, 2**1030],  # 2**1030: no float holds it
            FLOAT: [-0.0, 255, -1, 1e300, -1e300, math.inf, math.nan]}
_WRONG = {INT: [1.5, "7", True, None], FLOAT: ["x", True, None], BOOL: [1, "True"], STRING: [5, b"ab"],
          BYTES: ["zz", 3.5, [256], None], INTS: [3, [1.5], "12", None]}


@st.composite
def value_for(draw: Draw, type_: str, low: float | None = None, high: float | None = None) -> Any:
    """A value for a parameter or field: mostly right (inside its range), sometimes outside it, rarely
    of the wrong type."""
    if sometimes(draw, 25):
        return draw(st.sampled_from(_WRONG[type_]))
    ranged = low is not None and high is not None
    if ranged and type_ in NUMBERS and sometimes(draw, 6):  # just outside
        return draw(st.sampled_from([low - 1, high + 1] if type_ == INT else [low - 0.5, high + 0.5, math.nan]))
    if type_ in NUMBERS and not ranged and sometimes(draw, 5):
        return draw(st.sampled_from(_EXTREME[type_]))
    if type_ == INTS:  # each element often a frame field's value, sometimes none at all
        return draw(st.lists(st.integers(-2, 300) | st.sampled_from([0, 1, 2]), max_size=3))
    if type_ == INT:
        return draw(st.integers(int(low), int(high)) if ranged else st.integers(-5, 300))
    if type_ == FLOAT:
        return draw(st.floats(low, high) if ranged else st.floats(-3, 3).map(lambda f: round(f, 3)))
    if type_ == BOOL:
        return draw(st.booleans())
    if type_ == STRING:
        return draw(st.text(alphabet="ab,;09 é\u20ac\r", max_size=5))
    data = draw(st.binary(max_size=10)) if not ranged else draw(st.binary(min_size=int(low), max_size=int(high) + 1))
    form = draw(st.integers(0, 3))
    return list(data) if form == 1 else data.hex() if form == 2 else bytearray(data) if form == 3 else data


def exchanges_of(description: Description, kind: str, name: str) -> int:
    """How many exchanges an operation makes at most, each needing a reply plan (a sensor's read
    counted once for each reader that may make it)."""
    if kind in ("primitive", "sensor"):
        return 1
    if kind == "wait":
        return 0
    if kind == "interface":
        return len(description.runs(description.interface(name)))
    if kind == "input":
        spec = description.input(name)
        return len(description.sensors_read(spec.read_names())) + len(description.runs(spec.interface))
    return sum(len(description.runs(i)) for i in description.periodic())


def _plans(count: int) -> st.SearchStrategy[tuple[ReplyPlan, ...]]:
    return st.lists(reply_plans, min_size=count, max_size=count).map(tuple)


@st.composite
def operations(draw: Draw, description: Description) -> Operation:
    kinds = ["primitive", "primitive", "tick"]
    kinds += ["interface", "interface"] if description.interfaces else []
    kinds += ["input"] if description.inputs else []
    kinds += ["sensor", "wait", "wait"] if description.sensors else []
    kind = draw(st.sampled_from(kinds))
    if kind == "tick":
        return Operation("tick", plans=draw(_plans(exchanges_of(description, "tick", ""))))
    if kind == "wait":  # the wire's clock moves on: a sensor's value grows old
        return Operation("wait", args=(draw(st.sampled_from([5, 10, 50, 100, 150])),))
    if kind == "sensor":
        sensor = draw(st.sampled_from(description.sensors))
        return Operation("sensor", sensor.name, plans=draw(_plans(1)))
    if kind == "input":
        spec = draw(st.sampled_from(description.inputs))
        fields = tuple((f, draw(value_for(t))) for f, t in ADAPTERS[spec.adapter])
        return Operation("input", spec.name, fields, draw(_plans(exchanges_of(description, "input", spec.name))))
    element = draw(st.sampled_from(description.primitives if kind == "primitive" else description.interfaces))
    args = [draw(value_for(p.type, p.low, p.high)) for p in element.params]
    if sometimes(draw, 31):  # the wrong number of arguments
        args = args[:-1] if args else [1]
    return Operation(kind, element.name, tuple(args), draw(_plans(exchanges_of(description, kind, element.name))))


def _hook_exchanges(description: Description, hook: str) -> int:
    hooks = [getattr(c, hook) for c in description.connections]
    return sum(len(h.interface.calls) for h in hooks if h is not None)


@st.composite
def scripts(draw: Draw, description: Description) -> Script:
    """A session of the host with the description's robot, and the device's answers."""
    ops = tuple(draw(st.lists(operations(description), min_size=1, max_size=8)))
    after = draw(operations(description)) if sometimes(draw, 10) else None
    return Script(draw(_plans(_hook_exchanges(description, "startup"))), ops,
                  draw(_plans(_hook_exchanges(description, "terminate"))), after)
