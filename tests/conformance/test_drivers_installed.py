"""The published drivers of tests/published-drivers.txt are installed, at their pinned versions.

The conformance tests skip a device whose driver is missing. Under CI (CI=true) a
missing or different driver is a failure instead, so CI never passes by skipping
them; elsewhere this test skips, saying how to install them.
"""

from __future__ import annotations

import os
import re
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import pytest

REQUIREMENTS = Path(__file__).resolve().parents[1] / "published-drivers.txt"
ON_CI = os.environ.get("CI", "").lower() in ("1", "true", "yes")


def pinned() -> dict[str, str]:
    """name -> version, from the requirements file's `name==version` lines."""
    pins = {}
    for line in REQUIREMENTS.read_text(encoding="utf-8").splitlines():
        line = line.split("#")[0].strip()
        if line:
            match = re.fullmatch(r"([A-Za-z0-9._-]+)==([A-Za-z0-9.]+)", line)
            assert match, f"{REQUIREMENTS.name}: not `name==version`: {line!r}"
            pins[match[1]] = match[2]
    return pins


def test_the_requirements_pin_every_driver() -> None:
    assert set(pinned()) >= {"pycreate2", "pyax12", "pylx16a", "roboclaw", "pythoncrc", "tcr-roboclaw", "pynmea2", "pyvesc", "pyrplidar"}


def test_every_published_driver_is_installed_at_its_pinned_version() -> None:
    wrong = {}
    for name, wanted in pinned().items():
        try:
            installed = version(name)
        except PackageNotFoundError:
            installed = None
        if installed != wanted:
            wrong[name] = f"{installed or 'missing'} (pinned {wanted})"
    if wrong and not ON_CI:
        pytest.skip(f"published drivers not installed as pinned, {wrong}: the conformance tests of their devices "
                    f"skip; install them with `pip install --no-deps -r tests/{REQUIREMENTS.name}`")
    assert wrong == {}, f"install them with `pip install --no-deps -r tests/{REQUIREMENTS.name}`"
