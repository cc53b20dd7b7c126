"""A SLIP packet as rdisc writes and reads it is the one sliplib (0.7.2) sends and receives.

Why: RFC 1055 sends END (C0) after a packet, and C0 and DB inside it as DB DC and DB DD;
many senders put an END before each packet too. The description says both with `escape`
(without and with `header "\\xC0"`); sliplib's `Driver` is an independent reading of the RFC,
with and without its leading END. Both the runtime and the generated driver are checked.
"""

from __future__ import annotations

from pathlib import Path

import pytest

slip = pytest.importorskip("sliplib.slip")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

BARE = """\
robot slip { author "tests" }
state size: int = 0
state first: int = 0
state last: int = 0
connection link: serial { baud 115200 }
frame slip { payload  terminator "\\xC0"  escape "\\xDB" { "\\xC0": "\\xDC", "\\xDB": "\\xDD" } }
primitive send(data: bytes in 0..600) on link frame slip pack "*" (data)
primitive receive() on link frame slip pack "*" (b"") unpack "BB*" { first = out[0]  last = out[1]  size = len(out[2]) }
"""
LEADING = BARE.replace('frame slip { payload', 'frame slip { header "\\xC0"  payload')
MESSAGES = [b"\x00\x01", b"\xc0\xdb", b"\xdb\xdc\xc0\xdd", bytes(range(256)) * 2, b"\xdb" * 600]


def driver(leading: bool) -> slip.Driver:
    with slip.config.use_leading_end_byte(leading):
        return slip.Driver()


@pytest.mark.parametrize("kind", ["runtime", "driver"])
@pytest.mark.parametrize("leading", [False, True])
def test_packets_are_sent_as_sliplib_sends_them(kind: str, leading: bool, tmp_path: Path) -> None:
    port = ScriptedPort()
    text = LEADING if leading else BARE
    with implementation_of(kind, text, tmp_path, f"send_{leading}").connect(port, threads=False) as robot:
        for message in MESSAGES:
            port.written.clear()
            robot.call_primitive("send", message)
            assert bytes(port.written) == driver(leading).send(message)
            receiver = slip.Driver()
            receiver.receive(bytes(port.written))
            assert receiver.get(block=False) == message


@pytest.mark.parametrize("kind", ["runtime", "driver"])
@pytest.mark.parametrize("leading", [False, True])
def test_packets_sliplib_sends_are_read(kind: str, leading: bool, tmp_path: Path) -> None:
    """Read through either description: a leading END is an empty packet to the one without it."""
    sender = driver(leading)
    for name, text in (("bare", BARE), ("leading", LEADING)) if leading else (("bare", BARE),):
        port = ScriptedPort(b"".join(sender.send(message) for message in MESSAGES))
        with implementation_of(kind, text, tmp_path, f"{name}_{leading}").connect(port, threads=False) as robot:
            for message in MESSAGES:
                robot.call_primitive("receive")
                assert (robot.state["first"], robot.state["last"], robot.state["size"]) == (
                    message[0], message[1], len(message) - 2)
