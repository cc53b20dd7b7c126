"""HiWonder LX-16A bus servo as the published driver `pylx16a` speaks it, captured on a real pty.

Why: rdisc descriptions of the LX-16A must produce the same bytes as the driver people use, and
decode replies as the servo's protocol document says. This module runs `pylx16a.lx16a.LX16A`
against an emulated servo on the master side of a pseudo-terminal and records what it wrote.
`pylx16a.lx16a` imports only pyserial (PyQt6, a dependency of the package, is for its separate GUI),
so no Qt is needed.

The protocol (LewanSoul/HiWonder "Bus Servo Communication Protocol", 115200 baud, half duplex)
----------------------------------------------------------------------------------------------
Every packet, both ways::

    55 55  ID  LEN  CMD  P1 .. PN  CHK

* header: two 0x55 bytes.
* ID: 0-253 addresses one servo; 254 (0xFE) is broadcast: every servo takes the command and none
  answers, except SERVO_ID_READ, which a single servo on the bus answers with its own ID.
* LEN = N + 3: it counts itself, CMD, the N parameters and CHK (not the header or ID); the packet
  is LEN + 3 bytes long.
* CHK = ~(ID + LEN + CMD + P1 + ... + PN) & 0xFF: the low byte of the inverted sum of every byte
  after the header.
* 16-bit parameters are little-endian (low byte first). Angles are 0-1000 for 0-240 degrees
  (0.24 degree steps), times 0-30000 ms, voltages 4500-12000 mV.
* Write commands (no reply): MOVE_TIME_WRITE 1 (angle, time), MOVE_TIME_WAIT_WRITE 7 (angle, time;
  starts on MOVE_START 11), MOVE_STOP 12, ID_WRITE 13 (id 0-253), ANGLE_OFFSET_ADJUST 17 (signed
  byte -125..125 = -30..30 degrees), ANGLE_OFFSET_WRITE 18 (save it), ANGLE_LIMIT_WRITE 20 (min, max;
  min < max), VIN_LIMIT_WRITE 22 (min, max mV; min < max), TEMP_MAX_LIMIT_WRITE 24 (50-100 C),
  OR_MOTOR_MODE_WRITE 29 (mode 0 servo / 1 motor, 0, signed 16-bit speed -1000..1000),
  LOAD_OR_UNLOAD_WRITE 31 (0 unload, 1 load), LED_CTRL_WRITE 33 (0 LED on, 1 off),
  LED_ERROR_WRITE 35 (bits: 1 over temperature, 2 over voltage, 4 locked rotor).
* Read commands have no parameter; the servo answers with a packet of the same layout carrying the
  same CMD: MOVE_TIME_READ 2 and MOVE_TIME_WAIT_READ 8 (angle, time: LEN 7), ID_READ 14 (LEN 4),
  ANGLE_OFFSET_READ 19 (signed byte, LEN 4), ANGLE_LIMIT_READ 21 (LEN 7), VIN_LIMIT_READ 23 (LEN 7),
  TEMP_MAX_LIMIT_READ 25 (LEN 4), TEMP_READ 26 (C, LEN 4), VIN_READ 27 (mV, LEN 5), POS_READ 28
  (signed 16-bit, may be negative, LEN 5), OR_MOTOR_MODE_READ 30 (mode, 0, signed speed: LEN 7),
  LOAD_OR_UNLOAD_READ 32, LED_CTRL_READ 34, LED_ERROR_READ 36 (LEN 4 each).
  There is no acknowledgement and no error/status byte.

What the driver does
--------------------
`LX16A.initialize(port, timeout)` opens the port into the class attribute `LX16A._controller`.
The constructor `LX16A(id)` reads POS, ANGLE_OFFSET, ANGLE_LIMIT, VIN_LIMIT, TEMP_MAX_LIMIT,
OR_MOTOR_MODE (and the speed, read again, in motor mode), LOAD_OR_UNLOAD, LED_CTRL and LED_ERROR,
then writes LOAD_OR_UNLOAD 1 (enables torque): the emulated servo answers all of these, and the
capture starts after them. A read writes the request, reads exactly LEN + 3 bytes with the port
timeout and checks only the checksum. Angles are degrees converted with Python's round(deg * 25 / 6),
which rounds halves to even (`move(1, 0.6)`: 2.5 steps -> 2), a detail a description must match.

Bugs and deviations from the protocol document (entries marked `spec_bytes` / `spec_values`)
--------------------------------------------------------------------------------------------------
1. Replies are not validated beyond the checksum: a wrong header (not 55 55), another servo's ID,
   another command's CMD, or a LEN that does not match are all decoded as if right
   (`get_temp` with such replies returns the value). Spec: refuse (`Rejected`).
2. Broadcast is impossible: `LX16A(254)` raises ServoArgumentError, so neither broadcast writes
   (e.g. LOAD_OR_UNLOAD to all) nor the documented ID discovery (ID_READ to 254) can be sent.
   Marked with the spec packet as `spec_bytes`.
3. `move(..., time)` does not check time against 0-30000 ms: `move(1, 120, 30001)` is sent.
4. Relative moves (`relative=True`) are range-checked before the current angle is added: a negative
   step (`move(1, -10, 0, True)`) is refused although its target (458) is valid, and a step that
   overshoots (`move(1, 200, 0, True)` from 500: 1333) is sent unchecked.
5. `set_angle_limits` and `set_vin_limits` accept min == max; the document requires min < max.
6. `get_angle_offset` treats raw 126 and 127 as negative (threshold > 125 instead of the signed-byte
   > 127); outside the documented -125..125 but a deviation from the stated signed conversion.
7. A reply shorter than expected raises ServoTimeoutError after the port timeout (fine), but its
   message counts the expected parameter bytes, not the packet bytes. Not marked.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import Any, NamedTuple

from devices import PtyDevice
from pylx16a.lx16a import LX16A

__all__ = ["CALLS", "REPLIES", "Call", "Rejected", "Reply", "published_decode", "published_request"]

BROADCAST = 0xFE
TIMEOUT = 0.5  # port timeout: a short or missing reply raises ServoTimeoutError after it (room for a busy machine)
# Written by the harness after the driver's bytes: once it arrives, everything before it has.
SENTINEL = b"\x00\xa5\x5a\x00\xa5\x5a"


class Rejected(Exception):
    """Marker for `spec_bytes` / `spec_values`: the specification says this must be refused."""


class Call(NamedTuple):
    """One driver call: `LX16A(args[0]).<method>(*args[1:])`."""

    label: str
    method: str
    args: tuple[Any, ...]
    spec_bytes: bytes | type[Exception] | None = None  # set where the driver deviates from the spec


class Reply(NamedTuple):
    """A reply fed to `LX16A(args[0]).<method>(*args[1:])`, and what the spec says it decodes to."""

    label: str
    method: str
    args: tuple[Any, ...]
    reply: bytes
    spec_values: tuple[Any, ...] | type[Exception] | None = None  # set where the driver deviates


def checksum(body: bytes) -> int:
    """The protocol's checksum of the bytes after the header (ID to last parameter)."""
    return ~sum(body) & 0xFF


def packet(servo_id: int, cmd: int, params: bytes = b"") -> bytes:
    """A well-formed packet (both directions have the same layout)."""
    body = bytes([servo_id, len(params) + 3, cmd]) + params
    return b"\x55\x55" + body + bytes([checksum(body)])


CALLS: list[Call] = [
    Call("move_min", "move", (1, 0)),
    Call("move_typical", "move", (1, 120, 1000)),
    Call("move_max", "move", (1, 240, 30000)),
    Call("move_id0", "move", (0, 60, 500)),
    Call("move_id253", "move", (253, 180, 1)),
    Call("move_half_step", "move", (1, 0.6)),  # 2.5 steps: Python rounds half to even
    Call("move_negative", "move", (1, -1)),
    Call("move_over", "move", (1, 240.5)),
    Call("move_time_over", "move", (1, 120, 30001), Rejected),
    Call("move_wait", "move", (1, 120, 1000, False, True)),
    Call("move_relative", "move", (1, 10, 0, True)),
    Call("move_relative_negative", "move", (1, -10, 0, True), packet(1, 1, b"\xca\x01\x00\x00")),
    Call("move_relative_overshoot", "move", (1, 200, 0, True), Rejected),
    Call("move_start", "move_start", (1,)),
    Call("move_stop", "move_stop", (1,)),
    Call("set_id_0", "set_id", (1, 0)),
    Call("set_id_253", "set_id", (1, 253)),
    Call("set_id_254", "set_id", (1, 254)),
    Call("offset_0", "set_angle_offset", (1, 0)),
    Call("offset_max", "set_angle_offset", (1, 30)),
    Call("offset_min", "set_angle_offset", (1, -30)),
    Call("offset_minus_1", "set_angle_offset", (1, -1)),
    Call("offset_over", "set_angle_offset", (1, 31)),
    Call("offset_permanent", "set_angle_offset", (1, 10, True)),
    Call("angle_limits_full", "set_angle_limits", (1, 0, 240)),
    Call("angle_limits_typical", "set_angle_limits", (1, 30, 210)),
    Call("angle_limits_equal", "set_angle_limits", (1, 0, 0), Rejected),
    Call("angle_limits_swapped", "set_angle_limits", (1, 240, 0)),
    Call("angle_limits_negative", "set_angle_limits", (1, -1, 240)),
    Call("vin_limits_full", "set_vin_limits", (1, 4500, 12000)),
    Call("vin_limits_typical", "set_vin_limits", (1, 6000, 8400)),
    Call("vin_limits_equal", "set_vin_limits", (1, 7000, 7000), Rejected),
    Call("vin_limits_under", "set_vin_limits", (1, 4499, 12000)),
    Call("temp_limit_min", "set_temp_limit", (1, 50)),
    Call("temp_limit_typical", "set_temp_limit", (1, 85)),
    Call("temp_limit_max", "set_temp_limit", (1, 100)),
    Call("temp_limit_under", "set_temp_limit", (1, 49)),
    Call("motor_stop", "motor_mode", (1, 0)),
    Call("motor_max", "motor_mode", (1, 1000)),
    Call("motor_min", "motor_mode", (1, -1000)),
    Call("motor_minus_1", "motor_mode", (1, -1)),
    Call("motor_over", "motor_mode", (1, 1001)),
    Call("servo_mode", "servo_mode", (1,)),
    Call("load", "enable_torque", (1,)),
    Call("unload", "disable_torque", (1,)),
    Call("load_broadcast", "enable_torque", (BROADCAST,), packet(BROADCAST, 31, b"\x01")),
    Call("led_on", "led_power_on", (1,)),
    Call("led_off", "led_power_off", (1,)),
    Call("led_errors_none", "set_led_error_triggers", (1, False, False, False)),
    Call("led_errors_all", "set_led_error_triggers", (1, True, True, True)),
    Call("led_errors_temp_rotor", "set_led_error_triggers", (1, True, False, True)),
    Call("read_move", "get_last_instant_move_hw", (1,)),
    Call("read_wait_move", "get_last_delayed_move_hw", (1,)),
    Call("read_id", "get_id", (1, True)),
    Call("read_id_broadcast", "get_id", (BROADCAST, True), packet(BROADCAST, 14)),
    Call("read_offset", "get_angle_offset", (1, True)),
    Call("read_angle_limits", "get_angle_limits", (1, True)),
    Call("read_vin_limits", "get_vin_limits", (1, True)),
    Call("read_temp_limit", "get_temp_limit", (1, True)),
    Call("read_motor_mode", "is_motor_mode", (1, True)),
    Call("read_motor_speed", "get_motor_speed", (1, True)),
    Call("read_load", "is_torque_enabled", (1, True)),
    Call("read_led", "is_led_power_on", (1, True)),
    Call("read_led_errors", "get_led_error_triggers", (1, True)),
    Call("read_temp", "get_temp", (1,)),
    Call("read_vin", "get_vin", (1,)),
    Call("read_position", "get_physical_angle", (1,)),
    Call("read_position_id253", "get_physical_angle", (253,)),
]

_TEMP_30 = packet(1, 26, b"\x1e")
REPLIES: list[Reply] = [
    Reply("position_0", "get_physical_angle", (1,), packet(1, 28, b"\x00\x00")),
    Reply("position_500", "get_physical_angle", (1,), packet(1, 28, b"\xf4\x01")),
    Reply("position_1000", "get_physical_angle", (1,), packet(1, 28, b"\xe8\x03")),
    Reply("position_minus_1", "get_physical_angle", (1,), packet(1, 28, b"\xff\xff")),
    Reply("position_minus_100", "get_physical_angle", (1,), packet(1, 28, b"\x9c\xff")),
    Reply("temp_0", "get_temp", (1,), packet(1, 26, b"\x00")),
    Reply("temp_30", "get_temp", (1,), _TEMP_30),
    Reply("temp_255", "get_temp", (1,), packet(1, 26, b"\xff")),
    Reply("vin_4500", "get_vin", (1,), packet(1, 27, b"\x94\x11")),
    Reply("vin_12000", "get_vin", (1,), packet(1, 27, b"\xe0\x2e")),
    Reply("vin_max", "get_vin", (1,), packet(1, 27, b"\xff\xff")),
    Reply("offset_0", "get_angle_offset", (1, True), packet(1, 19, b"\x00")),
    Reply("offset_max", "get_angle_offset", (1, True), packet(1, 19, b"\x7d")),
    Reply("offset_min", "get_angle_offset", (1, True), packet(1, 19, b"\x83")),
    Reply("offset_minus_1", "get_angle_offset", (1, True), packet(1, 19, b"\xff")),
    Reply("offset_127", "get_angle_offset", (1, True), packet(1, 19, b"\x7f"), (30.48,)),
    Reply("angle_limits", "get_angle_limits", (1, True), packet(1, 21, b"\x00\x00\xe8\x03")),
    Reply("vin_limits", "get_vin_limits", (1, True), packet(1, 23, b"\x94\x11\xe0\x2e")),
    Reply("temp_limit", "get_temp_limit", (1, True), packet(1, 25, b"\x55")),
    Reply("id_253", "get_id", (1, True), packet(1, 14, b"\xfd")),
    Reply("move_hw", "get_last_instant_move_hw", (1,), packet(1, 2, b"\xe8\x03\x30\x75")),
    Reply("wait_move_hw", "get_last_delayed_move_hw", (1,), packet(1, 8, b"\xf4\x01\x00\x00")),
    Reply("servo_mode", "is_motor_mode", (1, True), packet(1, 30, b"\x00\x00\x00\x00")),
    Reply("motor_mode", "is_motor_mode", (1, True), packet(1, 30, b"\x01\x00\xe8\x03")),
    Reply("motor_speed_max", "get_motor_speed", (1, True), packet(1, 30, b"\x01\x00\xe8\x03")),
    Reply("motor_speed_min", "get_motor_speed", (1, True), packet(1, 30, b"\x01\x00\x18\xfc")),
    Reply("motor_speed_in_servo_mode", "get_motor_speed", (1, True), packet(1, 30, b"\x00\x00\x00\x00")),
    Reply("loaded", "is_torque_enabled", (1, True), packet(1, 32, b"\x01")),
    Reply("unloaded", "is_torque_enabled", (1, True), packet(1, 32, b"\x00")),
    Reply("led_on", "is_led_power_on", (1, True), packet(1, 34, b"\x00")),
    Reply("led_off", "is_led_power_on", (1, True), packet(1, 34, b"\x01")),
    Reply("led_errors_none", "get_led_error_triggers", (1, True), packet(1, 36, b"\x00")),
    Reply("led_errors_all", "get_led_error_triggers", (1, True), packet(1, 36, b"\x07")),
    Reply("led_errors_temp_rotor", "get_led_error_triggers", (1, True), packet(1, 36, b"\x05")),
    Reply("bad_checksum", "get_temp", (1,), _TEMP_30[:-1] + bytes([_TEMP_30[-1] ^ 0xFF])),
    Reply("bad_header", "get_temp", (1,), b"\xaa\xaa" + _TEMP_30[2:], Rejected),
    Reply("other_id", "get_temp", (1,), packet(2, 26, b"\x1e"), Rejected),
    Reply("other_cmd", "get_temp", (1,), packet(1, 25, b"\x1e"), Rejected),
    Reply("bad_length", "get_temp", (1,), b"\x55\x55\x01\x05\x1a\x1e\xc1", Rejected),
    Reply("short", "get_temp", (1,), _TEMP_30[:-1]),
    Reply("silent", "get_temp", (1,), b""),
    Reply("too_long", "get_temp", (1,), packet(1, 26, b"\x1e\x00")),
]

# Read command -> reply parameters of the emulated servo (position 500, so relative moves show).
_READS: dict[int, bytes] = {
    2: b"\xf4\x01\x00\x00", 8: b"\xf4\x01\x00\x00", 14: b"", 19: b"\x00", 21: b"\x00\x00\xe8\x03",
    23: b"\x94\x11\xe0\x2e", 25: b"\x55", 26: b"\x1e", 27: b"\xe8\x1c", 28: b"\xf4\x01",
    30: b"\x00\x00\x00\x00", 32: b"\x00", 34: b"\x00", 36: b"\x07",
}


class _Lx16a(PtyDevice):
    """An LX-16A on the bus: answers read commands, or `override` once (for the next read) if set."""

    def __init__(self, servo_id: int, motor_mode: bool = False) -> None:
        super().__init__()
        self.servo_id = servo_id
        self.reads = dict(_READS)
        self.reads[14] = bytes([servo_id])
        if motor_mode:
            self.reads[30] = b"\x01\x00\x64\x00"
        self.override: bytes | None = None
        self._pending = bytearray()

    def handle(self, data: bytes) -> None:
        self._pending += data
        while (frame := self._next_packet()) is not None:
            servo_id, cmd = frame[2], frame[4]
            if cmd not in self.reads or checksum(frame[2:-1]) != frame[-1]:
                continue
            if servo_id != self.servo_id and not (servo_id == BROADCAST and cmd == 14):
                continue
            reply = packet(self.servo_id, cmd, self.reads[cmd])
            if self.override is not None:
                reply, self.override = self.override, None
            self.send(reply)

    def _next_packet(self) -> bytes | None:
        start = self._pending.find(b"\x55\x55")
        if start < 0:
            del self._pending[:-1]
            return None
        del self._pending[:start]
        if len(self._pending) < 4 or len(self._pending) < 3 + self._pending[3]:
            return None
        size = 3 + self._pending[3]
        frame = bytes(self._pending[:size])
        del self._pending[:size]
        return frame


def _drain(dev: _Lx16a) -> bytes:
    """Everything the driver wrote so far, once it has all arrived (the sentinel follows it)."""
    assert LX16A._controller is not None
    LX16A._controller.write(SENTINEL)
    received = dev.wait_until(lambda: dev.received.endswith(SENTINEL), 2.0, "the sentinel")
    return received[: -len(SENTINEL)]


@contextlib.contextmanager
def _servo(method: str, servo_id: int) -> Iterator[tuple[_Lx16a, LX16A]]:
    """A constructed `LX16A(servo_id)` on a pty, with the constructor's traffic already cleared."""
    emulated_id = servo_id if 0 <= servo_id <= 253 else 1
    with _Lx16a(emulated_id, motor_mode=method == "get_motor_speed") as dev:
        LX16A.initialize(dev.port, timeout=TIMEOUT)
        try:
            servo = LX16A(servo_id)
            if method == "move_start":  # needs a move waiting for it
                servo.move(120, 1000, False, True)
            _drain(dev)
            dev.clear()
            yield dev, servo
        finally:
            controller, LX16A._controller = LX16A._controller, None
            if controller is not None:
                controller.close()


def published_request(method: str, *args: Any) -> bytes:
    """The bytes `LX16A(args[0]).<method>(*args[1:])` writes (the emulated servo answers validly).

    A driver exception (ServoArgumentError for an out-of-range argument, ...) propagates.
    """
    with _servo(method, args[0]) as (dev, servo):
        getattr(servo, method)(*args[1:])
        return _drain(dev)


def published_decode(method: str, args: tuple[Any, ...], reply: bytes) -> tuple[Any, ...] | type[Exception]:
    """What `LX16A(args[0]).<method>(*args[1:])` returns when the servo answers `reply` (b"": silence).

    A flat tuple of values (() for None), or the type of the exception the driver raised.
    """
    with _servo(method, args[0]) as (dev, servo):
        dev.override = reply
        try:
            result = getattr(servo, method)(*args[1:])
        except Exception as exc:  # noqa: BLE001 - the exception type is the result
            return type(exc)
    if result is None:
        return ()
    return tuple(result) if isinstance(result, (tuple, list)) else (result,)
