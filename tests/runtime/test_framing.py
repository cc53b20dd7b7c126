"""The framing module on its own: the checksum catalogue against its published
check values, and frames written and read back, garbage and faults included."""

from __future__ import annotations

import pytest

from rdisc.engine import (
    Bytes,
    Check,
    Checksum,
    Field,
    Frame,
    FrameError,
    Incoming,
    Length,
    Payload,
    Stuffing,
)
from rdisc.lowering.constructs import checksum
from rdisc.semantics import model as m
from rdisc.semantics.checksums import CATALOGUE
from tests.support.ports import ScriptedPort

# The check value of each catalogue CRC: its result over b"123456789" (CRC RevEng catalogue).
CHECK_VALUES = {
    "crc8": 0xF4, "crc8-maxim": 0xA1, "crc8-dvb-s2": 0xBC, "crc16-xmodem": 0x31C3, "crc16-ccitt-false": 0x29B1,
    "crc16-kermit": 0x2189, "crc16-modbus": 0x4B37, "crc16-arc": 0xBB3D, "crc16-x25": 0x906E,
    "crc32": 0xCBF43926, "crc32c": 0xE3069283, "crc8-rohc": 0xD0, "crc8-cdma2000": 0xDA, "crc8-wcdma": 0x25,
    "crc16-buypass": 0xFEE8, "crc16-dnp": 0xEA82, "crc16-maxim": 0x44C2, "crc16-usb": 0xB4C8,
    "crc16-genibus": 0xD64E, "crc32-bzip2": 0xFC891918, "crc32-mpeg-2": 0x0376E6E7, "crc32-posix": 0x765E7680,
    "crc32-jamcrc": 0x340BC6D9, "crc16-mcrf4xx": 0x6F91, "crc3-gsm": 0x4, "crc4-g-704": 0x7, "crc5-usb": 0x19, "crc7-mmc": 0x75,
    "crc7-rohc": 0x53, "crc7-umts": 0x61, "crc10-atm": 0x199, "crc12-dect": 0xF5B, "crc15-can": 0x059E,
    "crc24-lte-a": 0xCDE703, "crc24-openpgp": 0x21CF02, "crc24-ble": 0xC25A56, "crc64-ecma-182": 0x6C40DF5F0B497347,
    "crc64-xz": 0x995DC9BBDF1939FA,
}


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_catalogue_crcs_give_their_check_values(name: str) -> None:
    width, poly, init, reflect, xorout = CATALOGUE[name]
    crc = checksum(m.ChecksumAlgorithm("crc", width, poly, init, reflect, reflect, xorout))
    assert crc(b"123456789") == CHECK_VALUES[name]


def test_sums_and_xor() -> None:
    assert Checksum("sum", 8, inverted=True)(bytes([1, 4, 2, 0x1E, 0, 2])) == 0xD8  # a Dynamixel write
    assert Checksum("sum", 8, mask=0x7F)(bytes([0x80, 0x00, 0x7F])) == 0x7F
    assert Checksum("xor", 8)(b"GPGLL,4916.45,N,12311.12,W,225444,A,") == 0x1D  # NMEA's textbook sentence


DXL = Frame("dxl", [Bytes("header", b"\xff\xff"), Field("id", "", "B", 0), Length("", "B", 1, 0xFF), Payload(),
                    Check(Checksum("sum", 8, inverted=True), "B", 1, 3)],
            [Bytes("header", b"\xff\xff"), Field("id", "", "B", 0), Length("", "B", 1, 0xFF), Payload(),
             Check(Checksum("sum", 8, inverted=True), "B", 1, 3)])




def test_dynamixel_request_is_the_manuals() -> None:
    # Write goal position 512 to servo 1: FF FF 01 05 03 1E 00 02 D6 (AX-12 manual's example form).
    assert DXL.wrap(bytes([3, 0x1E, 0x00, 0x02]), [1]) == bytes.fromhex("ffff0105031e0002d6")


def test_reply_after_garbage_is_found() -> None:
    body = bytes([1, 3, 0, 0x20])
    reply = bytes.fromhex("00ff12") + b"\xff\xff" + body + bytes([~sum(body) & 0xFF])
    raw, payload = DXL.read(ScriptedPort(reply), [1], b"", -1)
    assert payload == bytes([0, 0x20])
    assert raw == reply[3:]


@pytest.mark.parametrize(("reply", "message"), [
    (b"\xff\xff\x01\x02\x00\x00", "checksum"),
    (b"\xff\xff\x02\x02\x00\xfb", "reply id is 2, expected 1"),
    (b"\xff\xff\x01\x05\x00", "short reply"),
    (b"\x00" * 20, "no header"),
])
def test_faults_are_frame_errors(reply: bytes, message: str) -> None:
    with pytest.raises(FrameError, match=message) as caught:
        DXL.read(ScriptedPort(reply), [1], b"", -1)
    assert not caught.value.timeout


def test_nothing_at_all_is_a_timeout() -> None:
    with pytest.raises(FrameError) as caught:
        DXL.read(ScriptedPort(b""), [1], b"", -1)
    assert caught.value.timeout


def test_reply_checksum_over_the_request_and_a_delimited_payload() -> None:
    crc = Checksum("crc", 16, 0x1021)
    frame = Frame("version", [Field("address", "", "B", 0), Payload()],
                  [Payload(), Bytes("literal", b"\n\x00"), Check(crc, ">H", 0, 1, with_request=True)])
    request = frame.wrap(b"\x15", [0x80])
    text = b"USB Roboclaw 2x7a v4.1.34"
    reply = text + b"\n\x00" + crc(request + text + b"\n\x00").to_bytes(2, "big")
    assert frame.read(ScriptedPort(reply), [0x80], request, -1)[1] == text
    spoilt = reply[:-1] + bytes([reply[-1] ^ 1])
    with pytest.raises(FrameError, match="checksum"):
        frame.read(ScriptedPort(spoilt), [0x80], request, -1)


def test_hex_checksum_and_terminator() -> None:
    frame = Frame("nmea", [Bytes("header", b"$"), Payload(), Bytes("literal", b"*"),
                           Check(Checksum("xor", 8), None, 1, 1), Bytes("terminator", b"\r\n")], [])
    sentence = b"GPGLL,4916.45,N,12311.12,W,225444,A,"
    assert frame.wrap(sentence, []) == b"$" + sentence + b"*1D\r\n"


def test_binary_checksum_bytes_are_compared_exactly() -> None:
    """A struct checksum byte that happens to be a lower-case letter is not upper-cased (0x61 is not 0x41)."""
    frame = Frame("f", [Payload()], [Bytes("header", b"\xaa"), Payload(), Check(Checksum("sum", 8), "B", 1, 1)])
    assert frame.read(ScriptedPort(b"\xaa\x61\x61"), [], b"", 1)[1] == b"\x61"
    with pytest.raises(FrameError, match="checksum"):
        frame.read(ScriptedPort(b"\xaa\x61\x41"), [], b"", 1)


DXL2 = Frame("dxl2", [Bytes("header", b"\xff\xff\xfd\x00"), Field("id", "", "B", 0), Length("<", "H", 2, 0xFFFF), Payload(),
                      Check(Checksum("crc", 16, 0x8005), "<H", 0, 3)],
             [Bytes("header", b"\xff\xff\xfd\x00"), Field("id", "", "B", 0), Length("<", "H", 2, 0xFFFF), Payload(),
              Check(Checksum("crc", 16, 0x8005), "<H", 0, 3)],
             Stuffing(b"\xff\xff\xfd", b"\xfd"))


def test_dynamixel_2_ping_is_the_manuals() -> None:
    """ROBOTIS's Protocol 2.0 example: ping ID 1 is FF FF FD 00 01 03 00 01 19 4E (CRC-16/BUYPASS)."""
    assert DXL2.wrap(b"\x01", [1]) == bytes.fromhex("fffffd00010300 01194e".replace(" ", ""))


def test_stuffing_is_inserted_counted_and_removed() -> None:
    payload = bytes.fromhex("0374 00 fffffd 01".replace(" ", ""))
    request = DXL2.wrap(payload, [1])
    assert request[5:7] == (len(payload) + 1 + 2).to_bytes(2, "little")  # the length counts the escape
    assert request[7:-2] == bytes.fromhex("037400fffffdfd01")
    raw, unstuffed = DXL2.read(ScriptedPort(request), [1], b"", -1)
    assert (raw, unstuffed) == (request, payload)


def test_a_reserved_sequence_without_its_escape_is_a_frame_error() -> None:
    body = bytes.fromhex("01 0700 55 fffffd 00".replace(" ", ""))  # FF FF FD not followed by FD
    crc = Checksum("crc", 16, 0x8005)(b"\xff\xff\xfd\x00" + body)
    with pytest.raises(FrameError, match="not followed by"):
        DXL2.read(ScriptedPort(b"\xff\xff\xfd\x00" + body + crc.to_bytes(2, "little")), [1], b"", -1)


def test_a_bad_frame_gives_back_what_it_took() -> None:
    """A frame cut short swallows the next one's header; through an Incoming the reader finds it again."""
    body = bytes([1, 3, 0, 0x20])
    good = b"\xff\xff" + body + bytes([~sum(body) & 0xFF])
    cut = good[:-3]  # no checksum: the good frame's first bytes complete it, wrongly
    port = Incoming(ScriptedPort(cut + good))
    with pytest.raises(FrameError, match="checksum"):
        DXL.read(port, [1], b"", -1)
    assert DXL.read(port, [1], b"", -1) == (good, bytes([0, 0x20]))
