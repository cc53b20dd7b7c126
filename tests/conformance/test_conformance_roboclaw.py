"""examples/roboclaw.rdis against the published RoboClaw drivers, byte for byte.

Every CALLS entry of `published.roboclaw` is made through rdisc's runtime and through the
driver `rdisc emit-python` generates, each talking to an emulated RoboClaw on a real pty;
the bytes written must equal the published driver's (or the manual's `spec_bytes`), and
what the manual refuses (or the driver only fails on) rdisc must refuse before writing.
Every REPLIES entry is fed to the matching primitive; the decoded state must equal the
published driver's decoding (or `spec_values`); replies the manual calls invalid must
raise RdisProtocolError (something came) or RdisTimeout (nothing came).

Deliberate differences: the version string is stored without its LF (the frame's "\\n\\0"
terminator is framing, not text); pyroboclaw's volts and amps are the raw tenths of a
volt and 10 mA units scaled by the test.
"""

from __future__ import annotations

import functools
import os
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("tcr_roboclaw")
pytest.importorskip("roboclaw.roboclaw")

from devices import PtyDevice
from published.roboclaw import (
    CALLS,
    READ_DATA,
    REPLIES,
    WRITE_DATA,
    Call,
    Failed,
    frame,
    published_decode,
    published_request,
    reply_frame,
)

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load

REPO = Path(__file__).resolve().parents[2]
DESCRIPTION = REPO / "examples" / "roboclaw.rdis"
TIMEOUT = 0.3  # rdisc's reply timeout (seconds): room for a busy machine (a silent case waits it on each of 4 tries)
_MARK = b"<end of capture>"

#: CALLS the description does not cover, with the reason (none: every entry is covered)
UNCOVERED: dict[tuple[str, tuple[Any, ...]], str] = {}

#: pyroboclaw's arguments -> the primitive's (tcr's arguments map one to one)
PY_ARGS = {
    "set_speed": lambda _motor, speed: (speed,),
    "drive_motor": lambda _motor, speed: (speed + 64,),  # -64..63 -> the 7-bit command's 0..127
    "stop_motor": lambda _motor: (0,),
    "stop_all": lambda: (0,),
    "reset_quad_encoders": lambda: (0,),
    "drive_to_position_raw": lambda _motor, *rest: rest,
}

#: state holding a method's decoded values, in the driver's order (`name[i]`: an element of a
#: per-motor array, M1 first); pyroboclaw's scale factors
STATE = {
    "ReadEncM1": ("encoder[0]", "encoder_status[0]"),
    "ReadEncM2": ("encoder[1]", "encoder_status[1]"),
    "ReadSpeedM1": ("speed[0]", "speed_status[0]"),
    "ReadSpeedM2": ("speed[1]", "speed_status[1]"),
    "ReadMainBatteryVoltage": ("main_battery",),
    "ReadLogicBatteryVoltage": ("logic_battery",),
    "ReadVersion": ("version",),
    "ReadM1VelocityPID": ("pid_p[0]", "pid_i[0]", "pid_d[0]", "pid_qpps[0]"),
    "ReadPWMs": ("pwm[0]", "pwm[1]"),
    "ReadCurrents": ("current[0]", "current[1]"),
    "ReadMinMaxMainVoltages": ("main_battery_min", "main_battery_max"),
    "ReadMinMaxLogicVoltages": ("logic_battery_min", "logic_battery_max"),
    "ReadTemp": ("temperature",),
    "ReadError": ("status",),
    "ForwardM1": (),
    "read_encoder": ("encoder[0]",),
    "read_batt_voltage": ("main_battery",),
    "read_currents": ("current[0]", "current[1]"),
    "read_status": ("status",),
    "set_speed": (),
}
SCALE = {"read_batt_voltage": 10, "read_currents": 100}


def plan(call: Call) -> list[tuple[str, tuple[Any, ...]]]:
    """The primitive calls that do what `call` does."""
    args = PY_ARGS[call.method](*call.args) if call.method in PY_ARGS else call.args
    if call.method[0].islower() and call.method not in PY_ARGS:
        args = ()  # pyroboclaw reads: the motor / battery argument is in the primitive's name or its motor
    calls = []
    for part in call.primitive.split(" + "):
        name, *motor = part.split()  # "forward 1": the primitive `forward` for motor 1
        calls.append((name, (*map(int, motor), *args)))
    return calls


def _state(robot: Any, key: str) -> Any:
    """A state variable's value, or one element (`encoder[1]`) of a per-motor array."""
    name, _, index = key.partition("[")
    value = robot.state[name]
    return value[int(index.rstrip("]"))] if index else value


class Claw(PtyDevice):
    """Answers each complete request: reads with a valid reply, writes with 0xFF, or `reply`."""

    def __init__(self) -> None:
        super().__init__()
        self.reply: bytes | None = None
        self._pending = bytearray()
        self._quiet = False

    def handle(self, data: bytes) -> None:
        if self._quiet:
            return
        self._pending += data
        while len(self._pending) >= 2:
            cmd = self._pending[1]
            if cmd in READ_DATA:
                size, answer = 2, reply_frame(cmd, READ_DATA[cmd], self._pending[0])
            elif cmd in WRITE_DATA or cmd == 66:
                size, answer = 4 + WRITE_DATA.get(cmd, 17), b"\xff"
            else:
                return
            if len(self._pending) < size:
                return
            del self._pending[:size]
            self.send(answer if self.reply is None else self.reply)

    def written(self) -> bytes:
        """What the host wrote since the last call (a marker written after it arrives after it)."""
        self._quiet = True
        assert self._slave is not None
        os.write(self._slave, _MARK)
        got = self.wait_until(lambda: self._received.endswith(_MARK), 2.0, "the marker")[:-len(_MARK)]
        self.clear()
        self._pending.clear()
        self.reply = None
        self._quiet = False
        return got


@pytest.fixture(scope="module")
def driver_module(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Any]:
    module = import_driver(DESCRIPTION, tmp_path_factory.mktemp("roboclaw"))
    yield module
    sys.modules.pop(module.__name__, None)


@pytest.fixture(scope="module", params=["runtime", "driver"])
def claw(request: pytest.FixtureRequest, driver_module: Any) -> Iterator[tuple[Claw, Any, Any]]:
    """(device, connected robot, its error classes) for one implementation; open for the module."""
    with Claw() as dev:
        if request.param == "runtime":
            robot, errs = load(DESCRIPTION).connect(dev.port, timeout=TIMEOUT), errors
        else:
            robot, errs = driver_module.connect(dev.port, timeout=TIMEOUT), driver_module
        dev.written()
        try:
            yield dev, robot, errs
        finally:
            dev.written()
            robot.close()  # the terminate hook stops both motors
            assert dev.written() == frame(34, bytes(4))


def _id(call: Call) -> str:
    return f"{call.method}{call.args!r}"


def test_every_call_is_covered_or_listed() -> None:
    model = load(DESCRIPTION).model
    covered = [(c.method, c.args) for c in CALLS
               if all(name in model.primitives for name, _ in plan(c)) and (c.method, c.args) not in UNCOVERED]
    assert sorted(map(repr, covered + list(UNCOVERED))) == sorted(repr((c.method, c.args)) for c in CALLS)
    assert not set(covered) & set(UNCOVERED)


@pytest.mark.parametrize("call", [c for c in CALLS if (c.method, c.args) not in UNCOVERED], ids=_id)
def test_request(call: Call, claw: tuple[Claw, Any, Any]) -> None:
    dev, robot, errs = claw
    dev.written()  # drain what an earlier failed test may have left
    if call.spec_bytes is not None and not isinstance(call.spec_bytes, bytes):
        expected: bytes | None = None  # the manual refuses the value
    elif call.spec_bytes is not None:
        expected = call.spec_bytes
    else:
        try:
            expected = published_request(call.method, *call.args)
        except Exception:  # noqa: BLE001 - the driver fails (part-way): rdisc must refuse cleanly
            expected = None
    if expected is None:
        for name, args in plan(call):
            with pytest.raises(errs.RdisValueError):
                robot.call_primitive(name, *args)
        assert dev.written() == b""  # refused before anything was written
    else:
        for name, args in plan(call):
            robot.call_primitive(name, *args)
        assert dev.written().hex(" ") == expected.hex(" ")


@functools.cache  # once for both implementations: the driver's retries wait out its timeouts
def _published_decode(method: str, args: tuple[Any, ...], reply: bytes) -> Any:
    return published_decode(method, args, reply)


def _call_for(method: str, args: tuple[Any, ...]) -> Call:
    return next(c for c in CALLS if (c.method, c.args) == (method, args))


@pytest.mark.parametrize("reply", REPLIES, ids=lambda r: f"{r.method}-{r.label}")
def test_reply(reply: Any, claw: tuple[Claw, Any, Any]) -> None:
    dev, robot, errs = claw
    expected = reply.spec_values
    if expected is None:
        expected = _published_decode(reply.method, reply.args, reply.reply)
    (name, args), = plan(_call_for(reply.method, reply.args))
    dev.written()
    dev.reply = reply.reply
    if expected is Failed or isinstance(expected, type):
        error = errs.RdisTimeout if reply.reply == b"" else errs.RdisProtocolError
        with pytest.raises(error):
            robot.call_primitive(name, *args)
        dev.written()
        return
    robot.call_primitive(name, *args)
    dev.written()
    got = tuple(_state(robot, s) for s in STATE[reply.method])
    if reply.method == "ReadVersion":
        expected = (expected[0].removesuffix("\n"),)  # LF NUL is the frame's terminator
    if reply.method in SCALE:
        got = tuple(v / SCALE[reply.method] for v in got)
    assert got == expected


def test_m2_position_follows_the_manual(claw: tuple[Claw, Any, Any]) -> None:
    """Command 66 (no published capture): accel, speed, decel, position, buffer as for M1's 65."""
    dev, robot, _ = claw
    robot.call_primitive("speed_accel_decel_position", 2, 1000, -2000, 1000, -5000, 0)
    data = bytes.fromhex("000003e8 fffff830 000003e8 ffffec78 00")
    assert dev.written() == frame(66, data)


def test_drive_interface_takes_fractions_of_full_power(claw: tuple[Claw, Any, Any]) -> None:
    dev, robot, _ = claw
    robot.call_interface("drive", 1.0, -0.5)
    robot.call_interface("drive", 2.0, -2.0)  # clamped to full power
    assert dev.written() == frame(34, bytes.fromhex("7fff c000")) + frame(34, bytes.fromhex("7fff 8001"))
