"""A primitive only written goes out in one step (`Primitive.request`), as the lowering describes
it (`rdisc.lower.Written`): its parameters checked, its values packed between its frame's
constant bytes, the checksum summed from the constant part's. The runtime's closure and the
driver's function give exactly the bytes the general way gives, or None and the general way
then raises its typed error; the typed methods take that step first."""

from __future__ import annotations

import functools
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import pytest
from conftest import fuzz_examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.compile import compile_text
from rdisc.emit.python import import_driver, to_python
from rdisc.engine.arguments import _accepted
from rdisc.lower import lower
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

DESCRIPTION = """\
robot written { description "primitives written in one step" }

const BROADCAST = 254
state mode: int = 2

frame summed(id: int in 0..BROADCAST) {
    header "\\xFF\\xFF"
    field id "B" = id
    length "B" = payload + 1
    payload
    checksum "sum" "B" inverted
}
frame crc(address: int) {
    header "\\xAA"  field address "B" = address  length "B" = payload  payload  checksum "crc16-xmodem" ">H"
    terminator "\\r\\n"
}
frame xored { header "\\x02"  length "B" = payload  payload  checksum "xor" "B" }
frame wide { header "\\xAB"  length "B" = payload  payload  checksum "sum" ">H" }
frame little { header "\\xAC"  payload  checksum "sum" "<H" }

connection link: serial { baud 115200 }

primitive goto(goal: int in 0..1023) on link frame summed(BROADCAST) pack "<BBH" (3, 30, goal)
primitive drive(right: int in -500..500, left: int in -500..500) on link pack ">Bhh" (145, right, left)
primitive speed(v: float in -1.5..1.5, turn: int) on link frame crc(7) pack ">bfh" (-3, v * 2, turn)
primitive flag(on: bool, level: int in 0..200) on link frame xored pack "<B?B" (9, on, level)
primitive scaled(x: int) on link pack ">BH" (1, x * 3 + 1)
primitive moded(x: int in 0..9) on link frame summed(1) pack "<BBB" (4, mode, x)
primitive nothing() on link frame summed(2) pack "B" (6)
primitive rounded(v: float) on link pack ">Bh" (2, round(v * 1000 + 0.5))
primitive signed(a: int, b: int in -100..100) on link frame wide pack ">hbIq" (a, b, 70000, a * 3)
primitive mixed(a: int) on link frame little pack ">H" (a)
"""

NAMES = ("goto", "drive", "speed", "flag", "scaled", "moded", "nothing", "rounded", "signed", "mixed")


@functools.cache
def _path() -> str:
    folder = tempfile.mkdtemp(prefix="rdisc-written-")
    path = f"{folder}/written.rdis"
    with open(path, "w", encoding="utf-8") as out:
        out.write(DESCRIPTION)
    return path


@functools.cache
def _robots() -> tuple[tuple[Any, ScriptedPort], ...]:
    """The runtime's robot and the driver's, each on its own port."""
    path = _path()
    driver = import_driver(path, path.rsplit("/", 1)[0], "written_driver_for_requests")
    made = []
    for robot in (load(path).connect, driver.connect):
        port = ScriptedPort()
        made.append((robot(port, threads=False), port))
    return tuple(made)


def _general(robot: Any, port: ScriptedPort, name: str, values: Sequence[Any]) -> bytes | str:
    """What the general way writes for these values, or the name of the error it raises."""
    plan = robot.device.primitives[name]
    before = len(port.written)
    try:
        type(robot)._primitive_in_full(robot, plan, _accepted(f"primitive {name}", plan.params, list(values)))
    except Exception as err:  # noqa: BLE001 - its type is compared
        return type(err).__name__
    return bytes(port.written[before:])


def _outside(plan: Any, values: Sequence[Any]) -> bool:
    """Whether the values are each of its parameter's own type, and one is outside its range."""
    return all(type(v) is p.kind for v, p in zip(values, plan.params)) and any(
        p.low is not None and not p.low <= v <= p.high for v, p in zip(values, plan.params))


INTS = st.one_of(st.integers(-2000, 2000), st.integers(-2**70, 2**70))
VALUES = st.one_of(INTS, st.floats(allow_nan=True, allow_infinity=True), st.booleans(), st.just("7"))


@settings(max_examples=fuzz_examples(60), deadline=None)
@given(name=st.sampled_from(NAMES), values=st.lists(VALUES, min_size=0, max_size=3))
def test_one_step_gives_the_general_ways_bytes_or_leaves_it_to_the_general_way(name: str, values: list[Any]) -> None:
    for robot, port in _robots():
        plan = robot.device.primitives[name]
        assert plan.request is not None, f"{name} is only written"
        fast = plan.request(robot._state, list(values))
        general = _general(robot, port, name, values)
        if fast is not None:
            assert fast == general
        if len(values) == len(plan.params) and _outside(plan, values):
            assert fast is None
            assert general == "RdisValueError"
        before = len(port.written)  # the host's way: the one step, else the general way's error
        try:
            robot.call_primitive(name, *values)
            called: bytes | str = bytes(port.written[before:])
        except Exception as err:  # noqa: BLE001 - its type is compared
            called = type(err).__name__
        assert called == general


@pytest.mark.parametrize(("name", "values", "expected"), [
    ("goto", [512], "FF FF FE 05 03 1E 00 02 D9"),  # the AX-12 manual's broadcast goal position
    ("goto", [0], "FF FF FE 05 03 1E 00 00 DB"),
    ("drive", [200, -45], "91 00 C8 FF D3"),
    ("moded", [3], "FF FF 01 04 04 02 03 F1"),
    ("nothing", [], "FF FF 02 02 06 F5"),
])
def test_one_step_writes_the_published_bytes(name: str, values: list[Any], expected: str) -> None:
    for robot, port in _robots():
        before = len(port.written)
        robot.call_primitive(name, *values)
        assert bytes(port.written[before:]) == bytes.fromhex(expected)


def test_the_lowering_folds_the_frame_into_constant_bytes() -> None:
    compilation = compile_text("written.rdis", DESCRIPTION)
    assert compilation.model is not None
    primitives = lower(compilation.model).device.primitives
    goto = primitives["goto"].request
    assert goto is not None
    assert (goto.head, goto.covered, goto.partial, goto.tail) == (b"\xff\xff\xfe\x05", b"\xfe\x05", 0xFE + 5, b"")
    speed = primitives["speed"].request
    assert speed is not None
    assert (speed.head, speed.partial, speed.tail) == (b"\xaa\x07\x07", None, b"\r\n")  # a CRC: over the bytes
    drive = primitives["drive"].request
    assert drive is not None and (drive.head, drive.checksum) == (b"", None)
    text = to_python(compilation.model, "written.rdis")
    assert "def _p_goto_request(state: StateValues, args: Args) -> bytes | None:" in text
    # One struct packs the whole frame, the checksum summed from the values (3 + 30 folded in).
    assert '_PACK_GOTO = struct.Struct("<4sBBHB").pack' in text
    assert "checksum = ((0x124 + (goal & 0xff) + (goal >> 8)) & 0xff) ^ 0xff" in text
    assert 'return _PACK_GOTO(b"\\xff\\xff\\xfe\\x05", 3, 30, goal, checksum)' in text
    # A value from the state is read once, for the pack and for the sum.
    assert "value_2 = state[\"mode\"]" in text
    assert "checksum = ((0x9 + value_2 + x) & 0xff) ^ 0xff" in text  # ID 1, length 4, the code 4
    # Signed and wide codes summed byte by byte (70000 folded in), a 16-bit sum in the payload's order;
    # a checksum in another byte order than the payload's: the payload packed, then summed.
    assert '_PACK_SIGNED = struct.Struct(">2shbIqH").pack' in text
    assert "+ (a >> 8 & 0xff)\n" in text and "+ (value_4 >> 56 & 0xff)\n" in text
    assert 'return b"\\xac" + payload + _PACK_MIXED_CHECKSUM((0x0 + sum(payload)) & 0xffff)' in text
    assert "request=_p_goto_request," in text
    # round() of float arithmetic in Python's operators: a result too large for a float is an
    # infinity, which round() refuses, so the general way then says what is wrong.
    assert "return _PACK_ROUNDED(2, round(v * 1000 + 0.5))" in text


def test_a_drivers_typed_method_hands_its_one_step_request_to_the_write() -> None:
    robot, port = _robots()[1]
    general: list[str] = []
    robot._call_primitive = lambda plan, values: general.append(plan.name)  # the general way, counted (this instance's)
    try:
        before = len(port.written)
        robot.primitives.goto(512)
        robot.primitives.moded(3)
        robot.primitives.nothing()
        assert bytes(port.written[before:]).hex(" ") == "ff ff fe 05 03 1e 00 02 d9 ff ff 01 04 04 02 03 f1 ff ff 02 02 06 f5"
        assert general == []
        robot.primitives.goto(5000)  # outside its range: the general way says what is wrong
        robot.primitives.rounded(1e306)  # too large for a float once scaled: likewise
        assert general == ["goto", "rounded"]
    finally:
        del robot._call_primitive


def test_a_drivers_typed_input_hands_its_one_step_request_to_the_write(tmp_path: Path) -> None:
    source = Path(__file__).parent.parent / "runtime" / "data" / "fast_create.rdis"
    port = ScriptedPort()
    robot = import_driver(source, tmp_path, "fast_create_typed").connect({"btserial": port}, threads=False)
    general: list[list[Any]] = []
    robot._input_in_full = lambda plan, values: general.append(values)  # the general way, counted
    del port.written[:]  # the startup hook's
    try:
        robot.inputs.set_velocity(linear=0.2, angular=0.0)
        robot.set_velocity(linear=-0.2, angular=-0.4)
        assert bytes(port.written).hex(" ") == "89 00 c8 7f ff 89 ff 38 01 f4"  # thesis Table 4.3
        assert general == []
        robot.inputs.set_velocity(linear=0, angular=0.0)  # an int: the general way makes it a float
        assert general == [[0, 0.0]]
    finally:
        del robot._input_in_full


def test_a_typed_method_takes_the_one_step_first_and_is_made_once() -> None:
    for robot, _port in _robots():
        counted: list[Any] = []
        robot._primitive = lambda plan, _args, seen=counted: seen.append(plan)  # the general way, counted (this instance's): it writes nothing
        try:
            robot.primitives.goto(100)
            robot.primitives.drive(1, 2)
            robot.call_primitive("goto", 5000)  # out of range: the general way says so
        except Exception:  # noqa: BLE001, S110 - the counted general way wrote nothing
            pass
        finally:
            del robot._primitive
        assert len(counted) == 1
        assert robot.primitives is robot.primitives  # the typed methods' object is made once
    runtime = _robots()[0][0]
    assert runtime.primitives.drive is runtime.primitives.drive  # the runtime's method kept, not made each call


NO_PARAMETERS = """\
robot computed { author "tests" }
frame f1(q0: int, q1: int) {
    length "B" = payload
    literal "\\xFF\\xFF"
    field d0 "B" = q0
    payload
}
connection c0: serial { baud 9600 }
primitive p1() on c0 frame f1(0, 0) pack "<b" ((0 + 0))
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_primitive_of_no_parameters_and_a_computed_value_is_written_in_one_step(tmp_path: Path, kind: str) -> None:
    """Found by the differential test: its driver wrote `if :` where no parameter is checked."""
    from tests.engine.test_one_engine import implementation_of
    from tests.support.ports import ScriptedPort

    port = ScriptedPort()
    with implementation_of(kind, NO_PARAMETERS, tmp_path, f"computed_{kind}").connect(port, threads=False) as robot:
        robot.call_primitive("p1")
    assert port.writes == [b"\x01\xff\xff\x00\x00"]


BYTES_RANGE = """\
robot bytes_range { author "tests" }
connection c0: serial { baud 9600 }
primitive p0(a0: int, a1: bytes in 0..2) on c0 pack "<b" (a0)
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_bytes_parameters_range_is_of_its_length_in_one_step_too(tmp_path: Path, kind: str) -> None:
    """Found by the differential test: the runtime's one step compared the range with the bytes
    themselves (a TypeError), the driver's compared them as bytes; the range is of their length."""
    from tests.engine.test_one_engine import implementation_of

    port = ScriptedPort()
    with implementation_of(kind, BYTES_RANGE, tmp_path, f"bytes_range_{kind}").connect(port, threads=False) as robot:
        robot.call_primitive("p0", 5, b"")
        robot.call_primitive("p0", 6, b"\xff\xff")
        with pytest.raises(Exception, match=r"^p0: parameter a1 has 3 bytes, outside 0\.\.2$") as raised:
            robot.call_primitive("p0", 7, b"abc")
    assert type(raised.value).__name__ == "RdisValueError"
    assert port.writes == [b"\x05", b"\x06"]
