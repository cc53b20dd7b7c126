"""`--record FILE` writes a new file: an existing one is refused unless `--force`, and the
description and its imports even then, on every surface that records (`rdisc run`, `rdisc sim`,
`rdisc console`, a generated driver), with exit status 2 and one line saying why."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import REPO, cli_env, run_command_here, run_rdisc
from mcap.reader import make_reader
from runtime_support import CREATE, EXAMPLES

IMPORTS = REPO / "tests" / "semantics" / "imports"


def surface(kind: str, tmp_path: Path) -> tuple[list[str], str, Path | None]:
    """The command line of a surface before `--record`, its name in messages, and its description."""
    if kind == "run":
        return [sys.executable, "-m", "rdisc", "run", str(CREATE), "--port", "loop://"], "rdisc run", CREATE
    if kind == "console":
        return ([sys.executable, "-m", "rdisc", "console", str(CREATE), "--port", "loop://", "--http", "127.0.0.1:0"],
                "rdisc console", CREATE)
    if kind == "sim":
        pytest.importorskip("mujoco")
        create2 = EXAMPLES / "create2.rdis"
        return [sys.executable, "-m", "rdisc", "sim", str(create2), "--duration", "0.01"], "rdisc sim", create2
    driver = tmp_path / "create_driver.py"
    assert run_rdisc("emit-python", CREATE, "-o", driver).returncode == 0
    return [sys.executable, str(driver), "--port", "loop://"], driver.name, None


def start(command: list[str], *more: str | Path) -> subprocess.CompletedProcess[str]:
    """The command with `more`: `rdisc run`, `rdisc sim` and a driver in this process (they refuse
    before they open anything), the console (which would serve) in a process of its own."""
    if command[1:3] != ["-m", "rdisc"] or command[3] in ("run", "sim"):
        return run_command_here([*command, *more])
    return subprocess.run([*command, *map(str, more)], env=cli_env(), capture_output=True, text=True,
                          check=False, timeout=120)


@pytest.mark.parametrize("kind", ["run", "sim", "console", "driver"])
def test_an_existing_file_is_refused_and_left_alone(kind: str, tmp_path: Path) -> None:
    command, prog, _ = surface(kind, tmp_path)
    kept = tmp_path / "kept.mcap"
    kept.write_bytes(b"a file of the user's")
    result = start(command, "--record", kept)
    assert result.returncode == 2, result.stderr
    assert result.stderr == f"{prog}: will not record to {kept}: it exists (--force replaces it)\n"
    assert kept.read_bytes() == b"a file of the user's"


@pytest.mark.parametrize("kind", ["run", "sim", "console"])
def test_the_description_is_refused_even_with_force(kind: str, tmp_path: Path) -> None:
    command, prog, description = surface(kind, tmp_path)
    assert description is not None
    before = description.read_bytes()
    for force in ((), ("--force",)):
        result = start(command, "--record", description, *force)
        assert result.returncode == 2, result.stderr
        assert result.stderr == f"{prog}: will not record to {description}: it is {description}, which this runs\n"
        assert description.read_bytes() == before


def test_an_import_of_the_description_is_refused_even_with_force(tmp_path: Path) -> None:
    shutil.copytree(IMPORTS / "parts", tmp_path / "parts")
    main = tmp_path / "main.rdis"
    main.write_text('import "parts/motors.rdis"\n\nrobot rover { author "tests" }\n\n'
                    "connection link: serial { baud 115200 }\n")
    imported = tmp_path / "parts" / "sensors.rdis"  # imported by motors.rdis
    before = imported.read_bytes()
    result = start([sys.executable, "-m", "rdisc", "run", str(main), "--port", "loop://"],
                   "--record", tmp_path / "parts" / ".." / "parts" / "sensors.rdis", "--force")
    assert result.returncode == 2, result.stderr
    assert result.stderr.endswith("which this runs\n") and "sensors.rdis" in result.stderr, result.stderr
    assert len(result.stderr.splitlines()) == 1
    assert imported.read_bytes() == before


@pytest.mark.parametrize("kind", ["run", "sim", "driver"])
def test_force_replaces_an_existing_file(kind: str, tmp_path: Path) -> None:
    command, _, _ = surface(kind, tmp_path)
    old = tmp_path / "old.mcap"
    old.write_bytes(b"an old recording" * 1000)
    result = start(command, "--record", old, "--force")
    assert result.returncode == 0, result.stderr
    with old.open("rb") as f:
        assert any(m.name == "rdisc" for m in make_reader(f).iter_metadata())
