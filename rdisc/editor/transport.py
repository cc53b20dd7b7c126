"""How the language server reads its client's messages: pygls's stdio loop, bounded and answering.

pygls reads a header line of any length, allocates whatever a `Content-Length` declares (a
declared 10**17 bytes ended the server), and drops a request whose parameters do not fit their
types without answering it (the client waits for ever). Here a header line is at most
`MAX_HEADER` bytes and a body at most `MAX_MESSAGE` (a larger one is read past in chunks, never
held); a body that is not JSON, a message that is not one JSON object, and a request whose id or
parameters are not of their types are each answered with the JSON-RPC error that says which and
where (`$.params.position.line ...`), and the server reads on.
"""

from __future__ import annotations

import asyncio
import json
import re
import threading
from typing import Any, BinaryIO

import cattrs
from cattrs.v import format_exception
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pygls.lsp.server import LanguageServer

MAX_HEADER = 1024  # bytes of one header line
MAX_MESSAGE = 64 * 2**20  # bytes of one body: a document at the parser's limit (8 Mi characters), escaped
CHUNK = 2**20  # bytes read at once while reading past a body too large

PARSE_ERROR, INVALID_REQUEST, INVALID_PARAMS = -32700, -32600, -32602

_LENGTH = re.compile(rb"content-length:[ \t]*(\d{1,20})[ \t]*\r?\n", re.IGNORECASE)


class Refused:
    """A message read past without being handled: why, for the error answered."""

    __slots__ = ("code", "reason")

    def __init__(self, code: int, reason: str) -> None:
        self.code = code
        self.reason = reason


def read_frame(stream: BinaryIO) -> bytes | Refused | None:
    """The next message's body, or why it was read past; None at the end of the stream."""
    length: int | None = None
    problem: str | None = None
    while True:
        line = stream.readline(MAX_HEADER)
        if not line:
            return None
        if not line.endswith(b"\n"):
            problem = f"a header line longer than {MAX_HEADER} bytes"
            _read_past_line(stream)
            continue
        if line.strip():
            if found := _LENGTH.fullmatch(line):
                length = int(found.group(1))
            elif line.lower().startswith(b"content-length:"):
                problem = f"a Content-Length that is not a number of bytes: {line.strip()[:40]!r}"
            continue
        if length is None:
            if problem is None:
                problem = "a message without a Content-Length header"
            return Refused(INVALID_REQUEST, problem)
        if length > MAX_MESSAGE:
            _read_past(stream, length)
            return Refused(INVALID_REQUEST, f"a message of {length} bytes, past the limit of {MAX_MESSAGE}: "
                                            "read past unhandled")
        body = stream.read(length)
        return body if problem is None else Refused(INVALID_REQUEST, problem)


def _read_past_line(stream: BinaryIO) -> None:
    while (rest := stream.readline(CHUNK)) and not rest.endswith(b"\n"):
        pass


def _read_past(stream: BinaryIO, length: int) -> None:
    while length > 0 and (chunk := stream.read(min(length, CHUNK))):
        length -= len(chunk)


def problems(error: BaseException) -> str:
    """Where and why a message's fields do not fit their types, from the converter's error."""
    def said(exc: BaseException, kind: type | None) -> str:
        return str(exc) if type(exc) is ValueError and str(exc) else format_exception(exc, kind)

    cause = error.__cause__ if isinstance(error, JsonRpcException) and error.__cause__ else error
    return "; ".join(cattrs.transform_error(cause, format_exception=said))


def _an_id(data: dict[str, Any]) -> int | str | None:
    found = data.get("id")
    return found if isinstance(found, (int, str)) and not isinstance(found, bool) else None


class Session:
    """One client on a pair of streams: the reading loop and the errors it answers."""

    def __init__(self, server: LanguageServer, stdin: BinaryIO, stdout: BinaryIO) -> None:
        self.server = server
        self.stdin = stdin
        self.stdout = stdout

    def send(self, message: dict[str, Any]) -> None:
        body = json.dumps(message).encode("utf-8")
        self.stdout.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.stdout.flush()

    def answer_error(self, ident: int | str | None, code: int, reason: str) -> None:
        self.send({"jsonrpc": "2.0", "id": ident, "error": {"code": code, "message": reason}})

    def deliver(self, body: bytes) -> None:
        """Hand one body to pygls, or answer why it cannot be."""
        try:
            data = json.loads(body)
        except (ValueError, RecursionError) as error:  # not UTF-8, not JSON, or nested past the parser
            self.answer_error(None, PARSE_ERROR, f"the message is not JSON: {error}")
            return
        if not isinstance(data, dict):
            self.answer_error(None, INVALID_REQUEST, "a message is one JSON object (LSP has no batches), not "
                                                     f"a {type(data).__name__ if data is not None else 'null'}")
            return
        if "method" in data and "id" in data and _an_id(data) is None:
            self.answer_error(None, INVALID_REQUEST, "a request's id is an integer or a string")
            return
        try:
            message = self.server.protocol.structure_message(data)
        except (JsonRpcException, cattrs.BaseValidationError) as error:
            self.refuse(data, problems(error))
            return
        self.server.protocol.handle_message(message)

    def refuse(self, data: dict[str, Any], reason: str) -> None:
        method = data.get("method")
        if "id" in data and isinstance(method, str):
            self.answer_error(_an_id(data), INVALID_PARAMS, f"{method}: {reason}")
        elif isinstance(method, str):  # a notification has no answer: the client's log says it
            self.server.window_log_message(types.LogMessageParams(
                type=types.MessageType.Error, message=f"{method} ignored: {reason}"))
        else:
            self.answer_error(_an_id(data), INVALID_REQUEST, f"not a request, response or notification: {reason}")

    async def run(self, stop: threading.Event) -> None:
        loop = asyncio.get_running_loop()
        while not stop.is_set():
            frame = await loop.run_in_executor(self.server.thread_pool, read_frame, self.stdin)
            if frame is None:
                return
            if isinstance(frame, Refused):
                self.answer_error(None, frame.code, frame.reason)
            else:
                self.deliver(frame)
