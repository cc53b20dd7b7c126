"""The declarations that hold data: the robot's attributes, constants, tables, enums,
adapters and state variables."""

from __future__ import annotations

from rdisc.diagnostics import Label
from rdisc.semantics import model as m
from rdisc.semantics import ros
from rdisc.semantics.check.pieces import Pieces
from rdisc.semantics.model import Type
from rdisc.semantics.operators import shown
from rdisc.semantics.resolve import check_name
from rdisc.semantics.types import Env, describe, unify
from rdisc.source import Span
from rdisc.syntax import ast


class Declarations(Pieces):
    """The rules of the robot, constants, tables, enums, adapters and state variables."""

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
            if k in spans:
                self.d.report("E101", key_expr.span, f"key {shown(k)} is in table `{name}` twice",
                              labels=(Label(spans[k], "first given here"),))
            elif k is not None:
                spans[k] = key_expr.span
                known = self.typer.constant(value)
                if known is not None:  # else reported
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
            path = None
            if f.ros is not None:
                problem = ros.path_problem(f.ros.value)
                if problem is not None:
                    self.d.report("E108", f.ros.span, problem)
                path = f.ros.value
            field_type = self.type_name(f.type, "an adapter field", True)  # None: reported
            fields.append(m.AdapterField(f.name.text, field_type, f.unit, path, f.doc))  # type: ignore[arg-type]
        message = None
        if decl.ros is not None:
            problem = ros.message_problem(decl.ros.value)
            if problem is not None:
                self.d.report("E108", decl.ros.span, problem)
            message = decl.ros.value
        return m.Adapter(decl.name.text, tuple(fields), message, id(decl) in self.s.standard, decl.doc, decl.span)

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
        return m.StateVariable(decl.name.text, type_, initial, decl.doc, decl.span)  # type: ignore[arg-type]
