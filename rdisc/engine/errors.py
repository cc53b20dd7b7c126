"""The errors a run raises: RdisError, and one subclass for each way a run fails, so that a
caller handles what it can (a timeout, a reply not as described, a lost port) and the rest alike.
"""

from __future__ import annotations


class RdisError(Exception):
    """Any failure while a description runs."""


class RdisTimeout(RdisError, TimeoutError):
    """The device sent no reply within the timeout."""


class RdisProtocolError(RdisError):
    """The device replied, but not as described: short, unterminated or unmatched."""


class RdisDeviceError(RdisError):
    """The device answered, with an error of its own (an `error` reply: Modbus's exception, a
    NACK): `code`, the device's code (None when it sends none), `name`, the member of the
    description's enum of that value (None when none has it), `values`, the error decoded."""

    def __init__(self, message: str, code: int | None = None, name: str | None = None,
                 values: tuple[object, ...] = ()) -> None:
        super().__init__(message)
        self.code = code
        self.name = name
        self.values = values


class RdisConnectionError(RdisError, ConnectionError):
    """A port could not be opened, failed, or disappeared."""


class RdisValueError(RdisError, ValueError):
    """A value could not be computed or encoded (division by zero, out of range for its code)."""


class RdisLimitError(RdisValueError):
    """A command beyond its actuator's limit, refused (`limit refuse`): nothing was written.
    `actuator`, its name; `limit`, "velocity" or "acceleration"; `most`, the limit (the joint's
    units a second, or a second squared)."""

    def __init__(self, message: str, actuator: str, limit: str, most: float) -> None:
        super().__init__(message)
        self.actuator = actuator
        self.limit = limit
        self.most = most


class RdisCallbackError(RdisError):
    """A user callback raised; the exception is the cause."""
