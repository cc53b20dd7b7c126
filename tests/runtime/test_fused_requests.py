"""The runtime's one-step requests in their fastest shapes (rdisc.runtime.at_once): a framed
write with a sum checksum packed whole by one struct (`Written.whole`, the lowering's), and an
input whose interface only scales its arguments into one primitive, fused into one closure
(its first argument's `clamp(field, low, high)` called there, `round(x * c)` with Python's own
`*`). Each gives exactly the bytes the general way gives, or None, and the general way then
says what is wrong."""

from __future__ import annotations

import functools
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import pytest
from conftest import fuzz_examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.compile import compile_text
from rdisc.engine.arguments import _accepted
from rdisc.lower import lower
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

DESCRIPTION = """\
robot fused { description "requests the runtime makes in one step" }

state gain: float = 2.0

adapter Pair ros "geometry_msgs/Twist" {
    forward: float unit "m/s" ros "linear.x"
    turn: float unit "rad/s" ros "angular.z"
}
adapter Count ros "std_msgs/Int32" {
    count: int ros "data"
}

frame tailed(id: int) {
    header "\\xFF"
    field id "B" = id
    length "B" = payload
    payload
    checksum "sum" "B" inverted
    terminator "\\r\\n"
}

connection link: serial { baud 115200 }

primitive pair(a: int in -300..300, b: int in 0..200) on link frame tailed(5) pack "<BhB" (7, a, b)
primitive single(x: int in -100..100) on link frame tailed(6) pack ">Bb" (1, x)
primitive wide(x: int) on link frame tailed(7) pack "<BI" (2, x)
primitive drive(velocity: int, radius: int) on link pack ">Bhh" (137, velocity, radius)
primitive speeds(left: int, right: int) on link pack ">Bhh" (145, left, right)
primitive level(value: int) on link pack ">Bh" (9, value)

interface drive(velocity: float, radius: float) {
    drive(round(velocity * 1000), round(1000 * radius))
}
interface speeds(left: float, right: float) {
    speeds(int(left * 500.0), round(-right * gain + 0.5))
}
interface level(value: float) {
    level(round(value * 100))
}

input steer: Pair -> drive(
    clamp(forward, -0.5, 0.5),
    0.0 if forward == 0 and turn == 0 else (-0.001 if turn > 0 else 0.001) if forward == 0
    else 32.767 if turn == 0 else clamp(forward / turn, -2.0, 2.0)
)
input wheels: Pair -> speeds(forward + turn, forward - turn)
input counted: Count -> level(count)
"""

PRIMITIVES = {"pair": 2, "single": 1, "wide": 1}
INPUTS = ("steer", "wheels", "counted")


@functools.cache
def _description(folder: str) -> Any:
    path = Path(folder) / "fused.rdis"
    path.write_text(DESCRIPTION, encoding="utf-8")
    return load(path)


@pytest.fixture(scope="module")
def robot(tmp_path_factory: pytest.TempPathFactory) -> Any:
    port = ScriptedPort()
    made = _description(str(tmp_path_factory.mktemp("fused"))).connect(port, threads=False)
    made.test_port = port
    yield made
    made.close()


def _outcome(robot: Any, call: Any) -> bytes | str:
    """What a call writes, or the name of the error it raises."""
    port = robot.test_port
    before = len(port.written)
    try:
        call()
    except Exception as err:  # noqa: BLE001 - its type is compared
        return type(err).__name__
    return bytes(port.written[before:])


def _primitive_in_full(robot: Any, name: str, values: Sequence[Any]) -> bytes | str:
    plan = robot.device.primitives[name]
    return _outcome(robot, lambda: type(robot)._primitive_in_full(
        robot, plan, _accepted(f"primitive {name}", plan.params, list(values))))


def _input_in_full(robot: Any, name: str, values: Sequence[Any]) -> bytes | str:
    plan = robot.device.inputs[name]
    return _outcome(robot, lambda: type(robot)._input_in_full(robot, plan, list(values)))


def test_the_lowering_stores_the_whole_frames_struct() -> None:
    compilation = compile_text("fused.rdis", DESCRIPTION)
    assert compilation.model is not None
    primitives = lower(compilation.model).device.primitives
    pair = primitives["pair"].request
    assert pair is not None and pair.whole is not None
    # Head (FF, the ID, the length), the code 7, a, b, the checksum, the terminator; the sum's
    # constant part the ID, the length and the code: 5 + 4 + 7.
    assert (pair.whole.format, pair.whole.partial) == ("<3sBhBB2s", 16)
    wide = primitives["wide"].request
    assert wide is not None and wide.whole is not None  # four bytes: the runtime packs, then sums
    assert primitives["drive"].request is not None and primitives["drive"].request.whole is None  # no frame


@pytest.mark.parametrize(("name", "values", "expected"), [
    ("pair", [-2, 200], "FF 05 04 07 FE FF C8 2A 0D 0A"),  # -2 as FE FF; ~(5+4+7+0xFE+0xFF+0xC8) & 0xFF
    ("pair", [300, 0], "FF 05 04 07 2C 01 00 C2 0D 0A"),
    ("single", [-100], "FF 06 02 01 9C 5A 0D 0A"),
    ("wide", [70000], "FF 07 05 02 70 11 01 00 6F 0D 0A"),
])
def test_a_framed_write_is_packed_whole_with_its_checksum(robot: Any, name: str, values: list[Any],
                                                          expected: str) -> None:
    assert _outcome(robot, lambda: robot.call_primitive(name, *values)) == bytes.fromhex(expected)
    assert _outcome(robot, lambda: getattr(robot.primitives, name)(*values)) == bytes.fromhex(expected)
    assert _primitive_in_full(robot, name, values) == bytes.fromhex(expected)


@pytest.mark.parametrize(("values", "expected"), [
    ((-0.2, -0.4), "89 ff38 01f4"), ((0.0, 0.0), "89 0000 0000"), ((0.0, 0.2), "89 0000 ffff"),
    ((0.0, -0.2), "89 0000 0001"), ((0.2, 0.0), "89 00c8 7fff"), ((-0.2, 0.0), "89 ff38 7fff"),
])
def test_an_input_fused_into_one_closure_writes_table_4_3(robot: Any, values: tuple[float, float],
                                                           expected: str) -> None:
    forward, turn = values
    assert robot.device.inputs["steer"].request.__name__ == "two_read_scaled"  # its shape, fused
    assert _outcome(robot, lambda: robot.call_input("steer", forward=forward, turn=turn)) == bytes.fromhex(expected)
    assert _input_in_full(robot, "steer", values) == bytes.fromhex(expected)


INTS = st.one_of(st.integers(-400, 400), st.integers(-2**40, 2**40))
NUMBERS = st.one_of(INTS, st.floats(allow_nan=True, allow_infinity=True), st.floats(-3, 3), st.booleans())


@settings(max_examples=fuzz_examples(150), deadline=None)
@given(name=st.sampled_from(sorted(PRIMITIVES)), values=st.lists(NUMBERS, min_size=0, max_size=3))
def test_a_whole_frame_gives_the_general_ways_bytes_or_leaves_it_to_the_general_way(
        robot: Any, name: str, values: list[Any]) -> None:
    plan = robot.device.primitives[name]
    fast = plan.request(robot._state, list(values))
    general = _primitive_in_full(robot, name, values)
    if fast is not None:
        assert fast == general
    if len(values) == PRIMITIVES[name] and all(type(v) is int for v in values) and isinstance(general, bytes):
        assert fast == general  # each of its own type, within its range: never left to the general way
    assert _outcome(robot, lambda: robot.call_primitive(name, *values)) == general
    if len(values) == PRIMITIVES[name]:  # (the typed method binds its arguments as Python does first)
        assert _outcome(robot, lambda: getattr(robot.primitives, name)(*values)) == general


@settings(max_examples=fuzz_examples(150), deadline=None)
@given(name=st.sampled_from(INPUTS), first=NUMBERS, second=NUMBERS)
def test_a_fused_input_gives_the_general_ways_bytes_or_leaves_it_to_the_general_way(
        robot: Any, name: str, first: Any, second: Any) -> None:
    plan = robot.device.inputs[name]
    values = [first, second][:len(plan.fields)]
    fast = plan.request(robot._state, list(values))
    general = _input_in_full(robot, name, values)
    if fast is not None:
        assert fast == general
    if all(type(v) is f.kind for v, f in zip(values, plan.fields)) and isinstance(general, bytes):
        assert fast == general  # of the fields' own types, and the general way writes: so does the one step
    fields = dict(zip((f.name for f in plan.fields), values))
    assert _outcome(robot, lambda: robot.call_input(name, **fields)) == general
