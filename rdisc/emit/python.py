"""Model → a standalone Python driver module (`rdisc emit-python`).

The driver follows the run-time contract in `rdisc.runtime`, as the runtime's
interpreter does, but compiled: each primitive, interface, input and output of
the description becomes a method whose expressions are plain Python source,
printed from the checked expression IR with the parser's precedence table. The
operations that Python would not bound or check the same way (float overflow,
powers, shifts, long strings) go through small helpers written into the module,
so both implementations compute the same values and raise the same errors.

What comes from the description enters the text only as a checked name (an
identifier, renamed with a trailing underscore where it would clash with a
Python keyword or a name the driver uses) or through `repr`. Nothing is
evaluated: the generator only prints. The module is deterministic: the same
Model and source name give byte-identical text.
"""

from __future__ import annotations

import dataclasses
import keyword
import os
import posixpath
import struct
from collections.abc import Iterable, Mapping
from types import ModuleType
from typing import NoReturn

from rdisc.emit import python_support as support
from rdisc.emit.python_expr import Chain, Compiler, Paren, Py, binary, call, lines, literal, quoted, state_key
from rdisc.emit.writer import Writer
from rdisc.runtime.codec import frame_fields
from rdisc.semantics import formats
from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.source import SourceFile, Span
from rdisc.syntax import precedence as p

__all__ = ["to_python"]

_PY_TYPES = {Type.INT: "int", Type.FLOAT: "float", Type.BOOL: "bool", Type.STRING: "str", Type.BYTES: "bytes"}

# Names a method body of the driver may use: a parameter or field of the same
# name would hide them, so such a parameter gets a trailing underscore.
_BODY_NAMES = frozenset((
    "self", "state", "request", "reply", "data", "line", "err", "error", "link", "message", "contents",
    "callback", "value", "values",
    "float", "int", "round", "abs", "min", "max", "str", "bool", "len", "type", "isinstance", "any", "dict",
    "list", "tuple", "id", "print", "super", "bytes", "object", "property", "range", "iter", "next", "sorted",
    "getattr", "zip",
    "Exception", "BaseException", "TypeError", "ValueError", "KeyError", "ArithmeticError", "IndexError",
    "ZeroDivisionError", "SystemExit", "KeyboardInterrupt",
    "annotations", "argparse", "dataclasses", "importlib", "json", "logging", "math", "numbers", "os", "re",
    "signal", "struct", "sys", "threading", "time", "Any", "Callable", "Iterator", "Mapping", "Protocol",
    "TypeVar", "cast",
    "ROBOT", "MAX_LINE", "Value", "OutputCallback", "ErrorCallback", "IoCallback", "Port", "PortSpec", "State",
    "connect", "main", "RdisError", "RdisTimeout", "RdisProtocolError", "RdisConnectionError", "RdisValueError",
    "RdisCallbackError",
))
# The robot class's own members: an input of one of these names gets a trailing underscore.
_ROBOT_MEMBERS = frozenset((
    "open", "close", "startup", "terminate", "tick", "state", "closed", "timeout", "on_output", "on_error",
    "on_io", "call_input", "call_interface", "call_primitive",
))
# Members of State besides the state variables (it is a Mapping).
_STATE_MEMBERS = frozenset(("keys", "items", "values", "get"))
# Module-level names a robot's class name must not take.
_MODULE_NAMES = frozenset((
    "State", "Port", "Value", "RdisError", "RdisTimeout", "RdisProtocolError", "RdisConnectionError",
    "RdisValueError", "RdisCallbackError", "None", "True", "False",
))


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


def _params(params: Iterable[tuple[str, Type]], reserved: frozenset[str] = _BODY_NAMES) -> dict[str, str]:
    """Python names for parameters or fields: original name → local name."""
    names: dict[str, str] = {}
    originals = [name for name, _ in params]
    for name in originals:
        names[name] = _escape(name, reserved | set(names.values()) | (set(originals) - {name}))
    return names


def _class_name(robot: str) -> str:
    """`irobot_create` → `IrobotCreate`."""
    name = "".join(part[:1].upper() + part[1:] for part in _identifier(robot).split("_")) or "Robot"
    if keyword.iskeyword(name) or name in _MODULE_NAMES:
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


def _printable(text: str, keep: str = "") -> str:
    """`text` with every character that is not printable (a line break above all) escaped as
    Python escapes it, so that it cannot end a comment or a string early; `keep` is kept as is."""
    out = []
    for ch in text:
        if ch.isprintable() or ch in keep:
            out.append(ch)
        elif ord(ch) <= 0xFF:
            out.append(f"\\x{ord(ch):02x}")
        elif ord(ch) <= 0xFFFF:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(f"\\U{ord(ch):08x}")
    return "".join(out)


def _docstring(text: str) -> str:
    """A triple-quoted docstring that reads back as `text` (its lines right-stripped)."""
    body = "\n".join(line.rstrip() for line in text.strip("\n").split("\n"))
    escaped = _printable(body.replace("\\", "\\\\"), keep="\n").replace('"""', '\\"\\"\\"')
    if escaped.endswith('"') and (len(escaped) - 1 - len(escaped[:-1].rstrip("\\"))) % 2 == 0:
        escaped = escaped[:-1] + '\\"'
    if "\n" in escaped:
        return f'"""{escaped}\n"""'
    return f'"""{escaped}"""'


# ---- the module ------------------------------------------------------------------------------


class _Driver:
    def __init__(self, model: m.Model, source_name: str, sources: Mapping[str, SourceFile]) -> None:
        for names in (model.states, model.connections, model.primitives, model.interfaces, model.adapters,
                      model.inputs, model.outputs):
            for name in names:
                _identifier(name)  # names enter the text as identifiers: only checked names can
        for element in (*model.primitives.values(), *model.interfaces.values()):
            for param in element.params:
                _identifier(param.name)
        for adapter in model.adapters.values():
            for field in adapter.fields:
                _identifier(field.name)
        self.model = model
        self.source_name = source_name
        self.sources = sources
        self.main_path = model.robot.span.path if model.robot.span else None
        self.cls = _class_name(model.robot.name)
        self.exprs = Compiler()
        taken: set[str] = set()
        self.codecs = {name: _constant_name(name, taken) for name in model.primitives}
        self.state_attrs = _params([(s.name, s.type) for s in model.states.values()], _STATE_MEMBERS)
        self.state_names = {state_key(name): attr for name, attr in self.state_attrs.items()}
        self.input_methods: dict[str, str] = {}
        for name in model.inputs:
            self.input_methods[name] = _escape(name, _ROBOT_MEMBERS | set(self.input_methods.values()))
        self.owner = {name: _owner(model, iface) for name, iface in model.interfaces.items()}
        self.periodic = {
            c: [i for i in model.interfaces.values() if i.periodic and self.owner[i.name] == c]
            for c in model.connections
        }
        self.worked = [c for c in model.connections.values() if self.has_work(c)]
        self.uses_struct = False
        used = {p.frame.frame for p in model.primitives.values() if p.frame is not None}
        self.framed = {name: f"_FRAME_{_identifier(name).upper()}" for name in model.frames if name in used}

    def has_work(self, c: m.Connection) -> bool:
        """Whether a connection's thread has anything to do: periodic interfaces or a keepalive."""
        return bool(self.periodic[c.name]) or (c.keepalive is not None and c.keepalive.interval_ms > 0)

    # -- helpers ---------------------------------------------------------------------------------

    def where(self, span: Span | None) -> str | None:
        """`file:line` of a span: the main file by the name it was given, another by its path
        relative to the main file's folder (or its name, when it is elsewhere)."""
        if span is None or span.path not in self.sources:
            return None
        line = self.sources[span.path].position(span.start).line + 1
        if span.path == self.main_path:
            return f"{self.source_name}:{line}"
        name = posixpath.basename(span.path.replace(os.sep, "/"))
        if self.main_path is not None:
            relative = os.path.relpath(span.path, os.path.dirname(self.main_path) or ".").replace(os.sep, "/")
            if not relative.startswith("../"):
                name = relative
        return f"{name}:{line}"

    def comment(self, w: Writer, span: Span | None, what: str = "") -> None:
        """`# file:line  what` before a block that came from the description."""
        where = self.where(span)
        if where is not None:
            w.line(_printable(f"# {where}" + (f"  {what}" if what else "")))

    def names(self, params: Mapping[str, str]) -> dict[str, str]:
        return {**self.state_names, **params}

    # -- the whole module ---------------------------------------------------------------------

    def module(self) -> str:
        # The parts that decide what the module needs (helpers, imports) are written first.
        codecs, robot = Writer(), Writer()
        self.codecs_section(codecs)
        self.robot_class(robot)
        self.connect_function(robot)
        self.command_line(robot)
        w = Writer()
        self.header(w)
        w.blank(2)
        w.raw(codecs.text().rstrip("\n"))
        if self.framed:
            w.blank(2)
            _section(w, "frames: the framing of rdisc.runtime.framing, and each frame of the description")
            w.blank(1)
            w.raw(support.framing())
            for frame in self.model.frames.values():
                if frame.name in self.framed:
                    w.blank(2)
                    self.comment(w, frame.span, f"frame {frame.name}")
                    w.line(f"{self.framed[frame.name]} = {_frame(frame)}")
        helpers = [name for name in support.HELPERS if name in self.exprs.helpers]  # a fixed order
        if helpers:
            w.blank(2)
            _section(w, "expression helpers: operations as rdisc.semantics.operators defines them")
            w.blank(1)
            if "_clamp" in helpers:
                w.line(support.NUMBER_TYPE)
                w.blank(2)
            for name in helpers:
                w.raw(support.HELPERS[name])
                w.blank(2)
        w.blank(2)
        _section(w, "ports, schedules and values")
        w.blank(1)
        w.raw(support.PORTS)
        w.blank(2)
        _section(w, "state: the robot's variables")
        w.blank(1)
        self.state_class(w)
        w.blank(2)
        _section(w, f"the robot: {self.cls}, connect()")
        w.blank(1)
        w.raw(robot.text().rstrip("\n"))
        w.blank(2)
        w.line('if __name__ == "__main__":')
        with w.indented():
            w.line("sys.exit(main())")
        return w.text()

    def header(self, w: Writer) -> None:
        robot = self.model.robot
        module = robot.name
        lines_ = [f"{robot.name}: {robot.description or 'a robot described in RDIS'}."]
        if robot.author:
            lines_.append(f"By {robot.author}.")
        if robot.doc:
            lines_ += ["", robot.doc]
        lines_ += [
            "",
            f"A driver generated by `rdisc emit-python` from {self.source_name}: change the",
            "description and generate it again rather than editing this file. It needs only",
            "the standard library, and pyserial to open ports by name or URL.",
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
            samples = {Type.INT: "0", Type.FLOAT: "0.0", Type.BOOL: "False", Type.STRING: '""'}
            arguments = ", ".join(f"{f.name}={samples[f.type]}" for f in fields)
            lines_.append(f"        robot.{self.input_methods[example.name]}({arguments})")
            command += f" --call {example.name}" + "".join(f" {f.name}={samples[f.type]}" for f in fields)
        lines_ += ["", "or as a program (`--help` for its options):", "", command + " --watch"]
        w.line(_docstring("\n".join(lines_)))
        w.blank(1)
        w.line("from __future__ import annotations")
        w.blank(1)
        modules = ["argparse", "dataclasses", "importlib", "json", "logging", "math", "numbers", "os", "signal",
                   "sys", "threading", "time"]
        if self.uses_struct or self.framed:
            modules.append("struct")
        if any(isinstance(x.decoding, m.Regex) for x in self.model.primitives.values()):
            modules.append("re")
        w.lines([f"import {name}" for name in sorted(modules)])
        w.line(f"from collections.abc import Callable, Iterator, Mapping{', Sequence' if self.framed else ''}")
        typing = ["Any", "Protocol", "cast"] + (["TypeVar"] if "_clamp" in self.exprs.helpers else [])
        w.line(f"from typing import {', '.join(sorted(typing))}")
        w.blank(1)
        w.line(f"ROBOT = {quoted(robot.name)}")
        w.line("MAX_LINE = 4096")
        w.line('"""Bytes of one reply line, terminator included."""')
        w.blank(2)
        _section(w, "errors: the classes of rdisc.runtime.errors")
        w.blank(1)
        w.raw(support.ERRORS)
        w.blank(2)
        w.raw(support.TYPES)

    # -- codecs --------------------------------------------------------------------------------

    def codecs_section(self, w: Writer) -> None:
        _section(w, "messages: each primitive's request and reply, prepared once")
        for prim in self.model.primitives.values():
            w.blank(1)
            self.comment(w, prim.span, f"primitive {prim.name}")
            const = self.codecs[prim.name]
            fixed = _constant_request(prim)
            match prim.encoding:
                case m.Pack(format=fmt):
                    if fixed is not None:
                        w.line(f"{const}_REQUEST = {quoted(fixed)}  # pack {quoted(fmt)} {_shown_args(prim)}")
                    else:
                        self.uses_struct = True
                        layout = formats.struct_layout(fmt)
                        w.line(f"{const}_REQUEST = struct.Struct({quoted(layout.fixed)})"
                               + ("  # then the rest: bytes" if layout.rest else ""))
                case m.Format(template=template):
                    if fixed is not None:
                        w.line(f"{const}_REQUEST = {quoted(fixed)}  # format {quoted(template)} {_shown_args(prim)}")
                    else:
                        w.line(f"{const}_REQUEST = {quoted(template)}")
                case _:
                    _unreachable(prim.encoding)
            self.reply_codec(w, const, prim.decoding)
            if prim.table is not None and prim.table.tag is not None:
                self.uses_struct = True
                w.line(f"{const}_TAG = struct.Struct({quoted(prim.table.tag)})")
            for case in prim.table.cases if prim.table else ():
                if prim.table.tag is None:  # type: ignore[union-attr]
                    w.line(f"{const}_{_case(case)}_REQUEST = {const}_REQUEST")
                self.reply_codec(w, f"{const}_{_case(case)}", case.decoding)

    def reply_codec(self, w: Writer, const: str, decoding: m.Unpack | m.Regex | None) -> None:
        match decoding:
            case m.Unpack(format=fmt):
                self.uses_struct = True
                layout = formats.struct_layout(fmt)
                w.line(f"{const}_REPLY = struct.Struct({quoted(layout.fixed)})"
                       + ("  # then the rest: bytes" if layout.rest else ""))
            case m.Regex(pattern=pattern):
                w.line(f"{const}_REPLY = re.compile({quoted(pattern)})")
            case None:
                pass
            case _:
                _unreachable(decoding)

    # -- state -----------------------------------------------------------------------------------

    def state_class(self, w: Writer) -> None:
        w.line("@dataclasses.dataclass(frozen=True, eq=False)")
        with w.block("class State(Mapping[str, Value]):"):
            w.line(_docstring(
                f"The state variables of {self.model.robot.name}: what was last read from the robot, and\n"
                "its constants. Immutable: post-actions publish a new State, so a reader always sees\n"
                'a consistent snapshot. Read a variable as an attribute or by name (`state["name"]`).'
            ))
            for s in self.model.states.values():
                w.blank(1)
                self.comment(w, s.span)
                w.line(f"{self.state_attrs[s.name]}: {_PY_TYPES[s.type]} = {literal(s.initial, s.type).text}")
                if s.doc:
                    w.line(_docstring(s.doc))
            w.blank(1)
            with w.block("def __getitem__(self, name: str) -> Value:"):
                w.line("value: Value = getattr(self, _STATE_ATTRIBUTES[name])")
                w.line("return value")
            w.blank(1)
            with w.block("def __iter__(self) -> Iterator[str]:"):
                w.line("return iter(_STATE_ATTRIBUTES)")
            w.blank(1)
            with w.block("def __len__(self) -> int:"):
                w.line("return len(_STATE_ATTRIBUTES)")
            w.blank(1)
            with w.block("def _replaced(self, changes: dict[str, Value]) -> State:"):
                w.line(_docstring(
                    "A copy with `changes` (attribute: value), as `dataclasses.replace` makes it but\n"
                    "without running `__init__` again, which would cost more than decoding a reply."
                ))
                w.line("new = object.__new__(State)")
                w.line("new.__dict__.update(self.__dict__)")
                w.line("new.__dict__.update(changes)")
                w.line("return new")
        w.blank(2)
        attributes = ", ".join(f"{quoted(name)}: {quoted(attr)}" for name, attr in self.state_attrs.items())
        w.line(f"_STATE_ATTRIBUTES: dict[str, str] = {{{attributes}}}")
        w.line('"""The attribute of State that holds each state variable, by name."""')

    # -- the robot class ---------------------------------------------------------------------------

    def robot_class(self, w: Writer) -> None:
        robot = self.model.robot
        with w.block(f"class {self.cls}:"):
            doc = [f"{robot.description or robot.name}."]
            if robot.doc:
                doc += ["", robot.doc]
            doc += [
                "",
                "`connect()` makes one and opens it: it opens the ports, runs the startup hooks and",
                "starts the connections' threads. `close()` (or leaving a `with` block) stops the",
                "threads, runs the terminate hooks and closes the ports. Callbacks registered before",
                "`open()` also see what the startup hooks do.",
            ]
            w.line(_docstring("\n".join(doc)))
            w.blank(1)
            self.init(w)
            w.blank(1)
            _section(w, "callbacks")
            w.blank(1)
            w.raw(_indent(support.ROBOT_CALLBACKS))
            w.blank(1)
            self.inputs_section(w)
            w.blank(1)
            self.lifecycle(w)
            w.blank(1)
            self.outputs_section(w)
            w.blank(1)
            self.interfaces_section(w)
            w.blank(1)
            self.primitives_section(w)
            w.blank(1)
            _section(w, "port I/O: one exchange at a time on each port")
            w.blank(1)
            w.raw(_indent(support.ROBOT_IO))
            if self.framed:
                w.blank(1)
                w.raw(_indent(support.ROBOT_FRAMED))
            w.blank(1)
            _section(w, "delivering to callbacks: one at a time, a failing one reported")
            w.blank(1)
            w.raw(_indent(support.ROBOT_DELIVERY))
        w.blank(2)
        self.tables(w)

    def init(self, w: Writer) -> None:
        with w.block("def __init__(self, *, timeout: float = 1.0) -> None:"):
            w.line('"""A robot not connected yet: `open()` connects it. `timeout`: seconds to wait for a reply."""')
            w.lines([
                "self.timeout = timeout",
                "self._state = State()",
                "self._state_lock = threading.Lock()  # post-actions publish one at a time",
                "self._callback_lock = threading.RLock()  # callbacks run one at a time",
                "self._output_callbacks: list[OutputCallback] = []",
                "self._error_callbacks: list[ErrorCallback] = []",
                "self._io_callbacks: list[IoCallback] = []",
                "self._links: dict[str, _Link] = {}",
                "self._threads: list[threading.Thread] = []",
                "self._stop = threading.Event()",
                "self._close_lock = threading.Lock()",
                "self._running = False",
                "self._closed = False",
            ])
            if self.framed:
                w.line("self._inputs: dict[int, Input] = {}  # each port's input, with bytes a bad frame gave back")
            for c in self.model.connections.values():
                self.comment(w, c.span, f"connection {c.name}: {c.kind}, {c.baud} baud, {c.frequency_hz:g} Hz")
                w.line(f"self._link_{c.name}: _Link  # set by open()")
                keepalive = c.keepalive.interval_ms / 1000.0 if c.keepalive else 0.0
                w.line(
                    f"self._schedule_{c.name} = _Schedule({float(c.frequency_hz)!r}, "
                    f"periodic={bool(self.periodic[c.name])!r}, keepalive_s={keepalive!r})"
                )

    # -- inputs ------------------------------------------------------------------------------------

    def inputs_section(self, w: Writer) -> None:
        _section(w, "domain inputs: what the framework asks of the robot")
        for i in self.model.inputs.values():
            w.blank(1)
            self.input_method(w, i)
        w.blank(1)
        with w.block("def call_input(self, name: str, /, **fields: Any) -> None:"):
            w.line(_docstring(
                "Run the domain input `name` with its adapter's fields by name, as the rdisc\n"
                "runtime's `Robot.call_input` does; errors are raised."
            ))
            w.lines([
                "entry = _INPUTS.get(name)",
                "if entry is None:",
                '    raise KeyError(f"{ROBOT} has no input named {name!r}")',
                "if not self._running:",
                "    raise self._not_running()",
                "method, adapter, expected = entry",
                "if len(fields) != len(expected) or any(field not in fields for field, _ in expected):",
                '    wanted = ", ".join(field for field, _ in expected)',
                '    given = ", ".join(fields) or "none"',
                '    raise TypeError(f"input {name} takes the fields {wanted} ({adapter}); given: {given}")',
                "method(self, *(fields[field] for field, _ in expected))",
            ])
        w.blank(1)
        for kind, table, doc in (
            ("interface", "_INTERFACES", "Run the interface `name` with positional arguments; errors are raised."),
            ("primitive", "_PRIMITIVES", ("Send the device command (primitive) `name` with positional arguments, "
                                          "read its reply\nand run its post-actions; errors are raised.")),
        ):
            w.blank(1)
            with w.block(f"def call_{kind}(self, name: str, /, *args: Any) -> None:"):
                w.line(_docstring(doc))
                w.lines([
                    f"entry = {table}.get(name)",
                    "if entry is None:",
                    f'    raise KeyError(f"{{ROBOT}} has no {kind} named {{name!r}}")',
                    "if not self._running:",
                    "    raise self._not_running()",
                    "method, params = entry",
                    "if len(args) != len(params):",
                    f'    raise TypeError(f"{kind} {{name}} takes {{len(params)}} arguments, {{len(args)}} given")',
                    "values = [",
                    f'    _accept(value, kind, f"{kind} {{name}}: parameter {{param}}")',
                    "    for value, (param, kind) in zip(args, params)",
                    "]",
                    "method(self, *values)",
                ])

    def input_method(self, w: Writer, i: m.DomainInput) -> None:
        adapter = self.model.adapters[i.adapter]
        fields = [(f.name, f.type) for f in adapter.fields]
        local = _params(fields)
        signature = "".join(f", {local[n]}: {_PY_TYPES[t]}" for n, t in fields)
        with w.block(f"def {self.input_methods[i.name]}(self{signature}) -> None:"):
            doc = [i.doc or f"The domain input `{i.name}`."]
            doc += ["", f"Takes {_a(adapter.name)} and runs the interface `{i.interface}`; errors are raised."]
            if adapter.fields:
                doc += ["", "Fields:"]
                for f in adapter.fields:
                    unit = f" [{f.unit}]" if f.unit else ""
                    about = f": {f.doc.splitlines()[0]}" if f.doc else ""
                    doc.append(f"    {local[f.name]}{unit}{about}")
            w.line(_docstring("\n".join(doc)))
            self.comment(w, i.span, f"input {i.name}: {i.adapter} -> {i.interface}")
            w.line("if not self._running:")
            w.line("    raise self._not_running()")
            for name, type_ in fields:
                py = _PY_TYPES[type_]
                w.line(f"if type({local[name]}) is not {py}:")
                w.line(f"    {local[name]} = _accept({local[name]}, {py}, {quoted(f'input {i.name}: field {name}')})")
            iface = self.model.interfaces[i.interface]
            self.guarded_call(w, f"self._interface_{i.interface}", iface.params, i.args, local, i.name)

    def guarded_call(
        self, w: Writer, method: str, params: tuple[m.Parameter, ...], args: tuple[m.Expr, ...],
        local: Mapping[str, str], element: str,
    ) -> None:
        """Call `method` with `args` bound to `params`. An argument that cannot be evaluated is an
        RdisValueError naming `element`; the call's own errors pass through."""
        exprs = self.exprs
        exprs.reads_state = False
        values = [exprs.bound(a, param.type, self.names(local)) for a, param in zip(args, params)]
        if exprs.reads_state:
            w.line("state = self._state")
        if all(exprs.safe(a, param.type) for a, param in zip(args, params)):  # nothing to evaluate
            _emit(w, "", call(method, values))
            return
        with w.block("try:"):
            _emit(w, "", call(method, values))
        with w.block("except RdisError:"):
            w.line("raise")
        _value_error(w, element)

    # -- lifecycle -------------------------------------------------------------------------------------

    def lifecycle(self, w: Writer) -> None:
        _section(w, "connections: opening, hooks, ticks, closing")
        w.blank(1)
        with w.block("def open(self, port: PortSpec | None = None, *, threads: bool = True) -> None:"):
            w.line(_docstring(
                "Open the ports, run the startup hooks, then start the connections' threads.\n\n"
                '`port`: a pyserial port name or URL ("/dev/ttyUSB0", "COM3", "socket://host:4000")\n'
                "or an open port object, for every connection; or a dict {connection: port}; a\n"
                "connection given none opens its address from the description. With\n"
                "`threads=False` no thread is started: call `tick()` from your own loop. If any of\n"
                "it fails, what was opened is closed again (terminate hooks included) and the\n"
                "error is raised."
            ))
            w.line("if self._running or self._closed:")
            w.line('    raise RdisConnectionError(f"{ROBOT}: already opened")')
            with w.block("try:"):
                w.line("_open_links(port, _CONNECTIONS, _ADDRESSES, self.timeout, self._links)")
                for c in self.model.connections.values():
                    w.line(f"self._link_{c.name} = self._links[{quoted(c.name)}]")
                w.line("self._running = True")
                w.line("self.startup()")
                for c in self.model.connections.values():
                    w.line(f"self._schedule_{c.name}.restart()")
                if self.model.connections:
                    with w.block("if threads:  # one a connection; one with nothing periodic only waits"):
                        w.line("self._threads = [")
                        for c in self.model.connections.values():
                            tick = f"self._tick_{c.name}" if self.has_work(c) else "None"
                            w.line(f"    threading.Thread(target=self._schedule_{c.name}.run, "
                                   f"args=({tick}, self._stop),")
                            w.line(f'                     name=f"{{ROBOT}} {c.name}", daemon=True),')
                        w.line("]")
                        w.line("for thread in self._threads:")
                        w.line("    thread.start()")
            with w.block("except BaseException:"):
                w.line("self.close()")
                w.line("raise")
        w.blank(1)
        with w.block("def startup(self) -> None:"):
            w.line('"""Run the startup hooks, in declaration order (`open()` does); errors are raised."""')
            hooks = [(c, c.startup) for c in self.model.connections.values() if c.startup is not None]
            for c, hook in hooks:
                assert hook is not None
                self.comment(w, hook.span, f"connection {c.name}: startup")
                self.hook_call(w, hook)
        w.blank(1)
        with w.block("def terminate(self) -> None:"):
            w.line(_docstring(
                "Run the terminate hooks of the connections that are open, in declaration order\n"
                "(`close()` does): they leave the robot stopped. Errors are reported, not raised."
            ))
            hooks = [(c, c.terminate) for c in self.model.connections.values() if c.terminate is not None]
            for c, hook in hooks:
                assert hook is not None
                self.comment(w, hook.span, f"connection {c.name}: terminate")
                with w.block(f"if {quoted(c.name)} in self._links:"):
                    with w.block("try:"):
                        self.hook_call(w, hook)
                    with w.block("except Exception as err:  # noqa: BLE001 - reported, and the others run"):
                        w.line("self._report(err)")
        w.blank(1)
        with w.block("def tick(self) -> None:"):
            w.line(_docstring(
                "One iteration of every connection's work, on this thread: its periodic interfaces,\n"
                "then its keepalive if due. Errors are reported, as the threads' are."
            ))
            w.line("if not self._running:")
            w.line("    raise self._not_running()")
            for c in self.worked:
                w.line(f"self._tick_{c.name}()")
        for c in self.worked:
            w.blank(1)
            self.tick_method(w, c)
        w.blank(1)
        w.raw(_indent(support.ROBOT_LIFECYCLE))
        w.blank(1)
        with w.block(f"def __enter__(self) -> {self.cls}:  # noqa: PYI034 - typing.Self needs Python 3.11"):
            w.line("return self")
        w.blank(1)
        with w.block("def __exit__(self, *exc: object) -> None:"):
            w.line("self.close()")

    def hook_call(self, w: Writer, hook: m.HookCall) -> None:
        iface = self.model.interfaces[hook.interface]
        self.guarded_call(w, f"self._interface_{hook.interface}", iface.params, hook.args, {}, hook.interface)

    def tick_method(self, w: Writer, c: m.Connection) -> None:
        with w.block(f"def _tick_{c.name}(self) -> None:"):
            work = [what for what, present in (
                ("its periodic interfaces", self.periodic[c.name]),
                ("then its keepalive when due" if self.periodic[c.name] else "its keepalive when due",
                 c.keepalive is not None and c.keepalive.interval_ms > 0),
            ) if present]
            w.line(_docstring(
                f"One tick of `{c.name}` (every {1000.0 / c.frequency_hz:g} ms): {', '.join(work)}.\n"
                "Errors go to the error callbacks, and the schedule goes on."
            ))
            for iface in self.periodic[c.name]:
                self.comment(w, iface.span, f"periodic interface {iface.name}")
                w.line("if self._stop.is_set():")
                w.line("    return")
                with w.block("try:"):
                    w.line(f"self._interface_{iface.name}()")
                with w.block("except Exception as err:  # noqa: BLE001 - reported; the schedule goes on"):
                    w.line("self._report(err)")
            if c.keepalive is not None and c.keepalive.interval_ms > 0:
                self.comment(w, c.keepalive.call.span, f"keepalive, every {c.keepalive.interval_ms:g} ms")
                with w.block(f"if self._schedule_{c.name}.keepalive_due():"):
                    with w.block("try:"):
                        self.hook_call(w, c.keepalive.call)
                    with w.block("except Exception as err:  # noqa: BLE001 - reported; the schedule goes on"):
                        w.line("self._report(err)")

    # -- outputs -----------------------------------------------------------------------------------------

    def outputs_section(self, w: Writer) -> None:
        _section(w, "domain outputs: what the robot reports")
        for o in self.model.outputs.values():
            w.blank(1)
            adapter = self.model.adapters[o.adapter]
            with w.block(f"def _output_{o.name}(self) -> None:"):
                fields = ", ".join(f"{f.name} [{f.unit}]" if f.unit else f.name for f in adapter.fields)
                doc = [o.doc or f"The domain output `{o.name}`.", "", f"Delivers {_a(adapter.name)}: {fields}."]
                w.line(_docstring("\n".join(doc)))
                self.comment(w, o.span, f"output {o.name}: {o.adapter}")
                exprs = self.exprs
                exprs.reads_state = False
                types = {f.name: f.type for f in adapter.fields}
                values = [(name, exprs.bound(e, types.get(name, e.type), self.names({}))) for name, e in o.fields]
                if exprs.reads_state:
                    w.line("state = self._state")
                if not values:
                    w.line(f"self._deliver({quoted(o.name)}, {{}})")
                    continue
                with w.block("try:"):
                    w.line("contents: dict[str, Value] = {")
                    with w.indented():
                        for name, value in values:
                            _emit(w, f"{quoted(name)}: ", value, ",")
                    w.line("}")
                _value_error(w, o.name)
                w.line(f"self._deliver({quoted(o.name)}, contents)")

    # -- interfaces ------------------------------------------------------------------------------------

    def interfaces_section(self, w: Writer) -> None:
        _section(w, "interfaces: primitive calls in priority order, with their delays")
        for iface in self.model.interfaces.values():
            w.blank(1)
            local = _params([(prm.name, prm.type) for prm in iface.params])
            signature = "".join(f", {local[prm.name]}: {_PY_TYPES[prm.type]}" for prm in iface.params)
            with w.block(f"def _interface_{iface.name}(self{signature}) -> None:"):
                doc = [iface.doc or f"The interface `{iface.name}`."]
                if iface.periodic:
                    doc += ["", f"Periodic: runs on every tick of `{self.owner[iface.name]}`."]
                w.line(_docstring("\n".join(doc)))
                self.comment(w, iface.span, f"interface {iface.name}" + (" (periodic)" if iface.periodic else ""))
                _in_ranges(w, iface.name, iface.params, local)
                for c in iface.run_order():
                    prim = self.model.primitives[c.primitive]
                    options = [f"priority {c.priority}"] if c.priority else []
                    options += [f"delay {c.delay_ms:g} ms"] if c.delay_ms else []
                    self.comment(w, c.span, ", ".join([f"call {prim.name}", *options]))
                    self.guarded_call(w, f"self._primitive_{prim.name}", prim.params, c.args, local, iface.name)
                    if c.delay_ms:
                        w.line(f"time.sleep({c.delay_ms / 1000.0!r})")
                if iface.triggers is not None:
                    w.line(f"self._output_{iface.triggers}()")
                if not iface.calls and iface.triggers is None:
                    w.line("return")

    # -- primitives ------------------------------------------------------------------------------------

    def primitives_section(self, w: Writer) -> None:
        _section(w, "primitives: one device command each")
        for prim in self.model.primitives.values():
            w.blank(1)
            self.primitive_method(w, prim)

    def primitive_method(self, w: Writer, prim: m.Primitive, case: m.ReplyCase | None = None) -> None:
        """`_primitive_NAME`; with `case`, the method for one entry of its reply table."""
        local = _params([(prm.name, prm.type) for prm in prim.params])
        names = self.names(local)
        signature = "".join(f", {local[prm.name]}: {_PY_TYPES[prm.type]}" for prm in prim.params)
        const = self.codecs[prim.name] + (f"_{_case(case)}" if case else "")
        method = f"_primitive_{prim.name}" + (f"_when_{_case(case)}" if case else "")
        if prim.table is not None and prim.table.tag is None:
            self.table_dispatch(w, prim, method, signature, local)
            for each in prim.table.cases:
                w.blank(1)
                self.primitive_method(w, prim.case(each), each)
            return
        with w.block(f"def {method}(self{signature}) -> None:"):
            if case is None:
                w.line(_docstring(prim.doc or f"The primitive `{prim.name}`."))
                self.comment(w, prim.span, f"primitive {prim.name} on {prim.connection}")
                _in_ranges(w, prim.name, prim.params, local)
            else:
                w.line(_docstring(f"`{prim.name}` when its reply table's key is {case.value}."))
            request = f"{const}_REQUEST"
            if _constant_request(prim) is None:
                self.encode(w, prim, names, const)
                request = "request"
            link = f"self._link_{prim.connection}, {quoted(prim.name)}"
            uses_reply = any(_reads_reply(a.value) for a in prim.actions)
            if prim.frame is not None:
                self.framed_exchange(w, prim, names, request, link, uses_reply, const)
                if prim.actions:
                    self.post_actions(w, prim, names)
                return
            match prim.decoding:
                case None:
                    w.line(f"self._send({link}, {request})")
                case m.Unpack():
                    exchange = f"self._exchange({link}, {request}, {const}_REPLY.size{_timeout(prim)})"
                    if not uses_reply:
                        w.line(exchange)
                    else:
                        w.line(f"data = {exchange}")
                        self.unpacked(w, prim, "data", const)
                case m.Regex():
                    self.exprs.helpers.add("_match")
                    end = self.model.connections[prim.connection].terminator_bytes()
                    until = "" if end == b"\n" else f", {end!r}"  # the default needs no argument
                    w.line(f"line = self._exchange_line({link}, {request}{until}{_timeout(prim)})")
                    w.line(f"{'reply = ' if uses_reply else ''}_match({quoted(prim.name)}, {const}_REPLY, line)")
                case _:
                    _unreachable(prim.decoding)
            if prim.actions:
                self.post_actions(w, prim, names)

    def framed_exchange(self, w: Writer, prim: m.Primitive, names: Mapping[str, str], request: str, link: str,
                        uses_reply: bool, const: str) -> None:
        """The request framed, and the reply read through the frame (or as the decoding says)."""
        assert prim.frame is not None
        frame = self.model.frames[prim.frame.frame]
        wire = self.framed[frame.name]
        bound = dict(zip((prm.name for prm in frame.params), prim.frame.args))
        exprs = self.exprs
        exprs.reads_state = False
        values = [exprs.expr(_substituted(e, bound), names) for e in frame_fields(frame).values()]
        if exprs.reads_state:
            w.line("state = self._state")
        with w.block("try:"):
            w.line(f"fields: list[int] = [{', '.join(lines(v, 1 << 20)[0] for v in values)}]")
            w.line(f"request = {wire}.wrap({request}, fields)")
        w.line("except (struct.error, *_EVAL_ERRORS) as err:")
        w.line(f'    raise RdisValueError(f"{_identifier(prim.name)}: {{err}}") from err')
        if not prim.expects_reply(self.model.frames):
            w.line(f"self._send({link}, request)")
            return
        if prim.table is not None and prim.table.tag is not None:
            self.tagged_reply(w, prim, names, link, wire, const)
            return
        if not frame.reply:  # an unframed reply
            match prim.decoding:
                case m.Unpack():
                    w.line(f"{'data = ' if uses_reply else ''}self._exchange({link}, request, {const}_REPLY.size"
                           f"{_timeout(prim)})")
                    if uses_reply:
                        self.unpacked(w, prim, "data", const)
                case m.Regex():
                    self.exprs.helpers.add("_match")
                    end = self.model.connections[prim.connection].terminator_bytes()
                    until = "" if end == b"\n" else f", {end!r}"
                    w.line(f"line = self._exchange_line({link}, request{until}{_timeout(prim)})")
                    w.line(f"{'reply = ' if uses_reply else ''}_match({quoted(prim.name)}, {const}_REPLY, line)")
            return
        match prim.decoding:
            case None:
                w.line(f"self._exchange_frame({link}, request, {wire}, fields, 0{_timeout(prim)})")
            case m.Unpack(format=fmt):
                rest = formats.struct_layout(fmt).rest
                size = "-1" if rest else f"{const}_REPLY.size"
                accept = ""  # a fixed size is checked by the exchange itself
                if prim.skip_unmatched and rest:
                    self.exprs.helpers.add("_unpacked_rest")
                    accept = f", lambda data: _unpacked_rest({quoted(prim.name)}, {const}_REPLY, data, ())"
                w.line(f"{'data = ' if uses_reply else ''}self._exchange_frame("
                       f"{link}, request, {wire}, fields, {size}{accept}{_timeout(prim)})")
                if uses_reply:
                    self.unpacked(w, prim, "data", const)
            case m.Regex():
                self.exprs.helpers.add("_match")
                match = f'_match({quoted(prim.name)}, {const}_REPLY, payload.decode("latin-1"))'
                accept = f", lambda payload: {match}" if prim.skip_unmatched else ""
                w.line(f"payload = self._exchange_frame({link}, request, {wire}, fields, -1{accept}{_timeout(prim)})")
                w.line(f"{'reply = ' if uses_reply else ''}{match}")

    def unpacked(self, w: Writer, prim: m.Primitive, data: str, const: str) -> None:
        """`reply = ...`: the values of an `unpack` reply."""
        assert isinstance(prim.decoding, m.Unpack)
        layout = formats.struct_layout(prim.decoding.format)
        strings = tuple(i for i, slot in enumerate(layout.slots) if slot.type is Type.STRING)
        if layout.rest:
            self.exprs.helpers.add("_unpacked_rest")
            w.line(f"reply = _unpacked_rest({quoted(prim.name)}, {const}_REPLY, {data}, {strings!r})")
        elif strings:
            self.exprs.helpers.add("_decoded")
            w.line(f"reply = _decoded({const}_REPLY.unpack({data}), {strings!r})")
        else:
            w.line(f"reply = {const}_REPLY.unpack({data})")

    def encode(self, w: Writer, prim: m.Primitive, names: Mapping[str, str], const: str) -> None:
        """`request = ...`: the format arguments evaluated and encoded."""
        exprs = self.exprs
        exprs.reads_state = False
        values = [exprs.expr(a, names) for a in prim.args]
        match prim.encoding:
            case m.Pack(format=fmt):
                layout = formats.struct_layout(fmt)
                values = [
                    call(f"{v.at(p.ATOM).text}.encode", [literal("latin-1", Type.STRING)])
                    if slot.type is Type.STRING else v
                    for v, slot in zip(values, layout.slots)
                ]
                encoded, suffix = call(f"{const}_REQUEST.pack", values), ""
                if layout.rest:  # the fixed part, then the bytes as they are
                    encoded = binary("+", call(f"{const}_REQUEST.pack", values[:-1]), values[-1])
                errors = "(struct.error, *_EVAL_ERRORS)"
            case m.Format():
                encoded, suffix = call(f"{const}_REQUEST.format", values), '.encode("latin-1")'
                errors = "_EVAL_ERRORS"
            case _:
                _unreachable(prim.encoding)
        if exprs.reads_state:
            w.line("state = self._state")
        with w.block("try:"):
            _emit(w, "request = ", encoded, suffix)
        w.line(f"except {errors} as err:")
        w.line(f'    raise RdisValueError(f"{_identifier(prim.name)}: {{err}}") from err')

    def tagged_reply(self, w: Writer, prim: m.Primitive, names: Mapping[str, str], link: str, wire: str,
                     const: str) -> None:
        """A reply chosen by its tag: each entry decodes the rest of the payload, then its post-actions run."""
        assert prim.table is not None
        name = quoted(prim.name)
        self.exprs.helpers.add("_tag_split")
        w.blank(1)
        with w.block("def decode(payload: bytes) -> tuple[int, tuple[Any, ...]]:"):
            w.line(f"tag, rest = _tag_split({name}, {const}_TAG, payload)")
            for case in prim.table.cases:
                reply_const = f"{const}_{_case(case)}_REPLY"
                match case.decoding:
                    case m.Unpack(format=fmt):
                        layout = formats.struct_layout(fmt)
                        strings = tuple(i for i, slot in enumerate(layout.slots) if slot.type is Type.STRING)
                        helper = "_unpacked_rest" if layout.rest else "_unpacked"
                        self.exprs.helpers.add(helper)
                        value = f"{helper}({name}, {reply_const}, rest, {strings!r})"
                    case m.Regex():
                        self.exprs.helpers.add("_match")
                        value = f'_match({name}, {reply_const}, rest.decode("latin-1"))'
                w.line(f"if tag == {case.value!r}:")
                w.line(f"    return tag, {value}")
            w.line(f'raise RdisProtocolError(f"{_identifier(prim.name)}: no reply entry for tag {{tag}}")')
        w.blank(1)
        accept = ", decode" if prim.skip_unmatched else ""
        w.line(f"tag, reply = decode(self._exchange_frame({link}, request, {wire}, fields, -1{accept}{_timeout(prim)}))")
        acting = [case for case in prim.table.cases if case.actions]
        for i, case in enumerate(acting):
            with w.block(f"{'if' if i == 0 else 'elif'} tag == {case.value!r}:"):
                self.post_actions(w, prim.case(case), names)

    def table_dispatch(self, w: Writer, prim: m.Primitive, method: str, signature: str,
                       local: Mapping[str, str]) -> None:
        """A primitive with a reply table: its key's value chooses the method that reads its reply."""
        assert prim.table is not None
        with w.block(f"def {method}(self{signature}) -> None:"):
            w.line(_docstring(prim.doc or f"The primitive `{prim.name}`."))
            self.comment(w, prim.span, f"primitive {prim.name} on {prim.connection}, its reply by {prim.table.key}")
            _in_ranges(w, prim.name, prim.params, local)
            args = ", ".join(local[prm.name] for prm in prim.params)
            key = local[prim.table.key]
            for i, case in enumerate(prim.table.cases):
                keyword = "if" if i == 0 else "elif"
                with w.block(f"{keyword} {key} == {case.value!r}:"):
                    w.line(f"self._primitive_{prim.name}_when_{_case(case)}({args})")
            if not prim.table.cases:
                w.line("return")

    def post_actions(self, w: Writer, prim: m.Primitive, names: Mapping[str, str]) -> None:
        targets = [a.target for a in prim.actions]
        if len(set(targets)) != len(targets):
            raise ValueError(f"primitive {prim.name} assigns a state variable twice")
        with w.block("with self._state_lock:  # every value from the same state, then all assigned"):
            w.line("state = self._state")
            with w.block("try:"):
                w.line("self._state = state._replaced({")
                with w.indented():
                    for action in prim.actions:
                        value = self.exprs.bound(action.value, self.model.states[action.target].type, names)
                        self.comment(w, action.span)
                        _emit(w, f"{quoted(self.state_attrs[action.target])}: ", value, ",")
                w.line("})")
            _value_error(w, prim.name)

    # -- module-level tables, connect() and the command line ------------------------------------------

    def tables(self, w: Writer) -> None:
        bauds = ", ".join(f"{quoted(c.name)}: {c.baud!r}" for c in self.model.connections.values())
        w.line(f"_CONNECTIONS: dict[str, int] = {{{bauds}}}")
        w.line('"""Each connection\'s baud rate, by name."""')
        w.blank(1)
        addresses = ", ".join(f"{quoted(c.name)}: {quoted(c.address)}" for c in self.model.connections.values()
                              if c.address is not None)
        w.line(f"_ADDRESSES: dict[str, str] = {{{addresses}}}")
        w.line('"""The port each connection opens when given none (its `address`)."""')
        w.blank(1)
        w.line("_INPUTS: dict[str, tuple[Callable[..., None], str, tuple[tuple[str, type], ...]]] = {")
        for i in self.model.inputs.values():
            adapter = self.model.adapters[i.adapter]
            fields = _tuple([f"({quoted(f.name)}, {_PY_TYPES[f.type]})" for f in adapter.fields])
            method = f"{self.cls}.{self.input_methods[i.name]}"
            w.line(f"    {quoted(i.name)}: ({method}, {quoted(adapter.name)}, {fields}),")
        w.line("}")
        w.line('"""Each domain input: its method, its adapter, and the adapter\'s fields with their types."""')
        w.blank(1)
        elements: tuple[tuple[str, Iterable[m.Interface | m.Primitive]], ...] = (
            ("interface", self.model.interfaces.values()), ("primitive", self.model.primitives.values()))
        for kind, items in elements:
            w.line(f"_{kind.upper()}S: dict[str, tuple[Callable[..., None], tuple[tuple[str, type], ...]]] = {{")
            for item in items:
                params = _tuple([f"({quoted(prm.name)}, {_PY_TYPES[prm.type]})" for prm in item.params])
                w.line(f"    {quoted(item.name)}: ({self.cls}._{kind}_{item.name}, {params}),")
            w.line("}")
            w.line(f'"""Each {kind}: its method, and its parameters with their types."""')
            if kind == "interface":
                w.blank(1)

    def connect_function(self, w: Writer) -> None:
        w.blank(2)
        w.line("def connect(")
        w.line("    port: PortSpec | None = None,")
        w.line("    timeout: float = 1.0,")
        w.line("    threads: bool = True,")
        w.line("    *,")
        w.line("    on_output: OutputCallback | None = None,")
        w.line("    on_error: ErrorCallback | None = None,")
        w.line("    on_io: IoCallback | None = None,")
        with w.block(f") -> {self.cls}:"):
            names = ", ".join(self.model.connections)
            w.line(_docstring(
                f"The robot, running: its ports open, its startup hooks run, its threads started.\n\n"
                '`port`: a pyserial port name or URL ("/dev/ttyUSB0", "COM3", "socket://host:4000")\n'
                "or an open port object, for every connection; or a dict {connection: port}; by\n"
                "default, each connection's address from the description\n"
                f"(connections: {names}). `timeout`: seconds to wait for a reply. With\n"
                "`threads=False`, call `tick()` yourself. Callbacks given here are registered\n"
                "before anything is opened, so they also see what the startup hooks do."
            ))
            w.line(f"robot = {self.cls}(timeout=timeout)")
            w.line("if on_output is not None:")
            w.line("    robot.on_output(on_output)")
            w.line("if on_error is not None:")
            w.line("    robot.on_error(on_error)")
            w.line("if on_io is not None:")
            w.line("    robot.on_io(on_io)")
            w.line("robot.open(port, threads=threads)")
            w.line("return robot")

    def command_line(self, w: Writer) -> None:
        w.blank(2)
        _section(w, "the command line: the options of `rdisc run`")
        w.blank(1)
        w.raw(support.COMMAND_LINE)
        w.blank(2)
        with w.block("def main(argv: list[str] | None = None) -> int:"):
            w.line(_docstring(
                "The command line, with the options of `rdisc run`: connect, make the --call calls in\n"
                "order, then run for --duration seconds (or, with --watch, until Ctrl-C; else end\n"
                "when the calls are done). It always ends by closing the robot, which runs the\n"
                "terminate hooks. Exit status: 0 done; 1 the device failed; 2 a usage error;\n"
                "130 after SIGINT; 143 after SIGTERM."
            ))
            description = f"Drive {self.model.robot.name} (a driver generated by rdisc from {self.source_name})."
            connections = "connections: " + ", ".join(self.model.connections)
            calls = "inputs: " + (", ".join(self.model.inputs) or "none")
            w.lines([
                f"parser = argparse.ArgumentParser(description={quoted(description)})",
                'parser.add_argument("--port", action="append", default=[], metavar="[CONN=]PORT",',
                '                    help="a pyserial port or URL (/dev/ttyUSB0, COM3, socket://host:port); "',
                f'                         "CONN=PORT for one connection of several ({connections})")',
                'parser.add_argument("--call", action="append", nargs="+", default=[], metavar="NAME [K=V ...]",',
                '                    help="call an input (or an interface) with named values; repeat for "',
                f'                         "several calls, in order ({calls})")',
                'parser.add_argument("--watch", action="store_true", help="print each output as a JSON line")',
                'parser.add_argument("--trace", action="store_true",',
                '                    help="print every byte written and read, in hex, on stderr")',
                'parser.add_argument("--duration", type=float, metavar="S",',
                '                    help="run for S seconds (default: until the calls are done; with --watch, "',
                '                         "until Ctrl-C)")',
                'parser.add_argument("--timeout", type=float, default=1.0, metavar="S",',
                '                    help="reply timeout in seconds (default 1)")',
                "args = parser.parse_args(argv)",
                "try:",
                "    port = _port_argument(args.port)",
                "    calls = [_call_argument(words) for words in args.call]",
                "except ValueError as err:",
                '    print(f"{parser.prog}: {err}", file=sys.stderr)',
                "    return 2",
                f"robot = {self.cls}(timeout=args.timeout)",
                "robot.on_error(_print_error)",
                "if args.watch:",
                "    robot.on_output(_print_output)",
                "if args.trace:",
                "    robot.on_io(_print_io)",
                "previous = {}",
                "_shutting_down[0] = False",
                "for signum in (signal.SIGINT, signal.SIGTERM):",
                "    try:",
                "        previous[signum] = signal.signal(signum, _on_signal)",
                "    except ValueError:  # not the main thread: leave the handlers alone",
                "        pass",
                "status = 0",
                "try:",
                "    start = time.monotonic()",
                "    robot.open(port)",
                "    for name, kind, values in calls:",
                "        if kind == \"input\":",
                "            robot.call_input(name, **values)",
                "        elif kind == \"interface\":",
                "            robot.call_interface(name, *(values[param] for param, _ in _INTERFACES[name][1]))",
                "        else:",
                "            robot.call_primitive(name, *(values[param] for param, _ in _PRIMITIVES[name][1]))",
                "    if args.duration is not None:",
                "        _sleep(args.duration - (time.monotonic() - start))",
                "    elif args.watch:",
                "        _sleep(None)",
                "except RdisError as err:",
                "    _print_error(err)",
                "    status = 1",
                "except (TypeError, ValueError) as err:  # values of the wrong type, or a bad port",
                '    print(f"{parser.prog}: {err}", file=sys.stderr)',
                "    status = 2",
                "except KeyboardInterrupt:",
                "    status = 130",
                "except _Terminated:",
                "    status = 143",
                "finally:",
                "    _shutting_down[0] = True  # a second signal must not cut the terminate hooks short",
                "    try:",
                "        robot.close()",
                "    finally:",
                "        for signum, handler in previous.items():",
                "            signal.signal(signum, handler)",
                "return status",
            ])


# ---- small pieces ------------------------------------------------------------------------------

def _owner(model: m.Model, iface: m.Interface) -> str | None:
    """The connection whose thread runs a periodic interface: that of its first call's primitive."""
    for c in iface.run_order():
        return model.primitives[c.primitive].connection
    return next(iter(model.connections), None)


def _reads_reply(e: m.Expr) -> bool:
    match e:
        case m.ReplyValue():
            return True
        case m.UnaryOp(operand=operand):
            return _reads_reply(operand)
        case m.BinaryOp(left=left, right=right):
            return _reads_reply(left) or _reads_reply(right)
        case m.IfElse(cond=cond, then=then, orelse=orelse):
            return _reads_reply(cond) or _reads_reply(then) or _reads_reply(orelse)
        case m.FuncCall(args=args):
            return any(_reads_reply(a) for a in args)
    return False


def _constant_request(prim: m.Primitive) -> bytes | None:
    """The request's bytes, when every format argument is a constant and the bytes do not
    depend on the machine (no native byte order); None when they are made at run time."""
    if not all(isinstance(a, m.Const) for a in prim.args):
        return None
    values = [a.value for a in prim.args if isinstance(a, m.Const)]
    try:
        match prim.encoding:
            case m.Pack(format=fmt):
                if formats.struct_layout(fmt).native:
                    return None
                return struct.pack(fmt, *(v.encode("latin-1") if isinstance(v, str) else v for v in values))
            case m.Format(template=template):
                return template.format(*values).encode("latin-1")
    except (struct.error, ValueError, TypeError):
        return None  # refused when it runs, every time, as the runtime refuses it
    return None


def _in_ranges(w: Writer, owner: str, params: tuple[m.Parameter, ...], local: Mapping[str, str]) -> None:
    """A value outside its parameter's declared range is refused, as the runtime refuses it."""
    for prm in params:
        if prm.low is None:
            continue
        name = local[prm.name]
        if prm.type is Type.BYTES:
            with w.block(f"if not {prm.low!r} <= len({name}) <= {prm.high!r}:"):
                w.line(f'raise RdisValueError(f"{_identifier(owner)}: parameter {prm.name} has {{len({name})}} '
                       f'bytes, outside {prm.range_text()}")')
        else:
            with w.block(f"if not {prm.low!r} <= {name} <= {prm.high!r}:"):
                w.line(f'raise RdisValueError(f"{_identifier(owner)}: parameter {prm.name} is {{{name}!r}}, '
                       f'outside {prm.range_text()}")')


def _timeout(prim: m.Primitive) -> str:
    """`, timeout=S` for a primitive with its own reply timeout."""
    return "" if prim.timeout_ms is None else f", timeout={prim.timeout_ms / 1000.0!r}"


def _case(case: m.ReplyCase) -> str:
    """A reply table entry's value in names: 7, or m7 for -7."""
    return f"m{-case.value}" if case.value < 0 else str(case.value)


def _substituted(e: m.Expr, bound: Mapping[str, m.Expr]) -> m.Expr:
    """A frame's expression over its parameters, rewritten over the arguments they are bound to."""
    match e:
        case m.Var(scope=m.Scope.PARAM, name=name):
            return bound[name]
        case m.UnaryOp():
            return dataclasses.replace(e, operand=_substituted(e.operand, bound))
        case m.BinaryOp():
            return dataclasses.replace(e, left=_substituted(e.left, bound), right=_substituted(e.right, bound))
        case m.IfElse():
            return dataclasses.replace(e, cond=_substituted(e.cond, bound), then=_substituted(e.then, bound),
                                       orelse=_substituted(e.orelse, bound))
        case m.FuncCall():
            return dataclasses.replace(e, args=tuple(_substituted(a, bound) for a in e.args))
    return e


def _frame(frame: m.Frame) -> str:
    """The constructor of a frame, as the framing module takes it."""
    fields = {name: i for i, name in enumerate(frame_fields(frame))}
    request = ", ".join(_frame_part(p, fields) for p in frame.request)
    reply = ", ".join(_frame_part(p, fields) for p in frame.reply)
    stuffing = ""
    if frame.stuffing is not None:
        reserved, escape = (text.encode("latin-1") for text in frame.stuffing)
        stuffing = f", Stuffing({reserved!r}, {escape!r})"
    return f"Frame({quoted(frame.name)}, [{request}], [{reply}]{stuffing})"


def _frame_part(part: m.FramePart, fields: Mapping[str, int]) -> str:
    match part:
        case m.FrameBytes(role=role, data=data):
            return f"Bytes({quoted(role)}, {data.encode('latin-1')!r})"
        case m.FrameField(name=name, format=fmt):
            return f"Field({quoted(name)}, {quoted(fmt)}, {fields[name]})"
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
    _unreachable(part)


def _shown_args(prim: m.Primitive) -> str:
    return "(" + ", ".join(literal(a.value, a.type).text for a in prim.args if isinstance(a, m.Const)) + ")"


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


def _value_error(w: Writer, element: str) -> None:
    """The `except` clause making an evaluation error an RdisValueError naming `element`."""
    w.line("except _EVAL_ERRORS as err:")
    w.line(f'    raise RdisValueError(f"{_identifier(element)}: {{err}}") from err')


def _section(w: Writer, title: str) -> None:
    """`# ---- title ----...` to column 100: the parts of the module, as a reader scans them."""
    w.line(f"# ---- {title} ".ljust(w.width(), "-"))


def _a(noun: str) -> str:
    return f"{'an' if noun[:1].lower() in 'aeiou' else 'a'} {noun}"


def _tuple(items: list[str]) -> str:
    return f"({items[0]},)" if len(items) == 1 else f"({', '.join(items)})"


def _indent(text: str) -> str:
    return "\n".join(("    " + line) if line else "" for line in text.split("\n"))


def _unreachable(node: NoReturn) -> NoReturn:
    raise AssertionError(f"unhandled case {node!r}")
