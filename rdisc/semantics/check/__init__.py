"""Types and rules of every declaration, and the Model built from them.

`check` walks the declarations once, typing every expression (rdisc.semantics.types) and
checking the rules of the thesis model, a module per kind of declaration: declarations (the
robot, constants, tables, enums, adapters, state, settings, connections), layouts (templates
and frames), replies (and post-actions), primitives, interfaces (with inputs and outputs), each
over the pieces they share (types, parameters, calls). Then what is declared and never used
(W102, W103). The Model is returned only when no error was found.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import partial

from rdisc.diagnostics import Diagnostics
from rdisc.semantics import model as m
from rdisc.semantics.check.declarations import Declarations
from rdisc.semantics.check.interfaces import Interfaces
from rdisc.semantics.check.memo import Memo, Remembering
from rdisc.semantics.check.primitives import Primitives
from rdisc.semantics.check.sensors import Sensors
from rdisc.semantics.frame_facts import unseeded
from rdisc.semantics.frames import FrameRules
from rdisc.semantics.model import Scope
from rdisc.semantics.resolve import Symbols, Unit
from rdisc.syntax import ast


def check(units: list[Unit], symbols: Symbols, diagnostics: Diagnostics, memo: Memo | None = None,
          settings: Mapping[str, m.Value] | None = None) -> m.Model | None:
    """The Model, or None; `memo`: the primitives' and interfaces' checks kept from the last check
    of the same document, reused where what they read did not change (the editor's); `settings`:
    values given when connecting, which stand for those settings' defaults (compile_path's)."""
    checker = Checker(units, symbols, diagnostics)
    checker.given = dict(settings or {})
    checker.remember(memo)
    model = checker.run()
    checker.forget_rest()
    return model


class Checker(Declarations, Primitives, Interfaces, Sensors, Remembering):
    """Each kind of declaration by its own rules, the Model built from them."""

    def run(self) -> m.Model | None:
        adapters = {name: self.adapter(decl) for name, decl in self.s.adapters.items()}
        states = {name: self.state(decl) for name, decl in self.s.states.items()}
        self.typer.settings = set(self.s.settings)
        settings = self.settings = {name: self.user_setting(decl) for name, decl in self.s.settings.items()}
        self.state_env = {n: (Scope.STATE, s.type) for n, s in settings.items()}
        self.state_env.update({n: (Scope.STATE, s.type) for n, s in states.items()})
        for keyword, name in self.s.damaged:  # lost to a syntax error: readable, of unknown type
            if keyword in ("state", "setting"):
                self.state_env.setdefault(name, (Scope.STATE, None))  # type: ignore[arg-type]
        tables = {name: self.table(name, decl) for name, decl in self.s.constants.items()
                  if isinstance(decl.value, ast.TableLit)}
        constants = {name: self.constant(decl) for name, decl in self.s.constants.items()
                     if not isinstance(decl.value, ast.TableLit)}
        enums = {name: self.enum(decl) for name, decl in self.s.enums.items()}
        rules = FrameRules(self.d, self.typer, self.setting)
        self.frames = {name: rules.frame(decl, self.params(decl.params, "frame"))
                       for name, decl in self.s.frames.items()}
        interface_params = {name: self.recall(decl, (), partial(self.params, decl.params, "interface"), "params")
                            for name, decl in self.s.interfaces.items()}
        primitives = self.primitives = {name: self.recall(decl, (), partial(self.primitive, decl))
                                        for name, decl in self.s.primitives.items()}
        connections = {name: self.connection(decl, interface_params) for name, decl in self.s.connections.items()}
        sensor_types = {name: self.type_name(decl.type) for name, decl in self.s.sensors.items()}
        sensors = {name: self.sensor(decl, sensor_types[name]) for name, decl in self.s.sensors.items()}
        readable = {n: (Scope.STATE, t) for n, t in sensor_types.items() if n not in self.state_env and t is not None}
        self.state_env.update(readable)  # interfaces and outputs read sensors, each read refreshed when stale
        interfaces = {
            name: self.recall(decl, self.interface_reads(decl, primitives),
                              partial(self.interface, decl, interface_params, primitives))
            for name, decl in self.s.interfaces.items()
        }
        self.interface_cycles(interfaces)
        inputs = {name: self.input(decl, adapters, interface_params) for name, decl in self.s.inputs.items()}
        outputs = {name: self.output(decl, adapters) for name, decl in self.s.outputs.items()}
        links, joints, transmissions = self.robot_body(primitives, interface_params, states)
        actuators = self.robot_actuators(links, joints, transmissions)
        robot = self.robot()
        self.unused(interfaces)
        unseeded(self.frames, primitives, self.s.primitives, self.d)
        if self.d.has_errors() or robot is None:
            return None
        model = m.Model(
            robot=robot,
            states=states,
            connections=connections,
            primitives=primitives,
            interfaces=interfaces,
            adapters=adapters,
            inputs=inputs,
            outputs=outputs,
            frames=self.frames,
            constants={n: v for n, v in constants.items() if v is not None},
            tables={n: t for n, t in tables.items() if t is not None},
            enums=enums,
            constant_docs={n: d.doc for n, d in self.s.constants.items() if d.doc and constants.get(n) is not None},
            enum_docs={n: d.doc for n, d in self.s.enums.items() if d.doc and n in enums},
            settings=settings,
            links=links,
            joints=joints,
            transmissions=transmissions,
            sensors={n: s for n, s in sensors.items() if s is not None},
            actuators=actuators,
        )
        if transmissions and inputs:  # the body against the inputs that drive it
            from rdisc.semantics.drive import check_drives

            check_drives(model, self.d, self.s)
        if transmissions and outputs:  # the body against the odometry its encoders give
            from rdisc.semantics.odometry import check_odometry

            check_odometry(model, self.d, self.s)
        return None if self.d.has_errors() else model

    def robot_body(self, primitives: dict[str, m.Primitive], interface_params: dict[str, tuple[m.Parameter, ...]],
                   states: dict[str, m.StateVariable],
                   ) -> tuple[dict[str, m.Link], dict[str, m.Joint], dict[str, m.Transmission]]:
        """Links, joints and transmissions, by the body's rules (rdisc.semantics.body), imported only
        for a description that has a body: most have none, and a check starts cold."""
        if not (self.s.links or self.s.joints or self.s.transmissions):
            return {}, {}, {}
        from rdisc.semantics.body import BodyRules

        errors = self.d.error_count
        body = BodyRules(self.d, self.typer, self.s, self.settings)
        links = {name: body.link(decl) for name, decl in self.s.links.items()}
        joints = {j.name: j for j in (body.joint(decl) for decl in self.s.joints.values()) if j is not None}
        joints = body.tree(links, joints)
        body.portable_names()
        body.spawned(links, joints)
        body.mimics(joints)
        transmissions = {name: body.transmission(decl, joints, primitives, interface_params, states)
                         for name, decl in self.s.transmissions.items()}
        if self.d.error_count == errors:  # a body refused otherwise is not yet one to simulate
            body.carried(links, joints)
        return links, joints, {n: t for n, t in transmissions.items() if t is not None}

    def robot_actuators(self, links: dict[str, m.Link], joints: dict[str, m.Joint],
                        transmissions: dict[str, m.Transmission]) -> dict[str, m.Actuator]:
        """The actuators and the transmissions naming them (rdisc.semantics.actuators), imported only
        for a description that declares one."""
        if not self.s.actuators:
            return {}
        from rdisc.semantics import actuators as rules
        from rdisc.semantics.body import BodyRules

        body = BodyRules(self.d, self.typer, self.s, self.settings)
        found = {name: rules.actuator(self.d, body, decl) for name, decl in self.s.actuators.items()}
        actuators = {n: a for n, a in found.items() if a is not None}
        rules.bind(self.d, self.s.transmissions, actuators, transmissions, links, joints)
        return actuators

    def unused(self, interfaces: dict[str, m.Interface]) -> None:
        """Outputs never delivered and state nothing uses. (Primitives and interfaces are the
        host's to call, through `call_primitive` and `call_interface`, so none is unused.)"""
        if self.s.damaged:  # what the lost declarations used is unknown
            return
        triggered = {o for i in interfaces.values() for o in i.triggers}
        for name, decl in self.s.outputs.items():
            if name not in triggered and id(decl) in self.main_decls and ("output", name) not in self.s.suggested:
                self.d.report("W102", decl.name.span, f"output `{name}` is never triggered",
                              help=f"add `triggers {name}` to the interface that reads its state")
        written = {a.target for p in self.primitives.values() for a in p.post_actions()}
        for name, state in self.s.states.items():
            known = self.state_env.get(name, (None, None))[1] is not None  # else its type is reported
            if name not in self.typer.reads and name not in written and known and id(state) in self.main_decls:
                self.d.report("W103", state.name.span, f"state variable `{name}` is never used",
                              help="read it in an expression, write it in a post-action, or remove it")
