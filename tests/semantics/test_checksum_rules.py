"""The checker's rules for checksums beyond sums, XORs and byte-wide CRCs: a CRC of 1 to 64
bits whose parameters fit its width, the Fletcher pair's fixed width and the LRC's options,
each refused with E502 at the words at fault, and E502's explanation says the same rules.
"""

from __future__ import annotations

import pytest

from rdisc.compile import compile_text
from rdisc.diagnostics.codes import CODES
from rdisc.semantics import model as m


def _check(part: str) -> tuple[list[tuple[str, str, str, str | None]], m.Model | None]:
    text = ('robot t { author "tests" }\nconnection link: serial { baud 9600 }\n'
            f"frame f {{ payload  {part} }}\n"
            'primitive p() on link frame f pack "B" (1)\n')
    compilation = compile_text("t.rdis", text)
    found = [(d.code, text[d.span.start:d.span.end], d.message, d.help) for d in compilation.diagnostics.items]
    return found, compilation.model


@pytest.mark.parametrize(("part", "width"), [
    ('checksum "crc" "B" width 7 poly 0x09 reflect', 7),
    ('checksum "CRC-24Q" ">I"', 24),
    ('checksum "crc-7/mmc" "B"', 7),
    ('checksum "crc64-xz" "<Q"', 64),
    ('checksum "crc" hex width 5 poly 0x05 init 0x1F xorout 0x1F reflect', 5),
    ('checksum "fletcher8" "<H"', 16),
    ('checksum "lrc" "B"', 8),
    ('checksum "twos-complement" ">H"', 16),
    ('checksum "crc" ">H" width 12 poly 0x80F reflect out', 12),
])
def test_widths_beside_8_16_and_32_are_accepted(part: str, width: int) -> None:
    found, model = _check(part)
    assert found == []
    assert model is not None
    check = model.frames["f"].request[-1]
    assert isinstance(check, m.FrameChecksum) and check.algorithm.width == width


@pytest.mark.parametrize(("part", "expected"), [
    ('checksum "crc" hex width 65 poly 0x1B', [
        ("E502", "65", "a CRC is 1 to 64 bits wide, not 65", None)]),
    ('checksum "crc" ">I" width 24 poly 0x1864CFB', [
        ("E502", "0x1864CFB", "`poly` 0x1864cfb does not fit a 24-bit CRC",
         "write the polynomial without its top bit, as the catalogue does: 0x864cfb")]),
    ('checksum "crc" "B" width 7 poly 0x09 init 0xFF', [
        ("E502", "0xFF", "`init` 0xff does not fit a 7-bit CRC", None)]),
    ('checksum "crc" "B" width 7 poly 0x09 xorout 0x80', [
        ("E502", "0x80", "`xorout` 0x80 does not fit a 7-bit CRC", None)]),
    ('checksum "fletcher8" "B"', [
        ("E502", '"B"', 'a 16-bit checksum does not fit "B" (8 bits)', None)]),
    ('checksum "fletcher8" "<H" width 8', [
        ("E502", "width 8", "a fletcher8 is 16 bits wide: it takes no `width`", None)]),
    ('checksum "lrc" "B" poly 7', [
        ("E502", "poly 7", "`poly` belongs to a CRC, not to a lrc", None)]),
    ('checksum "crc" ">H" width 12 poly 0x80F reflect reflect in', [
        ("E502", "reflect in", ("`reflect in` beside `reflect`: write `reflect` for both ways, `reflect in` or "
                                "`reflect out` for one"), None)]),
    ('checksum "crc24-lte-a" "B"', [
        ("E502", '"B"', 'a 24-bit checksum does not fit "B" (8 bits)', None)]),
    ('checksum "crc24-lte-a" ">3s"', [
        ("E502", '">3s"', 'a checksum is one integer: a struct format such as "B", ">H" or "<I", not ">3s"',
         'for the one integer 3 bytes hold, write ">3s{24}"')]),
])
def test_a_bad_width_or_parameter_is_e502_at_its_words(part: str, expected: list[tuple[str, str, str, str | None]],
                                                        ) -> None:
    assert _check(part)[0] == expected


@pytest.mark.parametrize(("words", "ways"), [("reflect", (True, True)), ("reflect in", (True, False)),
                                              ("reflect out", (False, True)), ("", (False, False))])
def test_reflect_names_the_ways_it_reflects(words: str, ways: tuple[bool, bool]) -> None:
    found, model = _check(f'checksum "crc" ">H" width 12 poly 0x80F {words}')
    assert found == [] and model is not None
    check = model.frames["f"].request[-1]
    assert isinstance(check, m.FrameChecksum)
    assert (check.algorithm.reflect_in, check.algorithm.reflect_out) == ways


def test_e502_explains_the_rules_the_checker_applies() -> None:
    explained = " ".join(CODES["E502"].explanation.split())
    for rule in ('"lrc" (the two\'s complement of the sum', '"fletcher8" (UBX\'s CK_A, CK_B: 16 bits, CK_A the low byte)',
                 "A sum, an XOR or an LRC is 1 to 32 bits wide, a CRC 1 to 64",
                 "a CRC's `poly`, `init` and `xorout` fit its width", '"crc24-lte-a" (RTCM 3\'s CRC-24Q)'):
        assert rule in explained
