"""`retry N`: a request whose reply timed out or did not match is sent again, the same bytes,
up to N more times (as published drivers resend); after the last try the typed error says how
many tries were made. Alike in the runtime and a generated driver."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

SERVO = """\
robot servo { author "tests" }
state position: int = 0
connection link: serial { baud 57600 }
/// The position of servo `id`: its reply echoes the id.
primitive read(id: int in 0..253) on link pack "BB" (0x02, id) unpack "<BH" expect out[0] == id retry 2
    { position = out[1] }
primitive once(id: int in 0..253) on link pack "BB" (0x02, id) unpack "<BH" expect out[0] == id
    { position = out[1] }
"""


class Dropping:
    """A servo that answers every request with its position, but loses its first `lost` replies
    (silent) and garbles the next `garbled` (another servo's id)."""

    def __init__(self, lost: int = 0, garbled: int = 0) -> None:
        self.lost = lost
        self.garbled = garbled

    def answer(self, request: bytes) -> bytes:
        if self.lost:
            self.lost -= 1
            return b""
        if self.garbled:
            self.garbled -= 1
            return bytes([request[1] + 1]) + (512).to_bytes(2, "little")
        return bytes([request[1]]) + (512).to_bytes(2, "little")

    def listen(self) -> bytes:
        return b""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, SERVO, tmp_path_factory.mktemp("retry"), "servo")


def test_a_lost_reply_is_asked_for_again_with_the_same_bytes(implementation: Any) -> None:
    port = ScriptedPort(device=Dropping(lost=1))
    with implementation.connect(port, threads=False) as robot:
        robot.call_primitive("read", 7)
        assert port.writes == [b"\x02\x07", b"\x02\x07"]
        assert robot.state["position"] == 512


def test_a_reply_that_does_not_match_is_asked_for_again(implementation: Any) -> None:
    port = ScriptedPort(device=Dropping(garbled=2))
    with implementation.connect(port, threads=False) as robot:
        robot.call_primitive("read", 7)
        assert port.writes == [b"\x02\x07"] * 3
        assert robot.state["position"] == 512


def test_after_the_last_try_the_timeout_says_how_many(implementation: Any) -> None:
    port = ScriptedPort(device=Dropping(lost=3))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:  # the driver's RdisTimeout is its own class
            robot.call_primitive("read", 7)
        assert type(caught.value).__name__ == "RdisTimeout"
        assert str(caught.value) == "read: no reply within 1 s (3 tries)"
        assert port.writes == [b"\x02\x07"] * 3
        assert robot.state["position"] == 0
        robot.call_primitive("read", 7)  # the device answers again: the next call succeeds
        assert robot.state["position"] == 512


def test_after_the_last_try_a_mismatch_is_a_protocol_error(implementation: Any) -> None:
    port = ScriptedPort(device=Dropping(garbled=5))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read", 7)
        assert type(caught.value).__name__ == "RdisProtocolError"
        assert str(caught.value) == "read: reply (8, 512) does not meet its `expect` (3 tries)"
        assert port.writes == [b"\x02\x07"] * 3


def test_without_retry_one_try(implementation: Any) -> None:
    port = ScriptedPort(device=Dropping(lost=1))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("once", 7)
        assert str(caught.value) == "once: no reply within 1 s"
        assert port.writes == [b"\x02\x07"]


def test_retry_goes_through_json_and_back(tmp_path: Path) -> None:
    compilation, built = through_json(SERVO, tmp_path, "servo")
    assert not compilation.diagnostics.items
    counts = {p["name"]: p.get("retry") for p in json.loads(built)["primitives"]}
    assert counts == {"read": 2, "once": None}


def test_retry_is_printed_back_as_written() -> None:
    diagnostics = Diagnostics()
    printed = print_module(parse("servo.rdis", SERVO, diagnostics))
    assert not diagnostics.items
    assert '    expect out[0] == id\n    retry 2 { position = out[1] }\n' in printed
    again = Diagnostics()
    assert print_module(parse("servo.rdis", printed, again)) == printed and not again.items
