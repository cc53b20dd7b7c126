"""A real VS Code: code-server (VS Code's workbench served to a browser, with its real Node
extension host) with editors/vscode installed exactly as the README says (`npm ci --omit=dev` in
the folder, the folder linked into the extensions directory), driven by Playwright in Debian's
Chromium. It opens a copy of examples/arm.rdis with a misspelt primitive and, through the
extension's client and `rdisc lsp` found on the login shell's PATH, gets colours from the
TextMate grammar, the diagnostic (a squiggle and the Problems panel), its quick fix, hover with
the wire layout, go to definition, completion, rename and Format Document into `rdisc fmt`'s
layout.

code-server comes from tests/vscode/package-lock.json: `npm ci --prefix tests/vscode
--ignore-scripts && npm run --prefix tests/vscode natives` (.ci/run does both)."""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from rdisc.format import format_text
from tests.support.editors import unformatted_arm

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
CODE_SERVER = HERE / "node_modules" / "code-server" / "out" / "node" / "entry.js"
CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync"]
WAIT_MS = 30_000  # a generous limit for any one condition (never a measure of speed)
ON_CI = os.environ.get("CI", "").lower() in ("1", "true", "yes")
pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)
# The user's settings: nothing asked of the network (gallery, updates, experiments), no welcome page,
# and files saved when asked (VS Code in a browser saves a second after each change by default).
SETTINGS = {"files.autoSave": "off", "extensions.autoCheckUpdates": False, "extensions.autoUpdate": False, "update.mode": "none",
            "workbench.enableExperiments": False, "telemetry.telemetryLevel": "off", "workbench.startupEditor": "none",
            "workbench.tips.enabled": False, "extensions.ignoreRecommendations": True, "editor.minimap.enabled": False,
            "workbench.colorTheme": "Default Dark Modern"}


def missing(reason: str) -> None:
    """Skip, or fail under CI, where .ci/run installs what the test needs."""
    if ON_CI:
        pytest.fail(reason, pytrace=False)
    pytest.skip(reason)


def installed_extension(extensions: Path) -> None:
    """The README's VS Code line, with code-server's extensions directory for ~/.vscode/extensions:
    `npm ci --omit=dev` in the folder (it needs the registry: .ci/run runs it once), then the link."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    found = re.search(r"\*\*VS Code\*\*.*?```sh\n(.*?)```", readme, re.DOTALL)
    assert found is not None, "the README has no VS Code set-up"
    line = re.fullmatch(r'cd (\S+) && npm ci --omit=dev && ln -s "\$PWD" ~/\.vscode/extensions/(\S+)', found[1].strip())
    assert line is not None, found[1]
    folder = ROOT / line[1]
    if not (folder / "node_modules" / "vscode-languageclient").is_dir():
        missing(f"{line[1]} has no node_modules (`npm ci --omit=dev --prefix {line[1]}`, as .ci/run does)")
    (extensions / line[2]).symlink_to(folder)


def started_code_server(tmp_path: Path, workspace: Path) -> tuple[subprocess.Popen[str], str]:
    """code-server on a free loopback port, with a home, settings and extensions of its own; the
    login shell's PATH (which VS Code gives its extension host) starts with this Python's `rdisc`."""
    home, data, extensions = tmp_path / "home", tmp_path / "data", tmp_path / "extensions"
    for made in (home, data / "User", extensions):
        made.mkdir(parents=True)
    (home / ".profile").write_text(f'PATH="{os.path.dirname(sys.executable)}:$PATH"\n', encoding="utf-8")
    (data / "User" / "settings.json").write_text(json.dumps(SETTINGS), encoding="utf-8")
    installed_extension(extensions)
    environment = {**os.environ, "HOME": str(home), "SHELL": "/bin/sh", "PYTHONPATH": str(ROOT),
                   "XDG_CONFIG_HOME": str(home / ".config"), "XDG_DATA_HOME": str(home / ".local" / "share")}
    process = subprocess.Popen(
        ["node", str(CODE_SERVER), "--auth", "none", "--bind-addr", "127.0.0.1:0", "--user-data-dir", str(data),
         "--extensions-dir", str(extensions), "--disable-telemetry", "--disable-update-check",
         "--disable-workspace-trust", "--disable-getting-started-override", str(workspace)],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, encoding="utf-8", env=environment, cwd=tmp_path,
        start_new_session=True)  # a process group of its own: its extension host and `rdisc lsp` end with it
    assert process.stdout is not None
    said = []
    for line in process.stdout:  # until it says where it listens (it exits, ending the loop, if it cannot)
        said.append(line)
        listening = re.search(r"HTTP server listening on (http://127\.0\.0\.1:\d+/)", line)
        if listening:
            # What it says next is read (and dropped), so that a full pipe never stops it.
            threading.Thread(target=process.stdout.read, daemon=True).start()
            return process, listening[1]
    process.wait(timeout=60)
    raise AssertionError(f"code-server exited with status {process.returncode} before listening: {''.join(said)}")


@pytest.fixture
def code_server(tmp_path: Path) -> Iterator[tuple[str, Path]]:
    """The served workbench's URL for a folder holding arm.rdis with `sync_read_present` misspelt in its call."""
    if not CODE_SERVER.is_file():
        missing("code-server is not installed (`npm ci --prefix tests/vscode --ignore-scripts && "
                "npm run --prefix tests/vscode natives`)")
    if not CHROMIUM.exists():
        missing("Debian's chromium is not installed (apt-get install chromium)")
    workspace = tmp_path / "workspace"
    workspace.mkdir()
    arm = unformatted_arm()
    assert arm.count("{ sync_read_present() }") == 1
    (workspace / "arm.rdis").write_text(arm.replace("{ sync_read_present() }", "{ sync_read_presnt() }"),
                                        encoding="utf-8")
    process, url = started_code_server(tmp_path, workspace)
    try:
        yield f"{url}?folder={workspace}", workspace / "arm.rdis"
    finally:
        os.killpg(process.pid, signal.SIGTERM)
        process.wait(timeout=60)


def test_vscode_with_the_readme_install_shows_a_misspelt_primitive(code_server: tuple[str, Path]) -> None:
    playwright_api = pytest.importorskip("playwright.sync_api")
    expect = playwright_api.Expect()  # one of its own: its timeout is not every other test's
    expect.set_options(timeout=WAIT_MS)
    url, document = code_server
    arm = unformatted_arm()
    lines = arm.splitlines()
    call = lines.index("interface read_joints() periodic triggers joints { sync_read_present() }")
    column = lines[call].index("sync_read_present")
    declared = next(i for i, text in enumerate(lines) if text.startswith("primitive sync_read_present("))
    renamed = arm.replace("sync_read_present", "read_positions")  # its declaration and its one call
    formatted = format_text(renamed, "arm.rdis")
    assert formatted != renamed  # not in that layout before: Format Document has edits to make
    formatted_call = formatted.splitlines().index("interface read_joints() periodic triggers joints { read_positions() }")

    with playwright_api.sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_FLAGS)
        try:
            page = browser.new_page(viewport={"width": 1600, "height": 1000})
            page.set_default_timeout(WAIT_MS)
            page.goto(url)
            page.get_by_role("treeitem", name="arm.rdis").click()
            editor = page.locator(".editor-instance .monaco-editor").first
            status = page.locator(".statusbar-item[id='status.editor.selection']")

            def go_to(line: int, character: int) -> None:
                """Go to Line/Column (Ctrl+G), 0-based `line` and `character`; the status bar says when it is there."""
                editor.locator(".view-lines").click()
                page.keyboard.press("Control+g")
                page.keyboard.type(f"{line + 1}:{character + 1}")
                page.keyboard.press("Enter")
                expect(page.locator(".quick-input-widget")).to_be_hidden()  # it moves the cursor before it closes
                expect(status).to_have_text(f"Ln {line + 1}, Col {character + 1}")

            # The language is RDIS (the extension's contribution), and the misspelt call is squiggled
            # once the server's diagnostic arrives.
            expect(page.locator(".statusbar-item[id='status.editor.mode']")).to_have_text("RDIS")
            go_to(call, column)
            expect(editor.locator(".squiggly-error")).to_have_count(1)

            # Colours: the tokens' scopes (the TextMate grammar's, and the server's semantic tokens), seen
            # as the theme's colours of the rendered spans: a keyword, a name, a string, a number.
            go_to(declared, 0)
            colours = spans_coloured(editor, lines[declared])
            assert colours["primitive"] != colours["sync_read_present"], colours  # a keyword is not a name
            string_line = next(i for i, text in enumerate(lines) if '"count")' in text)
            go_to(string_line, 0)
            coloured = spans_coloured(editor, lines[string_line])
            assert len({coloured["primitive"], coloured['"count"'], coloured["4095"], coloured["sync_goal"]}) == 4, coloured

            # The diagnostic in the Problems panel: its message, its code, its line.
            page.keyboard.press("Control+Shift+m")
            problem = page.locator(".markers-panel .monaco-list-row").filter(has_text="sync_read_presnt")
            expect(problem).to_have_count(1)
            expect(problem).to_contain_text("unknown primitive or interface `sync_read_presnt`")
            expect(problem).to_contain_text("E102")
            expect(problem).to_contain_text(f"[Ln {call + 1}, Col {column + 1}]")

            # Its quick fix (Ctrl+.), applied: the squiggle clears.
            go_to(call, column + 2)
            page.keyboard.press("Control+.")
            fix = page.locator(".action-widget .monaco-list-row").filter(has_text="Change to `sync_read_present`")
            expect(fix).to_have_class(re.compile(r"\bfocused\b"))  # the one fix, chosen: Enter applies it
            page.keyboard.press("Enter")
            expect(editor.locator(".squiggly-error")).to_have_count(0)
            expect(problem).to_have_count(0)

            # Hover on the call: its doc comment and wire layout.
            go_to(call, column + 2)
            page.keyboard.press("Control+k")
            page.keyboard.press("Control+i")
            hover = page.locator(".monaco-hover-content").filter(has_text="wire layout")
            expect(hover).to_contain_text("primitive sync_read_present()")
            expect(hover).to_contain_text("Ask all six servos")
            expect(hover).to_contain_text("primitive sync_read_present() on bus, frame dxl(254)")
            expect(hover).to_contain_text("request: 20 bytes")  # its bytes, as `rdisc dump` tables them
            expect(hover).to_contain_text(re.compile(r"offset\s+size\s+kind\s+value\s+0\s+4\s+header\s+FF FF FD 00\s"))
            page.keyboard.press("Escape")

            # Go to definition (F12): the cursor moves to the primitive's declaration.
            page.keyboard.press("F12")
            expect(status).to_have_text(re.compile(rf"^Ln {declared + 1}, Col \d+$"))

            # Completion (Ctrl+Space) inside the call's name offers the primitive.
            go_to(call, column + 4)
            page.keyboard.press("Control+Space")
            expect(page.locator(".suggest-widget .monaco-list-row").filter(has_text="sync_read_present").first).to_be_visible()
            page.keyboard.press("Escape")

            # Rename (F2): the declaration and the call follow.
            go_to(call, column + 2)
            page.keyboard.press("F2")
            rename = page.locator(".rename-box input")
            expect(rename).to_be_focused()
            rename.fill("read_positions")
            rename.press("Enter")
            expect(editor.locator(".view-line").filter(has_text="{ read_positions() }")).to_have_count(1)

            # Format Document (Ctrl+Shift+I on Linux): the cursor's line moves where `rdisc fmt` puts the call;
            # saved (Ctrl+S), the file is `rdisc fmt`'s text of the renamed description.
            page.keyboard.press("Control+Shift+i")
            expect(status).to_have_text(re.compile(rf"^Ln {formatted_call + 1}, Col \d+$"))
            unsaved = page.locator(".tab.active.dirty")
            expect(unsaved).to_have_count(1)
            page.keyboard.press("Control+s")
            expect(unsaved).to_have_count(0)
            assert document.read_text(encoding="utf-8") == formatted  # the declaration renamed too
        finally:
            browser.close()


def spans_coloured(editor: Any, text: str) -> dict[str, str]:
    """The computed colour of each token span on the rendered line that reads `text`."""
    line = editor.locator(".view-line").filter(has_text=text.split("(")[0]).first
    line.wait_for()
    spans: list[list[str]] = line.evaluate(
        "line => [...line.querySelectorAll('span > span')].map(s => [s.textContent, getComputedStyle(s).color])")
    coloured: dict[str, str] = {}
    for words, colour in spans:
        for word in re.findall(r'"[^"]*"|\w+', words.replace("\u00a0", " ")):
            coloured.setdefault(word, colour)
    return coloured
