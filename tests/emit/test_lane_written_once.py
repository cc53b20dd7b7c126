"""A generated driver's typed method writes a plain command with the engine's own statements
(`rdisc.engine.exchange._lane_write`'s `write_one`, comments and all): the rule of the plain
write (the port's lock, the refusal once closing, a port's failure a typed error) is written once,
in the engine, and the method only names its robot and its primitive's plan its own way."""

from __future__ import annotations

import ast
import re
import textwrap
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.emit.python import to_python

ROOT = Path(__file__).resolve().parents[2]


def _engine_statements() -> str:
    """`write_one`'s statements, read from the engine's file."""
    text = (ROOT / "rdisc" / "engine" / "exchange.py").read_text(encoding="utf-8")
    outer = next(node for node in ast.walk(ast.parse(text))
                 if isinstance(node, ast.FunctionDef) and node.name == "_lane_write")
    inner = next(node for node in outer.body if isinstance(node, ast.FunctionDef) and node.name == "write_one")
    return textwrap.dedent("\n".join(text.split("\n")[inner.body[0].lineno - 1 : inner.body[-1].end_lineno]))


def _method_statements(source: str, cls: str, method: str) -> str:
    """The typed method's statements from `acquire()` to the `finally`'s `release()`."""
    node = next(node for node in ast.walk(ast.parse(source)) if isinstance(node, ast.ClassDef) and node.name == cls)
    function = next(item for item in node.body if isinstance(item, ast.FunctionDef) and item.name == method)
    lines = source.split("\n")[function.lineno - 1 : function.end_lineno]
    start = next(n for n, line in enumerate(lines) if line.strip().startswith("acquire()"))
    end = next(n for n, line in enumerate(lines) if line.strip() == "release()")
    return textwrap.dedent("\n".join(lines[start : end + 1]))


@pytest.mark.parametrize(("example", "cls", "method", "robot", "plan"), [
    ("create.rdis", "IrobotCreate", "set_velocity", "self", "_P_DRIVE"),  # (delays made 0: written at once)
    ("ax12.rdis", "Ax12Primitives", "goto_all", "robot", "_P_GOTO_ALL"),
])
def test_the_typed_method_writes_with_the_engine_s_statements(tmp_path: Path, example: str, cls: str, method: str,
                                                              robot: str, plan: str) -> None:
    path = tmp_path / example
    path.write_text(re.sub(r"delay \d+ ms", "delay 0 ms", (ROOT / "examples" / example).read_text(encoding="utf-8")),
                    encoding="utf-8")
    model = compile_path(str(path)).model
    assert model is not None
    expected = re.sub(r"\bplan\b", plan, re.sub(r"\brobot\b", robot, _engine_statements()))
    assert _method_statements(to_python(model, example), cls, method) == expected
