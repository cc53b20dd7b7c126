"""Model → a standalone Python driver module (`rdisc emit-python`).

A driver is the engine (the modules of `rdisc.engine` as marked sections: the same
code the runtime runs) and the description's plans, written as Python source: each
expression of the checked IR printed as a small function with the parser's
precedence table, each encoder, decoder and frame as its constructor. Over them,
typed classes give every input, interface and primitive a real method
(`robot.inputs.set_velocity(linear=0.2, angular=0.0)`), so that a type checker
catches a misspelt name. The operations of expressions that Python's own operators
would not bound or check as the interpreter does (float overflow, powers, shifts, long
strings) are calls of rdisc.engine.operations, whose text the module carries too.

What comes from the description enters the text only as a checked name (an
identifier, renamed with a trailing underscore where it would clash with a
Python keyword or a name the driver uses) or through `repr`. Nothing is
evaluated: the generator only prints. The module is deterministic: the same
Model and source name give byte-identical text.
"""

from __future__ import annotations

import dataclasses
import functools
import keyword
import os
from collections.abc import Iterable, Mapping
from types import ModuleType

from rdisc import engine
from rdisc import lower as lowering
from rdisc.emit import python_support as support
from rdisc.emit.canonical import range_written
from rdisc.emit.python_expr import Chain, Compiler, Paren, Py, binary, lines, literal, quoted, table_name
from rdisc.emit.python_expr import call as function_call
from rdisc.emit.python_frame import OneStep, byte_terms, reads_state, type_tests
from rdisc.emit.python_lane import lane_statements
from rdisc.emit.python_lane import names as lane_names
from rdisc.emit.writer import Writer, printable
from rdisc.engine import carry
from rdisc.lower import lower
from rdisc.lowering.constructs import Construct
from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.semantics.operators import surely_float
from rdisc.source import SourceFile, Span, place
from rdisc.syntax import precedence as p

__all__ = ["import_driver", "to_python"]

_PY_TYPES = {Type.INT: "int", Type.FLOAT: "float", Type.BOOL: "bool", Type.STRING: "str", Type.BYTES: "bytes"}


_SIGNATURE = {"state": "state: StateValues", "args": "args: Args", "reply": "reply: Sequence[Any]"}


def _sample(type_: m.AnyType, comma: str) -> str:
    """A value of `type_` as an example shows it (an array's elements joined by `comma`)."""
    if isinstance(type_, m.Array):
        return "[" + comma.join([_sample(type_.element, comma)] * max(type_.size, 1)) + "]"
    return {Type.INT: "0", Type.FLOAT: "0.0", Type.BOOL: "False", Type.STRING: '""', Type.BYTES: '""'}[type_]


def _py_type(type_: m.AnyType) -> str:
    """The annotation of a value of `type_`: an array is a tuple (a list is taken too)."""
    if isinstance(type_, m.Array):
        return f"Sequence[{_PY_TYPES[type_.element]}]"
    return _PY_TYPES[type_]

# Names a plan function may use: a parameter or field of the same name would hide
# them, so such a parameter gets a trailing underscore. The engine's (`lookup`,
# `element`, ...) are among them too (`_body_names`).
_BODY_NAMES = frozenset((
    "self", "state", "args", "reply", "fields", "type", "Exception",
    "float", "int", "round", "abs", "min", "max", "str", "bool", "len", "bytes", "math", "struct", "re",
    "Any", "Args", "StateValues", "Sequence", "Value",
))
# Members of State besides the state variables (it is a Mapping).
# The most items a dict display is built from at its full size (CPython's BUILD_CONST_KEY_MAP); a larger
# one grows an item at a time, and a copy of its keys, filled in, costs half as much.
_DISPLAYED = 16
_STATE_MEMBERS = frozenset(("keys", "items", "values", "get"))
# The classes a driver defines for its robot, by their names' endings after the robot's class name.
_CLASS_ENDINGS = ("", "State", "Inputs", "Interfaces", "Primitives", "Sensors")


def to_python(model: m.Model, source_name: str, *, sources: Mapping[str, SourceFile] | None = None) -> str:
    """The driver module for `model`, generated from the file called `source_name`.

    `sources` (the files read while compiling, by path) give the `# file:line`
    comments; without them the comments are left out.
    """
    return _Driver(model, source_name, sources or {}).module()


def import_driver(description: str | os.PathLike[str], folder: str | os.PathLike[str],
                  module_name: str | None = None) -> ModuleType:
    """The driver of the description file `description`, written into `folder` and
    imported (as `module_name`, by default ROBOT_driver): the compiled driver in this
    process, without a separate `rdisc emit-python`. A description with errors raises
    rdisc.runtime.RdisLoadError."""
    import importlib.util
    import sys

    from rdisc.compile import compile_path
    from rdisc.diagnostics.load_error import RdisLoadError

    path = os.fspath(description)
    compilation = compile_path(path)
    if compilation.model is None or compilation.diagnostics.has_errors():
        raise RdisLoadError.of(path, compilation.diagnostics, compilation.sources)
    name = module_name or f"{_identifier(compilation.model.robot.name)}_driver"
    target = os.path.join(os.fspath(folder), f"{name}.py")
    with open(target, "w", encoding="utf-8") as out:
        out.write(to_python(compilation.model, os.path.basename(path), sources=compilation.sources))
    spec = importlib.util.spec_from_file_location(name, target)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses look their module up by name
    spec.loader.exec_module(module)
    return module


# ---- names ----------------------------------------------------------------------------------


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


def _docstring(text: str) -> str:
    """A triple-quoted docstring that reads back as `text` (its lines right-stripped)."""
    body = "\n".join(line.rstrip() for line in text.strip("\n").split("\n"))
    escaped = printable(body.replace("\\", "\\\\"), keep="\n").replace('"""', '\\"\\"\\"')
    if escaped.endswith('"') and (len(escaped) - 1 - len(escaped[:-1].rstrip("\\"))) % 2 == 0:
        escaped = escaped[:-1] + '\\"'
    if "\n" in escaped:
        return f'"""{escaped}\n"""'
    return f'"""{escaped}"""'


# ---- the module ------------------------------------------------------------------------------


class _Driver:
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

    # -- the whole module ---------------------------------------------------------------------

    def module(self) -> str:
        plans = Writer()
        self.plans(plans)
        w = Writer()
        w.line(_docstring(self.header()))
        w.blank(1)
        _section(w, "the rdisc engine: the modules of rdisc/engine, each after its marker")
        w.raw(support.engine_text())
        w.blank(2)
        _section(w, f"{self.model.robot.name}: the plans of {self.source_name}")
        w.blank(1)
        w.line(f"ROBOT = {quoted(self.model.robot.name)}")
        w.blank(2)
        w.raw(plans.text().rstrip("\n"))
        w.blank(2)
        _section(w, f"the robot: {self.cls}, connect(), main()")
        w.blank(1)
        self.facade(w)
        w.blank(2)
        w.line('if __name__ == "__main__":')
        with w.indented():
            w.line("sys.exit(main())")
        return w.text()

    def header(self) -> str:
        robot = self.model.robot
        module = robot.name
        text = [f"{robot.name}: {robot.description or 'a robot described in RDIS'}."]
        if robot.author:
            text.append(f"By {robot.author}.")
        if robot.doc:
            text += ["", robot.doc]
        text += [
            "",
            f"A driver generated by `rdisc emit-python` from {self.source_name}: change the",
            "description and generate it again rather than editing this file. It needs only",
            "the standard library, and pyserial to open ports by name or URL. It carries the",
            "rdisc engine, the code the rdisc runtime runs, followed by the description's plans.",
            "",
            f"    from {module} import connect",
            "",
            '    with connect("/dev/ttyUSB0") as robot:  # startup hooks now, terminate hooks on leaving',
            "        robot.on_output(print)",
        ]
        command = f"    python {module}.py --port /dev/ttyUSB0"
        example = next(iter(self.model.inputs.values()), None)
        if example is not None:
            fields = self.model.adapters[example.adapter].fields
            arguments = ", ".join(f"{f.name}={_sample(f.type, ', ')}" for f in fields)
            text.append(f"        robot.inputs.{_escape(example.name, {'_robot'})}({arguments})")
            command += f" --call {example.name}" + "".join(f" {f.name}={_sample(f.type, ',')}" for f in fields)
        text += ["", "or as a program (`--help` for its options):", "", command + " --watch"]
        return "\n".join(text)

    # -- plans ---------------------------------------------------------------------------------------

    def plans(self, w: Writer) -> None:
        """The lowered plans (`rdisc.lower`), each Code a function, each plan a constant."""
        model = self.model
        lowered = lower(model)
        device = lowered.device
        self.state_order = tuple(device.state)
        for table in model.tables.values():
            w.blank(2)
            entries = ", ".join(f"{literal(k, table.key_type).text}: {literal(v, table.value_type).text}"
                                for k, v in table.entries)
            _emit(w, f"{table_name(table.name)}: dict[Any, Any] = ", Py(f"{{{entries}}}", p.ATOM))
            if table.doc:
                w.line(_docstring(table.doc))
        for frame in model.frames.values():
            w.blank(2)
            self.comment(w, frame.span, f"frame {frame.name}")
            framed = lowered.frames[frame.name]
            if framed.fields is not None:
                self.code(w, f"_f_{frame.name}", framed.fields)
                w.blank(2)
            if framed.choose is not None:
                self.code(w, f"_choose_{frame.name}", framed.choose)
                w.blank(2)
            if framed.answer is not None:
                self.code(w, f"_answer_{frame.name}", framed.answer)
                w.blank(2)
            self.constant(w, self.plan["frame", frame.name], framed)
        for prim in model.primitives.values():
            w.blank(2)
            self.primitive(w, prim, device.primitives[prim.name])
        for o in model.outputs.values():
            w.blank(2)
            self.comment(w, o.span, f"output {o.name}: {o.adapter}")
            output = lowered.outputs[o.name]
            self.code(w, f"_o_{o.name}", output.fields)
            w.blank(2)
            self.constant(w, self.plan["output", o.name], output)
        for iface in model.callees_first():
            w.blank(2)
            self.interface(w, iface, device.interfaces[iface.name])
        for i in model.inputs.values():
            w.blank(2)
            self.comment(w, i.span, f"input {i.name}: {i.adapter} -> {i.interface}")
            plan = device.inputs[i.name]
            self.code(w, f"_in_{i.name}", plan.args)
            request = {"request": self.request(w, i, plan)} if plan.request else {}
            if request:
                self.slots["input", i.name] = request["request"]
            w.blank(2)
            self.constant(w, self.plan["input", i.name], plan, request)
        for c in model.connections.values():
            w.blank(2)
            baud = f"{c.baud} baud" if c.baud_setting is None else f"baud {c.baud_setting} ({c.baud} unless given)"
            line = "" if c.line_text() == "8N1" else f", {c.line_text()}"
            self.comment(w, c.span, f"connection {c.name}: {c.kind}, {baud}{line}")
            self.constant(w, self.plan["connection", c.name], device.connections[c.name])
        w.blank(2)
        named = {"name": "ROBOT"}
        if device.messages:
            named["messages"] = "_MESSAGES"
            self.messages(w, device.messages)
        if device.settings:
            named["settings"] = "_SETTINGS"
            w.line("_SETTINGS = (")
            with w.indented():
                w.lines([f"{self.text(setting)}," for setting in device.settings])
            w.line(")")
            w.line('"""The settings, given when connecting (`connect(port, NAME=value)`, `--set NAME=VALUE`)."""')
            w.blank(2)
        self.constant(w, "_DEVICE", device, named)
        w.line('"""The whole description, planned: what the robot runs."""')

    @staticmethod
    def messages(w: Writer, messages: Mapping[str, engine.Message]) -> None:
        """The ROS 2 message of each adapter, for recordings: its definition a line of text a line."""
        w.line("_MESSAGES = {")
        with w.indented():
            for adapter, message in messages.items():
                w.line(f"{quoted(adapter)}: Message(")
                with w.indented():
                    w.line(f"{quoted(message.type)},")
                    text = [quoted(line) for line in message.definition.splitlines(keepends=True)]
                    w.lines([*text[:-1], f"{text[-1]},"])
                    w.line(f"{_tuple([quoted(name) for name in message.fields])},")
                    w.line(f"{_tuple([quoted(path) for path in message.paths])},")
                w.line("),")
        w.line("}")
        w.line('"""Each adapter\'s ROS 2 message, as a recording (`--record`) carries it."""')
        w.blank(2)

    def code(self, w: Writer, name: str, code: lowering.Code) -> None:
        """`def name(...)` computing what `code` says; plans refer to it by that name."""
        self.names[code] = name
        signature = ", ".join(_SIGNATURE[taken] for taken in code.takes)
        if code.gives is lowering.Gives.BOOL:
            ((_, condition, _),) = code.items
            self.predicate(w, name, signature, code.params, condition)
        else:
            returns = "Args" if code.gives is lowering.Gives.LIST else "dict[str, Value]"
            self.function(w, name, signature, code.params, code.items, returns)

    def actions(self, w: Writer, name: str, code: lowering.Code) -> None:
        """Post-actions as `code` does, or, where they set at least two thirds of the state
        variables (each once), as a function giving the whole new state, which the engine
        publishes as it is (`Primitive.renews`): cheaper than merging so many changes into it.
        Never with sensors: their values are state that a whole new state would drop."""
        keys = [key for key, _, _ in code.items]
        if self.model.sensors or len(set(keys)) != len(keys) or 3 * len(keys) < 2 * len(self.state_order):
            self.code(w, name, code)
            return
        self.names[code] = name
        self.renewing.add(code)
        signature = ", ".join(_SIGNATURE[taken] for taken in code.takes)
        self.function(w, name, signature, code.params, code.items, "dict[str, Value]", self.state_order)

    def constant(self, w: Writer, name: str, plan: object, given: Mapping[str, str] = {}) -> None:
        """`name = Plan(...)`, one argument a line when long; `given`: fields written as these names."""
        self.names[plan] = name
        if isinstance(plan, lowering.Primitive) and len(plan.actuators) > 1 and "actuators" not in given:
            limits = "".join(f"\n    {self.text(limit)}," for limit in plan.actuators)  # one an actuator, a line each
            given = {**given, "actuators": f"({limits}\n)"}
        args, options = self.arguments(plan, given)
        if isinstance(plan, lowering.Primitive) and plan.actions in self.renewing:
            options["renews"] = "True"
        _construct(w, f"{name} = ", type(plan).__name__, args, options)

    def arguments(self, made: object, given: Mapping[str, str] = {}) -> tuple[list[str], dict[str, str]]:
        """The constructor arguments of a plan or a construct, as text: a plan's fields before
        `KW_ONLY` in order (those left at their defaults at the end left out, unless an option
        follows), the others by keyword when not at their defaults."""
        if isinstance(made, Construct):
            return [self.text(a) for a in made.args], {key: self.text(value) for key, value in made.options}
        positional: list[tuple[str, bool]] = []
        options: dict[str, str] = {}
        for f in dataclasses.fields(made):  # type: ignore[arg-type]
            if f.metadata.get(lowering.LOWERED_ONLY):
                continue
            value = getattr(made, f.name)
            default = f.default_factory() if f.default_factory is not dataclasses.MISSING else f.default
            text = given.get(f.name) or self.text(value)
            if not f.kw_only:
                positional.append((text, default is not dataclasses.MISSING and value == default))
            elif f.name in given or value != default:
                options[f.name] = text
        while positional and positional[-1][1] and not options:
            positional.pop()
        return [text for text, _ in positional], options

    def text(self, value: object) -> str:
        """A value of a plan as Python: a named plan or Code by its name, another plan or a
        construct as its constructor call, a hook's Code as a lambda, data through repr."""
        match value:
            case lowering.ErrorReply() if value in self.names:  # written before its primitive
                return self.names[value]
            case lowering.Code() if value not in self.names:  # a hook's arguments, over state
                items = ", ".join(self.exprs.expr(e, {}).text for _, e, _ in value.items)
                return f"lambda state: [{items}]"
            case (lowering.Code() | lowering.Frame() | lowering.Primitive() | lowering.Interface() | lowering.Output() | lowering.Input()
                  | lowering.Connection()):
                return self.names[value]
            case (Construct() | lowering.Call() | lowering.FrameUse() | lowering.Hook() | lowering.NoReply()
                  | lowering.LineReply() | lowering.FixedReply() | lowering.FramedReply() | lowering.TaggedReply()
                  | lowering.TaggedStream() | lowering.SubPayloads() | lowering.Records() | lowering.KeyedReply()
                  | lowering.SeveralReplies() | lowering.ListedReplies() | lowering.ErrorReply() | lowering.Sensor()):
                args, options = self.arguments(value)
                return f"{_kind(value)}({', '.join([*args, *(f'{k}={v}' for k, v in options.items())])})"
            case tuple() if value and isinstance(value[0], lowering.Entry):  # a reply table, written before
                return self.names[value]
            case type():
                return value.__name__
            case bool() | None:
                return repr(value)
            case int():
                return repr(value)
            case float():
                return literal(value, Type.FLOAT).text
            case str() | bytes():
                return quoted(value)
            case tuple():
                return _tuple([self.text(v) for v in value])
            case list():
                return "[" + ", ".join(self.text(v) for v in value) + "]"
            case dict():
                return "{" + ", ".join(f"{self.text(k)}: {self.text(v)}" for k, v in value.items()) + "}"
        raise AssertionError(f"no text for a {type(value).__name__}")

    def request(self, w: Writer, i: m.DomainInput, plan: lowering.Input) -> str:
        """The input's request in one step (the engine's `Input.request`): the input's and the
        call's expressions one after the other, packed. Returns the function's name."""
        (call,) = plan.interface.calls
        assert isinstance(call.target, lowering.Primitive) and call.target.encoder is not None  # `request`
        pack = _constant_name(f"PACK_{i.name}", self.taken)
        w.blank(2)
        w.line(f"{pack} = struct.Struct({quoted(call.target.encoder.args[0])}).pack")
        fields = plan.args.params
        step = OneStep("_write", self.names[call.target], "_input_in_full", self.plan["input", i.name], fields,
                       pack, call=call, binding=plan.args, connection=call.target.connection)
        self.one_step["input", i.name] = step
        local = _params([(f.name, f.type) for f in fields])
        function = f"_request_{i.name}"
        w.blank(2)
        w.line(f"# input {i.name}, written at once")
        with w.block(f"def {function}(state: StateValues, args: Args) -> bytes | None:"):
            names = [local[f.name] for f in fields]
            if names:
                w.line(f"({names[0]},) = args" if len(names) == 1 else f"{', '.join(names)} = args")
                with w.block(f"if {' or '.join(type_tests(names, fields, refused=True))}:"):
                    w.line("return None")
            with w.block("try:"):
                self.packing(w, step, local, "return ")
            with w.block("except Exception:  # noqa: BLE001 - the general way says what is wrong"):
                w.line("return None")
        return function

    def primitive(self, w: Writer, prim: m.Primitive, plan: lowering.Primitive) -> None:
        self.comment(w, prim.span, f"primitive {prim.name}")
        base, const = f"_p_{prim.name}", self.plan["primitive", prim.name]
        self.code(w, f"{base}_values", plan.values)
        shape = plan.reply
        functions = [("frame", None if plan.frame is None else plan.frame.args), ("lines", plan.lines),
                     *((f"reply_frame_{n}", use.args) for n, use in enumerate(_reply_frames(shape))),
                     ("error_frame", _error_frame(shape)), ("error_when", _error_when(shape)), ("expect", plan.expect)]
        for suffix, code in functions:
            if code is not None:
                w.blank(2)
                self.code(w, f"{base}_{suffix}", code)
        error = _error(shape)
        if error is not None:
            w.blank(2)
            w.line("# the reply that may come instead")
            self.constant(w, f"{const}_ERROR", error)
        answers = shape.answers if isinstance(shape, lowering.ListedReplies) else ()
        for n, answer in enumerate(answers, 1):  # each its own plan: frame, decoder, expect, post-actions
            own = (("frame", None if answer.frame is None else answer.frame.args), ("expect", answer.expect),
                   ("actions", answer.actions))
            for suffix, code in own:
                if code is not None and code not in self.names:
                    w.blank(2)
                    (self.actions if suffix == "actions" else self.code)(w, f"{base}_reply_{n}_{suffix}", code)
            w.blank(2)
            w.line(f"# reply {n} of {len(answers)}")
            self.constant(w, f"{const}_REPLY_{n}", answer)
        table = _table(shape)
        entries = [(None, plan)] if table is None else [(entry.case, entry.plan) for entry in table]
        texts: list[str] = []
        for case, entry in entries:
            name = const if case is None else f"{const}_{_case(case).upper()}"
            if entry.actions is not None and entry.actions not in self.names:
                w.blank(2)
                self.actions(w, f"{base}_actions" if case is None else f"{base}_{_case(case)}_actions", entry.actions)
            w.blank(2)
            if case is not None:
                w.line(f"# reply {case.values_text()}" if case.under is None
                       else f"# reply {case.under}, then {case.values_text()}")
                if case.last is None:
                    texts.append(f"{case.table_keys()[0]!r}: {name}")
                elif case.under is None:
                    texts.append(f"**dict.fromkeys({case.values()!r}, {name})")  # a range entry
                else:
                    texts.append(f"**{{({case.under}, tag): {name} for tag in {case.values()!r}}}")
            if entry.request is not None:
                step = self.written(w, prim, entry.request, "_write")
                if case is None:
                    self.one_step["primitive", prim.name] = step
                self.constant(w, name, entry, {"request": f"_p_{prim.name}_request"})
                continue
            if case is None and entry.asked is not None:  # a plain exchange: its typed method packs its request
                self.one_step["primitive", prim.name] = self.written(w, prim, entry.asked, "_ask")
            self.constant(w, name, entry)
        if table is not None:
            self.names[table] = "{" + ", ".join(texts) + "}"
            if len(f"    reply={self.text(shape)},") > w.width():  # the table its own constant, an entry a line
                w.blank(2)
                w.line(f"{const}_TABLE = {{")
                with w.indented():
                    w.lines([f"{item}," for item in texts])
                w.line("}")
                self.names[table] = f"{const}_TABLE"
            w.blank(2)
            self.constant(w, const, plan)

    def written(self, w: Writer, prim: m.Primitive, written: lowering.Written, way: str) -> OneStep:
        """The primitive's request in one step, as the lowering describes it: its parameters
        checked, its values packed between the frame's constant bytes, the checksum added to.
        Only written (`way` "_write"), also the engine's `Primitive.request` (`_p_NAME_request`);
        a plain exchange (`way` "_ask") only its typed method's. Blank lines written after."""
        plan = self.plan["primitive", prim.name]
        if written.constant is not None:
            step = OneStep(way, plan, "_call_primitive", plan, written.params, written=written,
                           connection=prim.connection)
            if way == "_write":
                self.slots["primitive", prim.name] = function = f"_p_{prim.name}_request"
                with w.block(f"def {function}(state: StateValues, args: Args) -> bytes | None:"):
                    w.line(f'"""{prim.name}, only written: always these bytes (given arguments, the general way '
                           'decides)."""')
                    w.line(f"return None if args else {quoted(written.constant)}")
                w.blank(2)
            return step
        whole = written.whole  # decided by the lowering
        pack = _constant_name(f"PACK_{prim.name}", self.taken)
        w.line(f"{pack} = struct.Struct({quoted(whole.format if whole else written.format)}).pack")
        checked = ("", "")
        if whole is None and written.checksum is not None:
            check = _constant_name(f"PACK_{prim.name}_CHECKSUM", self.taken)
            w.line(f"{check} = struct.Struct({quoted(written.check_format)}).pack")
            if written.partial is not None:  # a sum: the constant bytes' summed here
                before, after = _summed(written.checksum.value, [f"{written.partial:#x}", "sum(\0)"]).split("\0")
                checked = (f"{check}({before}", f"{after})")
            else:
                function_of = _constant_name(f"CHECKSUM_{prim.name}", self.taken)
                w.line(f"{function_of} = {self.text(written.checksum)}")
                covered = f"{quoted(written.covered)} + " if written.covered else ""
                checked = (f"{check}({function_of}({covered}", "))")
        w.blank(2)
        step = OneStep(way, plan, "_call_primitive", plan, written.params, pack, written, whole, checked,
                       connection=prim.connection)
        if way != "_write":
            return step
        self.slots["primitive", prim.name] = function = f"_p_{prim.name}_request"
        local = _params([(prm.name, prm.type) for prm in written.params])
        with w.block(f"def {function}(state: StateValues, args: Args) -> bytes | None:"):
            w.line(f'"""{prim.name}, only written: its request in one step (None: the general way decides)."""')
            with w.block("try:"):
                names = [local[prm.name] for prm in written.params]
                if not names:
                    with w.block("if args:"):
                        w.line("return None")
                else:
                    w.line(f"({names[0]},) = args" if len(names) == 1 else f"{', '.join(names)} = args")
                tests = type_tests(names, written.params, refused=True)
                together = f"if {' or '.join(tests)}:"
                for test in [] if not tests else [together] if len(together) <= w.width() - 8 else [
                        f"if {test}:" for test in tests]:
                    with w.block(test):  # one test, or one a parameter
                        w.line("return None")
                self.packing(w, step, local, "return ")
            with w.block("except Exception:  # noqa: BLE001 - the general way says what is wrong"):
                w.line("return None")
        w.blank(2)
        return step

    def packing(self, w: Writer, step: OneStep, local: Mapping[str, str], target: str) -> None:
        """The statements of a one-step request, the values already tested: the last one `target`
        (`return ` or `request = `) the bytes. `local`: the parameters' (or fields') names."""
        taken = set(local.values()) | _body_names()
        if step.call is not None:  # an interface's one call: an input's fields bound to its parameters first
            call, inner = step.call, local
            iface_params = call.args.params
            if step.binding is not None:
                inner = _params([(prm.name, prm.type) for prm in iface_params], frozenset(taken | {"request"}))
                used = set().union(*(_names(e) for _, e, _ in call.args.items))
                if iface_params:
                    targets = [inner[prm.name] if prm.name in used else "_" for prm in iface_params]
                    bound = [self.exprs.bound(e, prm.type, local) for (_, e, _), prm in zip(step.binding.items, iface_params)]
                    _items(w, f"{', '.join(targets)} = ", "(", bound, ")" if len(bound) > 1 else "")
            packed = [self.exprs.packed(e, t, inner) for _, e, t in call.args.items]
            _items(w, target, f"{step.pack}(", packed, ")")
            return
        written = step.written
        assert written is not None
        packed = [self.exprs.packed(e, t, local) for _, e, t in written.values.items]
        if step.whole is not None:
            self.whole(w, step, packed, taken, target)
            return
        if not (written.head or step.checked[0] or written.tail):
            _items(w, target, f"{step.pack}(", packed, ")")
            return
        payload = _escape("payload", taken)
        _items(w, f"{payload} = ", f"{step.pack}(", packed, ")")
        pieces = [quoted(written.head)] if written.head else []
        pieces += [payload] + ([payload.join(step.checked)] if step.checked[0] else [])
        pieces += [quoted(written.tail)] if written.tail else []
        w.line(f"{target}{' + '.join(pieces)}")

    def whole(self, w: Writer, step: OneStep, packed: list[Py], taken: set[str], target: str) -> None:
        """`target PACK(head, values..., checksum, tail)`: a sum checksum of the values' bytes, each
        value computed once (a name where it is more than a name or a constant)."""
        written, whole = step.written, step.whole
        assert written is not None and whole is not None
        sums: list[Py] = []
        taken = taken | {"request"}
        if whole.partial is not None:
            for n, ((_, e, _), value, slot) in enumerate(zip(written.values.items, packed, whole.slots), 1):
                if isinstance(e, m.Const):
                    continue  # summed already
                if not value.text.isidentifier():
                    name = _escape(f"value_{n}", taken)
                    taken.add(name)
                    _emit(w, f"{name} = ", value)
                    packed[n - 1] = value = Py(name, p.ATOM)
                sums += [Py(term, p.ATOM) for term in byte_terms(value.text, slot)]
        values = [Py(quoted(written.head), p.ATOM)] if written.head else []
        values += packed
        if whole.partial is not None and written.checksum is not None:
            checksum = _escape("checksum", taken)
            terms = [Py(f"{whole.partial:#x}", p.ATOM), *sums]
            total = _summed(written.checksum.value, [term.text for term in terms])
            if len(f"{checksum} = {total}") > w.width():  # the sum first, a term a line
                summed = _escape("summed", taken | {checksum})
                _emit(w, f"{summed} = ", functools.reduce(lambda a, b: binary("+", a, b), terms))
                total = _summed(written.checksum.value, [summed])
            w.line(f"{checksum} = {total}")
            values.append(Py(checksum, p.ATOM))
        if written.tail:
            values.append(Py(quoted(written.tail), p.ATOM))
        _items(w, target, f"{step.pack}(", values, ")")

    def interface(self, w: Writer, iface: m.Interface, plan: lowering.Interface) -> None:
        self.comment(w, iface.span, f"interface {iface.name}" + (" (periodic)" if iface.periodic else ""))
        for n, (c, call) in enumerate(zip(iface.run_order(), plan.calls), 1):
            function = f"_i_{iface.name}_{n}"
            if n > 1:
                w.blank(2)
            said = [f"priority {c.priority}"] if c.priority else []
            said += [f"delay {c.delay_ms:g} ms"] if c.delay_ms else []
            said += ["when ..."] if c.when is not None else []
            said += [f"until ... every {c.every_ms:g} ms within {c.within_ms:g} ms"] if c.until is not None else []
            self.comment(w, c.span, ", ".join([f"call {'interface ' if c.interface else ''}{c.primitive}", *said]))
            self.code(w, function, call.args)
            if call.when is not None:
                w.blank(2)
                self.code(w, f"{function}_when", call.when)
            if call.until is not None:
                w.blank(2)
                self.code(w, f"{function}_until", call.until)
        if plan.calls:
            w.blank(2)
        self.constant(w, self.plan["interface", iface.name], plan)
        if lowering.written_at_once(plan):  # its typed method packs its one call's values and writes them
            (call,) = plan.calls
            assert isinstance(call.target, lowering.Primitive) and call.target.encoder is not None
            pack = _constant_name(f"PACK_{iface.name}_CALL", self.taken)
            w.blank(2)
            w.line(f"{pack} = struct.Struct({quoted(call.target.encoder.args[0])}).pack")
            self.one_step["interface", iface.name] = OneStep(
                "_write", self.names[call.target], "_call_interface", self.plan["interface", iface.name],
                call.args.params, pack, call=call, connection=call.target.connection)

    # -- the typed face --------------------------------------------------------------------------

    def facade(self, w: Writer) -> None:
        model, cls = self.model, self.cls
        with w.block(f"class {cls}State(State):"):
            w.line(_docstring(
                f"The state variables of {model.robot.name}: what was last read from the robot, and\n"
                "its constants. Immutable: read a variable as an attribute or by name (`state[\"name\"]`)."))
            w.blank(1)
            w.line("__slots__ = ()")
            for s in model.states.values():
                if s.name in _STATE_MEMBERS or keyword.iskeyword(s.name):
                    continue  # by name only
                w.blank(1)
                self.comment(w, s.span)
                w.line(f"{s.name}: {_py_type(s.type)}")
                if s.doc:
                    w.line(_docstring(s.doc))
        if model.sensors:
            w.blank(2)
            with w.block(f"class {cls}Sensors(Sensors):"):
                w.line(_docstring("The sensors: `robot.sensors.NAME` is its value, read first when older than its\n"
                                  "cache time."))
                w.blank(1)
                w.line("__slots__ = ()")
                for sensor in model.sensors.values():
                    if sensor.name.startswith("_") or keyword.iskeyword(sensor.name):
                        continue  # by name only
                    w.blank(1)
                    self.comment(w, sensor.span)
                    w.line(f"{sensor.name}: {_py_type(sensor.type)}")
                    if sensor.doc:
                        w.line(_docstring(sensor.doc))
        for kind, title, elements in (
            ("input", "domain inputs: `robot.inputs.NAME(field=value, ...)`", model.inputs),
            ("interface", "interfaces: `robot.interfaces.NAME(...)`", model.interfaces),
            ("primitive", "primitives (one device command each): `robot.primitives.NAME(...)`", model.primitives),
        ):
            w.blank(2)
            with w.block(f"class {cls}{kind.capitalize()}s:"):
                w.line(_docstring(f"The {title}."))
                w.blank(1)
                w.line('__slots__ = ("_robot",)')
                w.blank(1)
                with w.block(f"def __init__(self, robot: {cls}) -> None:"):
                    w.line("self._robot = robot")
                taken: set[str] = {"_robot"}
                for name in elements:
                    method = _escape(name, taken)
                    taken.add(method)
                    w.blank(1)
                    if kind == "input":
                        self.input_method(w, model.inputs[name], method, "self._robot", keywords=True)
                    else:
                        self.call_method(w, kind, name, method)
        w.blank(2)
        robot = model.robot
        with w.block(f"class {cls}(Robot):"):
            doc = [f"{robot.description or robot.name}."]
            if robot.doc:
                doc += ["", robot.doc]
            doc += ["", "`connect()` makes one and opens it; `robot.inputs`, `robot.interfaces` and",
                    "`robot.primitives` hold a typed method for each element of the description."]
            w.line(_docstring("\n".join(doc)))
            w.blank(1)
            typed: tuple[tuple[str, str], ...] = (("inputs", "The domain inputs, as typed methods."),
                                                  ("interfaces", "The interfaces, as typed methods."),
                                                  ("primitives", "The primitives, as typed methods."))
            if model.sensors:
                typed += (("sensors", "The sensors, as typed attributes."),)
            # slots, not properties: every typed call reads one, and a slot is read without a call
            w.line(f"__slots__ = {_tuple([quoted(member) for member, _ in typed])}")
            for member, doc_ in typed:
                w.blank(1)
                w.line(f"{member}: {cls}{member.capitalize()}")
                w.line(f'"""{doc_}"""')
            w.blank(1)
            with w.block("def __init__(self, *, timeout: float = 1.0) -> None:"):
                w.line('"""A robot not connected yet: `open()` connects it. `timeout`: seconds a reply may take."""')
                w.line("super().__init__(_DEVICE, timeout=timeout)")
                for member, _ in typed:
                    made = "self.device.sensors, self.read_sensor" if member == "sensors" else "self"
                    w.line(f"self.{member} = {cls}{member.capitalize()}({made})")
                if self.dispatched:  # `call_primitive` goes to the typed method, which makes the request itself
                    w.line("self._one_step = {")
                    with w.indented():
                        w.lines([f"{quoted(name)}: (self.primitives.{method}, {count}),"
                                 for name, (method, count) in self.dispatched.items()])
                    w.line("}")
            w.blank(1)
            w.line("@property")
            with w.block(f"def state(self) -> {cls}State:"):
                w.line('"""The state variables now: an immutable snapshot."""')
                w.line(f"return {cls}State(self._state)")
            for i in model.inputs.values():
                w.blank(1)
                self.input_method(w, i, self.input_methods[i.name], "self", keywords=False)
            w.blank(1)
            with w.block(f"def __enter__(self) -> {cls}:  # noqa: PYI034 - typing.Self needs Python 3.11"):
                w.line("return self")
        w.blank(2)
        self.connect_function(w)
        w.blank(2)
        with w.block("def main(argv: list[str] | None = None) -> int:"):
            w.line(_docstring(
                "The command line, with the options of `rdisc run`: connect, make the --call calls in\n"
                "order, then run for --duration seconds from the end of the startup hooks (or, with\n"
                "--watch, until Ctrl-C). It always ends by closing the robot, which runs the terminate\n"
                "hooks. Exit status: 0 done; 1 the device failed; 2 a usage error; 130 after SIGINT; 143\n"
                "after SIGTERM."))
            about = f"Drive {robot.name} (a driver generated by rdisc from {self.source_name})."
            w.blank(1)
            with w.block("def run() -> int:"):
                w.line(f"parser = argparse.ArgumentParser(description={quoted(printable(about))})")
                w.line("add_arguments(parser, _DEVICE)")
                w.line("args = parser.parse_args(argv)")
                w.line(f"return run_command(args, {cls}(timeout=args.timeout), parser.prog)")
            w.blank(1)
            w.line("return command_line(run)  # SIGINT and SIGTERM handled from here: 130 or 143, no traceback")

    def input_method(self, w: Writer, i: m.DomainInput, method: str, robot: str, keywords: bool) -> None:
        """The typed method of an input, on the robot (`robot` "self") or on its inputs' object."""
        adapter = self.model.adapters[i.adapter]
        local = _params([(f.name, f.type) for f in adapter.fields], frozenset({"self"}))
        star = ", *" if keywords and adapter.fields else ""
        signature = star + "".join(f", {local[f.name]}: {_py_type(f.type)}" for f in adapter.fields)
        with w.block(f"def {method}(self{signature}) -> None:"):
            doc = [i.doc or f"The domain input `{i.name}`."]
            doc += ["", f"Takes {_a(adapter.name)} and runs the interface `{i.interface}`; errors are raised."]
            if adapter.fields:
                doc += ["", "Fields:"]
                for f in adapter.fields:
                    unit = f" [{f.unit}]" if f.unit else ""
                    about = f": {f.doc.splitlines()[0]}" if f.doc else ""
                    doc.append(f"    {local[f.name]}{unit}{about}")
            w.line(_docstring("\n".join(doc)))
            if robot != "self" and self.inline(self.one_step.get(("input", i.name)), local):
                # the robot's method of the same input: the request in one step is written there
                w.line(f"{robot}.{self.input_methods[i.name]}({', '.join(local[f.name] for f in adapter.fields)})")
                return
            self.runs(w, "input", i.name, robot, local)

    def call_method(self, w: Writer, kind: str, name: str, method: str) -> None:
        element = self.model.interfaces[name] if kind == "interface" else self.model.primitives[name]
        local = _params([(prm.name, prm.type) for prm in element.params], frozenset({"self"}))
        signature = "".join(f", {local[prm.name]}: {_py_type(prm.type)}"
                            + (f" = {literal(prm.default, prm.type).text}" if prm.default is not None else "")
                            for prm in element.params)
        with w.block(f"def {method}(self{signature}) -> None:"):
            doc = [element.doc or f"The {kind} `{name}`."]
            ranged = [f"    {local[prm.name]}: {range_written(prm)}" for prm in element.params if prm.low is not None]
            if ranged:
                doc += ["", "Ranges (a value outside is refused before anything is written):", *ranged]
            units = [f"    {local[prm.name]}: {prm.unit}" for prm in element.params if prm.unit is not None]
            if units:
                doc += ["", "Units (as the device takes them):", *units]
            w.line(_docstring("\n".join(doc)))
            self.runs(w, kind, name, "self._robot", local)
        if kind == "primitive" and self.inline(self.one_step.get((kind, name)), local):
            self.dispatched[name] = (method, len(element.params))

    def runs(self, w: Writer, kind: str, name: str, robot: str, local: Mapping[str, str]) -> None:
        """A typed method's body: an input or primitive with a request in one step makes it here
        (its values tested, packed by its struct) and hands it to the robot's write or plain
        exchange, else (values it does not take, or not on ports) the robot runs it the general
        way, which says what is wrong; any other element the general way."""
        plan, step = self.plan[kind, name], self.one_step.get((kind, name))
        values = ", ".join(local.values())
        if step is not None and self.inline(step, local):
            self.inline_body(w, step, robot, local)
            return
        function = self.slots.get((kind, name))
        if function is None:
            w.line(f"{robot}._{'input' if kind == 'input' else f'call_{kind}'}({plan}, [{values}])")
            return
        params = set(local.values())
        listed = _escape("values", params) if values else "[]"  # (an empty list twice: mypy infers no type of [])
        if robot != "self":
            named = _escape("robot", params | {listed})
            w.line(f"{named}, {listed} = {robot}, [{values}]" if values else f"{named} = {robot}")
            robot = named
        elif values:
            w.line(f"{listed} = [{values}]")
        sends = "_send_input" if kind == "input" else "_send"
        w.line(f"{robot}.{sends}({plan}, {function}({robot}._state, {listed}), {listed})")

    @staticmethod
    def inline(step: OneStep | None, local: Mapping[str, str]) -> bool:
        """Whether a typed method makes its request itself: none of its parameters' names hides
        a name the request's statements use (`_body_names()`, the module's `_` names, `robot`...)."""
        hidden = _body_names() | {"robot", "request", "tuple", "sum", "lane"} | lane_names()
        return step is not None and not any(name in hidden or name.startswith("_") for name in local.values())

    def inline_body(self, w: Writer, step: OneStep, robot: str, local: Mapping[str, str]) -> None:
        """The statements of a typed method that makes its request in one step (`OneStep`)."""
        values = ", ".join(local.values())
        asked = f", [{values}]" if step.way == "_ask" else ""  # the plain exchange's post-actions read them
        if robot != "self":
            w.line(f"robot = {robot}")
            robot = "robot"
        general = f"{robot}.{step.general}({step.plan}, [{values}])"
        constant = step.written.constant if step.written is not None else None
        if constant is not None:
            with w.block(f"if {robot}._direct:"):
                w.line(f"{robot}.{step.way}({step.target}, {quoted(constant)}{asked})")
            with w.block("else:"):
                w.line(general)
            return
        if step.call is not None:
            exprs = [e for _, e, _ in (*(step.binding.items if step.binding else ()), *step.call.args.items)]
        else:
            assert step.written is not None
            exprs = [e for _, e, _ in step.written.values.items]
        if reads_state(exprs):
            w.line(f"state = {robot}._state")
        lane = step.way == "_write"  # written through the connection's lane, in the method
        if lane:
            at = list(self.model.connections).index(step.connection)  # the engine's lanes: in this order
            w.line(f"lane = {robot}._lanes[{at}]  # {step.connection}: its port's lock and write (None: the general way)")
        tests = [f"{robot}._direct" if not lane else "lane is not None",
                 *type_tests([local[prm.name] for prm in step.params], step.params, refused=False)]
        condition = f"if {' and '.join(tests)}:"
        if len(condition) > w.width():
            w.line("if (")
            with w.indented():
                w.lines([tests[0], *(f"and {test}" for test in tests[1:])])
            w.line("):")
        else:
            w.line(condition)
        with w.indented():
            with w.block("try:"):
                self.packing(w, step, local, "request = ")
            with w.block("except Exception:  # noqa: BLE001, S110 - not taken here: the general way says why"):
                w.line("pass")
            with w.block("else:"):
                if lane:
                    self.through_lane(w, step, robot)
                else:
                    w.line(f"{robot}.{step.way}({step.target}, request{asked})")
                w.line("return")
        w.line(general)

    @staticmethod
    def through_lane(w: Writer, step: OneStep, robot: str) -> None:
        """`request` written as the engine's plain write writes it, with its statements
        (`python_lane`): under the port's lock, refused while the robot closes, a port's failure a
        typed error."""
        w.line("acquire, release, write = lane")
        w.lines(lane_statements(robot, step.target))

    def connect_function(self, w: Writer) -> None:
        own = ("port", "timeout", "threads", "on_output", "on_error", "on_io", "sim", "robot", self.cls)
        keywords = _params([(s.name, s.type) for s in self.model.settings.values()], frozenset(own))
        settings = list(self.model.settings.values())
        with w.block("def connect("):
            w.lines([
                "port: PortSpec | None = None,",
                "timeout: float = 1.0,",
                "threads: bool = True,",
                "*,",
                "on_output: OutputCallback | None = None,",
                "on_error: ErrorCallback | None = None,",
                "on_io: IoCallback | None = None,",
                "sim: Simulator | None = None,",
                *(f"{keywords[s.name]}: {_py_type(s.type)} = {literal(s.default, s.type).text}," for s in settings),
            ])
        w.line(f") -> {self.cls}:")
        with w.indented():
            connections = ", ".join(self.model.connections) or "none"
            doc = ("The robot, running: its ports open, its startup hooks run, its threads started.\n\n"
                   '`port`: a pyserial port name or URL ("/dev/ttyUSB0", "COM3", "socket://host:4000")\n'
                   "or an open port object, for every connection; or a dict {connection: port}; by\n"
                   "default, each connection's address from the description\n"
                   f"(connections: {connections}). `timeout`: seconds to wait for a reply. With\n"
                   "`threads=False`, call `tick()` yourself. Callbacks given here are registered\n"
                   "before anything is opened, so they also see what the startup hooks do. `sim`: a\n"
                   "simulated device in place of the ports (`rdisc.sim.Simulation` of the description).")
            if settings:
                doc += "\n\nSettings (a value outside its type or range is refused before anything is opened):"
                for s in settings:
                    about = f": {s.doc.splitlines()[0]}" if s.doc else ""
                    doc += f"\n    {keywords[s.name]}" + (f" in {s.range_text()}" if s.low is not None else "") + about
            w.line(_docstring(doc))
            w.lines([
                f"robot = {self.cls}(timeout=timeout)",
                "if on_output is not None:",
                "    robot.on_output(on_output)",
                "if on_error is not None:",
                "    robot.on_error(on_error)",
                "if on_io is not None:",
                "    robot.on_io(on_io)",
            ])
            given = [f"{quoted(s.name)}: {keywords[s.name]}" for s in settings]
            bound = ", settings={" + ", ".join(given) + "}" if settings else ""
            flat = f"robot.open(port, threads=threads, sim=sim{bound})"
            if len(flat) <= w.width():
                w.line(flat)
            else:
                w.line("robot.open(port, threads=threads, sim=sim, settings={")
                with w.indented():
                    w.lines([f"{item}," for item in given])
                w.line("})")
            w.line("return robot")


# ---- small pieces ------------------------------------------------------------------------------


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


def _construct(w: Writer, prefix: str, name: str, args: list[str], options: Mapping[str, str] = {}) -> None:
    """`prefix name(args, option=value, ...)`, one argument a line when it does not fit on one."""
    items = args + [f"{key}={value}" for key, value in options.items()]
    flat = f"{prefix}{name}({', '.join(items)})"
    if len(flat) <= w.width() and "\n" not in flat:
        w.line(flat)
        return
    w.line(f"{prefix}{name}(")
    with w.indented():
        w.lines([f"{item}," for item in items])
    w.line(")")


def _kind(made: object) -> str:
    """The name of what a constructor call makes."""
    return made.kind.__name__ if isinstance(made, Construct) else type(made).__name__


def _table(shape: lowering.Reply) -> tuple[lowering.Entry, ...] | None:
    """A reply shape's table, if it has one."""
    return shape.table if isinstance(shape, lowering.TABLED) else None


def _reply_frames(shape: lowering.Reply) -> tuple[lowering.FrameUse, ...]:
    """`replies N`'s own frames: the shape's, or its table's entries' (which share them)."""
    if isinstance(shape, lowering.SeveralReplies):
        return shape.frames
    return next((frames for entry in _table(shape) or () if (frames := _reply_frames(entry.plan.reply))), ())


def _error(shape: lowering.Reply) -> lowering.ErrorReply | None:
    """The reply that may come instead of the shape's, if any."""
    return shape.error if isinstance(shape, (lowering.FixedReply, lowering.FramedReply)) else None


def _error_frame(shape: lowering.Reply) -> lowering.Code | None:
    """The arguments of the frame of the reply that may come instead, if it has one of its own."""
    error = _error(shape)
    return None if error is None or error.frame is None else error.frame.args


def _error_when(shape: lowering.Reply) -> lowering.Code | None:
    """The condition that makes the reply itself the device's error (`error when`), if any."""
    error = _error(shape)
    return None if error is None else error.when


def _case(case: m.ReplyCase) -> str:
    """A reply table entry's value in names: 7, or m7 for -7; 224_239 for a range."""
    first, last = (f"m{-v}" if v < 0 else str(v) for v in (case.value, case.value if case.last is None else case.last))
    under = "" if case.under is None else f"{case.under}_"  # a nested table's entry: 240_121
    return under + (first if case.last is None else f"{first}_{last}")


def _summed(checksum: engine.Checksum, terms: list[str]) -> str:
    """A sum checksum's value: the sum of `terms` in its width, inverted and masked as it says."""
    full = (1 << checksum.width) - 1
    total = f"({' + '.join(terms)}) & {full:#x}" if len(terms) > 1 else f"{terms[0]} & {full:#x}"
    if checksum.inverted:
        total = f"({total}) ^ {full:#x}"
    if checksum.mask is not None and checksum.mask != full:
        total = f"({total}) & {checksum.mask:#x}"
    return total


def _items(w: Writer, prefix: str, opening: str, values: list[Py], closing: str) -> None:
    """`prefix opening v1, v2 closing` on one line if it fits, else a value a line. Without a
    closing, one value and no brackets."""
    if not closing:
        (value,) = values
        _emit(w, prefix, value)
        return
    flat = f"{prefix}{opening}{', '.join(v.text for v in values)}{closing}"
    if len(flat) <= w.width() and "\n" not in flat:
        w.line(flat)
        return
    w.line(prefix + opening)
    with w.indented():
        for value in values:
            _emit(w, "", value, ",")
    w.line(closing)


def _emit(w: Writer, prefix: str, value: Py, suffix: str = "") -> None:
    """`prefix value suffix` at the writer's depth, the value broken over lines if it is long
    (an operator chain inside parentheses, so that the break is inside them)."""
    width = w.width() - len(prefix) - len(suffix)
    if isinstance(value.shape, Chain) and len(value.text) > width:
        value = Py(f"({value.text})", p.ATOM, Paren(value))
    out = lines(value, width)
    out[0] = prefix + out[0]
    out[-1] += suffix
    w.lines(out)


def _section(w: Writer, title: str) -> None:
    """`# ---- title ----...` to column 100: the parts of the module, as a reader scans them."""
    w.comment(f"---- {title} ".ljust(w.width() - 2, "-"))


def _a(noun: str) -> str:
    return f"{'an' if noun[:1].lower() in 'aeiou' else 'a'} {noun}"


def _wrapped(items: list[str], width: int) -> list[str]:
    """`items` joined by spaces into lines of at most `width` characters (one item a line where it is longer)."""
    out: list[str] = []
    for item in items:
        if out and len(out[-1]) + 1 + len(item) <= width:
            out[-1] += " " + item
        else:
            out.append(item)
    return out


def _tuple(items: list[str]) -> str:
    if not items:
        return "()"
    return f"({items[0]},)" if len(items) == 1 else f"({', '.join(items)})"
