"""Descriptions whose names are the engine's: the random differential test's descriptions with
their parameters, state variables, primitives, interfaces, inputs, sensors and frames renamed
to names a driver's engine binds (`lookup`, `struct`, `Robot`, `isfinite`), or that a typed
method binds itself (`lane`, `acquire`, `request`), or that are the robot's own methods
(`open`, `tick`, `run_for`). A driver must take none of them from the engine. (The engine's
names with a leading underscore are not among them: the checker refuses such a name.)

The description is rendered with its own names and renamed as text (outside string literals);
a `Renamed` robot takes the calls by the original names, so the rest of the differential test
(its device model, its expectations) reads the description as drawn.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Mapping
from typing import Any

from hypothesis import strategies as st

from rdisc.compile import compile_text
from rdisc.engine import Robot, carry

# The names the generator gives what is renamed: parameters (a0), a frame's parameters (q0),
# state variables (s0), primitives (p0), interfaces (i0), inputs (n0), sensors (r0), frames (f0),
# constants (K0).
DRAWN = re.compile(r"\b(?:[aqspinrf]|K)\d+\b")
ROBOT = "generated"  # the robot's name as drawn (`robot generated { ... }`)
STRING = re.compile(r'[rb]?"(?:\\.|[^"\\\n])*"')
# What a typed method's statements bind besides the engine's names.
TYPED_LOCALS = ("robot", "lane", "acquire", "release", "write", "request", "checksum", "values", "args",
                "state", "data", "plan", "err", "self", "reply")
# Drawn three times in four, by the kind of name: what a name of that kind would most likely take.
# A parameter: a typed method's own names, the operations an expression calls, a plan's classes.
OFTEN = {
    "a": (*TYPED_LOCALS, "isfinite", "shown", "held_to", "lookup", "lookup_or", "struct", "math", "RdisError",
          "RdisValueError", "Robot", "Primitive", "Param", "Pack", "FrameUse", "StateValues", "Args", "Incoming",
          "Frame", "Port"),
    # An input (a method of the robot's own class): the robot's methods and attributes.
    "n": ("open", "close", "tick", "run_for", "call_primitive", "call_interface", "call_input", "state",
          "sensors", "device", "name", "sensor_age", "read_sensor", "startup", "terminate"),
    # A state variable (an attribute of the state's class), a primitive or an interface (a method).
    "s": ("keys", "items", "values", "get", "state", "name", "robot"),
    "p": ("robot", "open", "close", "state", "request", "lane"),
}
OFTEN["q"] = OFTEN["a"]
OFTEN["i"] = OFTEN["p"]


PROBE = """\
robot probe {{ author "tests" }}
state {name}: int = 0
connection link: serial {{ baud 9600 }}
primitive {name}({name}: int in 0..9) on link pack "BB" (1, {name}) unpack "B" {{ {name} = out[0] }}
interface {name}({name}: int) {{ {name}({name}) }}
"""


@functools.cache
def engine_names() -> tuple[str, ...]:
    """The engine's names a description may also give (each tried as every kind of name)."""
    robot = [name for name in dir(Robot) if not name.startswith("__")]
    candidates = sorted({*carry.names(), *robot, *(name for names in OFTEN.values() for name in names)})
    taken = _adapter_fields()
    return tuple(name for name in candidates
                 if re.fullmatch(r"[A-Za-z_]\w*", name) and name not in taken and not _refused(PROBE.format(name=name)))


def _adapter_fields() -> frozenset[str]:
    """The standard adapters' field names (`name`, `position`, `linear`...): an input's arguments
    read them before the description's own names, so a name renamed to one would mean the field."""
    model = compile_text("probe.rdis", PROBE.format(name="probe")).model
    assert model is not None
    return frozenset(field.name for adapter in model.adapters.values() for field in adapter.fields)


def _refused(text: str) -> bool:
    diagnostics = compile_text("probe.rdis", text).diagnostics.items
    return any(d.severity.name == "ERROR" for d in diagnostics)


# Robot names whose class would be named as an engine class (`incoming` -> Incoming).
ROBOTS = ("incoming", "robot", "frame", "port", "port_spec", "state", "calls", "device", "primitive", "reader")


@st.composite
def renamings(draw: Any, text: str) -> dict[str, str]:
    """A distinct engine name for each name of `text` the generator drew, the robot's too."""
    pool = engine_names()
    renaming = {ROBOT: draw(st.sampled_from(ROBOTS))}
    for name in sorted(set(DRAWN.findall(_outside_strings(text)))):
        often = [n for n in OFTEN.get(name[0], ()) if n in pool and n not in renaming.values()]
        unused = [n for n in pool if n not in renaming.values()]
        likely = often and draw(st.integers(0, 3)) > 0  # three times in four, where there are some
        renaming[name] = draw(st.sampled_from(often if likely else unused))
    return renaming


def _outside_strings(text: str) -> str:
    return STRING.sub('""', text)


def renamed(text: str, renaming: Mapping[str, str]) -> str:
    """`text` with each name renamed, string literals left as they are."""
    if ROBOT in renaming:
        text = text.replace(f"robot {ROBOT} {{", f"robot {renaming[ROBOT]} {{", 1)
    out, at = [], 0
    for literal in STRING.finditer(text):
        out.append(DRAWN.sub(lambda m: renaming.get(m.group(), m.group()), text[at:literal.start()]))
        out.append(literal.group())
        at = literal.end()
    out.append(DRAWN.sub(lambda m: renaming.get(m.group(), m.group()), text[at:]))
    return "".join(out)


class Renamed:
    """A robot of a renamed description, taking calls by the names as drawn: what the rest of the
    differential test reads is the description as drawn (its state by those names, an error's
    element too)."""

    def __init__(self, robot: Any, renaming: Mapping[str, str]) -> None:
        self._robot = robot
        self._to = dict(renaming)
        self._back = {new: old for old, new in renaming.items()}

    def __getattr__(self, name: str) -> Any:
        return getattr(self._robot, name)

    @property
    def state(self) -> dict[str, Any]:
        return {self._back.get(name, name): value for name, value in dict(self._robot.state).items()}

    @property
    def sensors(self) -> _Sensors:
        return _Sensors(self._robot.sensors, self._to)

    def sensor_age(self, name: str) -> Any:
        return self._robot.sensor_age(self._to.get(name, name))

    def call_primitive(self, name: str, *args: Any) -> Any:
        return self._called(self._robot.call_primitive, name, args, {})

    def call_interface(self, name: str, *args: Any) -> Any:
        return self._called(self._robot.call_interface, name, args, {})

    def call_input(self, name: str, **fields: Any) -> Any:
        return self._called(self._robot.call_input, name, (), fields)

    def _called(self, call: Any, name: str, args: tuple[Any, ...], fields: dict[str, Any]) -> Any:
        try:
            return call(self._to.get(name, name), *args, **fields)
        except Exception as err:
            element, colon, rest = str(err).partition(":")  # the element an error names first, as drawn
            kind, _, name = element.rpartition(" ")  # "p0", or "primitive p0" as a call's values are taken
            if colon and name in self._back and len(err.args) == 1:
                err.args = (f"{kind} {self._back[name]}".lstrip() + colon + rest,)
            raise


class _Sensors:
    """A robot's sensors, by the names as drawn."""

    def __init__(self, sensors: Any, renaming: Mapping[str, str]) -> None:
        self._sensors = sensors
        self._to = renaming

    def __getattr__(self, name: str) -> Any:
        return getattr(self._sensors, self._to.get(name, name))
