"""Groups repeated as many times as the message says: `#(BH)`, counted by a field `#B` earlier
in the same message (a request computes it from its arrays' length, a reply's count says how
many groups to read, at most MAX_ARRAY), and `*(BH)`, repeated until the message ends (a
remainder that is not a whole group is refused). Their values are arrays of any size (`int[]`
in state and parameters); runtime and generated driver alike, through the one engine."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from conftest import check_text

from rdisc import engine
from rdisc.diagnostics import Diagnostics
from rdisc.emit import dump
from rdisc.limits import MAX_ARRAY
from rdisc.lowering import constructs as codec
from rdisc.semantics import budget, formats
from rdisc.semantics import model as m
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

BUS = """\
robot bus { author "tests" }
frame f { header "\\xAA"  length "<H" = payload  payload }
connection port: serial { baud 115200 }
state ids: int[]
state temps: int[]
state status: int = 0
/// Sync write (Dynamixel 2.0 style): the servos' ids and goals, any number of them.
primitive sync_write(ids: int[], goals: int[]) on port frame f() pack "<BH*(BH)" (0x83, 30, ids, goals)
/// A counted write of a fixed six.
primitive write_six(ids: int[6], goals: int[6] in 0..1000) on port frame f() pack "<B#B#(BH)" (0x84, ids, goals)
/// A reply that says how many groups follow, and a field after them.
primitive read_counted() on port frame f() pack "B" (0x01) unpack "<#B#(BH)B"
    { ids = out[0]  temps = out[1]  status = out[2] }
/// A reply of groups until its end.
primitive read_all() on port frame f() pack "B" (0x02) unpack "<B*(BH)" { status = out[0]  ids = out[1]  temps = out[2] }
interface park(ids: int[]) { sync_write(ids, [512, 512, 512]) }
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, BUS, tmp_path_factory.mktemp("counted"), "bus")


def frame(payload: str) -> bytes:
    data = bytes.fromhex(payload)
    return b"\xaa" + len(data).to_bytes(2, "little") + data


def _pack(fmt: str) -> m.Pack:
    """A `pack` as the checker makes it: its layout stored beside it."""
    return m.Pack(fmt, formats.struct_layout(fmt))


def _unpack(fmt: str) -> m.Unpack:
    return m.Unpack(fmt, formats.struct_layout(fmt))


def test_a_request_repeats_its_group_as_its_arrays_hold(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.sync_write([1, 2], [0x100, 0x200])
        assert bytes(port.written).hex(" ") == "aa 09 00 83 1e 00 01 00 01 02 00 02"
        port.written.clear()
        robot.primitives.sync_write([], [])
        assert bytes(port.written).hex(" ") == "aa 03 00 83 1e 00"
        port.written.clear()
        robot.primitives.write_six([1, 2, 3, 4, 5, 6], [10, 20, 30, 40, 50, 60])
        assert bytes(port.written).hex(" ") == ("aa 14 00 84 06 01 0a 00 02 14 00 03 1e 00 04 28 00 05 32 00 "
                                                "06 3c 00")


def test_the_arrays_of_a_group_have_one_length(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(ValueError, match=r"^sync_write: the arrays of a repeated group have one length, "
                           r"not 1 and 2$"):
            robot.primitives.sync_write([1, 2], [3])
        with pytest.raises(ValueError, match=r"^sync_write: the arrays of a repeated group have one length, not 2 and 3$"):
            robot.interfaces.park([1, 2])
        with pytest.raises(ValueError, match=rf"^sync_write: a group is repeated at most {MAX_ARRAY} times, "
                           rf"not {MAX_ARRAY + 1}$"):
            robot.primitives.sync_write([1] * (MAX_ARRAY + 1), [2] * (MAX_ARRAY + 1))
        assert bytes(port.written) == b""


def test_a_reply_reads_as_many_groups_as_its_count_says(implementation: Any) -> None:
    port = ScriptedPort(frame("02 01 3412 02 7856 09") + frame("00 07"))
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.read_counted()
        assert (robot.state.ids, robot.state.temps, robot.state.status) == ((1, 2), (0x1234, 0x5678), 9)
        robot.primitives.read_counted()
        assert (robot.state.ids, robot.state.temps, robot.state.status) == ((), (), 7)


def test_a_reply_reads_groups_until_its_end(implementation: Any) -> None:
    port = ScriptedPort(frame("05 01 3412 02 7856 03 0100") + frame("06"))
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.read_all()
        assert (robot.state.status, robot.state.ids, robot.state.temps) == (5, (1, 2, 3), (0x1234, 0x5678, 1))
        robot.primitives.read_all()
        assert (robot.state.status, robot.state.ids, robot.state.temps) == (6, (), ())


@pytest.mark.parametrize(("reply", "message"), [
    (frame("02 01 3412 09"), "read_counted: 2 groups make 8 bytes, got 5"),
    (frame("ff" + "00" * 10), "read_counted: 255 groups make 767 bytes, got 11"),
    (frame(""), "read_counted: expected 2 bytes or more, got 0"),
])
def test_a_reply_whose_count_disagrees_with_its_size_is_refused(implementation: Any, reply: bytes,
                                                                message: str) -> None:
    with implementation.connect(ScriptedPort(reply), threads=False) as robot:
        with pytest.raises(Exception, match=f"^{message}$") as raised:
            robot.primitives.read_counted()
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert robot.state.ids == ()


def test_a_remainder_that_is_not_a_whole_group_is_refused(implementation: Any) -> None:
    with implementation.connect(ScriptedPort(frame("05 01 3412 02")), threads=False) as robot:
        with pytest.raises(Exception, match=r"^read_all: 4 bytes after the first 1 are not whole "
                           r"groups of 3$") as raised:
            robot.primitives.read_all()
        assert type(raised.value).__name__ == "RdisProtocolError"


def test_a_count_over_the_bound_is_refused() -> None:
    decoder = engine.Unpack("<H", groups=((0, 1, 0),), varying=("B", "", 0), varying_sizes=(1, 0))
    assert decoder.decode("r", bytes.fromhex("0300 010203")) == ((1, 2, 3),)
    with pytest.raises(engine.RdisProtocolError, match=rf"^r: the reply counts {MAX_ARRAY + 1} groups; at most "
                       rf"{MAX_ARRAY} are read$"):
        decoder.decode("r", (MAX_ARRAY + 1).to_bytes(2, "little") + bytes(MAX_ARRAY + 1))
    until = engine.Unpack("<", groups=((0, 1, 0),), varying=("B", "", -1), varying_sizes=(1, 0))
    with pytest.raises(engine.RdisProtocolError, match=rf"^r: the reply holds {MAX_ARRAY + 1} groups; at most "
                       rf"{MAX_ARRAY} are read$"):
        until.decode("r", bytes(MAX_ARRAY + 1))
    assert engine.MAX_ARRAY == MAX_ARRAY


def test_groups_before_the_count_field_and_values_after_the_group() -> None:
    encoder = codec.encoder(_pack("<2(Bb)#B#(hB)H"))
    data = encoder.encode("x", [(1, 2), (-1, -2), (300, -5, 7), (1, 2, 3), 9])
    assert data.hex(" ") == "01 ff 02 fe 03 2c 01 01 fb ff 02 07 00 03 09 00"
    assert codec.decoder(_unpack("<2(Bb)#B#(hB)H")).decode("x", data) == ((1, 2), (-1, -2), (300, -5, 7),
                                                                              (1, 2, 3), 9)


def test_the_layout_of_a_counted_group() -> None:
    layout = formats.struct_layout("<H#B2(bb)#(BH)I")
    assert layout.varying == formats.Varying("<HBbbbb", "BH", "I", 1, 255, "B", 1)
    assert layout.groups == ((1, 2, 2), (3, 2, 0))
    assert layout.size == 11 and layout.most(4) == 23
    assert [(s.code, s.repeat) for s in layout.slots] == [("H", 0), ("b", 2), ("b", 2), ("B", -1), ("H", -1),
                                                          ("I", 0)]
    assert formats.struct_layout(">*(?h)").varying == formats.Varying(">", "?h", "", -1)
    assert formats.struct_layout("<#Q#(B)").varying.count_high == MAX_ARRAY  # type: ignore[union-attr]


@pytest.mark.parametrize(("fmt", "message"), [
    ("<B#(BH)", "a `#(...)` group is counted by a field before it: `<#B #(BH)`"),
    ("<#BB", "a count field `#B` counts a `#(...)` group after it, and there is none"),
    ("<B*(BH)B", "a `*(...)` group is repeated until the message ends, so it comes last"),
    ("<#B*(B)", "a `*(...)` group is repeated until the message ends: it has no count field `#B`"),
    ("<#B#(B)#(H)", "one group of a message is repeated as the message says, not two"),
    ("<#B#B#(H)", "a message has one count field `#B`, for its `#(...)` group"),
    ("<#h#(B)", "a count field is `#` and an unsigned integer code: `#B`, `#H`, `#I`, `#L` or `#Q`"),
    ("B*(B)", ("a group repeated as the message says needs a byte order (`<` or `>`): in host order, padding "
              "would move with the count")),
    ("<*(B)*", ("`*` (the rest of the message) cannot follow a group repeated as the message says: where would "
               "the group end?")),
    ("<B*B", "`*` (the rest of the message) comes last"),
    ("<#B#(Bs)", "`s` cannot be repeated in a group: a group holds int, float and bool codes, without counts"),
])
def test_formats_the_checker_refuses(fmt: str, message: str) -> None:
    with pytest.raises(formats.TemplateError) as err:
        formats.struct_layout(fmt)
    assert err.value.message == message


ERRORS = """\
robot r { author "tests" }
frame f { header "\\xAA"  length "<H" = payload  payload }
connection port: serial { baud 115200 }
state ids: int[]
primitive wide(ids: int[300]) on port frame f() pack "<#B#(B)" (ids)
primitive unequal(a: int[2], b: int[3]) on port pack "<*(BB)" (a, b)
primitive scalar(a: int) on port pack "<*(B)" (a)
primitive unframed() on port pack "B" (1) unpack "<#B#(H)" { ids = out[0] }
primitive any(a: int[]) on port frame f() pack "<*(H)" (a)
state two: int[2]
primitive fixed() on port frame f() pack "B" (1) unpack "<*(B)" { two = out[0] }
"""


def test_the_checker_texts(tmp_path: Path) -> None:
    _, result = check_text(tmp_path, ERRORS)
    assert result.stderr.replace(str(tmp_path) + "/", "") == """\
error[E403]: the count field `#B` holds at most 255, but this array has 300 values
 --> d.rdis:5:65
  |
5 | primitive wide(ids: int[300]) on port frame f() pack "<#B#(B)" (ids)
  |                                                                 ^^^
  |
  = help: count the group with a wider field: `#H`

error[E403]: the arrays of a repeated group have one size, but this one has 3 values and the first 2
 --> d.rdis:6:67
  |
6 | primitive unequal(a: int[2], b: int[3]) on port pack "<*(BB)" (a, b)
  |                                                                - the first
  |                                                                   ^

error[E401]: pack code `B` of a repeated group takes an array int[], but this is an int
 --> d.rdis:7:48
  |
7 | primitive scalar(a: int) on port pack "<*(B)" (a)
  |                                                ^

error[E503]: the reply of `unframed` repeats a group as many times as the message says, but no frame says where the reply ends
 --> d.rdis:8:43
  |
8 | primitive unframed() on port pack "B" (1) unpack "<#B#(H)" { ids = out[0] }
  |                                           ^^^^^^^^^^^^^^^^
  |
  = help: read it through a frame with a `length` field or constant bytes after its payload

warning[W103]: state variable `two` is never used
  --> d.rdis:10:7
   |
10 | state two: int[2]
   |       ^^^
   |
   = help: read it in an expression, write it in a post-action, or remove it

error[E401]: state variable `two` holds an array int[2], but this array has any size
  --> d.rdis:11:73
   |
11 | primitive fixed() on port frame f() pack "B" (1) unpack "<*(B)" { two = out[0] }
   |                                                                         ^^^^^^
   |
   = help: declare it `int[]`

5 errors, 1 warning emitted
"""


def test_json_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(BUS, tmp_path, "bus")
    assert '"pack": "<BH*(BH)"' in built and '"unpack": "<#B#(BH)B"' in built
    assert '"type": "int[]"' in built
    printed = print_module(parse("bus.rdis", BUS, Diagnostics()))
    assert "state ids: int[]\n" in printed and 'pack "<B#B#(BH)" (132, ids, goals)' in printed
    assert print_module(parse("again.rdis", printed, Diagnostics())) == printed
    text = dump.dump(compilation.model)
    assert """\
primitive write_six(ids: int[6], goals: int[6] in 0..1000) on port, frame f()
  request: 5+n bytes
  offset  size  kind                  value
       0     1  header                AA
       1     2  length                "<H" = payload
       3     1  payload u8            84 (132)
       4     1  payload count u8      k (the rounds of the group)
       5     n  payload u8 x k        ids[i]
       ?     n  payload u16 LE x k    goals[i]
  reply: none
""" in text
    assert """\
  reply: 5+n bytes
  offset  size  kind                  value
       0     1  header                AA
       1     2  length                "<H" = payload
       3     1  payload count u8      k (the rounds of the group)
       4     n  payload u8 x k        out[0][i]
       ?     n  payload u16 LE x k    out[1][i]
       ?     1  payload u8            out[2]
""" in text


def test_the_link_budget_counts_the_most_rounds(tmp_path: Path) -> None:
    """A fixed array's size, else the count field's largest value, else MAX_ARRAY rounds."""
    compilation, _ = through_json(BUS, tmp_path, "bus")
    model = compilation.model
    assert model is not None
    sizes = {name: budget.message_bytes(prim, model.frames) for name, prim in model.primitives.items()}
    assert sizes == {
        "write_six": 3 + 2 + 6 * 3,
        "sync_write": 3 + 3 + MAX_ARRAY * 3,
        "read_counted": 4 + 3 + 2 + 255 * 3,
        "read_all": 4 + 3 + 1 + MAX_ARRAY * 3,
    }
