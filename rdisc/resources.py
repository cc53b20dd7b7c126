"""Where the grammar and the standard library are, installed or not.

In a wheel they are shipped inside the package (`rdisc/grammar`, `rdisc/stdlib`);
in a source checkout they sit at the top level beside the package.
"""

from __future__ import annotations

from pathlib import Path

_HERE = Path(__file__).resolve().parent


def _find(folder: str, name: str) -> Path:
    for base in (_HERE / folder, _HERE.parent / folder):
        if (base / name).is_file():
            return base / name
    raise FileNotFoundError(f"rdisc is installed without its {folder}/{name}")


def grammar_path() -> Path:
    return _find("grammar", "rdis.lark")


def stdlib_path() -> Path:
    return _find("stdlib", "adapters.rdis")
