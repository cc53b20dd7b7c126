"""The members of JSON objects read with their places: names, identifiers, types, strings,
objects and arrays of the kinds expected, each wrong kind, missing name or unknown member an
E008 error at the offending value; and the importer's state, shared by every kind of element."""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import lru_cache
from typing import Any, TypeVar

from rdisc.diagnostics import Diagnostics
from rdisc.engine.errors import nearest
from rdisc.json_import.values import JArray, JBool, JNull, JNumber, JObject, JString, JValue, kind_of
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.parse import parse

_Kind = TypeVar("_Kind", JString, JNumber, JBool, JNull, JArray, JObject)
_Built = TypeVar("_Built")
Members = dict[str, JValue]
NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_ARRAY_TYPE = re.compile(r"([A-Za-z][A-Za-z0-9_]*)\[([0-9]{0,6})\]")


def type_text(t: ast.TypeRef) -> str:
    """A declared type's name, as the importer compares it: an array's as `int[]`."""
    return f"{t.element.text}[]" if isinstance(t, ast.ArrayOf) else t.text


@lru_cache(maxsize=1)
def _standard_adapters() -> dict[str, ast.AdapterDecl]:
    """The standard adapters (stdlib/adapters.rdis), by name."""
    from rdisc.resources import stdlib_path

    path = stdlib_path()
    module = parse(str(path), path.read_text(encoding="utf-8"), Diagnostics())
    return {d.name.text: d for d in module.decls if isinstance(d, ast.AdapterDecl)}


class Reader:
    """What the elements know of each other, and the reading of JSON members with their places."""

    def __init__(self, path: str, diagnostics: Diagnostics) -> None:
        self.path = path
        self.d = diagnostics
        self.standard = _standard_adapters()
        self.adapter_fields = {name: {f.name.text: type_text(f.type) for f in a.fields} for name, a in self.standard.items()}
        self.primitive_types: dict[str, tuple[str, ...]] = {}
        self.interface_types: dict[str, tuple[str, ...]] = {}
        self.made_adapters: list[ast.AdapterDecl] = []
        self.frame_types: dict[str, tuple[str, ...]] = {}
        self.damaged: list[ast.Damaged] = []

    def error(self, span: Span, message: str, help: str | None = None) -> None:
        self.d.report("E008", span, message, help=help)

    def opening(self, obj: JObject) -> Span:
        """The `{` of an object: where a member it lacks is reported."""
        return Span(self.path, obj.span.start, obj.span.start + 1)

    def members(self, obj: JObject, what: str, known: tuple[str, ...]) -> Members:
        found: Members = {}
        for key, value in obj.members:
            if key.value in known:
                found[key.value] = value
                continue
            close = nearest(key.value, known)
            hint = (
                f"did you mean `{close}`?"
                if close
                else "known members: " + ", ".join(f"`{k}`" for k in known)
            )
            self.error(key.span, f"unknown member `{key.value}` in {what}", help=hint)
        return found

    def required(
        self, obj: JObject, m: Members, key: str, what: str, get: Callable[[JValue, str], _Built]
    ) -> _Built | None:
        if key not in m:
            self.error(self.opening(obj), f"{what} has no `{key}`")
            return None
        return get(m[key], f"`{key}`")

    def name(self, obj: JObject, m: Members, what: str) -> ast.Ident | None:
        return self.required(obj, m, "name", what, self.ident)

    def type_ref(self, v: JValue, what: str) -> ast.TypeRef | None:
        """A type's name, or an array type: `"int[6]"`, `"float[]"` (an adapter's field)."""
        s = self.string(v, what)
        if s is not None and (array := _ARRAY_TYPE.fullmatch(s.value)) is not None:
            start = s.span.start + 1  # after the opening quote: the name is written as is
            element = ast.Ident(array.group(1), Span(self.path, start, start + len(array.group(1))))
            size = None if not array.group(2) else ast.IntLit(int(array.group(2)), s.span)
            return ast.ArrayOf(element, size, s.span)
        return self.ident(v, what)

    def ident(self, v: JValue, what: str) -> ast.Ident | None:
        s = self.string(v, what)
        if s is None:
            return None
        if not NAME.fullmatch(s.value):
            self.error(
                s.span, f"{what} must be a name (a letter, then letters, digits or `_`), found {s.raw}"
            )
            return None
        return ast.Ident(s.value, self.inner(s))

    def inner(self, s: JString) -> Span:
        """The characters between the quotes, when they are written as is."""
        return s.span if "\\" in s.raw else Span(self.path, s.span.start + 1, s.span.end - 1)

    def string(self, v: JValue | None, what: str) -> JString | None:
        return self.expect(v, JString, what, "a string")

    def object(self, v: JValue | None, what: str) -> JObject | None:
        return self.expect(v, JObject, what, "an object")

    def array(self, v: JValue | None, what: str) -> tuple[JValue, ...]:
        found = self.expect(v, JArray, what, "an array")
        return () if found is None else found.items

    def expect(self, v: JValue | None, kind: type[_Kind], what: str, words: str) -> _Kind | None:
        if v is None or isinstance(v, kind):
            return v
        self.error(v.span, f"{what} must be {words}, found {kind_of(v)}")
        return None

    def doc(self, m: Members) -> str | None:
        """A doc text as the parser would read it back from `///` lines."""
        s = self.string(m.get("doc"), "`doc`")
        return None if s is None else "\n".join(line.rstrip() for line in s.value.split("\n")).strip()


def present(items: list[Any]) -> tuple[Any, ...]:
    """The items built; a missing one was reported, and `each` leaves its element out."""
    return tuple(x for x in items if x is not None)


def str_lit(s: JString | None) -> ast.StrLit | None:
    return None if s is None else ast.StrLit(s.value, s.span)
