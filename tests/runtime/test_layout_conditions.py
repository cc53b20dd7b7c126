"""`either when COND { } or when COND { } or { }`: a request's layout chosen by a condition over the
frame's parameters, so a setting passed as the frame's argument picks the framing (Pololu's Maestro
speaks its compact protocol, the Pololu protocol, or that with a CRC-7 byte). Here: exact bytes in
the runtime and the generated driver for each setting, E513, the JSON both ways, the printer, dump.
A reply's layout so chosen: tests/runtime/test_reply_layout_conditions.py.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path, compile_text
from rdisc.diagnostics import Diagnostics
from rdisc.diagnostics.codes import CODES
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.conftest import run_rdisc
from tests.engine.test_one_engine import implementation_of, through_json
from tests.support.pololu import crc7
from tests.support.ports import ScriptedPort

DESCRIPTION = """\
robot maestro { author "tests" }
connection link: serial { baud 9600 }
/// 0: the compact protocol, 1: the Pololu protocol, 2: the Pololu protocol with a CRC-7 byte
setting PROTOCOL: int in 0..2 = 0
setting DEVICE: int in 0..127 = 12
frame pololu(mode: int in 0..2, device: int in 0..127, command: int in 0..255) {
    request {
        either when mode == 0 { field command "B" = command  payload }
        or when mode == 1 { header "\\xAA"  field device "B" = device  field command "B" = command & 0x7F  payload }
        or { header "\\xAA"  field device "B" = device  field command "B" = command & 0x7F  payload
             checksum "crc" "B" width 7 poly 0x09 reflect over header .. payload }
    }
}
primitive set_target(channel: int in 0..23, target: int in 0..16383) on link
    frame pololu(PROTOCOL, DEVICE, 0x84) pack "BBB" (channel, target & 0x7F, target >> 7)
"""



def test_the_reference_crc7_gives_the_guides_example() -> None:
    assert crc7(bytes([0x83, 0x01])) == 0x17


@pytest.fixture(scope="module", params=["runtime", "driver"])
def maestro(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Any]:
    return request.param, implementation_of(request.param, DESCRIPTION, tmp_path_factory.mktemp("maestro"), "maestro")


POLOLU = bytes.fromhex("AA 0C 04 02 70 2E")


@pytest.mark.parametrize(("protocol", "expected"), [
    (None, bytes.fromhex("84 02 70 2E")),  # the setting's default: the compact protocol
    (0, bytes.fromhex("84 02 70 2E")),
    (1, POLOLU),
    (2, POLOLU + bytes([crc7(POLOLU)])),
])
def test_the_setting_chooses_the_layout(maestro: tuple[str, Any], protocol: int | None, expected: bytes) -> None:
    kind, implementation = maestro
    settings = {} if protocol is None else {"PROTOCOL": protocol}
    port = ScriptedPort(b"")
    given = {"settings": settings} if kind == "runtime" else settings
    with implementation.connect(port, threads=False, **given) as robot:
        robot.call_primitive("set_target", 2, 6000)
    assert bytes(port.written) == expected
    if protocol == 2:
        assert expected[-1] == 0x11


def _alone(layouts: str, params: str = "mode: int in 0..2", args: str = "0") -> str:
    return ('robot t { author "tests" }\nconnection link: serial { baud 9600 }\n'
            f"frame f({params}) {{ {layouts} }}\n"
            f'primitive p() on link frame f({args}) pack "B" (1)\n')


def _check(text: str) -> list[tuple[str, str, str, str | None]]:
    compilation = compile_text("t.rdis", text)
    return [(d.code, text[d.span.start:d.span.end], d.message, d.help) for d in compilation.diagnostics.items]


def test_a_plain_last_alternative_is_taken_when_none_holds_and_without_one_a_call_is_refused(tmp_path: Path) -> None:
    text = _alone('request { either when mode == 1 { header "\\x01"  payload } or when mode == 2 { payload } }',
                  args="MODE").replace("connection link", "setting MODE: int in 0..2 = 0\nconnection link")
    assert _check(text) == []
    port = ScriptedPort(b"")
    with implementation_of("runtime", text, tmp_path, "t").connect(port, threads=False) as robot, \
            pytest.raises(Exception) as caught:
        robot.call_primitive("p")
    assert (type(caught.value).__name__, str(caught.value)) == (
        "RdisValueError", "p: frame f: no layout's condition holds")
    assert bytes(port.written) == b""


@pytest.mark.parametrize(("layouts", "expected"), [
    ('request { either { payload } or when mode == 1 { header "\\xAA"  payload } }', [
        ("E513", 'either { payload } or when mode == 1 { header "\\xAA"  payload }',
         "alternative 1 has no `when`, but alternatives chosen by size and by a condition cannot be mixed",
         "give every alternative a `when`, except a plain last one, taken when none holds")]),
    ('request { either when mode { payload } or { header "\\xAA"  payload } }', [
        ("E513", "mode", "`when` takes a bool, but this is an int", None)]),
    ('request { either when speed == 1 { payload } or { header "\\xAA"  payload } }', [
        ("E103", "speed", "unknown name `speed` in a frame", None)]),
    ('either when mode == 1 { header "\\x01"  payload } or { header "\\x02"  payload }', [
        ("E513", 'either when mode == 1 { header "\\x01"  payload } or { header "\\x02"  payload }',
         "parts written for both directions cannot be chosen by `when`",
         "give the frame a `request { }` and a `reply { }`, each with its own `either when`")]),
])
def test_e513_refuses_a_condition_at_its_words(layouts: str, expected: list[Any]) -> None:
    assert _check(_alone(layouts)) == expected


def test_e513_explains_the_rules_the_checker_applies() -> None:
    assert CODES["E513"].name == "layout-condition"
    explain = " ".join(CODES["E513"].explanation.split())
    for words in ("the first alternative whose condition holds", "Each COND is a bool",
                  "Only the last alternative may go without `when`", "`when` is refused in a frame's parts written for both"):
        assert words in explain


def test_the_json_reads_back_to_the_same_model(tmp_path: Path) -> None:
    _, built = through_json(DESCRIPTION, tmp_path, "maestro")
    frame = json.loads(built)["frames"][0]
    assert frame["requestWhen"] == ["<mode == 0>", "<mode == 1>", None]
    assert [len(layout) for layout in (frame["request"], *frame["moreRequests"])] == [2, 4, 5]


def test_json_without_request_when_chooses_by_size(tmp_path: Path) -> None:
    """Without `requestWhen` the layouts are chosen by the payload's size, and the first, with no
    length field, would carry every payload: E507 says the others are never written."""
    _, built = through_json(DESCRIPTION, tmp_path, "maestro")
    document = json.loads(built)
    del document["frames"][0]["requestWhen"]
    (tmp_path / "sized.json").write_text(json.dumps(document), encoding="utf-8")
    found = compile_path(str(tmp_path / "sized.json")).diagnostics.items
    assert [(d.code, d.message) for d in found] == [
        ("E507", ("alternative 2 of frame `pololu` is never written: alternative 1 has no length field, so it "
                  "carries every payload"))]


@pytest.mark.parametrize(("when", "expected"), [
    ([None, "<mode == 1>", None], [
        ("E513", "alternative 1 has no `when`, but alternatives chosen by size and by a condition cannot be mixed")]),
    (["<mode == 0>", None], [("E008", "`requestWhen` has 2 conditions for 3 request layouts")]),
    (["<mode == 0>", "<mode == 1>", "<mode == 2>", None], [
        ("E008", "`requestWhen` has 4 conditions for 3 request layouts")]),
])
def test_a_wrong_request_when_in_json_is_a_diagnostic(tmp_path: Path, when: Any, expected: Any) -> None:
    _, built = through_json(DESCRIPTION, tmp_path, "maestro")
    document = json.loads(built)
    document["frames"][0]["requestWhen"] = when
    (tmp_path / "wrong.json").write_text(json.dumps(document), encoding="utf-8")
    found = compile_path(str(tmp_path / "wrong.json")).diagnostics.items
    assert [(d.code, d.message) for d in found] == expected


def test_request_when_for_one_layout_is_a_diagnostic(tmp_path: Path) -> None:
    _, built = through_json(DESCRIPTION, tmp_path, "maestro")
    document = json.loads(built)
    del document["frames"][0]["moreRequests"]
    document["frames"][0]["requestWhen"] = ["<mode == 0>"]
    (tmp_path / "one.json").write_text(json.dumps(document), encoding="utf-8")
    found = compile_path(str(tmp_path / "one.json")).diagnostics.items
    assert [(d.code, d.message) for d in found] == [("E008", "`requestWhen` has 1 condition for 1 request layout")]


def test_the_printer_writes_the_conditions_back() -> None:
    module = parse("maestro.rdis", DESCRIPTION, Diagnostics())
    printed = print_module(module)
    assert "either when mode == 0 { field command \"B\" = command  payload } or when mode == 1 { header" in printed
    assert "or { header \"\\xaa\"" in printed
    assert parse("maestro.rdis", printed, Diagnostics()) == module


def test_dump_shows_the_condition_before_each_layout(tmp_path: Path) -> None:
    source = tmp_path / "maestro.rdis"
    source.write_text(DESCRIPTION, encoding="utf-8")
    heads = [line for line in run_rdisc("dump", source).stdout.splitlines() if line.startswith("  request")]
    assert heads == ["  request, alternative 1, when mode == 0: 4 bytes", "  request, alternative 2, when mode == 1: 6 bytes",
                     "  request, alternative 3, when none holds: 7 bytes"]


def test_every_layout_a_condition_may_choose_must_state_the_payload() -> None:
    """Chosen by size, the layout without a length field takes the long payloads; chosen by a
    condition, the one with a length field may be written whatever the payload: E503."""
    def check(head: str) -> list[tuple[str, str, str, str | None]]:
        return _check(_alone(
            f'request {{ {head} {{ header "\\x01"  length "B" = payload  payload }} or {{ payload  terminator "\\n" }} }}',
            "mode: int in 0..1", "MODE").replace("connection link", "setting MODE: int in 0..1 = 0\nconnection link")
            .replace('pack "B" (1)', 'pack "B*" (1, data)').replace("primitive p()", "primitive p(data: bytes in 0..400)"))

    assert check("either") == []
    assert check("either when mode == 0") == [(
        "E503", "frame f(MODE)", ("the length field \"B\" of frame `f` cannot state every payload of `p`: 1 to 401 "
                                  "bytes, as parameter `data` allows"),
        "it states payloads of 0 to 255 bytes; narrow the range of parameter `data`")]


def test_the_budget_counts_the_longest_layout_a_setting_may_choose() -> None:
    model = compile_text("maestro.rdis", DESCRIPTION).model
    assert model is not None
    assert message_bytes(model.primitives["set_target"], model.frames) == 7  # AA 0C 04, 3 bytes, the CRC-7


def test_decode_knows_a_request_in_each_layout(tmp_path: Path) -> None:
    source, capture = tmp_path / "maestro.rdis", tmp_path / "capture.txt"
    source.write_text(DESCRIPTION, encoding="utf-8")
    capture.write_text("> 84 02 70 2E\n> AA 0C 04 02 70 2E\n> AA 0C 04 02 70 2E 11\n", encoding="utf-8")
    shown = [line.strip() for line in run_rdisc("decode", source, capture).stdout.splitlines()]
    assert [line for line in shown if line.startswith((">", "request", "unknown"))] == [
        "> 84 02 70 2E", "request set_target", "> AA 0C 04 02 70 2E", "request set_target",
        "> AA 0C 04 02 70 2E 11", "request set_target"]
    assert "6     1  checksum              crc width 7 poly 0x9 reflect as B, over header .. payload                11" in shown
