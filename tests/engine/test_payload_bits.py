"""Bit fields in a primitive's payload: an unsigned integer code of a `pack` or `unpack`
format split into fields from its lowest bit up, `B{1,1,6}`, one value each. A request joins
its values into the integer (a value wider than its bits is refused), a reply gives the
integer's fields, which an `expect` can hold (RPLIDAR's scan node: a start flag and its
inverse, a check bit). The engine's `Bits`, which splits a frame's `bits` part, does it for
runtime and generated driver alike."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from conftest import check_text

from rdisc.diagnostics import Diagnostics
from rdisc.emit import dump
from rdisc.lowering import constructs as codec
from rdisc.semantics import budget, formats
from rdisc.semantics import model as m
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

LIDAR = """\
robot lidar { author "tests" }
frame f { header "\\xAA"  length "<H" = payload  payload }
connection port: serial { baud 115200 }
state start: bool = False
state quality: int = 0
state angle: int = 0
state distance: int = 0
state ids: int[]
state name: string = ""
/// A scan node: start flag, its inverse, quality; check bit, angle; distance.
primitive node() on port format "" () unpack "<B{1,1,6}H{1,15}H"
    expect out[0] != out[1] and out[3] == 1 {
    start = out[0] == 1  quality = out[2]  angle = out[4]  distance = out[5]
}
/// A mode byte of three fields between two plain values.
primitive mode(on: bool, gear: int in 0..7, level: int) on port pack "<BB{1,3,4}H" (0x10, 1 if on else 0, gear, level, 500)
/// Bit fields before a counted group, and after it.
primitive sync(ids: int[], kind: int in 0..15) on port frame f() pack "<B{4,4}#B#(B)H{15,1}" (kind, 2, ids, 300, 1)
primitive status() on port frame f() pack "B" (1) unpack "<B{4,4}#B#(B)" { quality = out[1]  ids = out[2] }
/// Bit fields before text.
primitive named() on port pack "B" (2) unpack "<H{8,8}3s" { angle = out[0] + out[1]  name = out[2] }
interface slow(level: int in 0..15) { mode(True, 2, level) }
"""


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, LIDAR, tmp_path_factory.mktemp("bits"), "lidar")


def _pack(fmt: str) -> m.Pack:
    """A `pack` as the checker makes it: its layout stored beside it."""
    return m.Pack(fmt, formats.struct_layout(fmt))


def _unpack(fmt: str) -> m.Unpack:
    return m.Unpack(fmt, formats.struct_layout(fmt))


def test_a_request_joins_its_bit_fields_into_one_integer(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.mode(True, 5, 9)  # 1 | 5 << 1 | 9 << 4 = 0x9B
        assert bytes(port.written).hex(" ") == "10 9b f4 01"
        port.written.clear()
        robot.interfaces.slow(15)
        assert bytes(port.written).hex(" ") == "10 f5 f4 01"


def test_a_value_wider_than_its_bits_is_refused(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(ValueError, match=r"^mode: field value 3 is 16, which does not fit its 4 bits "
                           r"\(0 to 15\)$") as raised:
            robot.primitives.mode(False, 1, 16)
        assert type(raised.value).__name__ == "RdisValueError"
        with pytest.raises(ValueError, match=r"^mode: field value 3 is -1, which does not fit its 4 bits"):
            robot.primitives.mode(False, 1, -1)
        assert bytes(port.written) == b""


def test_a_reply_gives_the_fields_of_its_integers(implementation: Any) -> None:
    node = bytes.fromhex("3E 81 02 34 12")  # start 0, inverse 1, quality 15; check 1, angle 320; 0x1234
    with implementation.connect(ScriptedPort(node + bytes.fromhex("3D 03 10 00 08")), threads=False) as robot:
        robot.primitives.node()
        assert (robot.state.start, robot.state.quality, robot.state.angle, robot.state.distance) == (
            False, 15, 320, 0x1234)
        robot.primitives.node()
        assert (robot.state.start, robot.state.quality, robot.state.angle, robot.state.distance) == (
            True, 15, 0x801, 0x800)


@pytest.mark.parametrize(("reply", "values"), [
    ("3F 03 10 00 08", "(1, 1, 15, 1, 2049, 2048)"),  # both flags set
    ("3C 03 10 00 08", "(0, 0, 15, 1, 2049, 2048)"),  # neither
    ("3D 02 10 00 08", "(1, 0, 15, 0, 2049, 2048)"),  # the check bit clear
])
def test_a_node_whose_check_bits_disagree_is_refused(implementation: Any, reply: str, values: str) -> None:
    with implementation.connect(ScriptedPort(bytes.fromhex(reply)), threads=False) as robot:
        with pytest.raises(Exception, match=rf"^node: reply {values.replace('(', '[(]').replace(')', '[)]')} "
                           r"does not meet its `expect`$") as raised:
            robot.primitives.node()
        assert type(raised.value).__name__ == "RdisProtocolError"
        assert (robot.state.quality, robot.state.distance) == (0, 0)


def test_bit_fields_around_a_counted_group_and_before_text(implementation: Any) -> None:
    port = ScriptedPort(bytes.fromhex("AA 04 00 A3 02 07 08") + bytes.fromhex("4C 01 61 62 63"))
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.sync([1, 2, 3], 9)  # 9 | 2 << 4; 3 ids; 300 | 1 << 15
        assert bytes(port.written).hex(" ") == "aa 07 00 29 03 01 02 03 2c 81"
        robot.primitives.status()
        assert (robot.state.quality, robot.state.ids) == (10, (7, 8))
        robot.primitives.named()
        assert (robot.state.angle, robot.state.name) == (0x4C + 1, "abc")


def test_the_layout_and_the_engine_codec() -> None:
    layout = formats.struct_layout("<B{1,1,6}H{1,15}H")
    assert layout.fixed == "<BHH" and layout.size == 5
    assert layout.bits == ((0, "<B", (1, 1, 6)), (3, "<H", (1, 15)))
    assert [s.bits for s in layout.slots] == [(0, 1), (1, 1), (2, 6), (0, 1), (1, 15), None]
    assert [s.high for s in layout.slots] == [1, 1, 63, 1, (1 << 15) - 1, 0xFFFF]
    assert formats.struct_layout("<B{4, 4} H {8 8}").bits == ((0, "<B", (4, 4)), (2, "<H", (8, 8)))
    texts = formats.struct_layout("<H{8,8}3sB{7,1}?")
    assert [texts.joined(i) for i in (2, 5)] == [1, 3]
    encoder = codec.encoder(_pack("<B{4,4}#B#(B)H{15,1}"))
    assert (encoder.groups, encoder.varying, encoder.bits) == (  # type: ignore[union-attr]
        ((1, 1, 0),), ("B", "H", 1), ((0, "<B", (4, 4)), (3, "<H", (15, 1))))
    assert encoder.encode("x", [9, 2, (1, 2), 300, 1]).hex(" ") == "29 02 01 02 2c 81"
    assert codec.decoder(_unpack("<B{4,4}#B#(B)H{15,1}")).decode("x", bytes.fromhex("29 02 01 02 2c 81")) == (
        9, 2, (1, 2), 300, 1)


@pytest.mark.parametrize(("fmt", "message"), [
    ("<2B{4,4}", "a code split into bit fields has no count: `B{...}`, not `2B{...}`"),
    ("<h{8,8}", "bit fields split an unsigned integer code (`B`, `H`, `I`, `L` or `Q`), not `h` (signed): use `H`"),
    ("<f{16,16}", "bit fields split an unsigned integer code (`B`, `H`, `I`, `L` or `Q`), not `f`"),
    ("<B{8}", "bit fields are two widths or more, from the lowest bit up: `B{1,1,6}`"),
    ("<B{4,x}", "bit fields are two widths or more, from the lowest bit up: `B{1,1,6}`"),
    ("<B{4,3}", "the bit fields of `B` take 7 of its 8 bits: every bit is in one field (a reserved bit too)"),
    ("<H{8,9}", "the bit fields of `H` take 17 of its 16 bits: every bit is in one field (a reserved bit too)"),
    ("<B{0,8}", "a bit field is 1 bit wide or more"),
    ("<{4,4}", "bit fields `{...}` follow the unsigned integer code they split: `B{1,1,6}`"),
    ("<#B{4,4}#(B)", "bit fields `{...}` follow the unsigned integer code they split: `B{1,1,6}`"),
    ("<B{4,4", "bit fields `{...}` are closed by `}`"),
    ("<3(B{4,4})", "a repeated group holds no bit fields"),
])
def test_formats_the_checker_refuses(fmt: str, message: str) -> None:
    with pytest.raises(formats.TemplateError) as err:
        formats.struct_layout(fmt)
    assert err.value.message == message


ERRORS = """\
robot r { author "tests" }
connection port: serial { baud 115200 }
state x: int = 0
primitive wide() on port pack "<B{4,4}" (16, 1)
primitive real(f: float) on port pack "<B{4,4}" (1, f)
primitive part(v: int in 0..15) on port pack "<B{4,4}" (v, 2)
primitive short() on port pack "<H{4,4}" (1, 1)
primitive beyond() on port format "?" () unpack "<B{4,4}" { x = out[2] }
frame g { header "\\xAA"  field k "B{4,4}" = 1  payload }
interface i() { part(16) }
"""


def test_the_checker_texts(tmp_path: Path) -> None:
    _, result = check_text(tmp_path, ERRORS)
    assert result.stderr.replace(str(tmp_path) + "/", "") == """\
error[E403]: 16 does not fit pack code `B{4,4}` bits 0..3
 --> d.rdis:4:42
  |
4 | primitive wide() on port pack "<B{4,4}" (16, 1)
  |                                          ^^ `B{4,4}` bits 0..3 holds 0 to 15

error[E402]: pack code `B{4,4}` bits 4..7 takes an int, but this is a float
 --> d.rdis:5:53
  |
5 | primitive real(f: float) on port pack "<B{4,4}" (1, f)
  |                                                     ^ a float
  |
  = help: convert it: `round(...)` to the nearest integer, `int(...)` towards zero

error[E301]: the bit fields of `H` take 8 of its 16 bits: every bit is in one field (a reserved bit too)
 --> d.rdis:7:35
  |
7 | primitive short() on port pack "<H{4,4}" (1, 1)
  |                                   ^^^^^

error[E305]: `out[2]` is outside the reply, which has 2 values
 --> d.rdis:8:65
  |
8 | primitive beyond() on port format "?" () unpack "<B{4,4}" { x = out[2] }
  |                                                                 ^^^^^^
  |
  = help: valid indexes are 0 to 1

error[E501]: field `k` is one integer: a struct format such as "B", ">H" or "<I", not "B{4,4}"
 --> d.rdis:9:34
  |
9 | frame g { header "\\xAA"  field k "B{4,4}" = 1  payload }
  |                                  ^^^^^^^^

error[E403]: 16 is outside the range of parameter `v` of primitive `part`
  --> d.rdis:10:22
   |
10 | interface i() { part(16) }
   |                      ^^ in 0..15

error[E403]: 16 does not fit pack code `B{4,4}` bits 0..3 of primitive `part`
  --> d.rdis:10:22
   |
10 | interface i() { part(16) }
   |                      ^^ parameter `v` is packed as `B{4,4}` bits 0..3, 0 to 15

7 errors emitted
"""


def test_json_printer_dump_and_budget(tmp_path: Path) -> None:
    compilation, built = through_json(LIDAR, tmp_path, "lidar")
    assert '"unpack": "<B{1,1,6}H{1,15}H"' in built and '"pack": "<BB{1,3,4}H"' in built
    printed = print_module(parse("lidar.rdis", LIDAR, Diagnostics()))
    assert 'unpack "<B{1,1,6}H{1,15}H"' in printed
    assert print_module(parse("again.rdis", printed, Diagnostics())) == printed
    model = compilation.model
    assert model is not None
    text = dump.dump(model)
    assert """\
  reply: 5 bytes
  offset  size  kind                  value
       0     1  bits u8               out[0] (bit 0), out[1] (bit 1), out[2] (bits 2..7)
       1     2  bits u16 LE           out[3] (bit 0), out[4] (bits 1..15)
       3     2  u16 LE                out[5]
""" in text
    assert """\
  request: 4 bytes
  offset  size  kind                  value
       0     1  u8                    10 (16)
       1     1  bits u8               1 if on else 0 (bit 0), gear (bits 1..3), level (bits 4..7)
       2     2  u16 LE                F4 01 (500)
""" in text
    assert """\
       3     1  payload bits u8       kind (bits 0..3), 2 (bits 4..7)
       4     1  payload count u8      k (the rounds of the group)
       5     n  payload u8 x k        ids[i]
       ?     2  payload bits u16 LE   300 (bits 0..14), 1 (bit 15)
""" in text
    sizes = {name: budget.message_bytes(prim, model.frames) for name, prim in model.primitives.items()}
    assert sizes["node"] == 5 and sizes["mode"] == 4
