"""The language server: pygls's protocol wired to the workspace and the answering modules.

Each handler finds the document's analysis (waiting for its check if its text changed) and hands it
to the module that answers; none of them does work beyond a walk of one compilation's names, so a
hostile document costs what checking it costs, within the compiler's token and size limits.

A handler waits for its document's analysis last and then answers at once: the next check of
that document moves the spans of what it kept in place (rdisc.syntax.incremental), so an analysis
is read before its document's next check starts.
"""

from __future__ import annotations

import asyncio
import logging
import sys
import threading
from collections.abc import Callable, Generator
from concurrent.futures import Future
from typing import Any, BinaryIO, TypeVar
from urllib.parse import unquote

import cattrs
from lsprotocol import types
from pygls.exceptions import JsonRpcException, JsonRpcInvalidParams
from pygls.io_ import StdoutWriter
from pygls.lsp.server import LanguageServer
from pygls.protocol import LanguageServerProtocol, lsp_method

from rdisc import __version__
from rdisc.editor import actions, completion, formatting, hover, navigation, positions, symbols
from rdisc.editor.checks import Checker
from rdisc.editor.diagnostics import published
from rdisc.editor.documents import Analysis, Document, Workspace
from rdisc.editor.transport import Session
from rdisc.syntax.parse import MAX_FILE_CHARS

T = TypeVar("T")

_log = logging.getLogger(__name__)

MAX_OPEN_CHARS = 4 * MAX_FILE_CHARS  # of all the open documents together: four at the parser's limit


class Protocol(LanguageServerProtocol):
    """pygls's protocol, ignoring (with a line in the client's log) a change to a document that is
    not open, where pygls's KeyError reached the editor as a server error, and following no
    document past what the open documents may hold together (`MAX_OPEN_CHARS`). A refusal the
    server means (a JSON-RPC error: a document that is not open, a rename refused, parameters
    that do not fit their types) is one line in the server's log: pygls wrote each one's traceback
    to stderr, as if it were a fault of the server."""

    def structure_message(self, data: Any) -> Any:
        method = data.get("method") if isinstance(data, dict) else None
        kind = self.get_message_type(method) if isinstance(method, str) else None
        if kind is None:
            return super().structure_message(data)
        try:  # the transport answers a refusal with where the parameters do not fit
            return self._converter.structure(data, kind)
        except cattrs.BaseValidationError as error:
            _log.warning("%s refused: its parameters do not fit their types", method)
            raise error from None

    def _send_handler_result(self, future: Future[Any], *, msg_id: Any) -> None:
        refusal = None if future.cancelled() else future.exception()
        if not isinstance(refusal, JsonRpcException):
            super()._send_handler_result(future, msg_id=msg_id)
            return
        self._request_futures.pop(msg_id, None)
        _log.warning("request %s refused: %s", msg_id, refusal.message)
        self._send_response(msg_id, error=refusal.to_response_error())

    @lsp_method(types.TEXT_DOCUMENT_DID_OPEN)
    def lsp_text_document__did_open(self, params: types.DidOpenTextDocumentParams) -> Generator[Any, Any, None]:
        self.workspace.put_text_document(params.text_document)
        if not self._too_much(params.text_document.uri):
            yield from self._handled(types.TEXT_DOCUMENT_DID_OPEN, params)

    @lsp_method(types.TEXT_DOCUMENT_DID_CHANGE)
    def lsp_text_document__did_change(self, params: types.DidChangeTextDocumentParams) -> Generator[Any, Any, None]:
        uri = params.text_document.uri
        if unquote(uri) not in self.workspace.text_documents:
            self._server.window_log_message(types.LogMessageParams(
                type=types.MessageType.Error, message=f"textDocument/didChange ignored: {uri} is not open"))
            return
        for change in params.content_changes:
            self.workspace.update_text_document(params.text_document, change)
        if not self._too_much(uri):
            yield from self._handled(types.TEXT_DOCUMENT_DID_CHANGE, params)

    def _handled(self, method: str, params: Any) -> Generator[Any, Any, None]:
        if (handler := self.fm.features.get(method)) is not None:
            yield handler, (params,), None

    def _too_much(self, uri: str) -> bool:
        """Whether the open texts now hold more than MAX_OPEN_CHARS: then this document is
        followed no longer, and the editor is told so."""
        held = sum(len(document.source) for document in self.workspace.text_documents.values())
        if held <= MAX_OPEN_CHARS:
            return False
        self.workspace.remove_text_document(uri)
        server = self._server
        assert isinstance(server, RdisServer)
        server.forget(uri)
        server.window_show_message(types.ShowMessageParams(type=types.MessageType.Warning, message=(
            f"{uri} is not followed: the open documents would hold {held} characters, past the limit of "
            f"{MAX_OPEN_CHARS}; close some and open it again")))
        return True


class RdisServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__("rdisc", __version__, text_document_sync_kind=types.TextDocumentSyncKind.Incremental,
                         protocol_cls=Protocol)
        self.documents = Workspace()
        self.checks = Checker(self.documents, self.publish)

    def publish(self, document: Document) -> None:
        assert document.analysis is not None
        self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(
            uri=document.uri, version=document.version, diagnostics=published(document, document.analysis)))

    def good(self, uri: str) -> Analysis | None:
        """The document's last check without errors, if any."""
        document = self.documents.documents.get(uri)
        return document.good if document is not None else None

    def start_io(self, stdin: BinaryIO | None = None, stdout: BinaryIO | None = None) -> None:
        """pygls's stdio server, reading through rdisc.editor.transport: bounded, and answering
        every message it cannot handle."""
        output = stdout or sys.stdout.buffer
        self._stop_event = stop = threading.Event()  # set by pygls's shutdown
        self.protocol.set_writer(StdoutWriter(output))
        try:
            asyncio.run(Session(self, stdin or sys.stdin.buffer, output).run(stop))
        except (BrokenPipeError, KeyboardInterrupt, SystemExit):  # the client went, or said exit
            pass
        finally:
            self.shutdown()  # type: ignore[no-untyped-call]

    def forget(self, uri: str) -> None:
        """Follow the document no longer: its diagnostics cleared, the documents importing it checked
        again (its file is read now)."""
        self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
        for importer in self.documents.forget(uri):
            self.checks.request(importer.uri)

    def open_document(self, uri: str) -> Document:
        """An open document's text, never a file read for a URI the editor has not opened (pygls's
        `get_text_document` reads one: `file:///dev/zero` grew without end)."""
        found = self.documents.documents.get(uri)
        if found is None:
            raise JsonRpcInvalidParams(f"{uri} is not open")
        return found

    async def analysis(self, uri: str) -> Analysis:
        found = await self.checks.analysis(uri)
        if found is None:
            raise JsonRpcInvalidParams(f"{uri} is not open")
        return found


def make_server() -> RdisServer:
    server = RdisServer()

    @server.feature(types.INITIALIZED)
    def initialized(ls: RdisServer, params: types.InitializedParams) -> None:
        ls.checks.executor.submit(completion.warm)  # in the checks' thread: the parser is made once

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: RdisServer, params: types.DidOpenTextDocumentParams) -> None:
        item = params.text_document
        ls.documents.open(item.uri, positions.path_of(item.uri), item.text, item.version)
        ls.checks.request(item.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: RdisServer, params: types.DidChangeTextDocumentParams) -> None:
        uri = params.text_document.uri
        text = ls.workspace.get_text_document(uri).source  # pygls applied the changes
        if ls.documents.change(uri, text, params.text_document.version) is not None:
            ls.checks.request(uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: RdisServer, params: types.DidCloseTextDocumentParams) -> None:
        ls.forget(params.text_document.uri)

    @server.feature(types.TEXT_DOCUMENT_CODE_ACTION,
                    types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix]))
    async def code_action(ls: RdisServer, params: types.CodeActionParams) -> list[types.CodeAction]:
        analysis = await ls.analysis(params.text_document.uri)
        return actions.quick_fixes(params.text_document.uri, analysis.source, list(params.context.diagnostics))

    @server.feature(types.TEXT_DOCUMENT_HOVER)
    async def on_hover(ls: RdisServer, params: types.HoverParams) -> types.Hover | None:
        analysis = await ls.analysis(params.text_document.uri)
        return hover.hover(analysis, ls.good(params.text_document.uri), params.position)

    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    async def definition(ls: RdisServer, params: types.DefinitionParams) -> list[types.Location]:
        return navigation.definition(await ls.analysis(params.text_document.uri), params.position)

    @server.feature(types.TEXT_DOCUMENT_REFERENCES)
    async def references(ls: RdisServer, params: types.ReferenceParams) -> list[types.Location]:
        others, analysis = await _others(ls, params.text_document.uri), await ls.analysis(params.text_document.uri)
        return navigation.references(analysis, params.position, params.context.include_declaration, others)

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_HIGHLIGHT)
    async def highlight(ls: RdisServer, params: types.DocumentHighlightParams) -> list[types.DocumentHighlight]:
        return navigation.highlights(await ls.analysis(params.text_document.uri), params.position)

    @server.feature(types.TEXT_DOCUMENT_PREPARE_RENAME)
    async def prepare_rename(ls: RdisServer, params: types.PrepareRenameParams) -> types.Range | None:
        analysis = await ls.analysis(params.text_document.uri)
        return _refused(lambda: navigation.prepare_rename(analysis, params.position))

    @server.feature(types.TEXT_DOCUMENT_RENAME)
    async def rename(ls: RdisServer, params: types.RenameParams) -> types.WorkspaceEdit | None:
        others, analysis = await _others(ls, params.text_document.uri), await ls.analysis(params.text_document.uri)
        return _refused(lambda: navigation.rename(analysis, params.position, params.new_name, others))

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    async def document_symbols(ls: RdisServer, params: types.DocumentSymbolParams) -> list[types.DocumentSymbol]:
        return symbols.document_symbols(await ls.analysis(params.text_document.uri))

    @server.feature(types.TEXT_DOCUMENT_FOLDING_RANGE)
    async def folding(ls: RdisServer, params: types.FoldingRangeParams) -> list[types.FoldingRange]:
        return symbols.folding_ranges(await ls.analysis(params.text_document.uri))

    @server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL, symbols.LEGEND)
    async def semantic_tokens(ls: RdisServer, params: types.SemanticTokensParams) -> types.SemanticTokens:
        return symbols.semantic_tokens(await ls.analysis(params.text_document.uri))

    @server.feature(types.TEXT_DOCUMENT_COMPLETION,
                    types.CompletionOptions(trigger_characters=[".", '"', "(", " ", ","]))
    async def complete(ls: RdisServer, params: types.CompletionParams) -> types.CompletionList:
        analysis = await ls.analysis(params.text_document.uri)
        return completion.complete(analysis, params.position, ls.good(params.text_document.uri))

    @server.feature(types.TEXT_DOCUMENT_FORMATTING)
    def format_document(ls: RdisServer, params: types.DocumentFormattingParams) -> list[types.TextEdit]:
        document = ls.open_document(params.text_document.uri)
        return formatting.format_document(document.path, document.text)

    @server.feature(types.TEXT_DOCUMENT_RANGE_FORMATTING)
    def format_range(ls: RdisServer, params: types.DocumentRangeFormattingParams) -> list[types.TextEdit]:
        document = ls.open_document(params.text_document.uri)
        return formatting.format_range(document.path, document.text, params.range)

    return server


async def _others(ls: RdisServer, uri: str) -> list[Analysis]:
    """The other open documents' analyses: a name of a shared import is used in each."""
    return [found for other in list(ls.documents.documents)
            if other != uri and (found := await ls.checks.analysis(other)) is not None]


def _refused(answer: Callable[[], T]) -> T:
    """The answer, or an LSP error response saying why a rename is refused."""
    try:
        return answer()
    except navigation.Refused as refused:  # LSP's RequestFailed: the request was right, the rename is not
        raise JsonRpcException(str(refused), code=types.LSPErrorCodes.RequestFailed) from None


def serve() -> None:
    make_server().start_io()
