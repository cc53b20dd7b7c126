"""The documents an editor has open, each with its latest check and its last good one.

A document is checked when it opens, when it changes (the server debounces) and when a file it
imports changes; a question about a document whose text changed since its check checks it first,
so every answer is about the text the editor shows. Imports read the open documents' texts, saved
or not (rdisc.compile.open_texts).
"""

from __future__ import annotations

import os

from rdisc.compile import Compilation, compile_text, open_texts
from rdisc.editor.index import Index, build_index
from rdisc.source import SourceFile


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
    __slots__ = ("analysis", "good", "path", "text", "uri", "version")

    def __init__(self, uri: str, path: str, text: str, version: int | None) -> None:
        self.uri = uri
        self.path = path
        self.text = text
        self.version = version
        self.analysis: Analysis | None = None  # of `text`; None until checked after a change
        self.good: Analysis | None = None  # the last check that built a Model

    @property
    def real_path(self) -> str:
        return os.path.realpath(self.path)


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
        document = self.documents.pop(uri, None)
        if document is None:
            return []
        importers = [d for d in self.documents.values() if d.analysis is not None
                     and document.real_path in d.analysis.files]
        for importer in importers:
            self._check(importer)
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
        changed = document.real_path
        importers = [d for d in self.documents.values()
                     if d is not document and d.analysis is not None and changed in d.analysis.files]
        for importer in importers:
            self._check(importer)
        return [document, *importers]

    def _check(self, document: Document) -> None:
        texts = {d.real_path: d.text for d in self.documents.values() if d is not document}
        with open_texts(texts):
            compilation = compile_text(document.path, document.text)
        source = compilation.sources.get(document.path) or SourceFile(document.path, document.text)
        document.analysis = Analysis(compilation, source)
        if compilation.model is not None:
            document.good = document.analysis
