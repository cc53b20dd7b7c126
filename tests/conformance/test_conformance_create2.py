"""examples/create2.rdis speaks the Create 2 Open Interface as pycreate2 does, or as the spec says.

Why: the description is only worth having if the bytes it writes and the sensor values it decodes
are those of the driver people use (`published/create2.py` captures them on a real pty), except
where that driver is wrong, where the OI specification wins (`spec_bytes`, `spec_values`, and
`Rejected`: rdisc must refuse the call). Both the rdisc runtime and the driver `rdisc emit-python`
generates are checked, each over a real pty.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

pytest.importorskip("pycreate2")

from devices import PtyDevice, pty_device
from published.create2 import (
    CALLS,
    FIELDS,
    REPLIES,
    TIMEOUT,
    Call,
    Rejected,
    packet100,
    published_decode,
    published_request,
)

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load

DESCRIPTION = Path(__file__).resolve().parents[2] / "examples" / "create2.rdis"
NAMES = [name for name, _path in FIELDS]

# Written after every call (LEDs 139 with a colour no entry uses): its arrival ends the call's bytes.
MARKER = ("leds", (0x0F, 0xAB, 0xCD), bytes([139, 0x0F, 0xAB, 0xCD]))

# Entries the description does not cover, and why.
UNCOVERED: dict[str, str] = {
    "destructor": "not a protocol command: the driver's clean-up sequence on garbage collection "
                  "(with the song clearing of bug 5); each of its commands is covered on its own",
}

def _digit_codes(text: str) -> tuple[int, ...]:
    """The four codes of `text` for Digit LEDs ASCII: padded with blanks and cut to four, as the driver does.

    The primitive takes an array of character codes: the OI's range (32-126) is checked by the description.
    """
    return tuple(ord(c) for c in text.ljust(4)[:4])


def rdisc_call(call: Call) -> tuple[str, tuple[Any, ...]] | None:
    """The primitive and arguments that do what `call` does (None: not covered)."""
    if call.label in UNCOVERED:
        return None
    method, args = call.method, call.args
    if method in ("start", "safe", "full", "power", "stop", "reset"):
        return method, ()
    if method == "getMode":
        return "read_oi_mode", ()
    if method in ("drive", "drive_direct", "drive_pwm"):
        return method, args
    if method == "drive_stop":
        return "drive_direct", (0, 0)
    if method == "led":
        return "leds", tuple(args) + (0,) * (3 - len(args))  # the driver's defaults are 0
    if method == "digit_led_ascii":
        return "digit_leds_ascii", (_digit_codes(args[0]),)
    if method == "createSong":
        song, notes = args
        return "song", (song, bytes(notes))
    if method == "playSong":
        return "play", args
    if method == "get_sensors":
        return "sensors", ()
    raise AssertionError(f"no mapping for {call.label}")


COVERED = [c for c in CALLS if rdisc_call(c) is not None]


def test_every_call_is_covered_or_listed() -> None:
    labels = [c.label for c in CALLS]
    assert sorted([c.label for c in COVERED] + list(UNCOVERED)) == sorted(labels)
    assert not set(UNCOVERED) & {c.label for c in COVERED}


class Robot:
    """One implementation (runtime or generated driver) connected to an answering pty device."""

    def __init__(self, robot: Any, dev: PtyDevice, errs: Any) -> None:
        self.robot, self.dev, self.errors = robot, dev, errs
        self.sensor_reply = packet100()
        self.packet_replies: dict[int, bytes] = {}  # Sensors for one packet: its reply

    def answer(self, seen: bytearray, data: bytes) -> bytes | None:
        seen += data
        if seen.endswith(b"\x8e\x64"):  # Sensors, packet 100
            seen.clear()
            return self.sensor_reply
        if seen.endswith(b"\x8e\x23"):  # Sensors, packet 35: the OI mode
            seen.clear()
            return b"\x03"
        if len(seen) >= 2 and seen[-2] == 0x8E and seen[-1] in self.packet_replies:
            packet = seen[-1]
            seen.clear()
            return self.packet_replies[packet]
        return None

    def written_by(self, name: str, args: tuple[Any, ...]) -> bytes:
        """The bytes `name(*args)` writes (the call's exception propagates, after the bytes are drained)."""
        self.dev.clear()
        try:
            self.robot.call_primitive(name, *args)
        finally:
            mark_name, mark_args, mark = MARKER
            self.robot.call_primitive(mark_name, *mark_args)
            received = self.dev.wait_until(lambda: self.dev.received.endswith(mark), 2.0, "the marker")
        return received[: -len(mark)]


def _driver_module(tmp: Path) -> ModuleType:
    return import_driver(DESCRIPTION, tmp)


@pytest.fixture(scope="module")
def driver_module(tmp_path_factory: pytest.TempPathFactory) -> ModuleType:
    return _driver_module(tmp_path_factory.mktemp("create2"))


@pytest.fixture(scope="module", params=["runtime", "driver"])
def robot(request: pytest.FixtureRequest, driver_module: ModuleType) -> Iterator[Robot]:
    seen = bytearray()
    holder: list[Robot] = []
    # No thread: the description polls the encoders 20 times a second for its odometry, and these
    # tests compare the bytes of each call alone with the published driver's.
    with pty_device(lambda data: holder[0].answer(seen, data) if holder else None) as dev:
        if request.param == "runtime":
            impl, errs = load(DESCRIPTION).connect(dev.port, timeout=TIMEOUT, threads=False), errors
        else:
            impl, errs = driver_module.connect(dev.port, timeout=TIMEOUT, threads=False), driver_module
        holder.append(Robot(impl, dev, errs))
        try:
            yield holder[0]
        finally:
            impl.close()


@pytest.mark.parametrize("call", COVERED, ids=[c.label for c in COVERED])
def test_call_bytes(robot: Robot, call: Call) -> None:
    mapped = rdisc_call(call)
    assert mapped is not None
    name, args = mapped
    wanted: bytes | None = None
    if isinstance(call.spec_bytes, bytes):
        wanted = call.spec_bytes
    elif call.spec_bytes is not Rejected:
        try:
            wanted = published_request(call.method, *call.args, setup=call.setup)
        except Exception:  # noqa: BLE001 - the driver refuses it (song_odd): rdisc must refuse it too
            wanted = None
    if wanted is None:
        with pytest.raises(robot.errors.RdisValueError):
            robot.written_by(name, args)
        assert robot.dev.received == MARKER[2]  # nothing but the marker was written
        return
    assert robot.written_by(name, args) == wanted


# Corrupt replies: the driver raises a bare Exception after its timeout; rdisc's typed errors.
REPLY_ERRORS = {"short": "RdisProtocolError", "silent": "RdisTimeout"}


@pytest.mark.parametrize("reply", REPLIES, ids=[r.label for r in REPLIES])
def test_reply_values(robot: Robot, reply: Any) -> None:
    assert reply.method == "get_sensors"
    decoded = published_decode(reply.method, reply.args, reply.reply)
    robot.sensor_reply = reply.reply
    try:
        if reply.label in REPLY_ERRORS:
            assert isinstance(decoded, type) and issubclass(decoded, Exception)
            with pytest.raises(getattr(robot.errors, REPLY_ERRORS[reply.label])):
                robot.robot.call_primitive("sensors")
            return
        assert isinstance(decoded, tuple)
        wanted = dict(zip(NAMES, decoded))
        if isinstance(reply.spec_values, dict):
            wanted.update(reply.spec_values)
        robot.robot.call_primitive("sensors")
        state = robot.robot.state
        got = {name: state[name] for name in NAMES}
        assert got == wanted
        bits = {n for n in NAMES if isinstance(wanted[n], bool)}
        assert all(isinstance(got[n], bool) for n in bits)  # bit fields decode to bools
    finally:
        robot.sensor_reply = packet100()


def test_read_oi_mode(robot: Robot) -> None:
    robot.robot.call_primitive("read_oi_mode")
    assert robot.robot.state["oi_mode"] == 3


def test_set_velocity_and_battery(robot: Robot) -> None:
    """The SI layer: a Twist becomes Drive Direct in mm/s; `sense` reports the battery in V, A, Ah."""
    robot.dev.clear()
    robot.robot.call_input("set_velocity", linear=0.2, angular=0.5)  # 200 +- 58.75 mm/s
    assert robot.dev.wait_for(5) == bytes.fromhex("91 0103 008d")
    outputs: list[dict[str, Any]] = []
    robot.robot.on_output(outputs.append)
    robot.sensor_reply = packet100(o17=b"\x3e\x80", o19=b"\xfc\x18", o22=b"\x0a\x28", o24=b"\x0b\x54")
    try:
        robot.robot.call_interface("sense")
    finally:
        robot.sensor_reply = packet100()
    contents = outputs[-1]["contents"]
    assert outputs[-1]["name"] == "battery"
    assert contents["voltage"] == 16.0 and contents["current"] == -1.0
    assert contents["charge"] == 2.6 and contents["capacity"] == 2.9
    assert contents["percentage"] == pytest.approx(2600 / 2900)


# Sensors for one packet (no pycreate2 method reads one): the OI spec's sizes and signs, chosen by the
# packet number through the description's reply table. (packet, reply, state variable, value)
SINGLE_PACKETS = [
    (19, b"\xff\x38", "distance", -200), (20, b"\x00\x5a", "angle", 90), (21, b"\x02", "charging_state", 2),
    (22, b"\x3e\x80", "voltage", 16000), (23, b"\xfe\x0c", "current", -500), (24, b"\xe2", "temperature", -30),
    (25, b"\x0a\x8c", "battery_charge", 2700), (26, b"\x0b\xb8", "battery_capacity", 3000),
]


@pytest.mark.parametrize(("packet", "reply", "name", "value"), SINGLE_PACKETS, ids=[n for _, _, n, _ in SINGLE_PACKETS])
def test_single_packet_replies_follow_the_spec(robot: Robot, packet: int, reply: bytes, name: str, value: int) -> None:
    robot.packet_replies[packet] = reply
    assert robot.written_by("sensor", (packet,)) == bytes([142, packet])
    assert robot.robot.state[name] == value


def test_a_packet_outside_the_table_is_refused(robot: Robot) -> None:
    with pytest.raises(robot.errors.RdisValueError):
        robot.written_by("sensor", (27,))
    assert robot.dev.received == MARKER[2]
