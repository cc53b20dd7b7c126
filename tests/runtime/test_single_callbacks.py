"""`threading single`: a tick holds the port from its first exchange to its last, and callbacks run
one at a time. A callback on the host's thread that commands the robot while a tick holds the
port, the tick then waiting to run its own output's callback, once waited for ever (each thread
held what the other waited for). The tick now lets the port go while it waits for the callbacks,
and takes it back before its next exchange: the command is written, then the tick goes on.

The interleaving is made, not hoped for: the device answers the tick's request only once the
host's callback is waiting, and the tick runs on a thread of the test (`robot.tick()`).
"""

from __future__ import annotations

import importlib.util
import sys
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rdisc import engine
from rdisc.compile import compile_text
from rdisc.emit.python import to_python
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

DESCRIPTION = """\
robot single9 { author "tests" }

connection link: serial { baud 115200  threading single at 10 Hz }

primitive ask() on link format "A\\n" () regex r"^a\\s*$"
primitive poke() on link format "P\\n" ()
primitive go() on link format "C\\n" ()

interface poll() periodic triggers polled { ask() ask() }
interface report() triggers reported { poke() }

output polled: Contact { contact = True }
output reported: Contact { contact = False }
"""

WAIT = 10.0  # seconds: only a deadlock comes near it


class Device:
    """Answers each `A` with `a`, and tells the test when the tick's first request came (the tick
    holds the port then)."""

    def __init__(self) -> None:
        self.ticking = threading.Event()

    def answer(self, request: bytes) -> bytes:
        if request == b"A\n":
            self.ticking.set()
            return b"a\n"
        return b""

    def listen(self) -> bytes:
        return b""


def _robot(way: str, folder: Path) -> engine.Robot:
    if way == "runtime":
        path = folder / "single9.rdis"
        path.write_text(DESCRIPTION, encoding="utf-8")
        return engine.Robot(load(path).device)
    compilation = compile_text("single9.rdis", DESCRIPTION)
    assert compilation.model is not None, compilation.diagnostics.items
    path = folder / "single9_driver.py"
    path.write_text(to_python(compilation.model, "single9.rdis"), encoding="utf-8")
    spec = importlib.util.spec_from_file_location(f"single9_driver_{abs(hash(str(path)))}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    made: Callable[[], engine.Robot] = module.Single9
    return made()


@pytest.mark.parametrize("way", ["runtime", "driver"])
def test_a_host_callback_commanding_while_a_tick_holds_the_port_does_not_deadlock(way: str, tmp_path: Path) -> None:
    device = Device()
    port = ScriptedPort(device=device)
    robot = _robot(way, tmp_path)
    errors: list[BaseException] = []
    robot.on_error(errors.append)
    seen: list[str] = []

    def callback(message: Any) -> None:
        seen.append(message["name"])
        if message["name"] == "reported":  # on the host's thread, holding the callbacks' turn
            assert device.ticking.wait(WAIT)  # the tick holds the port now
            robot.primitives.go()

    robot.on_output(callback)
    robot.open(port, threads=False)
    try:
        ticker = threading.Thread(target=robot.tick, daemon=True)
        host = threading.Thread(target=robot.interfaces.report, daemon=True)
        host.start()
        while not seen and host.is_alive():  # the host's callback has begun
            host.join(0.01)
        ticker.start()
        host.join(WAIT)
        ticker.join(WAIT)
        assert not host.is_alive() and not ticker.is_alive(), "deadlocked"
    finally:
        robot.close()
    assert errors == []
    assert seen == ["reported", "polled"]
    # the tick's two exchanges whole, the host's command while the tick waited for the callbacks
    assert port.writes == [b"P\n", b"A\n", b"A\n", b"C\n"]
