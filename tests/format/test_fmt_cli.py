"""`rdisc fmt`: in place; --check fails with a diff; `-` filters; a file that does not parse: exit 2."""

from __future__ import annotations

import io
import os
from pathlib import Path

import pytest
from conftest import run_rdisc

from rdisc.cli.main import main

MESSY = 'state   count:int=0  # how many\nconnection bus: serial {\n baud 9600 }\n'
TIDY = 'state count: int = 0  # how many\nconnection bus: serial {\n    baud 9600\n}\n'


def test_files_are_formatted_in_place_and_a_formatted_file_is_left_alone(tmp_path: Path) -> None:
    messy, tidy = tmp_path / "messy.rdis", tmp_path / "tidy.rdis"
    messy.write_text(MESSY)
    tidy.write_text(TIDY)
    before = tidy.stat().st_mtime_ns
    result = run_rdisc("fmt", messy, tidy)
    assert (result.returncode, result.stdout) == (0, "")
    assert result.stderr == "rdisc fmt: 1 file reformatted, 1 unchanged\n"
    assert messy.read_text() == TIDY
    assert tidy.stat().st_mtime_ns == before


def test_check_exits_1_with_a_unified_diff_and_writes_nothing(tmp_path: Path) -> None:
    messy = tmp_path / "messy.rdis"
    messy.write_text(MESSY)
    result = run_rdisc("fmt", "--check", tmp_path)
    assert result.returncode == 1
    assert result.stdout == (
        f"--- {messy}\n+++ {messy}\n@@ -1,3 +1,4 @@\n"
        "-state   count:int=0  # how many\n+state count: int = 0  # how many\n connection bus: serial {\n"
        "- baud 9600 }\n+    baud 9600\n+}\n"
    )
    assert messy.read_text() == MESSY
    messy.write_text(TIDY)
    assert (run_rdisc("fmt", "--check", messy).returncode, run_rdisc("fmt", "--check", messy).stdout) == (0, "")


def test_diff_shows_the_change_exits_0_and_writes_nothing(tmp_path: Path) -> None:
    messy = tmp_path / "messy.rdis"
    messy.write_text(MESSY)
    result = run_rdisc("fmt", "--diff", messy)
    assert result.returncode == 0 and "+state count: int = 0  # how many\n" in result.stdout
    assert messy.read_text() == MESSY


def test_a_file_that_does_not_parse_gets_its_diagnostics_and_exit_2(tmp_path: Path) -> None:
    bad, messy = tmp_path / "bad.rdis", tmp_path / "messy.rdis"
    bad.write_text("state x: int =\n")
    messy.write_text(MESSY)
    result = run_rdisc("fmt", bad, messy)
    assert result.returncode == 2
    assert "error[E001]" in result.stderr and f"{bad}:2:1" in result.stderr
    assert "Traceback" not in result.stderr
    assert result.stderr.endswith("rdisc fmt: 1 file reformatted, 0 unchanged, 1 not formatted\n")
    assert bad.read_text() == "state x: int =\n"
    assert messy.read_text() == TIDY  # the others are still formatted


def test_a_missing_file_is_said_as_check_says_it(tmp_path: Path) -> None:
    result = run_rdisc("fmt", tmp_path / "none.rdis")
    assert result.returncode == 2
    assert result.stderr.startswith(f"error[E006]: cannot read {tmp_path / 'none.rdis'}: No such file or directory\n")


def test_a_dash_formats_standard_input_to_standard_output(monkeypatch: pytest.MonkeyPatch,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setattr("sys.stdin", io.StringIO(MESSY))
    assert main(["fmt", "-"]) == 0
    assert capsys.readouterr() == (TIDY, "")
    monkeypatch.setattr("sys.stdin", io.StringIO(MESSY))
    assert main(["fmt", "--check", "-"]) == 1
    assert capsys.readouterr().out.startswith("--- <stdin>\n+++ <stdin>\n")


def test_a_clean_check_does_not_import_the_formatter() -> None:
    probe = ("import sys; from rdisc.cli.main import main; main(['check', 'examples/create.rdis']); "
             "print(sorted(name for name in sys.modules if name.startswith('rdisc.format')))")
    import subprocess
    import sys

    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                            cwd=Path(__file__).resolve().parents[2], check=False)
    assert result.stdout == "[]\n", result.stderr


def test_a_json_description_is_not_formatted(tmp_path: Path) -> None:
    described = tmp_path / "robot.json"
    described.write_text("{}")
    result = run_rdisc("fmt", described)
    said = f"rdisc fmt: {described} is JSON; only .rdis descriptions are formatted\n"
    assert (result.returncode, result.stderr) == (2, said + "rdisc fmt: 0 files reformatted, 0 unchanged, 1 not formatted\n")
    assert described.read_text() == "{}"


def test_a_fifo_is_refused_unread_as_check_refuses_it(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.rdis"
    os.mkfifo(fifo)
    result = run_rdisc("fmt", fifo)
    assert result.returncode == 2
    assert result.stderr.startswith(f"error[E006]: cannot read {fifo}: not a regular file\n")


def test_a_description_past_the_token_budget_is_refused_as_check_refuses_it(tmp_path: Path) -> None:
    messy = tmp_path / "messy.rdis"
    messy.write_text(MESSY)
    result = run_rdisc("fmt", "--max-tokens", "5", messy)
    assert result.returncode == 2
    assert result.stderr.startswith("error[E005]: the description has more than 5 tokens, with its imports")
    assert messy.read_text() == MESSY
