"""examples/slcan.rdis against python-can (4.6.1)'s `can.interfaces.slcan`, the published driver
of serial-line CAN adapters, byte for byte: python-can's `slcanBus` runs over pyserial's
`loop://` (what it writes is read back out of the loop and compared with what rdisc writes for
the same call), and the lines an adapter sends are put into the loop for its `recv()` to read:
the description reads the same lines into the same identifier, kind, DLC and data. The runtime
and the generated driver alike.
"""

from __future__ import annotations

import os
import select
from pathlib import Path
from typing import Any

import pytest

slcan = pytest.importorskip("can.interfaces.slcan")
can = pytest.importorskip("can")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "slcan.rdis"


@pytest.fixture(scope="module", params=["runtime", "driver"])
def described(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, EXAMPLE.read_text(encoding="utf-8"), tmp_path_factory.mktemp("slcan"),
                             "slcan")


class Adapter:
    """The adapter's end of a pseudo-terminal whose other end python-can's bus opened."""

    def __init__(self) -> None:
        self.end, other = os.openpty()
        self.bus = slcan.slcanBus(os.ttyname(other), sleep_after_open=0, timeout=0.01)
        os.close(other)  # the bus opened it by its name
        self.written()

    def written(self) -> bytes:
        """Every byte the bus has written and the adapter not yet read."""
        data = b""
        while select.select([self.end], [], [], 0)[0]:  # python-can flushed (tcdrain) what it wrote
            data += os.read(self.end, 4096)
        return data

    def send(self, data: bytes) -> None:
        os.write(self.end, data)

    def close(self) -> None:
        self.bus.shutdown()  # writes `C` and closes its port
        os.close(self.end)


@pytest.fixture
def adapter() -> Any:
    opened = Adapter()
    yield opened
    opened.close()


def _ours(described: Any, call: str, *args: Any, kind: str = "primitive") -> bytes:
    port = ScriptedPort()
    with described.connect(port, threads=False) as robot:
        getattr(robot, f"call_{kind}")(call, *args)
    return bytes(port.written)


MESSAGES = [
    (0x123, False, False, bytes.fromhex("1122334455667788")),
    (0x000, False, False, b""),
    (0x7FF, False, False, b"\x00\xff"),
    (0x1ABCDEF0, True, False, bytes.fromhex("DEADBEEF")),
    (0x00000001, True, False, b"\x01"),
    (0x1FFFFFFF, True, False, bytes(8)),
    (0x321, False, True, 4),  # remote requests: a DLC, no data
    (0x7FF, False, True, 0),
    (0x12345678, True, True, 8),
]


FD_MESSAGES = [  # CAN FD: (id, extended, switched, data), of every length a DLC states
    *((0x123, False, False, bytes(range(n))) for n in (0, 1, 8, 12, 16, 20, 24, 32, 48, 64)),
    (0x7FF, False, True, bytes.fromhex("0102030405060708090A0B0C")),
    (0x1ABCDEF0, True, False, bytes(range(200, 216))),
    (0x1FFFFFFF, True, True, bytes(range(64))),
]


def _message(id_: int, extended: bool, remote: bool, data: Any) -> Any:
    if remote:
        return can.Message(arbitration_id=id_, is_extended_id=extended, is_remote_frame=True, dlc=data)
    return can.Message(arbitration_id=id_, is_extended_id=extended, data=data)


def _fd_message(id_: int, extended: bool, switched: bool, data: bytes) -> Any:
    return can.Message(arbitration_id=id_, is_extended_id=extended, is_fd=True, bitrate_switch=switched, data=data)


def _primitive(extended: bool, remote: bool) -> str:
    return ("request" if remote else "send") + ("_extended" if extended else "")


def _received(adapter: Adapter, data: bytes) -> Any:
    """What python-can's recv() makes of the lines, the first frame of them."""
    adapter.send(data)
    for _ in range(4):  # one line a call: acknowledgements give None
        received = adapter.bus.recv(0.5)
        if received is not None:
            return received
    raise AssertionError("python-can received no frame")


@pytest.mark.parametrize("message", MESSAGES)
def test_a_frame_is_sent_as_python_can_sends_it(described: Any, adapter: Adapter, message: tuple[Any, ...]) -> None:
    adapter.bus.send(_message(*message))
    id_, extended, remote, data = message
    assert _ours(described, _primitive(extended, remote), id_, data) == adapter.written()


@pytest.mark.parametrize("bitrate", [10000, 125000, 500000, 1000000, 83300])
def test_the_bit_rate_is_set_as_python_can_sets_it(described: Any, adapter: Adapter, bitrate: int) -> None:
    adapter.bus.set_bitrate(bitrate)
    theirs = adapter.written()
    assert theirs == b"C\r" + slcan.slcanBus._BITRATES[bitrate].encode() + b"\r\rO\r"  # the empty data-rate line too
    assert _ours(described, "set_bitrate", bitrate, kind="interface") == theirs


@pytest.mark.parametrize(("bitrate", "data_bitrate"), [(500000, 2000000), (1000000, 5000000)])
def test_a_can_fd_data_rate_is_set_as_python_can_sets_it(described: Any, adapter: Adapter, bitrate: int,
                                                         data_bitrate: int) -> None:
    adapter.bus.set_bitrate(bitrate, data_bitrate)
    assert _ours(described, "set_bitrate", bitrate, data_bitrate, kind="interface") == adapter.written()


@pytest.mark.parametrize("call", ["open", "close"])
def test_open_and_close(described: Any, adapter: Adapter, call: str) -> None:
    getattr(adapter.bus, call)()
    assert _ours(described, call) == adapter.written()


def test_listen_only_opens_as_python_can_does(described: Any) -> None:
    end, other = os.openpty()
    bus = slcan.slcanBus(os.ttyname(other), sleep_after_open=0, listen_only=True)
    try:
        assert os.read(end, 100) == _ours(described, "listen_only") == b"L\r"
    finally:
        bus.shutdown()
        os.close(end)
        os.close(other)


def test_an_unknown_bit_rate_is_refused_by_both(described: Any, adapter: Adapter) -> None:
    with pytest.raises(ValueError, match="Invalid bitrate"):
        adapter.bus.set_bitrate(12345)
    port = ScriptedPort()
    with described.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("rate", 12345)
    assert type(caught.value).__name__ == "RdisValueError" and port.written == b""


@pytest.mark.parametrize("message", MESSAGES)
def test_a_received_frame_is_read_as_python_can_reads_it(described: Any, adapter: Adapter,
                                                         message: tuple[Any, ...]) -> None:
    adapter.bus.send(_message(*message))
    line = adapter.written()  # an adapter receiving this frame sends the line python-can sends it with
    noise = b"\rz\r\a"  # acknowledgements of commands, and an error, before it: read past by both
    received = _received(adapter, noise + line)
    port = ScriptedPort(noise + line)
    with described.connect(port, threads=False) as robot:
        robot.call_primitive("receive")
        state = robot.state
        assert (state["id"], state["extended"], state["remote"], state["dlc"]) == (
            received.arbitration_id, received.is_extended_id, received.is_remote_frame, received.dlc) == message[:3] + (
            message[3] if message[2] else len(message[3]),)
        assert state["data"] == (b"" if received.is_remote_frame else bytes(received.data))
        assert (state["fd"], state["switched"]) == (received.is_fd, received.bitrate_switch) == (False, False)


@pytest.mark.parametrize(("reply", "versions"), [(b"V1013\r", (10, 13)), (b"V0107\r", (1, 7))])
def test_the_version_is_read_as_python_can_reads_it(described: Any, adapter: Adapter, reply: bytes,
                                                    versions: tuple[int, int]) -> None:
    received = b"t1230\r"  # a frame not yet read comes first: both read past it (python-can queues it)
    adapter.send(received + reply)
    assert adapter.bus.get_version(1.0) == versions
    port = ScriptedPort(received + reply)
    with described.connect(port, threads=False) as robot:
        robot.call_primitive("version")
        assert bytes(port.written) == adapter.written() == b"V\r"
        assert (robot.state["hardware"], robot.state["software"]) == versions


@pytest.mark.parametrize("number", ["A123", "0042", ""])
def test_the_serial_number_is_read_as_python_can_reads_it(described: Any, adapter: Adapter, number: str) -> None:
    reply = b"\rN" + number.encode() + b"\r"
    adapter.send(reply)
    assert adapter.bus.get_serial_number(1.0) == number
    port = ScriptedPort(reply)
    with described.connect(port, threads=False) as robot:
        robot.call_primitive("serial")
        assert bytes(port.written) == adapter.written() == b"N\r"
        assert robot.state["serial_number"] == number


@pytest.mark.parametrize("message", FD_MESSAGES)
def test_a_can_fd_frame_is_sent_as_python_can_sends_it(described: Any, adapter: Adapter,
                                                        message: tuple[Any, ...]) -> None:
    adapter.bus.send(_fd_message(*message))
    id_, extended, switched, data = message
    assert _ours(described, "send_fd_extended" if extended else "send_fd", id_, data, switched) == adapter.written()


@pytest.mark.parametrize("message", FD_MESSAGES)
def test_a_received_can_fd_frame_is_read_as_python_can_reads_it(described: Any, adapter: Adapter,
                                                                message: tuple[Any, ...]) -> None:
    adapter.bus.send(_fd_message(*message))
    line = adapter.written()
    received = _received(adapter, b"\r" + line)
    port = ScriptedPort(b"\r" + line)
    with described.connect(port, threads=False) as robot:
        robot.call_primitive("receive")
        state = robot.state
        assert (state["id"], state["extended"], state["fd"], state["switched"], state["dlc"], state["data"]) == (
            received.arbitration_id, received.is_extended_id, received.is_fd, received.bitrate_switch, received.dlc,
            bytes(received.data)) == (message[0], message[1], True, message[2], len(message[3]), message[3])


def test_a_can_fd_length_no_dlc_states_is_refused(described: Any, adapter: Adapter) -> None:
    adapter.bus.send(_fd_message(0x123, False, False, bytes(10)))
    assert adapter.written() == b"d1239" + b"00" * 10 + b"\r"  # python-can: DLC 9 (12 bytes) before 10 bytes
    port = ScriptedPort()
    with described.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("send_fd", 0x123, bytes(10), False)
    assert type(caught.value).__name__ == "RdisValueError" and port.written == b""
