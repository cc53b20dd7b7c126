"""The engine's table-driven CRC against the bit-by-bit Rocksoft model (tests/properties/
descriptions.py's `crc`) for every width from 1 to 64, reflected either way or both, and the
LRC and Fletcher pair against their definitions, on arbitrary bytes. The generated driver
carries the same module (tests/engine/test_carried.py), so this holds for it too.
"""

from __future__ import annotations

from conftest import fuzz_examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.engine import Checksum
from rdisc.semantics.checksums import CATALOGUE
from tests.properties.descriptions import Checksum as Reference
from tests.properties.descriptions import crc
from tests.runtime.test_framing import CHECK_VALUES


@st.composite
def parameters(draw: st.DrawFn) -> tuple[int, int, int, bool, bool, int]:
    width = draw(st.integers(1, 64))
    full = (1 << width) - 1
    return (width, draw(st.integers(0, full)), draw(st.integers(0, full)), draw(st.booleans()),
            draw(st.booleans()), draw(st.integers(0, full)))


@settings(max_examples=fuzz_examples(120), deadline=None, derandomize=True, database=None)
@given(parameters(), st.binary(max_size=40))
def test_a_table_driven_crc_is_the_bitwise_one(given: tuple[int, int, int, bool, bool, int], data: bytes) -> None:
    width, poly, init, reflect_in, reflect_out, xorout = given
    engine = Checksum("crc", width, poly, init, reflect_in, reflect_out, xorout)
    assert engine(data) == crc(data, width, poly, init, reflect_in, xorout, reflect_out)


@settings(max_examples=100, deadline=None, derandomize=True, database=None)
@given(st.sampled_from(["lrc", "fletcher8", "sum", "xor"]), st.integers(1, 32), st.binary(max_size=300))
def test_sums_are_their_definitions(kind: str, width: int, data: bytes) -> None:
    width = 16 if kind == "fletcher8" else width
    expected = Reference(kind, kind, width, (), (), 0, 0, False).compute(data)
    assert Checksum(kind, width)(data) == expected
    if kind == "lrc":
        assert (sum(data) + expected) % (1 << width) == 0


def test_the_bitwise_model_gives_the_catalogues_check_values() -> None:
    """The reference itself is right: the catalogue's check value of "123456789", every entry."""
    assert {name: crc(b"123456789", *CATALOGUE[name]) for name in CATALOGUE} == CHECK_VALUES
