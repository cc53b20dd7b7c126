"""`terminator` on a connection: reply lines end where the device says, in the
runtime and in the generated driver alike (compared in tests/test_one_semantics.py)."""

from __future__ import annotations

import pytest
from runtime_support import DATA

from rdisc.runtime import RdisProtocolError, load
from tests.support.ports import ScriptedPort


def test_lines_end_at_the_connections_terminator() -> None:
    port = ScriptedPort(b"L,42,mm\rL,7,cm\n\r")
    with load(DATA / "cr_device.rdis").connect(port, threads=False) as robot:
        robot.tick()
        assert dict(robot.state) == {"level": 42, "unit": "mm"}
        robot.tick()  # "\n" is not this device's terminator: it is part of the line
        assert dict(robot.state) == {"level": 7, "unit": "cm"}
        assert port.written == b"L?\rL?\r"


def test_a_line_without_the_terminator_is_a_protocol_error() -> None:
    errors: list[BaseException] = []
    with load(DATA / "cr_device.rdis").connect(ScriptedPort(b"L,42,mm\n"), threads=False, on_error=errors.append) as robot:
        robot.tick()
    assert [type(e) for e in errors] == [RdisProtocolError]
    assert str(errors[0]) == "read_level: reply line not terminated: 'L,42,mm\\n'"


@pytest.mark.parametrize("reply", [b"d\r\n", b"d\n"])
def test_the_default_terminator_takes_lf_and_cr_lf(reply: bytes) -> None:
    from runtime_support import KOALA

    with load(KOALA).connect(ScriptedPort(b"d\r\ng\r\n" + reply), threads=False) as robot:
        robot.call_input("set_velocity", linear=0.0, angular=0.0)
