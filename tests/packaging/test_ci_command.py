"""`.ci/run` runs the README's test command verbatim, and that command installs what the
tests need: the test extra, then the published drivers without their dependencies."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def readme_test_command() -> str:
    """The one line of the README's code block that runs pytest."""
    blocks = re.findall(r"```sh\n(.*?)```", (ROOT / "README.md").read_text(encoding="utf-8"), re.DOTALL)
    lines = [line for block in blocks for line in block.splitlines() if "pytest" in line]
    assert len(lines) == 1, lines
    return lines[0]


def test_the_readme_test_command_installs_the_drivers_without_their_dependencies() -> None:
    command = readme_test_command()
    assert command.startswith("pip install '.[test]' && ")
    assert "pip install --no-deps -r tests/published-drivers.txt" in command
    assert (ROOT / "tests" / "published-drivers.txt").is_file()


def test_ci_runs_the_readme_test_command_verbatim() -> None:
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert f"\n{readme_test_command()} || status=$?\n" in ci


def test_ci_installs_the_npm_packages_the_textmate_grammars_tests_run_on() -> None:
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert "\nnpm ci --prefix tests/editor --no-audit --no-fund\n" in ci
    assert (ROOT / "tests" / "editor" / "package-lock.json").is_file()  # what `npm ci` installs, exactly


def test_ci_installs_code_server_and_the_extensions_client_the_vscode_test_runs() -> None:
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert ("\nnpm ci --prefix tests/vscode --ignore-scripts --no-audit --no-fund\n"
            "npm run --prefix tests/vscode natives\n"
            "npm ci --prefix editors/vscode --omit=dev --no-audit --no-fund\n") in ci
    for folder in ("tests/vscode", "editors/vscode"):
        assert (ROOT / folder / "package-lock.json").is_file()  # what `npm ci` installs, exactly
    assert (ROOT / "tests" / "vscode" / "natives.sh").is_file()
