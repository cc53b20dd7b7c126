"""The errors a run raises: RdisError, and one subclass for each way a run fails, so that a
caller handles what it can (a timeout, a reply not as described, a lost port) and the rest alike;
and `nearest`, the known name an error's "did you mean" hint offers for a misspelt one.
"""

from __future__ import annotations

from collections.abc import Iterable


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


def nearest(name: str, known: Iterable[str]) -> str | None:
    """The known name a misspelt `name` most likely meant, for a "did you mean" hint: one edit
    away (a letter changed, added or dropped, or two neighbours swapped), which difflib's ratio
    misses in short names (`ix` for `id`); else the closest at difflib's ratio 0.6; else None.
    The one rule of every hint rdisc and its drivers give."""
    import difflib  # only when a name is unknown: start-up time matters

    candidates = [word for word in dict.fromkeys(known) if word != name]
    slips = [word for word in candidates if one_edit(name, word)]
    if slips:
        return max(slips, key=lambda word: difflib.SequenceMatcher(None, name, word).ratio())
    close = difflib.get_close_matches(name, candidates, n=1, cutoff=0.6)
    return close[0] if close else None


def one_edit(name: str, word: str) -> bool:
    """Whether `word` is `name` with one letter changed, added or dropped, or two neighbours swapped."""
    if abs(len(name) - len(word)) > 1 or not name or not word:
        return False
    start = 0
    while start < min(len(name), len(word)) and name[start] == word[start]:
        start += 1
    if len(name) == len(word):
        rest = name[start + 1:] == word[start + 1:]
        swapped = name[start + 2:] == word[start + 2:] and name[start:start + 2] == word[start:start + 2][::-1]
        return rest or swapped
    shorter, longer = (name, word) if len(name) < len(word) else (word, name)
    return shorter[start:] == longer[start + 1:]
