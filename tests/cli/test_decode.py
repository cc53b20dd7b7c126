"""`rdisc decode FILE [CAPTURE]`: captured traffic told as the description's requests and
replies, field by field: hex lines, a pyserial spy:// hex dump (made by pyserial's own
formatter) and an rdisc recording. Bytes that fit nothing, or whose checksum is wrong, are shown
as unknown; a capture that cannot be read is refused in one line, exit 2, never a traceback."""

from __future__ import annotations

import io
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import cli_env
from mcap_ros2.writer import Writer
from serial.urlhandler.protocol_spy import FormatHexdump

from rdisc.engine.recording import _BYTES_SCHEMA

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
HEAD = "  offset  size  kind                  value                         holds         bytes"
DRIVE = [
    "> 89 00 C8 FF FF",
    "  request drive",
    HEAD,
    "       0     1  u8                    89 (137)                      137           89",
    "       1     2  s16 BE                velocity                      200           00 C8",
    "       3     2  s16 BE                radius                        -1            FF FF",
]
BUMPERS = [
    "> 8E 07",
    "  request bumpers",
    HEAD,
    "       0     1  u8                    8E (142)                      142           8E",
    "       1     1  u8                    07 (7)                        7             07",
    "< 03",
    "  reply of bumpers",
    HEAD,
    "       0     1  u8                    out[0]                        3             03",
]


def decode(rdisc, description: str, capture: Path) -> list[str]:
    result = rdisc("decode", EXAMPLES / description, capture)
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    return result.stdout.splitlines()


def test_hex_lines_of_a_create_session(rdisc, tmp_path: Path) -> None:
    capture = tmp_path / "create.txt"
    capture.write_text("# drive, then the bumpers\n> 89 00 c8 ff ff\n>8e07\n< 03\n\n> 12 34  # no such opcode\n")
    assert decode(rdisc, "create.rdis", capture) == [
        *DRIVE, *BUMPERS, "> 12 34", "  unknown: no primitive's request is these 2 bytes"]


def test_an_ax12_exchange_framed_and_checked(rdisc, tmp_path: Path) -> None:
    """The manual's WRITE of goal 512 and its status; a READ of the position and its reply; the
    same reply with its checksum wrong is no reply, and a request with a wrong checksum no request;
    a broadcast is the broadcasting primitive's."""
    capture = tmp_path / "ax12.txt"
    capture.write_text("bus > ff ff 01 05 03 1e 00 02 d6\nbus < ff ff 01 02 00 fc\n"
                       "> FF FF 01 04 02 24 02 D2\n< ff ff 01 04 00 00 02 f8\n< ff ff 01 04 00 00 02 00\n"
                       "> FF FF 01 04 02 24 02 D3\n> ff ff fe 02 01 fe\n"
                       "> FF FF 01 04 02 24 02 D2\n< ff ff 02 04 00 00 02 f7\n")
    frame = "       0     2  header                FF FF                                       FF FF"
    field = "       2     1  field id              \"B\" = id                      1             01"
    checksum = "  checksum              sum inverted as B, over id .. payload                "
    lines = decode(rdisc, "ax12.rdis", capture)
    position, reply = lines[18:28], lines[28:37]
    assert lines == [
        "bus > FF FF 01 05 03 1E 00 02 D6",
        "  request goto",
        HEAD, frame, field,
        "       3     1  length                \"B\" = payload + 1             5             05",
        "       4     1  payload u8            03 (3)                        3             03",
        "       5     1  payload u8            1E (30)                       30            1E",
        "       6     2  payload u16 LE        goal                          512           00 02",
        "       8     1" + checksum + "D6",
        "bus < FF FF 01 02 00 FC",
        "  reply of goto",
        HEAD, frame, field,
        "       3     1  length                \"B\" = payload + 1             2             02",
        "       4     1  payload u8            out[0]                        0             00",
        "       5     1" + checksum + "FC",
        "> FF FF 01 04 02 24 02 D2",
        "  request read_position",
        HEAD, frame, field,
        "       3     1  length                \"B\" = payload + 1             4             04",
        "       4     1  payload u8            02 (2)                        2             02",
        "       5     1  payload u8            24 (36)                       36            24",
        "       6     1  payload u8            02 (2)                        2             02",
        "       7     1" + checksum + "D2",
        "< FF FF 01 04 00 00 02 F8",
        "  reply of read_position",
        HEAD, frame, field,
        "       3     1  length                \"B\" = payload + 1             4             04",
        "       4     1  payload u8            out[0]                        0             00",
        "       5     2  payload u16 LE        out[1]                        512           00 02",
        "       7     1" + checksum + "F8",
        "< FF FF 01 04 00 00 02 00",
        "  unknown: no primitive's reply is these 8 bytes",
        "> FF FF 01 04 02 24 02 D3",
        "  unknown: no primitive's request is these 8 bytes",
        "> FF FF FE 02 01 FE",  # a broadcast: the primitive whose frame says 254 is named first
        "  request ping_all (also fits: ping)",
        HEAD, frame,
        "       2     1  field id              \"B\" = id                      254           FE",
        "       3     1  length                \"B\" = payload + 1             2             02",
        "       4     1  payload u8            01 (1)                        1             01",
        "       5     1" + checksum + "FE",
        "> FF FF 01 04 02 24 02 D2",
        "  request read_position",
        *position[2:],
        "< FF FF 02 04 00 00 02 F7",  # servo 2 answers a request to servo 1: the engine's refusal said
        "  reply of read_position, but dxl: reply id is 2, expected 1",
        HEAD, frame,
        "       2     1  field id              \"B\" = id                      2             02",
        *reply[5:-1],
        "       7     1" + checksum + "F7",
    ]


def test_a_pyserial_spy_log(rdisc, tmp_path: Path) -> None:
    """What `spy://PORT?file=LOG` writes, by pyserial's own formatter: control lines skipped, a
    message of more than 16 bytes joined from its rows."""
    log = io.StringIO()
    spy = FormatHexdump(log, False)
    spy.control("RTS", "active")
    spy.tx(bytes.fromhex("8900c8ffff"))
    spy.rx(b"")
    spy.tx(bytes.fromhex("8e07"))
    spy.rx(bytes.fromhex("03"))
    spy.tx(bytes(range(17)))
    capture = tmp_path / "spy.log"
    capture.write_text(log.getvalue())
    assert decode(rdisc, "create.rdis", capture) == [
        *DRIVE, *BUMPERS, "> " + bytes(range(17)).hex(" ").upper(),
        "  unknown: no primitive's request is these 17 bytes"]


def test_an_rdisc_recording(rdisc, tmp_path: Path) -> None:
    capture = tmp_path / "create.mcap"
    with capture.open("wb") as f:
        writer = Writer(f)
        writer.add_metadata("rdisc", {"robot": "create", "timeout": "1", "settings": "{}"})
        schema = writer.register_msgdef("std_msgs/msg/UInt8MultiArray", _BYTES_SCHEMA)
        for n, (topic, data) in enumerate([("write", "8e07"), ("read", "03")], start=1):
            writer.write_message(f"/rdisc/btserial/{topic}", schema, {"data": list(bytes.fromhex(data))}, log_time=n)
        writer.finish()
    assert decode(rdisc, "create.rdis", capture) == [
        "btserial " + line if line[0] in "<>" else line for line in BUMPERS]


def test_hex_lines_on_stdin() -> None:
    result = subprocess.run([sys.executable, "-m", "rdisc", "decode", str(EXAMPLES / "create.rdis")],
                            input="> 8e 07\n< 03\n", env=cli_env(), capture_output=True, text=True, check=False)
    assert (result.returncode, result.stderr, result.stdout.splitlines()) == (0, "", BUMPERS)


@pytest.mark.parametrize(("text", "said"), [
    ("> 89 0g\n", "{path}:1: not hex bytes (two digits a byte): '89 0g'"),
    ("> 89 0\n", "{path}:1: not hex bytes (two digits a byte): '89 0'"),
    ("# fine\n89 00\n", "{path}:2: a message starts with > (host to device) or < (device to host): '89 00'"),
    ("> " + "00" * 40_000 + "\n", "{path}:1: a line of 80002 characters, more than 65536"),
    ("000000.000 TX   0000  zz\n", "{path}:1: not a row of pyserial's hex dump: '000000.000 TX   0000  zz'"),
])
def test_a_bad_capture_is_one_line_and_exit_2(rdisc, tmp_path: Path, text: str, said: str) -> None:
    capture = tmp_path / "bad.txt"
    capture.write_text(text)
    result = rdisc("decode", EXAMPLES / "create.rdis", capture)
    assert (result.returncode, result.stdout, result.stderr) == (2, "", "rdisc decode: " + said.format(path=capture) + "\n")


def test_too_much_text_binary_a_missing_file_and_not_a_recording(rdisc, tmp_path: Path) -> None:
    huge, binary, fake = tmp_path / "huge.txt", tmp_path / "bytes.bin", tmp_path / "fake.mcap"
    huge.write_text(("> 89 00 c8 ff ff\n") * (2**20 + 1))
    binary.write_bytes(b"\xff\xfe\x00" * 100)
    fake.write_bytes(b"not mcap")
    said = {
        huge: f"{huge}: more than 16 MiB of text",
        binary: f"{binary}: not text (hex lines or a spy log); a recording ends in .mcap",
        tmp_path / "missing.txt": f"{tmp_path / 'missing.txt'}: No such file or directory",
    }
    for path, line in said.items():
        result = rdisc("decode", EXAMPLES / "create.rdis", path)
        assert (result.returncode, result.stdout, result.stderr) == (2, "", f"rdisc decode: {line}\n")
    result = rdisc("decode", EXAMPLES / "create.rdis", fake)
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr.startswith(f"rdisc decode: {fake}: not a readable recording") and result.stderr.count("\n") == 1


def test_text_requests_by_their_format_and_replies_by_their_regex(rdisc, tmp_path: Path) -> None:
    capture = tmp_path / "koala.txt"
    capture.write_text("> 45 0a\n< 65 2c 31 2c 32 0d 0a\n> 47 0a\n")
    assert decode(rdisc, "koala.rdis", capture) == [
        "> 45 0A",
        "  request read_speed",
        HEAD,
        '       0     2  text                  "E\\n"                         "E\\n"         45 0A',
        "< 65 2C 31 2C 32 0D 0A",
        "  reply of read_speed",
        HEAD,
        '       0     7  text                  regex r"^e,(-?\\d+),(-?\\d+)\\s*$"  "e,1,2\\r\\n"   65 2C 31 2C 32 0D 0A',
        "  out = ['1', '2']",
        "> 47 0A",  # `G,{},{}\n` wants its commas
        "  unknown: no primitive's request is these 2 bytes",
    ]


def test_every_example_reads_random_bytes_without_a_traceback(tmp_path: Path) -> None:
    """Bytes of every length up to 300, random and cut from the examples' own headers, through
    every example: each message is named or unknown, in process, never an exception."""
    import random

    from rdisc.capture import Message
    from rdisc.emit.decode import decode as decoded
    from rdisc.runtime.device import load

    chance = random.Random(23)
    for path in sorted(EXAMPLES.glob("*.rdis")):
        description = load(path)
        messages = [Message(chance.random() < 0.5, (b"\xff\xff" if n % 3 == 0 else b"")
                            + bytes(chance.randrange(256) for _ in range(chance.randrange(300))))
                    for n in range(60)]
        text = decoded(description.model, description.device, messages)
        assert text.count("\n  request ") + text.count("\n  reply") + text.count("\n  unknown: ") >= 60, path


def test_a_capture_of_too_many_messages_is_refused(rdisc, tmp_path: Path, monkeypatch) -> None:
    from rdisc import capture as capture_module

    monkeypatch.setattr(capture_module, "MAX_MESSAGES", 3)
    capture = tmp_path / "long.txt"
    capture.write_text("> 8e 07\n< 03\n" * 2)
    result = rdisc("decode", EXAMPLES / "create.rdis", capture)
    assert (result.returncode, result.stdout, result.stderr) == (2, "", f"rdisc decode: {capture}: 4 messages, more than 3\n")


def test_a_modbus_exception_is_the_error_reply_of_its_request(rdisc, tmp_path: Path) -> None:
    """The Modbus specification's exception (`01 83 02 C0 F1`, function 0x83: its own frame's
    fields, not the request's) is told as the error of the request before it, its code named by
    the description's enum; with its CRC wrong, as nothing."""
    capture = tmp_path / "modbus.txt"
    capture.write_text("> 01 03 00 6B 00 02 B5 D7\n< 01 83 02 C0 F1\n< 01 83 02 C0 F2\n")
    assert decode(rdisc, "modbus.rdis", capture)[8:] == [
        "< 01 83 02 C0 F1",
        "  error of read_holding",
        HEAD,
        '       0     1  field unit            "B" = unit                    1             01',
        '       1     1  field function        "B" = function                131           83',
        "       2     1  payload u8            code, named by Exception      2             02",
        "       3     2  checksum              crc16-modbus as <H, over unit .. payload                C0 F1",
        "  error 2: ILLEGAL_DATA_ADDRESS",
        "< 01 83 02 C0 F2",
        "  unknown: no primitive's reply is these 5 bytes",
    ]


NAMED = """\
robot named { author "tests" }
enum Refusal { BUSY = 1, BAD_COMMAND = 3 }
state name: string = ""
connection link: serial { baud 9600 }
primitive name_of() on link pack "B" (0x21) unpack "<6Z" error "\\x15" unpack "B" code Refusal { name = out[0] }
"""


def test_a_nack_is_named_and_a_padded_name_read_to_its_nul(rdisc, tmp_path: Path) -> None:
    description = tmp_path / "named.rdis"
    description.write_text(NAMED, encoding="utf-8")
    capture = tmp_path / "named.txt"
    capture.write_text("> 21\n< 15 09\n> 21\n< 41 42 00 00 00 00\n")
    result = rdisc("decode", description, capture)
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout.splitlines()[4:] == [
        "< 15 09",
        "  error of name_of",
        HEAD,
        "       0     1  error marker          15                                          15",
        "       1     1  u8                    code, named by Refusal        9             09",
        "  error 9: not a member of Refusal",
        "> 21",
        "  request name_of",
        HEAD,
        "       0     1  u8                    21 (33)                       33            21",
        "< 41 42 00 00 00 00",
        "  reply of name_of",
        HEAD,
        '       0     6  text, padded          out[0]                        "AB"          41 42 00 00 00 00',
    ]


def test_bit_fields_show_the_values_they_hold(rdisc, tmp_path: Path) -> None:
    """S.BUS's sixteen 11-bit channels in 22 bytes (`22s{11*16}`, the first in the lowest bits)
    and its flags byte (`B{4,1,1,1,1}`): each field's value, in the row's order."""
    channels = [172, 992, 1811, 0, 2047, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]
    packed = sum(value << (11 * i) for i, value in enumerate(channels)).to_bytes(22, "little")
    frame = b"\x0f" + packed + b"\x13\x00"  # flags: 3 in the low nibble, failsafe (bit 4) set
    capture = tmp_path / "sbus.txt"
    capture.write_text(f"< {frame.hex(' ')}\n")
    result = rdisc("decode", EXAMPLES / "sbus.rdis", capture)  # 100000 baud is S.BUS's own rate: no W201
    assert (result.returncode, result.stderr) == (0, "")
    lines = result.stdout.splitlines()
    spans = ", ".join(f"out[{i}] (bits {11 * i}..{11 * i + 10})" for i in range(16))
    assert lines[4:7] == [
        f"       1    22  payload bits u176 LE  {spans}  {', '.join(map(str, channels))}  {packed.hex(' ').upper()}",
        ("      23     1  payload bits u8       out[16] (bits 0..3), out[17] (bit 4), out[18] (bit 5), out[19] (bit 6), "
        "out[20] (bit 7)  3, 1, 0, 0, 0  13"),
        "      24     1  literal               00                                          00",
    ]


def test_a_frames_bits_part_shows_its_fields(rdisc, tmp_path: Path) -> None:
    """RPLIDAR's descriptor: a 30-bit length and a 2-bit mode in one `<I`; a scan's bit fields."""
    capture = tmp_path / "rplidar.txt"
    capture.write_text("> A5 20\n< A5 5A 05 00 00 40 81 3E 03 0F 20 10\n")
    assert decode(rdisc, "rplidar.rdis", capture)[5:] == [
        "< A5 5A 05 00 00 40 81 3E 03 0F 20 10",
        "  reply of scan",
        HEAD,
        "       0     2  header                A5 5A                                       A5 5A",
        ('       2     4  bits                  "<I": length = payload (bits 0..29), mode = mode (bits 30..31)  5, 1'
        "          05 00 00 40"),
        '       6     1  field type            "B" = type                    129           81',
        "       7     1  payload bits u8       out[0] (bit 0), out[1] (bit 1), out[2] (bits 2..7)  0, 1, 15      3E",
        "       8     2  payload bits u16 LE   out[3] (bit 0), out[4] (bits 1..15)  1, 1921       03 0F",
        "      10     2  payload u16 LE        out[5]                        4128          20 10",
    ]


def test_lines_read_together_are_cut_as_the_engine_reads_them(rdisc, tmp_path: Path) -> None:
    """SLCAN's replies end in CR: an acknowledgement (a CR alone), a frame, another CR and the
    version that came in one read are four lines, as the engine's reader takes them; the first CR
    is no part of the frame after it. A framed reply table's tag is held to its entry's value."""
    capture = tmp_path / "slcan.txt"
    capture.write_text("< 0D 74 31 32 33 32 41 42 0D 0D 56 31 30 31 33 0D\n")
    assert decode(rdisc, "slcan.rdis", capture) == [
        "< 0D",
        "  unknown: no primitive's reply is these 1 bytes",
        "< 74 31 32 33 32 41 42 0D",
        "  reply when  = 116 of receive",  # its tag: no other entry's
        HEAD,
        "       0     1  payload tag u8        = 116                                       74",
        '       1     3  payload text          out[0]                        "123"         31 32 33',
        "       4     1  payload char          out[1]                                      32",
        "       5     2  payload bytes (the rest)  out[2]                                      41 42",
        "       7     1  terminator            0D                                          0D",
        "< 0D",
        "  unknown: no primitive's reply is these 1 bytes",
        "< 56 31 30 31 33 0D",  # the version, no CAN frame: its tag V is none of receive's
        "  reply of version",
        HEAD,
        '       0     5  payload text          regex r"^V(\\d\\d)(\\d\\d)"       "V1013"       56 31 30 31 33',
        "       5     1  terminator            0D                                          0D",
        "  out = ['10', '13']",
    ]


def test_slcan_commands_are_named_by_the_format_that_fixes_most_of_their_text(rdisc, tmp_path: Path) -> None:
    """`V` is the version request, `O` the open, though `rate`'s `"{}"` (any text) fits them too:
    the format fixing more of a text names it, one fixing less is not listed; `S6` fits two `"{}"`
    formats alike (no CAN FD frame: `{:03X}` writes three digits at least), both named."""
    capture = tmp_path / "slcan.txt"
    capture.write_text("> 56 0D\n< 56 31 30 31 33 0D\n> 4F 0D\n> 53 36 0D\n")
    assert decode(rdisc, "slcan.rdis", capture) == [
        "> 56 0D",
        "  request version",
        HEAD,
        '       0     1  payload text          "V"                           "V"           56',
        "       1     1  terminator            0D                                          0D",
        "< 56 31 30 31 33 0D",
        "  reply of version",
        HEAD,
        '       0     5  payload text          regex r"^V(\\d\\d)(\\d\\d)"       "V1013"       56 31 30 31 33',
        "       5     1  terminator            0D                                          0D",
        "  out = ['10', '13']",
        "> 4F 0D",
        "  request open",
        HEAD,
        '       0     1  payload text          "O"                           "O"           4F',
        "       1     1  terminator            0D                                          0D",
        "> 53 36 0D",
        "  request rate (also fits: data_rate)",
        HEAD,
        '       0     2  payload text          "{}" (BITRATES[bitrate])      "S6"          53 36',
        "       2     1  terminator            0D                                          0D",
    ]


def test_a_tmcl_refusal_is_the_error_of_its_request(rdisc, tmp_path: Path) -> None:
    """TMCL's `error when out[0] < 100 code Status`: a reply of status 100 is the reply; one of
    status 4 is the device's error, its code named as the runtime's RdisDeviceError names it."""
    capture = tmp_path / "tmcl.txt"
    capture.write_text("> 01 05 01 00 00 00 00 00 07\n< 02 01 64 05 00 00 00 00 6C\n< 02 01 04 05 00 00 00 00 0C\n")
    host, module = ('       0     1  field host            "B" = host                    2             02',
                    '       1     1  field module          "B" = module                  1             01')
    rest = ["       3     1  payload u8            out[1]                        5             05",
            "       4     4  payload s32 BE        out[2]                        0             00 00 00 00"]
    assert decode(rdisc, "tmcl.rdis", capture)[9:] == [
        "< 02 01 64 05 00 00 00 00 6C",
        "  reply of set_axis_parameter",
        HEAD, host, module,
        "       2     1  payload u8            out[0]                        100           64",
        *rest,
        "       8     1  checksum              sum as B, over host .. payload                6C",
        "< 02 01 04 05 00 00 00 00 0C",
        "  error of set_axis_parameter",
        HEAD, host, module,
        "       2     1  payload u8            code, named by Status         4             04",
        *rest,
        "       8     1  checksum              sum as B, over host .. payload                0C",
        "  error 4: INVALID_VALUE",
    ]


def test_an_nmea_sentence_is_held_against_its_regex_between_dollar_and_star(rdisc, tmp_path: Path) -> None:
    """A framed text reply's regex is the payload's (as the engine's `Match` reads it), not the
    whole frame's: the `$` header and the `*47` checksum are the frame's."""
    sentence = b"$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n"
    capture = tmp_path / "nmea.txt"
    capture.write_text(f"< {sentence.hex(' ')}\n")
    lines = decode(rdisc, "nmea.rdis", capture)
    assert lines[1] == "  reply of gga"
    assert lines[-1] == ("  out = ['GP', '123519', '4807.038', 'N', '01131.000', 'E', '1', '08', '0.9', '545.4', "
                         "'46.9', '', '']")
