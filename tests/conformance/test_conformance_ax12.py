"""examples/ax12.rdis against the published driver pyax12, byte for byte, over real ptys.

Every `CALLS` entry of `published.ax12` that the description covers is made through the rdisc
runtime and through the driver `rdisc emit-python` generates, each talking to an emulated servo
on its own pty; the bytes each writes must equal what pyax12 writes (`published_request`), or the
entry's `spec_bytes`; where the driver refuses the call (ValueError) or the manual does
(`Rejected`), rdisc must refuse it (RdisValueError) and write nothing. Every `REPLIES` entry is fed
to the matching read primitive: the state it decodes must equal what pyax12 returns
(`published_decode`), or `spec_values`; where pyax12 raises on a broken status packet, rdisc must
raise RdisProtocolError or RdisTimeout, as pinned in `BROKEN`.

Deliberate differences from pyax12 (the manual's reading, not the driver's):
* Error bits do not raise: the status packet's error byte goes into the `error` state and the
  parameters, which the manual says are valid whatever ERR holds, are decoded (`ERROR_BITS`).
* `ping` of an absent servo (silence, another ID answering) raises (RdisTimeout /
  RdisProtocolError) where pyax12 returns False; a write acknowledged by nobody raises RdisTimeout
  where pyax12 returns None (the default status return level 2 answers every instruction).
"""

from __future__ import annotations

import math
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("pyax12")

from published import ax12
from published.ax12 import BROADCAST, Rejected
from pyax12 import status_packet as sp

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load

ROOT = Path(__file__).resolve().parents[2]
DESCRIPTION = ROOT / "examples" / "ax12.rdis"
TIMEOUT = 0.5  # reply timeout: the emulated servo answers at once, but a busy machine may hold its thread back

# ---- CALLS: driver method and arguments -> ("primitive" | "interface", name, arguments) -------

Target = tuple[str, str, tuple[Any, ...]]

_READS = {  # read method -> primitive (READ_DATA of one register)
    "get_present_position": "read_position", "get_present_speed": "read_speed",
    "get_present_load": "read_load", "get_present_voltage": "read_voltage",
    "get_present_temperature": "read_temperature", "is_moving": "read_moving",
    "get_goal_position": "read_goal", "get_moving_speed": "read_moving_speed",
    "get_torque_limit": "read_torque_limit", "get_cw_angle_limit": "read_cw_limit",
    "get_ccw_angle_limit": "read_ccw_limit", "get_model_number": "read_model",
    "get_firmware_version": "read_firmware", "get_baud_rate": "read_baud",
    "get_return_delay_time": "read_return_delay", "get_max_temperature": "read_max_temperature",
    "get_min_voltage": "read_min_voltage", "get_max_voltage": "read_max_voltage",
    "get_max_torque": "read_max_torque", "get_status_return_level": "read_status_level",
    "is_torque_enable": "read_torque", "is_led_enabled": "read_led",
}
_REGISTER_WRITES = {0x18: ("torque", "torque_all"), 0x19: ("led", None)}


def _p(name: str, *args: Any) -> Target:
    return ("primitive", name, args)


def _i(name: str, *args: Any) -> Target:
    return ("interface", name, args)


def target(method: str, args: tuple[Any, ...]) -> Target:
    """The rdisc call standing for `Connection.<method>(*args)`."""
    dxl_id, rest = args[0], args[1:]
    broadcast = dxl_id == BROADCAST
    if method in _READS:
        return _p(_READS[method], dxl_id)
    if method == "ping":
        return _p("ping_all") if broadcast else _p("ping", dxl_id)
    if method == "read_data":  # raw reads: the register's own primitive, or the table dump
        return {(0x24, 2): _p("read_position", dxl_id), (0x00, 50): _p("dump", dxl_id)}[rest]
    if method == "write_data":
        unicast, everyone = _REGISTER_WRITES[rest[0]]
        return _p(everyone, rest[1]) if broadcast else _p(unicast, dxl_id, rest[1])
    if method == "goto":
        position, speed, degrees = (*rest, None, False)[:3]
        if degrees:
            return _i("goto_angle", dxl_id, math.radians(position))
        if speed is not None:
            return _p("goto_speed", dxl_id, position, speed)
        return _p("goto_all", position) if broadcast else _p("goto", dxl_id, position)
    if method == "set_speed":
        return _p("set_speed", dxl_id, rest[0])
    if method == "set_id":
        return _p("set_id", dxl_id, rest[0])
    if method == "set_baud_rate":
        value, unit = (*rest, "kbps")[:2]
        if unit == "raw":
            return _p("set_baud", dxl_id, value)
        return _i("set_baud_rate", dxl_id, float(value * 1000 if unit == "kbps" else value))
    if method == "set_return_delay_time":
        value, unit = (*rest, "us")[:2]
        if unit == "raw":
            return _p("set_return_delay", dxl_id, value)
        return _i("set_return_delay_time", dxl_id, value * 1e-6)
    if method in ("set_cw_angle_limit", "set_ccw_angle_limit"):
        side = "cw" if method == "set_cw_angle_limit" else "ccw"
        value, degrees = (*rest, False)[:2]
        if degrees:
            return _i(f"{side}_limit_angle", dxl_id, math.radians(value))
        return _p(f"set_{side}_limit", dxl_id, value)
    raise KeyError(method)


# Calls the description leaves out, with the reason (none: every entry is covered).
UNCOVERED: dict[str, str] = {}
COVERED = [c for c in ax12.CALLS if c.label not in UNCOVERED]

# ---- REPLIES: the state a read leaves, in the driver's representation ------------------------

def decoder(method: str, args: tuple[Any, ...]) -> Any:
    """state -> the values pyax12's `method` returns, from the state the read primitive set."""
    degrees = len(args) > 1 and args[1]
    return {
        "ping": lambda s: (True,),
        "goto": lambda s: (),
        "get_present_position": (lambda s: (round(math.degrees(s["angle"]), 1),)) if degrees
        else (lambda s: (s["position"],)),
        "get_present_speed": lambda s: (s["speed"],),
        "get_present_load": lambda s: (s["load"],),
        "get_present_voltage": lambda s: (s["voltage"],),
        "get_present_temperature": lambda s: (s["temperature"],),
        "is_moving": lambda s: (s["moving"],),
        "get_model_number": lambda s: (s["model"],),
        "get_baud_rate": lambda s: (round(s["bus_speed"], 1),),
    }[method]


# Status packets with error bits: pyax12 raises; the manual's reading is the value and the bits.
ERROR_BITS: dict[str, tuple[type[Exception] | None, tuple[Any, ...], int]] = {
    "err_input_voltage": (sp.InputVoltageError, (40,), 0x01),
    "err_angle_limit": (sp.AngleLimitError, (), 0x02),
    "err_overheating": (sp.OverheatingError, (80,), 0x04),
    "err_range": (sp.RangeError, (), 0x08),
    "err_checksum": (sp.InstructionChecksumError, (), 0x10),
    "err_overload": (sp.OverloadError, (512,), 0x20),
    "err_instruction": (sp.InstructionError, (True,), 0x40),
    "err_reserved_bit7": (None, (40,), 0x80),  # pyax12 ignores bit 7 and returns the value
}

# Replies that are not an answer to the request: what rdisc raises (pyax12 raises or says False).
BROKEN: dict[str, type[Exception]] = {
    "ping_other_id": errors.RdisProtocolError,  # pyax12: False
    "ping_silent": errors.RdisTimeout,  # pyax12: False
    "write_silent": errors.RdisTimeout,  # pyax12: None (status return level < 2 assumed)
    "bad_checksum": errors.RdisProtocolError,
    "bad_header": errors.RdisProtocolError,  # bytes came, but no FF FF header among them
    "no_checksum": errors.RdisProtocolError,  # a short packet
    "truncated": errors.RdisProtocolError,
    "silent": errors.RdisTimeout,
    "other_id": errors.RdisProtocolError,
    "too_few_params": errors.RdisProtocolError,
    "too_many_params_2byte": errors.RdisProtocolError,
    "too_many_params_1byte": errors.RdisProtocolError,  # spec: Rejected (pyax12 returns 40)
    "length_too_big": errors.RdisProtocolError,  # LEN 5 announces a byte that never comes
}


# ---- the two implementations, each on its own emulated bus ------------------------------------

class _Bus(ax12._Ax12):
    """The harness's emulated AX-12, answering whichever ID is addressed (never broadcast)."""

    def __init__(self) -> None:
        super().__init__(1)

    def _answer(self, packet: bytes) -> bytes:
        if packet[2] == BROADCAST:
            return b""
        self.dxl_id = packet[2]
        return super()._answer(packet)


class Side:
    """One implementation (the runtime, or the generated driver with its own error classes)."""

    def __init__(self, name: str, dev: _Bus, robot: Any, value_error: type[Exception],
                 protocol_error: type[Exception], timeout: type[Exception]) -> None:
        self.name, self.dev, self.robot = name, dev, robot
        self.errors = {errors.RdisValueError: value_error, errors.RdisProtocolError: protocol_error,
                       errors.RdisTimeout: timeout}

    def call(self, kind: str, name: str, args: tuple[Any, ...]) -> None:
        getattr(self.robot, f"call_{kind}")(name, *args)


@pytest.fixture(scope="module")
def sides(tmp_path_factory: pytest.TempPathFactory) -> Iterator[list[Side]]:
    drv = import_driver(DESCRIPTION, tmp_path_factory.mktemp("ax12"))
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
            sys.modules.pop("ax12_driver", None)


def _settle(dev: _Bus, size: int) -> bytes:
    """What the device received once `size` bytes arrived (the write may still be in flight)."""
    if size:
        dev.wait_for(size, timeout=2.0)
    return dev.received


# ---- tests --------------------------------------------------------------------------------------

def test_every_call_is_covered_or_listed() -> None:
    assert sorted([c.label for c in COVERED] + list(UNCOVERED)) == sorted(c.label for c in ax12.CALLS)
    assert not set(UNCOVERED) - {c.label for c in ax12.CALLS}


def test_every_reply_is_checked() -> None:
    labels = [r.label for r in ax12.REPLIES]
    special = set(ERROR_BITS) | set(BROKEN)
    assert special <= set(labels)
    for r in ax12.REPLIES:
        decoder(r.method, r.args)  # every method has a decoder


@pytest.mark.parametrize("call", COVERED, ids=lambda c: c.label)
def test_request(call: ax12.Call, sides: list[Side]) -> None:
    try:
        expected: bytes | type[Exception] = ax12.published_request(call.method, *call.args)
    except ValueError:
        expected = Rejected  # pyax12 refuses it before writing anything: so must rdisc
    if call.spec_bytes is not None:
        expected = call.spec_bytes
    kind, name, args = target(call.method, call.args)
    for side in sides:
        side.dev.clear()
        if expected is Rejected:
            with pytest.raises(side.errors[errors.RdisValueError]):
                side.call(kind, name, args)
            assert side.dev.received == b"", side.name
        else:
            assert isinstance(expected, bytes)
            side.call(kind, name, args)
            assert _settle(side.dev, len(expected)) == expected, side.name


@pytest.mark.parametrize("reply", ax12.REPLIES, ids=lambda r: r.label)
def test_reply(reply: ax12.Reply, sides: list[Side]) -> None:
    published = ax12.published_decode(reply.method, reply.args, reply.reply)
    kind, name, args = target(reply.method, reply.args)
    assert kind == "primitive"
    for side in sides:
        side.dev.override = reply.reply
        if reply.label in BROKEN:
            assert isinstance(published, type) or published in ((False,), ()) or reply.spec_values is Rejected
            with pytest.raises(side.errors[BROKEN[reply.label]]):
                side.call(kind, name, args)
            continue
        side.call(kind, name, args)
        got = decoder(reply.method, reply.args)(side.robot.state)
        if reply.label in ERROR_BITS:
            raised, values, bits = ERROR_BITS[reply.label]
            assert published == (raised if raised is not None else values)
            assert (got, side.robot.state["error"]) == (values, bits), side.name
            continue
        expected = reply.spec_values if reply.spec_values is not None else published
        assert isinstance(expected, tuple), expected
        assert got == expected, side.name
        assert [type(v) for v in got] == [type(v) for v in expected], side.name
        assert side.robot.state["error"] == 0, side.name


def test_reset_is_the_manual_packet(sides: list[Side]) -> None:
    """RESET has no pyax12 method (bug 8 of the harness): the manual's packet for ID 1."""
    for side in sides:
        side.dev.clear()
        side.dev.override = ax12.status(1)
        side.call("primitive", "reset", (1,))
        assert _settle(side.dev, 6) == bytes.fromhex("ff ff 01 02 06 f6"), side.name
        assert side.robot.state["error"] == 0, side.name
