"""What a typed call costs a generated driver, in Python calls (counted, not timed): its method
makes the request in one step (its values tested, packed by one precompiled struct, constants
folded) and writes it itself through its connection's lane (the port's lock and write), or hands
it to the engine's plain exchange, so that a command is the method and the port's write. benchmarks/driver_speed.py's figures depend on it, and a
count does not depend on the machine. Whatever the step, the bytes and errors are the general way's.
"""

from __future__ import annotations

import struct
from pathlib import Path
from typing import Any

import pytest

from rdisc.emit.python import import_driver
from tests.support.calls import calls_made
from tests.support.ports import ScriptedPort

ROOT = Path(__file__).resolve().parents[2]
FAST_CREATE = ROOT / "tests" / "runtime" / "data" / "fast_create.rdis"  # examples/create.rdis, no delay after a drive
TABLE_4_3 = [((-0.2, -0.4), "89 ff38 01f4"), ((0.0, 0.0), "89 0000 0000"), ((0.0, 0.2), "89 0000 ffff"),
             ((0.0, -0.2), "89 0000 0001"), ((0.2, 0.0), "89 00c8 7fff"), ((-0.2, 0.0), "89 ff38 7fff")]
PACKET_100 = struct.Struct(">B6?BBxBBhhBHhbHHH4H3xBBB?B6hB6HBB4hB")  # as examples/create2.rdis reads it



@pytest.fixture(scope="module")
def drivers(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    folder = tmp_path_factory.mktemp("typed_cost")
    return {name: import_driver(path, folder, f"{name}_cost_driver") for name, path in (
        ("create", FAST_CREATE), ("ax12", ROOT / "examples" / "ax12.rdis"), ("create2", ROOT / "examples" / "create2.rdis"))}


@pytest.mark.parametrize("way", ["robot", "inputs"])
def test_set_velocity_is_the_method_and_the_port(drivers: dict[str, Any], way: str) -> None:
    """The six rows of Table 4.3: the method (the speed's clamp inline: `_clamp`'s test of a name,
    the port's lock and write through its lane), the port's write; the first row divides (`_div`,
    which refuses a zero) and clamps the quotient (`_clamp`) besides. `robot.inputs.set_velocity`
    calls the robot's method. 38 calls either way before (the input's function and `_send_input`
    besides), one more a row before the clamp was inline, one more (the robot's write) before the
    method wrote through the lane."""
    port = ScriptedPort()
    with drivers["create"].connect({"btserial": port}, threads=False) as robot:
        send = robot.set_velocity if way == "robot" else robot.inputs.set_velocity
        made = []
        for (linear, angular), expected in TABLE_4_3:
            del port.written[:]
            made.append(calls_made(lambda v=linear, w=angular: send(linear=v, angular=w)))
            assert bytes(port.written) == bytes.fromhex(expected)
    assert made == ([4] + [2] * 5 if way == "robot" else [5] + [3] * 5), made


def test_an_interface_of_one_plain_write_is_the_method_and_the_port(drivers: dict[str, Any]) -> None:
    """`robot.interfaces.drive(0.2, 32.767)`: its one call's values packed in the method (`round` of
    Python's `*`) and written through the lane, the port's write; given ints (not floats), the
    general way writes the same bytes. 16 calls before (the interface run the general way), 3 with
    the robot's write."""
    port = ScriptedPort()
    with drivers["create"].connect({"btserial": port}, threads=False) as robot:
        del port.written[:]
        made = calls_made(lambda: robot.interfaces.drive(0.2, 32.767))
        robot.interfaces.drive(0, -1)
        assert bytes(port.written) == bytes.fromhex("89 00c8 7fff 89 0000 fc18")
    assert made == 2, made


def test_a_typed_input_given_ints_goes_the_general_way_to_the_same_bytes(drivers: dict[str, Any]) -> None:
    """An int for a float field is not the one step's (its type is tested): the general way makes
    it a float and writes what the floats write."""
    port = ScriptedPort()
    with drivers["create"].connect({"btserial": port}, threads=False) as robot:
        del port.written[:]
        robot.set_velocity(linear=0, angular=0)
        robot.inputs.set_velocity(linear=0.2, angular=0)
        assert bytes(port.written) == bytes.fromhex("89 0000 0000 89 00c8 7fff")


@pytest.mark.parametrize(("driver", "connection", "primitive", "args", "expected"), [
    ("ax12", "bus", "goto_all", (512,), "FF FF FE 05 03 1E 00 02 D9"),
    ("create2", "oi", "drive_direct", (-500, 123), "91 fe0c 007b"),
])
def test_a_typed_write_is_the_method_and_the_port(drivers: dict[str, Any], driver: str, connection: str,
                                                  primitive: str, args: tuple[int, ...], expected: str) -> None:
    """AX-12 goto_all(512), a framed broadcast write with its checksum summed inline, and the
    Create 2's drive_direct: the method (its range tested inline, the port's lock and write
    through its lane) and the port's write (`robot.primitives` a slot of the robot's). 6 calls
    before (the `primitives` property, the request's function, `_send`), 3 with the robot's write."""
    port = ScriptedPort()
    with drivers[driver].connect({connection: port}, threads=False) as robot:
        del port.written[:]
        assert calls_made(lambda: getattr(robot.primitives, primitive)(*args)) == 2
        assert bytes(port.written) == bytes.fromhex(expected)


def test_a_typed_write_out_of_range_is_refused_as_the_general_way_refuses_it(drivers: dict[str, Any]) -> None:
    port = ScriptedPort()
    driver = drivers["ax12"]
    with driver.connect({"bus": port}, threads=False) as robot:
        del port.written[:]
        with pytest.raises(driver.RdisValueError) as typed:
            robot.primitives.goto_all(1024)
        with pytest.raises(driver.RdisValueError) as general:
            robot.call_primitive("goto_all", 1024)
        assert str(typed.value) == str(general.value)
        assert "1024" in str(typed.value) and bytes(port.written) == b""


class Create2:
    """Answers Sensors (142) for packet 100 with its 80 bytes."""

    reply = PACKET_100.pack(5, True, False, False, True, False, False, 24, 40, 161, 0, 12, -35, 2, 15412, -1285,
                            27, 2410, 2696, 12, 1502, 2048, 87, 955, 3, 2, 0, False, 1, -200, 32767, -210, -190,
                            31204, -766, 33, 12, 8, 0, 0, 240, 1180, 161, 160, 303, 299, 42, 18, 2)

    def answer(self, request: bytes) -> bytes:
        return self.reply if request == b"\x8e\x64" else b""

    def listen(self) -> bytes:
        return b""


def test_the_sensor_exchange_is_one_plain_exchange_from_the_method(drivers: dict[str, Any]) -> None:
    """`robot.primitives.sensors()`: the method hands its constant request to the plain exchange
    (`_ask`: one read, one unpack), whose post-actions (`_assign`, the actions' function) store
    the 69 values. The port's own calls are 6 of them (its reset, its write and the device's
    answer, its read of the 80 bytes). 14 calls before (the `primitives` property,
    `_call_primitive`, the engine's composed request and its values' function)."""
    port = ScriptedPort(device=Create2())
    with drivers["create2"].connect({"oi": port}, threads=False) as robot:
        robot.primitives.sensors()
        made = calls_made(lambda: robot.primitives.sensors())
        state = robot.state
        assert (state["bump_right"], state["bump_left"], state["wheel_drop_left"], state["wall"]) == (
            True, False, False, True)
        assert (state["voltage"], state["current"], state["left_encoder"], state["stasis_disabled"]) == (
            15412, -1285, 31204, True)
    assert port.writes[-2:] == [b"\x8e\x64", b"\x8e\x64"]
    assert made == 10, made


PARAMETERS_NAMED_AS_THE_STEP = """\
robot shadowing { author "tests" }
connection link: serial { baud 57600 }
primitive put(type: int in 0..255, robot: int in 0..255, request: int) on link pack ">BBBh" (7, type, robot, request)
"""


def test_parameters_named_as_the_step_s_own_names_take_the_general_way(tmp_path: Path) -> None:
    """A parameter named `type`, `robot` or `request` would hide what the one step's statements use:
    the method hands its values to the general way, which writes the same bytes."""
    source = tmp_path / "shadowing.rdis"
    source.write_text(PARAMETERS_NAMED_AS_THE_STEP, encoding="utf-8")
    port = ScriptedPort()
    driver = import_driver(source, tmp_path, "shadowing_driver")
    with driver.connect(port, threads=False) as robot:
        robot.primitives.put(type=1, robot=2, request=-3)
        with pytest.raises(driver.RdisValueError):
            robot.primitives.put(type=256, robot=2, request=-3)
    assert port.writes == [bytes.fromhex("07 01 02 fffd")]


@pytest.mark.parametrize("example", sorted(path.name for path in (ROOT / "examples").glob("*.rdis")))
def test_the_lowering_plans_a_plain_exchange_only_where_the_engine_makes_one(example: str) -> None:
    """A typed method hands a request to the engine's plain exchange (`_ask`) where the lowering
    planned one (`Primitive.asked`): the engine's plan of that primitive is one too, by the same
    rule (`asked_at_once`); and it plans one for every plain exchange of parameters without a
    range reading another's."""
    from rdisc.compile import compile_path
    from rdisc.lower import lower
    from rdisc.runtime import load

    model = compile_path(str(ROOT / "examples" / example)).model
    assert model is not None
    planned = {name: plan.asked is not None for name, plan in lower(model).device.primitives.items()}
    made = {name: plan.asked is not None for name, plan in load(model).device.primitives.items()}
    assert planned == made


def test_call_primitive_goes_to_the_typed_method(drivers: dict[str, Any]) -> None:
    """`robot.call_primitive("goto_all", 512)` on a generated driver: one look-up, then the typed
    method (the same specialised function as `robot.primitives.goto_all`), the port's write: 3 calls, 4
    before (the engine's one-step request and its write besides the port's). Other counts of values,
    other types and values out of range go the general way, which says what is wrong."""
    port = ScriptedPort()
    driver = drivers["ax12"]
    with driver.connect({"bus": port}, threads=False) as robot:
        del port.written[:]
        assert calls_made(lambda: robot.call_primitive("goto_all", 512)) == 3
        assert bytes(port.written) == bytes.fromhex("FF FF FE 05 03 1E 00 02 D9")
        for args in [(), (512, 1), (512.0,), (1024,)]:
            with pytest.raises((TypeError, driver.RdisValueError)) as typed:
                robot.call_primitive("goto_all", *args)
            with pytest.raises(type(typed.value)) as general:
                robot._call_primitive(robot.device.primitives["goto_all"], list(args))
            assert str(typed.value) == str(general.value)
        assert bytes(port.written) == bytes.fromhex("FF FF FE 05 03 1E 00 02 D9")
