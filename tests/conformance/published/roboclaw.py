"""What the published RoboClaw drivers put on the wire, and what they make of replies.

Two drivers are captured, each talking to an emulated RoboClaw on a real pseudo-terminal:
`tcr_roboclaw` 0.1.5 (module `tcr_roboclaw`, class `Roboclaw`: Basicmicro's own library,
repackaged; CamelCase methods) and `roboclaw` 1.0.0.dev1 (module `roboclaw.roboclaw`, class
`RoboClaw`, "pyroboclaw"; snake_case methods). Method names never collide, so the method
name alone says which driver runs. `tcr_roboclaw` is the reference: it covers every command
with the manual's layouts; where the manual says otherwise, entries carry the manual's answer.

Packet serial as the Basicmicro RoboClaw user manual specifies it
------------------------------------------------------------------
* Write command: ``[address, command, data..., crc_hi, crc_lo]``. The address is
  0x80..0x87 (packet modes 7..14; any of them over USB). There is no broadcast address and
  no length field: the command fixes the data layout. Multi-byte values are big-endian.
* CRC: CRC-16/XMODEM (poly 0x1021, init 0x0000, not reflected, no final xor) over address,
  command and data; sent high byte first.
* Acknowledgement: a valid write-only command is answered by the single byte 0xFF; an
  invalid one (bad CRC, ...) by nothing at all.
* Read command: the host sends ``[address, command]`` only, no CRC (both drivers do).
  The reply is ``[data..., crc_hi, crc_lo]`` with the CRC computed over the request's
  address and command bytes followed by the reply data; the reply has no address of its
  own, so a reply meant for another address or command fails the CRC.
* A gap above 10 ms between bytes of a packet makes the device discard the packet.

Commands covered (fields in order; uN/sN = unsigned/signed N bits; "->" = read reply)::

    0/1    u8 0..127                      M1 forward / backward (0 = stop)
    4/5    u8 0..127                      M2 forward / backward
    6/7    u8 0..127                      M1 / M2 7-bit: 0 full reverse, 64 stop, 127 full forward
    8-13   u8 0..127                      mixed forward, backward, right, left, 7-bit f/b, l/r
    16/17  -> u32 count, u8 status        encoder M1 / M2, count 0..4,294,967,295; status bit 0
                                          underflow, bit 1 backwards, bit 2 overflow
    18/19  -> 32-bit speed, u8 status     pulses/s M1 / M2, status 1 = backward (sign of the
                                          speed not stated; Basicmicro's library: signed)
    20     (no data)                      reset both quadrature encoder counters
    21     -> text, 0x0A, 0x00            firmware version, up to 48 bytes
    22/23  u32 value                      set encoder M1 / M2
    24/25  -> u16                         main / logic battery, tenths of a volt
    28/29  u32 D, u32 P, u32 I, u32 QPPS  set velocity PID M1 / M2 (D first; 16.16 fixed point)
    32/33  s16 duty -32768..32767         duty M1 / M2
    34     s16 duty M1, s16 duty M2
    35/36  s32 speed                      speed M1 / M2, quadrature pulses per second
    37     s32 speed M1, s32 speed M2
    38/39  u32 accel, s32 speed           speed with acceleration M1 / M2
    40     u32 accel, s32 speed M1, s32 speed M2
    48     -> s16 pwm M1, s16 pwm M2      +-32767
    49     -> 16-bit current M1, M2       10 mA units (sign not stated; both drivers: signed)
    55/56  -> u32 P, u32 I, u32 D, u32 QPPS   read velocity PID (P first, unlike 28/29)
    57     u16 min, u16 max               main battery cut-offs, tenths of a volt
    59/60  -> u16 min, u16 max            main / logic battery cut-offs
    65     u32 accel, s32 speed, u32 decel, s32 position, u8 buffer   M1 to a position
    82     -> u16                         temperature, tenths of a degree
    90     -> status word                 16 bits in older manuals, 32 in current ones

Bugs and deviations found (the call that shows each is in CALLS / REPLIES)
--------------------------------------------------------------------------
tcr_roboclaw:

1. Any byte acknowledges a write (manual: only 0xFF): ``ForwardM1(64)`` answered by 0x00
   returns True.
2. No range checks; values are masked to the field width. ``DutyM1(32768)`` sends 0x8000,
   i.e. full reverse; ``DutyM1(-32769)`` sends 0x7FFF; ``SpeedM1(2**31)`` sends -2**31;
   ``SetEncM1(-1)`` sends 0xFFFFFFFF; byte commands send 128..255 (``ForwardM1(128)``).
   A byte value outside 0..255 raises OverflowError *after* address and command were
   written (``ForwardM1(-1)`` leaves ``80 00`` on the wire).
3. Encoder counts are decoded as signed 32-bit; the manual gives 0..4,294,967,295:
   count 0xFFFFFFFF reads as -1.
4. Reads of N longs (``ReadM1VelocityPID`` ...) decrement the retry counter before the first
   attempt: 2 attempts with the default 3 retries, none at all with ``retries=1``. Reads of
   1, 2, 4 or 4+1 bytes retry only on a timeout (a bad CRC fails at once); N-long reads
   and ``ReadVersion`` retry on a bad CRC too.
5. ``ReadVersion`` accepts 48 bytes without the LF NUL terminator.
6. A write with no acknowledgement is re-sent (3 frames in all) - harmless for motion
   commands, noted because the captured bytes then repeat.
7. PID constants are floats converted by ``int(x * 65536)`` (truncation) and read back
   divided by 65536; the wire carries raw 16.16 fixed-point u32.
8. Outside the covered set: ``ReadAutoHomingDutySpeedTimeout`` sends command 104, not 107.

pyroboclaw (`roboclaw`):

1. ``read_status()`` reads a 1-byte status; the manual's status is 2 (old) or 4 (current)
   bytes, so every real reply fails its CRC (CRCException) and the unread bytes stay in
   the input buffer; the names come from the old 16-bit table.
2. It never flushes input: any stale byte (a late ack, the bytes left by 1.) shifts every
   later reply. A missing reply, or a short one whose last two bytes happen to be a valid
   CRC, raises ``struct.error`` rather than its CRCException.
3. ``reset_quad_encoders()`` sends commands 22 and 23 with 0 (two frames) instead of 20.
4. ``drive_motor(m, speed)`` (speed + 64 into command 6/7) does not check -64..63:
   ``drive_motor(1, 64)`` sends 128; ``stop_motor``/``stop_all`` send forward 0.
5. ``read_encoder`` returns the count only (status dropped; decoded unsigned, as the manual
   says); ``read_speed`` reads command 55 first, divides by its QPPS (ZeroDivisionError
   when 0) and takes the sign from the status byte; voltages /10, currents /100, PWMs
   /327.67 come back as floats. ``read_input_pin_modes`` (not covered) names all three
   pins from the first byte.

Both compute the CRC correctly, send reads without a CRC and write identical frames for
the commands they share. Where they disagree: status width (tcr follows the manual), encoder count signedness
and strict 0xFF acknowledgement (pyroboclaw follows the manual), encoder reset (tcr uses
the manual's dedicated command 20).

Decoded values are flat tuples as the driver returns them, without tcr's leading success
flag: tcr's ``(0, ...)``/``False`` becomes the marker `Failed`; a raised exception comes
back as its type. ``spec_bytes``/``spec_values`` hold the manual's answer where the driver
differs; ``ValueError`` there means "outside the manual's range: refuse it", `Failed`
means "not a valid reply: reject it".
"""

from __future__ import annotations

import binascii
import os
from typing import Any, NamedTuple

import roboclaw.roboclaw as pyroboclaw
import tcr_roboclaw
from devices import PtyDevice

__all__ = ["CALLS", "REPLIES", "Call", "Failed", "Reply", "capture", "frame", "published_decode",
           "published_request", "reply_frame"]

ADDRESS = 0x80
_MARK = b"<end of capture>"
#: serial read timeout given to both drivers: short, so failing reads give up quickly, yet long
#: enough for the emulator's thread to answer on a busy machine (at 0.2 s a fresh machine's run
#: once read nothing of a whole reply in time: pyroboclaw's struct.error, not its CRCException)
TIMEOUT = 0.5


class Failed(Exception):
    """Marker: the driver reported failure through its return value (tcr: False or (0, ...))."""


def crc16(data: bytes) -> bytes:
    """CRC-16/XMODEM, high byte first (binascii's crc_hqx: independent of both drivers)."""
    return binascii.crc_hqx(data, 0).to_bytes(2, "big")


def frame(cmd: int, data: bytes = b"", address: int = ADDRESS) -> bytes:
    """A write command as the manual lays it out."""
    body = bytes([address, cmd]) + data
    return body + crc16(body)


def reply_frame(cmd: int, data: bytes, address: int = ADDRESS) -> bytes:
    """A read reply: data and the CRC over the request's address and command, then the data."""
    return data + crc16(bytes([address, cmd]) + data)


#: data bytes of each write command the captures use (the frame adds address, command, CRC)
WRITE_DATA = {0: 1, 1: 1, 4: 1, 5: 1, 6: 1, 7: 1, 8: 1, 9: 1, 10: 1, 11: 1, 12: 1, 13: 1, 20: 0,
              22: 4, 23: 4, 28: 16, 29: 16, 32: 2, 33: 2, 34: 4, 35: 4, 36: 4, 37: 8, 38: 8,
              39: 8, 40: 12, 57: 4, 65: 17}
_PID = bytes.fromhex("00010000 00008000 00004000 0000abe0")  # manual defaults P, I, D, QPPS 44000
#: a valid reply's data for each read command (the emulator adds the CRC)
READ_DATA = {16: bytes(5), 17: bytes(5), 18: bytes(5), 19: bytes(5),
             21: b"USB Roboclaw 2x7a v4.1.34\n\0", 24: bytes(2), 25: bytes(2), 48: bytes(4),
             49: bytes(4), 55: _PID, 56: _PID, 59: bytes(4), 60: bytes(4), 82: bytes(2), 90: bytes(4)}


class _RoboClaw(PtyDevice):
    """Answers each complete request: reads with `reply` (or a valid default), writes with 0xFF."""

    def __init__(self, reply: bytes | None) -> None:
        super().__init__()
        self._reply = reply
        self._pending = bytearray()
        self._quiet = False

    def handle(self, data: bytes) -> None:
        if self._quiet:
            return
        self._pending += data
        while len(self._pending) >= 2:
            cmd = self._pending[1]
            if cmd in READ_DATA:
                size = 2
                answer = reply_frame(cmd, READ_DATA[cmd], self._pending[0])
            elif cmd in WRITE_DATA:
                size = 4 + WRITE_DATA[cmd]
                answer = b"\xff"
            else:
                return  # unknown command: no answer, as a real device
            if len(self._pending) < size:
                return
            del self._pending[:size]
            self.send(answer if self._reply is None else self._reply)

    def written(self) -> bytes:
        """All the host wrote, even unanswered: a marker written after it arrives after it."""
        self._quiet = True
        assert self._slave is not None
        os.write(self._slave, _MARK)
        return self.wait_until(lambda: self._received.endswith(_MARK), 2.0, "the marker")[:-len(_MARK)]


_TCR = {name for name in vars(tcr_roboclaw.Roboclaw) if name[:1].isupper()}
_PYRC = {name for name in vars(pyroboclaw.RoboClaw) if not name.startswith("_")}
assert not _TCR & _PYRC


def capture(method: str, args: tuple[Any, ...], reply: bytes | None = None) -> tuple[bytes, Any]:
    """Run one driver call against the emulator; return (bytes written, result or exception type).

    `reply` replaces every answer the emulator gives (None: valid answers, b"": silence).
    """
    with _RoboClaw(reply) as dev:
        driver: Any
        if method in _TCR:
            driver = tcr_roboclaw.Roboclaw(dev.port, 115200, address=ADDRESS)
            driver.open()
            port = driver._port
        elif method in _PYRC:
            driver = pyroboclaw.RoboClaw(dev.port, ADDRESS)
            port = driver.port
        else:
            raise ValueError(f"no RoboClaw driver has a method {method!r}")
        port.timeout = TIMEOUT
        try:
            result: Any = getattr(driver, method)(*args)
        except Exception as exc:  # noqa: BLE001 - the driver's own failure is the observation
            result = type(exc)
        finally:
            port.close()
        return dev.written(), result


def published_request(method: str, *args: Any) -> bytes:
    """The bytes the driver writes for `method(*args)`, fed valid replies; re-raises its error."""
    written, result = capture(method, args, _CAPTURE_REPLY.get(method))
    if isinstance(result, type) and issubclass(result, Exception):
        raise result(f"{method}{args!r} raised; it wrote {written.hex(' ')}")
    return written


def published_decode(method: str, args: tuple[Any, ...], reply: bytes) -> tuple[Any, ...] | type[Exception]:
    """What the driver makes of `reply`: its values as a flat tuple, or an exception type."""
    result = capture(method, args, reply)[1]
    if isinstance(result, type):
        return result
    if method in _TCR:
        if result is True:
            return ()
        if result is False or not result[0]:
            return Failed
        return tuple(result[1:])
    if result is None:
        return ()
    return tuple(result) if isinstance(result, tuple) else (result,)


# pyroboclaw's read_status only completes on its own (wrong) 1-byte status reply
_CAPTURE_REPLY = {"read_status": reply_frame(90, b"\x00")}


class Call(NamedTuple):
    """One request: driver method, arguments, suggested rdisc primitive, the manual's bytes if different.

    `primitive` is rdisc's primitive, its leading arguments after a space ("forward 1": M1's
    forward), and several joined by " + " where one call of the driver writes several commands.
    """

    method: str
    args: tuple[Any, ...]
    primitive: str
    spec_bytes: bytes | type[Exception] | None = None


class Reply(NamedTuple):
    """One reply fed to a call, and the manual's decoding where the driver's differs."""

    label: str
    method: str
    args: tuple[Any, ...]
    reply: bytes
    spec_values: tuple[Any, ...] | type[Exception] | None = None


def _c(method: str, primitive: str, *arg_sets: tuple[Any, ...]) -> list[Call]:
    return [Call(method, args, primitive) for args in (arg_sets or [()])]


CALLS: list[Call] = [
    *_c("ForwardM1", "forward 1", (0,), (64,), (127,)),
    Call("ForwardM1", (128,), "forward 1", ValueError),
    Call("ForwardM1", (-1,), "forward 1"),  # OverflowError, after writing 80 00
    *_c("BackwardM1", "backward 1", (64,)),
    *_c("ForwardM2", "forward 2", (127,)),
    *_c("BackwardM2", "backward 2", (0,)),
    *_c("ForwardBackwardM1", "drive_7bit 1", (0,), (64,), (127,)),
    *_c("ForwardBackwardM2", "drive_7bit 2", (64,)),
    *_c("MixedForward", "mixed_forward", (127,)),
    *_c("MixedBackward", "mixed_backward", (32,)),
    *_c("MixedTurnRight", "mixed_turn_right", (10,)),
    *_c("MixedTurnLeft", "mixed_turn_left", (10,)),
    *_c("MixedForwardBackward", "mixed_drive_7bit", (64,)),
    *_c("MixedLeftRight", "mixed_turn_7bit", (0,)),
    *_c("DutyM1", "duty 1", (0,), (16384,), (-16384,), (32767,), (-32768,)),
    Call("DutyM1", (32768,), "duty 1", ValueError),
    Call("DutyM1", (-32769,), "duty 1", ValueError),
    *_c("DutyM2", "duty 2", (-1,)),
    *_c("DutyM1M2", "duty_both", (0, 0), (32767, -32768)),
    *_c("SpeedM1", "speed 1", (0,), (12000,), (-12000,), (2**31 - 1,), (-(2**31),)),
    Call("SpeedM1", (2**31,), "speed 1", ValueError),
    *_c("SpeedM2", "speed 2", (-1,)),
    *_c("SpeedM1M2", "speed_both", (1000, -1000)),
    *_c("SpeedAccelM1", "speed_accel 1", (12000, 12000), (2**32 - 1, -(2**31))),
    *_c("SpeedAccelM2", "speed_accel 2", (24000, -12000)),
    *_c("SpeedAccelM1M2", "speed_accel_both", (12000, 1000, -1000)),
    *_c("ResetEncoders", "reset_encoders"),
    *_c("SetEncM1", "set_encoder 1", (0,), (2**32 - 1,)),
    Call("SetEncM1", (-1,), "set_encoder 1", ValueError),
    *_c("SetEncM2", "set_encoder 2", (1000,)),
    *_c("ReadEncM1", "read_encoder 1"),
    *_c("ReadEncM2", "read_encoder 2"),
    *_c("ReadSpeedM1", "read_speed 1"),
    *_c("ReadSpeedM2", "read_speed 2"),
    *_c("ReadMainBatteryVoltage", "read_main_battery"),
    *_c("ReadLogicBatteryVoltage", "read_logic_battery"),
    *_c("ReadVersion", "read_version"),
    *_c("SetM1VelocityPID", "set_velocity_pid 1", (1.0, 0.5, 0.25, 44000), (0, 0, 0, 0),
        (1 / 3, 0, 0, 1)),
    *_c("SetM2VelocityPID", "set_velocity_pid 2", (1.0, 0.5, 0.25, 44000)),
    *_c("ReadM1VelocityPID", "read_velocity_pid 1"),
    *_c("ReadM2VelocityPID", "read_velocity_pid 2"),
    *_c("ReadPWMs", "read_pwms"),
    *_c("ReadCurrents", "read_currents"),
    *_c("SetMainVoltages", "set_main_battery_limits", (60, 340)),
    *_c("ReadMinMaxMainVoltages", "read_main_battery_limits"),
    *_c("ReadMinMaxLogicVoltages", "read_logic_battery_limits"),
    *_c("ReadTemp", "read_temperature"),
    *_c("ReadError", "read_status"),
    # pyroboclaw
    *_c("set_speed", "speed 1", (1, 0), (1, 12000)),
    *_c("set_speed", "speed 2", (2, -12000)),
    Call("set_speed", (1, 2**31), "speed 1"),  # struct.error
    *_c("drive_motor", "drive_7bit 1", (1, 0), (1, -64), (1, 63)),
    *_c("drive_motor", "drive_7bit 2", (2, 0)),
    Call("drive_motor", (1, 64), "drive_7bit 1", ValueError),
    Call("drive_motor", (1, -65), "drive_7bit 1"),  # struct.error
    *_c("stop_motor", "forward 1", (1,)),
    *_c("stop_motor", "forward 2", (2,)),
    *_c("stop_all", "forward 1 + forward 2"),
    *_c("reset_quad_encoders", "set_encoder 1 + set_encoder 2"),
    *_c("read_encoder", "read_encoder 1", (1,)),
    *_c("read_encoder", "read_encoder 2", (2,)),
    *_c("read_batt_voltage", "read_main_battery", ("main",)),
    *_c("read_batt_voltage", "read_logic_battery", ("logic",)),
    *_c("read_speed", "read_velocity_pid 1 + read_speed 1", (1,)),
    *_c("read_max_speed", "read_velocity_pid 2", (2,)),
    *_c("read_currents", "read_currents"),
    *_c("read_motor_pwms", "read_pwms"),
    *_c("read_temp_sensor", "read_temperature", (1,)),
    *_c("read_status", "read_status"),
    *_c("drive_to_position_raw", "speed_accel_decel_position 1", (1, 1000, 2000, 1000, 5000, 1)),
]


def _r(cmd: int, hex_data: str) -> bytes:
    return reply_frame(cmd, bytes.fromhex(hex_data))


def _bad_crc(good: bytes) -> bytes:
    return good[:-1] + bytes([good[-1] ^ 1])


_ENC = _r(16, "00003039 02")
_VERSION = b"USB Roboclaw 2x7a v4.1.34\n\0"
_NO_TERMINATOR = b"RoboClaw " + b"x" * 39  # 48 bytes, no LF NUL


def _replies(method: str, args: tuple[Any, ...], *cases: tuple[Any, ...]) -> list[Reply]:
    return [Reply(case[0], method, args, *case[1:]) for case in cases]


REPLIES: list[Reply] = [
    *_replies("ReadEncM1", (),
              ("zero", _r(16, "00000000 00")),
              ("typical, backwards", _ENC),
              ("count 0xFFFFFFFF, overflow", _r(16, "ffffffff 04"), (4294967295, 4)),
              ("count 0x80000000, underflow", _r(16, "80000000 01"), (2147483648, 1)),
              ("bad CRC", _bad_crc(_ENC)),
              ("CRC over the data only", bytes.fromhex("00003039 02") + crc16(bytes.fromhex("0000303902"))),
              ("reply for address 0x81", reply_frame(16, bytes.fromhex("00003039 02"), 0x81)),
              ("status byte missing", _r(16, "00003039")),
              ("no reply", b"")),
    *_replies("ReadEncM2", (), ("typical", _r(17, "0001e240 00"))),
    *_replies("ReadSpeedM1", (),
              ("zero", _r(18, "00000000 00")),
              ("forward 12000", _r(18, "00002ee0 00")),
              ("backward 12000 (signed)", _r(18, "ffffd120 01")),
              ("bad CRC", _bad_crc(_r(18, "00002ee0 00")))),
    *_replies("ReadSpeedM2", (), ("typical", _r(19, "000003e8 00"))),
    *_replies("ReadMainBatteryVoltage", (),
              ("zero", _r(24, "0000")),
              ("12.3 V", _r(24, "007b")),
              ("max", _r(24, "ffff")),
              ("bad CRC", _bad_crc(_r(24, "007b"))),
              ("one byte short", _r(24, "007b")[1:])),
    *_replies("ReadLogicBatteryVoltage", (), ("5.0 V", _r(25, "0032"))),
    *_replies("ReadVersion", (),
              ("typical", reply_frame(21, _VERSION)),
              ("empty text", reply_frame(21, b"\n\0")),
              ("bad CRC", _bad_crc(reply_frame(21, _VERSION))),
              ("48 bytes, no terminator", reply_frame(21, _NO_TERMINATOR), Failed)),
    *_replies("ReadM1VelocityPID", (),
              ("defaults", reply_frame(55, _PID)),
              ("all ones", _r(55, "ff" * 16)),
              ("bad CRC", _bad_crc(reply_frame(55, _PID)))),
    *_replies("ReadPWMs", (), ("+-max", _r(48, "7fff 8001"))),
    *_replies("ReadCurrents", (), ("1.5 A, -1 A", _r(49, "0096 ff9c"))),
    *_replies("ReadMinMaxMainVoltages", (), ("6.0 V .. 34.0 V", _r(59, "003c 0154"))),
    *_replies("ReadMinMaxLogicVoltages", (), ("6.0 V .. 34.0 V", _r(60, "003c 0154"))),
    *_replies("ReadTemp", (), ("25.3 C", _r(82, "00fd"))),
    *_replies("ReadError", (),
              ("normal", _r(90, "00000000")),
              ("position error limit warning", _r(90, "02000000"))),
    *_replies("ForwardM1", (64,),
              ("ack", b"\xff"),
              ("0x00 instead of ack", b"\x00", Failed),
              ("no ack", b"")),
    *_replies("read_encoder", (1,),
              ("typical", _ENC),
              ("count 0xFFFFFFFF", _r(16, "ffffffff 04")),
              ("bad CRC", _bad_crc(_ENC)),
              ("status byte missing", _r(16, "00003039")),
              ("no reply", b"")),
    *_replies("read_batt_voltage", ("main",), ("12.3 V", _r(24, "007b"))),
    *_replies("read_currents", (), ("1.5 A, -1 A", _r(49, "0096 ff9c"))),
    *_replies("read_status", (),
              ("manual's 4-byte status", _r(90, "00000000"), (0,)),
              ("driver's 1-byte status", _r(90, "01"), Failed)),
    *_replies("set_speed", (1, 0),
              ("ack", b"\xff"),
              ("0x00 instead of ack", b"\x00"),
              ("no ack", b"")),
]
