"""The Python names a driver gives what a description names, kept off keywords and the engine's names."""

from __future__ import annotations

import functools
import keyword
from collections.abc import Iterable

from rdisc import engine
from rdisc.engine import carry
from rdisc.semantics import model as m

# Names a plan function may use: a parameter or field of the same name would hide
# them, so such a parameter gets a trailing underscore. The engine's (`lookup`,
# `element`, ...) are among them too (`_body_names`).
_BODY_NAMES = frozenset((
    "self", "state", "args", "reply", "fields", "type", "Exception",
    "float", "int", "round", "abs", "min", "max", "str", "bool", "len", "bytes", "math", "struct", "re",
    "Any", "Args", "StateValues", "Sequence", "Value",
))
# Members of State besides the state variables (it is a Mapping).
_STATE_MEMBERS = frozenset(("keys", "items", "values", "get"))
# The classes a driver defines for its robot, by their names' endings after the robot's class name.
_CLASS_ENDINGS = ("", "State", "Inputs", "Interfaces", "Primitives", "Sensors")


def _identifier(name: str) -> str:
    if not name.isidentifier():
        raise ValueError(f"{name!r} is not a checked name")
    return name


def _escape(name: str, taken: Iterable[str]) -> str:
    """`name` as a Python identifier that is none of `taken` and not a keyword."""
    name = _identifier(name)
    taken = set(taken)
    while keyword.iskeyword(name) or name in taken:
        name += "_"
    return name


def _body_names() -> frozenset[str]:
    """The names a plan function's parameters must not hide: its own, and every name the engine binds."""
    return _BODY_NAMES | carry.names()


@functools.cache
def _robot_members() -> frozenset[str]:
    """The engine Robot's public members, its class's and an instance's (`device`, `name`): an
    input's typed method of one of these names gets a trailing underscore, so that it hides none."""
    robot = engine.Robot(engine.Device("", {}, {}, {}, {}, {}))
    return frozenset(name for name in dir(robot) if not name.startswith("_"))


def _params(params: Iterable[tuple[str, m.AnyType]], reserved: frozenset[str] | None = None) -> dict[str, str]:
    """Python names for parameters or fields: original name → local name, none of `reserved`
    (by default, `_body_names()`)."""
    reserved = _body_names() if reserved is None else reserved
    names: dict[str, str] = {}
    originals = [name for name, _ in params]
    for name in originals:
        names[name] = _escape(name, reserved | set(names.values()) | (set(originals) - {name}))
    return names


def class_name(robot: str) -> str:
    """`irobot_create` → `IrobotCreate`; `Robot` added where the class, or one of the classes named
    after it, would take a name the engine's modules bind (`incoming` → `IncomingRobot`)."""
    name = "".join(part[:1].upper() + part[1:] for part in _identifier(robot).split("_")) or "Robot"
    engine = carry.names()
    while keyword.iskeyword(name) or any(name + ending in engine for ending in _CLASS_ENDINGS):
        name += "Robot"
    return name


def _constant_name(name: str, taken: set[str]) -> str:
    base = "_" + _identifier(name).upper()
    result, n = base, 2
    while result in taken:
        result, n = f"{base}_{n}", n + 1
    taken.add(result)
    return result


# ---- text ----------------------------------------------------------------------------------------
