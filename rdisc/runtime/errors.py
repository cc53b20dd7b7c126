"""Typed run-time errors: the engine's, and the one only loading a description raises.

The engine (`rdisc.engine`) defines the error types; a generated driver
carries the engine, so code written against one works with the other.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rdisc.engine import (
    RdisCallbackError,
    RdisConnectionError,
    RdisError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)

if TYPE_CHECKING:
    from rdisc.compile import Compilation
    from rdisc.diagnostics import Diagnostic

__all__ = ["RdisCallbackError", "RdisConnectionError", "RdisError", "RdisLoadError", "RdisProtocolError",
           "RdisTimeout", "RdisValueError"]


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
    def from_compilation(cls, path: str, compilation: Compilation) -> RdisLoadError:
        from rdisc.diagnostics.text import render_plain

        items = compilation.diagnostics.sorted()
        text = render_plain(items, compilation.sources) if items else f"{path}: cannot be loaded"
        return cls(text, tuple(items), compilation.sources)
