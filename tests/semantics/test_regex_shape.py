"""Regexes that could backtrack without bound on a bad reply line are refused (E304); the
shapes real devices use are not."""

from __future__ import annotations

import pytest
from conftest import run_rdisc

from rdisc.semantics.regex_shape import risk

POLYNOMIAL = "parts of variable length in a row can match the same characters"
EXPONENTIAL = "a repeated part can split the same text between its rounds"

REFUSED = {
    r"^\s*\s*\s*\s*\s*\s*x$": POLYNOMIAL,  # from the issue: > 30 s on a 200-character line
    r"^(?:a{0,64}){0,64}b$": EXPONENTIAL,  # from the issue
    r"\d*\d*": POLYNOMIAL,
    r".*.*=.*": POLYNOMIAL,
    r"(\d+)\.?(\d*)": POLYNOMIAL,  # the optional dot is no fence
    r"a{0,64}a{0,64}a{0,64}b": POLYNOMIAL,  # bounded, but 64**3 ways
    r"(a+)+$": EXPONENTIAL,
    r"^(a+)+$": EXPONENTIAL,
    r"(\d+)*": EXPONENTIAL,
    r"(a|aa)+": EXPONENTIAL,
    r"(?:a|b|ab)+$": EXPONENTIAL,
    r"(.*a){12}": EXPONENTIAL,
    r"(\w+\s?)+$": EXPONENTIAL,
    r"(a?){20}a{20}": EXPONENTIAL,
    r"(x+x+)+y": POLYNOMIAL,  # within one round already
    r"(.)\1*\1*x": EXPONENTIAL,
}

ACCEPTED = [
    r"(.*)",
    r"^e,(-?\d+),(-?\d+)\t$",
    r"^n,(\d+),(\d+),(\d+),(\d+),(\d+),(\d+),(\d+),(\d+)\s*$",
    (r"(\w\w)GGA,([\d.]*),([\d.]*),([NS]?),([\d.]*),([EW]?),(\d?),(\d*),([\d.]*),(-?[\d.]*),M?,(-?[\d.]*),M?,"
     r"([\d.]*),(\d*)"),
    (r"(\w\w)RMC,([\d.]*),([AV]),([\d.]*),([NS]?),([\d.]*),([EW]?),([\d.]*),([\d.]*),(\d{6})?,([\d.]*),([EW]?)"
     r"(?:,([ADEMNS]?))?(?:,([SCUV]?))?"),
    r"^(0x[0-9a-f]+|\d+)?$",
    r"^(-?\d+)\s*$",
    r"(\d+,)*",  # the comma fences one round from the next
    r"(?:,(\d+))*$",
    r"(a|b)*c",
    r"(ab|a)*c",  # the next round must start with a, which b is not
    r"(\w|\d)+x",  # one character class
    r"(\d++)*",  # possessive: gives nothing back
    r"(?>a+)+b",  # atomic
    r"\s*+\s*x",
]


@pytest.mark.parametrize(("pattern", "why"), REFUSED.items(), ids=list(REFUSED))
def test_shapes_that_blow_up_are_refused(pattern: str, why: str) -> None:
    found = risk(pattern)
    assert found is not None and found.startswith(why), found


@pytest.mark.parametrize("pattern", ACCEPTED)
def test_shapes_real_devices_use_are_accepted(pattern: str) -> None:
    assert risk(pattern) is None


def test_the_checker_reports_them_at_the_regex(tmp_path) -> None:
    source = tmp_path / "slow.rdis"
    source.write_text(
        'robot r { author "tests" }\n'
        "connection c: serial { baud 9600 }\n"
        'primitive p() on c format "x" () regex r"^\\s*\\s*x$"\n'
        'primitive q() on c format "x" () regex r"^(?:a{0,64}){0,64}b$"\n',
        encoding="utf-8",
    )
    result = run_rdisc("check", source)
    assert result.returncode == 1
    assert result.stderr.count("error[E304]") == 2
    assert (
        "error[E304]: parts of variable length in a row can match the same characters, which takes polynomial "
        "time on a bad reply: put a character neither matches between them, or make the first possessive "
        "(`*+`, `++`)\n --> " in result.stderr
    )
    assert " --> " + str(source) + ":4:42\n" in result.stderr
