"""A tag table's entry that dispatches again on the next tag (Firmata's sysex: F0, then a
sub-command choosing the layout, ended by F7). The engine reads the tag, the nested table's tag,
then its entry's bytes; `skip unmatched` reads past a sub-command without an entry from the byte
after F0. In the runtime and a generated driver alike, over a scripted port; through JSON, the
printer, `rdisc dump`, the link budget and the checker."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.emit.dump import dump
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.conftest import run_rdisc
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

SYSEX = """\
robot sysex { author "tests" }
state major: int = 0
state minor: int = 0
state sketch: string = ""
state said: string = ""
state version: int = 0
state command: int = 0
connection link: serial { baud 57600 }
/// Messages as they come; a sysex message is F0, its sub-command, its data, F7.
primitive listen() on link format "" () skip unmatched reply tag "B" {
    0xF9: unpack "BB" { version = out[0] * 10 + out[1] }
    0xF0: tag "B" {
        0x79: unpack "BB*" until "\\xF7" { major = out[0]  minor = out[1]  sketch = ascii(unpack7(out[2])) }
        0x71: unpack "*" until "\\xF7" { said = ascii(unpack7(out[0]))  command = tag }
    }
}
/// The same without `skip unmatched`: a sub-command without an entry is an error.
primitive strict() on link format "" () reply tag "B" {
    0xF0: tag "B" { 0x79: unpack "BB*" until "\\xF7" { major = out[0] } }
}
"""
# REPORT_FIRMWARE 2.5 "Std", in Firmata's 7-bit pairs; STRING_DATA "hi"; an ANALOG_MAPPING_RESPONSE
# (6A), which has no entry; the version.
FIRMWARE = bytes.fromhex("f0 79 02 05 53 00 74 00 64 00 f7")
STRING = bytes.fromhex("f0 71 68 00 69 00 f7")
MAPPING = bytes.fromhex("f0 6a 7f 7f 00 01 f7")
VERSION = bytes.fromhex("f9 02 05")


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_sysex_sub_command_chooses_its_entry(kind: str, tmp_path: Path) -> None:
    seen: list[tuple[str, str]] = []
    port = ScriptedPort(FIRMWARE + MAPPING + STRING + VERSION)
    implementation = implementation_of(kind, SYSEX, tmp_path, "sysex")
    with implementation.connect(port, threads=False, on_io=lambda d, _c, b: seen.append((d, b.hex(" ")))) as robot:
        robot.call_primitive("listen")
        assert [robot.state[k] for k in ("major", "minor", "sketch", "said")] == [2, 5, "Std", ""]
        robot.call_primitive("listen")  # reads past the mapping, a byte at a time after its F0
        assert (robot.state["said"], robot.state["command"]) == ("hi", 0x71)  # `tag`: the sub-command
        robot.call_primitive("listen")
        assert robot.state["version"] == 25
        with pytest.raises(TimeoutError) as caught:
            robot.call_primitive("listen")
        assert str(caught.value) == "listen: no matching reply within 1 s"
    assert "".join(b for d, b in seen if d == "read").replace(" ", "") == \
        (FIRMWARE + MAPPING + STRING + VERSION).hex()


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_sub_command_without_an_entry_is_a_protocol_error(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, SYSEX, tmp_path, "sysex")
    with implementation.connect(ScriptedPort(MAPPING + bytes.fromhex("f0")), threads=False) as robot:
        with pytest.raises(Exception) as caught:
            robot.call_primitive("strict")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "strict: no reply entry for tag 240 then 106")
    with implementation.connect(ScriptedPort(bytes.fromhex("f0")), threads=False) as robot:
        with pytest.raises(Exception) as caught:  # F0 and then nothing: cut short
            robot.call_primitive("strict")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisProtocolError", "strict: expected 1 bytes after tag 240, got 0")


def test_a_nested_table_goes_through_json_the_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(SYSEX, tmp_path, "sysex")
    assert not compilation.diagnostics.items
    listen = next(p for p in json.loads(built)["primitives"] if p["name"] == "listen")
    assert listen["replyTable"]["cases"][1] == {"value": 240, "tag": "B", "cases": [
        {"value": 121, "unpack": "BB*", "until": "\u00f7",
         "postActions": ["major = __out__[0]", "minor = __out__[1]", "sketch = ascii(unpack7(__out__[2]))"]},
        {"value": 113, "unpack": "*", "until": "\u00f7",
         "postActions": ["said = ascii(unpack7(__out__[0]))", "command = tag"]}]}
    printed = print_module(parse("s.rdis", SYSEX, Diagnostics()))
    assert [line for line in printed.splitlines() if "240" in line or line.startswith("        ")][:3] == [
        '    240: tag "B" {',
        '        121: unpack "BB*" until "\\xf7" {',
        "            major = out[0]",
    ]
    assert print_module(parse("s.rdis", printed, Diagnostics())) == printed
    model = compilation.model
    assert model is not None
    shown = dump(model).split("\n\n")[1].rstrip().splitlines()
    start = shown.index("  reply tagged 240 then 121: 5+n bytes")
    assert shown[start:start + 8] == [
        "  reply tagged 240 then 121: 5+n bytes",
        "  offset  size  kind                  value",
        "       0     1  tag u8                = 240",
        "       1     1  tag u8                = 121",
        "       2     1  u8                    out[0]",
        "       3     1  u8                    out[1]",
        "       4     n  bytes (the rest)      out[2]",
        "       ?     1  end (dropped)         F7",
    ]
    # The longest entry: two tags, two bytes, the end (the rest at its shortest).
    assert message_bytes(model.primitives["listen"], model.frames) == 1 + 1 + 2 + 1


NESTED = "a nested tag table is an entry of a tagged reply read without a frame, one level deep: "


def test_what_the_checker_refuses_of_a_nested_table(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
connection link: serial { baud 9600 }
frame ended { request { payload } reply { payload  terminator "\\xFF" } }
primitive framed() on link frame ended pack "B" (1) reply tag "B" { 1: tag "B" { 2: unpack "B" } }
primitive deep() on link format "" () reply tag "B" { 1: tag "B" { 2: tag "B" { 3: unpack "B" } } }
primitive twice() on link format "" () reply tag "B" { 1: tag "B" { 2: unpack "B"  2: unpack "H" } }
primitive wide() on link format "" () reply tag "B" { 1: tag "B" { 300: unpack "B" } }
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E505", f"{NESTED}`framed` reads no tagged reply without a frame"),
        ("E505", f"{NESTED}a nested table holds no nested table"),
        ("E203", "2 has two entries in the reply table"),
        ("E403", "300 does not fit the tag's `B`"),
    ]


def test_rdisc_decode_tells_sub_commands_apart(tmp_path: Path) -> None:
    """Both tags are checked: F0 71 is the STRING_DATA entry, not REPORT_FIRMWARE's."""
    source = tmp_path / "sysex.rdis"
    source.write_text(SYSEX, encoding="utf-8")
    capture = tmp_path / "capture.txt"
    capture.write_text("< f0 71 68 00 f7\n< f0 6a 01 f7\n")
    result = run_rdisc("decode", str(source), str(capture))
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout.splitlines() == [
        "< F0 71 68 00 F7",
        "  reply when  = 113 of listen",
        "  offset  size  kind                  value                         holds         bytes",
        "       0     1  tag u8                = 240                                       F0",
        "       1     1  tag u8                = 113                                       71",
        "       2     2  bytes (the rest)      out[0]                                      68 00",
        "       4     1  end (dropped)         F7                                          F7",
        "< F0 6A 01 F7",
        "  unknown: no primitive's reply is these 4 bytes",
    ]
