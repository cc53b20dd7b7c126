"""Nothing is silently changed or lost: a constant that does not fit its pack code is a
diagnostic, and a value at run time that does not fit is an RdisValueError, never a
string cut short by struct (runtime and generated driver alike)."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import run_rdisc

from rdisc import engine
from rdisc.emit.python import import_driver
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

HEAD = 'robot r { author "tests" }\nconnection c: serial { baud 9600 }\n'


# A constant that does not fit its pack code is a diagnostic: tests/semantics/cases/security_silent.rdis.


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_string_longer_than_its_code_is_refused_at_run_time(tmp_path: Path, kind: str) -> None:
    source = tmp_path / "named.rdis"
    source.write_text(HEAD + 'primitive name(text: string) on c pack ">B4s" (7, text)\n', encoding="utf-8")
    implementation = load(source) if kind == "runtime" else import_driver(source, tmp_path, "named_driver")
    value_error = engine.RdisValueError if kind == "runtime" else implementation.RdisValueError
    port = ScriptedPort(timeout=1.0)
    with implementation.connect(port, threads=False) as robot:
        robot.call_primitive("name", "AB")
        robot.call_primitive("name", "ABCD")
        with pytest.raises(value_error, match=r"^name: 5 bytes of text do not fit the 4 that value 1 is packed in$"):
            robot.call_primitive("name", "ABCDE")
    assert port.written == b"\x07AB\x00\x00" + b"\x07ABCD"


@pytest.mark.parametrize(("name", "hint"), [
    ("crc16-buypass", None),  # in the catalogue now (CRC-16/BUYPASS, check value 0xFEE8)
    ("crc16-umts", None),  # its alias
    ("crc16-modbsu", "did you mean `crc16-modbus`?"),  # a slip of a name: two letters swapped
    ("crc16-buypas", "did you mean `crc16-buypass`?"),
    ("crc16-bypass", "did you mean `crc16-buypass`?"),
    ("crc16-byupass", "did you mean `crc16-buypass`?"),
    ("crc16-modbus-rtu", 'algorithms: "sum", "xor", "crc"'),  # near in spelling, but not a slip: no other CRC
    ("crc16-ibm", 'algorithms: "sum", "xor", "crc"'),
])
def test_a_checksum_hint_never_names_another_crc(tmp_path: Path, name: str, hint: str | None) -> None:
    source = tmp_path / "d.rdis"
    source.write_text(HEAD + f'frame f {{ payload  checksum "{name}" ">H" }}\n'
                      'primitive p() on c frame f pack "B" (1)\n', encoding="utf-8")
    result = run_rdisc("check", source)
    if hint is None:
        assert result.returncode == 0, result.stderr
        return
    assert result.returncode == 1
    assert f'error[E502]: unknown checksum algorithm "{name}"' in result.stderr
    assert f"= help: {hint}" in result.stderr, result.stderr
