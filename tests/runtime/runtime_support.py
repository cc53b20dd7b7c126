"""Shared by the runtime tests: paths, and callbacks that record what they get."""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
DATA = Path(__file__).resolve().parent / "data"
CREATE = EXAMPLES / "create.rdis"
KOALA = EXAMPLES / "koala.rdis"


class Recorder:
    """A callback that keeps what it is called with, and waits for it."""

    def __init__(self) -> None:
        self.items: list[Any] = []
        self._cond = threading.Condition()

    def __call__(self, *args: Any) -> None:
        with self._cond:
            self.items.append(args[0] if len(args) == 1 else args)
            self._cond.notify_all()

    def __len__(self) -> int:
        with self._cond:
            return len(self.items)

    def snapshot(self) -> list[Any]:
        with self._cond:
            return list(self.items)

    def wait(self, predicate: Callable[[list[Any]], bool], timeout: float = 3.0) -> list[Any]:
        """Wait until `predicate(items)`; return the items, or fail with what arrived."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while not predicate(self.items):
                left = deadline - time.monotonic()
                if left <= 0:
                    raise AssertionError(f"waited {timeout:g} s; got {self.items!r}")
                self._cond.wait(left)
            return list(self.items)

    def wait_count(self, n: int, timeout: float = 3.0) -> list[Any]:
        return self.wait(lambda items: len(items) >= n, timeout)


def typed_thesis_create(folder: Path) -> Path:
    """Appendix B with its `drive` interface typed (`parameterTypes`): then a float going into
    the primitive's ints is two E402 errors, not a thesis truncation."""
    document = json.loads((REPO / "tests" / "syntax" / "data" / "thesis_create.json").read_text(encoding="utf-8"))
    drive = next(i for i in document["interfaces"] if i["name"] == "drive")
    drive["parameterTypes"] = ["float", "float"]
    path = folder / "typed_thesis_create.json"
    path.write_text(json.dumps(document), encoding="utf-8")
    return path
