"""Writes the methods of rdisc's frozen dataclasses ahead of time, from their declarations
(why: `rdisc/frozen.py`).

    python -m rdisc.frozen_writer          # rewrite each *_methods.py from its module
    python -m rdisc.frozen_writer --check  # exit 1 when one of them is stale

The declarations are read as text (Python's `ast`), never imported: each class decorated
`@dataclass(frozen=True, slots=True)` and declared `class Name(metaclass=Frozen)` (so that its
class statement makes it once, rdisc.frozen.Frozen), its annotated fields in order, and their defaults: a
value (given to the written `__init__` when the class is made), or `field(default=...,
default_factory=..., compare=..., repr=...)` written in place or bound to a module-level name (`_span`).
"""

from __future__ import annotations

import argparse
import ast
import itertools
import sys
from dataclasses import dataclass
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent
# Each module of frozen dataclasses and the module written for it, relative to the package.
MODULES = {
    "syntax/ast.py": "syntax/ast_methods.py",
    "syntax/ast_expressions.py": "syntax/ast_expressions_methods.py",
    "syntax/ast_primitives.py": "syntax/ast_primitives_methods.py",
    "syntax/ast_frames.py": "syntax/ast_frames_methods.py",
    "syntax/ast_body.py": "syntax/ast_body_methods.py",
    "semantics/model.py": "semantics/model_methods.py",
    "semantics/model_expressions.py": "semantics/model_expressions_methods.py",
    "semantics/model_layouts.py": "semantics/model_layouts_methods.py",
    "semantics/model_frames.py": "semantics/model_frames_methods.py",
    "semantics/model_elements.py": "semantics/model_elements_methods.py",
    "semantics/model_body.py": "semantics/model_body_methods.py",
    "source.py": "source_methods.py",
    "diagnostics/core.py": "diagnostics/core_methods.py",
    "diagnostics/codes.py": "diagnostics/codes_methods.py",
    "semantics/budget.py": "semantics/budget_methods.py",
    "semantics/formats.py": "semantics/formats_methods.py",
    "semantics/resolve.py": "semantics/resolve_methods.py",
    "semantics/types.py": "semantics/types_methods.py",
    "syntax/precedence.py": "syntax/precedence_methods.py",
}
LINE = 110
EMPTY = {"dict": "{}", "list": "[]", "set": "set()"}  # the default factories handled, and what they make


class WriterError(Exception):
    """A declaration the writer does not handle: say which, rather than write it wrong."""


@dataclass(frozen=True)
class _Field:
    name: str
    default: bool  # the parameter has one (the class's own, which rdisc.frozen gives the function)
    factory: str | None  # the built-in type that makes the default
    compare: bool
    shown: bool  # in the repr
    declared: str  # the source of what the class body gives the field, as rdisc.frozen compares it


def _field_call(call: ast.Call, where: str) -> tuple[str | None, str | None, bool, bool]:
    """default, factory, compare and repr of a `field(...)` call."""
    if call.args:
        raise WriterError(f"{where}: field() takes keyword arguments only")
    given = {k.arg: k.value for k in call.keywords}
    unknown = set(given) - {"default", "default_factory", "compare", "repr"}
    if unknown:
        raise WriterError(f"{where}: field({', '.join(sorted(str(u) for u in unknown))}=...) is not handled")
    default = _literal(given["default"], where) if "default" in given else None
    factory = None
    if "default_factory" in given:
        value = given["default_factory"]
        if not (isinstance(value, ast.Name) and value.id in EMPTY):
            raise WriterError(f"{where}: a default_factory must be one of {', '.join(EMPTY)}")
        factory = value.id
    flags = {}
    for flag in ("compare", "repr"):
        value = given.get(flag, ast.Constant(True))
        if not (isinstance(value, ast.Constant) and isinstance(value.value, bool)):
            raise WriterError(f"{where}: {flag}= must be True or False")
        flags[flag] = value.value
    return default, factory, flags["compare"], flags["repr"]


def _literal(node: ast.expr, where: str) -> str:
    text = ast.unparse(node)
    try:
        ast.literal_eval(node)
    except ValueError:
        raise WriterError(f"{where}: a default must be a literal, not `{text}`") from None
    return text


def _is_field(node: ast.expr | None) -> bool:
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "field"


def _is_frozen(decorator: ast.expr) -> bool:
    if not (isinstance(decorator, ast.Call) and isinstance(decorator.func, ast.Name)
            and decorator.func.id == "dataclass"):
        return False
    flags = {k.arg: k.value for k in decorator.keywords}
    return all(isinstance(flags.get(k), ast.Constant) and flags[k].value is True  # type: ignore[attr-defined]
               for k in ("frozen", "slots"))


def _fields(cls: ast.ClassDef, named: dict[str, ast.expr], path: str) -> list[_Field]:
    fields: list[_Field] = []
    for statement in cls.body:
        if not (isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name)):
            continue
        name, value = statement.target.id, statement.value
        where = f"{path}:{statement.lineno}: {cls.name}.{name}"
        if "ClassVar" in ast.unparse(statement.annotation) or name.startswith("_"):
            raise WriterError(f"{where}: class variables and fields named with `_` are not handled")
        call = named.get(value.id) if isinstance(value, ast.Name) else value
        if call is not None and _is_field(call):
            assert isinstance(call, ast.Call)
            default, factory, compare, shown = _field_call(call, where)
            spec = f"FieldSpec({default or 'MISSING'}, {factory or 'MISSING'}, {compare}, {shown})"
            fields.append(_Field(name, default is not None or factory is not None, factory, compare, shown, spec))
        else:
            fields.append(_Field(name, value is not None, None, True, True, "MISSING" if value is None else "DEFAULT"))
    for before, after in itertools.pairwise(fields):
        if before.default and not after.default:
            raise WriterError(f"{path}: {cls.name}.{after.name}: a field without a default follows one with")
    return fields


def _wrapped(head: str, items: list[str], tail: str, indent: str) -> list[str]:
    """`head + ", ".join(items) + tail` on one line when it fits, else one item a line."""
    line = f"{indent}{head}{', '.join(items)}{tail}"
    if len(line) <= LINE:
        return [line]
    return [f"{indent}{head}", *(f"{indent}    {item}," for item in items), f"{indent}{tail.lstrip(',')}"]


def _tuple(items: list[str]) -> str:
    return "(" + ", ".join(items) + ("," if len(items) == 1 else "") + ")"


def _methods(cls: str, fields: list[_Field]) -> list[str]:
    """The source of the class's __init__, __repr__, __eq__ and __hash__, as `dataclasses` writes them."""
    params = ["self: Any"] + [f"{f.name}: Any" + (" = DEFAULT" if f.default else "")
                              for f in fields]
    setters = [f"_set_{cls}_{f.name}" for f in fields]
    chained = " = ".join([*setters, "_unbound"])
    lines = ([chained] if len(chained) <= LINE else [f"{setter} = _unbound" for setter in setters]) if fields else []
    lines += ["", ""] if fields else []
    lines += _wrapped(f"def _init_{cls}(", params, ") -> None:", "")
    for f in fields:
        value = f"{EMPTY[f.factory]} if {f.name} is FACTORY else {f.name}" if f.factory else f.name
        lines.append(f"    _set_{cls}_{f.name}(self, {value})")
    if not fields:
        lines.append("    pass")
    shown = ", ".join(f"{f.name}={{self.{f.name}!r}}" for f in fields if f.shown)
    lines += ["", "", f"def _repr_{cls}(self: Any) -> str:",
              f'    return f"{{self.__class__.__qualname__}}({shown})"']
    mine = [f"self.{f.name}" for f in fields if f.compare]
    theirs = [f"other.{f.name}" for f in fields if f.compare]
    lines += ["", "", f"def _eq_{cls}(self: Any, other: Any) -> Any:", "    if other.__class__ is self.__class__:"]
    same = f"        return {_tuple(mine)} == {_tuple(theirs)}"
    if len(same) <= LINE:
        lines.append(same)
    else:
        lines += ["        return (", *(f"            {m}," for m in mine), "        ) == (",
                  *(f"            {t}," for t in theirs), "        )"]
    lines += ["    return NotImplemented", "", "", f"def _hash_{cls}(self: Any) -> int:"]
    lines += _wrapped("return hash((", mine, ("," if len(mine) == 1 else "") + "))", "    ")
    return lines


def write(path: Path) -> str:
    """The source of the methods module for the module at `path`."""
    relative = path.resolve().relative_to(PACKAGE.parent).as_posix()
    tree = ast.parse(path.read_text(encoding="utf-8"), relative)
    named: dict[str, ast.expr] = {}  # module-level names a default may be: `_span = field(...)`, `ORIGIN`
    for statement in tree.body:
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
            target, value = statement.targets[0], statement.value
        elif isinstance(statement, ast.AnnAssign) and statement.value is not None:
            target, value = statement.target, statement.value
        else:
            continue
        if isinstance(target, ast.Name):
            named[target.id] = value
    frozen = [c for c in tree.body if isinstance(c, ast.ClassDef) and any(_is_frozen(d) for d in c.decorator_list)]
    for c in frozen:
        if not any(k.arg == "metaclass" and isinstance(k.value, ast.Name) and k.value.id == "Frozen"
                   for k in c.keywords):
            raise WriterError(f"{relative}:{c.lineno}: {c.name}: declare it `class {c.name}(metaclass=Frozen)`,"
                              " so that its class statement makes it once")
    classes = [(c.name, _fields(c, named, relative)) for c in frozen]
    every = [f for _, fields in classes for f in fields]
    used = ["DEFAULT"] * any(f.default for f in every) + ["FACTORY"] * any(f.factory for f in every)
    used += ["MISSING"] + ["FieldSpec"] * any(f.declared.startswith("FieldSpec") for f in every)
    out = [
        f'"""The methods of the frozen dataclasses of {relative}, written out ahead of time (why: rdisc/frozen.py).',
        "",
        "Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after",
        "changing a class's fields (a test holds this file equal to what it writes).",
        '"""',
        "",
        "from __future__ import annotations",
        "",
        "from rdisc import TYPE_CHECKING",
        f"from rdisc.frozen import {', '.join(used)}, Written, classes, field",
        "",
        "if TYPE_CHECKING:",
        "    from typing import Any",
        "",
        '__all__ = ["dataclass", "field"]',
        "",
        "# Each field's setter, `_set_<class>_<field>(instance, value)`: its slot's own `__set__`, bound by",
        "# rdisc.frozen when it makes the class (a third faster than object.__setattr__ with the field's name).",
        "_unbound: Any = None",
    ]
    for name, fields in classes:
        out += ["", "", *_methods(name, fields)]
    out += ["", "", "WRITTEN: dict[str, Written] = {"]
    for name, fields in classes:
        declared = [f'("{f.name}", {f.declared})' for f in fields]
        methods = [f'"__{m}__": _{m}_{name}' for m in ("init", "repr", "eq", "hash")]
        out += [f'    "{name}": Written(',
                *_wrapped("(", declared, ("," if len(declared) == 1 else "") + "),", "        "),
                *_wrapped("{", methods, "},", "        "),
                "    ),"]
    out += ["}", "dataclass = classes(WRITTEN)", ""]
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m rdisc.frozen_writer", description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="only say which written modules are stale (exit 1)")
    args = parser.parse_args(argv)
    stale = 0
    for source, target in MODULES.items():
        text = write(PACKAGE / source)
        path = PACKAGE / target
        if path.is_file() and path.read_text(encoding="utf-8") == text:
            continue
        stale += 1
        if args.check:
            print(f"{path} is stale: run python -m rdisc.frozen_writer", file=sys.stderr)
        else:
            path.write_text(text, encoding="utf-8", newline="\n")
            print(f"wrote {path}")
    return 1 if stale and args.check else 0


if __name__ == "__main__":
    sys.exit(main())
