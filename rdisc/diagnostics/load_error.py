"""The error a description with errors raises where it is loaded to run: by the runtime
(`rdisc.runtime.load`) and by a driver written and imported in process
(`rdisc.emit.python.import_driver`). Both reach it here, below them."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rdisc.diagnostics.core import Diagnostic, Diagnostics
from rdisc.engine.errors import RdisError

if TYPE_CHECKING:
    from rdisc.source import Sources

__all__ = ["RdisLoadError"]


class RdisLoadError(RdisError):
    """A description that cannot run: it has errors (`diagnostics`), rendered in the message.

    Raised by `rdisc.runtime.load`; a generated driver never raises it (it was
    generated from a description without errors).
    """

    def __init__(self, message: str, diagnostics: tuple[Diagnostic, ...] = (), sources: object = None) -> None:
        super().__init__(message)
        self.diagnostics = diagnostics
        self.sources = sources

    @classmethod
    def of(cls, path: str, diagnostics: Diagnostics, sources: Sources) -> RdisLoadError:
        """The error of a description file, its diagnostics rendered as plain text."""
        from rdisc.diagnostics.text import render_plain

        items = diagnostics.sorted()
        text = render_plain(items, sources) if items else f"{path}: cannot be loaded"
        return cls(text, tuple(items), sources)
