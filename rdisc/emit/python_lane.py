"""The statements with which a generated driver's typed method writes a plain command through
its connection's lane (the port's lock and write, `acquire, release, write = lane`): the
engine's own, `write_one` of `rdisc.engine.exchange._lane_write`, taken from the text the driver
carries. The rule (the port's lock around the write, the refusal of a write that gets the port
once the robot closes, a port's failure a typed error) is written once, in the engine; the
method only names the robot and the primitive its own way.
"""

from __future__ import annotations

import ast
import functools
import io
import textwrap
import tokenize

from rdisc.engine import carry

MODULE, FUNCTION, CLOSURE = "exchange", "_lane_write", "write_one"
RENAMED = ("robot", "plan")  # the closure's names a method gives its own: its robot, the primitive's plan


@functools.cache
def engine_statements() -> str:
    """The closure's statements as the engine writes them, dedented (comments included)."""
    (text,) = (section.body for section in carry.sections() if section.module == MODULE)
    outer = next(node for node in ast.parse(text).body if isinstance(node, ast.FunctionDef) and node.name == FUNCTION)
    inner = next(node for node in outer.body if isinstance(node, ast.FunctionDef) and node.name == CLOSURE)
    lines = text.split("\n")[inner.body[0].lineno - 1 : inner.body[-1].end_lineno]
    return textwrap.dedent("\n".join(lines))


@functools.cache
def names() -> frozenset[str]:
    """Every name the statements use besides the renamed ones: a method whose parameter is
    named so cannot write them (it takes the general way)."""
    return frozenset(token.string for token in _tokens() if token.type == tokenize.NAME) - set(RENAMED)


def lane_statements(robot: str, plan: str) -> list[str]:
    """The statements, lines relative to their block, `robot` and `plan` renamed to the
    method's expressions of the robot and of the primitive's plan."""
    given = dict(zip(RENAMED, (robot, plan)))
    lines = engine_statements().split("\n")
    for token in reversed(_tokens()):  # from the end: a renaming moves nothing before it
        if token.type == tokenize.NAME and token.string in given:
            (row, start), (_, end) = token.start, token.end
            lines[row - 1] = lines[row - 1][:start] + given[token.string] + lines[row - 1][end:]
    return lines


@functools.cache
def _tokens() -> tuple[tokenize.TokenInfo, ...]:
    return tuple(tokenize.generate_tokens(io.StringIO(engine_statements()).readline))
