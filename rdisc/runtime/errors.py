"""Typed run-time errors: the engine's, and the one only loading a description raises
(`rdisc.diagnostics.load_error`).

The engine (`rdisc.engine`) defines the error types; a generated driver
carries the engine, so code written against one works with the other.
"""

from __future__ import annotations

from rdisc.diagnostics.load_error import RdisLoadError
from rdisc.engine import (
    RdisCallbackError,
    RdisConnectionError,
    RdisDeviceError,
    RdisError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)

__all__ = ["RdisCallbackError", "RdisConnectionError", "RdisDeviceError", "RdisError", "RdisLoadError", "RdisProtocolError",
           "RdisTimeout", "RdisValueError"]
