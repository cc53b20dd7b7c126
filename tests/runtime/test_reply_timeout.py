"""A primitive's own reply timeout (`timeout 50 ms`), over a real pty whose device
never answers: the runtime and the generated driver give up after the primitive's
timeout, not the robot's, and say which."""

from __future__ import annotations

import threading
import time
from pathlib import Path

import pytest

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load
from tests.devices import pty_device

DESCRIPTION = """\
robot quiet { author "tests" }
state v: int = 0
connection c: serial { baud 9600 }
primitive quick() on c pack "B" (1) unpack "B" timeout 50 ms { v = out[0] }
primitive patient() on c pack "B" (2) unpack "B" { v = out[0] }
"""
ROBOT_TIMEOUT = 5.0  # the robot's reply timeout (seconds); `quick` has its own, 50 ms


@pytest.fixture(params=["runtime", "driver"])
def connect(request: pytest.FixtureRequest, tmp_path: Path):
    path = tmp_path / "quiet.rdis"
    path.write_text(DESCRIPTION)
    if request.param == "runtime":
        return lambda port: load(path).connect(port, timeout=ROBOT_TIMEOUT), errors.RdisTimeout
    driver = import_driver(path, tmp_path, "quiet_driver")
    return lambda port: driver.connect(port, timeout=ROBOT_TIMEOUT), driver.RdisTimeout


def test_the_primitive_timeout_applies_to_its_reply_only(connect) -> None:
    make, timeout_error = connect
    with pty_device(lambda data: b"\x07" if data.endswith(b"\x02") else b"") as dev, make(dev.port) as robot:
        start = time.monotonic()
        with pytest.raises(timeout_error, match=r"^quick: no reply within 0\.05 s$"):
            robot.call_primitive("quick")
        assert time.monotonic() - start < ROBOT_TIMEOUT / 2  # 50 ms, not the robot's 5 s (loose: a busy machine)
        robot.call_primitive("patient")  # the robot's timeout again: the reply comes
        assert robot.state["v"] == 7


TRICKLED = """\
robot trickled { author "tests" }
state v: int = 0
connection c: serial { baud 9600 }
frame f() {
    header "\\xFF\\xFF"
    payload
    checksum "sum" "B"
}
primitive read() on c frame f() pack "B" (1) unpack "<H" timeout 500 ms { v = out[0] }
primitive listen() on c frame f() format "" () unpack "<H" timeout 500 ms skip unmatched { v = out[0] }
primitive line() on c format "r\\n" () regex r"^v,(\\d+)$" timeout 500 ms { v = int(out[0]) }
primitive tagged() on c format "" () skip unmatched timeout 500 ms reply tag "B" { 1: unpack "B" { v = out[0] } }
"""


@pytest.mark.parametrize("primitive", ["read", "listen", "line", "tagged"])
@pytest.mark.parametrize("implementation", ["runtime", "driver"])
def test_a_trickling_device_cannot_hold_a_call_past_its_timeout(tmp_path: Path, implementation: str,
                                                                primitive: str) -> None:
    """A device sending one garbage byte every 0.1 s (each byte well within any per-byte
    timeout) still gets the call refused at its 0.5 s deadline: the timeout is a deadline
    for the whole reply, skipped bytes and frames included (for `tagged`, bytes that start
    no tag)."""
    path = tmp_path / "trickled.rdis"
    path.write_text(TRICKLED)
    if implementation == "runtime":
        robot = load(path).connect  # type: ignore[assignment]
        error = errors.RdisError
    else:
        driver = import_driver(path, tmp_path, "trickled_driver")
        robot, error = driver.connect, driver.RdisError
    stop = threading.Event()
    with pty_device(lambda data: b"") as dev:

        def trickle() -> None:
            while not stop.wait(0.1):
                dev.send(b"\xff" if primitive != "line" else b"v")  # a header byte, or the line's start

        sender = threading.Thread(target=trickle, daemon=True)
        sender.start()
        try:
            with robot(dev.port, timeout=ROBOT_TIMEOUT) as connected:
                start = time.monotonic()
                with pytest.raises(error):
                    connected.call_primitive(primitive)
                took = time.monotonic() - start
        finally:
            stop.set()
            sender.join()
    assert took < ROBOT_TIMEOUT / 2, took  # 0.5 s, loosely; per-byte timeouts would run without end
