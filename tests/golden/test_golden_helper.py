"""The golden helper: compares by default, rewrites only under --update-goldens."""

from __future__ import annotations

from pathlib import Path

import pytest


def test_equal_output_passes(golden, tmp_path: Path) -> None:
    path = tmp_path / "out.txt"
    path.write_bytes("same ✓\n".encode())
    type(golden)(update=False).check(path, "same ✓\n")


def test_different_output_fails_with_a_diff_and_leaves_the_file(golden, tmp_path: Path) -> None:
    path = tmp_path / "out.txt"
    path.write_text("line one\nline two\n", encoding="utf-8")
    with pytest.raises(pytest.fail.Exception) as failure:
        type(golden)(update=False).check(path, "line one\nline 2\n")
    assert "--update-goldens" in str(failure.value)
    assert "-line two\n+line 2" in str(failure.value)
    assert path.read_text(encoding="utf-8") == "line one\nline two\n"


def test_missing_golden_fails_and_is_not_created(golden, tmp_path: Path) -> None:
    path = tmp_path / "new.txt"
    with pytest.raises(pytest.fail.Exception, match="does not exist"):
        type(golden)(update=False).check(path, "anything\n")
    assert not path.exists()


def test_update_rewrites_byte_for_byte(golden, tmp_path: Path) -> None:
    path = tmp_path / "deeper" / "out.txt"
    updating = type(golden)(update=True)
    updating.check(path, "new\r\ncontent é\n")  # no newline translation
    assert path.read_bytes() == "new\r\ncontent é\n".encode()
    updating.check(path, "newer\n")
    assert path.read_bytes() == b"newer\n"
    type(golden)(update=False).check(path, "newer\n")


def test_a_trailing_newline_matters(golden, tmp_path: Path) -> None:
    path = tmp_path / "out.txt"
    path.write_bytes(b"text\n")
    with pytest.raises(pytest.fail.Exception):
        type(golden)(update=False).check(path, "text")


def test_the_session_helper_compares_unless_the_flag_is_given(golden, pytestconfig: pytest.Config) -> None:
    assert golden.update is pytestconfig.getoption("--update-goldens")
