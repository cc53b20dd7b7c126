"""One writing of each operation (rdisc.engine.operations): the checker's constant folding, the
runtime and a generated driver refuse the same expression with the same message. Each rule here
had a copy of its own in each of them before (the float overflow six), and the copies said it
differently; now a driver carries the module's text and calls its functions."""

from __future__ import annotations

import ast
import math
import struct
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path
from rdisc.emit.python_support import engine_text
from rdisc.engine import carry, operations
from tests.engine.test_one_engine import ScriptedPort, implementation_of

# (parameters, expression, arguments, pack code, what each of the three says)
CASES: list[tuple[str, str, tuple[Any, ...], str, str]] = [
    ("x: float, y: float", "x * y", (1e300, 1e300), "d", "the result is too large for a float"),
    ("x: float, y: float", "x + y", (1.7e308, 1.7e308), "d", "the result is too large for a float"),
    ("x: float, y: float", "x - y", (-1.7e308, 1.7e308), "d", "the result is too large for a float"),
    ("x: float, y: float", "x / y", (1e308, 1e-308), "d", "the result is too large for a float"),
    ("x: int, y: int", "x / y", (1, 0), "d", "division by zero"),
    ("x: float, y: float", "x / y", (1.5, 0.0), "d", "division by zero"),
    ("x: int, y: int", "x // y", (7, 0), "q", "division by zero"),
    ("x: int, y: int", "x % y", (7, 0), "q", "modulo by zero"),
    ("x: int, y: int", "x ** y", (3, 5000), "q", "3 ** 5000 is too large (results are limited to 4096 bits)"),
    ("x: int, y: int", "x ** y", (2, -1), "q", "negative integer exponent -1: write a float base, e.g. 2.0 ** -1"),
    ("x: float, y: float", "x ** y", (-8.0, 0.5), "d", "-8.0 ** 0.5 has no real value"),
    ("x: int, y: int", "x << y", (1, 5000), "q", "1 << 5000 is too large (results are limited to 4096 bits)"),
    ("x: int, y: int", "x >> y", (1, -1), "q", "negative shift count -1"),
    ("x: int, y: int", "x ** 2000 * y ** 2000 > 0", (3, 3), "?",
     "a 3170-bit integer * a 3170-bit integer is too large (results are limited to 4096 bits)"),
    # (a float parameter given NaN or inf is refused before its expression runs: tests/engine/test_finite_values.py;
    # a string's is refused by float(); the bytes of a float, a device's or a caller's, may still hold one)
    ("s: string", "float(s)", ("inf",), "d", "float('inf'): not a finite number"),
    ("s: string", "float(s) * 0.0", ("-1e999",), "d", "float('-1e999'): not a finite number"),
    ("s: string", "clamp(float(s), 0.0, 1.0)", ("nan",), "d", "float('nan'): not a finite number"),
    ("b: bytes", "round(from_f64le(b))", (struct.pack("<d", math.inf),), "q",
     "round(inf): cannot convert float infinity to integer"),
    ("b: bytes", "int(from_f64be(b))", (struct.pack(">d", math.nan),), "q", "int(nan): cannot convert float NaN to integer"),
    ("s: string", "int(s)", ("0xzz",), "q", "int('0xzz'): invalid literal for int() with base 0: '0xzz'"),
    ("s: string", "float(s)", ("one",), "d", "float('one'): could not convert string to float: 'one'"),
    ("x: float", "sqrt(x)", (-1.0,), "d", "sqrt(-1.0): outside the function's domain"),
    ("b: bytes, i: int", "byte(b, i)", (b"\x01", 3), "B", "byte 3 of 1 bytes: no such byte"),
]


def _literal(value: Any) -> str:
    """`value` as RDIS writes it in a constant expression."""
    if isinstance(value, float) and not math.isfinite(value):
        return f'float("{value}")'
    if isinstance(value, bytes):
        return 'b"' + "".join(f"\\x{b:02x}" for b in value) + '"'
    if isinstance(value, str):
        return f'"{value}"'
    return f"({value!r})" if value < 0 else repr(value)


def _folded(params: str, expr: str, args: tuple[Any, ...]) -> str:
    """`expr` with each parameter written as the constant it is given."""
    names = [p.split(":")[0].strip() for p in params.split(",")]
    tree = ast.parse(expr, mode="eval")
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and node.id in names:
            node.id = _literal(args[names.index(node.id)])
    return ast.unparse(tree).replace("'", '"')


DESCRIPTION = 'robot ops { author "tests" }\nconnection link: serial { baud 9600 }\n' + "".join(
    f'primitive case_{n}({params}) on link pack "<{code}" ({expr})\n'
    for n, (params, expr, _, code, _) in enumerate(CASES)
)


@pytest.fixture(scope="module")
def both(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    folder = tmp_path_factory.mktemp("operations")
    return {kind: implementation_of(kind, DESCRIPTION, folder, "ops") for kind in ("runtime", "driver")}


@pytest.mark.parametrize("number", range(len(CASES)), ids=[case[1] for case in CASES])
def test_folding_the_runtime_and_a_driver_refuse_alike(number: int, both: dict[str, Any], tmp_path: Path) -> None:
    params, expr, args, code, message = CASES[number]
    source = tmp_path / "folded.rdis"
    source.write_text('robot folded { author "tests" }\nconnection link: serial { baud 9600 }\n'
                      f'primitive p() on link pack "<{code}" ({_folded(params, expr, args)})\n', encoding="utf-8")
    assert [(d.code, d.message) for d in compile_path(str(source)).diagnostics.items] == [("E405", message)]
    for kind, implementation in both.items():
        port = ScriptedPort()
        with implementation.connect({"link": port}, threads=False) as robot, pytest.raises(ValueError) as caught:
            robot.call_primitive(f"case_{number}", *args)
        assert (kind, type(caught.value).__name__, str(caught.value)) == (
            kind, "RdisValueError", f"case_{number}: {message}")
        assert port.written == b""


def test_a_driver_carries_the_operations_once_and_needs_no_import_of_its_own(both: dict[str, Any]) -> None:
    text = Path(both["driver"].__file__).read_text(encoding="utf-8")
    assert text.count(carried_text()) == 1
    source = Path(operations.__file__).read_text(encoding="utf-8")
    assert _imported(source) <= _imported(engine_text())
    assert not any(module.startswith("rdisc") for module, _ in _imported(source))


def _imported(text: str) -> set[tuple[str, str]]:
    """(module, name) of each import at the top level of a module's text."""
    found: set[tuple[str, str]] = set()
    for node in ast.parse(text).body:
        if isinstance(node, ast.Import):
            found |= {(alias.name, "") for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            found |= {(node.module or "", alias.name) for alias in node.names}
    return found


def carried_text() -> str:
    """The operations' section of the carried engine: the module's body, as a driver carries it."""
    return next(part for part in carry.sections() if part.module == "operations").body
