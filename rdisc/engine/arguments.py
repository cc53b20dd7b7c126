"""Values given by the host: arguments bound to parameters as Python binds them, made their
declared types and checked against their ranges before anything is sent; settings bound before
a port is opened.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Mapping
from math import isfinite
from typing import Any

from rdisc.engine.errors import RdisValueError
from rdisc.engine.operations import MAX_INT
from rdisc.engine.plans import Device, Input, Interface, Primitive
from rdisc.engine.values import Args, Param, Value, _check_ranges, not_finite

_KIND_NAMES: dict[type, str] = {int: "int", float: "float", bool: "bool", str: "string", bytes: "bytes"}


def _accept(value: Any, kind: type, what: str) -> Any:
    """A value given for a parameter or field of type `kind`, made that type; else TypeError.

    An int is taken for a float; a float must be finite (else RdisValueError); bytes are bytes, a
    bytearray, a list of ints 0..255 or hex text ("3c20")."""
    if kind is float and type(value) is float:
        if not isfinite(value):
            raise not_finite(value, what)
        return value
    if type(value) is kind:
        return value
    if kind is float and isinstance(value, numbers.Real) and not isinstance(value, bool):
        try:
            made = float(value)
        except OverflowError:  # an int past the largest float
            raise not_finite(value, what) from None
        if not isfinite(made):
            raise not_finite(value, what)
        return made
    if kind is int and isinstance(value, numbers.Integral) and not isinstance(value, bool):
        return int(value)
    if kind is str and isinstance(value, str):
        return value
    if kind is bytes and isinstance(value, str):
        try:
            return bytes.fromhex(value)
        except ValueError:
            raise TypeError(f"{what} must be bytes, as hex such as 3c20 (two digits a byte), not {value!r}") from None
    if kind is bytes:
        try:
            if isinstance(value, (bytes, bytearray, memoryview, list, tuple)):
                return bytes(value)
        except (ValueError, TypeError) as err:
            raise TypeError(f"{what} must be bytes: {err}") from None
    raise TypeError(f"{what} must be {_KIND_NAMES[kind]}, not {type(value).__name__} {value!r}")


def _bind(what: str, params: tuple[Param, ...], args: tuple[Any, ...], kwargs: dict[str, Any]) -> Args:
    """Arguments by position and by name, as Python binds them."""
    if len(args) > len(params):
        raise TypeError(f"{what} takes {len(params)} arguments, {len(args)} given")
    if not kwargs and len(args) == len(params):  # every argument by position: nothing to bind
        return list(args)
    return [*args, *bind_named(what, params[len(args) :], kwargs).values()]


def _accepted(what: str, params: tuple[Param, ...], values: Args) -> Args:
    """Values given by position, each made its parameter's type (TypeError if it cannot be); the
    parameters left out take their defaults."""
    if len(values) != len(params):
        left_out = params[len(values) :]
        if len(values) > len(params) or any(p.default is None for p in left_out):
            required = next((i for i, p in enumerate(params) if p.default is not None), len(params))
            takes = len(params) if required == len(params) else f"{required} to {len(params)}"
            raise TypeError(f"{what} takes {takes} arguments, {len(values)} given")
        values.extend(p.default for p in left_out)
    for i, param in enumerate(params):
        if type(values[i]) is not param.kind or param.size is not None or param.kind is float:
            values[i] = _accept_param(values[i], param, f"{what}: parameter {param.name}")
    return values


def _accept_param(value: Any, param: Param, what: str) -> Any:
    """A value given for a parameter or an input's field, made its type (TypeError if it cannot be)."""
    if param.size is not None:
        return _accept_array(value, param, what)
    return _accept(value, param.kind, what)


def _accept_array(value: Any, param: Param, what: str) -> tuple[Any, ...]:
    """A list or tuple of the array's size (any size if open), each element made its type."""
    if not isinstance(value, (list, tuple)):
        raise TypeError(f"{what} must be a list of {param.size or 'any number of'} "
                        f"{_KIND_NAMES[param.kind]}s, not {type(value).__name__}")
    if param.size and len(value) != param.size:
        raise TypeError(f"{what} must have {param.size} values, not {len(value)}")
    kind = param.kind
    return tuple(v if type(v) is kind and kind is not float else _accept(v, kind, f"{what}[{i}]")
                 for i, v in enumerate(value))


def _widen(owner: str, floats: tuple[int, ...], values: Args) -> None:
    """Computed values bound to float parameters: an int made a float, in place."""
    try:
        for i in floats:
            if type(values[i]) is int:
                values[i] = float(values[i])
            elif type(values[i]) is tuple:  # an array of floats computed from ints
                values[i] = tuple(float(v) for v in values[i])
    except OverflowError as err:  # an int too large for a float
        raise RdisValueError(f"{owner}: {err}") from None


def bind_settings(device: Device, given: Mapping[str, Any] | None) -> dict[str, Value]:
    """The settings given when connecting, by name, each made its type (an int taken for a float)
    and checked against its range and the width of integers; the others keep their defaults.
    A name the description does not declare, or a value that does not fit, is an RdisValueError
    naming the setting, raised before any port is opened."""
    bound = {p.name: device.state[p.name] for p in device.settings}
    declared = {p.name: p for p in device.settings}
    for name, value in (given or {}).items():
        param = declared.get(name)
        if param is None:
            known = ", ".join(declared) or "none"
            raise RdisValueError(f"{device.name}: no setting named {name!r} (its settings: {known})")
        try:
            accepted = _accept_param(value, param, f"{device.name}: setting {name}")
        except TypeError as err:
            raise RdisValueError(str(err)) from None
        for item in accepted if param.size is not None else (accepted,):
            _within_width(item, f"{device.name}: setting {name}")
        if param.low is not None:
            _check_ranges(device.name, (param,), (0,), [accepted], "setting")
        bound[name] = accepted
    return bound


def _within_width(value: Any, what: str) -> None:
    if type(value) is int and not -MAX_INT <= value <= MAX_INT:
        raise RdisValueError(f"{what} is a {value.bit_length()}-bit integer; integers are limited to 64 bits and a sign")


class Unbound(TypeError):
    """Values given by name that do not bind to the parameters: the first name of none of them
    (`unknown`), else the first parameter given no value and without a default (`missing`)."""

    def __init__(self, what: str, unknown: str | None, missing: str | None) -> None:
        super().__init__(f"{what}: unexpected argument {unknown!r}" if unknown is not None
                         else f"{what}: missing argument {missing!r}")
        self.unknown = unknown
        self.missing = missing


def bind_named(what: str, params: tuple[Param, ...], given: Mapping[str, Any],
               read: Callable[[Any, Param], Any] | None = None) -> dict[str, Any]:
    """Values given by name bound to the parameters (or fields), in their order, each made its type
    by `read` if given; a parameter left out takes its default. The one binding of the typed API,
    `--call`, the console and a replay."""
    values: dict[str, Any] = {}
    missing = None
    found = 0
    for param in params:
        if param.name in given:
            values[param.name] = given[param.name]
            found += 1
        elif param.default is not None:
            values[param.name] = param.default
        elif missing is None:
            missing = param.name
    if found < len(given):
        raise Unbound(what, next(name for name in given if name not in values), None)
    if missing is not None:
        raise Unbound(what, None, missing)
    if read is not None:
        for param in params:
            if param.name in given:
                values[param.name] = read(values[param.name], param)
    return values


def call_values(device: Device, kind: object, name: str, given: Mapping[str, Any],
                read: Callable[[Any, Param, str], Any] | None = None) -> dict[str, Value]:
    """The values given by name (text, or JSON) of a call of the input, interface or primitive
    `name`: `bind_named` with `read_value` (or `read`, which calls it). KeyError if there is no
    such element; Unbound, TypeError or RdisValueError (naming the parameter) if they do not fit."""
    if kind not in ("input", "interface", "primitive"):
        raise ValueError(f"a call is of an input, an interface or a primitive, not {kind!r}")
    plans: Mapping[str, Input | Interface | Primitive] = (
        device.inputs if kind == "input" else device.interfaces if kind == "interface" else device.primitives)
    plan = plans.get(name)
    if plan is None:
        raise KeyError(f"{device.name} has no {kind} named {name!r}")
    reader = read_value if read is None else read
    if isinstance(plan, Input):
        return bind_named(f"input {name}", plan.fields, given,
                          lambda value, p: reader(value, p, f"input {name}: field {p.name}"))
    return bind_named(f"{kind} {name}", plan.params, given,
                      lambda value, p: reader(value, p, f"{kind} {name}: parameter {p.name}"))


def read_value(given: Any, param: Param, what: str) -> Any:
    """A value given from outside Python for a parameter, field or setting, made its type: text (a
    `--call` or `--set` K=V, a console's form) or a JSON value (a recording). A number is written as
    a description writes one (`42`, `0x2A`, `-1.5e3`), in ASCII, finite and within 64 bits and a
    sign, else it is an RdisValueError naming `what`; an array is `[a, b]` (or `a, b`) or a list;
    bytes are hex; an empty text is the default, if there is one, of any type but string and bytes.
    Any other value is taken as the typed API takes it (a TypeError if it does not fit)."""
    if given == "" and param.default is not None and (param.size is not None or param.kind not in (str, bytes)):
        return param.default
    if param.size is None:
        return _accept(_read_item(given, param.kind, what), param.kind, what)
    if isinstance(given, str):
        inner = given.strip()
        inner = inner[1:-1] if inner.startswith("[") and inner.endswith("]") else inner
        given = [item.strip() for item in inner.split(",")] if inner.strip() else []
    if isinstance(given, (list, tuple)):
        given = tuple(_read_item(item, param.kind, f"{what}[{i}]") for i, item in enumerate(given))
    return _accept_array(given, param, what)


def _read_item(given: Any, kind: type, what: str) -> Any:
    """One value (or an array's element) read: a number's text as its number, checked; a text that
    is no number is left for the type check to refuse."""
    if isinstance(given, float) and not math.isfinite(given):
        raise RdisValueError(f"{what} is {given!r}: a number must be finite")
    if not isinstance(given, str) or kind in (str, bytes):
        _within_width(given, what)
        return given
    text = given.strip()
    if text in ("True", "true", "False", "false"):
        return text in ("True", "true")
    shown = repr(text) if len(text) <= 40 else f"{text[:30]!r}... ({len(text)} characters)"
    if kind is not bool and not text.isascii():  # Python would read '٣٣' as 33
        raise RdisValueError(f"{what} is {shown}: a number is written in ASCII")
    digits = text.lstrip("+-").replace("_", "")
    number: int | float
    try:
        number = float(text) if kind is float and digits[:2].lower() not in ("0x", "0b", "0o") else int(text, 0)
    except ValueError:
        if digits.isdigit():  # `010` is no number, as in a description; or too many digits to read
            if len(digits) > 20:
                raise RdisValueError(f"{what} is {shown}: integers are limited to 64 bits and a sign") from None
            return given
        if kind is float:
            return given
        try:  # `1.5` or `1e400` for an int
            number = float(text)
        except ValueError:
            return given
    if not math.isfinite(number):
        raise RdisValueError(f"{what} is {shown}: a number must be finite")
    _within_width(number, what)
    return number
