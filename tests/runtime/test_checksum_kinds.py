"""Checksums beyond byte-wide CRCs, sums and XORs, held against published values, in the runtime
and the generated driver alike: Pololu's CRC-7 (the Motoron guide's own "Set speed" example and
its C routine), Modbus ASCII's LRC (the two's complement of the sum), RTCM 3's CRC-24Q
(pyrtcm's `calc_crc24q`) and a CRC reflected one way only (CRC-12/UMTS, the catalogue's check
value). Their JSON reads back to the same Model, and `rdisc dump` shows a CRC's parameters.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc.diagnostics import Diagnostics
from rdisc.engine import Checksum
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.conftest import run_rdisc
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json
from tests.support.pololu import crc7

DESCRIPTION = """\
robot checks { author "tests" }
state speed: int = 0
connection link: serial { baud 115200 }
/// Pololu's CRC-7: x^7 + x^3 + 1, computed least significant bit first (their "0x91").
frame pololu { payload  checksum "crc" "B" width 7 poly 0x09 reflect }
frame modbus_lrc { payload  checksum "lrc" "B" }
/// CRC-12/UMTS: its input unreflected, its output reflected.
frame umts { payload  checksum "crc" ">H" width 12 poly 0x80F reflect out }
frame gnss { header "$"  payload  checksum "CRC-24Q" hex  terminator "\\r\\n" }
primitive set_speed(motor: int in 1..3, value: int in -800..800) on link frame pololu \
pack "BBBB" (0xD1, motor, value & 0x7F, (value >> 7) & 0x7F)
primitive read_registers(unit: int in 1..247, first: int in 0..65535, count: int in 1..125) on link \
frame modbus_lrc pack ">BBHH" (unit, 3, first, count)
primitive text(line: bytes in 1..60) on link frame gnss pack "*" (line)
primitive block(data: bytes in 1..20) on link frame umts pack "*" (data)
primitive echo() on link frame pololu pack "B" (0x9A) unpack "<h" { speed = out[0] }
"""



def test_the_engine_gives_the_published_values() -> None:
    pololu = Checksum("crc", 7, 0x09, reflect_in=True, reflect_out=True)
    assert pololu(bytes.fromhex("D1016400")) == 0x68  # the Motoron guide's "Set speed" example
    assert Checksum("lrc", 8)(bytes.fromhex("010300000001")) == 0xFB  # Modbus ASCII ":010300000001FB"
    assert Checksum("fletcher8", 16)(bytes.fromhex("0608060064000100 0100")) == 0x127A  # UBX-CFG-RATE: 7A 12
    assert Checksum("crc", 7, 0x09)(b"123456789") == 0x75  # CRC-7/MMC, narrower than a byte, unreflected


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_pololu_crc7_is_the_guides(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, DESCRIPTION, tmp_path, "checks").connect(port, threads=False) as robot:
        robot.call_primitive("set_speed", 1, 100)
        assert bytes(port.written) == bytes.fromhex("D1016400 68")
        for motor, value in [(2, -800), (3, 800), (1, -1), (2, 0), (3, 255)]:
            port.written.clear()
            robot.call_primitive("set_speed", motor, value)
            body = bytes([0xD1, motor, value & 0x7F, (value >> 7) & 0x7F])
            assert bytes(port.written) == body + bytes([crc7(body)])


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_reply_with_a_crc7_is_checked(kind: str, tmp_path: Path) -> None:
    good = (-300).to_bytes(2, "little", signed=True)
    bad = (5).to_bytes(2, "little")
    port = ScriptedPort(good + bytes([crc7(good)]) + bad + bytes([crc7(bad) ^ 0x40]))
    with implementation_of(kind, DESCRIPTION, tmp_path, "checks").connect(port, threads=False) as robot:
        robot.call_primitive("echo")
        assert robot.state["speed"] == -300
        with pytest.raises(Exception, match="checksum") as caught:
            robot.call_primitive("echo")
    assert type(caught.value).__name__ == "RdisProtocolError"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_lrc_is_modbus_asciis(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, DESCRIPTION, tmp_path, "checks").connect(port, threads=False) as robot:
        robot.call_primitive("read_registers", 1, 0, 1)
        assert bytes(port.written) == bytes.fromhex("010300000001 FB")
        for unit, first, count in [(17, 0x006B, 3), (247, 65535, 125)]:
            port.written.clear()
            robot.call_primitive("read_registers", unit, first, count)
            assert sum(port.written) & 0xFF == 0  # the LRC makes the frame's sum zero


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_crc24q_is_pyrtcms(kind: str, tmp_path: Path) -> None:
    helpers = pytest.importorskip("pyrtcm.rtcmhelpers")
    lines = [b"123456789", b"\xd3\x00\x13>\xd0", bytes(range(60))]
    port = ScriptedPort()
    with implementation_of(kind, DESCRIPTION, tmp_path, "checks").connect(port, threads=False) as robot:
        for line in lines:
            port.written.clear()
            robot.call_primitive("text", line)
            assert bytes(port.written) == b"$" + line + b"%06X\r\n" % helpers.calc_crc24q(line)
    assert helpers.calc_crc24q(b"123456789") == 0xCDE703  # the catalogue's check value


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_crc_reflected_out_only_gives_the_catalogues_check_value(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, DESCRIPTION, tmp_path, "checks").connect(port, threads=False) as robot:
        robot.call_primitive("block", b"123456789")
    assert bytes(port.written) == b"123456789\x0d\xaf"  # CRC-12/UMTS: check=0xdaf


def test_dump_shows_a_crcs_parameters(tmp_path: Path) -> None:
    source = tmp_path / "checks.rdis"
    source.write_text(DESCRIPTION, encoding="utf-8")
    shown = run_rdisc("dump", source).stdout
    assert "checksum              crc width 7 poly 0x9 reflect as B, over payload" in shown
    assert "checksum              crc width 12 poly 0x80f reflect out as >H, over payload" in shown
    assert "checksum              lrc as B, over payload" in shown


def test_the_json_reads_back_to_the_same_model(tmp_path: Path) -> None:
    _, built = through_json(DESCRIPTION, tmp_path, "checks")
    checks = {frame["name"]: part for frame in json.loads(built)["frames"] for part in frame["request"]
              if "checksum" in part}
    assert checks["pololu"] == {"checksum": "crc", "kind": "crc", "width": 7, "poly": 9, "init": 0, "reflectIn": True,
                                "reflectOut": True, "xorOut": 0, "format": "B", "covers": [0, 0]}
    assert (checks["umts"]["reflectIn"], checks["umts"]["reflectOut"]) == (False, True)
    assert checks["modbus_lrc"] == {"checksum": "lrc", "kind": "lrc", "width": 8, "format": "B", "covers": [0, 0]}
    assert checks["gnss"]["checksum"] == "CRC-24Q" and checks["gnss"]["width"] == 24


def test_the_printer_writes_the_checksums_back() -> None:
    module = parse("checks.rdis", DESCRIPTION, Diagnostics())
    printed = print_module(module)
    for words in ('checksum "crc" "B" width 7 poly 9 reflect', 'checksum "lrc" "B"',
                  'checksum "crc" ">H" width 12 poly 2063 reflect out', 'checksum "CRC-24Q" hex'):  # numbers in decimal
        assert words in printed
    assert parse("checks.rdis", printed, Diagnostics()) == module
