"""Numbers in bytes of a length known only at run time, and text as hex: `int_le`, `int_be`,
`f32le`/`f32be`/`f64le`/`f64be` and their `from_` inverses, `nibbles` and `from_nibbles`,
`upper` and `unhex` (issue 23, construct 6). Each is typed and folded by the checker and run
by the runtime and a generated driver through the one module of operations
(rdisc.engine.operations), with the same bytes written, the same state and the same errors;
the operations agree with `struct` and `int.from_bytes` and each pair round-trips."""

from __future__ import annotations

import math
import struct
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.engine import operations
from rdisc.json_import.document import read
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.conftest import fuzz_examples
from tests.engine.test_one_engine import ScriptedPort, implementation_of, through_json

# A pan-tilt camera in the manner of Sony's VISCA (a position as four bytes of one nibble each,
# the frame ended by FF), with a speed sent as an IEEE float and a serial number read as hex.
CAMERA = """\
robot camera { author "tests" }
state position: int
state speed: float
state wide: float
state counter: int
state serial: bytes
state name: string
connection link: serial { baud 9600 }
frame visca { payload terminator "\\xff" }
primitive pan(p: int in 0..65535) on link frame visca pack ">BB*" (0x81, 0x01, nibbles(p, 4))
primitive where() on link frame visca pack "BB" (0x81, 0x09) unpack "B*" { position = from_nibbles(out[1]) }
primitive set_speed(v: float) on link pack "B*" (0x10, f32le(v))
primitive set_wide(v: float) on link pack "B*" (0x11, f64be(v))
primitive speeds() on link frame visca pack "B" (0x12) unpack "*" {
    speed = from_f32be(out[0]) if len(out[0]) == 4 else speed
    wide = from_f64le(out[0]) if len(out[0]) != 4 else wide
}
primitive count() on link frame visca pack "B" (0x13) unpack "B*" {
    counter = int_le(out[1], True) if out[0] == 1 else int_be(out[1])
}
primitive ident(key: bytes) on link format "ID{}\\r" (upper(hex(key))) regex "^S([0-9a-fA-F]*) ([a-z]*)$" {
    serial = unhex(out[0])
    name = upper(out[1])
}
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_values_become_bytes_and_bytes_values(kind: str, tmp_path: Path) -> None:
    replies = (b"\x90\x01\x02\x03\x04\xff"  # where: 0x1234 in nibbles
               + b"\x3f\xc0\x00\x00\xff"  # speeds: 1.5 as a big-endian f32
               + b"\x01\xfe\x80\xff"  # count: -32514 in two signed little-endian bytes
               + b"\x02\x01\x00\x00\xff"  # count: 0x10000 in three big-endian bytes
               + b"S0a1B abc\n")
    port = ScriptedPort(replies)
    with implementation_of(kind, CAMERA, tmp_path, "camera").connect(port, threads=False) as robot:
        robot.call_primitive("pan", 0x1234)
        robot.call_primitive("set_speed", 1.5)
        robot.call_primitive("set_wide", 2)
        assert bytes(port.written).hex(" ") == "81 01 01 02 03 04 ff 10 00 00 c0 3f 11 40 00 00 00 00 00 00 00"
        port.written.clear()
        robot.call_primitive("where")
        robot.call_primitive("speeds")
        robot.call_primitive("count")
        assert robot.state["counter"] == -32514
        robot.call_primitive("count")
        robot.call_primitive("ident", b"\xab\x01")
        assert bytes(port.written) == b"\x81\x09\xff\x12\xff\x13\xff\x13\xffIDAB01\r"
        assert dict(robot.state) == {"position": 0x1234, "speed": 1.5, "wide": 0.0, "counter": 0x10000,
                                     "serial": b"\x0a\x1b", "name": "ABC"}


@pytest.mark.parametrize(("call", "reply", "message"), [
    (("pan", 70000), b"", "pan: parameter p is 70000, outside 0..65535"),
    (("set_speed", 1e300), b"", "set_speed: f32le(1e+300): too large for a 32-bit float"),
    (("where",), b"\x90\x01\x10\x03\x04\xff", "where: from_nibbles(): byte 1 is 0x10, not a nibble"),
    (("where",), b"\x90" + bytes(17) + b"\xff", "where: from_nibbles(): 17 bytes, more than 16 nibbles (a 64-bit int)"),
    (("count",), b"\x01" + bytes(9) + b"\xff", "count: int_le(): 9 bytes, more than 8 (a 64-bit int)"),
    (("speeds",), b"\x01\x02\xff", "speeds: from_f64le(): 2 bytes, not 8"),
    (("ident", b""), b"S0a1 x\n", "ident: unhex(): an odd number of hex digits (3)"),
])
@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_what_does_not_convert_is_an_error_of_the_primitive(kind: str, call: tuple[object, ...], reply: bytes,
                                                             message: str, tmp_path: Path) -> None:
    port = ScriptedPort(reply)
    with implementation_of(kind, CAMERA, tmp_path, "camera").connect(port, threads=False) as robot:
        with pytest.raises(ValueError) as caught:
            robot.call_primitive(*call)
        assert (type(caught.value).__name__, str(caught.value)) == ("RdisValueError", message)
        assert dict(robot.state)["position"] == 0 and robot.state["serial"] == b""  # nothing kept
        if not reply:
            assert bytes(port.written) == b""  # refused before anything is written


def test_constants_are_folded_at_check_time(tmp_path: Path) -> None:
    source = tmp_path / "folded.rdis"
    source.write_text("""\
robot folded { author "tests" }
const A = int_le(b"\\x01\\x02")
const B = int_be(b"\\xff\\xfe", True)
const C = int_be(b"")
const D = f32le(1.5)
const E = from_f64be(f64be(2.25))
const F = nibbles(0x1234, 4)
const G = from_nibbles(F)
const H = upper("ab1f")
const I = unhex("0A1b")
const J = upper(b"ab\\xff")
const K = from_f32le(D) + from_f32be(f32be(3))
const L = f64le(1)
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None, [d.message for d in compilation.diagnostics.items]
    assert dict(compilation.model.constants) == {
        "A": 0x0201, "B": -2, "C": 0, "D": b"\x00\x00\xc0\x3f", "E": 2.25, "F": b"\x01\x02\x03\x04", "G": 0x1234,
        "H": "AB1F", "I": b"\x0a\x1b", "J": b"AB\xff", "K": 4.5, "L": b"\x00\x00\x00\x00\x00\x00\xf0\x3f"}


def test_what_the_checker_refuses(tmp_path: Path) -> None:
    source = tmp_path / "bad.rdis"
    source.write_text("""\
robot bad { author "tests" }
const A = int_le(b"123456789")
const B = unhex("0a 1b")
const C = unhex("abc")
const D = from_f32le(b"abc")
const E = f32be(1e39)
const F = nibbles(16, 1)
const G = nibbles(1, 17)
const H = nibbles(-1, 2)
const I = from_nibbles(b"\\x01\\xf0")
const J = int_le("0102")
const K = int_be(b"\\x01", 1)
const L = f64le(b"x")
const M = from_f64be(1.0)
const N = nibbles(1.5, 2)
const O = upper(1)
const P = unhex(b"0a")
const Q = int_le()
const R = from_nibbles(b"", 2)
state upper: int
link upper {}
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E104", "`upper` is a built-in function and cannot name a state variable"),
        ("E405", "int_le(): 9 bytes, more than 8 (a 64-bit int)"),
        ("E405", "unhex(): character 2 is ' ', not a hex digit"),
        ("E405", "unhex(): an odd number of hex digits (3)"),
        ("E405", "from_f32le(): 3 bytes, not 4"),
        ("E405", "f32be(1e+39): too large for a 32-bit float"),
        ("E405", "nibbles(): 16 does not fit in 1 nibble"),
        ("E405", "nibbles(): 17 nibbles, not 1 to 16"),
        ("E405", "nibbles(): -1 does not fit in 2 nibbles"),
        ("E405", "from_nibbles(): byte 1 is 0xf0, not a nibble"),
        ("E404", "`int_le` takes bytes and, if signed, `True`: `int_le(out[1])`, `int_le(out[1], True)`"),
        ("E404", "`int_be` takes bytes and, if signed, `True`: `int_be(out[1])`, `int_be(out[1], True)`"),
        ("E404", "`f64le` needs a number, not bytes"),
        ("E404", "`from_f64be` needs bytes, not a float"),
        ("E404", "`nibbles` takes an int and a count of nibbles: `nibbles(position, 4)`"),
        ("E404", "`upper` needs a string or bytes, not an int"),
        ("E404", "`unhex` needs a string of hex digits, not bytes"),
        ("E201", "`int_le` takes 1 to 2 arguments, but 0 given"),
        ("E201", "`from_nibbles` takes 1 argument, but 2 given"),
        ("W103", "state variable `upper` is never used"),
    ]


def test_the_functions_go_through_json_and_the_printer(tmp_path: Path) -> None:
    compilation, built = through_json(CAMERA, tmp_path, "camera")
    assert not compilation.diagnostics.items
    assert '"<nibbles(p, 4)>"' in built and '"<f32le(v)>"' in built and '"<upper(hex(key))>"' in built
    assert '"counter = int_le(__out__[1], True) if __out__[0] == 1 else int_be(__out__[1])"' in built
    module = parse("t.rdis", CAMERA, Diagnostics())
    printed = print_module(module)
    assert "pack \">BB*\" (129, 1, nibbles(p, 4))" in printed and "serial = unhex(out[0])" in printed
    assert module == parse("t.rdis", printed, Diagnostics())
    imported = read("camera.json", built, Diagnostics())  # `rdisc import`: the JSON back as a description
    assert imported is not None and "counter = int_le(out[1], True) if out[0] == 1 else int_be(out[1])" in \
        print_module(imported)


def test_a_driver_calls_the_carried_operations(tmp_path: Path) -> None:
    driver = implementation_of("driver", CAMERA, tmp_path, "camera_source")
    text = Path(driver.__file__).read_text(encoding="utf-8")
    assert "_nibbles(p, 4)" in text and "_f32le(v)" in text and "_upper(_hex(key))" in text
    assert "def _from_nibbles(data: bytes) -> int:" in text and "_f32le, _from_f32le = _float_bytes" in text


# ---- the operations themselves, against Python's own ------------------------------------------------

FEW = settings(max_examples=fuzz_examples(60), deadline=None, derandomize=True, database=None)
LAYOUTS = [("f32le", "<f"), ("f32be", ">f"), ("f64le", "<d"), ("f64be", ">d")]


@FEW
@given(data=st.binary(max_size=8), signed=st.booleans())
def test_int_le_and_int_be_agree_with_int_from_bytes(data: bytes, signed: bool) -> None:
    assert operations.FUNCTIONS["int_le"](data, signed) == int.from_bytes(data, "little", signed=signed)
    assert operations.FUNCTIONS["int_be"](data, signed) == int.from_bytes(data, "big", signed=signed)
    assert operations.FUNCTIONS["int_le"](data) == int.from_bytes(data, "little")


@FEW
@given(value=st.floats(allow_nan=False) | st.integers(-2**53, 2**53), which=st.sampled_from(LAYOUTS))
def test_floats_to_bytes_agree_with_struct_and_come_back(value: float, which: tuple[str, str]) -> None:
    name, code = which
    try:
        expected = struct.pack(code, value)
    except OverflowError:
        with pytest.raises(operations.EvalError, match=f"^{name}\\(.*\\): too large for a (32|64)-bit float$"):
            operations.FUNCTIONS[name](value)
        return
    data = operations.FUNCTIONS[name](value)
    assert data == expected
    back = operations.FUNCTIONS["from_" + name](data)
    assert back == struct.unpack(code, data)[0]
    if code[1] == "d":
        assert back == value
    assert operations.FUNCTIONS[name](back) == data  # a float of the width comes back exactly


@FEW
@given(data=st.binary(min_size=0, max_size=10), which=st.sampled_from(LAYOUTS))
def test_bytes_to_floats_agree_with_struct(data: bytes, which: tuple[str, str]) -> None:
    name, code = which
    if len(data) != struct.calcsize(code):
        with pytest.raises(ValueError, match=f"^from_{name}\\(\\): {len(data)} bytes, not {struct.calcsize(code)}$"):
            operations.FUNCTIONS["from_" + name](data)
        return
    value, expected = operations.FUNCTIONS["from_" + name](data), struct.unpack(code, data)[0]
    assert value == expected or (math.isnan(value) and math.isnan(expected))


@FEW
@given(count=st.integers(1, 16), data=st.data())
def test_nibbles_round_trip(count: int, data: st.DataObject) -> None:
    value = data.draw(st.integers(0, 16**count - 1))
    spread = operations.FUNCTIONS["nibbles"](value, count)
    assert len(spread) == count and all(b <= 0xF for b in spread)
    assert spread.hex()[1::2] == f"{value:0{count}x}"  # one hex digit a byte, most significant first
    assert operations.FUNCTIONS["from_nibbles"](spread) == value


@FEW
@given(data=st.binary(max_size=64))
def test_unhex_and_upper_undo_hex(data: bytes) -> None:
    digits = operations.FUNCTIONS["hex"](data)
    assert operations.FUNCTIONS["upper"](digits) == data.hex().upper()
    assert operations.FUNCTIONS["unhex"](digits) == data == operations.FUNCTIONS["unhex"](digits.upper())
