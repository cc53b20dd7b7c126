"""examples/nmea.rdis writes and reads NMEA 0183 GGA and RMC sentences as pynmea2 does, or as 0183 says.

Why: the description is only worth having if the sentences it writes are those pynmea2 renders and
the values it decodes are those pynmea2 parses (`published/nmea.py`), except where pynmea2 is wrong
and NMEA 0183 wins (`spec_values`; `Rejected`: rdisc must refuse). Both the rdisc runtime and the
driver `rdisc emit-python` generates are checked, each over a real pty. Reading a sentence writes
nothing and keeps what has arrived: the device side sends the sentence a moment after the read
began, as a receiver talks on its own, and sentences that came together are read one after the
other. gga() and rmc() `skip unmatched`: a sentence of the other type, noise, a bad checksum or
malformed fields are read past, and RdisTimeout comes when nothing that decodes follows. Since
reads keep unread input, each test starts by discarding whatever an earlier one left in the pty.
"""

from __future__ import annotations

import functools
import math
import os
import termios
import threading
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

pytest.importorskip("pynmea2")

from devices import PtyDevice, pty_device
from published.nmea import CALLS, REPLIES, Call, Rejected, Reply, published_decode, published_request

from rdisc.emit.python import import_driver
from rdisc.runtime import errors, load

DESCRIPTION = Path(__file__).resolve().parents[2] / "examples" / "nmea.rdis"
TIMEOUT = 0.5  # rdisc's reply timeout here (seconds): room for a busy machine
SEND_AFTER = 0.05  # the device sends a reply this long after the read began (as a receiver talks on its own)

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
# (A sentence that does not decode is read past: with nothing after it, the read times out.)
DEVIATIONS: dict[str, tuple[str, str]] = {
    "gga_without_crlf": ("RdisTimeout", ("on a serial line a sentence ends at CR LF: one without it "
                         "never ends (pynmea2 parses a str, where the end of the string ends it)")),
}
# Replies NMEA 0183 refuses (or pynmea2 fails on): gga()/rmc() read past them (`skip unmatched`) and,
# as nothing that decodes follows, raise RdisTimeout ("no matching reply") instead.
ERRORS: dict[str, str] = {
    "gga_bad_checksum": "RdisTimeout", "rmc_bad_checksum": "RdisTimeout",
    "rmc_no_checksum": "RdisTimeout", "rmc_no_checksum_strict": "RdisTimeout",
    "rmc_truncated": "RdisTimeout", "gga_truncated_checksum": "RdisTimeout",
    "no_dollar": "RdisTimeout",  # no `$` in the bytes that came: all skipped as noise
    "unknown_sentence": "RdisTimeout",  # read as a GGA: the regex does not match
    "silent": "RdisTimeout", "gga_bad_number": "RdisTimeout",  # "54A.4": the regex does not match
}
# The harness fails on these for a reason that is no protocol matter: compared with `parse` instead.
PARSED_INSTEAD = {
    "stream_raw_serial": "pynmea2 fails (TypeError: a usage bug, not a protocol matter): compared with `parse`",
}
# Read past, then followed by a valid sentence that rdisc loses with it: reading the sentence (which lacks
# the `*hh` CR LF where a frame has them) takes bytes of the next one, its `$` among them, and a read
# resumes after the bytes it took, not at the next `$` in them.


def test_every_entry_is_covered_or_listed() -> None:
    assert sorted([c.label for c in COVERED] + list(UNCOVERED)) == sorted(c.label for c in CALLS)
    assert not set(UNCOVERED) & {c.label for c in COVERED}
    assert set(DEVIATIONS) | set(ERRORS) | set(PARSED_INSTEAD) <= {r.label for r in REPLIES}


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

    def drain(self) -> None:
        """Discard the bytes the host has not read yet (what an earlier test left): reads keep them."""
        fd = os.open(self.dev.port, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        try:
            termios.tcflush(fd, termios.TCIFLUSH)  # the pty's input queue, whichever descriptor reads it
        finally:
            os.close(fd)

    def read(self, name: str, sentence: bytes) -> None:
        """Call the reading primitive `name` on an empty input while the device sends `sentence` (once).

        What the read leaves unread stays there for the next read of the same test.
        """
        self.drain()
        timer = threading.Timer(SEND_AFTER, self.dev.send, (sentence,))
        timer.start()
        try:
            self.robot.call_primitive(name)
        finally:
            timer.join()


def _driver_module(tmp: Path) -> ModuleType:
    return import_driver(DESCRIPTION, tmp)


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
    """The primitive that reads `reply` when it does not decode (by its label)."""
    return "rmc" if reply.label.startswith("rmc") else "gga"


def _error(reply: Reply) -> str | None:
    """The error rdisc raises reading `reply` alone, if it does not decode."""
    return DEVIATIONS[reply.label][0] if reply.label in DEVIATIONS else ERRORS.get(reply.label)


@functools.cache  # pynmea2's stream reads take a pty and its 0.2 s timeout: once per reply
def _sentences(reply: Reply) -> list[tuple[str, tuple[Any, ...]]]:
    """The sentences pynmea2 (or NMEA 0183) decodes from a valid `reply`: (primitive, values) each."""
    if reply.label in PARSED_INSTEAD:
        values = published_decode("parse", (), reply.reply)
    elif isinstance(reply.spec_values, tuple):
        values = reply.spec_values
    else:
        values = published_decode(reply.method, reply.args, reply.reply)
    assert isinstance(values, tuple), values
    sentences = []
    while values:  # a GGA is 18 values, an RMC 17 (with latitude and longitude)
        size = 18 if values[1] == "GGA" else 17
        sentences.append((values[1].lower(), values[:size]))
        values = values[size:]
    return sentences


def _check_state(gps: Gps, values: tuple[Any, ...]) -> None:
    wanted = expected_state(values)
    state = gps.robot.state
    got = {name: state[name] for name in wanted}
    assert got == {k: pytest.approx(v) if isinstance(v, float) else v for k, v in wanted.items()}


@pytest.mark.parametrize("reply", REPLIES, ids=[r.label for r in REPLIES])
def test_reply_values(gps: Gps, reply: Reply) -> None:
    error = _error(reply)
    if error is not None:
        if reply.label in ERRORS:  # NMEA 0183 refuses it, or pynmea2 fails too
            decoded = published_decode(reply.method, reply.args, reply.reply)
            assert reply.spec_values is Rejected or isinstance(decoded, type)
        with pytest.raises(getattr(gps.errors, error)):
            gps.read(_primitive(reply), reply.reply)
        return
    # Several sentences (stream_two_sentences: a GGA, then an RMC) are read one after the other:
    # the first read keeps what it did not take, and the next one reads it with nothing more sent.
    (first, values), *rest = _sentences(reply)
    gps.read(first, reply.reply)
    _check_state(gps, values)
    for name, values in rest:
        gps.robot.call_primitive(name)
        _check_state(gps, values)


_BY_LABEL = {r.label: r for r in REPLIES}
# Valid sentences sent after a reply. A sentence that does not decode and took the next one's start
# (no `*`, one hex digit, no CR LF) gives back all but its `$`: the reader finds the next `$` in it.
FOLLOWERS = {"gga": _BY_LABEL["gga_typical"], "rmc": _BY_LABEL["rmc_typical"]}
# Each single-sentence reply, then a valid sentence its reader does not take: a sentence of the other
# type (read by the other primitive), or of the primitive's own type after one that does not decode.
READ_PAST = [r for r in REPLIES if r.label != "stream_two_sentences"]


@pytest.mark.parametrize("reply", READ_PAST, ids=[r.label for r in READ_PAST])
def test_read_past(gps: Gps, reply: Reply) -> None:
    """`skip unmatched`: what gga()/rmc() do not decode is read past, up to the sentence they want."""
    if _error(reply) is not None:
        name = _primitive(reply)
    else:
        [(kind, _values)] = _sentences(reply)
        name = "rmc" if kind == "gga" else "gga"
    follower = FOLLOWERS[name]
    gps.read(name, reply.reply + follower.reply)
    [(_kind, values)] = _sentences(follower)
    _check_state(gps, values)
