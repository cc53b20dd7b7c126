"""`either when COND { } or { }` in a frame's `reply { }`: the reply's layout chosen by settings
passed as the frame's arguments (a Motoron's responses carry a CRC-7 byte unless its protocol
options turned it off). Here: exact bytes read by the runtime and the generated driver for each
setting, E513, the JSON both ways (`replyWhen`), the printer, dump, the budget and decode. The
Motoron itself, on a pty: tests/conformance/test_conformance_motoron.py.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path, compile_text
from rdisc.diagnostics import Diagnostics
from rdisc.semantics.budget import message_bytes
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.conftest import run_rdisc
from tests.engine.test_one_engine import implementation_of, through_json
from tests.runtime.test_layout_conditions import crc7
from tests.support.ports import ScriptedPort

DESCRIPTION = """\
robot motoron { author "tests" }
connection link: serial { baud 115200 }
setting CRC: bool = True
state speed: int = 0
frame command(crc: bool, code: int in 0x80..0xFF) {
    request { field code "B" = code  payload }
    reply {
        either when crc { payload  checksum "crc" "B" width 7 poly 0x09 reflect over payload }
        or { payload }
    }
}
primitive get_speed(motor: int in 1..3) on link
    frame command(CRC, 0x9A) pack "BBB" (motor, 6, 2) unpack "<h" { speed = out[0] }
"""

SPEED = (-300).to_bytes(2, "little", signed=True)


@pytest.fixture(scope="module", params=["runtime", "driver"])
def motoron(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Any]:
    return request.param, implementation_of(request.param, DESCRIPTION, tmp_path_factory.mktemp("motoron"), "motoron")


def _connect(motoron: tuple[str, Any], port: ScriptedPort, crc: bool | None) -> Any:
    kind, implementation = motoron
    settings = {} if crc is None else {"CRC": crc}
    return implementation.connect(port, threads=False, **({"settings": settings} if kind == "runtime" else settings))


@pytest.mark.parametrize(("crc", "reply"), [
    (None, SPEED + bytes([crc7(SPEED)])),  # the setting's default: a CRC byte after the payload
    (True, SPEED + bytes([crc7(SPEED)])),
    (False, SPEED),
])
def test_the_setting_chooses_the_reply_layout(motoron: tuple[str, Any], crc: bool | None, reply: bytes) -> None:
    port = ScriptedPort(reply + b"\x7f")  # a byte after the reply stays unread
    with _connect(motoron, port, crc) as robot:
        robot.call_primitive("get_speed", 2)
        assert robot.state["speed"] == -300
    assert bytes(port.written) == bytes.fromhex("9A 02 06 02")


def test_a_wrong_crc_in_the_chosen_layout_is_a_protocol_error(motoron: tuple[str, Any]) -> None:
    port = ScriptedPort(SPEED + b"\x00")
    with _connect(motoron, port, True) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("get_speed", 2)
    assert (type(caught.value).__name__, str(caught.value)) == (
        "RdisProtocolError", f"get_speed: command: checksum 00 does not match the reply, which sums to {crc7(SPEED):02x}")


def test_no_condition_holding_and_no_plain_layout_is_refused_before_anything_is_sent(tmp_path: Path) -> None:
    text = DESCRIPTION.replace("or { payload }", "or when not crc { payload }")
    port = ScriptedPort(SPEED)
    with implementation_of("runtime", text.replace("setting CRC: bool = True", "setting CRC: int in 0..1 = 0")
                           .replace("crc: bool", "crc: int in 0..1").replace("when crc {", "when crc == 1 {")
                           .replace("when not crc {", "when crc == 2 {"), tmp_path, "m").connect(
                               port, threads=False) as robot, pytest.raises(Exception) as caught:
        robot.call_primitive("get_speed", 2)
    assert (type(caught.value).__name__, str(caught.value)) == (
        "RdisValueError", "get_speed: frame command: no reply layout's condition holds")
    assert bytes(port.written) == b""


def _check(text: str) -> list[tuple[str, str, str, str | None]]:
    compilation = compile_text("t.rdis", text)
    return [(d.code, text[d.span.start:d.span.end], d.message, d.help) for d in compilation.diagnostics.items]


def test_the_description_checks_clean() -> None:
    assert _check(DESCRIPTION) == []


@pytest.mark.parametrize(("change", "expected"), [
    (("frame command(CRC, 0x9A)", "frame command(motor == 1, 0x9A)"), [
        ("E513", "motor == 1", ("the reply's layout is chosen by `crc` of frame `command`, so it is a setting or a "
         "constant, but this reads parameter `motor`"),
         "pass a setting: the device answers as it is configured, which is known when connecting")]),
    (("frame command(CRC, 0x9A)", "frame command(speed == 1, 0x9A)"), [
        ("E513", "speed == 1", ("the reply's layout is chosen by `crc` of frame `command`, so it is a setting or a "
         "constant, but this reads state variable `speed`"),
         "pass a setting: the device answers as it is configured, which is known when connecting")]),
    (("either when crc {", "either when code {"), [("E513", "code", "`when` takes a bool, but this is an int", None)]),
    (("either when crc {", "either {"), [
        ("E507", 'either { payload  checksum "crc" "B" width 7 poly 0x09 reflect over payload }\n        or { payload }',
         "alternative 1 of frame `command` starts with no `header`",
         "a reader knows which alternative came by its header: start each with its own")]),
])
def test_e513_asks_for_settings_and_bools(change: tuple[str, str], expected: list[Any]) -> None:
    assert _check(DESCRIPTION.replace(*change)) == expected


def test_the_constant_argument_is_a_known_configuration() -> None:
    assert _check(DESCRIPTION.replace("frame command(CRC, 0x9A)", "frame command(False, 0x9A)")) == []


def test_the_json_reads_back_to_the_same_model(tmp_path: Path) -> None:
    _, built = through_json(DESCRIPTION, tmp_path, "motoron")
    frame = json.loads(built)["frames"][0]
    assert frame["replyWhen"] == ["<crc>", None]
    assert "requestWhen" not in frame
    assert [len(layout) for layout in (frame["reply"], *frame["moreReplies"])] == [2, 1]


@pytest.mark.parametrize(("when", "expected"), [
    (["<crc>"], [("E008", "`replyWhen` has 1 condition for 2 reply layouts")]),
    ([None, "<crc>"], [
        ("E513", "alternative 1 has no `when`, but alternatives chosen by size and by a condition cannot be mixed")]),
])
def test_a_wrong_reply_when_in_json_is_a_diagnostic(tmp_path: Path, when: Any, expected: Any) -> None:
    _, built = through_json(DESCRIPTION, tmp_path, "motoron")
    document = json.loads(built)
    document["frames"][0]["replyWhen"] = when
    (tmp_path / "wrong.json").write_text(json.dumps(document), encoding="utf-8")
    found = compile_path(str(tmp_path / "wrong.json")).diagnostics.items
    assert [(d.code, d.message) for d in found] == expected


def test_the_printer_writes_the_conditions_back() -> None:
    module = parse("motoron.rdis", DESCRIPTION, Diagnostics())
    printed = print_module(module)
    assert 'either when crc { payload  checksum "crc" "B" width 7 poly 9 reflect over payload } or { payload }' \
        in printed
    assert parse("motoron.rdis", printed, Diagnostics()) == module


def test_dump_shows_the_condition_before_each_reply_layout(tmp_path: Path) -> None:
    source = tmp_path / "motoron.rdis"
    source.write_text(DESCRIPTION, encoding="utf-8")
    heads = [line for line in run_rdisc("dump", source).stdout.splitlines() if line.startswith("  reply")]
    assert heads == ["  reply, alternative 1, when crc: 3 bytes", "  reply, alternative 2, when none holds: 2 bytes"]


def test_the_budget_counts_the_longest_reply_a_setting_may_choose() -> None:
    model = compile_text("motoron.rdis", DESCRIPTION).model
    assert model is not None
    assert message_bytes(model.primitives["get_speed"], model.frames) == 4 + 3  # the request; the speed, its CRC


def test_decode_reads_a_reply_in_each_layout_and_refuses_a_wrong_crc(tmp_path: Path) -> None:
    source, capture = tmp_path / "motoron.rdis", tmp_path / "capture.txt"
    source.write_text(DESCRIPTION, encoding="utf-8")
    with_crc = SPEED + bytes([crc7(SPEED)])
    capture.write_text(f"> 9A 02 06 02\n< {with_crc.hex(' ')}\n> 9A 02 06 02\n< {SPEED.hex(' ')}\n"
                       f"> 9A 02 06 02\n< {SPEED.hex(' ')} 00\n", encoding="utf-8")
    shown = [line.strip() for line in run_rdisc("decode", source, capture).stdout.splitlines()]
    assert [line for line in shown if line.startswith(("<", "reply", "unknown"))] == [
        f"< {with_crc.hex(' ').upper()}", "reply of get_speed", f"< {SPEED.hex(' ').upper()}", "reply of get_speed",
        f"< {SPEED.hex(' ').upper()} 00", "unknown: no primitive's reply is these 3 bytes"]


def test_the_same_choice_each_way_reads_back_as_two_sides(tmp_path: Path) -> None:
    """Equal `request` and `reply` in JSON are one list of parts for both directions, unless a condition
    chooses their layouts (`when` is refused in parts for both directions)."""
    both = '{ either when crc { payload  checksum "crc" "B" width 7 poly 0x09 reflect over payload } or { payload } }'
    text = DESCRIPTION.replace("request { field code \"B\" = code  payload }", f"request {both}") \
        .replace('pack "BBB" (motor, 6, 2)', 'pack "BBB" (0x9A, motor, 6)')
    assert _check(text) == []
    _, built = through_json(text, tmp_path, "both")
    frame = json.loads(built)["frames"][0]
    assert frame["request"] == frame["reply"] and frame["requestWhen"] == frame["replyWhen"] == ["<crc>", None]
