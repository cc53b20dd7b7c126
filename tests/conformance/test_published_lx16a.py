"""pylx16a through the pty harness: every captured packet and decoded reply, pinned.

The literals were worked out from the LX-16A bus servo protocol (55 55 ID LEN CMD PARAMS CHK,
LEN = params + 3, CHK = ~(ID + LEN + CMD + params) & 0xFF, 16-bit values low byte first, angles
0-1000 for 0-240 degrees), not copied from the harness; `packets` re-checks each literal's
framing independently. Where the driver deviates from the protocol document, the entry's
`spec_bytes` / `spec_values` hold the document's answer.
"""

from __future__ import annotations

from typing import Any

import pytest

pytest.importorskip("pylx16a")

from published import lx16a
from published.lx16a import Rejected
from pylx16a.lx16a import ServoArgumentError, ServoChecksumError, ServoTimeoutError


def packets(data: bytes) -> list[bytes] | None:
    """`data` split into well-formed packets, or None if it is not a run of them."""
    out = []
    while data:
        if len(data) < 6 or data[:2] != b"\x55\x55" or len(data) < data[3] + 3:
            return None
        frame, data = data[:data[3] + 3], data[data[3] + 3:]
        if frame[-1] != ~sum(frame[2:-1]) & 0xFF:
            return None
        out.append(frame)
    return out


# label -> packet(s) written (hex), or the exception the driver raises before writing anything
REQUESTS: dict[str, str | type[Exception]] = {
    "move_min": "55 55 01 07 01 00 00 00 00 f6",
    "move_typical": "55 55 01 07 01 f4 01 e8 03 16",  # 500, 1000 ms
    "move_max": "55 55 01 07 01 e8 03 30 75 66",  # 1000, 30000 ms
    "move_id0": "55 55 00 07 01 fa 00 f4 01 08",  # 250, 500 ms
    "move_id253": "55 55 fd 07 01 ee 02 01 00 09",  # 750, 1 ms
    "move_half_step": "55 55 01 07 01 02 00 00 00 f4",  # round(2.5) = 2, half to even
    "move_negative": ServoArgumentError,
    "move_over": ServoArgumentError,
    "move_time_over": "55 55 01 07 01 f4 01 31 75 5b",  # 30001 ms: spec refuses
    "move_wait": "55 55 01 07 07 f4 01 e8 03 10",
    "move_relative": "55 55 01 07 01 1e 02 00 00 d6",  # 500 + 42
    "move_relative_negative": ServoArgumentError,
    "move_relative_overshoot": "55 55 01 07 01 35 05 00 00 bc",  # 500 + 833 = 1333: spec refuses
    "move_start": "55 55 01 03 0b f0",
    "move_stop": "55 55 01 03 0c ef 55 55 01 03 1c df",  # then reads the position
    "set_id_0": "55 55 01 04 0d 00 ed",
    "set_id_253": "55 55 01 04 0d fd f0",
    "set_id_254": ServoArgumentError,
    "offset_0": "55 55 01 04 11 00 e9",
    "offset_max": "55 55 01 04 11 7d 6c",  # +125
    "offset_min": "55 55 01 04 11 83 66",  # -125
    "offset_minus_1": "55 55 01 04 11 fc ed",  # -1 deg = -4
    "offset_over": ServoArgumentError,
    "offset_permanent": "55 55 01 04 11 2a bf 55 55 01 03 12 e9",  # +42, then save
    "angle_limits_full": "55 55 01 07 14 00 00 e8 03 f8",
    "angle_limits_typical": "55 55 01 07 14 7d 00 6b 03 f8",  # 125, 875
    "angle_limits_equal": "55 55 01 07 14 00 00 00 00 e3",  # min == max: spec refuses
    "angle_limits_swapped": ServoArgumentError,
    "angle_limits_negative": ServoArgumentError,
    "vin_limits_full": "55 55 01 07 16 94 11 e0 2e 2e",  # 4500, 12000 mV
    "vin_limits_typical": "55 55 01 07 16 70 17 d0 20 6a",  # 6000, 8400 mV
    "vin_limits_equal": "55 55 01 07 16 58 1b 58 1b fb",  # min == max: spec refuses
    "vin_limits_under": ServoArgumentError,
    "temp_limit_min": "55 55 01 04 18 32 b0",
    "temp_limit_typical": "55 55 01 04 18 55 8d",
    "temp_limit_max": "55 55 01 04 18 64 7e",
    "temp_limit_under": ServoArgumentError,
    "motor_stop": "55 55 01 07 1d 01 00 00 00 d9",
    "motor_max": "55 55 01 07 1d 01 00 e8 03 ee",
    "motor_min": "55 55 01 07 1d 01 00 18 fc c5",  # -1000 as 0xFC18
    "motor_minus_1": "55 55 01 07 1d 01 00 ff ff db",
    "motor_over": ServoArgumentError,
    "servo_mode": "55 55 01 07 1d 00 00 00 00 da",
    "load": "55 55 01 04 1f 01 da",
    "unload": "55 55 01 04 1f 00 db",
    "load_broadcast": ServoArgumentError,
    "led_on": "55 55 01 04 21 00 d9",
    "led_off": "55 55 01 04 21 01 d8",
    "led_errors_none": "55 55 01 04 23 00 d7",
    "led_errors_all": "55 55 01 04 23 07 d0",
    "led_errors_temp_rotor": "55 55 01 04 23 05 d2",
    "read_move": "55 55 01 03 02 f9",
    "read_wait_move": "55 55 01 03 08 f3",
    "read_id": "55 55 01 03 0e ed",
    "read_id_broadcast": ServoArgumentError,
    "read_offset": "55 55 01 03 13 e8",
    "read_angle_limits": "55 55 01 03 15 e6",
    "read_vin_limits": "55 55 01 03 17 e4",
    "read_temp_limit": "55 55 01 03 19 e2",
    "read_motor_mode": "55 55 01 03 1e dd",
    "read_motor_speed": "55 55 01 03 1e dd",
    "read_load": "55 55 01 03 20 db",
    "read_led": "55 55 01 03 22 d9",
    "read_led_errors": "55 55 01 03 24 d7",
    "read_temp": "55 55 01 03 1a e1",
    "read_vin": "55 55 01 03 1b e0",
    "read_position": "55 55 01 03 1c df",
    "read_position_id253": "55 55 fd 03 1c e3",
}

SPEC_BYTES: dict[str, str | type[Exception]] = {
    "move_time_over": Rejected,
    "move_relative_negative": "55 55 01 07 01 ca 01 00 00 2b",  # 500 - 42 = 458
    "move_relative_overshoot": Rejected,
    "angle_limits_equal": Rejected,
    "vin_limits_equal": Rejected,
    "load_broadcast": "55 55 fe 04 1f 01 dd",
    "read_id_broadcast": "55 55 fe 03 0e f0",
}

# label -> what the driver returns (flat tuple), or the exception it raises
DECODED: dict[str, tuple[Any, ...] | type[Exception]] = {
    "position_0": (0.0,),
    "position_500": (120.0,),
    "position_1000": (240.0,),
    "position_minus_1": (-0.24,),
    "position_minus_100": (-24.0,),
    "temp_0": (0,),
    "temp_30": (30,),
    "temp_255": (255,),
    "vin_4500": (4500,),
    "vin_12000": (12000,),
    "vin_max": (65535,),
    "offset_0": (0.0,),
    "offset_max": (30.0,),
    "offset_min": (-30.0,),
    "offset_minus_1": (-0.24,),
    "offset_127": (-30.96,),  # bug: 127 taken as 127 - 256
    "angle_limits": (0.0, 240.0),
    "vin_limits": (4500, 12000),
    "temp_limit": (85,),
    "id_253": (253,),
    "move_hw": (240.0, 30000),
    "wait_move_hw": (120.0, 0),
    "servo_mode": (False,),
    "motor_mode": (True,),
    "motor_speed_max": (1000,),
    "motor_speed_min": (-1000,),
    "motor_speed_in_servo_mode": (),
    "loaded": (True,),
    "unloaded": (False,),
    "led_on": (True,),
    "led_off": (False,),
    "led_errors_none": (False, False, False),
    "led_errors_all": (True, True, True),
    "led_errors_temp_rotor": (True, False, True),
    "bad_checksum": ServoChecksumError,
    "bad_header": (30,),  # bug: header not checked
    "other_id": (30,),  # bug: ID not checked
    "other_cmd": (30,),  # bug: command not checked
    "bad_length": (30,),  # bug: LEN not checked
    "short": ServoTimeoutError,
    "silent": ServoTimeoutError,
    "too_long": ServoChecksumError,
}

SPEC_VALUES: dict[str, tuple[Any, ...] | type[Exception]] = {
    "offset_127": (30.48,),
    "bad_header": Rejected, "other_id": Rejected, "other_cmd": Rejected, "bad_length": Rejected,
}

# replies that are not one well-formed packet answering the read (or no packet at all)
NOT_A_PACKET = {"bad_checksum", "bad_header", "short", "silent", "bad_length"}


def test_every_entry_is_pinned() -> None:
    assert list(REQUESTS) == [c.label for c in lx16a.CALLS]
    assert list(DECODED) == [r.label for r in lx16a.REPLIES]


@pytest.mark.parametrize("call", lx16a.CALLS, ids=lambda c: c.label)
def test_request(call: lx16a.Call) -> None:
    expected = REQUESTS[call.label]
    if isinstance(expected, str):
        data = bytes.fromhex(expected)
        assert packets(data)
        assert lx16a.published_request(call.method, *call.args) == data
    else:
        with pytest.raises(expected):
            lx16a.published_request(call.method, *call.args)


@pytest.mark.parametrize("reply", lx16a.REPLIES, ids=lambda r: r.label)
def test_decode(reply: lx16a.Reply) -> None:
    framed = packets(reply.reply)
    assert (framed is not None and len(framed) == 1) == (reply.label not in NOT_A_PACKET)
    got = lx16a.published_decode(reply.method, reply.args, reply.reply)
    expected = DECODED[reply.label]
    assert got == expected
    if isinstance(expected, tuple):
        assert [type(v) for v in got] == [type(v) for v in expected]  # type: ignore[union-attr]


def test_spec_marks() -> None:
    spec_bytes = {c.label: c.spec_bytes for c in lx16a.CALLS if c.spec_bytes is not None}
    assert spec_bytes == {k: bytes.fromhex(v) if isinstance(v, str) else v for k, v in SPEC_BYTES.items()}
    for value in spec_bytes.values():
        assert value is Rejected or packets(value)  # type: ignore[arg-type]
    assert {r.label: r.spec_values for r in lx16a.REPLIES if r.spec_values is not None} == SPEC_VALUES
    for label, spec in SPEC_VALUES.items():
        assert spec != DECODED[label]  # a mark is a real deviation
