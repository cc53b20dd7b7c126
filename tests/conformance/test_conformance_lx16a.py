"""examples/lx16a.rdis against the published driver pylx16a, byte for byte, over real ptys.

Every `CALLS` entry of `published.lx16a` that the description covers is made through the rdisc
runtime and through the driver `rdisc emit-python` generates, each talking to an emulated servo
on its own pty; the bytes each writes must equal what pylx16a writes (`published_request`), or the
entry's `spec_bytes`; where the driver refuses the call (ServoArgumentError) or the protocol
document does (`Rejected`), rdisc must refuse it (RdisValueError) and write nothing. Every
`REPLIES` entry is fed to the matching read primitive: the state it decodes must equal what
pylx16a returns (`published_decode`), or `spec_values`; where pylx16a raises, or decodes a reply
the document says to refuse, rdisc must raise as pinned in `BROKEN`.

Angles: pylx16a takes degrees and sends round(deg * 25 / 6) steps. The SI interfaces `move_to` and
`move_by` are called with the same angles in radians (and times in seconds); the raw primitives
(offsets, limits, delayed moves) with the driver's own step conversion.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("pylx16a")

from published import lx16a
from published.lx16a import BROADCAST, Rejected
from pylx16a.lx16a import ServoArgumentError

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load

ROOT = Path(__file__).resolve().parents[2]
DESCRIPTION = ROOT / "examples" / "lx16a.rdis"
TIMEOUT = 0.5  # reply timeout: the emulated servo answers at once, but a busy machine may hold its thread back

Call = tuple[str, str, tuple[Any, ...]]  # ("primitive" | "interface", name, arguments)


def _p(name: str, *args: Any) -> Call:
    return ("primitive", name, args)


def _steps(degrees: float) -> int:
    return round(degrees * 25 / 6)  # pylx16a's conversion (Python's round: halves to even)


_READS = {
    "get_last_instant_move_hw": "read_move", "get_last_delayed_move_hw": "read_wait_move",
    "get_angle_offset": "read_offset", "get_angle_limits": "read_angle_limits",
    "get_vin_limits": "read_vin_limits", "get_temp_limit": "read_temp_limit",
    "is_motor_mode": "read_mode", "get_motor_speed": "read_mode", "is_torque_enabled": "read_torque",
    "is_led_power_on": "read_led", "get_led_error_triggers": "read_led_errors",
    "get_temp": "read_temperature", "get_vin": "read_voltage", "get_physical_angle": "read_position",
}


def targets(method: str, args: tuple[Any, ...]) -> tuple[list[Call], list[Call]]:
    """(calls made first, not compared; the calls standing for `LX16A(args[0]).<method>(*args[1:])`)."""
    sid, rest = args[0], args[1:]
    if method in _READS:
        return [], [_p(_READS[method], sid)]
    if method == "move":
        angle, time, relative, wait = (*rest, 0, False, False)[:4]
        if wait:
            return [], [_p("move_wait", sid, _steps(angle), time)]
        if relative:  # from the position read (pylx16a: from the position it read when constructed)
            return [_p("read_position", sid)], [("interface", "move_by", (sid, math.radians(angle), time / 1000))]
        return [], [("interface", "move_to", (sid, math.radians(angle), time / 1000))]
    if method == "move_stop":  # pylx16a reads the position after stopping
        return [], [_p("move_stop", sid), _p("read_position", sid)]
    if method == "set_angle_offset":
        permanent = len(rest) > 1 and rest[1]
        return [], [_p("offset_adjust", sid, _steps(rest[0]))] + ([_p("offset_write", sid)] if permanent else [])
    if method == "set_angle_limits":
        return [], [_p("set_angle_limits", sid, _steps(rest[0]), _steps(rest[1]))]
    if method in ("enable_torque", "disable_torque"):
        on = int(method == "enable_torque")
        return [], [_p("torque_all", on) if sid == BROADCAST else _p("torque", sid, on)]
    if method in ("led_power_on", "led_power_off"):
        return [], [_p("led", sid, int(method == "led_power_on"))]
    if method == "set_led_error_triggers":
        temperature, voltage, stall = rest
        return [], [_p("set_led_errors", sid, temperature + 2 * voltage + 4 * stall)]
    if method == "get_id":
        return [], [_p("discover") if sid == BROADCAST else _p("read_id", sid)]
    direct = {"move_start": "move_start", "set_id": "set_id", "set_vin_limits": "set_vin_limits",
              "set_temp_limit": "set_temp_limit", "motor_mode": "motor_mode", "servo_mode": "servo_mode"}
    return [], [_p(direct[method], sid, *rest)]


# Calls the description leaves out, with the reason (none: every entry is covered).
UNCOVERED: dict[str, str] = {}
COVERED = [c for c in lx16a.CALLS if c.label not in UNCOVERED]


def _deg(steps: int) -> float:
    return steps * 6 / 25


def decoder(method: str) -> Any:
    """state -> the values pylx16a's `method` returns (a flat tuple)."""
    return {
        "get_physical_angle": lambda s: (round(math.degrees(s["angle"]), 2),),
        "get_temp": lambda s: (s["temperature"],),
        "get_vin": lambda s: (round(s["voltage"] * 1000),),
        "get_angle_offset": lambda s: (_deg(s["offset"]),),
        "get_angle_limits": lambda s: (_deg(s["min_angle"]), _deg(s["max_angle"])),
        "get_vin_limits": lambda s: (s["min_vin"], s["max_vin"]),
        "get_temp_limit": lambda s: (s["max_temperature"],),
        "get_id": lambda s: (s["servo_id"],),
        "get_last_instant_move_hw": lambda s: (_deg(s["move_target"]), s["move_time"]),
        "get_last_delayed_move_hw": lambda s: (_deg(s["wait_target"]), s["wait_time"]),
        "is_motor_mode": lambda s: (s["motor_mode"],),
        "get_motor_speed": lambda s: (s["motor_speed"],) if s["motor_mode"] else (),
        "is_torque_enabled": lambda s: (s["torque_on"],),
        "is_led_power_on": lambda s: (s["led_on"],),
        "get_led_error_triggers": lambda s: tuple(s["led_errors"] & bit != 0 for bit in (1, 2, 4)),
    }[method]


# Replies that are no answer to the request: what rdisc raises.
BROKEN: dict[str, type[Exception]] = {
    "bad_checksum": errors.RdisProtocolError,
    "bad_header": errors.RdisProtocolError,  # spec: Rejected (pylx16a returns 30)
    "other_id": errors.RdisProtocolError,  # spec: Rejected
    "other_cmd": errors.RdisProtocolError,  # spec: Rejected
    "bad_length": errors.RdisProtocolError,  # spec: Rejected (LEN 5 announces a byte never sent)
    "short": errors.RdisProtocolError,
    "silent": errors.RdisTimeout,
    "too_long": errors.RdisProtocolError,
}


# ---- the two implementations, each on its own emulated bus ------------------------------------

class _Bus(lx16a._Lx16a):
    """The harness's emulated LX-16A, answering whichever ID is addressed."""

    def __init__(self) -> None:
        super().__init__(1)

    def _next_packet(self) -> bytes | None:
        frame = super()._next_packet()
        if frame is not None and frame[2] != BROADCAST:
            self.servo_id = frame[2]
            self.reads[14] = bytes([frame[2]])
        return frame


class Side:
    """One implementation (the runtime, or the generated driver with its own error classes)."""

    def __init__(self, name: str, dev: _Bus, robot: Any, value_error: type[Exception],
                 protocol_error: type[Exception], timeout: type[Exception]) -> None:
        self.name, self.dev, self.robot = name, dev, robot
        self.errors = {errors.RdisValueError: value_error, errors.RdisProtocolError: protocol_error,
                       errors.RdisTimeout: timeout}

    def call(self, call: Call) -> None:
        kind, name, args = call
        getattr(self.robot, f"call_{kind}")(name, *args)


@pytest.fixture(scope="module")
def sides(tmp_path_factory: pytest.TempPathFactory) -> Iterator[list[Side]]:
    drv = import_driver(DESCRIPTION, tmp_path_factory.mktemp("lx16a"))
    with _Bus() as dev_rt, _Bus() as dev_drv:
        runtime = load(DESCRIPTION).connect(dev_rt.port, timeout=TIMEOUT)
        driver = drv.connect(dev_drv.port, timeout=TIMEOUT)
        try:
            yield [
                Side("runtime", dev_rt, runtime, errors.RdisValueError, errors.RdisProtocolError,
                     errors.RdisTimeout),
                Side("driver", dev_drv, driver, drv.RdisValueError, drv.RdisProtocolError, drv.RdisTimeout),
            ]
        finally:
            runtime.close()
            driver.close()
            sys.modules.pop("lx16a_driver", None)


# ---- tests --------------------------------------------------------------------------------------

def test_every_call_is_covered_or_listed() -> None:
    assert sorted([c.label for c in COVERED] + list(UNCOVERED)) == sorted(c.label for c in lx16a.CALLS)


def test_every_reply_is_checked() -> None:
    assert set(BROKEN) <= {r.label for r in lx16a.REPLIES}
    for r in lx16a.REPLIES:
        decoder(r.method)


@pytest.mark.parametrize("call", COVERED, ids=lambda c: c.label)
def test_request(call: lx16a.Call, sides: list[Side]) -> None:
    try:
        expected: bytes | type[Exception] = lx16a.published_request(call.method, *call.args)
    except ServoArgumentError:
        expected = Rejected  # pylx16a refuses it before writing anything: so must rdisc
    if call.spec_bytes is not None:
        expected = call.spec_bytes
    before, calls = targets(call.method, call.args)
    for side in sides:
        for setup in before:
            side.call(setup)
        side.dev.clear()
        if expected is Rejected:
            assert len(calls) == 1
            with pytest.raises(side.errors[errors.RdisValueError]):
                side.call(calls[0])
            assert side.dev.received == b"", side.name
        else:
            assert isinstance(expected, bytes)
            for one in calls:
                side.call(one)
            side.dev.wait_for(len(expected), timeout=2.0)
            assert side.dev.received == expected, side.name


@pytest.mark.parametrize("reply", lx16a.REPLIES, ids=lambda r: r.label)
def test_reply(reply: lx16a.Reply, sides: list[Side]) -> None:
    published = lx16a.published_decode(reply.method, reply.args, reply.reply)
    before, calls = targets(reply.method, reply.args)
    assert not before and len(calls) == 1
    for side in sides:
        side.dev.override = reply.reply
        if reply.label in BROKEN:
            assert isinstance(published, type) or reply.spec_values is Rejected
            with pytest.raises(side.errors[BROKEN[reply.label]]):
                side.call(calls[0])
            continue
        side.call(calls[0])
        got = decoder(reply.method)(side.robot.state)
        expected = reply.spec_values if reply.spec_values is not None else published
        assert isinstance(expected, tuple), expected
        assert got == expected, side.name
        assert [type(v) for v in got] == [type(v) for v in expected], side.name
