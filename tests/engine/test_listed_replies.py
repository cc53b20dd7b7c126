"""Replies of different shapes to one request, read by one primitive: `replies { ... }` reads
a fixed sequence of replies (a Dynamixel bulk read's status packets, each servo its own data),
each through its own frame or the primitive's, decoded its own way, held by its own `expect`
and stored by its own post-actions; all are read and met, within the one reply deadline,
before any post-action runs. Runtime and generated driver alike, through the one engine."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from conftest import check_text

from rdisc.diagnostics import Diagnostics
from rdisc.emit import dump
from rdisc.semantics import budget
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

BUS = r"""robot bus { author "tests" }
connection port: serial { baud 115200 }
frame f { header "\xFF"  length "B" = payload  payload  checksum "sum" "B" over length .. payload }
frame status(id: int in 0..253) { request { payload }  reply { header "\xFE"  field id "B" = id  payload } }
state position: int
state temperature: int
state label: string
/// A bulk read: servo 1's position (4 bytes), then the second servo's temperature (1 byte).
primitive bulk(second: int in 0..253) on port frame f() pack "<BBHHBHH" (0x92, 1, 132, 4, second, 146, 1) replies {
    frame status(1) unpack "<Bi" expect out[0] == 0 { position = out[1] }
    frame status(second) unpack "<BB" expect out[0] == 0 { temperature = out[1] }
}
/// The same, reading past packets that do not decode.
primitive bulk_skipping() on port frame f() pack "B" (0x92) skip unmatched replies {
    frame status(1) unpack "<Bi" { position = out[1] }
    frame status(2) unpack "<BB" { temperature = out[1] }
}
/// A bulk write (0x93) is a request only: each servo's ID, address, length and data, written with pack.
primitive bulk_write(goal: int, led: int in 0..1) on port frame f() pack "<BBHHIBHHB" (0x93, 1, 116, 4, goal, 2, 65, 1, led)
/// Two lines of different shapes after one request, unframed.
primitive ask() on port format "?\n" () replies {
    regex "P(-?[0-9]+)" { position = int(out[0]) }
    regex "N(.*)" expect out[0] != "" { label = out[0] }
}
"""
REQUEST = "ff 0b 92 01 84 00 04 00 07 92 00 01 00 c0"  # bulk(7)


def status(dxl_id: int, payload: str) -> bytes:
    return bytes([0xFE, dxl_id]) + bytes.fromhex(payload)


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, BUS, tmp_path_factory.mktemp("listed"), "bus")


def test_each_reply_is_read_its_own_way_and_stored_by_its_own_post_actions(implementation: Any) -> None:
    port = ScriptedPort(status(1, "00 78563412") + status(7, "00 2d") + b"P-12\nNarm\n")
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.bulk(7)
        assert bytes(port.written).hex(" ") == REQUEST
        assert (robot.state.position, robot.state.temperature) == (0x12345678, 45)
        robot.primitives.ask()
        assert bytes(port.written).hex(" ") == REQUEST + " 3f 0a"
        assert (robot.state.position, robot.state.label) == (-12, "arm")
        port.written.clear()
        robot.primitives.bulk_write(2048, 1)
        assert bytes(port.written).hex(" ") == "ff 10 93 01 74 00 04 00 00 08 00 00 02 41 00 01 00 01 69"


def test_a_bad_reply_is_refused_by_its_place_and_changes_no_state(implementation: Any) -> None:
    port = ScriptedPort(status(1, "00 78563412") + status(7, "01 2d"))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception, match=r"^bulk: reply 2 of 2: reply \(1, 45\) does not meet its `expect`$") \
                as raised:
            robot.primitives.bulk(7)
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert (robot.state.position, robot.state.temperature) == (0, 0)  # the first's post-actions did not run


def test_a_reply_of_another_servo_is_refused_by_its_place(implementation: Any) -> None:
    port = ScriptedPort(status(1, "00 78563412") + status(8, "00 2d"))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception, match=r"^bulk: reply 2 of 2: ") as raised:
            robot.primitives.bulk(7)
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert "id" in str(raised.value)
        assert robot.state.position == 0


def test_too_few_replies_time_out(implementation: Any) -> None:
    port = ScriptedPort(status(1, "00 78563412"))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception, match=r"^bulk: 1 of 2 replies within 1 s$") as raised:
            robot.primitives.bulk(7)
        assert type(raised.value).__name__ == "RdisTimeout"
        assert robot.state.position == 0


def test_skip_unmatched_reads_past_other_packets(implementation: Any) -> None:
    port = ScriptedPort(status(9, "00 01") + status(1, "00 05000000") + status(7, "00 2d") + status(2, "00 2e"))
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.bulk_skipping()
        assert (robot.state.position, robot.state.temperature) == (5, 46)


def test_json_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(BUS, tmp_path, "bus")
    assert '''"replyList": [
        {
          "frame": {
            "name": "status",
            "arguments": [
              "<1>"
            ]
          },
          "unpack": "<Bi",
          "expect": "<__out__[0] == 0>",
          "postActions": [
            "position = __out__[1]"
          ]
        },''' in built
    printed = print_module(parse("bus.rdis", BUS, Diagnostics()))
    assert """    replies {
        frame status(1) unpack "<Bi" expect out[0] == 0 { position = out[1] }
        frame status(second) unpack "<BB" expect out[0] == 0 { temperature = out[1] }
    }
""" in printed
    assert print_module(parse("bus.rdis", printed, Diagnostics())) == printed
    model = compilation.model
    assert model is not None
    text = dump.dump(model)
    assert """  reply 1 of 2, frame status(1): 7 bytes
  offset  size  kind                  value
       0     1  header                FE
       1     1  field id              "B" = id
       2     1  payload u8            out[0]
       3     4  payload s32 LE        out[1]
  reply 2 of 2, frame status(second): 4 bytes
""" in text
    assert budget.message_bytes(model.primitives["bulk"], model.frames) == 14 + 7 + 4


ERRORS = r"""robot bus { author "tests" }
connection port: serial { baud 115200 }
frame f { header "\xFF"  length "B" = payload  payload }
frame quiet { request { payload } }
state position: int
primitive one() on port frame f() pack "B" (1) replies { unpack "<h" { position = out[0] } }
primitive both() on port frame f() pack "B" (1) unpack "<h" replies { unpack "<h"  unpack "<B" }
primitive silent() on port pack "B" (1) replies { frame quiet() unpack "<h"  unpack "<B" }
primitive wrong() on port pack "B" (1) replies { unpack "<h" expect out[0] + 1  unpack "<B" { position = out[1] } }
"""


def test_the_checker_texts(tmp_path: Path) -> None:
    _, result = check_text(tmp_path, ERRORS)
    assert result.stderr.replace(str(tmp_path) + "/", "") == """\
error[E204]: a primitive reads 2 to 1024 replies, not 1
 --> d.rdis:6:48
  |
6 | primitive one() on port frame f() pack "B" (1) replies { unpack "<h" { position = out[0] } }
  |                                                ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^
  |
  = help: a primitive that reads one reply says how with `unpack` or `regex` alone

error[E203]: primitive `both` has `replies { }` and also `unpack`/`regex`
 --> d.rdis:7:61
  |
7 | primitive both() on port frame f() pack "B" (1) unpack "<h" replies { unpack "<h"  unpack "<B" }
  |                                                             ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^
  |
  = help: each reply of `replies { }` has its own decoding, `expect` and post-actions: write them there

error[E504]: reply 1 of `silent` is read through frame `quiet`, whose reply is empty
 --> d.rdis:8:51
  |
8 | primitive silent() on port pack "B" (1) replies { frame quiet() unpack "<h"  unpack "<B" }
  |                                                   ^^^^^^^^^^^^^
  |
  = help: read it through a frame whose reply has a `payload`, or through the primitive's frame (leave out its `frame`)

error[E401]: `expect` takes a bool, but this is an int
 --> d.rdis:9:69
  |
9 | primitive wrong() on port pack "B" (1) replies { unpack "<h" expect out[0] + 1  unpack "<B" { position = out[1] } }
  |                                                                     ^^^^^^^^^^

error[E305]: `out[1]` is outside the reply, which has 1 value
 --> d.rdis:9:106
  |
9 | primitive wrong() on port pack "B" (1) replies { unpack "<h" expect out[0] + 1  unpack "<B" { position = out[1] } }
  |                                                                                                          ^^^^^^
  |
  = help: valid indexes are 0 to 0

5 errors emitted
"""
