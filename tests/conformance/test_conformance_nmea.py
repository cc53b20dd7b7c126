"""examples/nmea.rdis writes and reads NMEA 0183 GGA and RMC sentences as pynmea2 does, or as 0183 says.

Why: the description is only worth having if the sentences it writes are those pynmea2 renders and
the values it decodes are those pynmea2 parses (`published/nmea.py`), except where pynmea2 is wrong
and NMEA 0183 wins (`spec_values`; `Rejected`: rdisc must refuse). Both the rdisc runtime and the
driver `rdisc emit-python` generates are checked, each over a real pty. Reading a sentence writes
nothing: the device side sends the sentence a moment after the read began, as a receiver talks on
its own.
"""

from __future__ import annotations

import importlib.util
import math
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

pytest.importorskip("pynmea2")

from devices import PtyDevice, pty_device
from published.nmea import CALLS, REPLIES, Call, Rejected, Reply, published_decode, published_request

from rdisc.runtime import errors, load

DESCRIPTION = Path(__file__).resolve().parents[2] / "examples" / "nmea.rdis"
TIMEOUT = 0.3  # rdisc's reply timeout here (seconds)
SEND_AFTER = 0.05  # the device sends a reply this long after the read began (the read flushes first)

# Written after every call: its arrival ends the call's bytes.
MARKER_ARGS = ("ZZ", *[""] * 14)
MARKER = b"$ZZGGA,,,,,,,,,,,,,,*41\r\n"  # ZZ and GGA XOR to "A" (0x41); 14 commas cancel

# Calls the description does not cover, and why.
UNCOVERED: dict[str, str] = {
    "gga_too_long": "RDIS cannot bound a format's output: no string length, so the 82-character limit "
                    "cannot be checked (rdisc would send the 86 characters, as pynmea2 does)",
    "gga_reserved_character": "RDIS has no character checks on string arguments: a field \"0,9\" would "
                              "be sent as two fields, as pynmea2 does",
}

_SEND = {("GGA", 14): "send_gga", ("RMC", 11): "send_rmc", ("RMC", 12): "send_rmc_mode",
         ("RMC", 13): "send_rmc_status"}


def rdisc_call(call: Call) -> tuple[str, tuple[Any, ...]] | None:
    """The primitive and arguments that render what `call` renders (None: not covered)."""
    if call.label in UNCOVERED:
        return None
    return _SEND[call.method, len(call.args) - 1], call.args


COVERED = [c for c in CALLS if rdisc_call(c) is not None]

# Replies where rdisc deliberately differs from the value the harness expects: the error it raises, and why.
DEVIATIONS: dict[str, tuple[str, str]] = {
    "gga_without_crlf": ("RdisProtocolError", ("on a serial line a sentence ends at CR LF: one without it "
                         "never ends (pynmea2 parses a str, where the end of the string ends it)")),
    "gga_no_checksum": ("RdisProtocolError", ("the checksum is optional in GGA, but a frame's parts are all "
                        "mandatory: RDIS cannot describe an optional `*hh`")),
}
# Replies NMEA 0183 refuses (or pynmea2 fails on): the error rdisc raises instead.
ERRORS: dict[str, str] = {
    "gga_bad_checksum": "RdisProtocolError", "rmc_bad_checksum": "RdisProtocolError",
    "rmc_no_checksum": "RdisProtocolError", "rmc_no_checksum_strict": "RdisProtocolError",
    "rmc_truncated": "RdisProtocolError", "gga_truncated_checksum": "RdisProtocolError",
    "no_dollar": "RdisProtocolError",  # no `$` in the bytes that came: all skipped as noise
    "unknown_sentence": "RdisProtocolError",  # read as a GGA: the regex does not match
    "silent": "RdisTimeout", "gga_bad_number": "RdisProtocolError",
}
# The harness decodes these with pynmea2's stream reader; what rdisc reads is the first sentence only.
FIRST_SENTENCE_ONLY = {
    "stream_two_sentences": "a read flushes unread input first: the RMC that came with the GGA is lost",
    "stream_raw_serial": "pynmea2 fails (TypeError: a usage bug, not a protocol matter): compared with `parse`",
}


def test_every_entry_is_covered_or_listed() -> None:
    assert sorted([c.label for c in COVERED] + list(UNCOVERED)) == sorted(c.label for c in CALLS)
    assert not set(UNCOVERED) & {c.label for c in COVERED}
    assert set(DEVIATIONS) | set(ERRORS) | set(FIRST_SENTENCE_ONLY) <= {r.label for r in REPLIES}


def _seconds(value: Any) -> float:
    """pynmea2's "hh:mm:ss[.ffffff]" (None: not given) as rdisc's seconds of the day (-1: not given)."""
    if value is None:
        return -1.0
    hours, minutes, seconds = str(value).split(":")
    return int(hours) * 3600 + int(minutes) * 60 + float(seconds)


def _number(value: Any) -> float:
    return float(value) if value not in (None, "") else 0.0


def expected_state(values: tuple[Any, ...]) -> dict[str, Any]:
    """pynmea2's decoded values as the state rdisc keeps (SI units, 0 for a field not given).

    The raw latitude/longitude text and hemispheres are in `latitude`/`longitude` (signed degrees); the
    altitude units "M" are checked by the regex.
    """
    talker, kind, time, *fields, latitude, longitude = values
    state = {"talker": talker, "utc_time": _seconds(time), "latitude": latitude, "longitude": longitude}
    if kind == "GGA":
        _lat, _ns, _lon, _ew, quality, sats, hdop, alt, _m, sep, _m2, age, station = fields
        return {**state, "fix_quality": quality or 0, "satellites": int(sats or 0), "hdop": _number(hdop),
                "altitude": _number(alt), "geoid_separation": _number(sep), "dgps_age": _number(age),
                "dgps_station": int(station or 0)}
    assert kind == "RMC"
    status, _lat, _ns, _lon, _ew, sog, cog, date, var, var_ew, mode, nav = fields
    year, month, day = (int(part) for part in date.split("-")) if date else (0, 0, 0)
    return {**state, "fix_valid": status == "A", "speed": _number(sog) * 1852 / 3600,
            "course": math.radians(_number(cog)), "day": day, "month": month, "year": year,
            "magnetic_variation": math.radians(_number(var)) * (-1 if var_ew == "W" else 1),
            "mode": mode, "nav_status": nav}


class Gps:
    """One implementation (runtime or generated driver) on a pty device."""

    def __init__(self, robot: Any, dev: PtyDevice, errs: Any) -> None:
        self.robot, self.dev, self.errors = robot, dev, errs

    def written_by(self, name: str, args: tuple[Any, ...]) -> bytes:
        self.dev.clear()
        self.robot.call_primitive(name, *args)
        self.robot.call_primitive("send_gga", *MARKER_ARGS)
        received = self.dev.wait_until(lambda: self.dev.received.endswith(MARKER), 2.0, "the marker")
        return received[: -len(MARKER)]

    def read(self, name: str, sentence: bytes) -> None:
        """Call the reading primitive `name` while the device sends `sentence` (once)."""
        timer = threading.Timer(SEND_AFTER, self.dev.send, (sentence,))
        timer.start()
        try:
            self.robot.call_primitive(name)
        finally:
            timer.join()


def _driver_module(tmp: Path) -> ModuleType:
    out = tmp / "nmea_driver.py"
    subprocess.run([sys.executable, "-m", "rdisc", "emit-python", str(DESCRIPTION), "-o", str(out)],
                   check=True, capture_output=True)
    spec = importlib.util.spec_from_file_location("nmea_driver", out)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up while the class is made
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def driver_module(tmp_path_factory: pytest.TempPathFactory) -> ModuleType:
    return _driver_module(tmp_path_factory.mktemp("nmea"))


@pytest.fixture(scope="module", params=["runtime", "driver"])
def gps(request: pytest.FixtureRequest, driver_module: ModuleType) -> Iterator[Gps]:
    with pty_device(lambda _data: None) as dev:
        if request.param == "runtime":
            impl, errs = load(DESCRIPTION).connect(dev.port, timeout=TIMEOUT), errors
        else:
            impl, errs = driver_module.connect(dev.port, timeout=TIMEOUT), driver_module
        try:
            yield Gps(impl, dev, errs)
        finally:
            impl.close()


@pytest.mark.parametrize("call", COVERED, ids=[c.label for c in COVERED])
def test_sentence_bytes(gps: Gps, call: Call) -> None:
    mapped = rdisc_call(call)
    assert mapped is not None and call.spec_bytes is None  # no covered call is refused by the spec
    assert gps.written_by(*mapped) == published_request(call.method, *call.args)


def _primitive(reply: Reply) -> str:
    return "rmc" if reply.label.startswith("rmc") else "gga"


@pytest.mark.parametrize("reply", REPLIES, ids=[r.label for r in REPLIES])
def test_reply_values(gps: Gps, reply: Reply) -> None:
    if reply.label in DEVIATIONS or reply.label in ERRORS:
        error = DEVIATIONS[reply.label][0] if reply.label in DEVIATIONS else ERRORS[reply.label]
        if reply.label in ERRORS:  # NMEA 0183 refuses it, or pynmea2 fails too
            decoded = published_decode(reply.method, reply.args, reply.reply)
            assert reply.spec_values is Rejected or isinstance(decoded, type)
        with pytest.raises(getattr(gps.errors, error)):
            gps.read(_primitive(reply), reply.reply)
        return
    if reply.label == "stream_raw_serial":
        values = published_decode("parse", (), reply.reply)
    elif isinstance(reply.spec_values, tuple):
        values = reply.spec_values
    else:
        values = published_decode(reply.method, reply.args, reply.reply)
    assert isinstance(values, tuple), values
    gps.read(_primitive(reply), reply.reply)
    wanted = expected_state(values[:18] if values[1] == "GGA" else values[:17])
    state = gps.robot.state
    got = {name: state[name] for name in wanted}
    assert got == {k: pytest.approx(v) if isinstance(v, float) else v for k, v in wanted.items()}
