"""The text a generated driver carries verbatim: the engine's modules, the expression
operations among them (`rdisc.engine.operations`, whose functions compiled expressions
call by name), as marked sections (`rdisc.engine.carry`).
"""

from __future__ import annotations


def engine_text() -> str:
    """The engine as every driver carries it: the modules of rdisc.engine as marked sections, in
    their listed order, each byte for byte from the end of its imports (`rdisc.engine.carry`)."""
    from rdisc.engine import carry

    return carry.text()
