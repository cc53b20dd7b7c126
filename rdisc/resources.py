"""Where the grammar and the standard library are, installed or not.

In a wheel they are shipped inside the package (`rdisc/grammar`, `rdisc/stdlib`);
in a source checkout they sit at the top level beside the package. Found with `os.path`:
`rdisc check` does not import pathlib to start (the `Path`s are made on request).
"""

from __future__ import annotations

import os

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from pathlib import Path

_HERE = os.path.dirname(os.path.realpath(__file__))


def _find(folder: str, name: str) -> str:
    for base in (os.path.join(_HERE, folder), os.path.join(os.path.dirname(_HERE), folder)):
        if os.path.isfile(os.path.join(base, name)):
            return os.path.join(base, name)
    raise FileNotFoundError(f"rdisc is installed without its {folder}/{name}")


def grammar_path() -> Path:
    from pathlib import Path

    return Path(_find("grammar", "rdis.lark"))


def stdlib_file() -> str:
    """The standard library's file, as a string."""
    return _find("stdlib", "adapters.rdis")


def frameworks_file() -> str:
    """The table of what each standard adapter is in each framework (rdisc.semantics.frameworks)."""
    return _find("stdlib", "frameworks.txt")


def stdlib_path() -> Path:
    from pathlib import Path

    return Path(stdlib_file())
