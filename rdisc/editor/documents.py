"""The documents an editor has open, each with its latest check and its last good one.

A document is checked when it opens, when it changes and when a file it imports changes; a
question about a document whose text changed since its check waits for (or makes) the check of
its text, so every answer is about the text the editor shows. Imports read the open documents'
texts, saved or not (rdisc.compile.open_texts). A check is a `Job`: what it reads is taken when it
is made, so it may run in a thread of its own (rdisc.editor.checks) while the editor types on;
its result is kept only if the document's text is still the one it checked. Each check parses
only the declarations changed since the last (rdisc.syntax.incremental), and checks again only
the primitives and interfaces whose declarations, or what they read, changed
(rdisc.semantics.check.memo).
"""

from __future__ import annotations

import os

from rdisc.compile import Compilation, compile_text, open_texts
from rdisc.editor.index import Index, build_index
from rdisc.semantics.check.memo import Memo
from rdisc.source import SourceFile
from rdisc.syntax.incremental import Reparser


class Analysis:
    """One check of a document's text: the compilation, the index of its names, and the real
    paths of the files it read (its own, its imports', the stdlib's)."""

    __slots__ = ("_index", "compilation", "files", "source")

    def __init__(self, compilation: Compilation, source: SourceFile) -> None:
        self.compilation = compilation
        self.source = source
        self.files = {os.path.realpath(path) for path in compilation.sources}
        self._index: Index | None = None

    @property
    def index(self) -> Index:
        """Made when first asked: publishing diagnostics needs none."""
        if self._index is None:
            self._index = build_index(self.compilation.units)
        return self._index

    def source_of(self, path: str) -> SourceFile | None:
        return self.compilation.sources.get(path)


class Document:
    __slots__ = ("analysis", "good", "memo", "parser", "path", "text", "uri", "version")

    def __init__(self, uri: str, path: str, text: str, version: int | None) -> None:
        self.uri = uri
        self.path = path
        self.text = text
        self.version = version
        self.analysis: Analysis | None = None  # of `text`; None until checked after a change
        self.good: Analysis | None = None  # the last check that built a Model (read for names and layouts:
        # a later check may have moved its spans with the declarations it kept, rdisc.syntax.incremental)
        self.parser = Reparser()  # its declarations as last parsed, reused by the next check
        self.memo = Memo()  # its primitives' and interfaces' checks, reused by the next check

    @property
    def real_path(self) -> str:
        return os.path.realpath(self.path)


class Job:
    """One check to make: a document's text as it was when it was made, and the other open
    documents' texts (its imports read them). Running it touches nothing shared."""

    __slots__ = ("document", "text", "texts")

    def __init__(self, document: Document, texts: dict[str, str]) -> None:
        self.document = document
        self.text = document.text
        self.texts = texts

    def run(self) -> Analysis:
        path = self.document.path
        with open_texts(self.texts):
            compilation = compile_text(path, self.text, parser=self.document.parser, memo=self.document.memo)
        source = compilation.sources.get(path) or SourceFile(path, self.text)
        return Analysis(compilation, source)


class Workspace:
    def __init__(self) -> None:
        self.documents: dict[str, Document] = {}

    def open(self, uri: str, path: str, text: str, version: int | None) -> Document:
        document = self.documents[uri] = Document(uri, path, text, version)
        return document

    def change(self, uri: str, text: str, version: int | None) -> Document | None:
        document = self.documents.get(uri)
        if document is not None:
            document.text, document.version, document.analysis = text, version, None
        return document

    def close(self, uri: str) -> list[Document]:
        """Forget a document; the open documents importing it, checked again (its file is read
        now, not its text): those to publish."""
        importers = self.forget(uri)
        for importer in importers:
            self._check(importer)
        return importers

    def forget(self, uri: str) -> list[Document]:
        """Forget a document: the open documents importing it, their checks dropped (its file is
        read now, not its text), to check again."""
        document = self.documents.pop(uri, None)
        if document is None:
            return []
        importers = self.importers(document)
        for importer in importers:
            importer.analysis = None
        return importers

    def analysis(self, uri: str) -> Analysis | None:
        """The check of the document's text as it is now (made now if it changed since)."""
        document = self.documents.get(uri)
        if document is None:
            return None
        if document.analysis is None:
            self._check(document)
        return document.analysis

    def check(self, uri: str) -> list[Document]:
        """Check the document (unless a question since its change did) and every open document
        that imports it: those to publish."""
        document = self.documents.get(uri)
        if document is None:
            return []
        if document.analysis is None:
            self._check(document)
        importers = self.importers(document)
        for importer in importers:
            self._check(importer)
        return [document, *importers]

    def importers(self, document: Document) -> list[Document]:
        """The other open documents whose last check read the document's file."""
        changed = document.real_path
        return [d for d in self.documents.values()
                if d is not document and d.analysis is not None and changed in d.analysis.files]

    def job(self, document: Document) -> Job:
        return Job(document, {d.real_path: d.text for d in self.documents.values() if d is not document})

    def settle(self, job: Job, analysis: Analysis) -> bool:
        """Keep a check's result if its document is open and its text is still the one checked
        (a stale result is dropped: a newer check follows); whether it was kept."""
        document = job.document
        if self.documents.get(document.uri) is not document or document.text != job.text:
            return False
        document.analysis = analysis
        if analysis.compilation.model is not None:
            document.good = analysis
        return True

    def _check(self, document: Document) -> None:
        job = self.job(document)
        self.settle(job, job.run())
