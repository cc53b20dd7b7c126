"""The errors a description's run raises: one base type, and one for each way a run fails."""

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
