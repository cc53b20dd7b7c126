"""`expect COND`: a reply must meet a condition on its decoded values (RPLIDAR's scan nodes
carry a check bit that must be the inverse of another). A reply that does not is refused
like one that does not decode: an RdisProtocolError, or read past under `skip unmatched`;
alike in the runtime and a generated driver."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from rdisc.compile import compile_path
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

NODES = """\
robot nodes { author "tests" }
state quality: int = 0
frame node { header "\\xA5"  payload  checksum "xor" "B" }
connection link: serial { baud 115200 }
/// A scan node: bit 0 of the first byte is the start flag, and must differ from bit 0 of the second.
primitive scan() on link frame node pack "B" (0x20) unpack "BB" skip unmatched timeout 100 ms
    expect out[0] & 1 != out[1] & 1 { quality = out[0] >> 1 }
primitive echo(k: int) on link pack "B" (0x21) unpack "B" expect out[0] == k { quality = out[0] }
"""


def _node(*values: int) -> bytes:
    check = 0
    for value in values:
        check ^= value
    return b"\xa5" + bytes(values) + bytes([check])


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, NODES, tmp_path_factory.mktemp("expect"), "nodes")


def test_skip_unmatched_reads_past_replies_that_do_not_meet_it(implementation: Any) -> None:
    port = ScriptedPort(_node(0x07, 0x01) + _node(0x06, 0x00) + _node(0x0A, 0x01))
    with implementation.connect(port, threads=False) as robot:
        robot.call_primitive("scan")
        assert robot.state["quality"] == 0x05  # the third node: the first two have equal bits
        assert port.script == b""


def test_a_reply_that_does_not_meet_it_is_a_protocol_error_and_sets_nothing(implementation: Any) -> None:
    port = ScriptedPort(b"\x05")
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception) as caught:  # the driver's RdisProtocolError is its own class
            robot.call_primitive("echo", 4)
        assert type(caught.value).__name__ == "RdisProtocolError"
        assert str(caught.value) == "echo: reply (5,) does not meet its `expect`"
        assert robot.state["quality"] == 0
        port.script = b"\x04"
        robot.call_primitive("echo", 4)
        assert robot.state["quality"] == 4


def test_expect_goes_through_json_and_back(tmp_path: Path) -> None:
    compilation, built = through_json(NODES, tmp_path, "nodes")
    assert not compilation.diagnostics.items
    scan = next(p for p in json.loads(built)["primitives"] if p["name"] == "scan")
    assert scan["expect"] == "<(__out__[0] & 1) != (__out__[1] & 1)>"


@pytest.mark.parametrize(("clauses", "expected"), [
    ('pack "B" (1) expect True', [("E202", "`expect` checks a decoded reply, but `p` decodes none")]),
    ('pack "B" (1) unpack "B" expect out[0] + 1', [("E401", "`expect` takes a bool, but this is an int")]),
    ('pack "B" (1) unpack "B" expect out[0] == 1 expect out[0] == 2',
     [("E203", "`expect` is given twice in `p`")]),
    ('pack "B" (k) reply k { 0: unpack "B"  1: unpack "<H" } expect True',
     [("E203", "primitive `p` has a reply table and also `expect`")]),
])
def test_what_the_checker_refuses(tmp_path: Path, clauses: str, expected: list[tuple[str, str]]) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text('robot r { author "tests" }\nconnection link: serial { baud 9600 }\n'
                      f"primitive p(k: int in 0..1) on link {clauses}\n", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == expected
