"""A lookup miss in a reply (`MODE[out[0]]` for a code the table lacks) is a reply the primitive
cannot read: an RdisProtocolError, read past under `skip unmatched` like a reply that does not
decode, and no state changes. In the runtime and a generated driver alike, over a scripted port."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.engine.test_one_engine import ScriptedPort, implementation_of

MODES = """\
robot modes { author "tests" }
connection link: serial { baud 9600 }
const MODE = { 1: "idle", 2: "run" }
state mode: string = ""
state raw: int = 0
frame packet { header "\\xAA"  payload }
/// The mode as a name; another device's code on the bus is read past.
primitive listen() on link frame packet format "" () skip unmatched unpack "BB" { mode = MODE[out[0]]  raw = out[1] }
/// The same, where a code without a name is an error.
primitive read() on link frame packet pack "B" (0x4D) unpack "BB" { mode = MODE[out[0]]  raw = out[1] }
/// Without a frame: A0 and the mode's code, among other messages.
primitive stream() on link format "" () skip unmatched reply tag "B" {
    0xA0: unpack "B" { mode = MODE[out[0]] }
    0xB0: unpack "B" { raw = out[0] }
}
frame sized { header "\\xAA"  length "B" = payload  payload }
/// A framed reply chosen by its tag: a message whose code has no name is another's, read past.
primitive framed() on link frame sized pack "B" (0x4D) skip unmatched reply tag "B" {
    0xA0: unpack "B" { mode = MODE[out[0]] }
    0xB0: unpack "B" { raw = out[0] }
}
/// The same without `skip unmatched`: a code without a name is an error.
primitive framed_strict() on link frame sized pack "B" (0x4D) reply tag "B" {
    0xA0: unpack "B" { mode = MODE[out[0]] }
    0xB0: unpack "B" { raw = out[0] }
}
/// Sub-payloads, each a tag and its length: a frame with a code without a name is read past whole.
primitive feedback() on link frame sized pack "B" (0x46) skip unmatched reply each tag "B" length "B" {
    0xA0: unpack "B" { mode = MODE[out[0]] }
    0xB0: unpack "B" { raw = out[0] }
}
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_lookup_miss_is_read_past_under_skip_unmatched(kind: str, tmp_path: Path) -> None:
    seen: list[tuple[str, str]] = []
    port = ScriptedPort(bytes.fromhex("aa 07 01  aa 02 05"))  # code 7 has no name: read past
    implementation = implementation_of(kind, MODES, tmp_path, "modes")
    with implementation.connect(port, threads=False, on_io=lambda d, _c, b: seen.append((d, b.hex(" ")))) as robot:
        robot.call_primitive("listen")
        assert (robot.state["mode"], robot.state["raw"]) == ("run", 5)
    assert seen == [("write", "aa"), ("read", "aa 07 01 aa 02 05")]  # the header of an empty request


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_lookup_miss_is_a_protocol_error_that_changes_no_state(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(bytes.fromhex("aa 07 01"))
    implementation = implementation_of(kind, MODES, tmp_path, "modes")
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "read: reply (7, 1): table MODE has no entry for 7")
        assert (robot.state["mode"], robot.state["raw"]) == ("", 0)
    assert bytes(port.written) == bytes.fromhex("aa 4d")


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_tagged_message_whose_lookup_misses_is_read_past(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(bytes.fromhex("a0 07  b0 a0  a0 02"))  # A0 07: no name; then B0's A0, then A0 02
    implementation = implementation_of(kind, MODES, tmp_path, "modes")
    with implementation.connect(port, threads=False) as robot:
        robot.call_primitive("stream")
        assert (robot.state["mode"], robot.state["raw"]) == ("", 0xA0)
        robot.call_primitive("stream")
        assert (robot.state["mode"], robot.state["raw"]) == ("run", 0xA0)


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_framed_tagged_reply_whose_lookup_misses_is_read_past(kind: str, tmp_path: Path) -> None:
    """A framed reply table under `skip unmatched` reads past a frame whose lookup misses, as it
    reads past one that does not decode; without it, the miss is an RdisProtocolError."""
    port = ScriptedPort(bytes.fromhex("aa 02 a0 07  aa 02 a0 02"  # A0 07: no name, read past; then A0 02
                                      "aa 02 a0 09"  # framed_strict: an error, no state changed
                                      "aa 06 b0 01 06 a0 01 07  aa 06 b0 01 06 a0 01 01"))  # feedback: the second
    implementation = implementation_of(kind, MODES, tmp_path, "modes")
    with implementation.connect(port, threads=False) as robot:
        robot.call_primitive("framed")
        assert (robot.state["mode"], robot.state["raw"]) == ("run", 0)
        with pytest.raises(Exception) as caught:
            robot.call_primitive("framed_strict")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "framed_strict: reply (9,): table MODE has no entry for 9")
        assert robot.state["mode"] == "run"
        robot.call_primitive("feedback")
        assert (robot.state["mode"], robot.state["raw"]) == ("idle", 6)
    assert bytes(port.written) == bytes.fromhex("aa 01 4d  aa 01 4d  aa 01 46")


PLAIN = """\
robot plain { author "tests" }
connection link: serial { baud 9600 }
const MODE = { 1: "idle", 2: "run" }
state mode: string = ""
/// No frame, no retry: a plain exchange, read and decoded in one step.
primitive read() on link pack "B" (0x4D) unpack "B" { mode = MODE[out[0]] }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_lookup_miss_in_a_plain_exchange_is_a_protocol_error_too(kind: str, tmp_path: Path) -> None:
    """The one-step read of a plain exchange (no frame, a fixed size) says a miss as the general
    way does (it said an RdisValueError, as if a value the host computed were wrong)."""
    port = ScriptedPort(bytes.fromhex("02 07"))
    with implementation_of(kind, PLAIN, tmp_path, "plain").connect(port, threads=False) as robot:
        robot.call_primitive("read")
        assert robot.state["mode"] == "run"
        with pytest.raises(Exception) as caught:
            robot.call_primitive("read")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "read: reply (7,): table MODE has no entry for 7")
        assert robot.state["mode"] == "run"
