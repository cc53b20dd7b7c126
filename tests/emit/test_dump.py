"""`rdisc dump` as a user reads it beside a manual: a header line over each table, constant
integers as the bytes they put on the wire (and their decimal value), text escaped as RDIS
writes it, so a `\\r\\n` does not break the table."""

from __future__ import annotations

from pathlib import Path

MODEM = """\
robot modem { author "tests" }
connection link: serial { baud 9600 }
primitive hello(speed: int) on link pack ">BHhB" (0x84, 500, -2, speed)
primitive at(command: string) on link format "AT+{}\\r\\n" (command) regex "^OK\\r$"
"""


def test_constants_in_hex_text_escaped_and_a_header(tmp_path: Path, rdisc) -> None:
    source = tmp_path / "modem.rdis"
    source.write_text(MODEM, encoding="utf-8")
    result = rdisc("dump", source)
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == """\
primitive hello(speed: int) on link
  request: 6 bytes
  offset  size  kind                  value
       0     1  u8                    84 (132)
       1     2  u16 BE                01 F4 (500)
       3     2  s16 BE                FF FE (-2)
       5     1  u8                    speed
  reply: none

primitive at(command: string) on link
  request: 0+n bytes
  offset  size  kind                  value
       0     n  text                  "AT+{}\\r\\n" (command)
  reply: 0+n bytes
  offset  size  kind                  value
       0     n  text                  regex "^OK\\r$"
"""


NACK = """\
robot nack { author "tests" }
enum Refusal { BUSY = 1 }
connection link: serial { baud 9600 }
primitive level() on link pack "B" (0x21) unpack "<BH" error "\\x15" unpack "B" code Refusal
"""


def test_an_error_reply_is_shown_after_the_reply(tmp_path: Path, rdisc) -> None:
    source = tmp_path / "nack.rdis"
    source.write_text(NACK, encoding="utf-8")
    result = rdisc("dump", source)
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout.split("  reply: ")[1] == """\
3 bytes
  offset  size  kind                  value
       0     1  u8                    out[0]
       1     2  u16 LE                out[1]
  or an error: 2 bytes
  offset  size  kind                  value
       0     1  error marker          15
       1     1  u8                    code, named by Refusal
"""


PADDED = """\
robot padded { author "tests" }
connection link: serial { baud 9600 }
primitive yaw() on link pack ">Bxx" (0x71) unpack ">hxxB{1,7}2xf"
"""


def test_pad_bytes_have_rows_so_the_offsets_after_them_are_where_values_are_read(tmp_path: Path, rdisc) -> None:
    source = tmp_path / "padded.rdis"
    source.write_text(PADDED, encoding="utf-8")
    result = rdisc("dump", source)
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == """\
primitive yaw() on link
  request: 3 bytes
  offset  size  kind                  value
       0     1  u8                    71 (113)
       1     2  pad                   zero bytes, skipped when read
  reply: 11 bytes
  offset  size  kind                  value
       0     2  s16 BE                out[0]
       2     2  pad                   zero bytes, skipped when read
       4     1  bits u8               out[1] (bit 0), out[2] (bits 1..7)
       5     2  pad                   zero bytes, skipped when read
       7     4  f32 BE                out[3]
"""
    capture = tmp_path / "capture.txt"
    capture.write_text("> 71 00 00\n< FF 38 00 00 03 00 00 41 20 00 00\n", encoding="utf-8")
    decoded = rdisc("decode", source, capture)
    assert (decoded.returncode, decoded.stderr) == (0, "")
    assert "  reply of yaw" in decoded.stdout and "10.0" in decoded.stdout
