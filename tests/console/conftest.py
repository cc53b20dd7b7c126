"""The console's browser tests share one Chromium per test process (each page in a context of its
own): launching it is a few seconds of a shared core, once, not once a module."""

from __future__ import annotations

from collections.abc import Iterator

import pytest


@pytest.fixture(scope="session")
def browser() -> Iterator[object]:
    from console.test_console import launched_chromium  # skips, as that module does, without Chromium

    yield from launched_chromium()
