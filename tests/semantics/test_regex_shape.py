"""Regexes that could backtrack without bound on a bad reply line are refused (E304); the
shapes real devices use are not."""

from __future__ import annotations

import pytest
from conftest import run_rdisc
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rdisc import regex_shape
from rdisc.regex_shape import risk

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


# Parts a pattern is drawn from: one character each (the walk's shortcut for a repeat of one), and
# groups, alternations and repeats of them.
_ATOMS = st.sampled_from(["a", "b", "x", ".", r"\d", r"\s", r"\w", "[ab]", "[^a]", "[0-9a-f]", r"\.", ","])
_QUANTIFIERS = st.sampled_from(["", "?", "*", "+", "{2}", "{0,3}", "{1,64}", "*+", "++", "*?"])


def _patterns(depth: int) -> st.SearchStrategy[str]:
    if depth == 0:
        part = _ATOMS
    else:
        inner = st.lists(_patterns(depth - 1), min_size=1, max_size=3)
        part = st.one_of(_ATOMS, inner.map(lambda parts: f"({''.join(parts)})"),
                         inner.map(lambda parts: f"(?:{'|'.join(parts)})"))
    return st.tuples(part, _QUANTIFIERS).map("".join)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(_patterns(2), min_size=1, max_size=5).map("".join))
def test_a_repeat_of_one_character_is_judged_as_the_whole_walk_judges_it(pattern: str) -> None:
    """The walk takes a repeat of one character (`\\d+`, `[ab]*`) without walking its rounds, which
    cannot vary; it finds what the whole walk finds on any pattern, refusal and reason alike."""
    shortcut = risk(pattern)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(regex_shape, "_ONE_CHARACTER", ())
        whole = risk(pattern)
    assert shortcut == whole, pattern


def test_the_shortcut_is_taken() -> None:
    """The differential test above compares two ways: `\\d+`'s rounds are walked only without the shortcut."""
    walked: list[object] = []
    original = regex_shape._Walk.sequence

    def counted(self: regex_shape._Walk, items: list[object], *rest: object) -> object:
        walked.append(items)
        return original(self, items, *rest)  # type: ignore[arg-type]

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(regex_shape._Walk, "sequence", counted)
        assert risk(r"^(-?\d+)\s*$") is None
        short = len(walked)
        patch.setattr(regex_shape, "_ONE_CHARACTER", ())
        walked.clear()
        assert risk(r"^(-?\d+)\s*$") is None
    assert (short, len(walked)) == (2, 7)
