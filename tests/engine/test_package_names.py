"""The engine package imports its modules when a name of theirs is first asked for: `rdisc
check` needs the engine's operations and signal handlers and no more of it, and
`rdisc.engine.X` is still every public name, the very object its module defines
(tests/engine/test_carried.py)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import rdisc.engine

ROOT = Path(__file__).resolve().parents[2]


def test_rdisc_check_imports_only_the_operations_and_signals_of_the_engine() -> None:
    """`rdisc check`, from its entry point: the checker's operations, and the handlers of
    SIGINT and SIGTERM every verb runs under (not the robot, its ports, recording, ...)."""
    code = ("import sys\nimport rdisc.start\nfrom rdisc.start import main\n"
            "rdisc.start.end_at_once = lambda status: None\n"  # `check` ends without teardown: print first
            f"sys.argv = ['rdisc', 'check', {str(ROOT / 'examples' / 'create.rdis')!r}]\n"
            "status = main()\n"
            "print(status, sorted(name for name in sys.modules if name.startswith('rdisc.engine')))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert done.stdout.split("\n")[0] == "0 ['rdisc.engine', 'rdisc.engine.operations', 'rdisc.engine.signals']"


def test_an_unknown_name_is_an_attribute_error() -> None:
    try:
        rdisc.engine.no_such_name  # type: ignore[attr-defined]  # noqa: B018
    except AttributeError as err:
        assert "no_such_name" in str(err)
    else:
        raise AssertionError("no AttributeError")
