"""A primitive's own reply timeout (`timeout 50 ms`), over a real pty whose device
never answers: the runtime and the generated driver give up after the primitive's
timeout, not the robot's, and say which."""

from __future__ import annotations

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
