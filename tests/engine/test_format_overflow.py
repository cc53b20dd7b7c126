"""A `format` request whose value does not fit its conversion (`{:c}` of 2**40, past the last
code point) is an RdisValueError naming the primitive, in the runtime and a driver alike, and
nothing is written."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.engine.test_one_engine import ScriptedPort, implementation_of

CHAR = """\
robot chars { author "tests" }
connection link: serial { baud 9600 }
primitive send_char(code: int) on link format "{:c}\\n" (code)
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_character_past_the_last_code_point_is_a_value_error(kind: str, tmp_path: Path) -> None:
    port = ScriptedPort()
    with implementation_of(kind, CHAR, tmp_path, "chars").connect(port, threads=False) as robot:
        robot.call_primitive("send_char", 65)
        assert bytes(port.written) == b"A\n"
        port.written.clear()
        with pytest.raises(ValueError) as caught:
            robot.call_primitive("send_char", 2**40)
        assert type(caught.value).__name__ == "RdisValueError"
        assert str(caught.value).startswith("send_char: "), caught.value
        assert bytes(port.written) == b""
