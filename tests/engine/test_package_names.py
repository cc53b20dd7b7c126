"""The engine package imports its modules when a name of theirs is first asked for: the checker
needs `rdisc.engine.operations` and no more of the engine, and `rdisc.engine.X` is still
every public name, the very object its module defines."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import rdisc.engine

ROOT = Path(__file__).resolve().parents[2]


def declared() -> dict[str, str]:
    """Each public name and the module its `if TYPE_CHECKING:` import names."""
    tree = ast.parse(Path(rdisc.engine.__file__).read_text(encoding="utf-8"))
    guard = next(node for node in tree.body if isinstance(node, ast.If))
    return {alias.name: node.module or "" for node in guard.body if isinstance(node, ast.ImportFrom)
            for alias in node.names}


def test_every_public_name_is_the_object_its_module_defines() -> None:
    names = declared()
    assert sorted(names) == sorted(rdisc.engine.__all__)
    for name, module in names.items():
        assert getattr(rdisc.engine, name) is getattr(sys.modules[module], name), name


def test_checking_a_description_imports_only_the_operations_of_the_engine() -> None:
    code = ("import sys\nfrom rdisc.compile import compile_path\n"
            f"assert not compile_path({str(ROOT / 'examples' / 'create.rdis')!r}).diagnostics.has_errors()\n"
            "print(sorted(name for name in sys.modules if name.startswith('rdisc.engine')))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert done.stdout.split("\n")[0] == "['rdisc.engine', 'rdisc.engine.operations']"


def test_an_unknown_name_is_an_attribute_error() -> None:
    try:
        rdisc.engine.no_such_name  # type: ignore[attr-defined]  # noqa: B018
    except AttributeError as err:
        assert "no_such_name" in str(err)
    else:
        raise AssertionError("no AttributeError")
