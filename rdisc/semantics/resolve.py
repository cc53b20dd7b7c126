"""Names: pass 1 declares every element of every file, pass 2 binds every reference.

Cycles between elements are fine because every element is declared before any
reference is bound. The result is a symbol table per kind; a reference that does
not resolve is reported here once, and later passes skip it silently.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from rdisc import TYPE_CHECKING
from rdisc.diagnostics import Diagnostics, Label
from rdisc.engine.operations import FUNCTIONS
from rdisc.source import Span
from rdisc.syntax import ast

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.resolve_methods import dataclass

from rdisc.frozen import Frozen

# Words that would be read as keywords where a name can stand. Other keywords of
# the language only occur in places no name can, so they stay usable as names
# (the thesis's Create has interfaces named `startup` and `drive`).
KEYWORDS = frozenset(["if", "else", "and", "or", "not", "True", "False", "out", "delay", "priority", "for"])


@dataclass(frozen=True, slots=True)
class Unit(metaclass=Frozen):
    """One parsed file and its role in the description."""

    module: ast.Module
    main: bool = False
    standard: bool = False  # stdlib/adapters.rdis


class Symbols:
    """Every declared element by kind and name (the first declaration wins); a plain class:
    `rdisc check` need not import `dataclasses`."""

    __slots__ = (
        "actuators", "adapters", "connections", "constants", "damaged", "enums", "frames", "inputs", "interfaces", "joints",
        "links", "outputs", "primitives", "robot", "sensors", "settings", "standard", "states", "suggested", "transmissions",
    )

    def __init__(self) -> None:
        self.robot: ast.RobotDecl | None = None
        self.states: dict[str, ast.StateDecl] = {}
        self.settings: dict[str, ast.SettingDecl] = {}
        self.sensors: dict[str, ast.SensorDecl] = {}
        self.connections: dict[str, ast.ConnectionDecl] = {}
        self.primitives: dict[str, ast.PrimitiveDecl] = {}
        self.interfaces: dict[str, ast.InterfaceDecl] = {}
        self.adapters: dict[str, ast.AdapterDecl] = {}
        self.inputs: dict[str, ast.InputDecl] = {}
        self.outputs: dict[str, ast.OutputDecl] = {}
        self.constants: dict[str, ast.ConstDecl] = {}
        self.enums: dict[str, ast.EnumDecl] = {}
        self.frames: dict[str, ast.FrameDecl] = {}
        self.links: dict[str, ast.LinkDecl] = {}
        self.joints: dict[str, ast.JointDecl] = {}
        self.transmissions: dict[str, ast.TransmissionDecl] = {}
        self.actuators: dict[str, ast.ActuatorDecl] = {}
        self.standard: set[int] = set()  # id() of declarations from the stdlib
        self.damaged: set[tuple[str, str]] = set()  # (keyword, name) lost to syntax errors
        # (kind, name) offered as "did you mean" for an unknown reference: probably used,
        # so not reported as unused as well.
        self.suggested: set[tuple[str, str]] = set()

    def is_damaged(self, keyword: str, name: str) -> bool:
        return (keyword, name) in self.damaged


_KINDS = {
    ast.StateDecl: ("states", "state variable"),
    ast.SettingDecl: ("settings", "setting"),
    ast.SensorDecl: ("sensors", "sensor"),
    ast.ConnectionDecl: ("connections", "connection"),
    ast.PrimitiveDecl: ("primitives", "primitive"),
    ast.InterfaceDecl: ("interfaces", "interface"),
    ast.AdapterDecl: ("adapters", "adapter"),
    ast.InputDecl: ("inputs", "input"),
    ast.OutputDecl: ("outputs", "output"),
    ast.ConstDecl: ("constants", "constant"),
    ast.EnumDecl: ("enums", "enum"),
    ast.FrameDecl: ("frames", "frame"),
    ast.LinkDecl: ("links", "link"),
    ast.JointDecl: ("joints", "joint"),
    ast.TransmissionDecl: ("transmissions", "transmission"),
    ast.ActuatorDecl: ("actuators", "actuator"),
}

_BODY = (ast.LinkDecl, ast.JointDecl, ast.TransmissionDecl, ast.ActuatorDecl)
"""Elements no expression reads, so a function's name is theirs to take (`link upper`)."""


def resolve(units: list[Unit], diagnostics: Diagnostics) -> Symbols:
    symbols = Symbols()
    for unit in units:
        _declare(unit, symbols, diagnostics)
    main = next((u for u in units if u.main), None)
    robot_lost = any(keyword == "robot" for keyword, _ in symbols.damaged)
    if symbols.robot is None and main is not None and not robot_lost and not main.module.refused:
        first = main.module.decls[0].span.start if main.module.decls else 0
        diagnostics.report(
            "E107",
            Span(main.module.path, first, first),
            f"{main.module.path} has no `robot` declaration",
            help="start the description with `robot NAME { author \"...\" }`",
        )
    # What a call statement or a command names: a primitive, or else an interface. Merged once
    # here, not per call: binding takes time in proportion to the description.
    callables: dict[str, ast.InterfaceDecl | ast.PrimitiveDecl] = {**symbols.interfaces, **symbols.primitives}
    for unit in units:
        for decl in unit.module.decls:
            _bind(decl, symbols, callables, diagnostics)
    return symbols


def check_name(name: ast.Ident, what: str, diagnostics: Diagnostics, read: bool = True) -> None:
    """Report a keyword, or a built-in function where an expression could `read` the name, used as a name."""
    if name.text in KEYWORDS:
        diagnostics.report("E104", name.span, f"`{name.text}` is a keyword and cannot name a {what}",
                           help=f"choose another name, e.g. `{name.text}_`")
    elif name.text in FUNCTIONS and read:
        diagnostics.report("E104", name.span, f"`{name.text}` is a built-in function and cannot name a {what}",
                           help=f"choose another name, e.g. `{name.text}_value`")


def closest(name: str, candidates: Iterable[str]) -> str | None:
    """The declared name closest to a misspelt one (the engine's one rule, `nearest`), if any is close."""
    from rdisc.engine.errors import nearest  # only for an unknown name: `check` imports little of the engine

    return nearest(name, candidates)


def suggest(name: str, candidates: Iterable[str]) -> str | None:
    """A 'did you mean' help line when a declared name is close."""
    close = closest(name, candidates)
    return f"did you mean `{close}`?" if close else None


def _declare(unit: Unit, symbols: Symbols, diagnostics: Diagnostics) -> None:
    symbols.damaged |= {(d.keyword, d.name.text) for d in unit.module.damaged}
    for decl in unit.module.decls:
        if isinstance(decl, ast.ImportDecl):
            continue
        if isinstance(decl, ast.RobotDecl):
            if not unit.main:
                diagnostics.report(
                    "E107", decl.name.span, "a `robot` declaration belongs in the main description, not an imported file"
                )
            elif symbols.robot is not None:
                diagnostics.report(
                    "E107",
                    decl.name.span,
                    "a description has exactly one `robot` declaration",
                    labels=(Label(symbols.robot.name.span, "the first one is here"),),
                )
            else:
                check_name(decl.name, "robot", diagnostics)
                symbols.robot = decl
            continue
        table_name, what = _KINDS[type(decl)]
        table = getattr(symbols, table_name)
        check_name(decl.name, what, diagnostics, read=not isinstance(decl, _BODY))
        first = table.get(decl.name.text)
        if first is not None:
            diagnostics.report(
                "E101",
                decl.name.span,
                f"{what} `{decl.name.text}` is declared twice",
                label=f"second {what} named `{decl.name.text}`",
                labels=(Label(first.name.span, "first declared here"),),
            )
            continue
        table[decl.name.text] = decl
        if unit.standard:
            symbols.standard.add(id(decl))


def _bind(decl: ast.Decl, symbols: Symbols, callables: Mapping[str, object], diagnostics: Diagnostics) -> None:
    def need(ident: ast.Ident, table: Mapping[str, object], what: str) -> None:
        if ident.text not in table and not symbols.is_damaged(what, ident.text):
            close = closest(ident.text, table)
            if close:
                symbols.suggested.add((what, close))
            diagnostics.report(
                "E102",
                ident.span,
                f"unknown {what} `{ident.text}`",
                label=f"no {what} of this name",
                help=f"did you mean `{close}`?" if close else None,
            )

    match decl:
        case ast.ConnectionDecl():
            for attr in decl.attrs:
                if isinstance(attr, ast.Hook):
                    need(attr.call.target, symbols.interfaces, "interface")
        case ast.PrimitiveDecl():
            for clause in decl.clauses:
                if isinstance(clause, ast.On):
                    need(clause.connection, symbols.connections, "connection")
                elif isinstance(clause, ast.Framed):
                    need(clause.frame, symbols.frames, "frame")
                elif isinstance(clause, ast.ErrorReply):
                    if clause.frame is not None:
                        need(clause.frame.frame, symbols.frames, "frame")
                    if clause.codes is not None:
                        need(clause.codes, symbols.enums, "enum")
        case ast.InterfaceDecl():
            for part in decl.clauses:
                if isinstance(part, ast.Triggers):
                    for output in part.outputs:
                        need(output, symbols.outputs, "output")
            for stmt in ast.call_stmts(decl.body):  # a primitive, or else an interface, of the name
                name = stmt.call.target.text
                if not symbols.is_damaged("primitive", name) and not symbols.is_damaged("interface", name):
                    need(stmt.call.target, callables, "primitive or interface")
        case ast.SensorDecl():
            need(decl.primitive, symbols.primitives, "primitive")
        case ast.InputDecl():
            need(decl.adapter, symbols.adapters, "adapter")
            need(decl.call.target, symbols.interfaces, "interface")
        case ast.OutputDecl():
            need(decl.adapter, symbols.adapters, "adapter")
            if decl.frame is not None:
                need(decl.frame, symbols.links, "link")
        case ast.JointDecl():
            need(decl.parent, symbols.links, "link")
            need(decl.child, symbols.links, "link")
            for item in decl.items:
                if isinstance(item, ast.JointMimic):
                    need(item.joint, symbols.joints, "joint")
        case ast.TransmissionDecl():
            need(decl.joint, symbols.joints, "joint")
            if decl.actuator is not None:
                need(decl.actuator, symbols.actuators, "actuator")
            for binding in decl.bindings:
                if binding.role == "command":
                    need(binding.target, callables, "primitive or interface")
                elif binding.target.text not in symbols.settings:  # read like state; refused by the checker
                    need(binding.target, symbols.states, "state variable")
        case _:
            pass
