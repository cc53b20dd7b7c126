"""The RoboClaw drivers' bytes and decodings, pinned to values worked out from the manual.

Each literal below was computed from the manual's frame layouts (big-endian fields, CRC-16/XMODEM
over address, command and data; reads send address and command only), not copied from a
capture; `test_literal_frames_follow_the_manual` re-checks their CRCs independently.
"""

from __future__ import annotations

import binascii
import struct
from typing import Any

import pytest

pytest.importorskip("tcr_roboclaw")
pytest.importorskip("PyCRC")
CRCException = pytest.importorskip("roboclaw.roboclaw").CRCException

from published.roboclaw import CALLS, REPLIES, Failed, capture, published_decode, published_request

# (method, args) -> the bytes the driver writes, or the exception it raises
REQUESTS: dict[tuple[str, tuple[Any, ...]], str | type[Exception]] = {
    ("ForwardM1", (0,)): "80 00 00 3b 5a",
    ("ForwardM1", (64,)): "80 00 40 73 9e",
    ("ForwardM1", (127,)): "80 00 7f b4 22",
    ("ForwardM1", (128,)): "80 00 80 aa d2",  # out of range, sent anyway
    ("ForwardM1", (-1,)): OverflowError,
    ("BackwardM1", (64,)): "80 01 40 40 af",
    ("ForwardM2", (127,)): "80 04 7f 78 e6",
    ("BackwardM2", (0,)): "80 05 00 c4 af",
    ("ForwardBackwardM1", (0,)): "80 06 00 91 fc",
    ("ForwardBackwardM1", (64,)): "80 06 40 d9 38",
    ("ForwardBackwardM1", (127,)): "80 06 7f 1e 84",
    ("ForwardBackwardM2", (64,)): "80 07 40 ea 09",
    ("MixedForward", (127,)): "80 08 7f 3d 8b",
    ("MixedBackward", (32,)): "80 09 20 a5 a0",
    ("MixedTurnRight", (10,)): "80 0a 0a 75 db",
    ("MixedTurnLeft", (10,)): "80 0b 0a 46 ea",
    ("MixedForwardBackward", (64,)): "80 0c 40 36 f3",
    ("MixedLeftRight", (0,)): "80 0d 00 4d 06",
    ("DutyM1", (0,)): "80 20 00 00 5b fe",
    ("DutyM1", (16384,)): "80 20 40 00 56 32",
    ("DutyM1", (-16384,)): "80 20 c0 00 4d aa",
    ("DutyM1", (32767,)): "80 20 7f ff 5d 69",
    ("DutyM1", (-32768,)): "80 20 80 00 40 66",
    ("DutyM1", (32768,)): "80 20 80 00 40 66",  # wraps to full reverse
    ("DutyM1", (-32769,)): "80 20 7f ff 5d 69",  # wraps to full forward
    ("DutyM2", (-1,)): "80 21 ff ff 71 c1",
    ("DutyM1M2", (0, 0)): "80 22 00 00 00 00 98 17",
    ("DutyM1M2", (32767, -32768)): "80 22 7f ff 80 00 da 77",
    ("SpeedM1", (0,)): "80 23 00 00 00 00 32 46",
    ("SpeedM1", (12000,)): "80 23 00 00 2e e0 ea 81",
    ("SpeedM1", (-12000,)): "80 23 ff ff d1 20 b4 f2",
    ("SpeedM1", (2**31 - 1,)): "80 23 7f ff ff ff 76 b1",
    ("SpeedM1", (-(2**31),)): "80 23 80 00 00 00 ef 7e",
    ("SpeedM1", (2**31,)): "80 23 80 00 00 00 ef 7e",  # wraps
    ("SpeedM2", (-1,)): "80 24 ff ff ff ff cc 5d",
    ("SpeedM1M2", (1000, -1000)): "80 25 00 00 03 e8 ff ff fc 18 82 90",
    ("SpeedAccelM1", (12000, 12000)): "80 26 00 00 2e e0 00 00 2e e0 4f 20",
    ("SpeedAccelM1", (2**32 - 1, -(2**31))): "80 26 ff ff ff ff 80 00 00 00 fb 56",
    ("SpeedAccelM2", (24000, -12000)): "80 27 00 00 5d c0 ff ff d1 20 79 b8",
    ("SpeedAccelM1M2", (12000, 1000, -1000)): "80 28 00 00 2e e0 00 00 03 e8 ff ff fc 18 80 b6",
    ("ResetEncoders", ()): "80 14 49 2d",
    ("SetEncM1", (0,)): "80 16 00 00 00 00 1d ff",
    ("SetEncM1", (2**32 - 1,)): "80 16 ff ff ff ff 84 30",
    ("SetEncM1", (-1,)): "80 16 ff ff ff ff 84 30",  # wraps
    ("SetEncM2", (1000,)): "80 17 00 00 03 e8 9e db",
    ("ReadEncM1", ()): "80 10",
    ("ReadEncM2", ()): "80 11",
    ("ReadSpeedM1", ()): "80 12",
    ("ReadSpeedM2", ()): "80 13",
    ("ReadMainBatteryVoltage", ()): "80 18",
    ("ReadLogicBatteryVoltage", ()): "80 19",
    ("ReadVersion", ()): "80 15",
    # D, P, I, QPPS: 0.25, 1.0, 0.5 in 16.16 fixed point; 1/3 truncates to 0x5555
    ("SetM1VelocityPID", (1.0, 0.5, 0.25, 44000)):
        "80 1c 00 00 40 00 00 01 00 00 00 00 80 00 00 00 ab e0 26 fa",
    ("SetM1VelocityPID", (0, 0, 0, 0)): "80 1c 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 3d 86",
    ("SetM1VelocityPID", (1 / 3, 0, 0, 1)): "80 1c 00 00 00 00 00 00 55 55 00 00 00 00 00 00 00 01 72 b0",
    ("SetM2VelocityPID", (1.0, 0.5, 0.25, 44000)):
        "80 1d 00 00 40 00 00 01 00 00 00 00 80 00 00 00 ab e0 36 18",
    ("ReadM1VelocityPID", ()): "80 37",
    ("ReadM2VelocityPID", ()): "80 38",
    ("ReadPWMs", ()): "80 30",
    ("ReadCurrents", ()): "80 31",
    ("SetMainVoltages", (60, 340)): "80 39 00 3c 01 54 e9 36",
    ("ReadMinMaxMainVoltages", ()): "80 3b",
    ("ReadMinMaxLogicVoltages", ()): "80 3c",
    ("ReadTemp", ()): "80 52",
    ("ReadError", ()): "80 5a",
    ("set_speed", (1, 0)): "80 23 00 00 00 00 32 46",
    ("set_speed", (1, 12000)): "80 23 00 00 2e e0 ea 81",
    ("set_speed", (2, -12000)): "80 24 ff ff d1 20 d3 26",
    ("set_speed", (1, 2**31)): struct.error,
    ("drive_motor", (1, 0)): "80 06 40 d9 38",
    ("drive_motor", (1, -64)): "80 06 00 91 fc",
    ("drive_motor", (1, 63)): "80 06 7f 1e 84",
    ("drive_motor", (2, 0)): "80 07 40 ea 09",
    ("drive_motor", (1, 64)): "80 06 80 00 74",  # out of range, sent anyway
    ("drive_motor", (1, -65)): struct.error,
    ("stop_motor", (1,)): "80 00 00 3b 5a",
    ("stop_motor", (2,)): "80 04 00 f7 9e",
    ("stop_all", ()): "80 00 00 3b 5a 80 04 00 f7 9e",
    ("reset_quad_encoders", ()): "80 16 00 00 00 00 1d ff 80 17 00 00 00 00 b7 ae",
    ("read_encoder", (1,)): "80 10",
    ("read_encoder", (2,)): "80 11",
    ("read_batt_voltage", ("main",)): "80 18",
    ("read_batt_voltage", ("logic",)): "80 19",
    ("read_speed", (1,)): "80 37 80 12",
    ("read_max_speed", (2,)): "80 38",
    ("read_currents", ()): "80 31",
    ("read_motor_pwms", ()): "80 30",
    ("read_temp_sensor", (1,)): "80 52",
    ("read_status", ()): "80 5a",
    ("drive_to_position_raw", (1, 1000, 2000, 1000, 5000, 1)):
        "80 41 00 00 03 e8 00 00 07 d0 00 00 03 e8 00 00 13 88 01 9d f9",
}

_PID_MAX = 0xFFFFFFFF / 65536
# (method, label) -> what the driver decodes
DECODED: dict[tuple[str, str], tuple[Any, ...] | type[Exception]] = {
    ("ReadEncM1", "zero"): (0, 0),
    ("ReadEncM1", "typical, backwards"): (12345, 2),
    ("ReadEncM1", "count 0xFFFFFFFF, overflow"): (-1, 4),  # manual: 4294967295
    ("ReadEncM1", "count 0x80000000, underflow"): (-2147483648, 1),  # manual: 2147483648
    ("ReadEncM1", "bad CRC"): Failed,
    ("ReadEncM1", "CRC over the data only"): Failed,
    ("ReadEncM1", "reply for address 0x81"): Failed,
    ("ReadEncM1", "status byte missing"): Failed,
    ("ReadEncM1", "no reply"): Failed,
    ("ReadEncM2", "typical"): (123456, 0),
    ("ReadSpeedM1", "zero"): (0, 0),
    ("ReadSpeedM1", "forward 12000"): (12000, 0),
    ("ReadSpeedM1", "backward 12000 (signed)"): (-12000, 1),
    ("ReadSpeedM1", "bad CRC"): Failed,
    ("ReadSpeedM2", "typical"): (1000, 0),
    ("ReadMainBatteryVoltage", "zero"): (0,),
    ("ReadMainBatteryVoltage", "12.3 V"): (123,),
    ("ReadMainBatteryVoltage", "max"): (65535,),
    ("ReadMainBatteryVoltage", "bad CRC"): Failed,
    ("ReadMainBatteryVoltage", "one byte short"): Failed,
    ("ReadLogicBatteryVoltage", "5.0 V"): (50,),
    ("ReadVersion", "typical"): ("USB Roboclaw 2x7a v4.1.34\n",),
    ("ReadVersion", "empty text"): ("\n",),
    ("ReadVersion", "bad CRC"): Failed,
    ("ReadVersion", "48 bytes, no terminator"): ("RoboClaw " + "x" * 39,),  # manual: invalid
    ("ReadM1VelocityPID", "defaults"): (1.0, 0.5, 0.25, 44000),
    ("ReadM1VelocityPID", "all ones"): (_PID_MAX, _PID_MAX, _PID_MAX, 4294967295),
    ("ReadM1VelocityPID", "bad CRC"): Failed,
    ("ReadPWMs", "+-max"): (32767, -32767),
    ("ReadCurrents", "1.5 A, -1 A"): (150, -100),
    ("ReadMinMaxMainVoltages", "6.0 V .. 34.0 V"): (60, 340),
    ("ReadMinMaxLogicVoltages", "6.0 V .. 34.0 V"): (60, 340),
    ("ReadTemp", "25.3 C"): (253,),
    ("ReadError", "normal"): (0,),
    ("ReadError", "position error limit warning"): (0x02000000,),
    ("ForwardM1", "ack"): (),
    ("ForwardM1", "0x00 instead of ack"): (),  # manual: not an acknowledgement
    ("ForwardM1", "no ack"): Failed,
    ("read_encoder", "typical"): (12345,),
    ("read_encoder", "count 0xFFFFFFFF"): (4294967295,),
    ("read_encoder", "bad CRC"): CRCException,
    ("read_encoder", "status byte missing"): struct.error,  # the CRC matched the 4 bytes it got
    ("read_encoder", "no reply"): struct.error,
    ("read_batt_voltage", "12.3 V"): (12.3,),
    ("read_currents", "1.5 A, -1 A"): (1.5, -1.0),
    ("read_status", "manual's 4-byte status"): CRCException,
    ("read_status", "driver's 1-byte status"): ("Warning: High Current - Motor 1",),
    ("set_speed", "ack"): (),
    ("set_speed", "0x00 instead of ack"): CRCException,
    ("set_speed", "no ack"): struct.error,
}


def _key(args: tuple[Any, ...]) -> str:
    return repr(args)


def test_every_entry_has_an_expectation() -> None:
    assert [(c.method, c.args) for c in CALLS] == list(REQUESTS)
    assert [(r.method, r.label) for r in REPLIES] == list(DECODED)


def test_literal_frames_follow_the_manual() -> None:
    assert binascii.crc_hqx(b"123456789", 0) == 0x31C3  # CRC-16/XMODEM check value
    for (method, _args), expected in REQUESTS.items():
        if isinstance(expected, str) and method[0].isupper():
            wire = bytes.fromhex(expected)
            assert wire[0] == 0x80
            if len(wire) > 2:  # a write: one CRC-signed frame
                assert binascii.crc_hqx(wire[:-2], 0).to_bytes(2, "big") == wire[-2:], method


@pytest.mark.parametrize("call", CALLS, ids=lambda c: f"{c.method}{_key(c.args)}")
def test_request(call: Any) -> None:
    expected = REQUESTS[(call.method, call.args)]
    if isinstance(expected, str):
        assert published_request(call.method, *call.args).hex(" ") == expected
    else:
        with pytest.raises(expected):
            published_request(call.method, *call.args)


def test_spec_bytes_mark_only_deviations() -> None:
    marked = {(c.method, c.args): c.spec_bytes for c in CALLS if c.spec_bytes is not None}
    assert marked == {
        ("ForwardM1", (128,)): ValueError,
        ("DutyM1", (32768,)): ValueError,
        ("DutyM1", (-32769,)): ValueError,
        ("SpeedM1", (2**31,)): ValueError,
        ("SetEncM1", (-1,)): ValueError,
        ("drive_motor", (1, 64)): ValueError,
    }
    for key in marked:
        assert isinstance(REQUESTS[key], str)  # the driver sends what the manual refuses


def test_a_byte_out_of_range_leaves_a_partial_frame() -> None:
    assert capture("ForwardM1", (-1,)) == (b"\x80\x00", OverflowError)


def test_retries_when_nothing_answers() -> None:
    assert capture("ReadEncM1", (), b"")[0] == bytes.fromhex("8010") * 3
    assert capture("ReadM1VelocityPID", (), b"")[0] == bytes.fromhex("8037") * 2  # one short
    assert capture("ForwardM1", (64,), b"")[0] == bytes.fromhex("8000 40 739e") * 3
    assert capture("set_speed", (1, 0), b"")[0] == bytes.fromhex("8023 00000000 3246")


@pytest.mark.parametrize("reply", REPLIES, ids=lambda r: f"{r.method}-{r.label}")
def test_decode(reply: Any) -> None:
    expected = DECODED[(reply.method, reply.label)]
    assert published_decode(reply.method, reply.args, reply.reply) == expected


def test_spec_values_mark_only_deviations() -> None:
    marked = {(r.method, r.label): r.spec_values for r in REPLIES if r.spec_values is not None}
    assert marked == {
        ("ReadEncM1", "count 0xFFFFFFFF, overflow"): (4294967295, 4),
        ("ReadEncM1", "count 0x80000000, underflow"): (2147483648, 1),
        ("ReadVersion", "48 bytes, no terminator"): Failed,
        ("ForwardM1", "0x00 instead of ack"): Failed,
        ("read_status", "manual's 4-byte status"): (0,),
        ("read_status", "driver's 1-byte status"): Failed,
    }
    for key, spec in marked.items():
        assert DECODED[key] != spec
