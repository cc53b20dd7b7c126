"""A file's name reaches generated code only escaped: a driver or a ROS node generated from a
description under any name (a CR, an LF, a NUL, U+2028, quotes, triple quotes, a backslash)
parses to the same statements as under a plain name, and importing it runs nothing the name
says."""

from __future__ import annotations

import ast
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import fuzz_examples, run_rdisc
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.compile import compile_path
from rdisc.emit.python import to_python
from rdisc.emit.ros import to_ros

REPO = Path(__file__).resolve().parents[2]
CREATE = REPO / "examples" / "create.rdis"
PLAIN = "create.rdis"
PAYLOAD = 'import pathlib; pathlib.Path("PWNED").write_text("ran") #'

HOSTILE = [
    f"x\r{PAYLOAD}.rdis",
    f"x\n{PAYLOAD}.rdis",
    f"x\r\n{PAYLOAD}.rdis",
    f"x\x00{PAYLOAD}.rdis",
    "x\u2028y\u2029z\x85w.rdis",
    'x"""; import os #.rdis',
    "x'''\\\".rdis",
    "x\\.rdis",
    "x\x0c\x0b\x1b[31m.rdis",
]


def _statements(source: str) -> object:
    """The module's statements with every string constant blanked: what the name may change."""
    return _shape(ast.parse(source))


def _shape(node: object) -> object:
    """A node as nested tuples, each its class's name and all its fields (not its place), string
    constants blanked: what `ast.dump` shows of the tree, made in one walk (the driver's 100,000
    nodes went through `ast.walk` and `ast.dump`, seconds a name)."""
    if isinstance(node, ast.AST):
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return ("Constant", "", node.kind)
        return (type(node).__name__, *[_shape(getattr(node, field, None)) for field in node._fields])
    if isinstance(node, list):
        return [_shape(item) for item in node]
    return node


@pytest.fixture(scope="module")
def model():  # type: ignore[no-untyped-def]
    compilation = compile_path(str(CREATE))
    assert compilation.model is not None
    return compilation.model


@pytest.fixture(scope="module")
def plain(model) -> dict[str, object]:  # type: ignore[no-untyped-def]
    return {"driver": _statements(to_python(model, PLAIN)), "node": _statements(to_ros(model, PLAIN))}


@pytest.mark.parametrize("name", HOSTILE, ids=[repr(n)[:24] for n in HOSTILE])
def test_a_hostile_name_changes_no_statement(model, plain: dict[str, object], name: str) -> None:  # type: ignore[no-untyped-def]
    assert _statements(to_python(model, name)) == plain["driver"]
    assert _statements(to_ros(model, name)) == plain["node"]


@settings(max_examples=fuzz_examples(10), deadline=None)
@given(st.text(min_size=1, max_size=40))
def test_any_name_changes_no_statement(model, plain: dict[str, object], name: str) -> None:  # type: ignore[no-untyped-def]
    assert _statements(to_python(model, name + ".rdis")) == plain["driver"]


def test_a_driver_named_with_a_carriage_return_runs_nothing_on_import(tmp_path: Path) -> None:
    """The finding: `x\\rimport ...#.rdis` put its statement into the driver, which ran on import."""
    name = f"x\r{PAYLOAD}.rdis"
    source = tmp_path / name
    shutil.copy(CREATE, source)
    result = run_rdisc("emit-python", source, "-o", tmp_path / "create_driver.py")
    assert result.returncode == 0, result.stderr
    imported = subprocess.run([sys.executable, "-c", "import create_driver"], cwd=tmp_path, capture_output=True,
                              text=True, check=False)
    assert imported.returncode == 0, imported.stderr
    assert not (tmp_path / "PWNED").exists()
