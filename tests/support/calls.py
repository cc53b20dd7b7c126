"""Counting the Python calls a command makes: the cost tests bound work by counts, not time."""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any


def calls_made(command: Callable[[], Any]) -> int:
    """How many Python functions `command()` enters (itself not counted)."""
    entered = 0

    def count(frame: Any, event: str, arg: Any) -> None:
        nonlocal entered
        if event == "call":
            entered += 1

    sys.setprofile(count)
    try:
        command()
    finally:
        sys.setprofile(None)
    return entered - 1  # the lambda given
