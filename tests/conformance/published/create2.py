"""iRobot Create 2 Open Interface as the published driver `pycreate2` speaks it, captured on a real pty.

Why: rdisc descriptions of the Create 2 must produce the bytes the driver people use produces, and
decode sensor packets as the OI specification says. This module runs `pycreate2.Create2` against the
master side of a pseudo-terminal and records what it really wrote.

The protocol (iRobot Create 2 Open Interface Specification, based on the Roomba 600)
-------------------------------------------------------------------------------------
Serial 115200 baud 8N1, no flow control, point to point (no address, no broadcast).

Command (host -> robot)::

    OPCODE  DATA1 .. DATAN

* No header, no length field, no checksum: the opcode fixes how many data bytes follow; the one
  variable command is Song (140), whose 2nd data byte counts *notes* (1-16), each note being two
  bytes, so it has 2N + 2 data bytes.
* 16-bit values are big-endian (high byte first), signed ones two's complement.
* No acknowledgement: commands are silent; only sensor requests answer.
* Opcodes used here: Reset 7 (robot answers a free-text boot banner), Start 128 (-> Passive),
  Safe 131, Full 132, Power 133 (powers down, -> Passive), Stop 173 (-> Off);
  Drive 137 [vel hi][vel lo][radius hi][radius lo]: velocity -500..500 mm/s, radius -2000..2000 mm,
  special radii 0x8000 or 0x7FFF = straight, 0xFFFF (-1) = spin clockwise, 0x0001 = counter-clockwise;
  Drive Direct 145 [right hi][right lo][left hi][left lo], -500..500 mm/s, *right wheel first*;
  Drive PWM 146 [right hi][right lo][left hi][left lo], -255..255;
  LEDs 139 [bits][power colour][power intensity]: bit 0 debris, 1 spot, 2 dock, 3 check robot;
  colour 0 green .. 255 red, intensity 0 off .. 255 full;
  Digit LEDs ASCII 164 [digit 3][digit 2][digit 1][digit 0], ASCII 32-126, leftmost digit first;
  Song 140 [song 0-4][length 1-16][note 31-127][duration 1/64 s 0-255]...; Play 141 [song 0-4];
  Sensors 142 [packet id].

Reply to Sensors 142 (robot -> host): the packet's data bytes only (no header, length or checksum).
Packet 100 is packets 7-58 back to back, 80 bytes; offsets (spec packet id in brackets)::

     0 [7]  bumps/wheel drops: bit 0 bump right, 1 bump left, 2 wheel drop right, 3 wheel drop left
     1 [8]  wall  2-5 [9-12] cliff left, front left, front right, right  6 [13] virtual wall (0/1)
     7 [14] overcurrents: bit 0 side brush, 1 reserved, 2 main brush, 3 right wheel, 4 left wheel
     8 [15] dirt detect u8 0-255   9 [16] unused   10 [17] IR omni u8
    11 [18] buttons: bit 0 clean, 1 spot, 2 dock, 3 minute, 4 hour, 5 day, 6 schedule, 7 clock
    12 [19] distance s16 mm   14 [20] angle s16 deg   16 [21] charging state u8 0-5
    17 [22] voltage u16 mV   19 [23] current s16 mA   21 [24] temperature s8 C
    22 [25] charge u16 mAh   24 [26] capacity u16 mAh   26 [27] wall signal u16
    28-35 [28-31] cliff left/front left/front right/right signal u16   36-38 [32, 33] unused
    39 [34] charging sources: bit 0 internal charger, 1 home base   40 [35] OI mode 0-3
    41 [36] song number   42 [37] song playing   43 [38] stream packets   44 [39] velocity s16
    46 [40] radius s16   48 [41] right velocity s16   50 [42] left velocity s16
    52 [43] left encoder counts s16   54 [44] right encoder counts s16 (both roll over)
    56 [45] light bumper: bit 0 left, 1 front left, 2 center left, 3 center right, 4 front right, 5 right
    57-68 [46-51] light bump left/front left/center left/center right/front right/right signal u16
    69 [52] IR left u8   70 [53] IR right u8
    71-78 [54-57] left motor, right motor, main brush, side brush current s16 mA
    79 [58] stasis: bit 0 toggling, 1 disabled

(The Stream command 148, not in pycreate2, is the one framed reply: [19][n][id][data]...[checksum],
the checksum making the 8-bit sum of every byte from the header 19 to the checksum zero.)

What the driver does
--------------------
`Create2(port)` opens pyserial (timeout 1 s; the harness shortens it to `TIMEOUT`). Every command
is one `SerialCommandInterface.write(opcode, data)`. `get_sensors` writes 142 100, sleeps 15 ms and
reads 80 bytes. Mode changes sleep 0.5 s: the harness replaces `pycreate2.create2api.time` by a
no-sleep shim while a call runs. `Create2.__del__` sends commands when the object is collected
(entry "destructor" below); the harness subclasses `Create2` with a silent `__del__` so no call's
capture ever holds the destructor's bytes. A call's bytes end where a marker the harness writes
after it through the same port arrives; the marker is cut off.

Bugs and deviations from the specification (entries marked `spec_bytes` / `spec_values`)
-----------------------------------------------------------------------------------------
1. Bumps and wheel drops are swapped left/right: `BumpsAndWheelDrop` is declared
   (bump_left, bump_right, wheeldrop_left, wheeldrop_right) but filled positionally with
   (bit 0 = BUMP_RIGHT, bit 1, bit 2 = WHEEL_DROP_RIGHT, bit 3). Reply "bump_right" (byte 0 = 0x01)
   decodes to bump_left=True; spec bump_right=True. Same for the wheel drops.
2. Overcurrent bits are wrong (OI.py MAIN_BRUSH=0x02, RIGHT_WHEEL=0x04, LEFT_WHEEL=0x08): the
   reserved bit 1 reads as main brush, the main brush bit 2 as right wheel, the right wheel bit 3
   as left wheel, and the left wheel bit 4 is never read. Replies "overcurrent_*".
3. Dirt detect is decoded signed (`b`): 200 reads -56; spec unsigned 0-255. Reply "dirt_200".
4. Encoder counts are decoded unsigned (0-65535); the spec gives a signed 16-bit counter that rolls
   over from 32767 to -32768. Equal modulo 65536; reply "encoders_negative" (0xFFFF: 65535 vs -1).
5. `safe`, `full`, `stop` and `reset` also send `clearSongMemory`: four Song + Play pairs
   (140 n 1 70 0, 141 n for n = 0..3), overwriting the user's songs 0-3 and sounding them. The
   spec commands are the single opcode (spec_bytes 131 / 132 / 173 / 7).
6. `playSong(n)` writes nothing (prints "Invalid Song") unless this Create2 object defined song n
   itself, although the robot keeps songs across connections. Call "play_undefined".
7. `createSong` checks nothing: `2 > size > 32` and `0 > song_num > 3` are always false, so song 5,
   17 notes or an empty song are sent (spec: song 0-4, 1-16 notes); an odd list raises a bare
   Exception. Marked `Rejected`.
8. `digit_led_ascii` upper-cases (its docstring says so): the spec displays the ASCII codes given,
   lower case included (call "digits_lower"). It replaces codes outside 32-126 by a space
   ("digits_unprintable", marked Rejected), pads short strings with spaces and drops characters
   after the fourth (not marked: the bytes sent are valid).
9. `getMode` raises AttributeError (`OPCODES.MODE` does not exist) before writing; it meant to
   send opcode 35, which is no command at all: the OI mode is sensor packet 35, read by 142 35.
10. There is no `drive` (137): only commented-out code. Entries "drive_*" are composed here with
    the driver's own `SCI.write(OPCODES.DRIVE, ...)` and the packing of that code (`>hH`).
11. `drive_direct` / `drive_pwm` clamp out-of-range values silently (600 -> 500); the spec only
    gives the range. Marked `Rejected` (an rdisc description should refuse them).
12. `get_sensors` does not flush the input first and checks only the length: a short or missing
    reply raises a bare Exception after the port timeout (1 s by default); a long reply decodes
    and leaves its extra bytes to shift the next read. (No header or checksum exists to check.)
13. `__del__` writes 145 0 0 0 0, 139 0 0 0, 164 32 32 32 32, the song clearing and 173, and
    sleeps about 1 s, whenever the object is garbage-collected.
Not capturable: `wake()` pulses RTS/DTR (no bytes; a pty refuses the ioctl).
"""

from __future__ import annotations

import contextlib
import io
import struct
from collections.abc import Iterator
from types import SimpleNamespace
from typing import Any, NamedTuple

import pycreate2.create2api
from devices import PtyDevice, pty_device
from pycreate2 import Create2
from pycreate2.OI import OPCODES

__all__ = [
    "CALLS", "FIELDS", "REPLIES", "TIMEOUT", "Call", "Rejected", "Reply",
    "published_decode", "published_request",
]

TIMEOUT = 0.5  # the port timeout the harness gives the driver (seconds): room for a busy machine
_MARK = b"\x00<end of call>\x00"  # written after a call; never a Create 2 command sequence


class Rejected(Exception):
    """Marker for `spec_bytes` / `spec_values`: the specification says this must be refused."""


class Call(NamedTuple):
    """One driver call `Create2.<method>(*args)`, after the `setup` calls (whose bytes are not kept)."""

    label: str
    method: str
    args: tuple[Any, ...]
    primitive: str  # suggested rdisc primitive ("" for no protocol command)
    spec_bytes: bytes | type[Exception] | None = None  # set where the driver deviates from the spec
    setup: tuple[tuple[str, tuple[Any, ...]], ...] = ()


class Reply(NamedTuple):
    """Bytes the robot answers to `Create2.<method>(*args)`, and what the spec says they decode to."""

    label: str
    method: str
    args: tuple[Any, ...]
    reply: bytes
    # where the driver deviates: the fields it decodes wrongly, by FIELDS name, with the spec's value
    spec_values: dict[str, Any] | type[Exception] | None = None


_CLEAR_SONGS = b"".join(bytes([140, n, 1, 70, 0, 141, n]) for n in range(4))
_SIXTEEN = [31, 0, 127, 255] * 8  # 16 notes: lowest note/shortest, highest note/longest
_DEFINE_0 = (("createSong", (0, [60, 32])),)

CALLS: list[Call] = [
    Call("start", "start", (), "start"),
    Call("safe", "safe", (), "safe", b"\x83"),
    Call("full", "full", (), "full", b"\x84"),
    Call("power", "power", (), "power"),
    Call("stop", "stop", (), "stop", b"\xad"),
    Call("reset", "reset", (), "reset", b"\x07"),
    Call("get_mode", "getMode", (), "oi_mode", b"\x8e\x23"),  # raises AttributeError, writes nothing
    Call("drive_direct_zero", "drive_direct", (0, 0), "drive_direct"),
    Call("drive_direct_max", "drive_direct", (500, 500), "drive_direct"),
    Call("drive_direct_min", "drive_direct", (-500, -500), "drive_direct"),
    Call("drive_direct_spin", "drive_direct", (100, -100), "drive_direct"),
    Call("drive_direct_minus_one", "drive_direct", (-1, 1), "drive_direct"),
    Call("drive_direct_clamped", "drive_direct", (600, -600), "drive_direct", Rejected),
    Call("drive_stop", "drive_stop", (), "drive_direct"),
    Call("drive_pwm_zero", "drive_pwm", (0, 0), "drive_pwm"),
    Call("drive_pwm_max", "drive_pwm", (255, 255), "drive_pwm"),
    Call("drive_pwm_min", "drive_pwm", (-255, -255), "drive_pwm"),
    Call("drive_pwm_typical", "drive_pwm", (128, -64), "drive_pwm"),
    Call("drive_pwm_clamped", "drive_pwm", (256, -256), "drive_pwm", Rejected),
    Call("drive_zero", "drive", (0, 0), "drive"),
    Call("drive_arc", "drive", (200, 500), "drive"),
    Call("drive_arc_back", "drive", (-200, -500), "drive"),
    Call("drive_max_radius", "drive", (-500, 2000), "drive"),
    Call("drive_straight", "drive", (500, 0x8000), "drive"),
    Call("drive_straight_alt", "drive", (500, 0x7FFF), "drive"),
    Call("drive_spin_cw", "drive", (100, -1), "drive"),
    Call("drive_spin_ccw", "drive", (100, 1), "drive"),
    Call("leds_off", "led", (), "leds"),
    Call("leds_max", "led", (0x0F, 255, 255), "leds"),
    Call("leds_debris_green", "led", (0x01, 0, 255), "leds"),
    Call("leds_check_orange", "led", (0x08, 128, 64), "leds"),
    Call("digits", "digit_led_ascii", ("ABCD",), "digit_leds_ascii"),
    Call("digits_blank", "digit_led_ascii", ("    ",), "digit_leds_ascii"),
    Call("digits_max", "digit_led_ascii", ("~~~~",), "digit_leds_ascii"),
    Call("digits_numbers", "digit_led_ascii", ("2017",), "digit_leds_ascii"),
    Call("digits_lower", "digit_led_ascii", ("abcd",), "digit_leds_ascii", b"\xa4abcd"),
    Call("digits_short", "digit_led_ascii", ("12",), "digit_leds_ascii"),
    Call("digits_long", "digit_led_ascii", ("ABCDE",), "digit_leds_ascii"),
    Call("digits_unprintable", "digit_led_ascii", ("\x1fA\x7fB",), "digit_leds_ascii", Rejected),
    Call("song_one_note", "createSong", (0, [60, 32]), "song"),
    Call("song_4_sixteen_notes", "createSong", (4, _SIXTEEN), "song"),
    Call("song_3_extremes", "createSong", (3, (127, 255, 31, 0)), "song"),
    Call("song_number_5", "createSong", (5, [60, 32]), "song", Rejected),
    Call("song_17_notes", "createSong", (0, [60, 8] * 17), "song", Rejected),
    Call("song_empty", "createSong", (0, []), "song", Rejected),
    Call("song_odd", "createSong", (0, [60, 32, 70]), "song"),  # refused too (a bare Exception)
    Call("play_0", "playSong", (0,), "play", setup=_DEFINE_0),
    Call("play_4", "playSong", (4,), "play", setup=(("createSong", (4, [72, 16])),)),
    Call("play_undefined", "playSong", (0,), "play", b"\x8d\x00"),
    Call("sensors", "get_sensors", (), "sensors_all"),
    Call("destructor", "__del__", (), ""),
]

# (spec field name, attribute path in the driver's Sensors namedtuple), in the order of packet 100.
FIELDS: tuple[tuple[str, str], ...] = (
    ("bump_right", "bumps_wheeldrops.bump_right"),
    ("bump_left", "bumps_wheeldrops.bump_left"),
    ("wheel_drop_right", "bumps_wheeldrops.wheeldrop_right"),
    ("wheel_drop_left", "bumps_wheeldrops.wheeldrop_left"),
    ("wall", "wall"),
    ("cliff_left", "cliff_left"),
    ("cliff_front_left", "cliff_front_left"),
    ("cliff_front_right", "cliff_front_right"),
    ("cliff_right", "cliff_right"),
    ("virtual_wall", "virtual_wall"),
    ("side_brush_overcurrent", "overcurrents.side_brush_overcurrent"),
    ("main_brush_overcurrent", "overcurrents.main_brush_overcurrent"),
    ("right_wheel_overcurrent", "overcurrents.right_wheel_overcurrent"),
    ("left_wheel_overcurrent", "overcurrents.left_wheel_overcurrent"),
    ("dirt_detect", "dirt_detect"),
    ("ir_omni", "ir_opcode"),
    ("button_clean", "buttons.clean"),
    ("button_spot", "buttons.spot"),
    ("button_dock", "buttons.dock"),
    ("button_minute", "buttons.minute"),
    ("button_hour", "buttons.hour"),
    ("button_day", "buttons.day"),
    ("button_schedule", "buttons.schedule"),
    ("button_clock", "buttons.clock"),
    ("distance", "distance"),
    ("angle", "angle"),
    ("charging_state", "charger_state"),
    ("voltage", "voltage"),
    ("current", "current"),
    ("temperature", "temperature"),
    ("battery_charge", "battery_charge"),
    ("battery_capacity", "battery_capacity"),
    ("wall_signal", "wall_signal"),
    ("cliff_left_signal", "cliff_left_signal"),
    ("cliff_front_left_signal", "cliff_front_left_signal"),
    ("cliff_front_right_signal", "cliff_front_right_signal"),
    ("cliff_right_signal", "cliff_right_signal"),
    ("internal_charger", "charger_available.internal_charger"),
    ("home_base", "charger_available.home_base"),
    ("oi_mode", "open_interface_mode"),
    ("song_number", "song_number"),
    ("song_playing", "song_playing"),
    ("stream_packets", "oi_stream_num_packets"),
    ("velocity", "velocity"),
    ("radius", "radius"),
    ("right_velocity", "velocity_right"),
    ("left_velocity", "velocity_left"),
    ("left_encoder", "encoder_counts_left"),
    ("right_encoder", "encoder_counts_right"),
    ("light_bumper_left", "light_bumper.left"),
    ("light_bumper_front_left", "light_bumper.front_left"),
    ("light_bumper_center_left", "light_bumper.center_left"),
    ("light_bumper_center_right", "light_bumper.center_right"),
    ("light_bumper_front_right", "light_bumper.front_right"),
    ("light_bumper_right", "light_bumper.right"),
    ("light_bump_left_signal", "light_bumper_left"),
    ("light_bump_front_left_signal", "light_bumper_front_left"),
    ("light_bump_center_left_signal", "light_bumper_center_left"),
    ("light_bump_center_right_signal", "light_bumper_center_right"),
    ("light_bump_front_right_signal", "light_bumper_front_right"),
    ("light_bump_right_signal", "light_bumper_right"),
    ("ir_left", "ir_opcode_left"),
    ("ir_right", "ir_opcode_right"),
    ("left_motor_current", "left_motor_current"),
    ("right_motor_current", "right_motor_current"),
    ("main_brush_current", "main_brush_current"),
    ("side_brush_current", "side_brush_current"),
    ("stasis_toggling", "statis.toggling"),
    ("stasis_disabled", "statis.disabled"),
)


def packet100(**at: bytes) -> bytes:
    """80 zero bytes with `o<offset>=bytes` patched in (offsets as in the table above)."""
    data = bytearray(80)
    for key, value in at.items():
        offset = int(key[1:])
        data[offset:offset + len(value)] = value
    return bytes(data)


# Every field away from zero: a typical robot driving forward on its dock-side.
TYPICAL = bytes.fromhex(
    "05" "01" "00010001" "01" "19" "c8" "00" "a1" "81"  # 0-11: bumps, wall, cliffs, vwall, oc, dirt, -, ir, btn
    "ff38" "005a" "02" "3e80" "fc18" "1c" "0a28" "0b54"  # 12-25: distance -200, angle 90, ..., capacity
    "03ff" "0fff" "0000" "0800" "0001"  # 26-35: wall signal 1023, cliff signals
    "000000" "03" "02" "04" "01" "02"  # 36-43: unused, sources, OI mode, song 4 playing, 2 stream packets
    "01f4" "8000" "fe0c" "0064" "8000" "7fff"  # 44-55: velocity..right encoder
    "21" "0001" "0002" "0fff" "0000" "0100" "0200"  # 56-68: light bumper bits, signals
    "a2" "00" "ff9c" "0064" "8000" "7fff" "03"  # 69-79: IR left/right, currents, stasis
)

REPLIES: list[Reply] = [
    Reply("zeros", "get_sensors", (), packet100()),
    Reply("ones", "get_sensors", (), b"\xff" * 80, {"dirt_detect": 255, "left_encoder": -1, "right_encoder": -1}),
    Reply("typical", "get_sensors", (), TYPICAL, {
        "bump_right": True, "bump_left": False, "wheel_drop_right": True, "wheel_drop_left": False,
        "right_wheel_overcurrent": True, "dirt_detect": 200, "left_encoder": -32768,
    }),
    Reply("bump_right", "get_sensors", (), packet100(o0=b"\x01"), {"bump_right": True, "bump_left": False}),
    Reply("bump_left", "get_sensors", (), packet100(o0=b"\x02"), {"bump_right": False, "bump_left": True}),
    Reply("wheel_drop_right", "get_sensors", (), packet100(o0=b"\x04"),
          {"wheel_drop_right": True, "wheel_drop_left": False}),
    Reply("wheel_drop_left", "get_sensors", (), packet100(o0=b"\x08"),
          {"wheel_drop_right": False, "wheel_drop_left": True}),
    Reply("overcurrent_side_brush", "get_sensors", (), packet100(o7=b"\x01")),
    Reply("overcurrent_reserved_bit", "get_sensors", (), packet100(o7=b"\x02"), {"main_brush_overcurrent": False}),
    Reply("overcurrent_main_brush", "get_sensors", (), packet100(o7=b"\x04"),
          {"main_brush_overcurrent": True, "right_wheel_overcurrent": False}),
    Reply("overcurrent_right_wheel", "get_sensors", (), packet100(o7=b"\x08"),
          {"right_wheel_overcurrent": True, "left_wheel_overcurrent": False}),
    Reply("overcurrent_left_wheel", "get_sensors", (), packet100(o7=b"\x10"), {"left_wheel_overcurrent": True}),
    Reply("dirt_200", "get_sensors", (), packet100(o8=b"\xc8"), {"dirt_detect": 200}),
    Reply("buttons_clean_clock", "get_sensors", (), packet100(o11=b"\x81")),
    Reply("signed_minimum", "get_sensors", (), packet100(
        o12=b"\x80\x00", o14=b"\x80\x00", o19=b"\x80\x00", o21=b"\x80", o44=b"\xfe\x0c", o46=b"\xf8\x30",
        o71=b"\x80\x00")),
    Reply("unsigned_maximum", "get_sensors", (), packet100(o17=b"\xff\xff", o22=b"\xff\xff", o10=b"\xff",
                                                          o69=b"\xff", o70=b"\xff")),
    Reply("encoders_negative", "get_sensors", (), packet100(o52=b"\xff\xff", o54=b"\x80\x00"),
          {"left_encoder": -1, "right_encoder": -32768}),
    Reply("light_bumper_right", "get_sensors", (), packet100(o56=b"\x20")),
    Reply("stasis_disabled", "get_sensors", (), packet100(o79=b"\x02")),
    Reply("long", "get_sensors", (), packet100() + b"\x01"),  # decodes; the extra byte stays queued
    Reply("short", "get_sensors", (), packet100()[:79]),  # a bare Exception (after the timeout)
    Reply("silent", "get_sensors", (), b""),  # a bare Exception after the timeout
]


class _Create2(Create2):
    """`Create2` whose destructor is silent: its commands must not leak into a later capture."""

    def __del__(self) -> None:
        pass


class _Replier:
    """Device side: answers `reply` once the host wrote bytes ending with `trigger`."""

    def __init__(self, trigger: bytes, reply: bytes) -> None:
        self.trigger, self.reply = trigger, reply
        self.seen = bytearray()
        self.armed = bool(trigger and reply)

    def __call__(self, data: bytes) -> bytes | None:
        self.seen += data
        if self.armed and self.seen.endswith(self.trigger):
            self.armed = False
            return self.reply
        return None


_TRIGGERS = {"get_sensors": b"\x8e\x64", "reset": b"\x07"}
_BANNER = b"bl-start\r\nSTR730\r\nbootloader id: #x47186549 82ECCFFF\r\nRoomba by iRobot!\r\n"


@contextlib.contextmanager
def _robot(reply: _Replier) -> Iterator[tuple[_Create2, PtyDevice]]:
    """A Create2 on a pty whose master answers through `reply`; sleeps and prints suppressed."""
    saved = pycreate2.create2api.time
    with pty_device(reply) as dev, contextlib.redirect_stdout(io.StringIO()):
        pycreate2.create2api.time = SimpleNamespace(sleep=lambda _s: None)  # type: ignore[assignment]
        robot = _Create2(dev.port)
        robot.SCI.ser.timeout = TIMEOUT
        try:
            yield robot, dev
        finally:
            pycreate2.create2api.time = saved
            robot.close()


def _drain(robot: Create2, dev: PtyDevice) -> bytes:
    """Everything the driver wrote since the last drain (waits for a marker written after it)."""
    if not robot.SCI.ser.is_open:  # the destructor closed it
        robot.SCI.ser.open()
    robot.SCI.ser.write(_MARK)
    received = dev.wait_until(lambda: dev.received.endswith(_MARK), 2.0, "the end-of-call marker")
    dev.clear()
    return received[: -len(_MARK)]


def _call(robot: Create2, method: str, args: tuple[Any, ...]) -> Any:
    if method == "drive":  # no driver method: the driver's write and its commented-out packing
        velocity, radius = args
        data = struct.unpack("4B", struct.pack(">hH", velocity, radius & 0xFFFF))
        return robot.SCI.write(OPCODES.DRIVE, data)
    if method == "__del__":
        return Create2.__del__(robot)
    return getattr(robot, method)(*args)


def published_request(method: str, *args: Any, setup: tuple[tuple[str, tuple[Any, ...]], ...] = ()) -> bytes:
    """The bytes `Create2.<method>(*args)` writes, after `setup` calls (not included).

    Requests that read are answered validly (80 zero bytes, a boot banner). A driver exception
    propagates.
    """
    answer = packet100() if method == "get_sensors" else _BANNER
    with _robot(_Replier(_TRIGGERS.get(method, b""), answer)) as (robot, dev):
        for name, setup_args in setup:
            _call(robot, name, setup_args)
        _drain(robot, dev)
        try:
            _call(robot, method, args)
        finally:
            written = _drain(robot, dev)
        return written


def _field(sensors: Any, path: str) -> Any:
    for name in path.split("."):
        sensors = getattr(sensors, name)
    return sensors


def published_decode(method: str, args: tuple[Any, ...], reply: bytes) -> tuple[Any, ...] | type[Exception]:
    """What `Create2.<method>(*args)` decodes from `reply` (b"": silence), or its exception type.

    For `get_sensors`: one value per `FIELDS` entry, taken from the driver's namedtuple by the
    field's *name*, so a driver that names a bit wrongly shows up as a wrong value.
    """
    with _robot(_Replier(_TRIGGERS[method], reply)) as (robot, _dev):
        try:
            sensors = _call(robot, method, args)
        except Exception as exc:  # noqa: BLE001 - the exception type is the result
            return type(exc)
    return tuple(_field(sensors, path) for _name, path in FIELDS)
