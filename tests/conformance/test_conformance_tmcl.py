"""examples/tmcl.rdis against pytrinamic (0.2.26), Trinamic's own TMCL library, byte for byte:
pytrinamic's SerialTmclInterface is driven over a port that records what it writes and answers
with replies pytrinamic's TMCLReply builds; rdisc must write the same nine bytes for the same
call, and read the same value from the same reply. A reply whose status is a refusal, which
pytrinamic raises as a TMCLReplyStatusError, is an RdisDeviceError with the same status and its
name; a reply whose checksum pytrinamic refuses (TMCLReplyChecksumError) is an RdisProtocolError.
The runtime and the generated driver alike.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

serial = pytest.importorskip("serial")
tmcl = pytest.importorskip("pytrinamic.tmcl")
interface = pytest.importorskip("pytrinamic.connections.serial_tmcl_interface")
helpers = pytest.importorskip("pytrinamic.helpers")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "tmcl.rdis"
MODULE, HOST = 3, 2


class Wire(serial.Serial):  # type: ignore[misc]
    """A port pytrinamic accepts as an opened pyserial Serial: it records what is written and
    answers each read with the next reply given."""

    def __init__(self, *replies: bytes) -> None:  # no port is opened
        self.written = bytearray()
        self.replies = list(replies)

    def write(self, data: bytes) -> int:  # type: ignore[override]
        self.written += data
        return len(data)

    def read(self, size: int = 1) -> bytes:
        return self.replies.pop(0)[:size]

    def close(self) -> None:
        pass

    def __repr__(self) -> str:
        return "Wire"


def reply(command: int, value: int, status: int = 100) -> bytes:
    """The reply a module sends, as pytrinamic's TMCLReply frames it (value as 32 bits)."""
    return bytes(tmcl.TMCLReply(HOST, MODULE, status, command, value & 0xFFFFFFFF).to_buffer())


def pytrinamic(call: str, args: tuple[int, ...], answer: bytes) -> tuple[bytes, Any]:
    """What pytrinamic writes for one call answered by `answer`, and what it returns."""
    wire = Wire(answer)
    module = interface.SerialTmclInterface(wire, host_id=HOST, module_id=MODULE)
    result = getattr(module, call)(*args)
    return bytes(wire.written), result


@pytest.fixture(scope="module", params=["runtime", "driver"])
def trinamic(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Any]:
    folder = tmp_path_factory.mktemp("tmcl")
    return request.param, implementation_of(request.param, EXAMPLE.read_text(encoding="utf-8"), folder, "tmcl")


def _connect(trinamic: tuple[str, Any], port: ScriptedPort) -> Any:
    kind, implementation = trinamic
    if kind == "runtime":
        return implementation.connect(port, threads=False, settings={"MODULE": MODULE, "HOST": HOST})
    return implementation.connect(port, threads=False, MODULE=MODULE, HOST=HOST)


# (pytrinamic's call, its arguments, rdisc's primitive or interface, its arguments, the command, the
# value the module answers, the state that holds it)
CALLS = [
    ("rotate", (0, 51200), "rotate", (0, 51200), 1, 0, None),
    ("rotate", (1, -2000), "rotate", (1, -2000), 1, 0, None),
    ("stop", (0,), "stop", (0,), 3, 0, None),
    ("move_to", (0, 100000), "move_to", (0, 100000), 4, 100000, "answered"),
    ("move_to", (2, -7), "move_to", (2, -7), 4, -7, "answered"),
    ("move_by", (0, -51200), "move_by", (0, -51200), 4, 48800, "answered"),
    ("set_axis_parameter", (4, 0, 2000), "set_axis_parameter", (4, 0, 2000), 5, 2000, None),
    ("set_axis_parameter", (0, 1, -123456), "set_axis_parameter", (0, 1, -123456), 5, -123456, None),
    ("get_axis_parameter", (1, 0, None, True), "get_axis_parameter", (1, 0), 6, -51200, "parameter"),
    ("get_axis_parameter", (3, 5, None, True), "get_axis_parameter", (3, 5), 6, 0x7FFFFFFF, "parameter"),
    ("set_global_parameter", (65, 0, 7), "set_global_parameter", (65, 0, 7), 9, 7, None),
    ("get_global_parameter", (0, 2, None, True), "get_global_parameter", (0, 2), 10, -1, "global"),
    ("get_analog_input", (4,), "get_input", (4, 1), 15, 3301, "input"),
    ("get_digital_input", (1,), "get_input", (1, 0), 15, 1, "input"),
    ("get_digital_output", (0,), "get_input", (0, 2), 15, 0, "input"),
    ("set_digital_output", (2,), "set_output", (2, True), 14, 0, None),
    ("clear_digital_output", (2,), "set_output", (2, False), 14, 0, None),
]


@pytest.mark.parametrize(("call", "args", "ours", "our_args", "command", "value", "state"), CALLS,
                         ids=[f"{c[0]}{c[1]}" for c in CALLS])
def test_a_call_is_the_datagram_pytrinamic_sends_and_its_reply_is_read_alike(
        trinamic: tuple[str, Any], call: str, args: tuple[Any, ...], ours: str, our_args: tuple[Any, ...],
        command: int, value: int, state: str | None) -> None:
    answer = reply(command, value)
    expected, returned = pytrinamic(call, args, answer)
    port = ScriptedPort(answer)
    with _connect(trinamic, port) as robot:
        if ours in ("move_to", "move_by"):
            robot.call_interface(ours, *our_args)
        else:
            robot.call_primitive(ours, *our_args)
        assert bytes(port.written) == expected
        if state is not None:
            assert robot.state[state] == helpers.to_signed_32(returned) == value  # the value as a signed int32


@pytest.mark.parametrize("status", sorted(set(tmcl.TMCLStatus.messages) - {100, 101}))
def test_a_refusal_is_the_devices_error_with_pytrinamics_status(trinamic: tuple[str, Any], status: int) -> None:
    answer = reply(6, 0, status)
    with pytest.raises(tmcl.TMCLReplyStatusError) as theirs:
        pytrinamic("get_axis_parameter", (1, 0), answer)
    port = ScriptedPort(answer)
    with _connect(trinamic, port) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("get_axis_parameter", 1, 0)
    assert type(caught.value).__name__ == "RdisDeviceError"
    assert caught.value.code == theirs.value.status_code == status
    constants = {value: name for name, value in vars(tmcl.TMCLStatus).items() if isinstance(value, int)}
    named = constants.get(status) or theirs.value.error_description.upper().replace(" ", "_")  # 9: no constant
    assert caught.value.name == named
    assert robot.state["parameter"] == 0


def test_a_reply_with_a_wrong_checksum_is_refused(trinamic: tuple[str, Any]) -> None:
    answer = bytearray(reply(6, 1234))
    answer[-1] ^= 0x01
    with pytest.raises(tmcl.TMCLReplyChecksumError):
        pytrinamic("get_axis_parameter", (1, 0), bytes(answer))
    port = ScriptedPort(bytes(answer))
    with _connect(trinamic, port) as robot, pytest.raises(Exception, match="checksum") as caught:
        robot.call_primitive("get_axis_parameter", 1, 0)
    assert type(caught.value).__name__ == "RdisProtocolError"


def test_another_modules_reply_is_refused(trinamic: tuple[str, Any]) -> None:
    answer = bytes(tmcl.TMCLReply(HOST, MODULE + 1, 100, 6, 5).to_buffer())
    port = ScriptedPort(answer)
    with _connect(trinamic, port) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("get_axis_parameter", 1, 0)
    assert type(caught.value).__name__ == "RdisProtocolError"
