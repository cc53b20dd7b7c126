"""pyax12 through the pty harness: every captured packet and decoded reply, pinned.

The literals were worked out from the AX-12 manual (protocol 1.0: FF FF ID LEN INSTR PARAMS CHK,
LEN = params + 2, CHK = ~(ID + LEN + INSTR + params) & 0xFF, 16-bit values low byte first), not
copied from the harness; `frame_ok` re-checks each literal's framing independently. Where the
driver deviates from the manual, the entry's `spec_bytes` / `spec_values` hold the manual's answer.
"""

from __future__ import annotations

from typing import Any

import pytest

pytest.importorskip("pyax12")

from published import ax12
from published.ax12 import Rejected
from pyax12 import status_packet as sp


def frame_ok(frame: bytes) -> bool:
    """One protocol 1.0 packet: FF FF header, LEN = bytes after LEN, checksum over ID..last param."""
    return (len(frame) >= 6 and frame[:2] == b"\xff\xff" and frame[3] == len(frame) - 4
            and frame[-1] == ~sum(frame[2:-1]) & 0xFF)


# label -> instruction packet (hex), or the exception the driver raises before sending anything
REQUESTS: dict[str, str | type[Exception]] = {
    "ping_id0": "ff ff 00 02 01 fc",
    "ping_id1": "ff ff 01 02 01 fb",
    "ping_id253": "ff ff fd 02 01 ff",
    "ping_broadcast": "ff ff fe 02 01 fe",
    "ping_id255": ValueError,
    "read_position_raw": "ff ff 01 04 02 24 02 d2",
    "read_control_table": "ff ff 01 04 02 00 32 c6",
    "torque_on": "ff ff 01 04 03 18 01 de",
    "torque_off": "ff ff 01 04 03 18 00 df",
    "torque_off_broadcast": "ff ff fe 04 03 18 00 e2",
    "led_on": "ff ff 01 04 03 19 01 dd",
    "led_off_id253": "ff ff fd 04 03 19 00 e2",
    "present_position": "ff ff 01 04 02 24 02 d2",
    "present_position_degrees": "ff ff 01 04 02 24 02 d2",
    "present_speed": "ff ff 01 04 02 26 02 d0",
    "present_load": "ff ff 01 04 02 28 02 ce",
    "present_voltage": "ff ff 01 04 02 2a 01 cd",
    "present_temperature": "ff ff 01 04 02 2b 01 cc",
    "is_moving": "ff ff 01 04 02 2e 01 c9",
    "goal_position": "ff ff 01 04 02 1e 02 d8",
    "moving_speed": "ff ff 01 04 02 20 02 d6",
    "torque_limit": "ff ff 01 04 02 22 02 d4",
    "cw_angle_limit": "ff ff 01 04 02 06 02 f0",
    "ccw_angle_limit": "ff ff 01 04 02 08 02 ee",
    "model_number": "ff ff 01 04 02 00 02 f6",
    "firmware_version": "ff ff 01 04 02 02 01 f5",
    "baud_rate": "ff ff 01 04 02 04 01 f3",
    "return_delay_time": "ff ff 01 04 02 05 01 f2",
    "max_temperature": "ff ff 01 04 02 0b 01 ec",
    "min_voltage": "ff ff 01 04 02 0c 01 eb",
    "max_voltage": "ff ff 01 04 02 0d 01 ea",
    "max_torque": "ff ff 01 04 02 0e 02 e8",
    "status_return_level": "ff ff 01 04 02 10 01 e7",
    "is_torque_enable": "ff ff 01 04 02 18 01 df",
    "is_led_enabled": "ff ff 01 04 02 19 01 de",
    "goto_0": "ff ff 01 05 03 1e 00 00 d8",
    "goto_512": "ff ff 01 05 03 1e 00 02 d6",
    "goto_1023": "ff ff 01 05 03 1e ff 03 d6",
    "goto_1024": "ff ff 01 05 03 1e 00 04 d4",  # above the 0-1023 range: spec refuses
    "goto_negative": ValueError,
    "goto_speed_0": "ff ff 01 07 03 1e 00 02 00 00 d4",
    "goto_speed_1023": "ff ff 01 07 03 1e 2c 01 ff 03 a7",
    "goto_broadcast": "ff ff fe 05 03 1e 00 02 d9",
    "goto_deg_min": "ff ff 01 05 03 1e 00 00 d8",
    "goto_deg_0": "ff ff 01 05 03 1e ff 01 d8",  # floor(511.5) = 511 = 0x1FF, the manual's 150 deg
    "goto_deg_max": "ff ff 01 05 03 1e ff 03 d6",
    "goto_deg_over": "ff ff 01 05 03 1e 02 04 d2",  # 1026: spec refuses
    "set_speed_0": "ff ff 01 05 03 20 00 00 d6",
    "set_speed_1023": "ff ff 01 05 03 20 ff 03 d4",
    "set_speed_wheel_cw_max": "ff ff 01 05 03 20 ff 07 d0",
    "set_speed_negative": ValueError,
    "set_id_0": "ff ff 01 04 03 03 00 f4",
    "set_id_253": "ff ff 01 04 03 03 fd f7",
    "set_id_254": "ff ff 01 04 03 03 fe f6",  # the broadcast ID as an ID: spec refuses
    "set_id_negative": ValueError,
    "baud_1mbps": "ff ff 01 04 03 04 01 f2",  # 2 000 000 / (1 + 1)
    "baud_57600": "ff ff 01 04 03 04 22 d1",  # 34
    "baud_9600_bps": "ff ff 01 04 03 04 cf 24",  # 207
    "baud_raw_0": "ff ff 01 04 03 04 00 f3",
    "baud_raw_254": "ff ff 01 04 03 04 fe f5",
    "return_delay_0": "ff ff 01 04 03 05 00 f2",
    "return_delay_1us": "ff ff 01 04 03 05 00 f2",  # round(1 / 2) = 0 (half to even)
    "return_delay_500us": "ff ff 01 04 03 05 fa f8",  # 250 x 2 us
    "return_delay_raw_254": "ff ff 01 04 03 05 fe f4",
    "cw_limit_0": "ff ff 01 05 03 06 00 00 f0",
    "cw_limit_1023": "ff ff 01 05 03 06 ff 03 ee",
    "cw_limit_deg_min": "ff ff 01 05 03 06 00 00 f0",
    "ccw_limit_0_wheel": "ff ff 01 05 03 08 00 00 ee",
    "ccw_limit_1023": "ff ff 01 05 03 08 ff 03 ec",
    "ccw_limit_deg_max": "ff ff 01 05 03 08 ff 03 ec",
}

SPEC_BYTES: dict[str, bytes | type[Exception]] = {
    "goto_1024": Rejected, "goto_deg_over": Rejected, "set_id_254": Rejected,
}

# label -> what the driver returns (flat tuple), or the exception it raises
DECODED: dict[str, tuple[Any, ...] | type[Exception]] = {
    "ping_ok": (True,),
    "ping_other_id": (False,),
    "ping_silent": (False,),
    "position_0": (0,),
    "position_512": (512,),
    "position_1023": (1023,),
    "position_deg_0": (-150.0,),
    "position_deg_512": (0.1,),
    "position_deg_1023": (150.0,),
    "speed_0": (0,),
    "speed_ccw_max": (1023,),
    "speed_cw_max": (2047,),
    "load_0": (0,),
    "load_ccw_100": (-100,),  # bug: a CCW load comes out negative ("clockwise")
    "load_ccw_max": (-1023,),
    "load_cw_100": (100,),
    "load_cw_max": (1023,),
    "voltage_0": (0.0,),
    "voltage_12v": (12.0,),
    "voltage_max": (25.5,),
    "temperature_0": (0,),
    "temperature_40": (40,),
    "temperature_max": (255,),
    "moving_no": (False,),
    "moving_yes": (True,),
    "model_ax12": (12,),
    "baud_1mbps": (1000000.0,),
    "write_ack": (),
    "write_silent": (),
    "err_input_voltage": sp.InputVoltageError,
    "err_angle_limit": sp.AngleLimitError,
    "err_overheating": sp.OverheatingError,
    "err_range": sp.RangeError,
    "err_checksum": sp.InstructionChecksumError,
    "err_overload": sp.OverloadError,
    "err_instruction": sp.InstructionError,
    "err_reserved_bit7": (40,),
    "bad_checksum": sp.StatusChecksumError,
    "bad_header": ValueError,
    "no_checksum": ValueError,
    "truncated": ValueError,
    "silent": TypeError,
    "other_id": TypeError,
    "too_few_params": ValueError,
    "too_many_params_2byte": ValueError,
    "too_many_params_1byte": (40,),  # bug: the extra parameter is ignored
    "length_too_big": ValueError,
}

SPEC_VALUES: dict[str, tuple[Any, ...] | type[Exception]] = {
    "load_ccw_100": (100,), "load_ccw_max": (1023,), "load_cw_100": (-100,), "load_cw_max": (-1023,),
    "too_many_params_1byte": Rejected,
}

# replies that are not one well-formed status packet (or no packet at all)
NOT_A_PACKET = {"ping_silent", "write_silent", "bad_checksum", "bad_header", "no_checksum", "truncated",
                "silent", "length_too_big"}


def test_every_entry_is_pinned() -> None:
    assert list(REQUESTS) == [c.label for c in ax12.CALLS]
    assert list(DECODED) == [r.label for r in ax12.REPLIES]


@pytest.mark.parametrize("call", ax12.CALLS, ids=lambda c: c.label)
def test_request(call: ax12.Call) -> None:
    expected = REQUESTS[call.label]
    if isinstance(expected, str):
        packet = bytes.fromhex(expected)
        assert frame_ok(packet)
        assert ax12.published_request(call.method, *call.args) == packet
    else:
        with pytest.raises(expected):
            ax12.published_request(call.method, *call.args)


@pytest.mark.parametrize("reply", ax12.REPLIES, ids=lambda r: r.label)
def test_decode(reply: ax12.Reply) -> None:
    assert frame_ok(reply.reply) == (reply.label not in NOT_A_PACKET)
    got = ax12.published_decode(reply.method, reply.args, reply.reply)
    expected = DECODED[reply.label]
    assert got == expected
    if isinstance(expected, tuple):
        assert [type(v) for v in got] == [type(v) for v in expected]  # type: ignore[union-attr]


def test_spec_marks() -> None:
    assert {c.label: c.spec_bytes for c in ax12.CALLS if c.spec_bytes is not None} == SPEC_BYTES
    assert {r.label: r.spec_values for r in ax12.REPLIES if r.spec_values is not None} == SPEC_VALUES
    for label, spec in SPEC_VALUES.items():
        assert spec != DECODED[label]  # a mark is a real deviation
