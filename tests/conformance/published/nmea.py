"""NMEA 0183 GGA and RMC sentences as the published library `pynmea2` renders and parses them.

Why: rdisc descriptions of a GPS receiver must render and decode the same sentences as the library
people use, and follow NMEA 0183 where it does not. pynmea2 has no serial layer of its own:
`published_request` returns the rendered sentence's bytes, `published_decode` parses bytes, and the
"stream" methods read them from a real pty through pyserial and `pynmea2.NMEAStreamReader`, the way
pynmea2's README connects a receiver.

The protocol (NMEA 0183, versions 2.0 to 4.1)
---------------------------------------------
Serial 4800 baud 8N1 (0183-HS: 38400), ASCII, one talker broadcasting to any number of listeners:
no address of a listener, no acknowledgement, no request needed (the receiver talks once a second).

Sentence::

    $ TTSSS , field1 , ... , fieldN * HH <CR><LF>

* `$` starts a sentence (`!` for encapsulated ones); TT is the talker (GP GPS, GN multi-GNSS, GL,
  GA ...), SSS the formatter (GGA, RMC). At most 82 characters from `$` to <LF> inclusive.
* No length field: the frame is delimited by `$` and <CR><LF>; a listener synchronises on `$`.
* Fields are comma-separated, variable length; an empty field means "not available". The reserved
  characters <CR> <LF> $ * , ! \\ ^ ~ <DEL> never appear inside a field.
* Checksum: `*` then two hex digits (0-9, A-F, high nibble first) of the XOR of every character
  strictly between `$` and `*`. Mandatory in RMC (and RMA, RMB) since 0183 v2.0; talkers send it on
  every sentence.
* Time hhmmss[.ss] UTC, seconds 00-60 (60: leap second); latitude ddmm.mmmm + N/S; longitude
  dddmm.mmmm + E/W; date ddmmyy.

GGA (fix data): time, lat, N/S, lon, E/W, quality (0 no fix, 1 GPS, 2 DGPS, 3 PPS, 4 RTK fixed,
5 RTK float, 6 estimated, 7 manual, 8 simulator), satellites in use, HDOP, altitude above mean sea
level, M, geoidal separation, M, age of differential data (s), differential station ID (0000-1023).

RMC (recommended minimum): time, status (A valid / V void), lat, N/S, lon, E/W, speed over ground
(knots), course over ground (degrees true), date, magnetic variation (degrees), E/W, mode (v2.3+:
A autonomous, D differential, E estimated, M manual, S simulator, N not valid), navigational
status (v4.1: S safe, C caution, U unsafe, V not valid).

What the harness returns
------------------------
A call renders `pynmea2.<GGA|RMC>(talker, sentence, fields).render(newline=True)` as ASCII bytes.
A decoded sentence is (talker, sentence type, every field as the library types it, latitude,
longitude): times as "hh:mm:ss[.ffffff]", dates as "yyyy-mm-dd", missing typed fields None,
missing untyped ones "". "stream" returns the values of every sentence read, one after the other.

Bugs and deviations from NMEA 0183 (entries marked `spec_values` / documented)
-----------------------------------------------------------------------------
1. `parse` accepts a sentence without checksum unless `check=True`, even RMC where it is mandatory:
   "rmc_no_checksum" and a cut-off "rmc_truncated" decode (the latter with empty fields). Rejected.
2. `parse` accepts a sentence without `$` ("no_dollar": Rejected), and, leniently, leading blanks
   and a lower-case checksum ("rmc_lower_case_checksum", not marked).
3. No resynchronisation on `$`: bytes before it make `parse` fail ("garbage_before_dollar"), and
   `NMEAStreamReader` (default errors="raise") raises on the partial line a receiver sends when the
   port opens mid-sentence ("stream_mid_sentence"); spec: the following sentence decodes. With
   errors="ignore" it skips the line ("stream_mid_sentence_ignore").
4. Typed fields fall back silently to the raw string when the conversion fails: the leap second
   "235960" (valid UTC) comes back as the str "235960" ("rmc_leap_second"; spec "23:59:60"), and a
   malformed altitude "54A.4" as a str instead of an error ("gga_bad_number": Rejected).
5. Without a checksum the line end stays in the last field: "gga_no_checksum" (checksum optional
   in GGA) decodes the station ID as "\\r\\n", "rmc_no_checksum" the variation direction as "W\\r\\n",
   and "rmc_truncated" the latitude hemisphere as "N\\r\\n", so its latitude reads 0.0. (Its regex
   takes everything up to `*` as data; with a checksum the `*` stops it before <CR><LF>.)
6. Several numbers are left as strings (satellites, HDOP, geoidal separation, age, station ID,
   magnetic variation), and trailing fields a sentence lacks read "" (RMC v2.0 has no mode):
   representation only, not marked.
7. `render()` adds no <CR><LF> unless `newline=True`, and checks neither the 82-character limit
   ("gga_too_long", 86) nor reserved characters: an HDOP "0,9" silently becomes two fields
   ("gga_reserved_character"). Both marked Rejected.
8. `NMEAStreamReader(serial.Serial(...))` fails with TypeError (it joins str and the bytes
   `readline` returns, "stream_raw_serial"): it needs an `io.TextIOWrapper`, and then one non-ASCII
   noise byte raises UnicodeDecodeError whatever `errors=` says ("stream_line_noise").
9. `GGA.is_valid` counts only qualities 1-5 as valid (6 estimated, 7 manual and 8 simulator are
   not); not part of the decoded values.
"""

from __future__ import annotations

import datetime
import io
from typing import Any, NamedTuple

import pynmea2
import serial
from devices import pty_device

__all__ = ["CALLS", "REPLIES", "TIMEOUT", "Call", "Rejected", "Reply", "published_decode", "published_request"]

TIMEOUT = 0.5  # the port timeout of the "stream" reads (seconds): room for a busy machine


class Rejected(Exception):
    """Marker for `spec_values`: NMEA 0183 says this is not a valid sentence."""


class Call(NamedTuple):
    """Render `pynmea2.<method>(args[0], method, args[1:])`: args are the talker and the fields."""

    label: str
    method: str
    args: tuple[str, ...]
    primitive: str  # suggested rdisc primitive
    spec_bytes: bytes | type[Exception] | None = None  # set where pynmea2 deviates (Rejected: invalid)


class Reply(NamedTuple):
    """Bytes a receiver sends, read by `method` ("parse", "parse_strict", "stream", "stream_raw_serial")."""

    label: str
    method: str
    args: tuple[Any, ...]
    reply: bytes
    spec_values: tuple[Any, ...] | type[Exception] | None = None  # set where pynmea2 deviates


CALLS: list[Call] = [
    Call("gga_typical", "GGA", ("GP", "123519", "4807.038", "N", "01131.000", "E", "1", "08", "0.9",
                                "545.4", "M", "46.9", "M", "", ""), "gga"),
    Call("gga_south_fraction", "GGA", ("GP", "184353.07", "1929.045", "S", "02410.506", "E", "1", "04",
                                       "2.6", "100.00", "M", "-33.9", "M", "", "0000"), "gga"),
    Call("gga_no_fix", "GGA", ("GP", "", "", "", "", "", "0", "00", "99.99", "", "", "", "", "", ""), "gga"),
    Call("gga_zero", "GGA", ("GP", "000000.00", "0000.0000", "N", "00000.0000", "E", "0", "00", "0.0",
                             "0.0", "M", "0.0", "M", "", ""), "gga"),
    Call("gga_extremes", "GGA", ("GN", "235959.99", "9000.00", "S", "18000.00", "W", "8", "12", "99.9",
                                 "-9999.9", "M", "-999.9", "M", "999.9", "1023"), "gga"),  # 82 characters
    Call("gga_too_long", "GGA", ("GN", "235959.99", "9000.0000", "S", "18000.0000", "W", "8", "12", "99.9",
                                 "-9999.9", "M", "-999.9", "M", "999.9", "1023"), "gga", Rejected),  # 86
    Call("gga_reserved_character", "GGA", ("GP", "123519", "4807.038", "N", "01131.000", "E", "1", "08",
                                           "0,9", "545.4", "M", "46.9", "M", "", ""), "gga", Rejected),
    Call("rmc_typical", "RMC", ("GP", "123519", "A", "4807.038", "N", "01131.000", "E", "022.4", "084.4",
                                "230394", "003.1", "W"), "rmc"),
    Call("rmc_void", "RMC", ("GP", "", "V", "", "", "", "", "", "", "", "", "", "N"), "rmc"),
    Call("rmc_west", "RMC", ("GP", "225446", "A", "4916.45", "N", "12311.12", "W", "000.5", "054.7",
                             "191194", "020.3", "E"), "rmc"),
    Call("rmc_mode", "RMC", ("GP", "083559.00", "A", "4717.11437", "N", "00833.91522", "E", "0.004", "77.52",
                             "091202", "", "", "A"), "rmc"),
    Call("rmc_nav_status", "RMC", ("GN", "083559.00", "A", "4717.11437", "N", "00833.91522", "E", "0.004",
                                   "77.52", "091202", "", "", "A", "V"), "rmc"),
    Call("rmc_extremes", "RMC", ("GN", "235959.99", "A", "9000.0000", "N", "18000.0000", "E", "0.0", "359.9",
                                 "311299", "180.0", "E", "D"), "rmc"),
    Call("rmc_zero", "RMC", ("GP", "000000.00", "A", "0000.0000", "S", "00000.0000", "W", "000.0", "000.0",
                             "010100", "000.0", "W", "A"), "rmc"),
]

GGA = b"$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n"
RMC = b"$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A\r\n"
GGA_VALUES = ("GP", "GGA", "12:35:19", "4807.038", "N", "01131.000", "E", 1, "08", "0.9", 545.4, "M", "46.9",
              "M", "", "", 48.1173, 11 + 31 / 60)
RMC_VALUES = ("GP", "RMC", "12:35:19", "A", "4807.038", "N", "01131.000", "E", 22.4, 84.4, "1994-03-23",
              "003.1", "W", "", "", 48.1173, 11 + 31 / 60)

REPLIES: list[Reply] = [
    Reply("gga_typical", "parse", (), GGA),
    Reply("gga_without_crlf", "parse", (), GGA[:-2]),
    Reply("gga_south_fraction", "parse", (),
          b"$GPGGA,184353.07,1929.045,S,02410.506,E,1,04,2.6,100.00,M,-33.9,M,,0000*6D\r\n"),
    Reply("gga_no_fix", "parse", (), b"$GPGGA,,,,,,0,00,99.99,,,,,,*48\r\n"),
    Reply("gga_extremes", "parse", (),
          b"$GNGGA,235959.99,9000.00,S,18000.00,W,8,12,99.9,-9999.9,M,-999.9,M,999.9,1023*68\r\n"),
    Reply("rmc_typical", "parse", (), RMC),
    Reply("rmc_void", "parse", (), b"$GPRMC,,V,,,,,,,,,,N*53\r\n"),
    Reply("rmc_nav_status", "parse", (),
          b"$GNRMC,083559.00,A,4717.11437,N,00833.91522,E,0.004,77.52,091202,,,A,V*33\r\n"),
    Reply("rmc_extremes", "parse", (),
          b"$GNRMC,235959.99,A,9000.0000,N,18000.0000,E,0.0,359.9,311299,180.0,E,D*21\r\n"),
    Reply("rmc_zero", "parse", (),
          b"$GPRMC,000000.00,A,0000.0000,S,00000.0000,W,000.0,000.0,010100,000.0,W,A*28\r\n"),
    Reply("rmc_lower_case_checksum", "parse", (), RMC.replace(b"*6A", b"*6a")),
    Reply("gga_bad_checksum", "parse", (), GGA.replace(b"*47", b"*48")),
    Reply("rmc_bad_checksum", "parse", (), RMC.replace(b"022.4", b"023.4")),
    Reply("gga_no_checksum", "parse", (), GGA.replace(b"*47", b""), GGA_VALUES),
    Reply("rmc_no_checksum", "parse", (), RMC.replace(b"*6A", b""), Rejected),
    Reply("rmc_no_checksum_strict", "parse_strict", (), RMC.replace(b"*6A", b"")),
    Reply("rmc_truncated", "parse", (), b"$GPRMC,123519,A,4807.038,N\r\n", Rejected),
    Reply("gga_truncated_checksum", "parse", (), GGA.replace(b"*47", b"*4")),
    Reply("garbage_before_dollar", "parse", (), b"\x00\xfe#!" + GGA, GGA_VALUES),
    Reply("no_dollar", "parse", (), GGA[1:], Rejected),
    Reply("unknown_sentence", "parse", (), b"$GPXYZ,1,2*4F\r\n"),
    Reply("silent", "parse", (), b""),
    Reply("rmc_leap_second", "parse", (), RMC.replace(b"123519", b"235960").replace(b"*6A", b"*6C"),
          ("GP", "RMC", "23:59:60", *RMC_VALUES[3:])),
    Reply("gga_bad_number", "parse", (), GGA.replace(b"545.4", b"54A.4").replace(b"*47", b"*33"), Rejected),
    Reply("stream_two_sentences", "stream", ("raise",), GGA + RMC),
    Reply("stream_mid_sentence", "stream", ("raise",), RMC[-23:] + GGA, GGA_VALUES),
    Reply("stream_mid_sentence_ignore", "stream", ("ignore",), RMC[-23:] + GGA),
    Reply("stream_line_noise", "stream", ("ignore",), b"\xff\xfe\r\n" + GGA, GGA_VALUES),
    Reply("stream_raw_serial", "stream_raw_serial", (), GGA),
]


def published_request(method: str, *args: str) -> bytes:
    """The bytes of the sentence `pynmea2.<method>` renders from (talker, *fields), with <CR><LF>."""
    sentence = getattr(pynmea2, method)(args[0], method, args[1:])
    return str(sentence.render(newline=True)).encode("ascii")


def _plain(value: Any) -> Any:
    if isinstance(value, datetime.time):
        return value.replace(tzinfo=None).isoformat()
    if isinstance(value, datetime.date):
        return value.isoformat()
    return value


def _values(msg: Any) -> tuple[Any, ...]:
    fields = tuple(_plain(getattr(msg, field[1])) for field in msg.fields)
    return (msg.talker, msg.sentence_type, *fields, msg.latitude, msg.longitude)


def _stream(reply: bytes, errors: str, wrap: bool = True) -> tuple[Any, ...]:
    """Read `reply` as a receiver on a pty sends it, through pyserial and NMEAStreamReader."""
    with pty_device(lambda _data: None) as dev, serial.Serial(dev.port, 4800, timeout=TIMEOUT) as port:
        dev.send(reply)  # after the port opened: opening flushes the input
        text = io.TextIOWrapper(io.BufferedReader(port), encoding="ascii") if wrap else port
        try:
            reader = pynmea2.NMEAStreamReader(text, errors=errors)
            values: list[Any] = []
            for _line in range(reply.count(b"\n")):
                for msg in next(reader):
                    values.extend(_values(msg))
            return tuple(values)
        finally:
            text.close()  # closes the port too (closing it again on exit is harmless)


def published_decode(method: str, args: tuple[Any, ...], reply: bytes) -> tuple[Any, ...] | type[Exception]:
    """What pynmea2 decodes from `reply` (see the module docstring), or the exception type it raised."""
    try:
        if method == "stream":
            return _stream(reply, *args)
        if method == "stream_raw_serial":
            return _stream(reply, "raise", wrap=False)
        line = reply.decode("latin-1")  # pynmea2 parses str; latin-1 keeps every byte as one character
        return _values(pynmea2.parse(line, check=method == "parse_strict"))
    except Exception as exc:  # noqa: BLE001 - the exception type is the result
        return type(exc)
