"""`rdisc lsp` against a hostile client: bytes written straight to a real `python -m rdisc lsp`'s
stdin (pytest-lsp's client cannot write malformed frames). Each hostile message is answered
with the JSON-RPC error that says what and where, or ignored with a line in the client's log,
and the request that follows it is answered: the server never dies, never leaves a request
unanswered, never reads a file the editor did not open."""

from __future__ import annotations

import json
import os
import select
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
BOT = 'robot bot { author "me" }\nstate speed: int = 0\ninterface go() { speed = speed + 1 }\n'


class Client:
    """A client that writes whatever bytes it is given and reads the server's framed answers."""

    def __init__(self) -> None:
        # pygls logs to stderr: a pipe nobody read would fill and stop the server
        self.errors = tempfile.TemporaryFile()  # noqa: SIM115 - kept open as long as the server
        self.process = subprocess.Popen(
            [sys.executable, "-m", "rdisc", "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
            stderr=self.errors, env={**os.environ, "PYTHONPATH": str(ROOT)})
        self.buffer = b""
        self.ids = 100

    def write(self, data: bytes) -> None:
        assert self.process.stdin is not None
        self.process.stdin.write(data)
        self.process.stdin.flush()

    def send(self, message: dict[str, Any]) -> None:
        body = json.dumps(message).encode()
        self.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def notify(self, method: str, params: dict[str, Any]) -> None:
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def read(self) -> dict[str, Any]:
        assert self.process.stdout is not None
        deadline = time.monotonic() + 60
        while True:
            if b"\r\n\r\n" in self.buffer:
                head, rest = self.buffer.split(b"\r\n\r\n", 1)
                length = int(next(line for line in head.split(b"\r\n")
                                  if line.lower().startswith(b"content-length")).split(b":")[1])
                if len(rest) >= length:
                    self.buffer = rest[length:]
                    message: dict[str, Any] = json.loads(rest[:length])
                    return message
            ready, _, _ = select.select([self.process.stdout], [], [], max(0.0, deadline - time.monotonic()))
            assert ready, "the server answered nothing"
            chunk = os.read(self.process.stdout.fileno(), 65536)
            assert chunk, f"the server ended: {self.process.wait()} {self.logged()!r}"
            self.buffer += chunk

    def logged(self) -> bytes:
        self.errors.seek(0)
        return self.errors.read()

    def answers(self, until_id: int | None) -> list[dict[str, Any]]:
        """What the server sent up to and including the answer with `until_id`."""
        found = []
        while True:
            message = self.read()
            found.append(message)
            if "method" not in message and message.get("id") == until_id:
                return found

    def ask(self, method: str, params: Any) -> list[dict[str, Any]]:
        self.ids += 1
        self.send({"jsonrpc": "2.0", "id": self.ids, "method": method, "params": params})
        return self.answers(self.ids)

    def still_answers(self) -> None:
        """A request after the hostile one gets its own, right answer."""
        (answer,) = [m for m in self.ask("textDocument/hover", {"textDocument": {"uri": "file:///never/opened"},
                                                                 "position": {"line": 0, "character": 0}})
                     if "id" in m]
        assert answer["error"] == {"code": -32602, "message": "file:///never/opened is not open"}


@pytest.fixture(scope="module")
def client() -> Iterator[Client]:
    found = Client()
    found.ask("initialize", {"capabilities": {}})
    found.notify("initialized", {})
    yield found
    found.process.kill()
    found.process.wait()


def error_of(messages: list[dict[str, Any]]) -> dict[str, Any]:
    (answer,) = [m for m in messages if "method" not in m]
    error: dict[str, Any] = answer["error"]
    return error


def framed(body: bytes) -> bytes:
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


@pytest.mark.parametrize("data, code, message", [
    (framed(b"{abc}"), -32700,
     "the message is not JSON: Expecting property name enclosed in double quotes: line 1 column 2 (char 1)"),
    (framed(b"\xff\xfe\x00\xd8"), -32700, "the message is not JSON: "),
    (framed(b'[{"jsonrpc": "2.0", "id": 1, "method": "shutdown"}]'), -32600,
     "a message is one JSON object (LSP has no batches), not a list"),
    (framed(b"5"), -32600, "a message is one JSON object (LSP has no batches), not a int"),
    (framed(b'{"jsonrpc": "2.0", "method": "x", "params": ' + b"[" * 100_000 + b"]" * 100_000 + b"}"), -32700,
     "the message is not JSON: maximum recursion depth exceeded while decoding a JSON array from a unicode string"),
    (b'\r\n', -32600, "a message without a Content-Length header"),
    (b"Content-Length: -5\r\n\r\n", -32600, "a Content-Length that is not a number of bytes: b'Content-Length: -5'"),
    (b"X-Junk: " + b"x" * 5000 + b"\r\n" + framed(b"{}"), -32600, "a header line longer than 1024 bytes"),
    (framed(b'{"jsonrpc": "2.0", "id": {"a": 1}, "method": "textDocument/hover", "params": {}}'), -32600,
     "a request's id is an integer or a string"),
])
def test_a_malformed_message_is_answered_with_its_error_and_the_next_is_answered(
        client: Client, data: bytes, code: int, message: str) -> None:
    client.write(data)
    (answer,) = client.answers(None)
    assert answer["error"]["code"] == code
    assert answer["error"]["message"].startswith(message) and (message or answer["error"]["message"])
    client.still_answers()


@pytest.mark.parametrize("position, message", [
    ({"line": -1, "character": 0},
     "Position.line should be in range [0:2147483647], but was -1. @ $.params.position"),
    ({"line": 2**31, "character": 3},
     "Position.line should be in range [0:2147483647], but was 2147483648. @ $.params.position"),
    ({"line": 0, "character": 2**40},
     "Position.character should be in range [0:2147483647], but was 1099511627776. @ $.params.position"),
    ("zz", ("invalid value for type, expected int @ $.params.position.line; "
           "invalid value for type, expected int @ $.params.position.character")),
])
def test_a_request_whose_parameters_do_not_fit_is_answered_with_where(
        client: Client, position: Any, message: str) -> None:
    for method in ("textDocument/hover", "textDocument/completion", "textDocument/rename"):
        params = {"textDocument": {"uri": "file:///x.rdis"}, "position": position, "newName": "b"}
        assert error_of(client.ask(method, params)) == {"code": -32602, "message": f"{method}: {message}"}
    client.still_answers()


def test_a_declared_length_past_the_limit_is_read_past_without_holding_it() -> None:
    lone = Client()
    lone.write(b"Content-Length: 99999999999999999\r\n\r\n" + b"x" * 1000)
    assert lone.process.stdin is not None
    lone.process.stdin.close()  # the 10**17 bytes never come: the server reads to the end and stops
    assert lone.process.wait(timeout=60) == 0
    assert b"MemoryError" not in lone.logged()


def test_formatting_a_uri_that_is_not_open_reads_no_file(client: Client) -> None:
    for uri in ("file:///dev/zero", "file:///etc/hostname"):  # /dev/zero grew the server without end
        for method, extra in (("textDocument/formatting", {}), ("textDocument/rangeFormatting", {"range": {
                "start": {"line": 0, "character": 0}, "end": {"line": 1, "character": 0}}})):
            params = {"textDocument": {"uri": uri}, "options": {"tabSize": 4, "insertSpaces": True}, **extra}
            assert error_of(client.ask(method, params)) == {"code": -32602, "message": f"{uri} is not open"}
    client.still_answers()


def test_a_change_to_a_document_that_is_not_open_is_ignored_with_a_log_line(client: Client) -> None:
    client.notify("textDocument/didChange", {"textDocument": {"uri": "file:///not/open.rdis", "version": 2},
                                             "contentChanges": [{"text": "robot r {}"}]})
    client.notify("textDocument/didChange", {"textDocument": {"uri": "file:///x.rdis", "version": 2},
                                             "contentChanges": [{"range": {"start": {"line": -1, "character": 0},
                                                                           "end": {"line": 0, "character": 0}},
                                                                 "text": ""}]})
    client.ids += 1
    client.send({"jsonrpc": "2.0", "id": client.ids, "method": "shutdown!", "params": None})
    seen = client.answers(client.ids)
    assert [(m.get("method"), m.get("params", {}).get("message")) for m in seen[:2]] == [
        ("window/logMessage", "textDocument/didChange ignored: file:///not/open.rdis is not open"),
        ("window/logMessage", ("textDocument/didChange ignored: Position.line should be in range [0:2147483647], "
                              "but was -1. @ $.params.content_changes[0].range.start"))]
    client.still_answers()


def test_a_document_of_lone_surrogates_or_a_nul_in_its_uri_is_answered(client: Client, tmp_path: Path) -> None:
    surrogates = tmp_path.as_uri() + "/lone.rdis"
    client.notify("textDocument/didOpen", {"textDocument": {
        "uri": surrogates, "languageId": "rdis", "version": 1,
        "text": 'robot bot { author "\ud800" }\nstate \udc00speed: int = 0\n'}})
    (symbols,) = [m for m in client.ask("textDocument/documentSymbol", {"textDocument": {"uri": surrogates}})
                  if "id" in m]
    assert [(s["name"], s["range"]["end"]) for s in symbols["result"]] == [("bot", {"line": 0, "character": 24})]
    nul = tmp_path.as_uri() + "/%00.rdis"  # the path a file cannot have: the URI is the document's name
    client.notify("textDocument/didOpen", {"textDocument": {"uri": nul, "languageId": "rdis", "version": 1,
                                                            "text": BOT}})
    (hover,) = [m for m in client.ask("textDocument/hover", {"textDocument": {"uri": nul},
                                                             "position": {"line": 1, "character": 7}}) if "id" in m]
    assert hover["result"]["contents"]["value"] == "```rdis\nstate speed: int = 0\n```"


def not_followed(uri: str, held: int, limit: int) -> str:
    return (f"{uri} is not followed: the open documents would hold {held} characters, past the limit of {limit}; "
            "close some and open it again")


def test_the_open_documents_hold_a_bounded_number_of_characters_together(tmp_path: Path) -> None:
    from rdisc.editor.server import MAX_OPEN_CHARS

    lone = Client()
    lone.ask("initialize", {"capabilities": {}})
    big = 'robot bot { author "me" }\n#' + "x" * (MAX_OPEN_CHARS // 3) + "\n"  # a third of the bound, and more
    uris = [tmp_path.as_uri() + f"/big{number}.rdis" for number in range(3)]
    for uri in uris:  # each is past the parser's limit, so its check is a quick refusal
        lone.notify("textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "rdis", "version": 1,
                                                              "text": big}})
    held = 3 * len(big)
    seen = lone.ask("textDocument/documentSymbol", {"textDocument": {"uri": uris[2]}})
    assert [m["params"]["message"] for m in seen if m.get("method") == "window/showMessage"] == [
        not_followed(uris[2], held, MAX_OPEN_CHARS)]
    assert error_of(seen) == {"code": -32602, "message": f"{uris[2]} is not open"}
    (kept,) = [m for m in lone.ask("textDocument/documentSymbol", {"textDocument": {"uri": uris[0]}}) if "id" in m]
    assert "result" in kept
    lone.notify("textDocument/didChange", {"textDocument": {"uri": uris[0], "version": 2}, "contentChanges": [
        {"range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}}, "text": big}]})
    seen = lone.ask("textDocument/documentSymbol", {"textDocument": {"uri": uris[0]}})
    assert [m["params"]["message"] for m in seen if m.get("method") == "window/showMessage"] == [
        not_followed(uris[0], held, MAX_OPEN_CHARS)]
    assert error_of(seen) == {"code": -32602, "message": f"{uris[0]} is not open"}
    lone.still_answers()
    lone.process.kill()
    lone.process.wait()


def test_an_expected_refusal_is_one_line_in_the_servers_log_not_a_traceback(client: Client) -> None:
    """pygls wrote the traceback of every refusal the server meant (a document that is not open,
    parameters that do not fit, a rename refused) to stderr: each is one line there now, and the
    client's error is the same."""
    client.notify("textDocument/didOpen", {"textDocument": {"uri": "file:///quiet.rdis", "languageId": "rdis",
                                                            "version": 1, "text": BOT}})
    options = {"tabSize": 4, "insertSpaces": True}
    assert error_of(client.ask("textDocument/formatting", {"textDocument": {"uri": "file:///etc/hostname"},
                                                           "options": options})) == {
        "code": -32602, "message": "file:///etc/hostname is not open"}
    assert error_of(client.ask("textDocument/rename", {"textDocument": {"uri": "file:///never/opened"},
                                                       "position": {"line": 0, "character": 0},
                                                       "newName": "b"}))["message"] == \
        "file:///never/opened is not open"
    assert error_of(client.ask("textDocument/rename", {"textDocument": {"uri": "file:///quiet.rdis"},
                                                       "position": {"line": 1, "character": 7},
                                                       "newName": "9"}))["code"] == -32803
    assert error_of(client.ask("textDocument/hover", {"textDocument": {"uri": "file:///quiet.rdis"},
                                                      "position": {"line": -1, "character": 0}}))["code"] == -32602
    client.still_answers()
    logged = client.logged().decode(errors="replace")
    assert "Traceback" not in logged
    assert "file:///etc/hostname is not open" in logged  # one line, to say what was refused
