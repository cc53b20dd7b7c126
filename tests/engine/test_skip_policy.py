"""`skip unmatched`'s policy, runtime and generated driver alike: a frame of another device or
message is read past, and why is told to the trace; a corrupt reply of this device (its constants
and fields right, its checksum wrong) is an RdisProtocolError. After a frame read past, the next is
looked for from the byte after its start, so a real frame that starts inside one that did not
decode is found; a frame a checksum vouched for is read past whole.
"""

from __future__ import annotations

from typing import Any

import pytest

from tests.engine.test_one_engine import implementation_of
from tests.support.ports import ScriptedPort

POLICY = r"""
robot policy { author "tests" }

state v: int = 0

frame summed(id: int) {
    header "\xFF\xFF"
    field id "B" = id
    length "B" = payload + 1
    payload
    checksum "sum" "B" inverted
}
frame bare { header "\xAA"  length "B" = payload  payload }

connection link: serial { baud 9600 }

primitive servo() on link frame summed(1) pack "B" (3) skip unmatched timeout 50 ms unpack "B" { v = out[0] }
primitive plain() on link frame bare pack "B" (3) skip unmatched timeout 50 ms unpack "B" { v = out[0] }
"""


def _summed(id_: int, payload: bytes) -> bytes:
    body = bytes([id_, len(payload) + 1]) + payload
    return b"\xff\xff" + body + bytes([~sum(body) & 0xFF])


@pytest.fixture(scope="module")
def implementations(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    folder = tmp_path_factory.mktemp("policy")
    return {kind: implementation_of(kind, POLICY, folder, f"policy_{kind}") for kind in ("runtime", "driver")}


@pytest.fixture(params=["runtime", "driver"])
def traced(request: pytest.FixtureRequest, implementations: dict[str, Any]):
    """A robot on a port that gives `script`, and its trace: (kind, connection, data) in order."""

    def traced(script: bytes) -> tuple[Any, list[tuple[str, str, bytes]]]:
        robot = implementations[request.param].connect(ScriptedPort(script), threads=False)
        events: list[tuple[str, str, bytes]] = []
        robot.on_trace(lambda when, *event: events.append(event))
        return robot, events

    return traced


def test_another_servos_reply_is_read_past_and_why_is_traced(traced) -> None:
    other = _summed(2, b"\x05")
    robot, events = traced(other + _summed(1, b"\x09"))
    with robot:
        robot.call_primitive("servo")
        assert robot.state["v"] == 9
    assert events == [
        ("write", "link", _summed(1, b"\x03")),
        ("skip", "link", b"servo: summed: reply id is 2, expected 1"),
        ("read", "link", other + _summed(1, b"\x09")),
    ]


def test_a_corrupt_reply_of_this_device_is_an_error_under_skip_unmatched(traced) -> None:
    corrupt = _summed(1, b"\x06")[:-1] + b"\x00"
    robot, events = traced(corrupt + _summed(1, b"\x09"))
    with robot, pytest.raises(Exception, match=r"^servo: summed: checksum ") as raised:
        robot.call_primitive("servo")
    assert type(raised.value).__name__ == "RdisProtocolError"
    assert robot.state["v"] == 0
    assert [kind for kind, _, _ in events] == ["write", "read"]  # nothing read past


def test_a_frame_without_a_checksum_is_rescanned_from_its_second_byte(traced) -> None:
    """AA 03 starts a frame of three bytes that does not decode as one; inside it AA 01 09 is the reply."""
    robot, events = traced(bytes.fromhex("aa 03 aa 01 09"))
    with robot:
        robot.call_primitive("plain")
        assert robot.state["v"] == 9
    assert events == [
        ("write", "link", bytes.fromhex("aa 01 03")),
        ("skip", "link", b"plain: expected 1 bytes, got 3"),
        ("read", "link", bytes.fromhex("aa 03 aa 01 09")),
    ]


def test_a_frame_a_checksum_vouched_for_is_read_past_whole(traced) -> None:
    """Servo 1's reply of another message (five bytes, not one) holds what looks like the start of a
    reply; it is read past whole, so that look-alike (whose checksum would be wrong) is never read."""
    other_message = _summed(1, b"\xff\xff\x01\x02\x00")
    robot, events = traced(other_message + _summed(1, b"\x09"))
    with robot:
        robot.call_primitive("servo")
        assert robot.state["v"] == 9
    assert [kind for kind, _, _ in events] == ["write", "skip", "read"]


def test_nothing_that_matches_is_still_a_timeout(traced) -> None:
    """Read past: servo 2's reply, then the bytes after its first, which hold no header."""
    robot, events = traced(_summed(2, b"\x05"))
    with robot, pytest.raises(Exception, match=r"^servo: no matching reply within 0.05 s$") as raised:
        robot.call_primitive("servo")
    assert type(raised.value).__name__ == "RdisTimeout"
    assert [data for kind, _, data in events if kind == "skip"] == [
        b"servo: summed: reply id is 2, expected 1",
        b"servo: summed: no header b'\\xff\\xff' in the reply (after 3 bytes)",
    ]


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_an_unframed_tagged_message_read_past_is_traced_with_why(kind: str, tmp_path) -> None:
    """Without a frame (Firmata's stream): a tag without an entry, then a message whose lookup
    misses, are read past, each told to the trace with why, before the one that is read."""
    from tests.engine.test_lookup_miss import MODES

    port = ScriptedPort(bytes.fromhex("c3  a0 07  a0 02"))
    events: list[tuple[str, str, bytes]] = []
    with implementation_of(kind, MODES, tmp_path, "modes").connect(port, threads=False) as robot:
        robot.on_trace(lambda when, *event: events.append(event))
        robot.call_primitive("stream")
        assert robot.state["mode"] == "run"
    assert events == [
        ("skip", "link", b"stream: no reply entry for tag 195"),
        ("skip", "link", b"stream: reply (7,): table MODE has no entry for 7"),
        ("skip", "link", b"stream: no reply entry for tag 7"),  # looked for from the byte after its tag
        ("read", "link", bytes.fromhex("c3 a0 07 a0 02")),
    ]
