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

import functools
import keyword
import os
from collections.abc import Iterable, Mapping
from types import ModuleType
from typing import NoReturn

from rdisc import engine
from rdisc.emit import python_support as support
from rdisc.emit.python_expr import Chain, Compiler, Paren, Py, lines, literal, quoted, table_name
from rdisc.emit.writer import Writer, printable
from rdisc.engine import carry
from rdisc.runtime.codec import bit_fields, decoder, encoder, escape_table, frame_fields
from rdisc.runtime.device import Description
from rdisc.runtime.messages import recorded_messages
from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.source import SourceFile, Span, place
from rdisc.syntax import precedence as p

__all__ = ["import_driver", "to_python"]

_PY_TYPES = {Type.INT: "int", Type.FLOAT: "float", Type.BOOL: "bool", Type.STRING: "str", Type.BYTES: "bytes"}


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
_STATE_MEMBERS = frozenset(("keys", "items", "values", "get"))
# The classes a driver defines for its robot, by their names' endings after the robot's class name.
_CLASS_ENDINGS = ("", "State", "Inputs", "Interfaces", "Primitives")


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
    from rdisc.runtime.errors import RdisLoadError

    path = os.fspath(description)
    compilation = compile_path(path)
    if compilation.model is None or compilation.diagnostics.has_errors():
        raise RdisLoadError.from_compilation(path, compilation)
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
        self.input_methods: dict[str, str] = {}
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
                 values: Iterable[tuple[str, m.Expr, Type | None]], returns: str) -> None:
        """`def name(signature) -> returns:` whose body unpacks `args` into the parameters'
        names and returns a list (keys None) or a dict of the expressions' values, each bound
        to its type where one is given."""
        local = _params([(prm.name, prm.type) for prm in params or ()])
        items = list(values)
        with w.block(f"def {name}({signature}) -> {returns}:"):
            used = set().union(*(_names(e) for _, e, _ in items))
            if used & {prm.name for prm in params or ()}:
                targets = [local[prm.name] if prm.name in used else "_" for prm in params or ()]
                w.line(f"({targets[0]},) = args" if len(targets) == 1 else f"{', '.join(targets)} = args")
            keyed = returns.startswith("dict")
            opening, closing = ("{", "}") if keyed else ("[", "]")
            rendered = []
            for key, e, type_ in items:
                py = self.exprs.bound(e, type_, local) if type_ is not None else self.exprs.expr(e, local)
                rendered.append((f"{quoted(key)}: " if keyed else key, py))  # key "*": an array given element by element
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
            _emit(w, "return bool(", self.exprs.expr(e, local), ")")

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
        model = self.model
        runs = Description(model).device.inputs  # the engine decides which inputs are written at once
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
            values = frame_fields(frame)
            if values:
                function = f"_f_{frame.name}"
                self.function(w, function, "args: Args", frame.params, [("", e, None) for _, e in values],
                              "list[Any]")
                w.blank(2)
            _emit(w, f"{self.plan['frame', frame.name]} = ", Py(_frame(frame, function if values else None), p.ATOM))
        for prim in model.primitives.values():
            w.blank(2)
            self.primitive(w, prim)
        for o in model.outputs.values():
            w.blank(2)
            self.comment(w, o.span, f"output {o.name}: {o.adapter}")
            types = {f.name: f.type for f in model.adapters[o.adapter].fields}
            function = f"_o_{o.name}"
            self.function(w, function, "state: StateValues", None,
                          [(name, e, types.get(name, e.type)) for name, e in o.fields], "dict[str, Value]")
            w.blank(2)
            w.line(f"{self.plan['output', o.name]} = Output({quoted(o.name)}, {function}, {quoted(o.adapter)})")
        for iface in model.callees_first():
            w.blank(2)
            self.interface(w, iface)
        for i in model.inputs.values():
            w.blank(2)
            self.comment(w, i.span, f"input {i.name}: {i.adapter} -> {i.interface}")
            adapter = model.adapters[i.adapter]
            fields = tuple(m.Parameter(f.name, f.type) for f in adapter.fields)
            params = model.interfaces[i.interface].params
            self.function(w, f"_in_{i.name}", "state: StateValues, args: Args", fields,
                          [("", a, None) for a, _ in zip(i.args, params)], "Args")
            options = {}
            if runs[i.name].request is not None:
                options["request"] = self.request(w, i, fields)
            w.blank(2)
            _construct(w, f"{self.plan['input', i.name]} = ", "Input", [
                quoted(i.name), quoted(i.adapter), _param_tuple(fields), self.plan["interface", i.interface],
                f"_in_{i.name}"], options)
        for c in model.connections.values():
            w.blank(2)
            self.connection(w, c)
        w.blank(2)
        state = ", ".join([*(f"{quoted(s.name)}: {literal(s.default, s.type).text}" for s in model.settings.values()),
                           *(f"{quoted(s.name)}: {literal(s.initial, s.type).text}" for s in model.states.values())])
        by_name = {kind: ", ".join(f"{quoted(name)}: {self.plan[kind, name]}" for name in names)
                   for kind, names in (("connection", model.connections), ("primitive", model.primitives),
                                       ("interface", model.interfaces), ("input", model.inputs))}
        settings = {"settings": "_SETTINGS"} if model.settings else {}
        messages = recorded_messages(model)
        if messages:
            settings["messages"] = "_MESSAGES"
            self.messages(w, messages)
        if model.settings:
            w.line("_SETTINGS = (")
            with w.indented():
                w.lines([f"{item}," for item in _param_items(_setting_params(model))])
            w.line(")")
            w.line('"""The settings, given when connecting (`connect(port, NAME=value)`, `--set NAME=VALUE`)."""')
            w.blank(2)
        _construct(w, "_DEVICE = ", "Device", [
            "ROBOT", f"{{{state}}}", f"{{{by_name['connection']}}}", f"{{{by_name['primitive']}}}",
            f"{{{by_name['interface']}}}", f"{{{by_name['input']}}}"], settings)
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

    def request(self, w: Writer, i: m.DomainInput, fields: tuple[m.Parameter, ...]) -> str:
        """The input's request in one step (the engine's `Input.request`): the input's and the
        call's expressions one after the other, packed. Returns the function's name."""
        iface = self.model.interfaces[i.interface]
        (call,) = iface.calls
        prim = self.model.primitives[call.primitive]
        values = _direct(prim, call)
        assert values is not None and isinstance(prim.encoding, m.Pack)  # as the engine requires
        pack = _constant_name(f"PACK_{i.name}", self.taken)
        w.blank(2)
        w.line(f"{pack} = struct.Struct({quoted(prim.encoding.format)}).pack")
        local = _params([(f.name, f.type) for f in fields])
        inner = _params([(prm.name, prm.type) for prm in iface.params], _body_names() | set(local.values()))
        used = set().union(*(_names(e) for _, e, _ in values))
        function = f"_request_{i.name}"
        w.blank(2)
        w.line(f"# input {i.name}, written at once")
        with w.block(f"def {function}(state: StateValues, args: Args) -> bytes | None:"):
            names = [local[f.name] for f in fields]
            if names:
                w.line(f"({names[0]},) = args" if len(names) == 1 else f"{', '.join(names)} = args")
                checks = " or ".join(f"type({n}) is not {_PY_TYPES[f.type] if isinstance(f.type, Type) else 'tuple'}"
                                    for n, f in zip(names, fields))
                with w.block(f"if {checks}:"):
                    w.line("return None")
            with w.block("try:"):
                if iface.params:
                    targets = [inner[prm.name] if prm.name in used else "_" for prm in iface.params]
                    bound = [self.exprs.bound(a, prm.type, local) for a, prm in zip(i.args, iface.params)]
                    _items(w, f"{', '.join(targets)} = ", "(", bound, ")" if len(bound) > 1 else "")
                packed = [self.exprs.bound(e, t, inner) if t is not None else self.exprs.expr(e, inner)
                          for _, e, t in values]
                _items(w, "return ", f"{pack}(", packed, ")")
            with w.block("except Exception:  # noqa: BLE001 - the general way says what is wrong"):
                w.line("return None")
        return function

    def primitive(self, w: Writer, prim: m.Primitive) -> None:
        self.comment(w, prim.span, f"primitive {prim.name}")
        base = f"_p_{prim.name}"
        signature = "state: StateValues, args: Args"
        spreads = prim.spreads()
        self.function(w, f"{base}_values", signature, prim.params,
                      [("*" if i in spreads else "", a, None) for i, a in enumerate(prim.args)], "Args")
        if prim.frame is not None:
            w.blank(2)
            self.function(w, f"{base}_frame", signature, prim.params, [("", a, None) for a in prim.frame.args],
                          "Args")
            fields = f"FrameUse({self.plan['frame', prim.frame.frame]}, {base}_frame)"
        else:
            fields = "None"
        const = self.plan["primitive", prim.name]
        common = [quoted(prim.name), quoted(prim.connection), _param_tuple(prim.params), f"{base}_values",
                  _codec(None if prim.encoding is None else encoder(prim.encoding))]
        options = {"frame": fields} if prim.frame is not None else {}
        if prim.lines:
            options["lines"] = f"{base}_lines"
            w.blank(2)
            self.function(w, options["lines"], signature, prim.params,
                          [(level.line, level.value, Type.BOOL) for level in prim.lines], "dict[str, Value]")
        if prim.skip_unmatched:
            options["skip"] = "True"
        if prim.timeout_ms is not None:
            options["timeout"] = repr(prim.timeout_ms / 1000.0)
        if prim.replies:
            options["replies"] = str(prim.replies)
        if prim.reply_frames:
            uses = []
            for n, use in enumerate(prim.reply_frames):
                w.blank(2)
                self.function(w, f"{base}_reply_frame_{n}", signature, prim.params,
                              [("", a, None) for a in use.args], "Args")
                uses.append(f"FrameUse({self.plan['frame', use.frame]}, {base}_reply_frame_{n})")
            options["reply_frames"] = _tuple(uses)
        if prim.expect is not None:
            options["expect"] = f"{base}_expect"
            w.blank(2)
            self.predicate(w, options["expect"], f"{signature}, reply: Sequence[Any]", prim.reply_locals(),
                           prim.expect)
        answers: list[str] = []
        for n, listed in enumerate(prim.listed, 1):  # each its own plan: frame, decoder, expect, post-actions
            own = {key: value for key, value in options.items() if key != "frame"}
            own_frame = listed.frame or prim.frame
            if own_frame is not None:
                w.blank(2)
                self.function(w, f"{base}_reply_{n}_frame", signature, prim.params,
                              [("", a, None) for a in own_frame.args], "Args")
                own["frame"] = f"FrameUse({self.plan['frame', own_frame.frame]}, {base}_reply_{n}_frame)"
            own["decoder"] = _codec(decoder(listed.decoding))
            if listed.expect is not None:
                own["expect"] = f"{base}_reply_{n}_expect"
                w.blank(2)
                self.predicate(w, own["expect"], f"{signature}, reply: Sequence[Any]", prim.params, listed.expect)
            self.post_actions(w, f"{base}_reply_{n}_actions", prim, listed.actions, own)
            w.blank(2)
            w.line(f"# reply {n} of {len(prim.listed)}")
            _construct(w, f"{const}_REPLY_{n} = ", "Primitive", common, own)
            answers.append(f"{const}_REPLY_{n}")
        if answers:
            options["answers"] = _tuple(answers)
        if prim.records is not None:
            options["records"] = repr(prim.records.encode("latin-1"))
        cases = [(prim, None)] if prim.table is None else [(prim.case(c), c) for c in prim.table.cases]
        table: list[str] = []
        for case, entry in cases:
            name = const if entry is None else f"{const}_{_case(entry).upper()}"
            own = dict(options)
            if case.decoding is not None:
                own["decoder"] = _codec(decoder(case.decoding))
            self.post_actions(w, f"{base}_actions" if entry is None else f"{base}_{_case(entry)}_actions", prim,
                              case.actions, own)
            w.blank(2)
            if entry is not None:
                w.line(f"# reply {entry.values_text()}")
                table.append(f"{entry.value}: {name}" if entry.last is None
                             else f"**dict.fromkeys({entry.values()!r}, {name})")  # a range entry
            _construct(w, f"{name} = ", "Primitive", common, own)
        if prim.table is not None:
            options["table"] = "{" + ", ".join(table) + "}"
            if len(f"    table={options['table']},") > w.width():  # its own constant, an entry a line
                w.blank(2)
                w.line(f"{const}_TABLE = {{")
                with w.indented():
                    w.lines([f"{item}," for item in table])
                w.line("}")
                options["table"] = f"{const}_TABLE"
            if prim.table.tag is not None:
                options["tag"] = quoted(prim.table.tag)
                if prim.table.each:
                    options["each"] = "True"
                if prim.table.length is not None:
                    options["length"] = quoted(prim.table.length)
            else:
                options["key"] = str(next(i for i, prm in enumerate(prim.params) if prm.name == prim.table.key))
            w.blank(2)
            _construct(w, f"{const} = ", "Primitive", common, options)

    def post_actions(self, w: Writer, name: str, prim: m.Primitive, actions: tuple[m.PostAction, ...],
                     options: dict[str, str]) -> None:
        """The function of a reply's post-actions, if it has any, named in `options` with the
        state variables they may make too wide."""
        if not actions:
            return
        options["actions"] = name
        states = self.model.states
        w.blank(2)
        self.function(w, name, "state: StateValues, args: Args, reply: Sequence[Any]", prim.reply_locals(),
                      [(a.target, a.value, states[a.target].type) for a in actions], "dict[str, Value]")
        checked = [quoted(a.target) for a in actions if states[a.target].type is Type.INT and m.may_outgrow(a.value)]
        if checked:
            options["checked"] = _tuple(checked)

    def interface(self, w: Writer, iface: m.Interface) -> None:
        self.comment(w, iface.span, f"interface {iface.name}" + (" (periodic)" if iface.periodic else ""))
        calls = []
        for n, c in enumerate(iface.run_order(), 1):
            function = f"_i_{iface.name}_{n}"
            if n > 1:
                w.blank(2)
            said = [f"priority {c.priority}"] if c.priority else []
            said += [f"delay {c.delay_ms:g} ms"] if c.delay_ms else []
            said += ["when ..."] if c.when is not None else []
            self.comment(w, c.span, ", ".join([f"call {'interface ' if c.interface else ''}{c.primitive}", *said]))
            direct = None if c.interface else _direct(self.model.primitives[c.primitive], c)
            self.function(w, function, "state: StateValues, args: Args", iface.params,
                          direct if direct is not None else [("", a, None) for a in c.args], "Args")
            delay = f", {c.delay_ms / 1000.0!r}" if c.delay_ms or direct is not None else ""
            options = ", direct=True" if direct is not None else ""
            if c.when is not None:
                w.blank(2)
                self.predicate(w, f"{function}_when", "state: StateValues, args: Args", iface.params, c.when)
                options += f", when={function}_when"
            target = self.plan["interface" if c.interface else "primitive", c.primitive]
            calls.append(f"Call({target}, {function}{delay}{options})")
        if calls:
            w.blank(2)
        output = {"outputs": _tuple([self.plan["output", o] for o in iface.triggers])} if iface.triggers else {}
        _construct(w, f"{self.plan['interface', iface.name]} = ", "Interface",
                   [quoted(iface.name), _param_tuple(iface.params), _tuple(calls)], output)

    def connection(self, w: Writer, c: m.Connection) -> None:
        baud = f"{c.baud} baud" if c.baud_setting is None else f"baud {c.baud_setting} ({c.baud} unless given)"
        self.comment(w, c.span, f"connection {c.name}: {c.kind}, {baud}")
        periodic = [self.plan["interface", i.name] for i in self.model.interfaces.values()
                    if i.periodic and self.model.owner(i) == c.name]

        def hook(call: m.HookCall) -> str:
            args = [self.exprs.expr(a, {}).text for a in call.args]
            return f"Hook({self.plan['interface', call.interface]}, lambda state: [{', '.join(args)}])"

        options = {"address": quoted(c.address)} if c.address is not None else {}
        if c.terminator != "\n":
            options["terminator"] = quoted(c.terminator_bytes())
        if c.frequency_hz:
            options["frequency"] = repr(float(c.frequency_hz))
        if periodic:
            options["periodic"] = _tuple(periodic)
        for event, call in (("startup", c.startup), ("terminate", c.terminate),
                            ("keepalive", c.keepalive.call if c.keepalive else None)):
            if call is not None:
                options[event] = hook(call)
        if c.keepalive is not None:
            options["interval"] = repr(c.keepalive.interval_ms / 1000.0)
        if c.baud_setting is not None:
            options["baud_setting"] = quoted(c.baud_setting)
        _construct(w, f"{self.plan['connection', c.name]} = ", "Connection", [quoted(c.name), str(c.baud)], options)

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
                        self.input_method(w, model.inputs[name], method, "self._robot._input", keywords=True)
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
            with w.block("def __init__(self, *, timeout: float = 1.0) -> None:"):
                w.line('"""A robot not connected yet: `open()` connects it. `timeout`: seconds a reply may take."""')
                w.line("super().__init__(_DEVICE, timeout=timeout)")
            for member, returns, body, doc_ in (
                ("state", f"{cls}State", f"{cls}State(self._state)", "The state variables now: an immutable snapshot."),
                ("inputs", f"{cls}Inputs", f"{cls}Inputs(self)", "The domain inputs, as typed methods."),
                ("interfaces", f"{cls}Interfaces", f"{cls}Interfaces(self)", "The interfaces, as typed methods."),
                ("primitives", f"{cls}Primitives", f"{cls}Primitives(self)", "The primitives, as typed methods."),
            ):
                w.blank(1)
                w.line("@property")
                with w.block(f"def {member}(self) -> {returns}:"):
                    w.line(f'"""{doc_}"""')
                    w.line(f"return {body}")
            for i in model.inputs.values():
                w.blank(1)
                self.input_method(w, i, self.input_methods[i.name], "self._input", keywords=False)
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
            w.line(f"parser = argparse.ArgumentParser(description={quoted(printable(about))})")
            w.line("add_arguments(parser, _DEVICE)")
            w.line("args = parser.parse_args(argv)")
            w.line(f"return run_command(args, {cls}(timeout=args.timeout), parser.prog)")

    def input_method(self, w: Writer, i: m.DomainInput, method: str, runs: str, keywords: bool) -> None:
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
            values = ", ".join(local[f.name] for f in adapter.fields)
            w.line(f"{runs}({self.plan['input', i.name]}, [{values}])")

    def call_method(self, w: Writer, kind: str, name: str, method: str) -> None:
        element = self.model.interfaces[name] if kind == "interface" else self.model.primitives[name]
        local = _params([(prm.name, prm.type) for prm in element.params], frozenset({"self"}))
        signature = "".join(f", {local[prm.name]}: {_py_type(prm.type)}"
                            + (f" = {literal(prm.default, prm.type).text}" if prm.default is not None else "")
                            for prm in element.params)
        with w.block(f"def {method}(self{signature}) -> None:"):
            doc = [element.doc or f"The {kind} `{name}`."]
            ranged = [f"    {local[prm.name]}: {prm.range_text()}" for prm in element.params if prm.low is not None]
            if ranged:
                doc += ["", "Ranges (a value outside is refused before anything is written):", *ranged]
            units = [f"    {local[prm.name]}: {prm.unit}" for prm in element.params if prm.unit is not None]
            if units:
                doc += ["", "Units (as the device takes them):", *units]
            w.line(_docstring("\n".join(doc)))
            values = ", ".join(local[prm.name] for prm in element.params)
            w.line(f"self._robot._call_{kind}({self.plan[kind, name]}, [{values}])")

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


def _direct(prim: m.Primitive, call: m.PrimitiveCall) -> list[tuple[str, m.Expr, Type | None]] | None:
    """A call's values as the primitive's format values, computed straight from the call's
    arguments, when that changes nothing (`formats_its_params`, as the runtime's planner decides)."""
    if not prim.formats_its_params():
        return None
    by_param = {prm.name: (prm, arg) for prm, arg in zip(prim.params, call.args)}
    values: list[tuple[str, m.Expr, Type | None]] = []
    for arg in prim.args:
        if isinstance(arg, m.Var):
            prm, expr = by_param[arg.name]
            values.append(("", expr, prm.type))
        else:
            values.append(("", arg, None))
    return values


def _names(e: m.Expr) -> set[str]:
    """The parameters and fields an expression reads."""
    return {v.name for v in m.variables(e) if v.scope is not m.Scope.STATE}


def _setting_params(model: m.Model) -> tuple[m.Parameter, ...]:
    """The settings as the engine takes them: parameters of the whole description."""
    return tuple(m.Parameter(s.name, s.type, s.low, s.high, s.default) for s in model.settings.values())


def _param_tuple(params: tuple[m.Parameter, ...]) -> str:
    return _tuple(_param_items(params))


def _param_items(params: tuple[m.Parameter, ...]) -> list[str]:
    """Each parameter's `Param(...)` constructor."""
    items = []
    for prm in params:
        bounds = f", {prm.low!r}, {prm.high!r}" if prm.low is not None else ""
        default = f", default={literal(prm.default, prm.type).text}" if prm.default is not None else ""
        if isinstance(prm.type, m.Array):
            items.append(f"Param({quoted(prm.name)}, {_PY_TYPES[prm.type.element]}{bounds}{default}, "
                         f"size={prm.type.size})")
        else:
            items.append(f"Param({quoted(prm.name)}, {_PY_TYPES[prm.type]}{bounds}{default})")
    return items


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


def _codec(codec: object) -> str:
    """The constructor of an encoder or a decoder."""
    match codec:
        case None:
            return "None"
        case engine.Pack() | engine.Unpack():
            options = (f", strings={codec.strings!r}" if codec.strings else "") + (", rest=True" if codec.rest else "")
            options += f", groups={codec.groups!r}" if codec.groups else ""
            options += f", varying={codec.varying!r}" if codec.varying else ""
            options += f", bits={codec.bits!r}" if codec.bits else ""
            options += f", until={codec.until!r}" if isinstance(codec, engine.Unpack) and codec.until else ""
            return f"{type(codec).__name__}({quoted(codec.struct.format)}{options})"
        case engine.Format():
            return f"Format({quoted(codec.template)})"
        case engine.Match():
            return f"Match({quoted(codec.pattern)})"
    raise AssertionError(codec)


def _case(case: m.ReplyCase) -> str:
    """A reply table entry's value in names: 7, or m7 for -7; 224_239 for a range."""
    first, last = (f"m{-v}" if v < 0 else str(v) for v in (case.value, case.value if case.last is None else case.last))
    return first if case.last is None else f"{first}_{last}"


def _frame(frame: m.Frame, fields: str | None) -> str:
    """The constructor of a frame, as the engine takes it; `fields`: the function of its field values."""
    index = {key: i for i, key in enumerate(frame_fields(frame))}
    request, reply = (", ".join(_frame_part(part, index) for part in parts) for parts in (frame.request, frame.reply))
    stuffing = ""
    if frame.stuffing is not None:
        reserved, escape = (text.encode("latin-1") for text in frame.stuffing)
        stuffing = f", Stuffing({reserved!r}, {escape!r})"
    options = stuffing
    if frame.params:
        options += f", params={_param_tuple(frame.params)}"
    if fields is not None:
        options += f", fields={fields}"
    for word, layouts in (("more_requests", frame.more_requests), ("more_replies", frame.more_replies)):
        if layouts:
            options += f", {word}=[" + ", ".join(
                "[" + ", ".join(_frame_part(part, index) for part in parts) + "]" for parts in layouts) + "]"
    if frame.escaping is not None:
        options += f", escaping=Escaping({frame.escaping.escape.encode('latin-1')!r}, {escape_table(frame.escaping)!r})"
    return f"Frame({quoted(frame.name)}, [{request}], [{reply}]{options})"


def _frame_part(part: m.FramePart, index: Mapping[tuple[str, m.Expr], int]) -> str:
    match part:
        case m.FrameBytes(role=role, data=data):
            return f"Bytes({quoted(role)}, {data.encode('latin-1')!r})"
        case m.FrameField(name=name, format=fmt, value=value):
            return f"Field({quoted(name)}, {quoted(fmt)}, {index[(name, value)]})"
        case m.FrameLength(format=fmt, adjust=adjust):
            return f"Length({quoted(fmt)}, {adjust})"
        case m.FramePayload():
            return "Payload()"
        case m.FrameChecksum(algorithm=a):
            options = [f"{a.poly:#x}", f"{a.init:#x}", repr(a.reflect_in), repr(a.reflect_out), f"{a.xorout:#x}",
                       repr(a.inverted), repr(a.mask)]
            args = ", ".join([quoted(a.kind), str(a.width), *options])
            fmt = quoted(part.format) if part.format is not None else "None"
            return f"Check(Checksum({args}), {fmt}, {part.first}, {part.last}, {part.with_request!r})"
        case m.FrameOptional(count=count):
            return f"OptionalParts({count})"
        case m.FrameBits(format=fmt):
            entries, adjust = bit_fields(part, dict(index))
            return f"Bits({quoted(fmt)}, {entries!r}, {adjust})"
    _unreachable(part)


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


def _tuple(items: list[str]) -> str:
    if not items:
        return "()"
    return f"({items[0]},)" if len(items) == 1 else f"({', '.join(items)})"


def _unreachable(node: NoReturn) -> NoReturn:
    raise AssertionError(f"unhandled case {node!r}")
