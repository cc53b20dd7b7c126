"""docs/language.md is true where a machine can tell: its examples, put together with the
few declarations they refer to, check without a diagnostic, and it names every
diagnostic code, built-in function and catalogue CRC that the checker knows."""

from __future__ import annotations

import re
from pathlib import Path

from rdisc.compile import compile_path
from rdisc.diagnostics.codes import CODES
from rdisc.engine.operations import FUNCTIONS
from rdisc.semantics.frames import CATALOGUE

DOC = Path(__file__).resolve().parents[2] / "docs" / "language.md"

# What the examples refer to without declaring it.
PRELUDE = """
connection bus: serial { baud 1000000 }
connection link: serial { baud 9600 }
connection serial0: serial { baud 115200 }
frame ended { request { payload } reply { payload  terminator "\\xFF" } }
interface startup() { drive(0, 0) }
interface shutdown() { drive(0, 0) }
state error: int = 0
state position: int = 0
state speed: int = 0
state v: int = 0
output moving_now: Hit { hit = moving }
interface poll_all() triggers moving_now { poll() }
input turn: PlanarSpeed -> drive(forward, turn)
"""


def test_the_examples_check_clean(tmp_path: Path) -> None:
    blocks = re.findall(r"```rdis\n(.*?)```", DOC.read_text(encoding="utf-8"), re.DOTALL)
    assert len(blocks) >= 10
    (tmp_path / "servos").mkdir()
    (tmp_path / "servos" / "common.rdis").write_text("const COMMON = 1\n", encoding="utf-8")
    source = tmp_path / "language.rdis"
    source.write_text("\n".join(blocks) + PRELUDE, encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == []


def test_it_names_every_code_function_and_catalogue_crc() -> None:
    text = DOC.read_text(encoding="utf-8")
    words = set(re.findall(r"[A-Za-z0-9_-]+", text))
    assert sorted(c for c in CODES if c not in words) == []
    assert sorted(f for f in FUNCTIONS if f not in words) == []
    assert sorted(c for c in CATALOGUE if c not in words) == []
