"""The engine's modules form a line: each imports only modules before it in the listed order
(`rdisc/engine/carry.py`), so none needs itself through others. Read from their text with
`ast`, every import counted: at the top, under `if TYPE_CHECKING:`, inside a function.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from rdisc.engine import carry

ORDER = [module for module, _ in carry.MODULES]


def _imported(folder: Path, text: str) -> set[str]:
    """The engine's modules a module's text imports, anywhere in it (`__init__`: the package itself)."""
    found: set[str] = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Import):
            sources = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            source = "rdisc.engine." * (node.level == 1) + (node.module or "")
            # from rdisc.engine import wire: a module; from rdisc.engine import Robot: the package
            sources = [f"rdisc.engine.{alias.name}" if (folder / f"{alias.name}.py").is_file() else "rdisc.engine"
                       for alias in node.names] if source.rstrip(".") == "rdisc.engine" else [source]
        else:
            continue
        for source in sources:
            parts = source.split(".")
            if parts[:2] == ["rdisc", "engine"]:
                found.add(parts[2] if len(parts) > 2 else "__init__")
    return found


def graph(folder: Path = carry.FOLDER) -> dict[str, set[str]]:
    """Each module of the engine (its `__init__` too) and the engine's other modules it imports."""
    return {path.stem: _imported(folder, path.read_text(encoding="utf-8")) - {path.stem}
            for path in sorted(folder.glob("*.py"))}


def circle(edges: dict[str, set[str]]) -> list[str] | None:
    """A circle of imports (its modules in order, the first again at the end), or None."""
    done: set[str] = set()
    path: list[str] = []

    def visit(module: str) -> list[str] | None:
        if module in path:
            return [*path[path.index(module):], module]
        if module in done:
            return None
        path.append(module)
        for needed in sorted(edges.get(module, ())):
            found = visit(needed)
            if found is not None:
                return found
        path.pop()
        done.add(module)
        return None

    for module in sorted(edges):
        found = visit(module)
        if found is not None:
            return found
    return None


def test_no_circle_among_the_engine_modules_imports() -> None:
    found = circle(graph())
    assert found is None, f"the engine's modules import in a circle: {' -> '.join(found or ())}"


def test_every_import_of_a_module_goes_down_the_listed_order() -> None:
    """Its head's imports (tests/engine/test_carried.py), and those for type checking or inside a function."""
    for module, needed in graph().items():
        if module in ORDER:
            for other in needed:
                assert other in ORDER and ORDER.index(other) < ORDER.index(module), f"{module} imports {other}"


@pytest.mark.parametrize(("edges", "expected"), [
    ({"a": {"b"}, "b": set()}, None),
    ({"a": {"b", "c"}, "b": {"c"}, "c": set()}, None),
    ({"a": {"b"}, "b": {"a"}}, ["a", "b", "a"]),
    ({"a": {"b"}, "b": {"c"}, "c": {"b"}}, ["b", "c", "b"]),
])
def test_the_circle_finder_finds_a_circle_and_no_other(edges: dict[str, set[str]], expected: list[str] | None) -> None:
    assert circle(edges) == expected


def test_the_reader_counts_imports_for_type_checking_and_inside_functions(tmp_path: Path) -> None:
    (tmp_path / "wire.py").write_text("", encoding="utf-8")
    (tmp_path / "low.py").write_text(
        "from typing import TYPE_CHECKING\n"
        "if TYPE_CHECKING:\n    from rdisc.engine.high import High\n"
        "def late():\n    import rdisc.engine.other\n    from rdisc.engine import wire, Robot\n"
        "    from .near import x\n", encoding="utf-8")
    assert graph(tmp_path) == {"low": {"high", "other", "wire", "__init__", "near"}, "wire": set()}
