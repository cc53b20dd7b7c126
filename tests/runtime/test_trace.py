"""`--trace` tells the truth: each request stamped when it was written, each reply when its last
byte came, every line in the order the bytes crossed the wire across threads, and the reason each
reply `skip unmatched` read past. On a pty device that answers late, runtime and generated driver alike.
"""

from __future__ import annotations

import threading
from pathlib import Path
from typing import Any

import pytest

from rdisc.emit.python import import_driver
from rdisc.runtime import load
from tests.conftest import run_rdisc, untimed
from tests.devices import PtyDevice

LATE = """\
robot late { author "tests" }
state v: int = 0
connection link: serial { baud 9600 threading single at 2 Hz }
primitive ask() on link pack "B" (0x41) unpack "B" { v = out[0] }
primitive poke() on link pack "B" (0x50)
interface poll() periodic { ask() }
"""

DELAY = 0.3  # seconds the device takes to answer `ask`


class LateDevice(PtyDevice):
    """Answers 0x41 with 0x07 after DELAY; takes 0x50 silently. `asked` is set once it has an 0x41."""

    reply_delay = DELAY

    def __init__(self) -> None:
        super().__init__()
        self.asked = threading.Event()

    def handle(self, data: bytes) -> None:
        for byte in data:
            if byte == 0x41:
                self.asked.set()
                self.send(b"\x07")


@pytest.fixture(scope="module")
def implementations(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    folder = tmp_path_factory.mktemp("late")
    source = folder / "late.rdis"
    source.write_text(LATE, encoding="utf-8")
    return {"runtime": load(source), "driver": import_driver(source, folder, "late_driver")}


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_host_write_during_a_periodic_exchange_is_shown_after_its_reply(
        kind: str, implementations: dict[str, Any]) -> None:
    """The host pokes while the periodic `ask` waits for its late reply: the poke reaches the device
    after the reply (the port is the exchange's until then), and that is the order shown, the
    request stamped when it was written, a reply's time later."""
    traced: list[tuple[float, str, str, bytes]] = []
    seen: list[tuple[str, str, bytes]] = []
    with LateDevice() as device:
        robot = implementations[kind].connect(device.port, on_io=lambda *event: seen.append(event))
        robot.on_trace(lambda *event: traced.append(event))
        with robot:
            assert device.asked.wait(2.0)
            robot.primitives.poke()  # waits for the port: the reply to `ask` comes first
            device.wait_for(2)
        answered = device.sent[0][0]
        poked = [at for at, data in device.chunks if 0x50 in data]
    assert seen[:3] == [("write", "link", b"\x41"), ("read", "link", b"\x07"), ("write", "link", b"\x50")]
    assert [event[1:] for event in traced[:3]] == seen[:3]
    (asked_at, *_), (read_at, *_), (poked_at, *_) = traced[:3]
    assert asked_at + DELAY * 0.8 <= read_at <= poked_at  # stamped when written, not when answered
    assert poked and device.chunks[0][0] <= poked[0]
    assert answered / 1e9 > 0  # the device answered (its clock is the host's wall clock)


SKIPPING = """\
robot skipping { author "tests" }
state v: int = 0
frame summed(id: int) {
    header "\\xFF\\xFF"
    field id "B" = id
    length "B" = payload + 1
    payload
    checksum "sum" "B" inverted
}
connection link: serial { baud 9600 }
primitive listen() on link frame summed(1) pack "B" (3) skip unmatched timeout 500 ms unpack "B" { v = out[0] }
"""


def _frame(id_: int, payload: bytes) -> bytes:
    body = bytes([id_, len(payload) + 1]) + payload
    return b"\xff\xff" + body + bytes([~sum(body) & 0xFF])


class FrameDevice(PtyDevice):
    """Answers each request with `answer`."""

    def __init__(self, answer: bytes) -> None:
        super().__init__()
        self.answer = answer

    def handle(self, data: bytes) -> None:
        self.send(self.answer)


def test_run_trace_shows_why_a_reply_was_skipped(tmp_path: Path) -> None:
    source = tmp_path / "skipping.rdis"
    source.write_text(SKIPPING, encoding="utf-8")
    other = _frame(2, b"\x05")
    with FrameDevice(other + _frame(1, b"\x09")) as device:
        result = run_rdisc("run", str(source), "--port", device.port, "--call", "listen", "--trace")
    assert result.returncode == 0, result.stderr
    assert untimed(result.stderr) == [
        "link > ff ff 01 02 03 f9",
        "link skip listen: summed: reply id is 2, expected 1",
        "link < ff ff 02 02 05 f6 ff ff 01 02 09 f3",
    ]


def test_run_trace_stamps_a_request_when_it_was_written(tmp_path: Path) -> None:
    """`rdisc run --trace` against the late device: the request's line is stamped a reply's delay
    before the reply's (both used to be stamped when the reply came)."""
    source = tmp_path / "late.rdis"
    source.write_text(LATE, encoding="utf-8")
    with LateDevice() as device:
        result = run_rdisc("run", str(source), "--port", device.port, "--trace", "--duration", "0.2")
    assert result.returncode == 0, result.stderr
    assert untimed(result.stderr)[:2] == ["link > 41", "link < 07"]
    written, read = (float(line.split()[0]) for line in result.stderr.splitlines()[:2])
    assert written + DELAY * 0.8 <= read
