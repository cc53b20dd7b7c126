"""A group's `%` codes, unsigned integers of as many bytes as the width field `%H` states:
Dynamixel's sync write of N bytes a servo, byte for byte as dynamixel-sdk's GroupSyncWrite
writes it, from the runtime and from the generated driver alike (ScriptedPort)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from rdisc.engine.errors import RdisValueError
from tests.engine.test_one_engine import implementation_of
from tests.support.ports import ScriptedPort

sdk = pytest.importorskip("dynamixel_sdk")

SYNC = """robot sync { author "t" }
connection bus: serial { baud 1000000 }
frame dxl(id: int in 0..254) {
    header "\\xFF\\xFF\\xFD\\x00"
    field id "B" = id
    length "<H" = payload + 2
    payload
    checksum "crc16-buypass" "<H" over header .. payload
    stuff "\\xFD" after "\\xFF\\xFF\\xFD"
}
/// Any register of 1, 2 or 4 bytes, on the servos asked for.
primitive sync_write(address: int in 0..65535, width: int in 1..4, ids: int[] in 0..253, values: int[])
    on bus frame dxl(0xFE) pack "<BH%H*(B%)" (0x83, address, width, ids, values)
"""


class _Capture:
    """The little of dynamixel-sdk's PortHandler that a packet's sending uses: its bytes kept."""

    def __init__(self) -> None:
        self.is_using = False
        self.written = b""

    def clearPort(self) -> None:  # the SDK's names
        pass

    def writePort(self, packet: list[int]) -> int:
        self.written += bytes(packet)
        return len(packet)


def _sdk_packet(address: int, width: int, ids: list[int], values: list[int]) -> bytes:
    port = _Capture()
    group = sdk.GroupSyncWrite(port, sdk.PacketHandler(2.0), address, width)
    for servo, value in zip(ids, values):
        assert group.addParam(servo, list(value.to_bytes(width, "little")))
    assert group.txPacket() == sdk.COMM_SUCCESS
    return port.written


CASES = [
    (64, 1, [1, 2, 3], [1, 0, 1]),  # torque enable: one byte a servo
    (104, 2, [7, 9], [0x1234, 0xFFFF]),  # a 2-byte register
    (116, 4, [1, 2, 3, 4, 5, 6], [2048, 0, 4095, 0x7FFFFFFF, 1 << 31, 0xFFFFFFFF]),  # goal position
    (116, 4, [11], [1000]),
]


@pytest.fixture(scope="module", params=["runtime", "driver"])
def description(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, SYNC, tmp_path_factory.mktemp(request.param), "sync")


@pytest.mark.parametrize(("address", "width", "ids", "values"), CASES)
def test_a_sync_write_of_n_bytes_a_servo_is_the_sdks(description: Any, address: int, width: int, ids: list[int],
                                                     values: list[int]) -> None:
    port = ScriptedPort()
    with description.connect(port, threads=False) as robot:
        robot.primitives.sync_write(address, width, ids, values)
    assert bytes(port.written) == _sdk_packet(address, width, ids, values)


@pytest.mark.parametrize(("width", "values", "said"), [
    (2, [70000], "70000 is not an unsigned integer of 2 bytes (value 4, sized by value 2)"),
    (1, [-1], "-1 is not an unsigned integer of 1 bytes (value 4, sized by value 2)"),
])
def test_a_value_wider_than_the_width_is_refused(description: Any, width: int, values: list[int], said: str) -> None:
    port = ScriptedPort()
    with description.connect(port, threads=False) as robot, pytest.raises(ValueError) as raised:
        robot.primitives.sync_write(116, width, [1], values)
    assert type(raised.value).__name__ == "RdisValueError" and str(raised.value).endswith(said)
    assert bytes(port.written) == b""


def test_the_width_field_states_one_to_eight_bytes(tmp_path: Path) -> None:
    text = SYNC.replace("width: int in 1..4", "width: int")
    robot = implementation_of("runtime", text, tmp_path, "wide").connect(ScriptedPort(), threads=False)
    with robot, pytest.raises(RdisValueError) as raised:  # the range leaves it to the run
        robot.primitives.sync_write(116, 9, [1], [5])
    assert str(raised.value).endswith("a width field states 1 to 8 bytes, not 9")


PLAIN = """robot plain { author "t" }
connection link: serial { baud 9600 }
primitive counted(width: int, ids: int[], values: int[]) on link pack "<%B#B#(B%)H" (width, ids, values, 7)
primitive twice(width: int, values: int[2]) on link pack "<%B2(%%)" (width, values, values)
primitive big(width: int, values: int[1]) on link pack ">%B1(%)" (width, values)
"""


@pytest.mark.parametrize(("name", "args", "written"), [
    ("counted", (2, [1, 2], [0x0102, 0x0304]), "02 02 01 02 01 02 04 03 07 00"),  # the count field computed
    ("counted", (8, [], []), "08 00 07 00"),
    ("twice", (1, [5, 6]), "01 05 05 06 06"),
    ("big", (3, [0x010203]), "03 01 02 03"),  # the format's byte order
])
@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_width_fields_in_every_kind_of_group(tmp_path: Path, kind: str, name: str, args: tuple[Any, ...],
                                             written: str) -> None:
    port = ScriptedPort()
    with implementation_of(kind, PLAIN, tmp_path, "plain").connect(port, threads=False) as robot:
        getattr(robot.primitives, name)(*args)
    assert bytes(port.written).hex(" ") == written
