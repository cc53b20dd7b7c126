"""A plain write (`Exchange._write`: a request with no reply, every command's path) is chosen once,
not tested at each write: on open ports no I/O or trace callback watches, a closure over the port's
lock and write; the watched way once a callback comes, even after the robot opened. Either way
the same bytes, the same refusal once the robot closes, the same typed error for a failing port,
on one port or several. Alike in the runtime and a generated driver."""

from __future__ import annotations

from typing import Any

import pytest

from tests.engine.test_one_engine import implementation_of
from tests.support.ports import ScriptedPort

TWO_PORTS = """\
robot two_ports { author "tests" }
connection left: serial { baud 57600 }
connection right: serial { baud 57600 }
primitive go(speed: int in -500..500) on left pack ">Bh" (1, speed)
primitive turn(rate: int in 0..255) on right pack "BB" (2, rate)
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, TWO_PORTS, tmp_path_factory.mktemp("plain_write"), "plain_write")


def test_a_callback_that_comes_after_opening_sees_the_next_writes(implementation: Any) -> None:
    port = ScriptedPort()
    seen: list[tuple[str, bytes]] = []
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.go(1)
        robot.on_io(lambda kind, connection, data: seen.append((connection, data)))
        robot.primitives.go(2)
        robot.call_primitive("turn", 3)
        robot.on_trace(lambda when, kind, connection, data: seen.append(("trace", data)))
        robot.primitives.turn(4)
    assert port.writes[:4] == [b"\x01\x00\x01", b"\x01\x00\x02", b"\x02\x03", b"\x02\x04"]
    assert seen[:4] == [("left", b"\x01\x00\x02"), ("right", b"\x02\x03"), ("right", b"\x02\x04"),
                        ("trace", b"\x02\x04")]


def test_each_connection_writes_to_its_own_port(implementation: Any) -> None:
    left, right = ScriptedPort(), ScriptedPort()
    with implementation.connect({"left": left, "right": right}, threads=False) as robot:
        robot.primitives.go(-500)
        robot.call_primitive("turn", 255)
        robot.primitives.turn(0)
    assert (left.writes, right.writes) == ([b"\x01\xfe\x0c"], [b"\x02\xff", b"\x02\x00"])


def test_a_closed_robot_or_a_failing_port_is_the_same_typed_error(implementation: Any) -> None:
    left, right = ScriptedPort(), ScriptedPort()
    robot = implementation.connect({"left": left, "right": right}, threads=False)
    right.fail = True
    with pytest.raises(Exception) as failed:
        robot.primitives.turn(1)
    assert (type(failed.value).__name__, str(failed.value)) == ("RdisConnectionError",
                                                               "right: [Errno 5] the device is gone")
    robot.close()
    for send in (lambda: robot.primitives.go(1), lambda: robot.call_primitive("go", 1), lambda: robot._write(
            robot.device.primitives["go"], b"\x01\x00\x01")):
        with pytest.raises(Exception) as refused:
            send()
        assert type(refused.value).__name__ == "RdisConnectionError"
    assert left.writes == []
