"""rdisc's parts form a line, data flowing one way: each part (a package or a module directly
under rdisc/) imports only parts before it in LAYERS, so no import runs up or sideways and
none needs itself through others. Read from the text with `ast`, every import counted: at the
top, under `if TYPE_CHECKING:`, inside a function. (The engine's own modules form a line of
their own: tests/engine/test_imports.py.)
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1] / "rdisc"

LAYERS = [
    "engine",  # the run-time semantics: the standard library and pyserial only
    "frozen", "patterns", "resources", "limits",
    "regex_shape",  # what a regex's matches begin with, and which take more than linear time
    "source_methods", "source",
    "recordings", "capture",  # a recording read back; captured traffic
    "diagnostics",
    "syntax",  # text -> AST
    "semantics",  # AST -> Model
    "json_import", "compile",  # JSON -> AST; the pipeline to the Model
    "lowering", "lower",  # Model -> plans
    "highlight", "format",
    "emit",  # plans and Model -> outputs
    "sim", "runtime",
    "console", "editor",
    "cli", "start", "__main__",
]
"""Bottom first. `frozen_writer` and `__init__` stand apart (no other part imports them); `__version__` and
`TYPE_CHECKING` (typing's, without importing typing) are the package's own attributes."""
APART = {"__init__", "__version__", "TYPE_CHECKING", "frozen_writer"}


def part_of(path: Path, root: Path) -> str:
    first = path.relative_to(root).parts[0]
    return first.removesuffix(".py")


def imported_parts(path: Path, root: Path) -> set[str]:
    """The parts of rdisc a module's text imports, anywhere in it."""
    package = ("rdisc", *path.relative_to(root).parts[:-1])
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            sources = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = ".".join(package[:len(package) - node.level + 1]) if node.level else ""
            module = ".".join(part for part in (base, node.module) if part)
            sources = [f"{module}.{alias.name}" for alias in node.names] if module == "rdisc" else [module]
        else:
            continue
        for source in sources:
            names = source.split(".")
            if names[0] == "rdisc" and len(names) > 1:
                found.add(names[1])
    return found


def graph(root: Path = ROOT) -> dict[str, set[str]]:
    """Each part and the other parts its modules import."""
    edges: dict[str, set[str]] = {}
    for path in sorted(root.rglob("*.py")):
        part = part_of(path, root)
        edges.setdefault(part, set()).update(imported_parts(path, root) - {part})
    return edges


@pytest.fixture(scope="module")
def rdisc_graph() -> dict[str, set[str]]:
    """rdisc's graph, read once (every module parsed: about 2.5 s)."""
    return graph()


def test_every_part_is_placed(rdisc_graph: dict[str, set[str]]) -> None:
    assert set(rdisc_graph) - APART == set(LAYERS)


@pytest.mark.parametrize("part", LAYERS)
def test_a_part_imports_only_parts_below_it(rdisc_graph: dict[str, set[str]], part: str) -> None:
    below = set(LAYERS[:LAYERS.index(part)])
    assert rdisc_graph[part] - below - APART == set()


def test_the_reader_sees_every_kind_of_import(tmp_path: Path) -> None:
    (tmp_path / "low.py").write_text("", encoding="utf-8")
    (tmp_path / "high").mkdir()
    (tmp_path / "high" / "view.py").write_text(
        "from typing import TYPE_CHECKING\n"
        "if TYPE_CHECKING:\n    from rdisc.top import Top\n"
        "def late():\n    import rdisc.middle.part\n    from rdisc import low\n"
        "    from ..side import x\n    from . import near\n", encoding="utf-8")
    assert graph(tmp_path) == {"high": {"top", "middle", "low", "side"}, "low": set()}
