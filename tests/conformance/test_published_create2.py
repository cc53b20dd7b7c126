"""The pycreate2 harness captures real bytes: each entry pinned to bytes worked out from the OI spec.

Why: the rdisc Create 2 description will be checked against `published/create2.py`; these literal
expectations (computed by hand from the iRobot Create 2 OI specification, not copied from the
harness) prove the harness records what the driver writes and that every deviation is marked.
"""

from __future__ import annotations

from typing import Any

import pytest

pytest.importorskip("pycreate2")

from published.create2 import CALLS, FIELDS, REPLIES, Rejected, published_decode, published_request

SAME = "same as the spec"
SONGS = "8c 00 01 46 00 8d 00  8c 01 01 46 00 8d 01  8c 02 01 46 00 8d 02  8c 03 01 46 00 8d 03"

# label: (spec bytes in hex or Rejected, what the driver does: SAME, other hex, or the exception it raises)
EXPECTED_CALLS: dict[str, tuple[str | type[Exception], str | type[Exception]]] = {
    "start": ("80", SAME),
    "safe": ("83", "83 " + SONGS),
    "full": ("84", "84 " + SONGS),
    "power": ("85", SAME),
    "stop": ("ad", SONGS + " ad"),
    "reset": ("07", SONGS + " 07"),
    "get_mode": ("8e 23", AttributeError),  # Sensors, packet 35 (OI mode)
    "drive_direct_zero": ("91 0000 0000", SAME),
    "drive_direct_max": ("91 01f4 01f4", SAME),  # 500 = 0x01F4, right first
    "drive_direct_min": ("91 fe0c fe0c", SAME),  # -500 = 0x10000 - 500 = 0xFE0C
    "drive_direct_spin": ("91 0064 ff9c", SAME),  # right 100, left -100
    "drive_direct_minus_one": ("91 ffff 0001", SAME),
    "drive_direct_clamped": (Rejected, "91 01f4 fe0c"),
    "drive_stop": ("91 0000 0000", SAME),
    "drive_pwm_zero": ("92 0000 0000", SAME),
    "drive_pwm_max": ("92 00ff 00ff", SAME),
    "drive_pwm_min": ("92 ff01 ff01", SAME),  # -255 = 0xFF01
    "drive_pwm_typical": ("92 0080 ffc0", SAME),  # 128, -64
    "drive_pwm_clamped": (Rejected, "92 00ff ff01"),
    "drive_zero": ("89 0000 0000", SAME),
    "drive_arc": ("89 00c8 01f4", SAME),  # 200 mm/s, radius 500 mm
    "drive_arc_back": ("89 ff38 fe0c", SAME),  # -200, -500
    "drive_max_radius": ("89 fe0c 07d0", SAME),  # -500, 2000
    "drive_straight": ("89 01f4 8000", SAME),
    "drive_straight_alt": ("89 01f4 7fff", SAME),
    "drive_spin_cw": ("89 0064 ffff", SAME),
    "drive_spin_ccw": ("89 0064 0001", SAME),
    "leds_off": ("8b 00 00 00", SAME),
    "leds_max": ("8b 0f ff ff", SAME),
    "leds_debris_green": ("8b 01 00 ff", SAME),
    "leds_check_orange": ("8b 08 80 40", SAME),
    "digits": ("a4 41 42 43 44", SAME),  # "ABCD"
    "digits_blank": ("a4 20 20 20 20", SAME),
    "digits_max": ("a4 7e 7e 7e 7e", SAME),
    "digits_numbers": ("a4 32 30 31 37", SAME),
    "digits_lower": ("a4 61 62 63 64", "a4 41 42 43 44"),
    "digits_short": ("a4 31 32 20 20", SAME),  # padded with blanks
    "digits_long": ("a4 41 42 43 44", SAME),  # the first four
    "digits_unprintable": (Rejected, "a4 20 41 20 42"),
    "song_one_note": ("8c 00 01 3c 20", SAME),  # song 0, 1 note: C4 (60) for 32/64 s
    "song_4_sixteen_notes": ("8c 04 10" + " 1f 00 7f ff" * 8, SAME),
    "song_3_extremes": ("8c 03 02 7f ff 1f 00", SAME),
    "song_number_5": (Rejected, "8c 05 01 3c 20"),
    "song_17_notes": (Rejected, "8c 00 11" + " 3c 08" * 17),
    "song_empty": (Rejected, "8c 00 00"),
    "song_odd": (Rejected, Exception),  # the driver refuses too (bare Exception)
    "play_0": ("8d 00", SAME),
    "play_4": ("8d 04", SAME),
    "play_undefined": ("8d 00", ""),
    "sensors": ("8e 64", SAME),  # Sensors, packet 100
    "destructor": ("91 0000 0000  8b 00 00 00  a4 20 20 20 20 " + SONGS + " ad", SAME),
}


def test_every_call_has_an_expectation() -> None:
    assert [c.label for c in CALLS] == list(EXPECTED_CALLS)


@pytest.mark.parametrize("call", CALLS, ids=[c.label for c in CALLS])
def test_call_bytes(call: Any) -> None:
    spec, driver = EXPECTED_CALLS[call.label]
    if isinstance(driver, type):
        with pytest.raises(driver):
            published_request(call.method, *call.args, setup=call.setup)
    else:
        wanted = spec if driver == SAME else driver
        assert isinstance(wanted, str)
        assert published_request(call.method, *call.args, setup=call.setup) == bytes.fromhex(wanted)
    agrees = driver == SAME or (spec is Rejected and isinstance(driver, type))
    assert call.spec_bytes == (None if agrees else spec if spec is Rejected else bytes.fromhex(str(spec)))


# Types the spec gives each packet-100 field; everything else is a bit or a 0/1 byte.
U8 = {"dirt_detect", "ir_omni", "charging_state", "oi_mode", "song_number", "stream_packets", "ir_left",
      "ir_right"}
U16 = {"voltage", "battery_charge", "battery_capacity", "wall_signal", "cliff_left_signal",
       "cliff_front_left_signal", "cliff_front_right_signal", "cliff_right_signal", "light_bump_left_signal",
       "light_bump_front_left_signal", "light_bump_center_left_signal", "light_bump_center_right_signal",
       "light_bump_front_right_signal", "light_bump_right_signal"}
SIGNED = {"temperature", "distance", "angle", "current", "velocity", "radius", "right_velocity",
          "left_velocity", "left_encoder", "right_encoder", "left_motor_current", "right_motor_current",
          "main_brush_current", "side_brush_current"}
NAMES = [name for name, _path in FIELDS]
ZERO = dict.fromkeys(NAMES, 0)
ONES = {n: 255 if n in U8 else 65535 if n in U16 else -1 if n in SIGNED else True for n in NAMES}

# label: (spec values of the non-zero fields, or the exception; the fields the driver decodes otherwise)
EXPECTED_REPLIES: dict[str, tuple[dict[str, Any] | type[Exception], dict[str, Any]]] = {
    "zeros": ({}, {}),
    "ones": (ONES, {"dirt_detect": -1, "left_encoder": 65535, "right_encoder": 65535}),
    "typical": ({
        "bump_right": True, "wheel_drop_right": True, "wall": True, "cliff_front_left": True,
        "cliff_right": True, "virtual_wall": True, "side_brush_overcurrent": True,
        "right_wheel_overcurrent": True, "left_wheel_overcurrent": True, "dirt_detect": 200, "ir_omni": 161,
        "button_clean": True, "button_clock": True, "distance": -200, "angle": 90, "charging_state": 2,
        "voltage": 16000, "current": -1000, "temperature": 28, "battery_charge": 2600,
        "battery_capacity": 2900, "wall_signal": 1023, "cliff_left_signal": 4095,
        "cliff_front_right_signal": 2048, "cliff_right_signal": 1, "internal_charger": True,
        "home_base": True, "oi_mode": 2, "song_number": 4, "song_playing": True, "stream_packets": 2,
        "velocity": 500, "radius": -32768, "right_velocity": -500, "left_velocity": 100,
        "left_encoder": -32768, "right_encoder": 32767, "light_bumper_left": True, "light_bumper_right": True,
        "light_bump_left_signal": 1, "light_bump_front_left_signal": 2, "light_bump_center_left_signal": 4095,
        "light_bump_front_right_signal": 256, "light_bump_right_signal": 512, "ir_left": 162,
        "left_motor_current": -100, "right_motor_current": 100, "main_brush_current": -32768,
        "side_brush_current": 32767, "stasis_toggling": True, "stasis_disabled": True,
    }, {"bump_right": False, "bump_left": True, "wheel_drop_right": False, "wheel_drop_left": True,
        "right_wheel_overcurrent": False, "dirt_detect": -56, "left_encoder": 32768}),
    "bump_right": ({"bump_right": True}, {"bump_right": False, "bump_left": True}),
    "bump_left": ({"bump_left": True}, {"bump_right": True, "bump_left": False}),
    "wheel_drop_right": ({"wheel_drop_right": True}, {"wheel_drop_right": False, "wheel_drop_left": True}),
    "wheel_drop_left": ({"wheel_drop_left": True}, {"wheel_drop_right": True, "wheel_drop_left": False}),
    "overcurrent_side_brush": ({"side_brush_overcurrent": True}, {}),
    "overcurrent_reserved_bit": ({}, {"main_brush_overcurrent": True}),
    "overcurrent_main_brush": ({"main_brush_overcurrent": True},
                               {"main_brush_overcurrent": False, "right_wheel_overcurrent": True}),
    "overcurrent_right_wheel": ({"right_wheel_overcurrent": True},
                                {"right_wheel_overcurrent": False, "left_wheel_overcurrent": True}),
    "overcurrent_left_wheel": ({"left_wheel_overcurrent": True}, {"left_wheel_overcurrent": False}),
    "dirt_200": ({"dirt_detect": 200}, {"dirt_detect": -56}),
    "buttons_clean_clock": ({"button_clean": True, "button_clock": True}, {}),
    "signed_minimum": ({"distance": -32768, "angle": -32768, "current": -32768, "temperature": -128,
                        "velocity": -500, "radius": -2000, "left_motor_current": -32768}, {}),
    "unsigned_maximum": ({"voltage": 65535, "battery_charge": 65535, "ir_omni": 255, "ir_left": 255,
                          "ir_right": 255}, {}),
    "encoders_negative": ({"left_encoder": -1, "right_encoder": -32768},
                          {"left_encoder": 65535, "right_encoder": 32768}),
    "light_bumper_right": ({"light_bumper_right": True}, {}),
    "stasis_disabled": ({"stasis_disabled": True}, {}),
    "long": ({}, {}),
    "short": (Exception, {}),
    "silent": (Exception, {}),
}


def test_every_reply_has_an_expectation() -> None:
    assert [r.label for r in REPLIES] == list(EXPECTED_REPLIES)
    assert len(NAMES) == 69 and len(set(NAMES)) == 69


@pytest.mark.parametrize("reply", REPLIES, ids=[r.label for r in REPLIES])
def test_reply_values(reply: Any) -> None:
    spec, driver_differs = EXPECTED_REPLIES[reply.label]
    decoded = published_decode(reply.method, reply.args, reply.reply)
    if isinstance(spec, type):
        assert decoded is spec
        assert reply.spec_values is None
        return
    assert isinstance(decoded, tuple)
    spec_all = {**ZERO, **spec}
    assert dict(zip(NAMES, decoded)) == {**spec_all, **driver_differs}
    assert reply.spec_values == ({k: spec_all[k] for k in driver_differs} or None)
