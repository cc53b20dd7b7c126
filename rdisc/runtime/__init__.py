"""rdisc's runtime: interprets a checked Model against real devices.

The run-time semantics are implemented once, in the engine (`rdisc.engine`), which the
runtime imports and every driver `rdisc emit-python` generates carries. What differs is
only how a description becomes the engine's plans: here the expressions are interpreted
(`rdisc.semantics.evaluate`), in a driver they are compiled to Python. The contract both
keep (primitives, replies, frames, schedules, callbacks, errors, the command line) is
docs/runtime.md.
"""

from rdisc.engine import MAX_LINE, Robot
from rdisc.runtime.device import Description, load
from rdisc.runtime.errors import (
    RdisCallbackError,
    RdisConnectionError,
    RdisDeviceError,
    RdisError,
    RdisLoadError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)

__all__ = [
    "MAX_LINE",
    "Description",
    "RdisCallbackError",
    "RdisConnectionError",
    "RdisDeviceError",
    "RdisError",
    "RdisLoadError",
    "RdisProtocolError",
    "RdisTimeout",
    "RdisValueError",
    "Robot",
    "load",
]
