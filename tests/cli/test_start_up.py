"""`rdisc check` of a clean description imports only what checking needs (start-up time is
most of a check of a small file): not Lark (the parser's tables are written ahead of time),
nor pathlib, json or difflib, which only imports, `--format json` and misspellings need."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NOT_NEEDED = ("lark", "pathlib", "json", "difflib")


def imported_by_check(*args: str) -> list[str]:
    probe = ("import sys; from rdisc.cli.main import main; status = main(sys.argv[1:]); "
             f"print(status, sorted(name for name in sys.modules if name.partition('.')[0] in {NOT_NEEDED!r}), "
             "file=sys.stderr)")
    done = subprocess.run([sys.executable, "-c", probe, *args], capture_output=True, text=True, check=True)
    return done.stderr.splitlines()[-1].split(maxsplit=1)


def test_a_clean_check_imports_neither_lark_nor_what_only_other_paths_need() -> None:
    assert imported_by_check("check", str(ROOT / "examples" / "create.rdis")) == ["0", "[]"]


def test_a_check_in_json_imports_json() -> None:
    status, names = imported_by_check("check", "--format", "json", str(ROOT / "examples" / "create.rdis"))
    assert status == "0" and "'json'" in names
