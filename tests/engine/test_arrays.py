"""Arrays: a fixed number of values of one type (`int[6]`) in state and parameters. Elements
are read as `position[i]` and stored in post-actions as `position[id] = out[0]`; an array
argument of `pack` gives its elements as that many values; a range bounds each element. An
index outside the array is refused, never wrapped: at check time when it is a constant, as an
RdisValueError when it runs, in the runtime and a generated driver alike."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

ARM = """\
robot arm { author "tests" }
const IDS = [1, 2, 3]
state position: int[3]
state home: float[3] = [0, 0.5, 1]
connection bus: serial { baud 57600 }
primitive sync_goal(goal: int[3] in 0..4095) on bus pack "<BHHBHBHBH" (0x83, 30, 2, IDS[0], goal[0], IDS[1], goal[1],
                                                                       IDS[2], goal[2])
primitive goals(goal: int[3]) on bus pack "<B3H" (0x84, goal)
primitive read_one(id: int) on bus pack "<Bb" (0x02, id) unpack "<H" { position[id] = out[0] }
primitive read_all() on bus pack "B" (0x05) unpack "<3H" { position[2] = out[0]  position[0] = out[2] }
interface move_all(goal: int[3]) { sync_goal(goal) }
interface park() { goals([512, 512, 512]) }
interface tilt(by: int) { goals([position[0] + by, position[1] + by, position[2] + by]) }
interface rest() { goals([round(home[0] * 100), round(home[1] * 100), round(home[2] * 100)]) }
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, ARM, tmp_path_factory.mktemp("arrays"), "arm")


def test_an_array_gives_its_elements_to_the_format(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.interfaces.move_all([100, 200, 300])
        assert bytes(port.written).hex(" ") == "83 1e 00 02 00 01 64 00 02 c8 00 03 2c 01"
        port.written.clear()
        robot.interfaces.park()
        assert bytes(port.written).hex(" ") == "84 00 02 00 02 00 02"
        assert robot.state["position"] == (0, 0, 0)
        assert robot.state["home"] == (0.0, 0.5, 1.0)


def test_post_actions_store_elements(implementation: Any) -> None:
    port = ScriptedPort(bytes.fromhex("3412" "0100 0200 0300"))
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.read_one(1)
        assert robot.state.position == (0, 0x1234, 0)
        robot.primitives.read_all()  # out[0] into position[2], out[2] into position[0]: both kept
        assert robot.state.position == (3, 0x1234, 1)
        port.written.clear()
        robot.interfaces.tilt(10)
        assert bytes(port.written).hex(" ") == "84 0d 00 3e 12 0b 00"
        port.written.clear()
        robot.interfaces.rest()
        assert bytes(port.written).hex(" ") == "84 00 00 32 00 64 00"


def test_an_index_outside_the_array_is_refused_when_it_runs(implementation: Any) -> None:
    port = ScriptedPort(bytes.fromhex("3412" "3412"))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(ValueError, match=r"^read_one: index 3 is outside position, which has 3 values$"):
            robot.primitives.read_one(3)
        with pytest.raises(ValueError, match=r"^read_one: index -1 is outside position"):
            robot.primitives.read_one(-1)
        assert robot.state.position == (0, 0, 0)


def test_each_element_is_checked_before_anything_is_written(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(ValueError, match=r"sync_goal: parameter goal\[2\] is 5000, outside 0\.\.4095"):
            robot.interfaces.move_all([1, 2, 5000])
        with pytest.raises(TypeError, match=r"move_all: parameter goal must have 3 values, not 2"):
            robot.interfaces.move_all([1, 2])
        with pytest.raises(TypeError, match=r"move_all: parameter goal must be a list of 3 ints, not int"):
            robot.interfaces.move_all(7)
        assert bytes(port.written) == b""


def test_arrays_go_through_json_the_printer_and_dump(tmp_path: Path, rdisc) -> None:
    compilation, built = through_json(ARM, tmp_path, "arm")
    assert not compilation.diagnostics.items
    document = json.loads(built)
    assert document["constants"] == {"IDS": [1, 2, 3]}
    assert document["stateVariables"][1] == {"name": "home", "type": "float[3]", "value": "<[0.0, 0.5, 1.0]>"}
    (read_all,) = [p for p in document["primitives"] if p["name"] == "read_all"]
    assert read_all["postActions"] == ["position[2] = __out__[0]", "position[0] = __out__[2]"]
    printed = print_module(parse("arm.rdis", ARM, Diagnostics()))
    assert "state home: float[3] = [0, 0.5, 1]\n" in printed
    assert print_module(parse("again.rdis", printed, Diagnostics())) == printed
    dump = rdisc("dump", tmp_path / "arm.rdis").stdout
    assert "       5     1  u8                    01 (1)\n       6     2  u16 LE                goal[0]\n" in dump


# What the checker refuses in arrays: tests/semantics/cases/arrays.rdis.


JOINTS = """\
robot joints { author "tests" }
const NAMES = ["pan", "tilt"]
state ticks: int[2] = [512, 1023]
connection link: serial { baud 9600 }
primitive goto(goal: int[2] in 0..1023) on link pack "<B2H" (0x84, goal)
interface move(rad: float[2]) triggers joints { goto([round(rad[0] * 325.95) + 512, round(rad[1] * 325.95) + 512]) }
output joints: JointState { name = NAMES  position = [(ticks[0] - 512) / 325.95, (ticks[1] - 512) / 325.95] }
input aim: JointState -> move(position)
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_joint_state_carries_every_joint(tmp_path: Path, kind: str) -> None:
    """The standard JointState's arrays take their size from the description: an input of
    another size is refused before anything is written."""
    port = ScriptedPort()
    with implementation_of(kind, JOINTS, tmp_path, "joints").connect(port, threads=False) as robot:
        delivered: list[dict[str, Any]] = []
        robot.on_output(delivered.append)
        robot.inputs.aim(name=["pan", "tilt"], position=[0.5, -1.0])
        assert bytes(port.written).hex(" ") == "84 a3 02 ba 00"
        assert delivered == [{"name": "joints", "contents": {"name": ("pan", "tilt"),
                                                            "position": (0.0, 511 / 325.95)}}]
        with pytest.raises(ValueError, match=r"^aim: move takes 2 values for rad, not 3$"):
            robot.inputs.aim(name=["pan", "tilt", "roll"], position=[0.0, 0.0, 0.0])
        assert bytes(port.written).hex(" ") == "84 a3 02 ba 00"


GROUPS = """\
robot servos { author "tests" }
const IDS = [1, 2, 3]
state position: int[3]
state load: int[3]
connection bus: serial { baud 57600 }
primitive sync_goal(goal: int[3] in 0..4095) on bus pack "<BHH3(BI)" (0x83, 116, 4, IDS, goal)
primitive sync_read() on bus pack "B" (0x82) unpack "<B3(Hb)" { position = out[1]  load = out[2] }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_repeated_group_interleaves_its_arrays(tmp_path: Path, kind: str) -> None:
    """`3(BI)` takes two arrays of 3 and writes ID, goal, ID, goal, ...; `3(Hb)` in a reply
    gives one array a code."""
    port = ScriptedPort(bytes.fromhex("07" "0100ff" "0200fe" "030000"))
    with implementation_of(kind, GROUPS, tmp_path, "servos").connect(port, threads=False) as robot:
        robot.primitives.sync_goal([10, 20, 4095])
        assert bytes(port.written).hex(" ") == "83 74 00 04 00 01 0a 00 00 00 02 14 00 00 00 03 ff 0f 00 00"
        robot.primitives.sync_read()
        assert (robot.state.position, robot.state.load) == ((1, 2, 3), (-1, -2, 0))


def test_a_repeated_group_in_dump_and_json(tmp_path: Path, rdisc) -> None:
    """What the checker refuses of a group is in tests/semantics/cases/arrays.rdis."""
    _, built = through_json(GROUPS, tmp_path, "servos")
    assert '"pack": "<BHH3(BI)"' in built
    dump = rdisc("dump", tmp_path / "servos.rdis").stdout
    assert ("       5     1  u8                    01 (1)\n       6     4  u32 LE                goal[0]\n"
            "      10     1  u8                    02 (2)\n") in dump
    assert "       3     1  s8                    out[2][0]\n       4     2  u16 LE                out[1][1]\n" in dump
