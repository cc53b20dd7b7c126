"""Every declaration that is neither a message nor a call: the robot's attributes, constants,
tables, enums, adapters, state variables and settings; connections (the serial line, threading,
hooks and keepalive, terminator and address)."""

from __future__ import annotations

from collections.abc import Callable

from rdisc.diagnostics import Label
from rdisc.semantics import model as m
from rdisc.semantics import ros
from rdisc.semantics.check.pieces import MAX_TERMINATOR, Pieces
from rdisc.semantics.frameworks import with_frameworks
from rdisc.semantics.model import Type
from rdisc.semantics.operators import shown
from rdisc.semantics.resolve import check_name
from rdisc.semantics.types import Env, describe, unify
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.precedence import octets

MAX_BAUD = 100_000_000  # bit/s: no serial line is faster
MAX_FREQUENCY_HZ = 10_000  # ticks a second of a connection's thread
STANDARD_BAUDS = frozenset(
    (50, 75, 110, 134, 150, 200, 300, 600, 1200, 1800, 2400, 4800, 9600, 14400, 19200, 28800, 38400, 57600,
     76800, 115200, 230400, 250000, 460800, 500000, 576000, 921600, 1000000, 1152000, 1500000, 2000000,
     2500000, 3000000, 3500000, 4000000,
     100000, 420000)  # S.BUS's and CRSF's own rates
)
CONNECTION_KINDS = ("serial", "tcp")
PARITIES = ("none", "even", "odd", "mark", "space")  # pyserial's, each its first letter there
DATA_BITS = (5, 6, 7, 8)
STOP_BITS = (1, 1.5, 2)
DEFAULT_BAUD = 9600
DEFAULT_FREQUENCY_HZ = 10.0
THREADING_MODELS = ("single", "dual", "multiple")  # a tick holds the port; each exchange does; a thread each


class Declarations(Pieces):
    """The rules of every declaration that is neither a message nor a call."""

    def robot(self) -> m.Robot | None:
        decl = self.s.robot
        if decl is None:
            return None
        attrs: dict[str, str] = {}
        for key in ("author", "description", "version"):
            found = self.once([a for a in decl.attrs if a.key == key], f"`{key}`", decl.name)
            if found is not None:
                attrs[key] = found.value
        return m.Robot(decl.name.text, doc=decl.doc, span=decl.span, **attrs)

    def table(self, name: str, decl: ast.ConstDecl) -> m.Table | None:
        """`const T = {key: value, ...}`: constant keys of one type (int or string), each once, and
        constant values of one type."""
        assert isinstance(decl.value, ast.TableLit)
        env = Env({}, "in a table", "constants declared before it")
        entries: dict[m.Value, m.Value] = {}
        spans: dict[m.Value, Span] = {}
        key_types: set[m.AnyType] = set()
        value_type: m.AnyType | None = None
        errors = self.d.error_count
        if not decl.value.entries:
            self.d.report("E204", decl.value.span, f"table `{name}` is empty", help="give it `key: value` entries")
        for key_expr, value_expr in decl.value.entries:
            for_entry = self.d.error_count
            key, value = self.typer.expr(key_expr, env), self.typer.expr(value_expr, env)
            for node, expr in ((key, key_expr), (value, value_expr)):
                if node.type is not None and not self.typer.is_constant(node) and self.d.error_count == for_entry:
                    self.d.report("E204", expr.span, "a table's keys and values are constants")
            if key.type is not None and key.type not in (Type.INT, Type.STRING):
                self.d.report("E401", key_expr.span, f"a table's keys are ints or strings, not {describe(key.type)}")
            if key.type is not None:
                key_types.add(key.type)
            if value.type is not None:
                joined = value.type if value_type is None else unify(value_type, value.type)
                if joined is None and value_type is not None:
                    self.d.report("E401", value_expr.span, f"a table's values are of one type: this is "
                                  f"{describe(value.type)}, the ones before are {describe(value_type)}")
                value_type = joined or value_type
            k = self.typer.constant(key)
            if k is not None and not self.typer.kept(k, key_expr.span):  # ints kept in 64 bits and a sign
                continue
            if k in spans:
                self.d.report("E101", key_expr.span, f"key {shown(k)} is in table `{name}` twice",
                              labels=(Label(spans[k], "first given here"),))
            elif k is not None:
                spans[k] = key_expr.span
                known = self.typer.constant(value)
                if known is not None and self.typer.kept(known, value_expr.span):  # else reported
                    entries[k] = known
        if len(key_types) > 1:
            self.d.report("E401", decl.value.span, f"the keys of table `{name}` are of one type")
        key_type = next(iter(key_types), None)  # one, or more than one reported
        if self.d.error_count != errors or not isinstance(key_type, Type) or value_type is None:
            self.typer.failed.add(name)  # reported: its lookups are not reported again
            return None
        if value_type is Type.FLOAT:
            entries = {k: m.coerce(v, Type.FLOAT) for k, v in entries.items()}
        self.typer.tables[name] = (key_type, value_type, entries)
        # A table's values may be arrays, which m.Table.value_type (a Type) does not say.
        return m.Table(name, key_type, value_type, tuple(entries.items()), decl.doc)  # type: ignore[arg-type]

    def constant(self, decl: ast.ConstDecl) -> m.Value | None:
        """A named constant, visible to every expression declared after it."""
        errors, failed_reads = self.d.error_count, self.typer.failed_reads
        assert not isinstance(decl.value, ast.TableLit)  # `table`
        node = self.typer.expr(decl.value, Env({}, "in a constant", "constants declared before it"))
        value = self.typer.constant(node)
        if value is None or node.type is None or not self.typer.kept(value, decl.value.span):
            if self.d.error_count == errors and self.typer.failed_reads == failed_reads:
                self.d.report("E204", decl.value.span, "a constant's value must be a constant expression")
            self.typer.failed.add(decl.name.text)
            return None
        self.typer.named[decl.name.text] = (node.type, value)
        return value

    def enum(self, decl: ast.EnumDecl) -> dict[str, int]:
        members: dict[str, int] = {}
        self.typer.enums[decl.name.text] = members
        first: dict[str, ast.EnumMember] = {}
        for member in decl.members:
            if member.name.text in first:
                self.d.report("E101", member.name.span, f"member `{member.name.text}` is declared twice",
                              labels=(Label(first[member.name.text].name.span, "first declared here"),))
                continue
            first[member.name.text] = member
            node = self.typer.expr(member.value, Env({}, "in an enum", "constants"))
            value = self.typer.constant(node)
            if node.type is not Type.INT or not isinstance(value, int) or isinstance(value, bool):
                if node.type is not None:
                    self.d.report("E204", member.value.span, "an enum member's value is a constant integer")
                continue
            if not self.typer.kept(value, member.value.span):  # 64 bits and a sign: it must go through JSON
                continue
            members[member.name.text] = value
        return members

    def adapter(self, decl: ast.AdapterDecl) -> m.Adapter:
        fields: list[m.AdapterField] = []
        seen: dict[str, ast.FieldDecl] = {}
        for f in decl.fields:
            check_name(f.name, "field", self.d)
            if f.name.text in seen:
                self.d.report(
                    "E101", f.name.span, f"field `{f.name.text}` is declared twice in adapter `{decl.name.text}`",
                    labels=(Label(seen[f.name.text].name.span, "first declared here"),),
                )
                continue
            seen[f.name.text] = f
            path = self.ros_name(f.ros, ros.path_problem)
            field_type = self.type_name(f.type, "an adapter field", True)  # None: reported
            fields.append(m.AdapterField(f.name.text, field_type, f.unit, path, f.doc))  # type: ignore[arg-type]
        message = self.ros_name(decl.ros, ros.message_problem)
        made = m.Adapter(decl.name.text, tuple(fields), message, id(decl) in self.s.standard, decl.doc, decl.span)
        return with_frameworks(made)

    def ros_name(self, given: ast.StrLit | None, problem: Callable[[str], str | None]) -> str | None:
        """A ROS name as written (an adapter's message type, a field's path), its fault reported (E108)."""
        if given is None:
            return None
        found = problem(given.value)
        if found is not None:
            self.d.report("E108", given.span, found)
        return given.value

    def state(self, decl: ast.StateDecl) -> m.StateVariable:
        type_ = self.type_name(decl.type, open_size=True)
        initial: object = type_.default() if type_ else None
        if decl.init is not None:
            errors = self.d.error_count
            node = self.typer.expr(decl.init, Env({}, "in an initial value", ""))
            value = self.typer.constant(node)
            if value is None:
                if self.d.error_count == errors:  # not already explained
                    self.d.report("E204", decl.init.span, "an initial value must be a constant")
            elif type_ is not None and node.type is not None and self.typer.kept(value, decl.init.span):
                before = self.d.error_count
                self.flow(node, type_, decl.init.span, f"state variable `{decl.name.text}`")
                if self.d.error_count == before:
                    initial = m.coerce(value, type_)
        made = m.StateVariable(decl.name.text, type_, initial, decl.doc, decl.span)  # type: ignore[arg-type]
        if decl.noise is not None and type_ is not None:
            from rdisc.semantics.check.noise import value_noise  # only for a description that states noise
            made = m.StateVariable(made.name, made.type, made.initial, made.doc, made.span,
                                   value_noise(self.d, decl.noise, made.name, made.type, "state variable"))
        return made

    def user_setting(self, decl: ast.SettingDecl) -> m.Setting:
        """`setting NAME: TYPE in LOW..HIGH = DEFAULT`: a parameter of the whole description, given
        when connecting. Its default is required: the checks and the link budget use it."""
        check_name(decl.name, "setting", self.d)
        state = self.s.states.get(decl.name.text)
        if state is not None:
            self.d.report("E101", decl.name.span, f"`{decl.name.text}` is declared as a state variable and as a "
                          "setting", labels=(Label(state.name.span, "the state variable"),),
                          help="expressions read both by name: rename one")
        type_ = self.type_name(decl.type)
        param = ast.Param(decl.name, decl.type, decl.span, decl.low, decl.high, decl.default)
        low, high = self.param_range(param, type_.element if isinstance(type_, m.Array) else type_, "setting")
        default = self.param_default(param, type_, low, high, "setting")
        default = self.given.get(decl.name.text, default)  # the value given when connecting stands for it
        if decl.default is None:
            from rdisc.syntax.printer import print_type  # for the message: a clean check needs none

            self.d.report("E213", decl.name.span, f"setting `{decl.name.text}` has no default",
                          help=f"give the value it has when none is given: `setting {decl.name.text}: "
                          f"{print_type(decl.type)} = ...`; the checks and the link budget use it")
        return m.Setting(decl.name.text, type_, default, low, high, decl.doc, decl.span)  # type: ignore[arg-type]

    def baud_setting(self, ref: ast.Ref) -> float | None:
        """`baud NAME` of an int setting: its default is checked as a baud rate, and is what the
        link budget assumes; the value given when connecting is the port's."""
        setting = self.settings[ref.name]
        declared = (Label(self.s.settings[ref.name].name.span, "declared here"),)
        self.typer.reads.add(ref.name)
        if setting.type is None or setting.default is None:  # reported
            return None
        if setting.type is not Type.INT:
            self.d.report("E213", ref.span, f"the baud rate is an int, but setting `{ref.name}` is "
                          f"{describe(setting.type)}", labels=declared)
            return None
        baud = int(setting.default)  # type: ignore[arg-type]  # an int: its type is
        if not 0 < baud <= MAX_BAUD:
            self.d.report("E204", ref.span, f"the baud rate must be a positive integer at most {MAX_BAUD}, but "
                          f"the default of setting `{ref.name}` is {baud}", labels=declared)
            return None
        if baud not in STANDARD_BAUDS:
            self.d.report("W201", ref.span, f"{baud} (the default of setting `{ref.name}`) is not a standard "
                          "baud rate", help="standard rates include 9600, 19200, 38400, 57600, 115200")
        return baud

    def connection(self, decl: ast.ConnectionDecl,
                   interface_params: dict[str, tuple[m.Parameter, ...]]) -> m.Connection:
        name = decl.name
        if decl.kind.text not in CONNECTION_KINDS:
            self.d.report("E209", decl.kind.span, f"unknown connection kind `{decl.kind.text}`",
                          help="connections are `serial` or `tcp` (a `socket://host:port` port)")
        baud_clause = self.once([a for a in decl.attrs if isinstance(a, ast.Baud)], "`baud`", name)
        baud: float | None = DEFAULT_BAUD
        given = baud_clause.value if isinstance(baud_clause, ast.Baud) else None
        baud_setting = given.name if isinstance(given, ast.Ref) and given.name in self.settings else None
        if baud_setting is not None:
            baud = self.baud_setting(given)  # type: ignore[arg-type]
        elif isinstance(baud_clause, ast.Baud):
            baud = self.setting(baud_clause.value, "the baud rate", MAX_BAUD)
            if baud is not None:
                if baud != int(baud) or baud <= 0:
                    self.d.report("E204", baud_clause.value.span, f"the baud rate must be a positive integer, not {baud:g}")
                elif int(baud) not in STANDARD_BAUDS:
                    self.d.report("W201", baud_clause.value.span, f"{int(baud)} is not a standard baud rate",
                                  help="standard rates include 9600, 19200, 38400, 57600, 115200")
        threading = self.once([a for a in decl.attrs if isinstance(a, ast.Threading)], "`threading`", name)
        frequency: float | None = DEFAULT_FREQUENCY_HZ
        if isinstance(threading, ast.Threading):
            if threading.model.text not in THREADING_MODELS:
                self.d.report("E209", threading.model.span, f"unknown threading model `{threading.model.text}`",
                              help="threading is `single`, `dual` or `multiple`")
            frequency = self.setting(threading.frequency, "the frequency", MAX_FREQUENCY_HZ, " Hz")
            if frequency is not None and frequency <= 0:
                self.d.report("E204", threading.frequency.span, f"the frequency must be positive, not {frequency:g} Hz")
        hooks: dict[str, m.HookCall | None] = {}
        interval: float | None = None
        env = Env(self.state_env, "in a hook argument", "state variables")
        for event in ("startup", "terminate", "keepalive"):
            hook = self.once([a for a in decl.attrs if isinstance(a, ast.Hook) and a.event == event], f"`{event}`", name)
            hooks[event] = None
            if not isinstance(hook, ast.Hook):
                continue
            target = self.s.interfaces.get(hook.call.target.text)
            params = interface_params.get(hook.call.target.text)
            args = self.call(hook.call, params, env, "interface", target.name if target else None)
            hooks[event] = m.HookCall(m.InterfaceRef(hook.call.target.text), args, hook.span)
            if hook.every is not None:
                interval = self.duration(hook.every, "the keepalive interval")
                if interval is not None and interval <= 0:
                    self.d.report("E204", hook.every.span, "the keepalive interval must be positive")
        keepalive = m.Keepalive(hooks["keepalive"], interval) if hooks["keepalive"] and interval else None
        terminator = "\n"
        clause = self.once([a for a in decl.attrs if isinstance(a, ast.Terminator)], "`terminator`", name)
        if isinstance(clause, ast.Terminator):
            text = clause.value.value
            if not 1 <= len(text) <= MAX_TERMINATOR or not octets(text):
                self.d.report("E204", clause.value.span,
                              f"a terminator is 1 to {MAX_TERMINATOR} bytes (characters up to \\xff)")
            else:
                terminator = text
        address_clause = self.once([a for a in decl.attrs if isinstance(a, ast.Address)], "`address`", name)
        address = address_clause.value.value if isinstance(address_clause, ast.Address) else None
        if decl.kind.text == "tcp" and address_clause is not None and not address_clause.value.value.startswith("socket://"):
            self.d.report("E204", address_clause.value.span, "a tcp connection's address is `socket://HOST:PORT`")
        data_bits, parity, stop_bits = self.serial_line(decl)
        return m.Connection(
            name.text, decl.kind.text, int(baud or 0), float(frequency or 0), hooks["startup"], hooks["terminate"],
            keepalive, decl.doc, decl.span, terminator, address, baud_setting, data_bits, parity, stop_bits,
            threading.model.text if isinstance(threading, ast.Threading) else "single",
        )

    def serial_line(self, decl: ast.ConnectionDecl) -> tuple[int, str, float]:
        """A serial line's character, `databits`, `parity` and `stopbits` (8N1 unless said): the
        settings a UART has, stated only on a `serial` connection (E215)."""
        name = decl.name
        data = self.once([a for a in decl.attrs if isinstance(a, ast.DataBits)], "`databits`", name)
        parity = self.once([a for a in decl.attrs if isinstance(a, ast.Parity)], "`parity`", name)
        stop = self.once([a for a in decl.attrs if isinstance(a, ast.StopBits)], "`stopbits`", name)
        if decl.kind.text == "tcp":
            for clause in (data, parity, stop):
                if clause is not None:
                    self.d.report("E215", clause.span, f"`{name.text}` is a tcp connection, which has no serial line "
                                  "to set", help="data bits, parity and stop bits are a `serial` connection's")
        data_bits, parity_name, stop_bits = 8, "none", 1.0
        if isinstance(data, ast.DataBits):
            value = self.setting(data.value, "the data bits")
            if value is not None and value not in DATA_BITS:
                self.d.report("E215", data.value.span, f"a character has 5, 6, 7 or 8 data bits, not {value:g}")
            elif value is not None:
                data_bits = int(value)
        if isinstance(parity, ast.Parity):
            if parity.value.text not in PARITIES:
                self.d.report("E215", parity.value.span, f"unknown parity `{parity.value.text}`",
                              help="parity is none, even, odd, mark or space")
            else:
                parity_name = parity.value.text
        if isinstance(stop, ast.StopBits):
            value = self.setting(stop.value, "the stop bits")
            if value is not None and value not in STOP_BITS:
                shown = value if isinstance(value, int) else format(value, "g")  # an int may be too big for a float
                self.d.report("E215", stop.value.span, f"a character ends with 1, 1.5 or 2 stop bits, not {shown}")
            elif value is not None:
                stop_bits = value  # 2 stays an int: the driver says `stop_bits=2`
        if stop_bits == 1.5 and data_bits != 5:
            assert isinstance(stop, ast.StopBits)  # 1.5 is only ever stated
            self.d.report("E215", stop.value.span, f"1.5 stop bits go with 5 data bits, not {data_bits}",
                          help="a UART sends 1.5 stop bits only after 5 data bits: say `stopbits 1` or `2`")
        return data_bits, parity_name, stop_bits
