"""`rdisc decode` of frames whose bytes on the wire are not their table's: escaped (SLIP), byte
stuffed (Dynamixel 2.0) and trimmed (MAVLink 2). Each is read by the engine's own frame reader
(`Frame.read`: unescaped, unstuffed, its payload zero-filled to its decoding's size) and its
table held against the bytes as read, which decode shows. The captures are other code's: sliplib's
SLIP packets, pymavlink's MAVLink 2 frames, and Dynamixel packets stuffed as the e-Manual says
(tests/devices/dynamixel.py, which is not rdisc's code)."""

from __future__ import annotations

from pathlib import Path

from cli.test_decode import HEAD

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

SLIP = """\
robot slip { author "tests" }
state first: int = 0
connection link: serial { baud 115200 }
frame slip { payload  terminator "\\xC0"  escape "\\xDB" { "\\xC0": "\\xDC", "\\xDB": "\\xDD" } }
primitive send(data: bytes in 0..600) on link frame slip pack "B*" (7, data)
primitive receive() on link frame slip pack "B" (9) unpack "BB*" { first = out[0] }
"""

MAVLINK = """\
robot mavlink { author "tests" }
state value: float = 0.0
/// CRC_EXTRA by message id: PARAM_REQUEST_READ, PARAM_VALUE.
const EXTRAS = { 20: 214, 22: 220 }
connection link: serial { baud 57600 }
frame mav2(sent: int in 0..65535, answer: int in 0..65535) {
    request {
        header "\\xFD"  length "B" = payload  literal "\\x00\\x00\\x00\\x01\\x01"  field sent "<H" = sent  literal "\\x00"
        payload trimmed  checksum "crc16-mcrf4xx" "<H" seed EXTRAS[sent]
    }
    reply {
        header "\\xFD"  length "B" = payload  literal "\\x00\\x00\\x00\\x01\\x01"  field answer "<H" = answer
        literal "\\x00"  payload trimmed  checksum "crc16-mcrf4xx" "<H" seed EXTRAS[answer]
    }
}
primitive param_read(at: int in -1..32767, id: string) on link frame mav2(20, 22) pack "<hBB16Z" (at, 1, 1, id)
    unpack "<fHH16ZB" { value = out[0] }
"""

DXL = """\
robot dxl { author "tests" }
connection bus: serial { baud 1000000 }
frame dxl(id: int in 0..253) {
    header "\\xFF\\xFF\\xFD\\x00"
    field id "B" = id
    length "<H" = payload + 2
    payload
    checksum "crc16-buypass" "<H" over header .. payload
    stuff "\\xFD" after "\\xFF\\xFF\\xFD"
}
primitive write(id: int in 0..253, address: int in 0..65535, data: bytes in 1..8) on bus frame dxl(id)
    pack "<BH*" (3, address, data) unpack "<BB" expect out[0] == 0x55
"""


def decoded(rdisc, tmp_path: Path, description: str, capture: str) -> list[str]:
    path = tmp_path / "device.rdis"
    path.write_text(description, encoding="utf-8")
    (tmp_path / "capture.txt").write_text(capture, encoding="utf-8")
    result = rdisc("decode", path, tmp_path / "capture.txt")
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    return result.stdout.splitlines()


def test_slip_packets_are_unescaped_as_the_engine_reads_them(rdisc, tmp_path: Path) -> None:
    """sliplib's packets of 07 C0 DB 05 (END and ESC inside) and of 09, and a reply 01 C0 02 DB."""
    assert decoded(rdisc, tmp_path, SLIP, "> 07 db dc db dd 05 c0\n> 09 c0\n< 01 db dc 02 db dd c0\n"
                                          "< 01 db 02 c0\n") == [
        "> 07 DB DC DB DD 05 C0",
        "  request send",
        "  read as 5 bytes (unescaped): 07 C0 DB 05 C0",
        HEAD,
        "       0     1  payload u8            07 (7)                        7             07",
        "       1     3  payload bytes (the rest)  data                                        C0 DB 05",
        "       4     1  terminator            C0                                          C0",
        "> 09 C0",
        "  request receive",
        HEAD,
        "       0     1  payload u8            09 (9)                        9             09",
        "       1     1  terminator            C0                                          C0",
        "< 01 DB DC 02 DB DD C0",
        "  reply of receive",
        "  read as 5 bytes (unescaped): 01 C0 02 DB C0",
        HEAD,
        "       0     1  payload u8            out[0]                        1             01",
        "       1     1  payload u8            out[1]                        192           C0",
        "       2     2  payload bytes (the rest)  out[2]                                      02 DB",
        "       4     1  terminator            C0                                          C0",
        "< 01 DB 02 C0",  # an escape before no code: the engine refuses it, so decode does
        "  unknown: no primitive's reply is these 4 bytes",
    ]


def test_mavlink_2_payloads_are_zero_filled_as_the_engine_reads_them(rdisc, tmp_path: Path) -> None:
    """pymavlink's PARAM_REQUEST_READ of index 7, "RATE" (12 trailing zero bytes trimmed), and the
    PARAM_VALUE that answers it (RATE_RLL_P = 0.25, 300 of them, type 0: 7 bytes trimmed)."""
    lines = decoded(rdisc, tmp_path, MAVLINK,
                    "> fd 08 00 00 00 01 01 14 00 00 07 00 01 01 52 41 54 45 19 31\n"
                    "< fd 12 00 00 00 01 01 16 00 00 00 00 80 3e 2c 01 07 00 52 41 54 45 5f 52 4c 4c 5f 50 80 2b\n"
                    "< fd 12 00 00 00 01 01 16 00 00 00 00 80 3e 2c 01 07 00 52 41 54 45 5f 52 4c 4c 5f 50 80 2c\n")
    assert lines[:4] == [
        "> FD 08 00 00 00 01 01 14 00 00 07 00 01 01 52 41 54 45 19 31",
        "  request param_read",
        ("  read as 32 bytes (payload zero-filled): FD 08 00 00 00 01 01 14 00 00 07 00 01 01 52 41 54 45 "
        "00 00 00 00 00 00 00 00 00 00 00 00 19 31"),
        HEAD]
    assert lines[12:16] == [
        ("      14    16  payload text, padded  id                            \"RATE\"        "
        "52 41 54 45 00 00 00 00 00 00 00 00 00 00 00 00"),
        "      30     0  payload trimmed       trailing zero bytes dropped; put back when read",
        ("      30     2  checksum              crc16-mcrf4xx as <H, over length .. payload, then EXTRAS[sent] "
        "(not sent)                19 31"),
        "< FD 12 00 00 00 01 01 16 00 00 00 00 80 3E 2C 01 07 00 52 41 54 45 5F 52 4C 4C 5F 50 80 2B"]
    assert lines[16:18] == [
        "  reply of param_read",
        ("  read as 37 bytes (payload zero-filled): FD 12 00 00 00 01 01 16 00 00 00 00 80 3E 2C 01 07 00 "
        "52 41 54 45 5F 52 4C 4C 5F 50 00 00 00 00 00 00 00 80 2B")]
    assert lines[24:30] == [
        "      10     4  payload f32 LE        out[0]                        0.25          00 00 80 3E",
        "      14     2  payload u16 LE        out[1]                        300           2C 01",
        "      16     2  payload u16 LE        out[2]                        7             07 00",
        ("      18    16  payload text, padded  out[3]                        \"RATE_RLL_P\"  "
        "52 41 54 45 5F 52 4C 4C 5F 50 00 00 00 00 00 00"),
        "      34     1  payload u8            out[4]                        0             00",
        "      35     0  payload trimmed       trailing zero bytes dropped; put back when read"]
    assert lines[31:] == [  # its CRC one off: no PARAM_VALUE, as the engine would refuse it
        "< FD 12 00 00 00 01 01 16 00 00 00 00 80 3E 2C 01 07 00 52 41 54 45 5F 52 4C 4C 5F 50 80 2C",
        "  unknown: no primitive's reply is these 30 bytes"]


def test_dynamixel_packets_are_unstuffed_as_the_engine_reads_them(rdisc, tmp_path: Path) -> None:
    """A WRITE of FF FF FD 07 at 0x10, stuffed (an FD after FF FF FD), and its status."""
    assert decoded(rdisc, tmp_path, DXL, "> ff ff fd 00 01 0a 00 03 10 00 ff ff fd fd 07 73 85\n"
                                         "< ff ff fd 00 01 04 00 55 00 a1 0c\n") == [
        "> FF FF FD 00 01 0A 00 03 10 00 FF FF FD FD 07 73 85",
        "  request write",
        "  read as 16 bytes (unstuffed): FF FF FD 00 01 0A 00 03 10 00 FF FF FD 07 73 85",
        HEAD,
        "       0     4  header                FF FF FD 00                                 FF FF FD 00",
        "       4     1  field id              \"B\" = id                      1             01",
        "       5     2  length                \"<H\" = payload + 2            10            0A 00",
        "       7     1  payload u8            03 (3)                        3             03",
        "       8     2  payload u16 LE        address                       16            10 00",
        "      10     4  payload bytes (the rest)  data                                        FF FF FD 07",
        "      14     2  checksum              crc16-buypass as <H, over header .. payload                73 85",
        "< FF FF FD 00 01 04 00 55 00 A1 0C",
        "  reply of write",
        HEAD,
        "       0     4  header                FF FF FD 00                                 FF FF FD 00",
        "       4     1  field id              \"B\" = id                      1             01",
        "       5     2  length                \"<H\" = payload + 2            4             04 00",
        "       7     1  payload u8            out[0]                        85            55",
        "       8     1  payload u8            out[1]                        0             00",
        "       9     2  checksum              crc16-buypass as <H, over header .. payload                A1 0C",
    ]


def test_a_stuffed_status_packet_of_a_sync_read_is_unstuffed(rdisc, tmp_path: Path) -> None:
    """examples/arm.rdis: the sync read of six positions, answered by the e-Manual's status packets;
    the sixth servo's position holds FF FF FD, so its packet is stuffed."""
    (tmp_path / "capture.txt").write_text(
        "> ff ff fd 00 fe 0d 00 82 84 00 04 00 01 02 03 04 05 06 b2 9b\n"
        "< ff ff fd 00 05 08 00 55 00 ff 0f 00 00 d8 2d\n"
        "< ff ff fd 00 06 09 00 55 00 00 ff ff fd fd bc 96\n", encoding="utf-8")
    result = rdisc("decode", EXAMPLES / "arm.rdis", tmp_path / "capture.txt")
    assert (result.returncode, result.stderr) == (0, "")
    lines = result.stdout.splitlines()
    assert [line for line in lines if not line.startswith("   ")][-4:-1] == [
        "< FF FF FD 00 06 09 00 55 00 00 FF FF FD FD BC 96",
        "  reply of sync_read_present",
        "  read as 15 bytes (unstuffed): FF FF FD 00 06 09 00 55 00 00 FF FF FD BC 96"]
    assert lines[-2] == ("       9     4  payload s32 LE        out[2]                        -33554688     "
                         "00 FF FF FD")
