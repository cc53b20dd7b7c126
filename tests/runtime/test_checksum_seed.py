"""`seed TABLE[FIELD]`: a byte a lookup table holds for a frame field's value, summed after a
checksum's bytes and never sent (MAVLink 2's CRC_EXTRA; tests/conformance/test_conformance_mavlink.py
holds it against pymavlink). Here: the checker's E512, the JSON both ways, the printer, `rdisc dump`,
and a field value the table lacks, in the runtime and the generated driver alike.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path, compile_text
from rdisc.diagnostics import Diagnostics
from rdisc.diagnostics.codes import CODES
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.conftest import run_rdisc
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

DESCRIPTION = """\
robot seeded { author "tests" }
state echoed: int = 0
connection link: serial { baud 57600 }
/// a byte per message id, summed last, never sent
const EXTRAS = { 1: 50, 2: 124 }
frame tagged(id: int in 0..255) {
    request { header "\\xFD"  field id "B" = id  payload  checksum "crc16-mcrf4xx" "<H" seed EXTRAS[id] }
    reply { header "\\xFD"  field id "B" = id  payload  checksum "crc16-mcrf4xx" "<H" seed EXTRAS[id] }
}
primitive send(message: int in 0..255, value: int in 0..255) on link frame tagged(message) pack "B" (value)
    unpack "B" { echoed = out[0] }
primitive first(value: int in 0..255) on link frame tagged(1) pack "B" (value)
"""


HEARTBEAT = """\
robot heartbeat { author "tests" }
connection serial0: serial { baud 57600 }
/// MAVLink 2's COMMAND_LONG (76, CRC_EXTRA 152) and HEARTBEAT (0, CRC_EXTRA 50).
const CRC_EXTRA = { 0: 50, 76: 152 }
frame mavlink(message: int in 0..65535) {
    header "\\xFD"  length "B" = payload  literal "\\x00\\x00\\x00\\xFF\\xBE"  field message "<H" = message
    literal "\\x00"  payload trimmed  checksum "CRC-16/MCRF4XX" "<H" seed CRC_EXTRA[message]
}
primitive heartbeat() on serial0 frame mavlink(0) pack "<IBBBBB" (0, 6, 8, 0, 0, 3)
"""


def crc_mcrf4xx(data: bytes) -> bytes:
    crc = 0xFFFF
    for byte in data:
        t = (byte ^ crc) & 0xFF
        t = (t ^ (t << 4)) & 0xFF
        crc = ((crc >> 8) ^ (t << 8) ^ (t << 3) ^ (t >> 4)) & 0xFFFF
    return crc.to_bytes(2, "little")


@pytest.fixture(scope="module", params=["runtime", "driver"])
def seeded(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, DESCRIPTION, tmp_path_factory.mktemp("seeded"), "seeded")


@pytest.mark.parametrize(("message", "seed"), [(1, 50), (2, 124)])
def test_the_seed_of_the_fields_value_is_summed_and_not_sent(seeded: Any, message: int, seed: int) -> None:
    port = ScriptedPort(b"\xFD" + bytes([message, 9]) + crc_mcrf4xx(bytes([message, 9, seed])))
    with seeded.connect(port, threads=False) as robot:
        robot.call_primitive("send", message, 7)
        assert bytes(port.written) == b"\xFD" + bytes([message, 7]) + crc_mcrf4xx(bytes([message, 7, seed]))
        assert robot.state["echoed"] == 9


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_constant_request_is_seeded_too(kind: str, tmp_path: Path) -> None:
    """docs/language.md's HEARTBEAT: no parameters, so the whole request is worked out once;
    the bytes are pymavlink 2.4.41's for MAVLink_heartbeat_message(6, 8, 0, 0, 0, 3) from 255/190."""
    port = ScriptedPort(b"")
    with implementation_of(kind, HEARTBEAT, tmp_path, "heartbeat").connect(port, threads=False) as robot:
        robot.call_primitive("heartbeat")
    assert bytes(port.written).hex(" ").upper() == "FD 09 00 00 00 FF BE 00 00 00 00 00 00 00 06 08 00 00 03 5C 2B"


def test_a_request_framed_once_with_constant_arguments_is_seeded(seeded: Any) -> None:
    port = ScriptedPort(b"\xFD\x01\x09" + crc_mcrf4xx(bytes([1, 9, 50])))
    with seeded.connect(port, threads=False) as robot:
        robot.call_primitive("first", 7)
    assert bytes(port.written) == b"\xFD\x01\x07" + crc_mcrf4xx(bytes([1, 7, 50]))


def test_a_value_the_table_lacks_is_refused_before_anything_is_sent(seeded: Any) -> None:
    port = ScriptedPort(b"")
    with seeded.connect(port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("send", 3, 7)
    assert (type(caught.value).__name__, str(caught.value)) == (
        "RdisValueError", "send: the checksum's seed table has no entry for 3")
    assert bytes(port.written) == b""


def test_the_json_reads_back_to_the_same_model(tmp_path: Path) -> None:
    _, built = through_json(DESCRIPTION, tmp_path, "seeded")
    frame = json.loads(built)["frames"][0]
    assert [part.get("seed") for part in (*frame["request"], *frame["reply"]) if "checksum" in part] == [
        {"table": "EXTRAS", "field": "id"}] * 2


@pytest.mark.parametrize(("seed", "expected"), [
    ({"table": "EXTRAS"}, [("E008", 'a checksum\'s `seed` is {"table": NAME, "field": NAME}')]),
    ("EXTRAS[id]", [("E008", 'a checksum\'s `seed` is {"table": NAME, "field": NAME}')]),
    ({"table": "EXTRAS", "field": "id", "byte": 1}, [("E008", "unknown member `byte` in a checksum's seed")]),
    ({"table": "EXTRA", "field": "id"}, [("E512", "`EXTRA` is no lookup table")]),
])
def test_a_wrong_seed_in_json_is_a_diagnostic(tmp_path: Path, seed: Any, expected: list[tuple[str, str]]) -> None:
    _, built = through_json(DESCRIPTION, tmp_path, "seeded")
    document = json.loads(built)
    document["frames"][0]["request"][-1]["seed"] = seed
    (tmp_path / "wrong.json").write_text(json.dumps(document), encoding="utf-8")
    found = compile_path(str(tmp_path / "wrong.json")).diagnostics.items
    assert [(d.code, d.message) for d in found] == expected


def test_the_printer_writes_the_seed_back() -> None:
    module = parse("seeded.rdis", DESCRIPTION, Diagnostics())
    printed = print_module(module)
    assert 'checksum "crc16-mcrf4xx" "<H" seed EXTRAS[id]' in printed
    assert parse("seeded.rdis", printed, Diagnostics()) == module


def test_dump_shows_the_seed(tmp_path: Path) -> None:
    source = tmp_path / "seeded.rdis"
    source.write_text(DESCRIPTION, encoding="utf-8")
    assert "crc16-mcrf4xx as <H, over id .. payload, then EXTRAS[id] (not sent)" in run_rdisc("dump", source).stdout


def test_decode_knows_a_seeded_frame_and_not_one_without_its_seed(tmp_path: Path) -> None:
    source, capture = tmp_path / "heartbeat.rdis", tmp_path / "capture.txt"
    source.write_text(HEARTBEAT, encoding="utf-8")
    frame = "FD 09 00 00 00 FF BE 00 00 00 00 00 00 00 06 08 00 00 03"
    unseeded = crc_mcrf4xx(bytes.fromhex(frame)[1:]).hex(" ").upper()
    capture.write_text(f"> {frame} 5C 2B\n> {frame} {unseeded}\n", encoding="utf-8")
    shown = run_rdisc("decode", source, capture).stdout.splitlines()
    assert [line.strip() for line in shown if not line.startswith("   ")] == [
        f"> {frame} 5C 2B", "request heartbeat", "offset  size  kind" + " " * 18 + "value" + " " * 25 + "holds"
        + " " * 9 + "bytes", f"> {frame} {unseeded}", "unknown: no primitive's request is these 21 bytes"]


def _check(table: str, seed: str) -> list[tuple[str, str, str, str | None]]:
    text = ('robot t { author "tests" }\nconnection link: serial { baud 9600 }\n'
            f"const NAMES = {{ \"a\": 1 }}\nconst {table}\n"
            f'frame f(id: int in 0..255) {{ field id "B" = id  payload  checksum "crc16-mcrf4xx" "<H" {seed} }}\n'
            'primitive p() on link frame f(1) pack "B" (1)\n')
    compilation = compile_text("t.rdis", text)
    return [(d.code, text[d.span.start:d.span.end], d.message, d.help) for d in compilation.diagnostics.items]


@pytest.mark.parametrize(("table", "seed", "expected"), [
    ("EXTRAS = { 1: 50 }", "seed EXTRAS[id]", []),
    ("EXTRAS = { 1: 50 }", "seed EXTRA[id]", [("E512", "EXTRA", "`EXTRA` is no lookup table", "did you mean `EXTRAS`?")]),
    ("EXTRAS = { 1: 50 }", "seed EXTRAS[ids]", [
        ("E512", "ids", "`ids` is no `field` of this side of the frame: a seed is keyed by a field the frame carries",
         "did you mean `id`?")]),
    ("EXTRAS = { 1: 256 }", "seed EXTRAS[id]", [
        ("E512", "EXTRAS", "`EXTRAS[1]` is 256: a seed is one byte, 0 to 255", None)]),
    ("EXTRAS = { 1: 0.5 }", "seed EXTRAS[id]", [
        ("E512", "EXTRAS", "`EXTRAS` holds values that are not integers: a seed is one byte, 0 to 255", None)]),
    ("EXTRAS = { 1: 50 }", "seed NAMES[id]", [
        ("E512", "NAMES", "`NAMES` is keyed by strings, not by a field's integers", None)]),
])
def test_e512_refuses_a_seed_at_its_words(table: str, seed: str, expected: list[Any]) -> None:
    assert _check(table, seed) == expected


def test_e512_explains_the_rules_the_checker_applies() -> None:
    explain = " ".join(CODES["E512"].explanation.split())
    for words in ("a lookup table declared with `const`, keyed by integers", "0 to 255",
                  "names a `field` of the side the checksum is on", "`RdisValueError`"):
        assert words in explain


def test_w501_warns_of_a_message_the_seed_table_lacks() -> None:
    """A frame argument that is a constant gives the seed field a value known when checking: a
    table without it is warned of (the request would be an RdisValueError when framed)."""
    assert _check("EXTRAS = { 2: 50 }", "seed EXTRAS[id]") == [
        ("W501", "frame f(1)", ("`p` frames id 1 with `f`, but its seed table `EXTRAS` has no entry for 1: its request "
         "cannot be framed (an RdisValueError)"), "add the message's byte to the table: `1: ...` in `EXTRAS`")]
    assert CODES["W501"].name == "unseeded-message"


def test_w501_is_silent_where_the_value_is_known_only_at_run_time() -> None:
    """`send`'s message id is its parameter (checked when framed); `first`'s, 1, is in the table."""
    assert [d.code for d in compile_text("seeded.rdis", DESCRIPTION).diagnostics.items] == []
