"""Where each name of a description is declared and where it is used, read from the syntax trees
of a compilation (the main file, its imports and the stdlib's adapters).

The places follow the resolver's rules (rdisc.semantics.resolve): a call names a primitive or else
an interface, a hook or an input an interface, an expression a parameter, loop variable or field
before a state variable, setting or constant. A name nothing declares is no occurrence: the checker
has reported it, and its did-you-mean is a quick fix.
"""

from __future__ import annotations

import bisect
from collections.abc import Iterable, Mapping

from rdisc.semantics.resolve import Unit
from rdisc.source import Span
from rdisc.syntax import ast

Node = object  # a syntax node, or a declaration's name


class Symbol:
    """A declared name: its kind in words ("primitive", "parameter", ...), its place, its
    declaration, and the element it belongs to (a parameter's primitive, a field's adapter)."""

    __slots__ = ("declaration", "kind", "members", "name", "owner", "span", "standard")

    def __init__(self, kind: str, name: ast.Ident, declaration: Node, owner: Symbol | None = None,
                 standard: bool = False) -> None:
        self.kind = kind
        self.name = name.text
        self.span = name.span
        self.declaration = declaration
        self.owner = owner
        self.standard = standard  # declared in stdlib/adapters.rdis
        self.members: dict[str, Symbol] = {}  # its parameters, fields or enum members, by name

    @property
    def key(self) -> tuple[str, int]:
        """What names the same symbol in another compilation of the same files."""
        return (self.span.path, self.span.start)


class Occurrence:
    """A name's place in a file: where it is declared (`declaration`) or used."""

    __slots__ = ("declaration", "span", "symbol")

    def __init__(self, span: Span, symbol: Symbol, declaration: bool) -> None:
        self.span = span
        self.symbol = symbol
        self.declaration = declaration


KINDS: dict[type, str] = {
    ast.StateDecl: "state variable", ast.SettingDecl: "setting", ast.ConnectionDecl: "connection",
    ast.PrimitiveDecl: "primitive", ast.InterfaceDecl: "interface", ast.AdapterDecl: "adapter",
    ast.InputDecl: "input", ast.OutputDecl: "output", ast.ConstDecl: "constant", ast.EnumDecl: "enum",
    ast.FrameDecl: "frame", ast.LinkDecl: "link", ast.JointDecl: "joint", ast.TransmissionDecl: "transmission",
    ast.RobotDecl: "robot", ast.SensorDecl: "sensor", ast.ActuatorDecl: "actuator",
}
READ = ("state variable", "setting", "constant", "sensor")
"""The declarations an expression reads by name, after its own names, in this order."""


class Index:
    """Every declaration and use of a name in a compilation's files, by file in source order."""

    def __init__(self) -> None:
        self.globals: dict[str, dict[str, Symbol]] = {kind: {} for kind in KINDS.values()}
        self.symbols: list[Symbol] = []
        self.by_path: dict[str, list[Occurrence]] = {}
        self._starts: dict[str, list[int]] = {}

    def add(self, span: Span | None, symbol: Symbol, declaration: bool = False) -> None:
        if span is not None:
            self.by_path.setdefault(span.path, []).append(Occurrence(span, symbol, declaration))

    def finish(self) -> None:
        for path, found in self.by_path.items():
            found.sort(key=lambda o: o.span.start)
            self._starts[path] = [o.span.start for o in found]

    def at(self, path: str, offset: int) -> Occurrence | None:
        """The occurrence at `offset` (or just before it: a cursor at the end of a name)."""
        found = self.by_path.get(path, [])
        i = bisect.bisect_right(self._starts.get(path, []), offset) - 1
        if 0 <= i < len(found) and found[i].span.start <= offset <= found[i].span.end:
            return found[i]
        return None

    def occurrences(self, symbol: Symbol) -> list[Occurrence]:
        """The symbol's declaration and every use of it, in the files of this index."""
        return [o for found in self.by_path.values() for o in found if o.symbol.key == symbol.key]

    def lookup(self, kinds: Iterable[str], name: str) -> Symbol | None:
        for kind in kinds:
            found = self.globals[kind].get(name)
            if found is not None:
                return found
        return None


def build_index(units: list[Unit]) -> Index:
    """The index of every unit's declarations and uses (the first declaration of a name wins)."""
    index = Index()
    for unit in units:
        for decl in unit.module.decls:
            kind = KINDS.get(type(decl))
            if kind is None or isinstance(decl, ast.ImportDecl):
                continue
            assert not isinstance(decl, ast.ImportDecl)
            symbol = Symbol(kind, decl.name, decl, standard=unit.standard)
            index.globals[kind].setdefault(decl.name.text, symbol)
            index.symbols.append(symbol)
            index.add(decl.name.span, symbol, True)
            symbol.members = _members(decl, symbol, index)
    uses = _Uses(index)
    for unit in units:
        for decl in unit.module.decls:
            if isinstance(decl, ast.ImportDecl):
                continue
            declared = index.globals[KINDS[type(decl)]].get(decl.name.text)
            uses.decl(decl, declared.members if declared is not None and declared.declaration is decl else {})
    index.finish()
    return index


def _members(decl: ast.Decl, owner: Symbol, index: Index) -> dict[str, Symbol]:
    """The names a declaration declares inside itself: parameters, an adapter's fields, an enum's members."""
    found: dict[str, Symbol] = {}

    def declare(kind: str, name: ast.Ident, node: Node) -> None:
        symbol = Symbol(kind, name, node, owner, owner.standard)
        found.setdefault(name.text, symbol)
        index.symbols.append(symbol)
        index.add(name.span, symbol, True)

    match decl:
        case ast.PrimitiveDecl() | ast.InterfaceDecl() | ast.FrameDecl():
            for param in decl.params:
                declare("parameter", param.name, param)
        case ast.AdapterDecl():
            for field in decl.fields:
                declare("field", field.name, field)
        case ast.EnumDecl():
            for member in decl.members:
                declare("enum member", member.name, member)
    return found


class _Uses:
    """One walk over a declaration, recording each name it uses."""

    def __init__(self, index: Index) -> None:
        self.index = index

    def use(self, ident: ast.Ident | None, kinds: Iterable[str]) -> Symbol | None:
        if ident is None:
            return None
        symbol = self.index.lookup(kinds, ident.text)
        if symbol is not None:
            self.index.add(ident.span, symbol)
        return symbol

    def local(self, ident: ast.Ident, node: Node, owner: Symbol | None, scope: dict[str, Symbol]) -> dict[str, Symbol]:
        """`scope` with a loop's or a `replies id in ...`'s variable added (declared here)."""
        symbol = Symbol("loop variable", ident, node, owner)
        self.index.symbols.append(symbol)
        self.index.add(ident.span, symbol, True)
        return {**scope, ident.text: symbol}

    def member_of(self, owner: Symbol | None, name: ast.Ident | None) -> None:
        if owner is not None and name is not None:
            symbol = owner.members.get(name.text)
            if symbol is not None:
                self.index.add(name.span, symbol)

    def decl(self, decl: ast.Decl, scope: dict[str, Symbol]) -> None:
        match decl:
            case ast.ConnectionDecl():
                for attr in decl.attrs:
                    if isinstance(attr, ast.Hook):
                        self.call(attr.call, ("interface",), scope)
                    else:
                        self.walk(attr, scope)
            case ast.SensorDecl():
                self.use(decl.primitive, ("primitive",))
                self.walk(decl.cache, scope)
            case ast.PrimitiveDecl():
                owner = self.index.globals["primitive"].get(decl.name.text)
                for clause in decl.clauses:
                    self.clause(clause, scope, owner)
                for param in decl.params:
                    self.walk(param, scope)
            case ast.InterfaceDecl():
                for param in decl.params:
                    self.walk(param, scope)
                for part in decl.clauses:
                    if isinstance(part, ast.Triggers):
                        for output in part.outputs:
                            self.use(output, ("output",))
                self.body(decl.body, scope)
            case ast.InputDecl():
                adapter = self.use(decl.adapter, ("adapter",))
                fields = adapter.members if adapter is not None else {}
                self.call(decl.call, ("interface",), fields)
            case ast.OutputDecl():
                adapter = self.use(decl.adapter, ("adapter",))
                self.use(decl.frame, ("link",))
                for assign in decl.fields:
                    self.member_of(adapter, assign.target)
                    self.walk(assign.value, scope)
                    self.walk(assign.index, scope)
            case ast.JointDecl():
                self.use(decl.parent, ("link",))
                self.use(decl.child, ("link",))
                for item in decl.items:
                    if isinstance(item, ast.JointMimic):
                        self.use(item.joint, ("joint",))
                        self.walk((item.multiplier, item.offset), scope)
                    else:
                        self.walk(item, scope)
            case ast.TransmissionDecl():
                self.use(decl.joint, ("joint",))
                if decl.actuator is not None:
                    self.use(decl.actuator, ("actuator",))
                for binding in decl.bindings:
                    if binding.role == "command":
                        target = self.use(binding.target, ("primitive", "interface"))
                        self.member_of(target, binding.member)
                    else:
                        self.use(binding.target, ("state variable",))
                    self.walk(binding.index, scope)
                    for conversion in binding.conversions:
                        self.walk(conversion.value, scope)
            case ast.FrameDecl():
                for param in decl.params:
                    self.walk(param, scope)
                self.walk(decl.items, scope)
            case _:
                self.walk(decl, scope)

    def clause(self, clause: ast.PrimitiveClause, scope: dict[str, Symbol], owner: Symbol | None) -> None:
        match clause:
            case ast.On():
                self.use(clause.connection, ("connection",))
            case ast.ReplyTable():
                self.member_of(owner, clause.key)
                self.walk(clause.entries, scope)
            case ast.Replies(var=var) if var is not None:
                inner = self.local(var, clause, owner, scope)
                self.walk(clause.over, scope)
                self.walk(clause.high, scope)
                self.walk(clause.frame, inner)
            case ast.Lines():
                for setting in clause.settings:
                    self.walk(setting.value if isinstance(setting, ast.Assign) else setting, scope)
            case _:
                self.walk(clause, scope)

    def body(self, body: tuple[ast.BodyStmt, ...], scope: dict[str, Symbol]) -> None:
        for stmt in body:
            if isinstance(stmt, ast.ForStmt):
                self.walk(stmt.low, scope)
                self.walk(stmt.high, scope)
                self.body(stmt.body, self.local(stmt.var, stmt, None, scope))
            else:
                self.call(stmt.call, ("primitive", "interface"), scope)
                self.walk((stmt.delays, stmt.priorities, stmt.conditions, stmt.polls), scope)

    def call(self, call: ast.Call, kinds: tuple[str, ...], scope: dict[str, Symbol]) -> None:
        self.use(call.target, kinds)
        self.walk(call.args, scope)

    def walk(self, node: object, scope: Mapping[str, Symbol]) -> None:
        """Every use of a name inside `node` (a node, a tuple of them, or None), iteratively:
        expressions are as deep as the parser allows."""
        stack = [node]
        pop, push = stack.pop, stack.extend
        while stack:
            item = pop()
            kind = type(item)
            if kind in _LEAVES:
                continue
            if kind is tuple:
                push(item)  # type: ignore[arg-type]
                continue
            if kind is ast.Ref:
                assert isinstance(item, ast.Ref)
                symbol = scope.get(item.name) or self.index.lookup(READ, item.name)
                if symbol is not None:
                    self.index.add(item.span, symbol)
                continue
            if kind is ast.Member:
                assert isinstance(item, ast.Member)
                self.member_of(self.use(item.enum, ("enum",)), item.member)
                continue
            if kind is ast.MethodCall:
                assert isinstance(item, ast.MethodCall)
                self.use(item.base, ("constant",))
            elif kind is ast.Framed:
                assert isinstance(item, ast.Framed)
                self.use(item.frame, ("frame",))
            elif kind is ast.ErrorReply:
                assert isinstance(item, ast.ErrorReply)
                self.use(item.codes, ("enum",))
            elif kind is ast.Assign:  # a post-action's target: a state variable
                assert isinstance(item, ast.Assign)
                self.use(item.target, ("state variable",))
            slots = _SLOTS.get(kind) or _slots(kind)
            push([getattr(item, slot) for slot in slots])


_LEAVES = frozenset([type(None), str, int, float, bool, bytes, Span, ast.Ident, ast.IntLit, ast.FloatLit, ast.StrLit,
                     ast.BytesLit, ast.BoolLit])
"""What holds no name: skipped by the walk."""


_SLOTS: dict[type, tuple[str, ...]] = {}


def _slots(cls: type) -> tuple[str, ...]:
    """A node class's fields (its slots), but its span."""
    found = _SLOTS.get(cls)
    if found is None:
        found = _SLOTS[cls] = tuple(s for s in getattr(cls, "__slots__", ()) if s != "span")
    return found
