"""The pynmea2 harness renders and parses real sentences: each entry pinned to NMEA 0183 by hand.

Why: the rdisc NMEA description will be checked against `published/nmea.py`; these literal sentences
and values (checksums XOR-ed by hand, several from receiver manuals) prove the harness reports what
pynmea2 does and that every deviation from NMEA 0183 is marked.
"""

from __future__ import annotations

from functools import reduce
from typing import Any

import pytest

pynmea2 = pytest.importorskip("pynmea2")

from published.nmea import CALLS, REPLIES, Rejected, published_decode, published_request

SAME = "same as the spec"


def xor_checksum(body: str) -> str:
    """NMEA 0183: XOR of every character between `$` and `*`, two upper-case hex digits."""
    return f"{reduce(lambda acc, ch: acc ^ ord(ch), body, 0):02X}"


# label: (the sentence NMEA 0183 gives, or Rejected; what pynmea2 renders: SAME or another sentence)
EXPECTED_CALLS: dict[str, tuple[str | type[Exception], str]] = {
    "gga_typical": ("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n", SAME),
    "gga_south_fraction": ("$GPGGA,184353.07,1929.045,S,02410.506,E,1,04,2.6,100.00,M,-33.9,M,,0000*6D\r\n",
                           SAME),
    "gga_no_fix": ("$GPGGA,,,,,,0,00,99.99,,,,,,*48\r\n", SAME),
    "gga_zero": ("$GPGGA,000000.00,0000.0000,N,00000.0000,E,0,00,0.0,0.0,M,0.0,M,,*5D\r\n", SAME),
    "gga_extremes": ("$GNGGA,235959.99,9000.00,S,18000.00,W,8,12,99.9,-9999.9,M,-999.9,M,999.9,1023*68\r\n",
                     SAME),
    "gga_too_long": (Rejected,
                     "$GNGGA,235959.99,9000.0000,S,18000.0000,W,8,12,99.9,-9999.9,M,-999.9,M,999.9,1023*68\r\n"),
    "gga_reserved_character": (Rejected, "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0,9,545.4,M,46.9,M,,*45\r\n"),
    "rmc_typical": ("$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A\r\n", SAME),
    "rmc_void": ("$GPRMC,,V,,,,,,,,,,N*53\r\n", SAME),
    "rmc_west": ("$GPRMC,225446,A,4916.45,N,12311.12,W,000.5,054.7,191194,020.3,E*68\r\n", SAME),
    "rmc_mode": ("$GPRMC,083559.00,A,4717.11437,N,00833.91522,E,0.004,77.52,091202,,,A*57\r\n", SAME),
    "rmc_nav_status": ("$GNRMC,083559.00,A,4717.11437,N,00833.91522,E,0.004,77.52,091202,,,A,V*33\r\n", SAME),
    "rmc_extremes": ("$GNRMC,235959.99,A,9000.0000,N,18000.0000,E,0.0,359.9,311299,180.0,E,D*21\r\n", SAME),
    "rmc_zero": ("$GPRMC,000000.00,A,0000.0000,S,00000.0000,W,000.0,000.0,010100,000.0,W,A*28\r\n", SAME),
}


def test_every_call_has_an_expectation() -> None:
    assert [c.label for c in CALLS] == list(EXPECTED_CALLS)


@pytest.mark.parametrize("call", CALLS, ids=[c.label for c in CALLS])
def test_call_sentence(call: Any) -> None:
    spec, driver = EXPECTED_CALLS[call.label]
    rendered = spec if driver == SAME else driver
    assert isinstance(rendered, str)
    assert published_request(call.method, *call.args) == rendered.encode("ascii")
    body, checksum = rendered[1:-2].split("*")
    assert checksum == xor_checksum(body)
    if spec is Rejected:
        assert call.spec_bytes is Rejected
    else:
        assert call.spec_bytes is None
        assert len(rendered) <= 82


LAT_48 = 48 + 7.038 / 60
LON_11 = 11 + 31 / 60
GGA = ("GP", "GGA", "12:35:19", "4807.038", "N", "01131.000", "E", 1, "08", "0.9", 545.4, "M", "46.9", "M", "", "",
       LAT_48, LON_11)
RMC = ("GP", "RMC", "12:35:19", "A", "4807.038", "N", "01131.000", "E", 22.4, 84.4, "1994-03-23", "003.1", "W", "",
       "", LAT_48, LON_11)

Expected = tuple[Any, ...] | type[Exception]
# label: (what NMEA 0183 says the bytes decode to, or Rejected; what pynmea2 gives: SAME or other)
EXPECTED_REPLIES: dict[str, tuple[Expected, Expected | str]] = {
    "gga_typical": (GGA, SAME),
    "gga_without_crlf": (GGA, SAME),
    "gga_south_fraction": (("GP", "GGA", "18:43:53.070000", "1929.045", "S", "02410.506", "E", 1, "04", "2.6",
                            100.0, "M", "-33.9", "M", "", "0000", -(19 + 29.045 / 60), 24 + 10.506 / 60), SAME),
    "gga_no_fix": (("GP", "GGA", None, "", "", "", "", 0, "00", "99.99", None, "", "", "", "", "", 0.0, 0.0), SAME),
    "gga_extremes": (("GN", "GGA", "23:59:59.990000", "9000.00", "S", "18000.00", "W", 8, "12", "99.9", -9999.9,
                      "M", "-999.9", "M", "999.9", "1023", -90.0, -180.0), SAME),
    "rmc_typical": (RMC, SAME),
    "rmc_void": (("GP", "RMC", None, "V", "", "", "", "", None, None, None, "", "", "N", "", 0.0, 0.0), SAME),
    "rmc_nav_status": (("GN", "RMC", "08:35:59", "A", "4717.11437", "N", "00833.91522", "E", 0.004, 77.52,
                        "2002-12-09", "", "", "A", "V", 47 + 17.11437 / 60, 8 + 33.91522 / 60), SAME),
    "rmc_extremes": (("GN", "RMC", "23:59:59.990000", "A", "9000.0000", "N", "18000.0000", "E", 0.0, 359.9,
                      "1999-12-31", "180.0", "E", "D", "", 90.0, 180.0), SAME),
    "rmc_zero": (("GP", "RMC", "00:00:00", "A", "0000.0000", "S", "00000.0000", "W", 0.0, 0.0, "2000-01-01",
                  "000.0", "W", "A", "", 0.0, 0.0), SAME),
    "rmc_lower_case_checksum": (RMC, SAME),
    "gga_bad_checksum": (pynmea2.ChecksumError, SAME),
    "rmc_bad_checksum": (pynmea2.ChecksumError, SAME),
    "gga_no_checksum": (GGA, GGA[:15] + ("\r\n",) + GGA[16:]),
    "rmc_no_checksum": (Rejected, RMC[:12] + ("W\r\n",) + RMC[13:]),
    "rmc_no_checksum_strict": (pynmea2.ChecksumError, SAME),
    "rmc_truncated": (Rejected, ("GP", "RMC", "12:35:19", "A", "4807.038", "N\r\n", "", "", None, None, None, "",
                                 "", "", "", 0.0, 0.0)),
    "gga_truncated_checksum": (pynmea2.ParseError, SAME),
    "garbage_before_dollar": (GGA, pynmea2.ParseError),
    "no_dollar": (Rejected, GGA),
    "unknown_sentence": (pynmea2.SentenceTypeError, SAME),
    "silent": (pynmea2.ParseError, SAME),
    "rmc_leap_second": (("GP", "RMC", "23:59:60", *RMC[3:]), ("GP", "RMC", "235960", *RMC[3:])),
    "gga_bad_number": (Rejected, GGA[:10] + ("54A.4",) + GGA[11:]),
    "stream_two_sentences": (GGA + RMC, SAME),
    "stream_mid_sentence": (GGA, pynmea2.ParseError),
    "stream_mid_sentence_ignore": (GGA, SAME),
    "stream_line_noise": (GGA, UnicodeDecodeError),
    "stream_raw_serial": (TypeError, SAME),  # a usage bug of the library, not a protocol matter
}


def matches(actual: Any, expected: Any) -> bool:
    """Equal, exception types by identity, floats to rounding."""
    if isinstance(expected, type) or isinstance(actual, type):
        return actual is expected
    return len(actual) == len(expected) and all(
        a == pytest.approx(e) if isinstance(e, float) else (a == e and type(a) is type(e))
        for a, e in zip(actual, expected)
    )


def test_every_reply_has_an_expectation() -> None:
    assert [r.label for r in REPLIES] == list(EXPECTED_REPLIES)


@pytest.mark.parametrize("reply", REPLIES, ids=[r.label for r in REPLIES])
def test_reply_values(reply: Any) -> None:
    spec, driver = EXPECTED_REPLIES[reply.label]
    decoded = published_decode(reply.method, reply.args, reply.reply)
    assert matches(decoded, spec if driver == SAME else driver), decoded
    if driver == SAME:
        assert reply.spec_values is None
    else:
        assert matches(reply.spec_values, spec)


def test_checksums_of_replies_are_right() -> None:
    wrong = {"gga_bad_checksum", "rmc_bad_checksum"}
    for reply in REPLIES:
        for line in reply.reply.decode("latin-1").split("\n"):
            start, star = line.find("$"), line.find("*")
            checksum = line[star + 1:].strip()
            if start >= 0 and star > start and len(checksum) == 2:
                assert (checksum.upper() == xor_checksum(line[start + 1:star])) == (reply.label not in wrong)
