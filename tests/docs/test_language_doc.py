"""docs/language.md is true where a machine can tell: its examples, put together with the
few declarations they refer to, check without a diagnostic; each complete one (a whole
description) checks alone and does what the session under it says, byte for byte; and it names
every diagnostic code, built-in function and catalogue CRC that the checker knows."""

from __future__ import annotations

import ast
import re
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics.codes import CODES
from rdisc.engine import RdisError
from rdisc.engine.operations import FUNCTIONS
from rdisc.runtime import load
from rdisc.semantics.checksums import CATALOGUE
from tests.support.ports import ScriptedPort

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
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "upper.stl").write_bytes(b"")  # the mesh the body's example names (E614)
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


# -- complete examples, run ------------------------------------------------------------------------

SESSION = re.compile(r"```rdis complete\n(.*?)```\n(?:\n?```session\n(.*?)```)?", re.DOTALL)
CALL = re.compile(r"(\w+)\((.*)\)")


def complete_examples() -> list[tuple[str, str, str]]:
    """Each example marked complete (```` ```rdis complete ````): its name (its robot's), its
    text, and the session under it (```` ```session ````), if any."""
    found = []
    for text, session in SESSION.findall(DOC.read_text(encoding="utf-8")):
        name = re.search(r"^robot (\w+)", text, re.MULTILINE)
        assert name is not None, f"a complete example declares its robot:\n{text}"
        found.append((name.group(1), text, session))
    return found


SETTING = re.compile(r"setting (\w+) = (.+)")


def run_session(description: Any, session: str) -> None:
    """A session's calls, each as its lines say: `name(args)` a primitive or interface called with
    these literal arguments, `> HEX` what it writes, `< HEX` what the device answers it, then
    `NAME == VALUE` a state variable after it, or `! ErrorType: message` what it raises. Lines
    `setting NAME = VALUE` connect anew, with those settings, for the calls after them."""
    lines = [line.strip() for line in session.splitlines() if line.strip()]
    runs: list[tuple[dict[str, Any], list[list[str]]]] = [({}, [])]
    for line in lines:
        setting = SETTING.fullmatch(line)
        if setting is not None:
            if runs[-1][1]:
                runs.append(({}, []))
            runs[-1][0][setting.group(1)] = ast.literal_eval(setting.group(2))
        elif CALL.fullmatch(line) is not None:
            runs[-1][1].append([line])
        else:
            assert runs[-1][1], f"a session's line {line!r} comes before any call"
            runs[-1][1][-1].append(line)
    for settings, calls in runs:
        port = ScriptedPort()
        with description.connect(port, threads=False, settings=settings) as robot:
            for call, *said in calls:
                _call(robot, port, call, said)


def _call(robot: Any, port: ScriptedPort, call: str, said: list[str]) -> None:
    """One call of a session, and what its lines say of it."""
    matched = CALL.fullmatch(call)
    assert matched is not None
    writes = "".join(line[1:] for line in said if line.startswith(">")).split()
    port.script = bytes.fromhex("".join(line[1:] for line in said if line.startswith("<")))
    before = len(port.written)
    name, args = matched.group(1), ast.literal_eval(f"({matched.group(2)},)") if matched.group(2) else ()
    run = robot.call_primitive if name in robot.device.primitives else robot.call_interface
    raised = next((line[1:].strip() for line in said if line.startswith("!")), None)
    try:
        run(name, *args)
    except RdisError as err:  # the session says what it raises
        assert f"{type(err).__name__}: {err}" == raised, f"{call}: {err!r}"
    else:
        assert raised is None, f"{call} raised nothing, where the session says {raised}"
    assert port.written[before:].hex(" ").upper().split() == writes, call
    for line in said:
        if "==" in line:
            variable, value = (part.strip() for part in line.split("==", 1))
            assert robot.state[variable] == ast.literal_eval(value), line
        else:
            assert line[:1] in ("<", ">", "!"), f"{call}: a session's line {line!r} says nothing it knows"


@pytest.mark.parametrize(("name", "text", "session"), complete_examples(), ids=[n for n, _, _ in complete_examples()])
def test_a_complete_example_checks_alone_and_runs_its_session(tmp_path: Path, name: str, text: str,
                                                              session: str) -> None:
    source = tmp_path / f"{name}.rdis"
    source.write_text(text, encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == []
    run_session(load(source), session)


# -- the operator table, held to the parser --------------------------------------------------------


def _binary_rows() -> list[list[str]]:
    """The binary operators of the table's rows, loosest first (`a if c else b`, `not`, unary
    operators and `**` left out)."""
    text = DOC.read_text(encoding="utf-8")
    table = text[text.index("| operators (loosest first) |") :].split("\n\n", 1)[0]
    rows = []
    for line in table.splitlines()[2:]:
        cell = line.split(" | ")[0].removeprefix("| ")
        operators = [op.replace("\\|", "|") for op in re.findall(r"`((?:[^`\\]|\\.)+)`", cell)]
        if operators and all(re.fullmatch(r"[=!<>|^&+\-*/%]+|or|and", op) for op in operators) and operators != ["**"]:
            rows.append(operators)
    return rows


def _tree(text: str) -> object:
    """An expression's shape: ("op", left, right) for each binary operation, names as they are."""
    from rdisc.diagnostics import Diagnostics
    from rdisc.syntax import ast as syntax
    from rdisc.syntax.parse import parse_expression

    def shape(e: syntax.Expr) -> object:
        return (e.op, shape(e.left), shape(e.right)) if isinstance(e, syntax.BinOp) else getattr(e, "name", e)

    parsed = parse_expression("doc", text, 0, Diagnostics())
    assert parsed is not None, text
    return shape(parsed)


def test_the_operator_table_is_the_parsers_precedence() -> None:
    """Each row binds tighter than every row above it, and each row's operators group to the
    left, as the parser reads them (`a | b & c` is `a | (b & c)`, `x & 0x0F == 3` is
    `(x & 0x0F) == 3`)."""
    rows = _binary_rows()
    assert rows[:3] == [["or"], ["and"], ["==", "!=", "<", "<=", ">", ">="]] and len(rows) == 9
    for i, looser in enumerate(rows):
        for tighter in rows[i + 1 :]:
            for a in looser:
                for b in tighter:
                    assert _tree(f"x {a} y {b} z") == (a, "x", (b, "y", "z"))
                    assert _tree(f"x {b} y {a} z") == (a, (b, "x", "y"), "z")
        for a in looser:
            for b in looser:
                assert _tree(f"x {a} y {b} z") == (b, (a, "x", "y"), "z")


def test_the_standard_adapter_lists_name_every_standard_adapter() -> None:
    """README's and this page's lists of the standard adapters are stdlib/adapters.rdis's, each
    in its order (JointState was missing from both)."""
    root = DOC.parents[1]
    declared = re.findall(r"^adapter (\w+)", (root / "stdlib" / "adapters.rdis").read_text(encoding="utf-8"),
                          re.MULTILINE)
    for text in (DOC.read_text(encoding="utf-8"), (root / "README.md").read_text(encoding="utf-8")):
        listed = re.search(r"\(`(?:stdlib/adapters\.rdis`: `)?(DifferentialSpeed`[^)]*)\)", text)
        assert listed is not None
        assert re.findall(r"\w+", listed.group(1)) == declared
