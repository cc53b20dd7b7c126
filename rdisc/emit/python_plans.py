"""The driver writer's plans: each lowered plan a constant, each Code a function, each one-step request packed."""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Mapping

from rdisc import engine
from rdisc import lower as lowering
from rdisc.emit.python_base import _DriverBase, _names
from rdisc.emit.python_expr import Py, binary, literal, quoted, table_name
from rdisc.emit.python_frame import OneStep, byte_terms, type_tests
from rdisc.emit.python_names import _body_names, _constant_name, _escape, _params
from rdisc.emit.python_text import _construct, _docstring, _emit, _items, _tuple
from rdisc.emit.writer import Writer
from rdisc.lower import lower
from rdisc.lowering.constructs import Construct
from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.syntax import precedence as p

_SIGNATURE = {"state": "state: StateValues", "args": "args: Args", "reply": "reply: Sequence[Any]"}


class _Plans(_DriverBase):
    """Writes the plans of `rdisc.lower` as Python source."""

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
                # One assignment a parameter, in order (none reads another: the fields' names are
                # taken apart from them), not one of a tuple, which is made and taken apart again.
                # An unused one is still computed: where it fails, the general way says why.
                for (_, e, _), prm in zip(step.binding.items, iface_params):
                    _emit(w, f"{inner[prm.name] if prm.name in used else '_'} = ",
                          self.exprs.bound(e, prm.type, local))
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
