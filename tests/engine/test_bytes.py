"""Bytes as values: state holds them (`state firmware: bytes`), `b"..."` writes them, and
`hex`, `ascii`, `encode`, `pack7`, `unpack7`, `+` and `==` work on them, in the runtime and a
generated driver alike (the driver carries the functions' text from rdisc.engine.operations);
constants are folded and refused at check time; all of it travels through JSON and the printer."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.emit.dump import dump
from rdisc.engine import carry
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

# Firmata (protocol 2.x): a sysex message is F0, a command, 7-bit data, F7. REPORT_FIRMWARE (0x79)
# answers with the version and the sketch's name, each character as two 7-bit bytes (low 7 bits,
# then bit 7); STRING_DATA (0x71) carries text the same way.
FIRMATA = """\
robot firmata { author "tests" }
const QUERY = b"\\x79"
state firmware: bytes
state name: string
state digits: string
state major: int
state greeting: bytes = b"hi"
connection link: serial { baud 57600 }
frame sysex { header "\\xf0" payload terminator "\\xf7" }
primitive sysex_raw(data: bytes in 0..16) on link pack "*" (data) frame sysex
primitive report_firmware() on link pack "*" (QUERY) frame sysex unpack "BBB*" {
    major = out[1]
    firmware = out[3]
    name = ascii(unpack7(out[3]))
    digits = hex(unpack7(out[3]))
}
primitive string_data(text: bytes) on link pack "B*" (0x71, text) frame sysex
interface say(text: string) { string_data(pack7(encode(text))) }
interface nothing() { sysex_raw(b"") sysex_raw(QUERY + b"\\x01") }
interface greet() { string_data(pack7(greeting)) when greeting == b"hi" and firmware != b"" }
"""

REPLY = bytes.fromhex("f0 79 02 05 53 00 74 00 64 00 f7")  # version 2.5, "Std"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_bytes_are_written_stored_and_turned_into_text(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort(REPLY)
    with implementation_of(kind, FIRMATA, tmp_path, "firmata").connect(port, threads=False) as robot:
        assert robot.state["greeting"] == b"hi" and robot.state["firmware"] == b""
        robot.call_interface("greet")  # firmware is empty: no call
        robot.call_interface("nothing")
        assert bytes(port.written).hex(" ") == "f0 f7 f0 79 01 f7"
        port.written.clear()
        robot.call_primitive("report_firmware")
        assert bytes(port.written).hex(" ") == "f0 79 f7"
        assert robot.state["major"] == 2
        assert robot.state["firmware"] == b"S\x00t\x00d\x00"
        assert (robot.state["name"], robot.state["digits"]) == ("Std", "537464")
        port.written.clear()
        robot.call_interface("say", "ok")
        robot.call_interface("greet")
        assert bytes(port.written).hex(" ") == "f0 71 6f 00 6b 00 f7 f0 71 68 00 69 00 f7"


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_what_cannot_be_converted_is_refused_before_anything_is_written(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, FIRMATA, tmp_path, "firmata").connect(port, threads=False) as robot:
        with pytest.raises(ValueError) as caught:
            robot.call_interface("say", "café")
        assert (type(caught.value).__name__, str(caught.value)) == (
            "RdisValueError", "say: encode(): character 3 is 'é', not ASCII")
        assert bytes(port.written) == b""


@pytest.mark.parametrize(("reply", "message"), [
    ("f0 79 02 05 53 00 74 f7", "report_firmware: unpack7(): an odd number of bytes (3), not pairs of 7-bit bytes"),
    ("f0 79 02 05 53 02 f7", "report_firmware: unpack7(): bytes 0 and 1 make 339, more than a byte"),
    ("f0 79 02 05 53 00 ff 01 f7", "report_firmware: unpack7(): byte 2 has bit 7 set, not a 7-bit byte"),
    ("f0 79 02 05 53 00 7f 01 f7", "report_firmware: ascii(): byte 1 is 0xff, not ASCII"),
])
@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_reply_that_does_not_decode_is_an_error(kind: str, reply: str, message: str, tmp_path: Path) -> None:
    port = ScriptedPort(bytes.fromhex(reply))
    with implementation_of(kind, FIRMATA, tmp_path, "firmata").connect(port, threads=False) as robot:
        with pytest.raises(ValueError) as caught:
            robot.call_primitive("report_firmware")
        assert (type(caught.value).__name__, str(caught.value)) == ("RdisValueError", message)
        assert robot.state["firmware"] == b""  # no post-action of a failed reply is kept


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_bytes_built_at_run_time_are_bounded(kind: str, tmp_path: Path) -> None:
    text = FIRMATA + """\
interface twice(data: bytes) { string_data(data + data) }
interface packed(data: bytes) { string_data(pack7(data)) }
"""
    port = ScriptedPort()
    with implementation_of(kind, text, tmp_path, "bounded").connect(port, threads=False) as robot:
        robot.call_interface("twice", b"\x01")
        assert bytes(port.written).hex(" ") == "f0 71 01 01 f7"
        with pytest.raises(ValueError) as caught:
            robot.call_interface("twice", bytes(600_000))
        assert str(caught.value) == "twice: more than 1048576 bytes"
        with pytest.raises(ValueError) as caught:
            robot.call_interface("packed", bytes(600_000))
        assert str(caught.value) == "packed: pack7(): 600000 bytes make more than 1048576 bytes"
        assert bytes(port.written).hex(" ") == "f0 71 01 01 f7"


def test_constants_are_folded_at_check_time(tmp_path: Path) -> None:
    source = tmp_path / "consts.rdis"
    source.write_text("""\
robot consts { author "tests" }
const HELLO = encode("hello")
const SIZE = len(HELLO + b"\\r\\n")
const PACKED = pack7(b"\\xff\\x01")
const TEXT = ascii(unpack7(b"o\x00k\x00"))
const SAME = PACKED == b"\x7f\x01\x01\x00" and hex(HELLO) == "68656c6c6f"
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None, [d.message for d in compilation.diagnostics.items]
    assert dict(compilation.model.constants) == {
        "HELLO": b"hello", "SIZE": 7, "PACKED": b"\x7f\x01\x01\x00", "TEXT": "ok", "SAME": True}


def test_what_the_checker_refuses(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
const A = ascii(b"\\xff")
const B = unpack7(b"\\x01")
const C = hex(1)
const D = encode(b"x")
const E = b"a" + "a"
const F = b"a" < b"b"
state s: bytes = "text"
adapter Blob { data: bytes }
connection link: serial { baud 9600 }
primitive send(data: bytes in 1..2) on link pack "*" (data)
interface i() { send(b"") send(b"abc") send(b"ab") }
primitive say(data: bytes) on link format "{}{:>4}" (data, data)
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E105", "an adapter field cannot be bytes"),
        ("E401", "state variable `s` takes bytes, but this is a string"),
        ("E405", "ascii(): byte 0 is 0xff, not ASCII"),
        ("E405", "unpack7(): an odd number of bytes (1), not pairs of 7-bit bytes"),
        ("E404", "`hex` needs bytes, not an int"),
        ("E404", "`encode` needs a string, not bytes"),
        ("E404", "`+` needs two numbers, two strings or two bytes, not bytes and a string"),
        ("E404", "`<` compares two numbers or two strings, not bytes and bytes"),
        ("E401", "format field `{}` cannot format bytes"),  # fuzzer, seed 43: was an internal error
        ("E401", "format field `{:>4}` cannot format bytes"),
        ("E403", 'b"" (0 bytes) is outside the range of parameter `data` of primitive `send`'),
        ("E403", 'b"abc" (3 bytes) is outside the range of parameter `data` of primitive `send`'),
        ("W103", "state variable `s` is never used"),
    ]


def test_a_bytes_literal_is_ascii_and_escapes(tmp_path: Path) -> None:
    diagnostics = Diagnostics()
    parse("t.rdis", 'const A = b"\\x00\\n\\\\ok"\nconst B = b"caf\u00e9\\u00e9"\n', diagnostics)
    assert [(d.code, d.message, d.help) for d in diagnostics.items] == [
        ("E004", "`\u00e9` in bytes is not ASCII", "write the bytes it stands for as escapes: `\\xc3\\xa9` in UTF-8"),
        ("E003", "unknown escape `\\u00e9` in bytes",
         'bytes are ASCII characters and the escapes `\\xHH`, `\\n`, `\\r`, `\\t`, `\\0`, `\\\\` and `\\"`'),
    ]


def test_bytes_go_through_json_and_the_printer(tmp_path: Path) -> None:
    compilation, built = through_json(FIRMATA, tmp_path, "firmata")
    assert not compilation.diagnostics.items
    assert '"QUERY": "<b\\"y\\">"' in built  # bytes that are all text print as text
    assert '"value": "<b\\"hi\\">"' in built and '"value": "<b\\"\\">"' in built
    assert '"<pack7(encode(text))>"' in built and '"when": "<greeting == b\\"hi\\" and firmware != b\\"\\">"' in built
    module = parse("t.rdis", FIRMATA, Diagnostics())
    printed = print_module(module)
    assert 'const QUERY = b"y"\n' in printed
    assert "sysex_raw(QUERY + b\"\\x01\")" in printed
    assert print_module(parse("t.rdis", printed, Diagnostics())) == printed
    assert module == parse("t.rdis", printed, Diagnostics())


def test_a_driver_carries_the_functions_as_written_once(tmp_path: Path) -> None:
    driver = implementation_of("driver", FIRMATA, tmp_path, "firmata_source")
    text = Path(driver.__file__).read_text(encoding="utf-8")
    assert carried_text() in text and "def _unpack7(data: bytes) -> bytes:" in carried_text()
    assert "return [_pack7(_encode(text))]" in text


def test_constant_bytes_have_their_size_in_the_dump_and_the_budget(tmp_path: Path) -> None:
    source = tmp_path / "firmata.rdis"
    source.write_text(FIRMATA, encoding="utf-8")
    model = compile_path(str(source)).model
    assert model is not None
    assert """\
primitive report_firmware() on link, frame sysex()
  request: 3 bytes
  offset  size  kind                  value
       0     1  header                F0
       1     1  payload bytes (the rest)  79
       2     1  terminator            F7
""" in dump(model)
    assert message_bytes(model.primitives["report_firmware"], model.frames) == 3 + 5


def carried_text() -> str:
    """The operations' section of the carried engine: the module's body, as a driver carries it."""
    return next(part for part in carry.sections() if part.module == "operations").body
