"""Several replies to one request, read by one primitive: `replies N` reads N replies in turn,
each as one reply is read (through the frame's reply side, decoded, held by `expect`), all
within the one reply deadline; the post-actions read value i of them all as an array of N
(a sync read answered by N status packets). `replies id in IDS frame status(id)` reads each
through a frame of its own arguments (each servo's status packet carries its ID). Runtime and
generated driver alike, through the one engine."""

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

BUS = """\
robot bus { author "tests" }
connection port: serial { baud 115200 }
frame f { header "\\xFF"  length "B" = payload  payload  checksum "sum" "B" over length .. payload }
state error: int[3]
state present: int[3]
state quality: int[2]
/// A sync read: one request, three status packets.
primitive read_all() on port frame f() pack "BB" (0x82, 3) replies 3 unpack "<BBh" expect out[0] == 0x55 {
    error = out[1]  present = out[2]
}
/// A sync read whose status packets carry each servo's ID, in the order asked.
const IDS = [1, 2, 3]
frame status(id: int in 0..253) { request { payload }  reply { header "\\xFE"  field id "B" = id  payload } }
primitive read_ids() on port frame f() pack "BBBB" (0x82, 1, 2, 3) replies id in IDS frame status(id)
    unpack "<Bh" { error = out[0]  present = out[1] }
/// Two unframed scan nodes after one request, their check bits held node by node.
primitive nodes() on port format "N" () unpack "<B{1,1,6}" replies 2 expect out[0] != out[1] { quality = out[2] }
"""


def status(payload: str) -> bytes:
    data = bytes.fromhex(payload)
    return b"\xff" + bytes([len(data)]) + data + bytes([(len(data) + sum(data)) & 0xFF])


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, BUS, tmp_path_factory.mktemp("replies"), "bus")


def test_one_request_and_its_replies_collected_into_arrays(implementation: Any) -> None:
    port = ScriptedPort(status("55 00 0100") + status("55 02 ffff") + status("55 00 3412")
                        + bytes.fromhex("3e 81"))
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.read_all()
        assert bytes(port.written).hex(" ") == "ff 02 82 03 87"
        assert (robot.state.error, robot.state.present) == ((0, 2, 0), (1, -1, 0x1234))
        robot.primitives.nodes()
        assert robot.state.quality == (15, 32)
        assert bytes(port.written).hex(" ") == "ff 02 82 03 87 4e"


def test_a_reply_that_breaks_its_expect_is_refused_by_its_place(implementation: Any) -> None:
    port = ScriptedPort(status("55 00 0100") + status("56 02 ffff") + status("55 00 3412"))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception, match=r"^read_all: reply 2 of 3: reply \(86, 2, -1\) does not meet its "
                           r"`expect`$") as raised:
            robot.primitives.read_all()
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert robot.state.present == (0, 0, 0)


def test_too_few_replies_time_out(implementation: Any) -> None:
    port = ScriptedPort(status("55 00 0100") + status("55 00 0200"))
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception, match=r"^read_all: 2 of 3 replies within 1 s$") as raised:
            robot.primitives.read_all()
        assert type(raised.value).__name__ == "RdisTimeout"
        with pytest.raises(Exception, match=r"^read_all: no reply within 1 s$"):
            robot.primitives.read_all()
        assert robot.state.present == (0, 0, 0)


def test_each_reply_through_its_own_frame(implementation: Any) -> None:
    port = ScriptedPort(bytes.fromhex("FE 01 00 0a00" "FE 02 04 0b00" "FE 03 00 0c00"
                                      "FE 01 00 0a00" "FE 03 00 0c00"))
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.read_ids()
        assert bytes(port.written).hex(" ") == "ff 04 82 01 02 03 8c"
        assert (robot.state.error, robot.state.present) == ((0, 4, 0), (10, 11, 12))
        with pytest.raises(Exception, match=r"^read_ids: reply 2 of 3: status: reply id is 3, expected 2$") as raised:
            robot.primitives.read_ids()
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert robot.state.present == (10, 11, 12)


def test_a_bad_frame_among_the_replies_is_refused(implementation: Any) -> None:
    broken = bytearray(status("55 00 0200"))
    broken[-1] ^= 0xFF
    with implementation.connect(ScriptedPort(status("55 00 0100") + bytes(broken)), threads=False) as robot:
        with pytest.raises(Exception, match=r"^read_all: reply 2 of 3: f: ") as raised:
            robot.primitives.read_all()
        assert type(raised.value).__name__ == "RdisProtocolError"


ERRORS = """\
robot r { author "tests" }
connection port: serial { baud 115200 }
frame f { header "\\xFF"  length "B" = payload  payload }
state one: int = 0
state two: int[2]
primitive scalar() on port pack "B" (1) replies 2 unpack "B" { one = out[0] }
primitive single() on port pack "B" (1) replies 1 unpack "B"
primitive none() on port pack "B" (1) replies 2
primitive grouped() on port frame f() pack "B" (1) replies 2 unpack "<*(B)"
primitive many() on port pack "B" (1) replies 1025 unpack "B"
primitive fine() on port pack "B" (1) replies 2 unpack "B" { two = out[0] }
frame g(id: int in 0..9) { header "\\xAA"  field id "B" = id  length "B" = payload  payload }
primitive hidden(one: int) on port pack "B" (1) replies one in 0..1 frame g(one) unpack "B"
primitive varying() on port pack "B" (1) replies id in two frame g(id) unpack "B"
primitive wide() on port pack "B" (1) replies id in [1, 20] frame g(id) unpack "B"
primitive lone() on port pack "B" (1) replies id in 3..3 frame g(id) unpack "B"
"""


def test_the_checker_texts(tmp_path: Path) -> None:
    _, result = check_text(tmp_path, ERRORS)
    assert result.stderr.replace(str(tmp_path) + "/", "") == """\
error[E401]: state variable `one` takes an int, but this is an array int[2]
 --> d.rdis:6:70
  |
6 | primitive scalar() on port pack "B" (1) replies 2 unpack "B" { one = out[0] }
  |                                                                      ^^^^^^
  |
  = help: take one of its values (`[0]`), or declare the target `int[2]` to keep them all

error[E204]: a reply count is a constant int from 2 to 1024, not 1
 --> d.rdis:7:49
  |
7 | primitive single() on port pack "B" (1) replies 1 unpack "B"
  |                                                 ^

error[E202]: `none` reads 2 replies, but decodes none
 --> d.rdis:8:39
  |
8 | primitive none() on port pack "B" (1) replies 2
  |                                       ^^^^^^^^^
  |
  = help: say how each reply is read: `unpack` or `regex` (a reply table chooses one reply)

error[E401]: `grouped` reads 2 replies, whose values are arrays: each value of the replies would be an array of arrays
 --> d.rdis:9:52
  |
9 | primitive grouped() on port frame f() pack "B" (1) replies 2 unpack "<*(B)"
  |                                                    ^^^^^^^^^
  |
  = help: read a reply of single values, or one reply with a repeated group

error[E204]: a reply count must be at most 1024
  --> d.rdis:10:47
   |
10 | primitive many() on port pack "B" (1) replies 1025 unpack "B"
   |                                               ^^^^

error[E101]: loop variable `one` has the name of a parameter
  --> d.rdis:13:57
   |
13 | primitive hidden(one: int) on port pack "B" (1) replies one in 0..1 frame g(one) unpack "B"
   |                  --- a parameter `one`
   |                                                         ^^^
   |
   = help: give the loop variable a name of its own

error[E212]: `replies` goes over a constant array, a range or an array parameter, not an array known only when it runs
  --> d.rdis:14:56
   |
14 | primitive varying() on port pack "B" (1) replies id in two frame g(id) unpack "B"
   |                                                        ^^^
   |
   = help: pass the array to the primitive as a parameter: `replies id in ids` over `ids: int[]` reads a reply for each element the caller gives

error[E403]: 20 is outside the range of parameter `id` of frame `g`
  --> d.rdis:15:69
   |
15 | primitive wide() on port pack "B" (1) replies id in [1, 20] frame g(id) unpack "B"
   |                                                                     ^^ in 0..9

error[E204]: a primitive reads 2 to 1024 replies, not 1
  --> d.rdis:16:39
   |
16 | primitive lone() on port pack "B" (1) replies id in 3..3 frame g(id) unpack "B"
   |                                       ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^

9 errors emitted
"""


def test_json_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(BUS, tmp_path, "bus")
    assert '"replies": 3' in built and '"replies": 2' in built
    printed = print_module(parse("bus.rdis", BUS, Diagnostics()))
    assert '    replies 3\n    unpack "<BBh"\n' in printed
    assert print_module(parse("again.rdis", printed, Diagnostics())) == printed
    model = compilation.model
    assert model is not None
    assert """\
  3 replies, each: 7 bytes
  offset  size  kind                  value
       0     1  header                FF
       1     1  length                "B" = payload
       2     1  payload u8            out[0]
       3     1  payload u8            out[1]
       4     2  payload s16 LE        out[2]
       6     1  checksum              sum as B, over length .. payload
""" in dump.dump(model)
    sizes = {name: budget.message_bytes(prim, model.frames) for name, prim in model.primitives.items()}
    assert sizes == {"read_all": 5 + 3 * 7, "read_ids": 7 + 3 * 5, "nodes": 1 + 2 * 1}
    assert """\
  3 replies, frame status(1) .. status(3), each: 5 bytes
  offset  size  kind                  value
       0     1  header                FE
       1     1  field id              "B" = id
       2     1  payload u8            out[0]
       3     2  payload s16 LE        out[1]
""" in dump.dump(model)
    assert '"replyFrames": [' in built
    printed = print_module(parse("bus.rdis", BUS, Diagnostics()))
    assert "    replies id in IDS frame status(id)\n" in printed


def test_build_and_import_in_turn_keep_an_array_parameter_indexed(tmp_path: Path) -> None:
    """A reply frame's argument read from an array parameter by the loop variable comes back
    as `ids[reply]`: build, import and build again gave the same JSON, and the source stays."""
    from rdisc.json_import.document import read

    text = """\
robot r { author "tests" }
connection port: serial { baud 115200 }
frame g(id: int in 0..9) { header "\\xAA"  field id "B" = id  length "B" = payload  payload }
primitive varying(ids: int[2]) on port pack "B" (1) replies i in 0..1 frame g(ids[i]) unpack "B"
primitive later(ids: int[3]) on port pack "B" (1) replies i in 1..2 frame g(ids[i]) unpack "B"
"""
    _, built = through_json(text, tmp_path, "grows")
    imported = print_module(read("grows.json", built, Diagnostics()))
    assert "    replies reply in 0..1 frame g(ids[reply])\n" in imported
    assert "    replies reply in 1..2 frame g(ids[reply])\n" in imported
    _, again = through_json(imported, tmp_path, "again")
    assert again == built


EACH = """\
robot bus { author "tests" }
connection port: serial { baud 115200 }
frame f { header "\\xFF"  length "<H" = payload  payload  checksum "sum" "B" over length .. payload }
frame status(id: int in 0..253) { request { payload }  reply { header "\\xFE"  field id "B" = id  payload } }
state present: int[]
state errors: int[3]
/// A sync read of the servos asked for, as many as given, each status packet carrying its ID.
primitive read_each(ids: int[] in 0..253) on port frame f() pack "<B*(B)" (0x82, ids)
    replies id in ids frame status(id) unpack "<Bh" { present = out[1] }
/// Three servos, each asked for by the caller.
primitive read_three(ids: int[3] in 0..253) on port frame f() pack "<B3B" (0x82, ids)
    replies id in ids frame status(id) unpack "<Bh" { errors = out[0] }
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def each_implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, EACH, tmp_path_factory.mktemp("each"), "each")


def test_a_reply_for_each_element_of_an_array_parameter(each_implementation: Any) -> None:
    """`replies id in ids` over `ids: int[]`: as many replies as the caller gives ids, each
    through the frame of its own id, in the order asked."""
    port = ScriptedPort(bytes.fromhex("FE 05 00 0a00" "FE 07 04 0b00"
                                      "FE 01 00 0100" "FE 02 00 0200" "FE 03 00 0300" "FE 04 09 0400"))
    with each_implementation.connect(port, threads=False) as robot:
        robot.primitives.read_each([5, 7])
        assert bytes(port.written).hex(" ") == "ff 03 00 82 05 07 91"
        assert robot.state.present == (10, 11)
        robot.primitives.read_each([1, 2, 3, 4])
        assert bytes(port.written).hex(" ").endswith("ff 05 00 82 01 02 03 04 91")
        assert robot.state.present == (1, 2, 3, 4)


def test_each_reply_is_held_to_its_element_and_an_empty_array_writes_nothing(each_implementation: Any) -> None:
    port = ScriptedPort(bytes.fromhex("FE 01 00 0100" "FE 03 00 0300" "FE 02 00 0200"))
    with each_implementation.connect(port, threads=False) as robot:
        with pytest.raises(Exception, match=r"^read_three: reply 2 of 3: status: reply id is 3, expected 2$") as raised:
            robot.primitives.read_three([1, 2, 3])
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert robot.state.errors == (0, 0, 0)
        written = bytes(port.written)
        with pytest.raises(Exception, match=r"^read_each: parameter ids is empty: a reply for each of its "
                           r"elements is none to read$") as raised:
            robot.primitives.read_each([])
        assert type(raised.value).__name__ == "RdisValueError"
        assert bytes(port.written) == written
        with pytest.raises(Exception, match=r"^read_each: 1 of 2 replies within"):
            robot.primitives.read_each([2, 9])


def test_replies_over_an_array_parameter_in_json_printer_dump_and_budget(tmp_path: Path) -> None:
    """Canonical JSON names the variable and the array, the one frame written as it is: build,
    import and build again give the same JSON and the same source line (nothing grows)."""
    from rdisc.json_import.document import read

    compilation, built = through_json(EACH, tmp_path, "each")
    assert """\
      "repliesEach": {
        "variable": "id",
        "over": "ids"
      },
      "replyFrames": [
        {
          "name": "status",
          "arguments": [
            "<id>"
          ]
        }
      ],""" in built
    assert '"replies": 3' not in built
    imported = print_module(read("each.json", built, Diagnostics()))
    assert imported.count("\n    replies id in ids frame status(id) {") == 2
    _, again = through_json(imported, tmp_path, "again")
    assert again == built
    printed = print_module(parse("each.rdis", EACH, Diagnostics()))
    assert printed.count("\n    replies id in ids frame status(id)") == 2
    model = compilation.model
    assert model is not None
    shown = dump.dump(model)
    assert "  a reply for each of ids, frame status(id), each: 5 bytes\n" in shown
    assert "  3 replies, one for each of ids, frame status(id), each: 5 bytes\n" in shown
    sizes = {name: budget.message_bytes(prim, model.frames) for name, prim in model.primitives.items()}
    assert sizes["read_three"] == 8 + 3 * 5


def test_the_variable_of_replies_over_an_array_parameter_is_its_own(tmp_path: Path) -> None:
    text = EACH.replace("replies id in ids frame status(id) unpack \"<Bh\" { errors",
                        "replies ids in ids frame status(ids) unpack \"<Bh\" { errors")
    _, result = check_text(tmp_path, text)
    assert [line for line in result.stderr.splitlines() if line.startswith("error")] == [
        "error[E101]: loop variable `ids` has the name of a parameter"]
