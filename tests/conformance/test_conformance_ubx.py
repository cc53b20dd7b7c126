"""A u-blox UBX message as rdisc frames and reads it is the one pyubx2 (1.4.0) serializes.

Why: UBX closes every message with the 8-bit Fletcher pair CK_A, CK_B over class, id, length
and payload (`checksum "fletcher8" "<H"`). pyubx2 is the published reading of the u-blox
interface description; the first request is also the manual's own UBX-CFG-RATE example.
Both the runtime and the generated driver are checked.
"""

from __future__ import annotations

from pathlib import Path

import pytest

pyubx2 = pytest.importorskip("pyubx2")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

DESCRIPTION = """\
robot ubx { author "tests" }
state measure: int = 0
state navigation: int = 0
state reference: int = 0
connection uart: serial { baud 9600 }
frame ubx(group: int, message: int) {
    header "\\xB5\\x62"  field group "B" = group  field message "B" = message  length "<H" = payload
    payload  checksum "fletcher8" "<H"
}
primitive set_rate(measure: int in 25..65535, navigation: int in 1..127, reference: int in 0..5) on uart \
frame ubx(0x06, 0x08) pack "<HHH" (measure, navigation, reference)
primitive poll_rate() on uart frame ubx(0x06, 0x08) pack "" () unpack "<HHH" {
    measure = out[0]
    navigation = out[1]
    reference = out[2]
}
"""
RATES = [(100, 1, 1), (1000, 1, 0), (25, 127, 5), (65535, 3, 2), (200, 16, 4)]


def _rate(measure: int, navigation: int, reference: int) -> bytes:
    return bytes(pyubx2.UBXMessage("CFG", "CFG-RATE", pyubx2.SET, measRate=measure, navRate=navigation,
                                   timeRef=reference).serialize())


def test_the_manuals_cfg_rate_is_pyubx2s() -> None:
    assert _rate(100, 1, 1) == bytes.fromhex("B562 0608 0600 6400 0100 0100 7A12")


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_requests_are_framed_as_pyubx2_serializes_them(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, DESCRIPTION, tmp_path, "ubx").connect(port, threads=False) as robot:
        for rate in RATES:
            port.written.clear()
            robot.call_primitive("set_rate", *rate)
            assert bytes(port.written) == _rate(*rate), rate


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_replies_pyubx2_serializes_are_read(kind: str, tmp_path: Path) -> None:
    poll = bytes(pyubx2.UBXMessage("CFG", "CFG-RATE", pyubx2.POLL).serialize())
    port = ScriptedPort(b"".join(_rate(*rate) for rate in RATES))
    with implementation_of(kind, DESCRIPTION, tmp_path, "ubx").connect(port, threads=False) as robot:
        for rate in RATES:
            port.written.clear()
            robot.call_primitive("poll_rate")
            assert bytes(port.written) == poll
            assert (robot.state["measure"], robot.state["navigation"], robot.state["reference"]) == rate


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_wrong_fletcher_pair_is_refused(kind: str, tmp_path: Path) -> None:
    reply = bytearray(_rate(100, 1, 1))
    reply[-1] ^= 0x01  # CK_B
    port = ScriptedPort(bytes(reply))
    with (implementation_of(kind, DESCRIPTION, tmp_path, "ubx").connect(port, threads=False) as robot,
          pytest.raises(Exception, match="checksum") as caught):
        robot.call_primitive("poll_rate")
    assert type(caught.value).__name__ == "RdisProtocolError"
