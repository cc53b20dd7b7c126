"""Bit fields over bytes: `Ns{...}` in a `pack` or `unpack` format splits the integer that N bytes
hold, in the format's byte order, into fields from its lowest bit up — fields that cross bytes and
an integer wider than `Q` (SBUS's and CRSF's sixteen 11-bit channels in 22 bytes, `<22s{11*16}`),
or an integer of a size struct lacks (`>3s{24}`, 3 bytes). `W*N` in the braces is N fields of W
bits. The engine's `Bits` joins and splits them, for the runtime and the generated driver alike.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from conftest import check_text

from rdisc.emit import dump
from rdisc.lowering import constructs as codec
from rdisc.semantics import formats
from rdisc.semantics import model as m
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

RADIO = """\
robot radio { author "tests" }
connection port: serial { baud 100000 }
state channels: int[4]
state capacity: int = 0
state flags: int = 0
/// Four 11-bit channels and 4 bits of flags in 6 bytes, least significant first.
primitive send(values: int[4] in 0..2047, flags: int in 0..15) on port pack "<B6s{11*4,4}" (0x0F, values, flags)
primitive read() on port format "" () unpack "<6s{11*4,4}" {
    channels = [out[0], out[1], out[2], out[3]]  flags = out[4]
}
/// A 24-bit big-endian integer between two bytes.
primitive battery() on port format "" () unpack ">B3s{24}B" { capacity = out[1]  flags = out[2] }
primitive set_capacity(value: int) on port pack ">3s{24}" (value)
"""
CHANNELS = [1, 2047, 0x555, 992]


def _wire(values: list[int], flags: int) -> bytes:
    """The reference: the fields joined as Python ints, least significant byte first."""
    word = sum(v << (11 * i) for i, v in enumerate(values)) | flags << 44
    return word.to_bytes(6, "little")


@pytest.fixture(scope="module", params=["runtime", "driver"])
def implementation(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    return implementation_of(request.param, RADIO, tmp_path_factory.mktemp("wide"), "radio")


def test_fields_across_bytes_are_packed_least_significant_first(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.primitives.send(CHANNELS, 9)
        assert bytes(port.written) == b"\x0f" + _wire(CHANNELS, 9)
        port.written.clear()
        robot.primitives.set_capacity(0x123456)
        assert bytes(port.written) == b"\x12\x34\x56"


def test_fields_across_bytes_are_read(implementation: Any) -> None:
    script = _wire(CHANNELS, 6) + bytes.fromhex("AA FF FF FE 07")
    with implementation.connect(ScriptedPort(script), threads=False) as robot:
        robot.primitives.read()
        assert (list(robot.state.channels), robot.state.flags) == (CHANNELS, 6)
        robot.primitives.battery()
        assert (robot.state.capacity, robot.state.flags) == (0xFFFFFE, 7)


def test_a_value_wider_than_its_bits_is_refused(implementation: Any) -> None:
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        with pytest.raises(ValueError, match=r"^set_capacity: field value 0 is 16777216, which does not fit its 24 "
                           r"bits \(0 to 16777215\)$") as raised:
            robot.primitives.set_capacity(1 << 24)
        assert type(raised.value).__name__ == "RdisValueError"
        assert bytes(port.written) == b""


def test_the_layout_and_the_engine_codec() -> None:
    layout = formats.struct_layout("<B22s{11*16}B")
    assert (layout.fixed, layout.size, len(layout.slots)) == ("<B22sB", 24, 18)
    assert layout.bits == ((1, "<22s", (11,) * 16),)
    assert [s.bits for s in layout.slots[1:4]] == [(0, 11), (11, 11), (22, 11)] and layout.slots[1].high == 2047
    assert formats.struct_layout(">3s{24}").bits == ((0, ">3s", (24,)),)
    assert formats.struct_layout("<B{4 * 2}").bits == ((0, "<B", (4, 4)),)
    encoder = codec.encoder(m.Pack("<6s{11*4,4}", formats.struct_layout("<6s{11*4,4}")))
    assert encoder.encode("x", [*CHANNELS, 9]) == _wire(CHANNELS, 9)
    decoder = codec.decoder(m.Unpack(">HH3s{24}B", formats.struct_layout(">HH3s{24}B")))
    assert decoder.decode("x", bytes.fromhex("00A8 007B 123456 4D")) == (168, 123, 0x123456, 77)


@pytest.mark.parametrize(("fmt", "message"), [
    ("22s{11*16}", ("bytes split into bit fields are one integer in the format's byte order: `<` (least "
                   "significant byte first) or `>`")),
    ("=2s{8,8}", ("bytes split into bit fields are one integer in the format's byte order: `<` (least "
                 "significant byte first) or `>`")),
    ("<3s{}", "bytes split into bit fields take one width or more: `>3s{24}`"),
    ("<9s{72}", "a bit field is at most 64 bits wide"),
    ("<22s{11*15}", "the bit fields of `22s` take 165 of its 176 bits: every bit is in one field (a reserved bit too)"),
    ("<2s{4*x}", "bit fields are two widths or more, from the lowest bit up: `B{1,1,6}`"),
    ("<2s{4*0,16}", "bit fields are two widths or more, from the lowest bit up: `B{1,1,6}`"),
    ("<3(2s{8,8})", "`2` cannot be repeated in a group: a group holds int, float and bool codes, without counts"),
])
def test_formats_the_checker_refuses(fmt: str, message: str) -> None:
    with pytest.raises(formats.TemplateError) as err:
        formats.struct_layout(fmt)
    assert err.value.message == message


def test_the_checker_points_at_the_format(tmp_path: Path) -> None:
    _, result = check_text(tmp_path, """\
robot r { author "tests" }
connection port: serial { baud 115200 }
primitive loose() on port pack "2s{8,8}" (1, 2)
primitive wide() on port pack "<2s{4,4,8}" (16, 1, 1)
""")
    assert result.stderr.replace(str(tmp_path) + "/", "") == """\
error[E301]: bytes split into bit fields are one integer in the format's byte order: `<` (least significant byte first) or `>`
 --> d.rdis:3:33
  |
3 | primitive loose() on port pack "2s{8,8}" (1, 2)
  |                                 ^^

error[E403]: 16 does not fit pack code `2s{4,4,8}` bits 0..3
 --> d.rdis:4:45
  |
4 | primitive wide() on port pack "<2s{4,4,8}" (16, 1, 1)
  |                                             ^^ `2s{4,4,8}` bits 0..3 holds 0 to 15

2 errors emitted
"""


def test_json_and_dump(tmp_path: Path) -> None:
    compilation, built = through_json(RADIO, tmp_path, "radio")
    assert '"pack": "<B6s{11*4,4}"' in built
    assert compilation.model is not None
    assert """\
  request: 7 bytes
  offset  size  kind                  value
       0     1  u8                    0F (15)
       1     6  bits u48 LE           values[0] (bits 0..10), values[1] (bits 11..21), values[2] (bits 22..32), \
values[3] (bits 33..43), flags (bits 44..47)
""" in dump.dump(compilation.model)
