"""One engine: the runtime and every generated driver run `rdisc.engine`, the driver
carrying its modules' text byte for byte; the cases where the two used to disagree
now behave as the contract says, in both; the public face is the same in both."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from rdisc import engine
from rdisc.compile import Compilation, compile_path
from rdisc.emit.canonical import to_json
from rdisc.emit.python import import_driver
from rdisc.engine import carry
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

ROOT = Path(__file__).resolve().parents[2]

DISAGREEMENTS = r"""
robot disagreements { author "tests" }

state v: int = 0

frame named { request { field a "B" = 0x81  payload } reply { field a "B" = 0x90  payload } }
frame ended { request { payload } reply { payload  terminator "\xFF" } }
frame summed(id: int) {
    header "\xFF\xFF"
    field id "B" = id
    length "B" = payload + 1
    payload
    checksum "sum" "B" inverted
}

connection link: serial { baud 9600 }

primitive same_name() on link frame named pack "B" (1) unpack "B" { v = out[0] }
primitive tagged() on link frame ended pack "B" (2) reply tag "B" {
    0x10: unpack "B" { v = out[0] }
    0x11: unpack "<H" { v = out[0] }
}
primitive skipping() on link frame summed(1) pack "B" (3) skip unmatched timeout 50 ms unpack "B" { v = out[0] }
primitive strict() on link frame summed(1) pack "B" (4) unpack "B" { v = out[0] }
"""


def implementation_of(kind: str, text: str, folder: Path, name: str) -> Any:
    """A description's text run by the runtime (`kind` "runtime") or as its generated driver."""
    source = folder / f"{name}.rdis"
    source.write_text(text, encoding="utf-8")
    return load(source) if kind == "runtime" else import_driver(source, folder, f"{name}_driver")


def through_json(text: str, folder: Path, name: str) -> tuple[Compilation, str]:
    """Compile a description's text and read its canonical JSON back: the JSON must come out
    the same. Returns the compilation and the JSON."""
    source = folder / f"{name}.rdis"
    source.write_text(text, encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None
    built = to_json(compilation.model)
    (folder / f"{name}.json").write_text(built, encoding="utf-8")
    again = compile_path(str(folder / f"{name}.json"))
    assert again.model is not None and to_json(again.model) == built
    return compilation, built


def _frame(id_: int, payload: bytes) -> bytes:
    body = bytes([id_, len(payload) + 1]) + payload
    return b"\xff\xff" + body + bytes([~sum(body) & 0xFF])


@pytest.fixture(scope="module")
def implementations(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    folder = tmp_path_factory.mktemp("disagreements")
    source = folder / "disagreements.rdis"
    source.write_text(DISAGREEMENTS, encoding="utf-8")
    return {"runtime": load(source), "driver": import_driver(source, folder, "disagreements_driver")}


@pytest.fixture(params=["runtime", "driver"])
def robot_of(request: pytest.FixtureRequest, implementations: dict[str, Any]):
    implementation = implementations[request.param]

    def robot_of(script: bytes, on_io=None):
        return implementation.connect(ScriptedPort(script), threads=False, on_io=on_io)

    return robot_of


def test_the_driver_carries_the_engine_byte_for_byte(implementations) -> None:
    driver_text = Path(implementations["driver"].__file__).read_text(encoding="utf-8")
    for section in carry.sections():  # each module's text after its imports, after its marker
        assert f"{section.marker}\n\n\n{section.body}\n" in driver_text
    assert carry.text() in driver_text
    assert driver_text.count("class Robot(") == 1  # the engine once, nothing of it written again


def test_a_reply_field_is_checked_against_its_own_value(robot_of) -> None:
    with robot_of(b"\x90\x07") as robot:
        robot.call_primitive("same_name")
        assert robot.state["v"] == 7
        assert robot.primitives is not None


def test_a_tagged_reply_through_a_terminated_frame_decodes(robot_of) -> None:
    with robot_of(b"\x11\x34\x12\xff") as robot:
        robot.call_primitive("tagged")
        assert robot.state["v"] == 0x1234


def test_skip_unmatched_reads_past_frames_that_do_not_match(robot_of) -> None:
    other_servo = _frame(2, b"\x05")  # a bad checksum from servo 1 is an error: tests/engine/test_skip_policy.py
    with robot_of(other_servo + _frame(1, b"\x09")) as robot:
        robot.call_primitive("skipping")
        assert robot.state["v"] == 9


def test_every_byte_read_is_shown_whatever_became_of_it(robot_of) -> None:
    seen: list[tuple[str, str, bytes]] = []
    bad = _frame(1, b"\x06")[:-1] + b"\x00"
    with robot_of(bad, on_io=lambda *event: seen.append(event)) as robot, \
            pytest.raises(Exception, match="^strict: ") as raised:  # the engine's, or the driver's copy
        robot.call_primitive("strict")
    assert type(raised.value).__name__ == "RdisProtocolError"
    assert seen == [("write", "link", _frame(1, b"\x04")), ("read", "link", bad)]


CREATE = ROOT / "examples" / "create.rdis"


@pytest.fixture(scope="module")
def create(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    folder = tmp_path_factory.mktemp("create")
    return {"runtime": load(CREATE), "driver": import_driver(CREATE, folder, "create_namespaces")}


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_inputs_interfaces_and_primitives_are_methods_by_name(create, kind) -> None:
    port = ScriptedPort()
    robot = create[kind].connect({"btserial": port}, threads=False)
    try:
        del port.written[:]
        robot.inputs.set_velocity(linear=0.2, angular=0.0)
        robot.interfaces.drive(velocity=-0.2, radius=-0.4)
        robot.interfaces.drive(0.0, 0.0)
        robot.primitives.drive(velocity=200, radius=1000)
        robot.primitives.drive(-1, 1)
        assert bytes(port.written) == bytes.fromhex("89 00c8 7fff  89 ff38 fe70  89 0000 0000  89 00c8 03e8  89 ffff 0001")
        with pytest.raises(TypeError):
            robot.interfaces.drive(velocity=0.2, radus=1.0)
        with pytest.raises(TypeError):
            robot.inputs.set_velocity(0.2, 0.0)  # an input's fields are named
    finally:
        robot.close()


def test_mypy_strict_rejects_a_misspelt_keyword(create, tmp_path, mypy_cache) -> None:
    folder = Path(create["driver"].__file__).parent
    script = tmp_path / "use_driver.py"
    script.write_text(
        "from create_namespaces import connect\n\n"
        "robot = connect('loop://')\n"
        "robot.inputs.set_velocity(linear=0.2, angular=0.0)\n"
        "robot.interfaces.drive(velocity=0.2, radus=1.0)\n"
        "robot.primitives.drive(velocity=200, radius=1000)\n",
        encoding="utf-8",
    )
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--no-error-summary", "--cache-dir", str(mypy_cache),
         str(script)],
        capture_output=True, text=True, check=False, cwd=tmp_path, env={"MYPYPATH": str(folder), "PATH": ""},
    )
    assert [line for line in done.stdout.splitlines() if ": error:" in line] == [
        (f'{script.name}:5: error: Unexpected keyword argument "radus" for "drive" of '
         '"IrobotCreateInterfaces"; did you mean "radius"?  [call-arg]'),
    ], done.stdout + done.stderr


TABLE_4_3 = [((-0.2, -0.4), "89 ff38 01f4"), ((0.0, 0.0), "89 0000 0000"), ((0.0, 0.2), "89 0000 ffff"),
             ((0.0, -0.2), "89 0000 0001"), ((0.2, 0.0), "89 00c8 7fff"), ((-0.2, 0.0), "89 ff38 7fff")]


@pytest.fixture(scope="module")
def fast_create(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """The Create without delays: its set_velocity is written at once."""
    source = ROOT / "tests" / "runtime" / "data" / "fast_create.rdis"
    return {"runtime": load(source), "driver": import_driver(source, tmp_path_factory.mktemp("fast"), "fast_create")}


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_input_written_at_once_behaves_as_the_general_way(fast_create, kind) -> None:
    """set_velocity is one plain write, so it goes through `Input.request` (the driver's compiled
    from the expressions, the runtime's a closure of the same plan). The general way (ints for the
    float fields) writes the same bytes, and an error found on the quick way is reported by
    the general way, naming the element at fault."""
    device = fast_create[kind].device if kind == "runtime" else fast_create[kind]._DEVICE
    plan = device.inputs["set_velocity"]
    assert plan.request is not None and plan.primitive is not None and plan.primitive.name == "drive"
    port = ScriptedPort()
    robot = fast_create[kind].connect({"btserial": port}, threads=False)
    try:
        for (linear, angular), expected in TABLE_4_3:
            assert plan.request(robot.state, [linear, angular]) == bytes.fromhex(expected)
            del port.written[:]
            robot.inputs.set_velocity(linear=linear, angular=angular)  # the quick way
            robot.inputs.set_velocity(linear=linear, angular=angular if angular else 0)  # an int: the general way
            assert bytes(port.written) == bytes.fromhex(expected) * 2
        assert plan.request(robot.state, [1e308, 1e-308]) is None  # linear / angular is too large for a float
        value_error = engine.RdisValueError if kind == "runtime" else fast_create[kind].RdisValueError
        with pytest.raises(value_error, match=r"^set_velocity: the result is too large for a float$"):
            robot.inputs.set_velocity(linear=1e308, angular=1e-308)
        assert plan.request(robot.state, [True, 0.0]) is None
        with pytest.raises(TypeError, match=r"^input set_velocity: field linear"):
            robot.inputs.set_velocity(linear=True, angular=0.0)
    finally:
        robot.close()
