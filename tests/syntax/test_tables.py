"""The parser's tables written ahead of time (rdisc/syntax/tables.py) are what Lark makes of the
grammar now, and a check of a clean description runs on them alone: Lark is not imported."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from rdisc.syntax import tables_writer

ROOT = Path(__file__).resolve().parents[2]


def test_the_written_tables_are_what_lark_makes_of_the_grammar() -> None:
    assert tables_writer.TARGET.read_text(encoding="utf-8") == tables_writer.write()
    assert tables_writer.main(["--check"]) == 0


def test_the_written_tables_do_not_depend_on_the_interpreter(tmp_path: Path) -> None:
    """Lark numbers its states by sets hashed by identity: each interpreter its own way. The writer
    numbers them itself, so two interpreters with other hash seeds, each building Lark's parser
    afresh (an empty cache folder each), write the same text: the committed one."""
    probe = "import sys; from rdisc.syntax import tables_writer; sys.stdout.write(tables_writer.write())"
    texts = []
    for seed in ("1", "2"):
        (tmp_path / seed).mkdir()
        env = {**os.environ, "PYTHONHASHSEED": seed, "TMPDIR": str(tmp_path / seed)}
        texts.append(subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True,
                                    encoding="utf-8", check=True).stdout)
        assert [path.name.startswith(".lark_cache") for path in (tmp_path / seed).iterdir()] == [True]
    assert texts[0] == texts[1] == tables_writer.TARGET.read_text(encoding="utf-8")


def test_checking_a_clean_description_imports_neither_lark_nor_the_grammar() -> None:
    probe = ("import sys; from rdisc.compile import compile_path; compile_path(sys.argv[1]); "
             "print(sorted(name for name in sys.modules if name.partition('.')[0] == 'lark'))")
    done = subprocess.run([sys.executable, "-c", probe, str(ROOT / "examples" / "create.rdis")],
                          capture_output=True, text=True, check=True)
    assert done.stdout == "[]\n"


def test_a_declaration_with_a_syntax_error_is_still_parsed_by_lark() -> None:
    probe = ("import sys; from rdisc.diagnostics import Diagnostics; from rdisc.syntax.parse import parse; "
             "d = Diagnostics(); parse('t.rdis', 'state s: int = (1', d); "
             "print([x.code for x in d.sorted()], 'lark' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert done.stdout == "['E001'] True\n"
