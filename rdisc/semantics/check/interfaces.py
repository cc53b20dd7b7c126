"""Interfaces and the domain inputs and outputs that use them: an interface's body written out
as plain calls (loops unrolled, bounded), call statements with `when`/`until`/priority, calls
in a cycle, a periodic interface's one connection, and inputs' and outputs' adapters."""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from rdisc.diagnostics import Label
from rdisc.frozen import field_names, replace
from rdisc.semantics import model as m
from rdisc.semantics.check.declarations import MAX_FREQUENCY_HZ
from rdisc.semantics.check.layouts import Layouts
from rdisc.semantics.model import Scope, Type
from rdisc.semantics.resolve import suggest
from rdisc.semantics.types import Env, Names, describe
from rdisc.source import Span
from rdisc.syntax import ast

MAX_POLLS = 100_000  # calls of one `until`: its limit over its interval, plus the first
MAX_PRIORITY = 1_000_000  # either way; priorities only order the calls of one interface
MAX_UNROLLED = 4096  # calls an interface's body makes, its loops written out
MAX_UNROLLED_ALL = 65_536  # the same for all interfaces: the work loops cause stays bounded


class _Unrolling:
    """What the statements of one interface's body are checked against, and the calls made (a
    plain class: a frozen one would need a module of written methods, and this one is never
    compared or shown)."""

    __slots__ = ("calls", "decl", "env", "interface_params", "primitives")

    def __init__(self, decl: ast.InterfaceDecl, env: Env, interface_params: dict[str, tuple[m.Parameter, ...]],
                 primitives: dict[str, m.Primitive], calls: list[m.PrimitiveCall]) -> None:
        self.decl = decl
        self.env = env
        self.interface_params = interface_params
        self.primitives = primitives
        self.calls = calls


class Interfaces(Layouts):
    """The rules of interfaces, inputs and outputs."""

    def interface(self, decl: ast.InterfaceDecl, interface_params: dict[str, tuple[m.Parameter, ...]],
                  primitives: dict[str, m.Primitive]) -> m.Interface:
        name = decl.name
        params = interface_params[name.text]
        kind = self.once([c for c in decl.clauses if isinstance(c, ast.Kind)], "the kind (`periodic`/`adhoc`)", name)
        periodic = isinstance(kind, ast.Kind) and kind.word == "periodic"
        triggers = self.once([c for c in decl.clauses if isinstance(c, ast.Triggers)], "`triggers`", name)
        if periodic and decl.params:
            self.d.report(
                "E205", decl.params[0].span.to(decl.params[-1].span),
                f"periodic interface `{name.text}` cannot take parameters",
                help="nobody passes arguments on a tick: read state variables instead, or make it `adhoc`",
            )
        scope = {p.name: (Scope.PARAM, p.type) for p in params}  # one of a type in error: known, of type None
        env = self.env_with(scope, "in an interface", "its parameters and state variables")
        calls: list[m.PrimitiveCall] = []
        self.body(decl.body, _Unrolling(decl, env, interface_params, primitives, calls), {})
        rate = None
        if periodic:
            connection = self.periodic_connection(decl)
            if isinstance(kind, ast.Kind) and kind.rate is not None:
                rate = self.periodic_rate(decl, kind.rate, connection)
        outputs: dict[str, ast.Ident] = {}
        for output in triggers.outputs if isinstance(triggers, ast.Triggers) else ():
            if output.text in outputs:
                self.d.report("E203", output.span, f"`{output.text}` is triggered twice",
                              labels=(Label(outputs[output.text].span, "first given here"),))
            outputs.setdefault(output.text, output)
        out_ref = tuple(m.OutputRef(o) for o in outputs)
        return m.Interface(name.text, params, periodic, tuple(calls), out_ref, decl.doc, decl.span, rate)

    def body(self, stmts: tuple[ast.BodyStmt, ...], u: _Unrolling, loops: dict[str, ast.Ident]) -> None:
        """An interface's statements as plain calls: each loop written out, its variable a constant
        in each round, so the Model, the budget and every emitter see only calls. A round that
        reports an error ends its loop: the next rounds would repeat the fault."""
        for stmt in stmts:
            if isinstance(stmt, ast.CallStmt):
                call = self.call_stmt(stmt, u.env, u.interface_params, u.primitives)
                if loops:  # `IDS[i] + 1` of this round is known: the call says its value
                    call = replace(call, args=tuple(self.value_of(a) for a in call.args),
                                   when=None if call.when is None else self.value_of(call.when),
                                   until=None if call.until is None else self.value_of(call.until))
                u.calls.append(call)
                self.written += 1
                continue
            found = self.loop_values(stmt, u, loops)
            if found is None:
                continue
            type_, values = found
            name = stmt.var.text  # no constant has it (loop_variable): bound as one, then gone
            for value in values:
                self.typer.named[name] = (type_, value)
                errors = self.d.error_count
                self.body(stmt.body, u, {**loops, name: stmt.var})
                if self.d.error_count > errors:
                    break
            del self.typer.named[name]

    def loop_values(self, stmt: ast.ForStmt, u: _Unrolling,
                    loops: dict[str, ast.Ident]) -> tuple[Type, Sequence[m.Value]] | None:
        """The values a loop's variable takes, or None when the loop is in error (reported)."""
        head = Span(stmt.span.path, stmt.span.start, (stmt.high or stmt.low).span.end)  # `for i in 0..5`
        if not self.loop_variable(stmt.var, u.decl.params, loops):
            return None
        if not stmt.body:
            self.d.report("E212", head, "a loop without calls", help="write the calls it makes in its `{ }`")
            return None
        found = self.constant_values(stmt.low, stmt.high, u.env)
        if found is None:
            return None
        type_, values = found
        # Each round makes a call or more, so these bound the work before any is done.
        rounds = len(values)
        too_many = f"interface `{u.decl.name.text}` unrolls into more than {MAX_UNROLLED} calls" \
            if len(u.calls) + rounds > MAX_UNROLLED else \
            f"the description's interfaces unroll into more than {MAX_UNROLLED_ALL} calls" \
            if self.written + rounds > MAX_UNROLLED_ALL else None
        if too_many is not None:
            self.d.report("E212", head, too_many, help="every round of a loop makes its calls: loop over fewer values")
            return None
        return type_, values

    def call_stmt(self, stmt: ast.CallStmt, env: Env, interface_params: dict[str, tuple[m.Parameter, ...]],
                  primitives: dict[str, m.Primitive]) -> m.PrimitiveCall:
        """One call as the Model has it (in a loop, with the loop variables of this round)."""
        callee = stmt.call.target.text
        calls_interface = callee not in self.s.primitives and callee in self.s.interfaces
        if calls_interface:
            args = self.call(stmt.call, interface_params[callee], env, "interface",
                             self.s.interfaces[callee].name)
        else:
            target = self.s.primitives.get(callee)
            prim = primitives.get(callee)
            args = self.call(stmt.call, prim.params if prim else None, env, "primitive",
                             target.name if target else None)
            if prim is not None:
                self.constants_into_pack(prim, args, stmt.call.args)
        delay_clause = self.once(list(stmt.delays), "`delay`", stmt.call.target)
        delay = self.duration(delay_clause, "a delay") if isinstance(delay_clause, ast.Duration) else 0
        if delay_clause is not None and delay is not None and delay < 0:
            self.d.report("E204", delay_clause.span, f"a delay must be zero or more, not {delay:g} ms")
        priority_expr = self.once(list(stmt.priorities), "`priority`", stmt.call.target)
        priority = self.setting(priority_expr, "a priority", MAX_PRIORITY) if priority_expr is not None else 0
        if priority_expr is not None and priority is not None and priority != int(priority):
            self.d.report("E204", priority_expr.span, "a priority must be an integer")
        self.once(list(stmt.conditions), "`when`", stmt.call.target)
        when = self.typer.expr(stmt.conditions[0], env) if stmt.conditions else None
        if when is not None and when.type is not None and when.type is not Type.BOOL:
            self.d.report("E401", stmt.conditions[0].span, f"`when` takes a bool, but this is {describe(when.type)}")
        until, every, within = self.poll(stmt, env)
        return m.PrimitiveCall(
            m.PrimitiveRef(callee), args, delay or 0, int(priority or 0), stmt.span, calls_interface, when,
            until, every, within,
        )

    def poll(self, stmt: ast.CallStmt, env: Env) -> tuple[m.Expr | None, float, float]:
        """`until COND every P within T`: COND a bool over state and the interface's parameters,
        0 < P <= T, at most MAX_POLLS calls. (None, 0, 0) without one, or where it is refused."""
        clause = self.once(list(stmt.polls), "`until`", stmt.call.target)
        if not isinstance(clause, ast.Poll):
            return None, 0, 0
        until = self.typer.expr(clause.condition, env)
        if until.type is not None and until.type is not Type.BOOL:
            self.d.report("E401", clause.condition.span, f"`until` takes a bool, but this is {describe(until.type)}")
            return None, 0, 0
        every = self.duration(clause.every, "a poll's interval")
        within = self.duration(clause.within, "a poll's limit")
        if until.type is None or every is None or within is None:
            return None, 0, 0
        if not 0 < every <= within:
            self.d.report("E204", clause.span, f"a poll's interval must be positive and at most its limit, not "
                          f"every {every:g} ms within {within:g} ms",
                          help="`until COND every 10 ms within 2 s` calls again every 10 ms, for at most 2 s")
            return None, 0, 0
        if within / every >= MAX_POLLS:
            self.d.report("E204", clause.span, f"a poll makes at most {MAX_POLLS} calls, not "
                          f"{int(within / every) + 1} (every {every:g} ms within {within:g} ms)",
                          help="poll less often")
            return None, 0, 0
        return until, every, within

    def interface_cycles(self, interfaces: dict[str, m.Interface]) -> None:
        """Calls between interfaces form no cycle, so every call ends and its cost is known:
        each cycle is reported once, at the call that closes it in the interface first declared."""
        done: set[str] = set()
        for name in interfaces:
            self._calls_visited(interfaces, done, name, [])

    def _calls_visited(self, interfaces: dict[str, m.Interface], done: set[str], name: str,
                       path: list[tuple[str, m.PrimitiveCall]]) -> None:
        """`interface_cycles` from `name`, reached by `path`: each interface it calls visited in
        turn (`done`: those whose calls were all visited). (A method, not a nested function that
        calls itself: that is a cycle, which waits for the collector.)"""
        if name in done:
            return
        for call in interfaces[name].calls:
            if not call.interface or call.primitive not in interfaces:
                continue
            on_path = [n for n, _ in path] + [name]
            if call.primitive in on_path:
                ring = on_path[on_path.index(call.primitive):]
                through = " -> ".join(f"`{n}`" for n in [*ring, call.primitive])
                self.d.report("E210", call.span, f"interface `{name}` calls `{call.primitive}`, which leads "
                              f"back to it: {through}",
                              help="calls between interfaces must end: break the cycle")
                continue
            self._calls_visited(interfaces, done, call.primitive, [*path, (name, call)])
        done.add(name)

    def periodic_rate(self, decl: ast.InterfaceDecl, rate: ast.Expr, connection: str | None) -> float | None:
        """A periodic interface's own rate (`periodic 10 Hz`): positive, bounded as a connection's
        frequency, and used only on a connection of `threading multiple` (W230 elsewhere)."""
        value = self.setting(rate, "the rate", MAX_FREQUENCY_HZ, " Hz")
        if value is None:
            return None
        if value <= 0:
            self.d.report("E204", rate.span, f"the rate must be positive, not {value:g} Hz")
            return None
        conn = self.s.connections.get(connection) if connection is not None else None
        threading = next((a for a in conn.attrs if isinstance(a, ast.Threading)), None) if conn is not None else None
        model = threading.model.text if threading is not None else "single"
        if conn is not None and model in ("single", "dual"):  # another is E209
            self.d.report("W230", rate.span, f"`{decl.name.text}` states its own rate, but `{conn.name.text}` is "
                          f"`threading {model}`: it runs at the connection's frequency",
                          help=f"write `threading multiple` on `{conn.name.text}`, or leave the rate out")
        return value

    def periodic_connection(self, decl: ast.InterfaceDecl) -> str | None:
        """The connection a periodic interface runs on (None: unknown, or in error: reported)."""
        used: dict[str, ast.Ident] = {}
        for stmt, prim in self.primitives_called(decl, set()):
            on = next((c for c in prim.clauses if isinstance(c, ast.On)), None)
            if on is not None:
                used.setdefault(on.connection.text, stmt.call.target)
        if len(used) > 1:
            first, second = list(used.items())[:2]
            self.d.report(
                "E208", decl.name.span, f"periodic interface `{decl.name.text}` uses two connections",
                labels=(Label(first[1].span, f"on `{first[0]}`"), Label(second[1].span, f"on `{second[0]}`")),
                help="split it into one periodic interface per connection",
            )
        elif not used and len(self.s.connections) > 1 and not decl.body:
            self.d.report("E208", decl.name.span,
                          f"periodic interface `{decl.name.text}` calls no primitive, so its connection is unknown")
        if len(used) == 1:
            return next(iter(used))
        return next(iter(self.s.connections)) if len(self.s.connections) == 1 and not used else None

    def primitives_called(self, decl: ast.InterfaceDecl,
                          seen: set[str]) -> Iterator[tuple[ast.CallStmt, ast.PrimitiveDecl]]:
        """The primitive declarations an interface calls, through the interfaces it calls (each
        once: a cycle is reported on its own), with the statement in `decl` that leads there."""
        seen.add(decl.name.text)
        for stmt in ast.call_stmts(decl.body):
            callee = stmt.call.target.text
            prim = self.s.primitives.get(callee)
            if prim is not None:
                yield stmt, prim
            elif callee in self.s.interfaces and callee not in seen:
                yield from ((stmt, p) for _, p in self.primitives_called(self.s.interfaces[callee], seen))

    def input(self, decl: ast.InputDecl, adapters: dict[str, m.Adapter],
              interface_params: dict[str, tuple[m.Parameter, ...]]) -> m.DomainInput:
        adapter = adapters.get(decl.adapter.text)
        if adapter is None:  # unknown adapter, already reported: do not report its fields as unknown
            return m.DomainInput(decl.name.text, m.AdapterRef(decl.adapter.text), m.InterfaceRef(decl.call.target.text),
                                 (), decl.doc, decl.span)
        scope = {f.name: (Scope.FIELD, f.type) for f in adapter.fields}
        env = self.env_with(scope, "in an input", f"the fields of `{adapter.name}` and state variables")
        self.hidden_state(decl, adapter, scope)
        target = self.s.interfaces.get(decl.call.target.text)
        args = self.call(decl.call, interface_params.get(decl.call.target.text), env, "interface",
                         target.name if target else None)
        return m.DomainInput(decl.name.text, m.AdapterRef(adapter.name), m.InterfaceRef(decl.call.target.text),
                             args, decl.doc, decl.span)

    def hidden_state(self, decl: ast.InputDecl, adapter: m.Adapter, fields: Names) -> None:
        """W104 where an input reads a name that is both a field of its adapter and a state
        variable (or setting): the field hides it, once a name. Not for a standard adapter, whose
        fields are a message's (JointState's `position`), read by design beside state so named."""
        declared = self.s.adapters.get(adapter.name)
        if declared is None or id(declared) in self.s.standard:
            return
        seen: set[str] = set()
        for ref in _refs(decl.call.args):
            if ref.name not in fields or ref.name in seen:
                continue
            hidden = self.s.states.get(ref.name) or self.s.settings.get(ref.name)
            if hidden is None:
                continue
            seen.add(ref.name)
            kind = "state variable" if isinstance(hidden, ast.StateDecl) else "setting"
            self.d.report("W104", ref.span, f"`{ref.name}` here is the field of adapter `{adapter.name}`, "
                          f"which hides {kind} `{ref.name}`",
                          labels=(Label(hidden.name.span, f"{kind} `{ref.name}`, not read by input "
                                        f"`{decl.name.text}`"),),
                          help=f"rename the {kind} to read it in this input, or the field")

    def output(self, decl: ast.OutputDecl, adapters: dict[str, m.Adapter]) -> m.DomainOutput:
        adapter = adapters.get(decl.adapter.text)
        frame = None if decl.frame is None else decl.frame.text
        env = Env(self.state_env, "in an output", "state variables")
        values: dict[str, m.Expr] = {}
        first: dict[str, ast.Assign] = {}
        for assign in decl.fields:
            value = self.typer.expr(assign.value, env)
            if adapter is None:
                continue
            field = adapter.field(assign.target.text)
            if field is None:
                self.d.report(
                    "E206", assign.target.span,
                    f"adapter `{adapter.name}` has no field `{assign.target.text}`",
                    help=suggest(assign.target.text, [f.name for f in adapter.fields]) or
                    "its fields are " + ", ".join(f"`{f.name}`" for f in adapter.fields),
                )
                continue
            if field.name in first:
                self.d.report("E206", assign.target.span, f"field `{field.name}` is defined twice",
                              labels=(Label(first[field.name].target.span, "first defined here"),))
                continue
            first[field.name] = assign
            self.flow(value, field.type, assign.value.span, f"field `{field.name}` of `{adapter.name}`")
            values[field.name] = value
        if adapter is None:
            return m.DomainOutput(decl.name.text, m.AdapterRef(decl.adapter.text), (), decl.doc, decl.span, frame)
        missing = [f.name for f in adapter.fields if f.name not in values and f.name not in first]
        if missing and len(first) == len(decl.fields):  # a misspelt field already explains the gap
            self.d.report(
                "E206", decl.name.span,
                f"output `{decl.name.text}` does not define {', '.join(f'`{n}`' for n in missing)} "
                f"of adapter `{adapter.name}`",
                help="an output defines every field of its adapter",
            )
        fields = tuple((f.name, values[f.name]) for f in adapter.fields if f.name in values)
        noise: tuple[m.Noise, ...] = ()
        filters: tuple[m.Kalman, ...] = ()
        if decl.noises or decl.filters:  # their rules imported only then: most outputs state none, and a check starts cold
            from rdisc.semantics.check.noise import errors

            noise, filters = errors(self.d, decl, adapter)
        return m.DomainOutput(decl.name.text, m.AdapterRef(adapter.name), fields, decl.doc, decl.span, frame,
                              noise, filters)


def _refs(node: object) -> Iterator[ast.Ref]:
    """The names an expression (or a tuple of them) reads, in order."""
    if isinstance(node, ast.Ref):
        yield node
    elif isinstance(node, tuple):
        for item in node:
            yield from _refs(item)
    elif not isinstance(node, Span):
        for name in field_names(node):
            yield from _refs(getattr(node, name))
