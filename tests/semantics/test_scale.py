"""The checker's time grows linearly with its input (DESIGN.md, Bounds): resolving and checking
a description four times as large costs about four times the CPU, measured in the same test.
The bounds are loose ratios (a quadratic step costs sixteen times), and each figure is the
least of a few runs, so a busy machine does not fail them."""

from __future__ import annotations

import gc
import time
from collections.abc import Callable

from rdisc.compile import compile_text
from rdisc.diagnostics import Diagnostics
from rdisc.resources import stdlib_path
from rdisc.semantics.check import check
from rdisc.semantics.resolve import Unit, resolve
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.parse import parse

HEAD = """\
robot generated { author "tests" }
connection link: serial { baud 115200 }
"""
GROUP = """
state reading_{i}: int = 0
primitive set_motor_{i}(speed: int) on link pack ">Bh" (0x80, speed)
primitive read_sensor_{i}() on link pack "B" (0x8E) unpack ">h" {{ reading_{i} = out[0] }}
interface motor_{i}(speed: float) triggers range_{i} {{
    set_motor_{i}(round(speed * 1000)) delay 1 ms
    read_sensor_{i}()
}}
input velocity_{i}: DifferentialSpeed -> motor_{i}(linear)
output range_{i}: Range {{ distance = reading_{i} * 0.001 }}
"""


def least_cpu(work: Callable[[], object], runs: int = 5) -> float:
    """The least CPU time of a few runs of `work`. What earlier tests left in this worker is moved
    out of the collector's sight first (`gc.freeze`): a full collection during the larger run would
    otherwise walk that whole heap, a cost of the worker and not of the check (a `rdisc check`
    process starts with none)."""
    times = []
    for _ in range(runs):
        gc.collect()
        gc.freeze()
        try:
            start = time.process_time()
            work()
            times.append(time.process_time() - start)
        finally:
            gc.unfreeze()
    return min(times)


def declarations(groups: int) -> ast.Module:
    """A syntax tree of `groups` primitives, each called by an interface (built directly: no parser)."""
    span = Span("generated.rdis", 0, 0)
    decls: list[ast.Decl] = [ast.RobotDecl(ast.Ident("generated", span), (), span)]
    for i in range(groups):
        name = ast.Ident(f"p{i}", span)
        decls.append(ast.PrimitiveDecl(name, (), (), span))
        call = ast.CallStmt(ast.Call(name, (), span), (), (), span)
        decls.append(ast.InterfaceDecl(ast.Ident(f"i{i}", span), (), (), (call,), span))
    return ast.Module("generated.rdis", tuple(decls))


def test_resolution_is_linear() -> None:
    """Each call statement looks its name up among the primitives and interfaces: in constant
    time, not by merging their tables again (quadratic: 2.9 s at 100,000 lines)."""
    small, large = declarations(2000), declarations(8000)
    cost = {module: least_cpu(lambda module=module: resolve([Unit(module, main=True)], Diagnostics()))
            for module in (small, large)}
    assert cost[large] < 8 * cost[small] + 0.01, cost


def test_checking_is_linear() -> None:
    """Resolving and checking (the stages after the parser) four times as much text costs
    about four times as much."""
    texts = [HEAD + "".join(GROUP.format(i=i) for i in range(groups)) for groups in (100, 400)]
    assert not compile_text("generated.rdis", texts[0]).diagnostics.items  # a clean description
    standard = parse(str(stdlib_path()), stdlib_path().read_text(encoding="utf-8"), Diagnostics())
    modules = [parse("generated.rdis", text, Diagnostics()) for text in texts]

    def analyse(module: ast.Module) -> None:
        units = [Unit(standard, standard=True), Unit(module, main=True)]
        diagnostics = Diagnostics()
        check(units, resolve(units, diagnostics), diagnostics)
        assert not diagnostics.items

    small, large = (least_cpu(lambda module=module: analyse(module)) for module in modules)
    assert large < 8 * small + 0.01, (small, large)  # as resolution's: about 4.5x alone, 6.6x once in a loaded suite


def test_a_format_templates_fields_are_checked_in_linear_time() -> None:
    """A template of 4n fields costs about four times one of n (the offset of each field was
    found by scanning from the start: sixteen times)."""
    from rdisc.semantics.formats import format_fields

    small, large = "{},x" * 2_000, "{},x" * 8_000
    assert len(format_fields(large)) == 8_000
    ratio = least_cpu(lambda: format_fields(large), 5) / least_cpu(lambda: format_fields(small), 5)
    assert ratio < 10, ratio  # linear is 4, the quadratic scan was 16; 8.9 was seen on a machine at load 8
