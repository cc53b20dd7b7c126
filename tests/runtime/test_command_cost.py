"""What a plain command costs the runtime, in Python calls (counted, not timed): the figures of
benchmarks/driver_speed.py depend on them, and a count does not depend on the machine.

A call is a Python function entered (`sys.setprofile`'s "call"), from the command's method to
the port's `write`; the bytes are the thesis's and the AX-12 manual's.
"""

from __future__ import annotations

from typing import Any

import pytest
from runtime_support import DATA, EXAMPLES

from rdisc.runtime import load
from tests.support.calls import calls_made
from tests.support.ports import ScriptedPort

TABLE_4_3 = [((-0.2, -0.4), "89 ff38 01f4"), ((0.0, 0.0), "89 0000 0000"), ((0.0, 0.2), "89 0000 ffff"),
             ((0.0, -0.2), "89 0000 0001"), ((0.2, 0.0), "89 00c8 7fff"), ((-0.2, 0.0), "89 ff38 7fff")]



@pytest.fixture(scope="module")
def create() -> Any:
    return load(DATA / "fast_create.rdis")


@pytest.fixture(scope="module")
def ax12() -> Any:
    return load(EXAMPLES / "ax12.rdis")


def test_set_velocity_costs_the_runtime_few_calls(create: Any) -> None:
    """The six rows of Table 4.3 through `call_input`: the one-step request of the input and the
    prepared conditionals' tests (`linear == 0`) made in their closures. 143 calls before, then 125;
    55 with the input's request made where `call_input` is, the interface's arguments and the
    primitive's values in one closure, `clamp(linear, ...)` called there, `round(velocity * 1000)`
    computed there, and the conditionals' comparisons made in their closures."""
    port = ScriptedPort()
    robot = create.connect({"btserial": port}, threads=False)
    try:
        made = []
        for (linear, angular), expected in TABLE_4_3:
            del port.written[:]
            made.append(calls_made(lambda v=linear, w=angular: robot.call_input("set_velocity", linear=v, angular=w)))
            assert bytes(port.written) == bytes.fromhex(expected)
        assert sum(made) <= 55, made
    finally:
        robot.close()


@pytest.mark.parametrize("way", ["call_primitive", "primitives"])
def test_goto_all_costs_the_runtime_four_calls(ax12: Any, way: str) -> None:
    """AX-12 goto_all(512), a framed broadcast write: the method (`call_primitive`, or the typed
    method, `robot.primitives` kept on the robot), the request (its value tested, its checksum
    summed in the closure), the write and the port's write. Five and seven before the methods
    made the one-step write themselves, six and eight when the request called the engine's test
    of its values."""
    port = ScriptedPort()
    robot = ax12.connect({"bus": port}, threads=False)
    try:
        command = ((lambda: robot.call_primitive("goto_all", 512)) if way == "call_primitive"
                   else (lambda: robot.primitives.goto_all(512)))
        command()  # the typed method made once
        del port.written[:]
        assert calls_made(command) <= 4
        assert bytes(port.written) == bytes.fromhex("FF FF FE 05 03 1E 00 02 D9")
    finally:
        robot.close()
