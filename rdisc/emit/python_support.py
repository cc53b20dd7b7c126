"""The texts a generated driver carries verbatim: the engine's and the expression operations'.

`rdisc.emit.python` writes the engine's text (`engine_text`) first, then the operations'
(`carried_text`), whose functions the compiled expressions call by name, then the plans.
"""

from __future__ import annotations

import ast
from pathlib import Path

from rdisc.engine import operations


def carried_text() -> str:
    """The text of rdisc.engine.operations after its imports, byte for byte: what every driver
    carries after the engine's text, whose imports it uses (a driver has one block of imports)."""
    text = Path(operations.__file__).read_text(encoding="utf-8")
    imports = [node for node in ast.parse(text).body if isinstance(node, (ast.Import, ast.ImportFrom))]
    lines = text.splitlines(keepends=True)
    return "".join(lines[imports[-1].end_lineno or 0 :]).strip("\n")


def engine_text() -> str:
    """The text of rdisc.runtime.engine from its `from __future__` line to its end: what
    every driver carries, byte for byte."""
    from rdisc.runtime import engine

    text = Path(engine.__file__).read_text(encoding="utf-8")
    return text[text.index("from __future__ import annotations") :].rstrip("\n")
