"""The UTF-8 intervals tests/conftest.py gives Hypothesis in place of its scan of every code point
are what the scan finds: the code points UTF-8 encodes, each decoded back as written."""

from __future__ import annotations

from hypothesis.internal import charmap


def _scanned(points: list[int]) -> tuple[set[int], set[int]]:
    """What Hypothesis's scan finds at these code points: encodable, and encodable but not read back."""
    encodable, changed = set(), set()
    for point in points:
        try:
            encoded = chr(point).encode("utf-8")
        except UnicodeEncodeError:
            continue
        encodable.add(point)
        if encoded.decode("utf-8") != chr(point):
            changed.add(point)
    return encodable, changed


def test_the_known_utf8_intervals_are_the_scan_s() -> None:
    encodable, changed = charmap.intervals_from_codec("utf-8")
    assert charmap.intervals_from_codec.scan is not None  # the conftest's, not Hypothesis's own
    # every code point within 256 of an edge of the Unicode range, the surrogates and the planes, and one in 61
    edges = [0, 0xD800, 0xE000, 0x10000, 0x110000] + [plane << 16 for plane in range(17)]
    points = sorted({p for edge in edges for p in range(max(0, edge - 256), min(0x110000, edge + 256))}
                    | set(range(0, 0x110000, 61)))
    scanned_encodable, scanned_changed = _scanned(points)
    assert {p for p in points if p in encodable} == scanned_encodable
    assert {p for p in points if p in changed} == scanned_changed == set()
