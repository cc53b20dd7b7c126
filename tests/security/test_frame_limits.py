"""Frames refuse what they cannot carry, at check time where the values are known and at
run time otherwise, in the runtime and in generated drivers alike: a frame parameter's
range, a length field's capacity, a computed field's pack code. Nothing is cut or
wrapped silently, and nothing is written for a call that is refused."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from conftest import check_text

from tests.engine.test_one_engine import ScriptedPort, implementation_of

HEAD = """\
robot limits { author "tests" }
frame c(id: int in 0..253) {
    header "\\xFF"
    field id "B" = id
    length "B" = payload
    payload
}
frame tagged(kind: int) {
    field code "B" = kind | 0x80
    payload
}
connection link: serial { baud 9600 }
"""

RUNS = HEAD + """\
primitive ping(id: int) on link frame c(id) pack "B" (1)
primitive blob(data: bytes) on link frame c(1) pack "*" (data)
primitive mark(kind: int) on link frame tagged(kind) pack "B" (2)
"""


def test_a_constant_argument_outside_a_frame_parameters_range_is_an_error(tmp_path: Path) -> None:
    source, result = check_text(tmp_path, HEAD + 'primitive bad() on link frame c(254) pack "B" (1)\n')
    assert result.returncode == 1
    assert result.stderr == (
        "error[E403]: 254 is outside the range of parameter `id` of frame `c`\n"
        f"  --> {source}:13:33\n"
        "   |\n"
        '13 | primitive bad() on link frame c(254) pack "B" (1)\n'
        "   |                                 ^^^ in 0..253\n"
        "\n"
        "1 error emitted\n"
    )


def test_a_length_field_must_state_every_payload_a_bytes_range_allows(tmp_path: Path) -> None:
    source, result = check_text(tmp_path, HEAD + 'primitive blob(data: bytes in 0..300) on link frame c(1) pack "B*" (7, data)\n')
    assert result.returncode == 1
    assert result.stderr == (
        'error[E503]: the length field "B" of frame `c` cannot state every payload of `blob`: 1 to 301 bytes, '
        "as parameter `data` allows\n"
        f"  --> {source}:13:47\n"
        "   |\n"
        '13 | primitive blob(data: bytes in 0..300) on link frame c(1) pack "B*" (7, data)\n'
        "   |                                               ^^^^^^^^^^\n"
        "   |\n"
        "   = help: it states payloads of 0 to 255 bytes; narrow the range of parameter `data`\n"
        "\n"
        "1 error emitted\n"
    )
    _, fine = check_text(tmp_path, HEAD + 'primitive blob(data: bytes in 0..254) on link frame c(1) pack "B*" (7, data)\n')
    assert fine.returncode == 0, fine.stderr


def test_a_computed_field_of_constant_arguments_must_fit_its_code(tmp_path: Path) -> None:
    source, result = check_text(tmp_path, HEAD + 'primitive bad() on link frame tagged(0x100) pack "B" (1)\n')
    assert result.returncode == 1
    assert result.stderr == (
        "error[E403]: 384 does not fit pack code `B` as field `code` of frame `tagged`\n"
        f"  --> {source}:13:25\n"
        "   |\n"
        '13 | primitive bad() on link frame tagged(0x100) pack "B" (1)\n'
        "   |                         ^^^^^^^^^^^^^^^^^^^ field `code` is packed as `B`, 0 to 255\n"
        "\n"
        "1 error emitted\n"
    )
    _, fine = check_text(tmp_path, HEAD + 'primitive good() on link frame tagged(0x7F) pack "B" (1)\n')
    assert fine.returncode == 0, fine.stderr


@pytest.fixture(scope="module", params=["runtime", "driver"])
def robot(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    implementation = implementation_of(request.param, RUNS, tmp_path_factory.mktemp("frame_limits"), "limits")
    port = ScriptedPort()
    with implementation.connect(port, threads=False) as robot:
        robot.port_for_tests = port
        yield robot


@pytest.mark.parametrize(("call", "message"), [
    (("ping", 254), "ping: frame c: parameter id is 254, outside 0..253"),
    (("ping", -1), "ping: frame c: parameter id is -1, outside 0..253"),
    (("blob", b"x" * 256), "blob: frame c: a 256-byte payload is more than its length field states (255 bytes)"),
    (("mark", 0x100), "mark: ubyte format requires 0 <= number <= 255"),
])
def test_a_call_the_frame_cannot_carry_is_refused_and_nothing_is_written(robot: Any, call: tuple, message: str) -> None:
    port = robot.port_for_tests
    port.written.clear()
    with pytest.raises(ValueError) as caught:  # a driver's RdisValueError is its own class
        robot.call_primitive(*call)
    assert type(caught.value).__name__ == "RdisValueError"
    assert str(caught.value) == message
    assert bytes(port.written) == b""


@pytest.mark.parametrize(("call", "written"), [
    (("ping", 253), "fd 01 01"),
    (("ping", 0), "00 01 01"),
    (("blob", b"x" * 255), "01 ff" + " 78" * 255),
    (("mark", 0x7F), "ff 02"),
])
def test_a_call_within_the_limits_is_written_whole(robot: Any, call: tuple, written: str) -> None:
    port = robot.port_for_tests
    port.written.clear()
    robot.call_primitive(*call)
    assert bytes(port.written) == b"\xff" * (call[0] != "mark") + bytes.fromhex(written)


def test_an_argument_of_another_type_is_one_type_error(tmp_path: Path) -> None:
    """Found by the fuzzer: a string where a ranged int goes was compared with the range."""
    _source, result = check_text(tmp_path, HEAD + 'primitive bad() on link frame c("x") pack "B" (1)\n'
                                           'primitive worse() on link frame tagged(2.5) pack "B" (1)\n')
    assert result.returncode == 1
    assert [line for line in result.stderr.splitlines() if line.startswith(("error", "rdisc:"))] == [
        "error[E401]: parameter `id` of frame `c` takes an int, but this is a string",
        "error[E402]: parameter `kind` of frame `tagged` takes an int, but this is a float",
    ]
