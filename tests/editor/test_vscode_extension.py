"""The VS Code extension under editors/vscode: its manifest contributes the language, the
TextMate grammar and the settings; extension.js starts `rdisc lsp` over stdio (run by node against
stand-ins for the `vscode` API and vscode-languageclient, tests/editor/extension_check.js); the
language configuration's indentation rules and brackets."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from tests.editor.parsed_tokens import ROOT

VSCODE = ROOT / "editors" / "vscode"
HERE = Path(__file__).resolve().parent
ON_CI = os.environ.get("CI", "").lower() in ("1", "true", "yes")


def manifest() -> dict[str, Any]:
    made: dict[str, Any] = json.loads((VSCODE / "package.json").read_text(encoding="utf-8"))
    return made


def test_the_manifest_contributes_the_language_its_grammar_and_the_server_settings() -> None:
    made = manifest()
    (language,) = made["contributes"]["languages"]
    (grammar,) = made["contributes"]["grammars"]
    assert (language["id"], language["extensions"], grammar["language"]) == ("rdis", [".rdis"], "rdis")
    assert made["activationEvents"] == ["onLanguage:rdis"]
    assert json.loads((VSCODE / grammar["path"]).read_text(encoding="utf-8"))["scopeName"] == grammar["scopeName"]
    assert (VSCODE / language["configuration"]).is_file() and (VSCODE / made["main"]).is_file()
    settings = made["contributes"]["configuration"]["properties"]
    assert (settings["rdis.server.path"]["default"], settings["rdis.server.args"]["default"]) == ("rdisc", ["lsp"])
    assert made["dependencies"] == {"vscode-languageclient": "9.0.1"}  # exact: what `npm ci` installs
    lock = json.loads((VSCODE / "package-lock.json").read_text(encoding="utf-8"))
    assert lock["packages"]["node_modules/vscode-languageclient"]["version"] == "9.0.1"


def test_the_extension_starts_rdisc_lsp_over_stdio_and_restarts_it_when_its_settings_change() -> None:
    node = shutil.which("node")
    if node is None:
        if ON_CI:
            pytest.fail("node is not installed", pytrace=False)
        pytest.skip("node is not installed")
    done = subprocess.run([node, str(HERE / "extension_check.js"), str(VSCODE / "extension.js")],
                          capture_output=True, text=True, encoding="utf-8", check=False, timeout=60)
    assert done.returncode == 0, done.stderr
    made = json.loads(done.stdout)
    documents = [{"scheme": "file", "language": "rdis"}, {"scheme": "untitled", "language": "rdis"}]

    def client(command: str, *args: str) -> list[Any]:
        return ["client", "rdis", "RDIS language server", {"command": command, "args": list(args), "transport": 0},
                documents]

    assert made == {"subscriptions": 1, "events": [
        ["step", "activate with no settings"],
        client("rdisc", "lsp"), ["start", "rdis"],
        ["step", "an unrelated setting changes"],
        ["step", "rdis.server.path changes"],
        ["stop", "rdis"], client("/opt/robots/.venv/bin/rdisc", "lsp"), ["start", "rdis"],
        ["step", "the server cannot start"],
        ["stop", "rdis"], client("rdisc-missing", "lsp", "--verbose"), ["start", "rdis"],
        ["error", ("RDIS: could not start `rdisc-missing lsp --verbose` (spawn rdisc ENOENT). "
                  "Install rdisc (pip install rdisc) or set rdis.server.path to its command.")],
        ["step", "deactivate"],
    ]}


def test_the_language_configuration_comments_brackets_and_indents() -> None:
    made = json.loads((VSCODE / "language-configuration.json").read_text(encoding="utf-8"))
    assert made["comments"] == {"lineComment": "#"}
    assert made["brackets"] == [["{", "}"], ["[", "]"], ["(", ")"]]
    assert {"open": '"', "close": '"', "notIn": ["string", "comment"]} in made["autoClosingPairs"]
    increase = re.compile(made["indentationRules"]["increaseIndentPattern"])
    decrease = re.compile(made["indentationRules"]["decreaseIndentPattern"])
    opened = ["robot arm {", "    reply {  # the answer", "const IDS = [", "    sync_goal(["]
    not_opened = ["robot arm { author \"x\" }", "    error = out[1]", '    header "{"  # a brace']
    assert [bool(increase.match(line)) for line in opened + not_opened] == [True] * 4 + [False] * 3
    assert [bool(decrease.match(line)) for line in ("}", "    ])", "    }  # end", "x = {}")] == [True] * 3 + [False]
    assert re.fullmatch(made["wordPattern"], "sync_read_present") and not re.fullmatch(made["wordPattern"], "_x")
    assert made["onEnterRules"] == [{"beforeText": r"^\s*///", "action": {"indent": "none", "appendText": "/// "}}]


def test_rdisc_lsp_takes_the_stdio_flag_vscode_languageclient_adds() -> None:
    """vscode-languageclient starts a server it talks to over stdio as COMMAND ARGS --stdio: `rdisc
    lsp --stdio` serves (initialize answered, shutdown and exit obeyed), as `rdisc lsp` does."""
    messages = [{"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"processId": None, "rootUri": None,
                                                                              "capabilities": {}}},
                {"jsonrpc": "2.0", "method": "initialized", "params": {}},
                {"jsonrpc": "2.0", "id": 2, "method": "shutdown"}, {"jsonrpc": "2.0", "method": "exit"}]
    framed = b"".join(b"Content-Length: %d\r\n\r\n%s" % (len(body), body)
                      for body in (json.dumps(message).encode("utf-8") for message in messages))
    done = subprocess.run([sys.executable, "-m", "rdisc", "lsp", "--stdio"], input=framed, capture_output=True,
                          check=False, timeout=60)
    assert done.returncode == 0, done.stderr.decode("utf-8", "replace")
    replies = [json.loads(body) for body in re.split(rb"Content-Length: \d+\r\n(?:[^\r\n]+\r\n)*\r\n", done.stdout) if body]
    assert [reply["id"] for reply in replies] == [1, 2]
    assert replies[0]["result"]["serverInfo"]["name"] == "rdisc" and replies[1]["result"] is None
