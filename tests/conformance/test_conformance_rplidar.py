"""examples/rplidar.rdis writes RPLIDAR's requests and reads its response descriptors as pyrplidar
(0.1.2) does.

Why: RPLIDAR's descriptor keeps the response's length in the low 30 bits of a little-endian u32
and the send mode in its high 2 (a `bits` part); pyrplidar's PyRPlidarResponse unpacks it with
`& 0x3FFFFFFF` and `>> 30`, and its PyRPlidarCommand writes A5 CMD (and, with data, the size, the
data and their XOR). A scan node's fields are bit fields of its payload (`B{1,1,6}H{1,15}H`), read
as PyRPlidarMeasurement reads them with shifts and masks; pyrplidar does not check the node's check
bits, which the interface manual states (the start flag's inverse, a check bit of 1), and the
description refuses a node that breaks them. Both the runtime and the generated driver are checked.
"""

from __future__ import annotations

import struct
from pathlib import Path

import pytest

protocol = pytest.importorskip("pyrplidar_protocol")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

DESCRIPTION = (Path(__file__).resolve().parents[2] / "examples" / "rplidar.rdis").read_text(encoding="utf-8")
INFO = bytes([0x18, 0x1D, 0x01, 0x07]) + bytes.fromhex("0123456789ABCDEF0123456789ABCDEF")


@pytest.fixture(params=["runtime", "driver"])
def robot(request: pytest.FixtureRequest, tmp_path: Path):  # type: ignore[no-untyped-def]
    port = ScriptedPort()
    with implementation_of(request.param, DESCRIPTION, tmp_path, "rplidar").connect(port, threads=False) as robot:
        yield robot, port


@pytest.mark.parametrize(("call", "args", "command", "data"), [
    ("stop", (), protocol.RPLIDAR_CMD_STOP, None),
    ("reset", (), protocol.RPLIDAR_CMD_RESET, None),
    ("set_pwm", (660,), protocol.RPLIDAR_CMD_SET_MOTOR_PWM, struct.pack("<H", 660)),
    ("set_pwm", (0,), protocol.RPLIDAR_CMD_SET_MOTOR_PWM, struct.pack("<H", 0)),
    ("set_pwm", (1023,), protocol.RPLIDAR_CMD_SET_MOTOR_PWM, struct.pack("<H", 1023)),
])
def test_requests_are_written_as_pyrplidar_writes_them(robot, call: str, args: tuple[int, ...], command: bytes,  # type: ignore[no-untyped-def]
                                                      data: bytes | None) -> None:
    robot_, port = robot
    robot_.call_primitive(call, *args)
    assert bytes(port.written) == protocol.PyRPlidarCommand(command, data).raw_bytes


def test_get_info_and_scan_descriptors_are_read_as_pyrplidar_reads_them(robot) -> None:  # type: ignore[no-untyped-def]
    robot_, port = robot
    info = bytes.fromhex("A5 5A 14 00 00 00 04")
    scan = bytes.fromhex("A5 5A 05 00 00 40 81")
    for descriptor, length, mode, kind in ((info, 20, 0, 0x04), (scan, 5, 1, 0x81)):
        parsed = protocol.PyRPlidarResponse(descriptor)
        assert (parsed.data_length, parsed.send_mode, parsed.data_type) == (length, mode, kind)
    node = bytes.fromhex("3E 81 02 34 12")  # start flag 0, its inverse 1, quality 15; check bit 1
    port.script = info + INFO + scan + node
    robot_.call_primitive("get_info")
    published = protocol.PyRPlidarDeviceInfo(INFO)
    assert (robot_.state["model"], robot_.state["firmware_minor"], robot_.state["firmware_major"],
            robot_.state["hardware"]) == (published.model, published.firmware_minor, published.firmware_major,
                                          published.hardware)
    robot_.call_primitive("scan")
    measured = protocol.PyRPlidarMeasurement(node)
    assert (robot_.state["start"], robot_.state["quality"], robot_.state["angle"], robot_.state["distance"]) == (
        measured.start_flag, measured.quality, measured.angle, measured.distance)
    assert bytes(port.written) == (protocol.PyRPlidarCommand(protocol.RPLIDAR_CMD_GET_INFO).raw_bytes
                                   + protocol.PyRPlidarCommand(protocol.RPLIDAR_CMD_SCAN).raw_bytes)


def test_a_descriptor_pyrplidar_reads_as_another_mode_is_refused(robot) -> None:  # type: ignore[no-untyped-def]
    robot_, port = robot
    single = bytes.fromhex("A5 5A 05 00 00 00 81")  # SCAN answered in single-response mode
    assert protocol.PyRPlidarResponse(single).send_mode == 0
    port.script = single + bytes.fromhex("3E 81 02 34 12")
    with pytest.raises(Exception, match=r"^scan: rplidar: reply mode is 0, expected 1$"):
        robot_.call_primitive("scan")


def test_nodes_follow_without_descriptors_and_their_check_bits_are_held(robot) -> None:  # type: ignore[no-untyped-def]
    robot_, port = robot
    good = bytes.fromhex("3D 03 10 00 08")  # a new scan: start flag 1, its inverse 0
    port.script = good + bytes.fromhex("3F 03 10 00 08")  # both flags set: a broken node
    robot_.call_primitive("node")
    measured = protocol.PyRPlidarMeasurement(good)
    assert (robot_.state["start"], robot_.state["quality"], robot_.state["angle"], robot_.state["distance"]) == (
        measured.start_flag, measured.quality, measured.angle, measured.distance)
    with pytest.raises(Exception, match=r"^node: "):
        robot_.call_primitive("node")
    assert port.written == b""


def _node(start: int, quality: int, angle_q6: int, distance_q2: int, inverse: int | None = None,
          check: int = 1) -> bytes:
    """A scan node as the interface manual lays it out, the inverse flag right unless given."""
    flags = start | (1 - start if inverse is None else inverse) << 1 | quality << 2
    return struct.pack("<BHH", flags, check | angle_q6 << 1, distance_q2)


NODES = [_node(0, 15, 320, 0x1234), _node(1, 0, 0, 0), _node(0, 63, (1 << 15) - 1, 0xFFFF),
         _node(1, 47, 23040 - 1, 1), _node(0, 1, 1, 4000)]


def test_node_fields_are_read_as_pyrplidar_reads_them(robot) -> None:  # type: ignore[no-untyped-def]
    robot_, port = robot
    port.script = b"".join(NODES)
    for node in NODES:
        robot_.call_primitive("node")
        measured = protocol.PyRPlidarMeasurement(node)
        assert (robot_.state["start"], robot_.state["quality"], robot_.state["angle"], robot_.state["distance"]) == (
            measured.start_flag, measured.quality, measured.angle, measured.distance)


@pytest.mark.parametrize("node", [_node(0, 15, 320, 8, inverse=0), _node(1, 15, 320, 8, inverse=1),
                                  _node(1, 15, 320, 8, check=0)])
def test_a_node_breaking_its_check_bits_is_refused(robot, node: bytes) -> None:  # type: ignore[no-untyped-def]
    robot_, port = robot
    port.script = node
    with pytest.raises(Exception, match=r"^node: reply \(.*\) does not meet its `expect`$") as raised:
        robot_.call_primitive("node")
    assert type(raised.value).__name__ == "RdisProtocolError"
    assert robot_.state["quality"] == 0
