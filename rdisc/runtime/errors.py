"""Typed run-time errors: what went wrong talking to a device, by kind.

A generated driver defines classes of the same names (it imports nothing from
rdisc), so code written against one works with the other.
"""

from __future__ import annotations


class RdisError(Exception):
    """Any failure while a description runs."""


class RdisTimeout(RdisError, TimeoutError):
    """The device sent no reply within the timeout."""


class RdisProtocolError(RdisError):
    """The device replied, but not as described: short, unterminated or unmatched."""


class RdisConnectionError(RdisError, ConnectionError):
    """A port could not be opened, failed, or disappeared."""


class RdisValueError(RdisError, ValueError):
    """A value could not be computed or encoded (division by zero, out of range for its code)."""


class RdisCallbackError(RdisError):
    """A user callback raised; the exception is the cause."""


class RdisLoadError(RdisError):
    """A description that cannot run: it has errors (`diagnostics`), rendered in the message.

    Raised by `rdisc.runtime.load`; a generated driver never raises it (it was
    generated from a description without errors).
    """

    def __init__(self, message: str, diagnostics: tuple = (), sources: object = None) -> None:
        super().__init__(message)
        self.diagnostics = diagnostics
        self.sources = sources

    @classmethod
    def from_compilation(cls, path: str, compilation) -> RdisLoadError:  # compilation: rdisc.compile.Compilation
        from rdisc.diagnostics.text import render_plain

        items = compilation.diagnostics.sorted()
        text = render_plain(items, compilation.sources) if items else f"{path}: cannot be loaded"
        return cls(text, tuple(items), compilation.sources)
