"""Counting the Python calls a command makes: the cost tests bound work by counts, not time."""

from __future__ import annotations

import gc
import sys
from collections.abc import Callable
from typing import Any


def calls_made(command: Callable[[], Any]) -> int:
    """How many Python functions `command()` enters (itself not counted). The garbage collector is
    held off meanwhile: a collection's callbacks (hypothesis registers one) are not the command's."""
    entered = 0

    def count(frame: Any, event: str, arg: Any) -> None:
        nonlocal entered
        if event == "call":
            entered += 1

    collecting = gc.isenabled()
    gc.disable()
    sys.setprofile(count)
    try:
        command()
    finally:
        sys.setprofile(None)
        if collecting:
            gc.enable()
    return entered - 1  # the lambda given
