"""When the language server checks a document: at once when it opens or changes, with no pause
waited for. Checks run one at a time, in a thread of their own, so the server reads the editor's
messages meanwhile; the changes made during a check are gathered into one next check, of the
latest text. A result whose document changed since it was made is dropped, never published over
the newer text's (rdisc.editor.documents.Workspace.settle).
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from functools import partial

from rdisc.editor.documents import Analysis, Document, Job, Workspace


class Checker:
    """The queue of documents to check, the check running, and the questions waiting for one."""

    def __init__(self, workspace: Workspace, publish: Callable[[Document], None]) -> None:
        self.workspace = workspace
        self.publish = publish
        self.queued: dict[str, None] = {}  # the documents to check, by uri, in the order asked
        self.running: Job | None = None
        self.waiting: dict[str, list[asyncio.Future[Analysis | None]]] = {}
        self.executor = ThreadPoolExecutor(1, thread_name_prefix="rdisc-check")

    def request(self, uri: str) -> None:
        """Check the document now, or after the check running (once, however often asked)."""
        self.queued[uri] = None
        if self.running is None:
            self._start()

    async def analysis(self, uri: str) -> Analysis | None:
        """The check of the document's text as it is now, waited for if it is not made yet;
        None for a document that is not open."""
        document = self.workspace.documents.get(uri)
        if document is None:
            return None
        if document.analysis is not None:
            return document.analysis
        waiter: asyncio.Future[Analysis | None] = asyncio.get_running_loop().create_future()
        self.waiting.setdefault(uri, []).append(waiter)
        self.request(uri)
        return await waiter

    def _start(self) -> None:
        while self.queued:
            uri = next(iter(self.queued))
            del self.queued[uri]
            document = self.workspace.documents.get(uri)
            if document is None:
                self._answer(uri, None)
            elif document.analysis is None:  # else checked since it was asked for
                job = self.running = self.workspace.job(document)
                made = asyncio.get_running_loop().run_in_executor(self.executor, job.run)
                made.add_done_callback(partial(self._done, job))
                return

    def _done(self, job: Job, made: asyncio.Future[Analysis]) -> None:
        self.running = None
        document = job.document
        try:
            analysis = made.result()
        except Exception as error:  # an internal error: the questions waiting get it, the server goes on
            for waiter in self.waiting.pop(document.uri, []):
                if not waiter.done():
                    waiter.set_exception(error)
            self._start()
            raise
        if self.workspace.settle(job, analysis):
            self._answer(document.uri, analysis)
            self.publish(document)
            for importer in self.workspace.importers(document):
                importer.analysis = None
                self.queued[importer.uri] = None
        elif self.workspace.documents.get(document.uri) is None:
            self._answer(document.uri, None)
        self._start()

    def _answer(self, uri: str, analysis: Analysis | None) -> None:
        for waiter in self.waiting.pop(uri, []):
            if not waiter.done():  # a question given up on is cancelled
                waiter.set_result(analysis)
