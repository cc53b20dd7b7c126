"""The driver writer's typed face: the robot's classes, a method for each input, interface, primitive."""

from __future__ import annotations

import keyword
from collections.abc import Mapping

from rdisc.emit.canonical import range_written
from rdisc.emit.python_expr import literal, quoted
from rdisc.emit.python_frame import OneStep, reads_state, type_tests
from rdisc.emit.python_lane import lane_statements
from rdisc.emit.python_lane import names as lane_names
from rdisc.emit.python_names import _STATE_MEMBERS, _body_names, _escape, _params
from rdisc.emit.python_plans import _Plans
from rdisc.emit.python_text import _a, _docstring, _py_type, _tuple
from rdisc.emit.writer import Writer, printable
from rdisc.semantics import model as m


class _TypedFace(_Plans):
    """Writes the typed classes over the plans, and connect()."""

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
