"""The console's browser tests share one Chromium while a test process runs them (each page in a
context of its own): launching it is a few seconds of a shared core. It closes when the process
leaves tests/console: Playwright's sync API keeps an event loop running in the main thread while
it lives, where the editor's asyncio tests (pytest-asyncio, pytest-lsp) need none."""

from __future__ import annotations

from collections.abc import Iterator

import pytest


@pytest.fixture(scope="package")
def browser() -> Iterator[object]:
    from console.test_console import launched_chromium  # skips, as that module does, without Chromium

    yield from launched_chromium()
