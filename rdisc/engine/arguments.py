"""Values given by the host: arguments bound to parameters as Python binds them, made their
declared types and checked against their ranges before anything is sent; settings bound before
a port is opened.
"""

from __future__ import annotations

import numbers
from collections.abc import Mapping
from typing import Any

from rdisc.engine.errors import RdisValueError
from rdisc.engine.operations import MAX_INT
from rdisc.engine.plans import Device, Param
from rdisc.engine.values import Args, Value

_KIND_NAMES: dict[type, str] = {int: "int", float: "float", bool: "bool", str: "string", bytes: "bytes"}


def _accept(value: Any, kind: type, what: str) -> Any:
    """A value given for a parameter or field of type `kind`, made that type; else TypeError.

    An int is taken for a float; bytes are bytes, a bytearray, a list of ints 0..255 or
    hex text ("3c20")."""
    if type(value) is kind:
        return value
    if kind is float and isinstance(value, numbers.Real) and not isinstance(value, bool):
        return float(value)
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
    values = list(args)
    for param in params[len(args) :]:
        if param.name in kwargs:
            values.append(kwargs.pop(param.name))
        elif param.default is not None:
            values.append(param.default)
        else:
            raise TypeError(f"{what}: missing argument {param.name!r}")
    if kwargs:
        raise TypeError(f"{what}: unexpected argument {next(iter(kwargs))!r}")
    return values


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
        if type(values[i]) is not param.kind or param.size is not None:
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
    return tuple(v if type(v) is param.kind else _accept(v, param.kind, f"{what}[{i}]") for i, v in enumerate(value))


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


def _check_ranges(owner: str, params: tuple[Param, ...], ranged: tuple[int, ...], values: Args,
               role: str = "parameter") -> None:
    """A value outside its parameter's (or setting's) declared range is refused before anything is sent."""
    for i in ranged:
        p, value = params[i], values[i]
        low, high = p.low, p.high
        assert low is not None and high is not None  # `ranged` holds the parameters with a range
        if isinstance(value, bytes):
            if not low <= len(value) <= high:
                raise RdisValueError(f"{owner}: {role} {p.name} has {len(value)} bytes, outside {low!r}..{high!r}")
        elif isinstance(value, tuple):
            for k, item in enumerate(value):
                if not low <= item <= high:
                    raise RdisValueError(f"{owner}: {role} {p.name}[{k}] is {item!r}, outside {low!r}..{high!r}")
        elif not low <= value <= high:
            raise RdisValueError(f"{owner}: {role} {p.name} is {value!r}, outside {low!r}..{high!r}")


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
            if type(item) is int and not -MAX_INT <= item <= MAX_INT:
                raise RdisValueError(f"{device.name}: setting {name} is a {item.bit_length()}-bit integer; "
                                     "integers are limited to 64 bits and a sign")
        if param.low is not None:
            _check_ranges(device.name, (param,), (0,), [accepted], "setting")
        bound[name] = accepted
    return bound
