"""`rdisc check` of a clean description imports only what checking needs (start-up time is
most of a check of a small file): not Lark (the parser's tables are written ahead of time),
nor pathlib, json or difflib, which only imports, `--format json` and misspellings need, nor
pygls and lsprotocol, which only `rdisc lsp` needs, nor the `importlib` package (a verb's module is
imported with `__import__`), nor `typing`, which only the type checker needs (`TYPE_CHECKING` comes
from `rdisc` and `rdisc.engine`)."""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

import pytest

from rdisc.cli.main import parser

ROOT = Path(__file__).resolve().parents[2]
NOT_NEEDED = ("lark", "pathlib", "json", "difflib", "pygls", "lsprotocol", "importlib", "typing")


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


def entry(*args: str) -> subprocess.CompletedProcess[str]:
    """The `rdisc` entry (rdisc.start) run with `args`, in a process with an exit handler of its own."""
    probe = ("import atexit, sys; atexit.register(lambda: print('torn down', file=sys.stderr)); "
             "sys.argv = ['rdisc', *sys.argv[1:]]; from rdisc.start import main; sys.exit(main())")
    return subprocess.run([sys.executable, "-c", probe, *args], capture_output=True, text=True, check=False)


def test_check_ends_its_process_at_once_with_its_output_written(tmp_path: Path) -> None:
    clean = entry("check", str(ROOT / "examples" / "create.rdis"))
    assert (clean.returncode, clean.stdout, clean.stderr) == (0, "", "")
    bad = tmp_path / "bad.rdis"
    bad.write_text("state x: int = y\n", encoding="utf-8")
    found = entry("check", "--format", "json", str(bad))
    assert found.returncode == 1 and found.stderr == ""
    assert found.stdout.rstrip().endswith("]") and '"E103"' in found.stdout  # all of it written


def test_check_runs_without_the_cyclic_collector() -> None:
    """Its process ends at once: a collection would walk every object the check made, for nothing."""
    probe = ("import gc, sys; import rdisc.start; passes = []; "
             "gc.callbacks.append(lambda phase, info: passes.append(info) if phase == 'start' else None); "
             "rdisc.start.end_at_once = lambda status: print(len(passes), gc.isenabled(), file=sys.stderr); "
             "sys.argv = ['rdisc', *sys.argv[1:]]; rdisc.start.main()")
    done = subprocess.run([sys.executable, "-c", probe, "check", str(ROOT / "examples" / "create.rdis")],
                          capture_output=True, text=True, check=True)
    assert done.stderr == "0 False\n"


def test_other_verbs_are_torn_down_as_usual() -> None:
    done = entry("explain", "E103")
    assert done.returncode == 0 and done.stderr == "torn down\n"


def test_a_clean_check_does_not_import_dataclasses() -> None:
    """`dataclasses` imports `inspect` (with `dis`, `ast` and `tokenize`): the classes a check
    makes take their methods from modules written ahead of time (rdisc/frozen.py)."""
    probe = ("import sys; from rdisc.cli.main import main; main(sys.argv[1:]); "
             "print(sorted(name for name in ('dataclasses', 'inspect') if name in sys.modules))")
    done = subprocess.run([sys.executable, "-c", probe, "check", str(ROOT / "examples" / "create.rdis")],
                          capture_output=True, text=True, check=True)
    assert done.stdout == "[]\n"


def test_a_check_imports_the_body_s_rules_only_for_a_description_with_a_body() -> None:
    """Most descriptions have no links, joints or transmissions: their check does without
    rdisc.semantics.body (640 lines), which a description with a body (arm.rdis) still gets."""
    probe = ("import sys; from rdisc.cli.main import main; status = main(sys.argv[1:]); "
             "print(status, 'rdisc.semantics.body' in sys.modules)")
    found = [subprocess.run([sys.executable, "-c", probe, "check", str(ROOT / "examples" / name)],
                            capture_output=True, text=True, check=True).stdout for name in ("create.rdis", "arm.rdis")]
    assert found == ["0 False\n", "0 True\n"]


NOISY = """robot ranger { author "tests" }
state level: int = 0
connection port: serial { baud 9600 }
primitive level() on port pack "B" (1) unpack "B" { level = out[0] }
interface watch() triggers range { level() }
output range: Range {
    distance = level / 1000.0
    noise distance 0.01 "m"
}
"""


def test_a_check_imports_the_rules_of_sensors_and_noise_only_for_a_description_that_has_them(tmp_path) -> None:
    """A description without sensors (koala.rdis) does without rdisc.semantics.sensed, one without
    noise or filters (create.rdis) without rdisc.semantics.check.noise."""
    noisy = tmp_path / "noisy.rdis"
    noisy.write_text(NOISY, encoding="utf-8")
    probe = ("import sys; from rdisc.cli.main import main; status = main(sys.argv[1:]); "
             "print(status, *(name in sys.modules for name in ('rdisc.semantics.sensed', 'rdisc.semantics.check.noise')))")
    found = [subprocess.run([sys.executable, "-c", probe, "check", str(path)], capture_output=True, text=True,
                            check=True).stdout
             for path in (ROOT / "examples" / "koala.rdis", ROOT / "examples" / "create.rdis", noisy)]
    assert found == ["0 False False\n", "0 True False\n", "0 False True\n"]


def test_a_clean_check_does_not_ask_the_terminal_s_width() -> None:
    """argparse's own formatter asks the width (importing shutil, with bz2 and lzma) for each
    argument added; rdisc's asks it only when help or usage is written."""
    probe = ("import sys; from rdisc.cli.main import main; main(sys.argv[1:]); "
             "print(sorted(name for name in ('shutil', 'bz2', 'lzma') if name in sys.modules))")
    done = subprocess.run([sys.executable, "-c", probe, "check", str(ROOT / "examples" / "create.rdis")],
                          capture_output=True, text=True, check=True)
    assert done.stdout == "[]\n"


@pytest.mark.parametrize("columns", ["40", "72", "150"])
@pytest.mark.parametrize("verb", [None, "check", "run", "dump"])
def test_help_is_laid_out_as_argparse_lays_it_out(monkeypatch: pytest.MonkeyPatch, columns: str,
                                                   verb: str | None) -> None:
    """The help and usage rdisc writes are argparse's own, to the terminal's width (COLUMNS)."""
    monkeypatch.setenv("COLUMNS", columns)
    top = parser([] if verb is None else [verb])
    verbs = next(a for a in top._actions if isinstance(a, argparse._SubParsersAction))
    shown = top if verb is None else verbs.choices[verb]
    ours = (shown.format_help(), shown.format_usage())
    shown.formatter_class = argparse.HelpFormatter
    assert ours == (shown.format_help(), shown.format_usage())


def test_a_clean_check_imports_only_what_its_description_needs() -> None:
    """`string` (a `format` primitive's fields), the printer (an expression in a message), the
    table of codes (a diagnostic shown), the regex rules (a `regex` primitive) and the syntax
    errors' descriptions are imported when first needed: together some milliseconds of a cold
    check of create.rdis."""
    probe = ("import sys; from rdisc.cli.main import main; status = main(sys.argv[1:]); print(status, "
             "[name for name in ('string', 'rdisc.syntax.printer', 'rdisc.diagnostics.codes', "
             "'rdisc.regex_shape', 'rdisc.syntax.errors') if name in sys.modules])")
    found = [subprocess.run([sys.executable, "-c", probe, "check", str(ROOT / "examples" / name)],
                            capture_output=True, text=True, check=True).stdout for name in ("create.rdis", "koala.rdis")]
    assert found == ["0 []\n", "0 ['string', 'rdisc.regex_shape']\n"]
