"""`retry N` over a real pty: a device that loses one reply and garbles the next (a bad
checksum) is asked three times with the same bytes and the third reply is taken; one that never
answers is asked N + 1 times, each try waiting the primitive's whole timeout, and the
RdisTimeout says how many tries were made. The runtime and the generated driver alike."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load
from tests.devices import pty_device

DESCRIPTION = """\
robot noisy { author "tests" }
state position: int = 0
connection c: serial { baud 57600 }
frame packet { header "\\xFF\\xFF"  payload  checksum "sum" "B" }
primitive read(id: int in 0..253) on c frame packet pack "BB" (0x02, id) unpack "<H" timeout 100 ms retry 2
    { position = out[0] }
"""
REQUEST = b"\xff\xff\x02\x05\x07"  # header, 0x02, id 5, the sum of 0x02 and 0x05


def _reply(position: int, check_delta: int = 0) -> bytes:
    payload = position.to_bytes(2, "little")
    return b"\xff\xff" + payload + bytes([(sum(payload) + check_delta) & 0xFF])


@pytest.fixture(params=["runtime", "driver"])
def connect(request: pytest.FixtureRequest, tmp_path: Path) -> tuple[Callable[[str], Any], type[Exception]]:
    path = tmp_path / "noisy.rdis"
    path.write_text(DESCRIPTION, encoding="utf-8")
    if request.param == "runtime":
        return (lambda port: load(path).connect(port, timeout=5.0, threads=False)), errors.RdisTimeout
    driver = import_driver(path, tmp_path, "noisy_driver")
    return (lambda port: driver.connect(port, timeout=5.0, threads=False)), driver.RdisTimeout


def test_a_lost_and_a_garbled_reply_are_asked_for_again(connect: tuple[Callable[[str], Any], type[Exception]]) -> None:
    make, _ = connect
    answers = [b"", _reply(300, check_delta=1), _reply(512)]  # lost, a bad checksum, good
    with pty_device(lambda data: answers.pop(0)) as dev, make(dev.port) as robot:
        robot.call_primitive("read", 5)
        assert dev.received == REQUEST * 3
        assert robot.state["position"] == 512
        assert answers == []


def test_a_silent_device_is_asked_n_plus_one_times(connect: tuple[Callable[[str], Any], type[Exception]]) -> None:
    make, timeout_error = connect
    with pty_device(lambda data: b"") as dev, make(dev.port) as robot:
        with pytest.raises(timeout_error) as caught:
            robot.call_primitive("read", 5)
        assert str(caught.value) == "read: no reply within 0.1 s (3 tries)"
        assert dev.wait_for(len(REQUEST) * 3) == REQUEST * 3
        assert robot.state["position"] == 0
