"""How a generated driver carries the engine: its modules' texts, in a listed order, as
marked sections of one module (the way Lark's standalone tool carries Lark).

A module is carried from the end of its head to its end. Its head is its docstring and its
imports: the standard library's, gathered once above the first section, and the engine's
own (those it needs only for type checking included), which the sections make needless.
A module that `rdisc check` imports keeps `typing` out of its run time: its head ends with
`TYPE_CHECKING = False` and `if TYPE_CHECKING:` over the standard library's imports too (gathered
with the others) and over type variables, which the driver carries at the start of the module's body.
Each module comes after every module it imports, so the sections one after the other are
one working module. `names()` is every name that module binds at its top level: the names a
driver's own code must never take. This module itself is not carried.
"""

from __future__ import annotations

import ast
import functools
from dataclasses import dataclass
from pathlib import Path

MODULES = (
    ("errors", "the errors a run raises"),
    ("operations", "values' operations, limits"),
    ("values", "types of values, callbacks"),
    ("checksums", "sums, XORs and CRCs"),
    ("matrices", "small matrices, for filters"),
    ("kalman", "the Kalman filter"),
    ("wire", "a port's input, frames' parts"),
    ("codec", "encoding and decoding"),
    ("frames", "frames written and read"),
    ("actuation", "actuators' limits on commands"),
    ("plans", "what a description specialises"),
    ("arguments", "values given by the host"),
    ("ports", "ports, a simulated device"),
    ("signals", "SIGINT, SIGTERM, exit statuses"),
    ("schedule", "a connection's thread"),
    ("telling", "callbacks told, one at a time"),
    ("replies", "replies read, post-actions run"),
    ("exchange", "writing and reading"),
    ("sensing", "sensors' cached values"),
    ("running", "the plans run"),
    ("robot", "lifecycle and public face"),
    ("recording", "sessions in MCAP"),
    ("command", "the command line"),
)
"""The engine's modules in the order a driver carries them, each with what it holds."""

PACKAGE = "rdisc.engine"
FOLDER = Path(__file__).parent
WIDTH = 100  # a marker's columns, as the driver's other section lines


@dataclass(frozen=True)
class Section:
    """One module as a driver carries it: `body`, its text after its head (`head`, the lines dropped)."""

    module: str
    what: str
    head: str
    body: str
    imports: tuple[ast.Import | ast.ImportFrom, ...]  # the head's standard-library imports

    @property
    def path(self) -> str:
        return f"rdisc/engine/{self.module}.py"

    @property
    def marker(self) -> str:
        return f"# ---- rdisc engine: {self.module} ({self.path}), {self.what} ".ljust(WIDTH, "-")


def _own(node: ast.stmt) -> bool:
    """Whether a statement imports from the engine itself."""
    return isinstance(node, ast.ImportFrom) and (node.module or "").split(".")[:2] == PACKAGE.split(".")


def _type_checking(node: ast.stmt) -> bool:
    """Whether a statement is `if TYPE_CHECKING:` over imports and type variables only."""
    return (isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"
            and not node.orelse and all(isinstance(inner, (ast.Import, ast.ImportFrom)) or _type_variable(inner)
                                        for inner in node.body))


def _type_variable(node: ast.stmt) -> bool:
    """Whether a statement is `Name = TypeVar(...)`."""
    return (isinstance(node, ast.Assign) and isinstance(node.value, ast.Call)
            and isinstance(node.value.func, ast.Name) and node.value.func.id == "TypeVar")


def section(module: str, what: str, text: str) -> Section:
    """A module's text split into its head (its docstring, its imports, `if TYPE_CHECKING:` over
    imports of the engine) and its body. An import of rdisc outside the engine, or a top-level
    import after the head, is refused (ValueError): a driver would carry it."""
    statements = ast.parse(text).body
    end = 0
    imports: list[ast.Import | ast.ImportFrom] = []
    carried: list[str] = []  # the type variables of the head's `if TYPE_CHECKING:`
    for at, node in enumerate(statements):
        if at == 0 and isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):
            pass  # the docstring
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            imports += [_standard(module, node)] if not _own(node) else []
        elif ast.unparse(node) == "TYPE_CHECKING = False":
            pass  # typing's, which the driver imports with the rest of typing's names
        elif isinstance(node, ast.If) and _type_checking(node):
            for inner in node.body:
                if isinstance(inner, (ast.Import, ast.ImportFrom)):
                    imports += [_standard(module, inner)] if not _own(inner) else []
                else:
                    carried.append(ast.get_source_segment(text, inner) or "")
        else:
            break
        end = node.end_lineno or end
    for node in statements:
        if node.lineno > end and (isinstance(node, (ast.Import, ast.ImportFrom))
                                  or (isinstance(node, ast.If) and ast.unparse(node.test) == "TYPE_CHECKING")):
            raise ValueError(f"{module}: line {node.lineno}: an import after the first definition")
    lines = text.split("\n")
    body = "\n\n".join([*carried, "\n".join(lines[end:]).strip("\n")])
    return Section(module, what, "\n".join(lines[:end]), body, tuple(imports))


def _standard(module: str, node: ast.Import | ast.ImportFrom) -> ast.Import | ast.ImportFrom:
    """`node`, an import of the standard library's, or ValueError: a driver would carry it."""
    modules = [node.module or ""] if isinstance(node, ast.ImportFrom) else [a.name for a in node.names]
    if any(name.split(".")[0] == "rdisc" for name in modules):
        raise ValueError(f"{module}: the engine imports nothing of rdisc but itself")
    return node


@functools.cache
def sections() -> tuple[Section, ...]:
    """The engine's modules as a driver carries them, in order."""
    return tuple(section(module, what, (FOLDER / f"{module}.py").read_text(encoding="utf-8"))
                 for module, what in MODULES)


def _kind(name: str) -> tuple[int, str]:
    """isort's order of imported names: constants, then classes, then the others."""
    return (0 if name.isupper() and len(name) > 1 else 1 if name[:1].isupper() else 2), name


def imports() -> str:
    """The standard-library imports of every module's head, gathered once (`TYPE_CHECKING`, which
    only the dropped heads use, left out), in isort's order."""
    straight: set[str] = set()
    froms: dict[str, set[str]] = {}
    bound: dict[str, str] = {}
    for part in sections():
        for node in part.imports:
            source = (node.module or "") if isinstance(node, ast.ImportFrom) else ""
            for alias in node.names:
                name = alias.name if alias.asname is None else f"{alias.name} as {alias.asname}"
                binds = alias.asname or alias.name.split(".")[0]
                if bound.setdefault(binds, f"{source}:{name}") != f"{source}:{name}":
                    raise ValueError(f"{part.module}: {binds} is imported from two places")
                if isinstance(node, ast.Import):
                    straight.add(name)
                elif name != "TYPE_CHECKING":
                    froms.setdefault(source, set()).add(name)
    future = froms.pop("__future__", set())
    out = [f"from __future__ import {', '.join(sorted(future))}", ""] if future else []
    out += [f"import {name}" for name in sorted(straight)]
    out += [f"from {source} import {', '.join(sorted(names, key=_kind))}" for source, names in sorted(froms.items())]
    return "\n".join(out)


@functools.cache
def text() -> str:
    """The engine as a driver carries it: the gathered imports, then each module's body after its marker."""
    sections_text = "\n\n\n".join(f"{part.marker}\n\n\n{part.body}" for part in sections())
    return f"{imports()}\n\n{sections_text}"  # one blank line after imports, as isort has it before a comment


def bound(statements: list[ast.stmt]) -> list[str]:
    """The names statements bind at their own level (not in the functions and classes they
    define), in order, a name bound twice listed twice."""
    names: list[str] = []
    for node in statements:
        match node:
            case ast.FunctionDef(name=name) | ast.AsyncFunctionDef(name=name) | ast.ClassDef(name=name):
                names.append(name)
            case ast.Import(names=aliases) | ast.ImportFrom(names=aliases):
                names += [alias.asname or alias.name.split(".")[0] for alias in aliases]
            case ast.Assign(targets=targets):
                names += [n.id for target in targets for n in ast.walk(target) if isinstance(n, ast.Name)]
            case ast.AnnAssign(target=target) | ast.AugAssign(target=target) if isinstance(target, ast.Name):
                names.append(target.id)
            case ast.If(body=body, orelse=orelse) | ast.For(body=body, orelse=orelse) | \
                    ast.While(body=body, orelse=orelse):
                names += bound(body) + bound(orelse)
            case ast.With(body=body):
                names += bound(body)
            case ast.Try(body=body, handlers=handlers, orelse=orelse, finalbody=final):
                names += bound(body) + bound(orelse) + bound(final)
                for handler in handlers:
                    names += bound(handler.body)
    return names


@functools.cache
def names() -> frozenset[str]:
    """Every name the carried engine binds at its top level, imports included."""
    return frozenset(bound(ast.parse(text()).body))
