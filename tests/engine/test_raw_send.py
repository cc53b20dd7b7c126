"""`Robot.send_raw`: bytes written as they are and the device's answer read as a terminal shows
it (the console's raw terminal), under the port's lock as a call's request, in the runtime and a
generated driver alike (the driver carries the engine)."""

from __future__ import annotations

import threading
from pathlib import Path

import pytest

from rdisc import engine
from tests.engine.test_one_engine import ScriptedPort, implementation_of

PLAIN = """\
robot plain { author "tests" }
state v: int = 0
connection link: serial { baud 9600 }
connection other: serial { baud 9600 }
primitive ask() on link pack "B" (0x41) unpack "B" { v = out[0] }
"""

KINDS = ["runtime", "driver"]


class Answering:
    """Answers every write with `answer`; and checks, while it answers, that no other thread can
    take the port's lock (the raw send holds it, as a call does)."""

    def __init__(self, answer: bytes) -> None:
        self.answer_bytes = answer
        self.lock: object = None
        self.free_while_answering: list[bool] = []

    def answer(self, request: bytes) -> bytes:
        if self.lock is not None:
            got: list[bool] = []
            other = threading.Thread(target=lambda: got.append(self.lock.acquire(blocking=False)))  # type: ignore[attr-defined]
            other.start()
            other.join()
            self.free_while_answering.append(got[0])
        return self.answer_bytes

    def listen(self) -> bytes:
        return b""


@pytest.mark.parametrize("kind", KINDS)
def test_raw_bytes_are_written_as_they_are_and_the_answer_read_whole(kind: str, tmp_path: Path) -> None:
    device = Answering(b"\x3a\x98OK\r\n")
    port = ScriptedPort(device=device)
    seen: list[tuple[str, str, bytes]] = []
    with implementation_of(kind, PLAIN, tmp_path, "plain").connect({"link": port, "other": ScriptedPort()},
                                                                    threads=False,
                                                                    on_io=lambda *event: seen.append(event)) as robot:
        device.lock = robot._links["link"].port.lock
        assert robot.send_raw("link", b"\x8e\x16") == b"\x3a\x98OK\r\n"
        assert port.writes == [b"\x8e\x16"]
        assert device.free_while_answering == [False]  # the port's lock was held: no call comes between
        assert seen == [("write", "link", b"\x8e\x16"), ("read", "link", b"\x3a\x98OK\r\n")]
        robot.call_primitive("ask")  # a call after it reads its own reply: nothing of the raw answer is left
        assert robot.state["v"] == 0x3A
        assert port.timeout == 0.05  # the port's own timeout, as it was


@pytest.mark.parametrize("kind", KINDS)
def test_no_answer_is_empty_and_input_waiting_before_is_not_the_answer(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    port.input += b"\x07\x07"  # what came before the raw send: discarded, as before a request
    with implementation_of(kind, PLAIN, tmp_path, "plain").connect({"link": port, "other": ScriptedPort()},
                                                                    threads=False) as robot:
        assert robot.send_raw("link", b"\x01") == b""
        assert port.writes == [b"\x01"]


@pytest.mark.parametrize("kind", KINDS)
def test_a_raw_send_is_refused_as_a_call_is(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    robot = implementation_of(kind, PLAIN, tmp_path, "plain").connect({"link": port, "other": ScriptedPort()},
                                                                       threads=False)
    with pytest.raises(KeyError, match="plain has no connection named 'nowhere'"):
        robot.send_raw("nowhere", b"\x01")
    robot.close()
    with pytest.raises(Exception) as closed:  # a driver's error class is its own
        robot.send_raw("link", b"\x01")
    assert _said(closed.value) == ("RdisConnectionError", "plain: raw bytes not sent: the robot is closed")
    failing = ScriptedPort(fail=True)
    broken = implementation_of(kind, PLAIN, tmp_path, "plain").connect({"link": failing, "other": ScriptedPort()},
                                                                        threads=False)
    with broken, pytest.raises(Exception) as gone:
        broken.send_raw("link", b"\x01")
    assert _said(gone.value) == ("RdisConnectionError", "link: [Errno 5] the device is gone")
    assert port.writes == []


def test_a_simulated_robot_has_no_port_to_send_raw_bytes_on(tmp_path: Path) -> None:
    pytest.importorskip("mujoco")
    from rdisc.compile import compile_path
    from rdisc.runtime import load
    from rdisc.sim import Simulation

    arm = Path(__file__).resolve().parents[2] / "examples" / "arm.rdis"
    model = compile_path(str(arm)).model
    assert model is not None
    sim = Simulation(model)
    robot = load(arm).connect(sim=sim, threads=False)
    try:
        connection = next(iter(robot.device.connections))
        with pytest.raises(engine.RdisConnectionError) as refused:
            robot.send_raw(connection, b"\x01")
    finally:
        robot.close()
    assert str(refused.value) == f"{connection}: the device is simulated: there is no port"


def _said(error: BaseException) -> tuple[str, str]:
    return type(error).__name__, str(error)
