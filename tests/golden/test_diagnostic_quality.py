"""What reviewing the diagnostics found: one diagnostic per fault, and words, not Python.

Each test states how a diagnostic should be; those marked xfail are known
faults of rdisc today (strict: when one is fixed the mark must go).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.compile import compile_path

HEAD = 'robot quality { author "tests" }\n'


def diagnose(tmp_path: Path, text: str) -> list[tuple[str, str]]:
    path = tmp_path / "quality.rdis"
    path.write_text(HEAD + text, encoding="utf-8")
    return [(d.code, d.message) for d in compile_path(str(path)).diagnostics.sorted()]


def codes(tmp_path: Path, text: str) -> list[str]:
    return [code for code, _ in diagnose(tmp_path, text)]


# -- one diagnostic per fault ------------------------------------------------------------


def test_syntax_error_in_an_interface_does_not_make_its_primitives_unused(tmp_path: Path) -> None:
    assert codes(tmp_path, """
connection link: serial { baud 9600 }
primitive ping(x: int) on link pack "B" (x)
interface go() { ping(1 }
input start: Contact -> go()
""") == ["E001"]


def test_invalid_regex_does_not_make_out_indexes_wrong(tmp_path: Path) -> None:
    assert codes(tmp_path, """
state level: int = 0
connection link: serial { baud 9600 threading single at 10 Hz }
primitive read() on link format "R\\n" () regex r"L,(\\d+" { level = int(out[0]) }
interface poll() periodic triggers report { read() }
output report: Range { distance = float(level) }
""") == ["E304"]


def test_misspelt_output_field_is_one_error(tmp_path: Path) -> None:
    assert codes(tmp_path, """
connection link: serial { baud 9600 threading single at 10 Hz }
primitive ping() on link pack "B" (1)
interface poll() periodic triggers report { ping() }
output report: Range { distanse = 1.0 }
""") == ["E206"]


@pytest.mark.parametrize("value", ["1e308 + 1e308", "sqrt(-1.0)", "1 // 0"])
def test_failed_constant_initial_value_is_one_error(tmp_path: Path, value: str) -> None:
    assert codes(tmp_path, f"""
state s: float = {value}
connection link: serial {{ baud 9600 }}
primitive p(x: float) on link pack ">d" (x)
interface go() {{ p(s) }}
input i: Contact -> go()
""") == ["E405"]


def test_division_by_zero_in_an_argument_is_one_error(tmp_path: Path) -> None:
    assert codes(tmp_path, """
connection link: serial { baud 9600 }
primitive p(x: int) on link pack ">h" (x)
interface go() { p(1 // 0) }
input i: Contact -> go()
""") == ["E405"]


# -- a constant that overflows is an error, however it overflows --------------------------


@pytest.mark.parametrize("expr", ["1e308 * 10.0", "1e308 + 1e308", "2.0 ** 2000"])
def test_float_overflow_is_e405(tmp_path: Path, expr: str) -> None:
    assert "E405" in codes(tmp_path, f"""
connection link: serial {{ baud 9600 }}
primitive p(x: float) on link pack ">d" (x)
interface go() {{ p({expr}) }}
input i: Contact -> go()
""")


def test_float_overflow_by_division_is_e405(tmp_path: Path) -> None:
    assert "E405" in codes(tmp_path, """
connection link: serial { baud 9600 }
primitive p(x: float) on link pack ">d" (x)
interface go() { p(1e308 / 0.1) }
input i: Contact -> go()
""")


# -- words, not Python --------------------------------------------------------------------


def message_of(tmp_path: Path, code: str, text: str) -> str:
    found = [m for c, m in diagnose(tmp_path, text) if c == code]
    assert found, diagnose(tmp_path, text)
    return found[0]


ARGUMENT = """
connection link: serial {{ baud 9600 }}
primitive p(x: {type}) on link pack "{pack}" (x)
interface go() {{ p({expr}) }}
input i: Contact -> go()
"""


def test_float_power_overflow_is_said_in_words(tmp_path: Path) -> None:
    message = message_of(tmp_path, "E405", ARGUMENT.format(type="float", pack=">d", expr="10.0 ** 400"))
    assert "(34," not in message and "Numerical result" not in message
    assert "too large" in message or "overflow" in message


def test_math_domain_error_is_said_in_words(tmp_path: Path) -> None:
    message = message_of(tmp_path, "E405", ARGUMENT.format(type="float", pack=">d", expr="sqrt(-1.0)"))
    assert ",)" not in message and "math domain error" not in message


def test_huge_int_to_float_is_said_briefly(tmp_path: Path) -> None:
    message = message_of(tmp_path, "E405", ARGUMENT.format(type="float", pack=">d", expr="float(10 ** 400)"))
    assert len(message) < 160, message


def test_huge_value_out_of_range_is_said_briefly(tmp_path: Path) -> None:
    message = message_of(tmp_path, "E403", """
connection link: serial { baud 9600 }
primitive p() on link pack ">q" (int(1e308) << 10)
interface go() { p() }
input i: Contact -> go()
""")
    assert len(message) < 160, message


@pytest.mark.parametrize("field, word", [("{0.__class__}", "attribute"), ("{0[0]}", "index")])
def test_format_field_access_is_named_for_what_it_is(tmp_path: Path, field: str, word: str) -> None:
    message = message_of(tmp_path, "E303", f"""
connection link: serial {{ baud 9600 }}
primitive p(x: int) on link format "{field}" (x)
interface go() {{ p(1) }}
input i: Contact -> go()
""")
    assert word in message and "not positional" not in message


def test_syntax_error_lists_only_tokens_that_can_follow(tmp_path: Path) -> None:
    message = message_of(tmp_path, "E001", """
connection link: serial { baud 9600 }
primitive p(x: int) on link pack ">q" (lambda: 1)
interface go() { p(1) }
input i: Contact -> go()
""")
    assert "`}`" not in message and "`]`" not in message and "a name" not in message, message


def test_constant_argument_that_does_not_fit_the_pack_code_is_e403(tmp_path: Path) -> None:
    assert "E403" in codes(tmp_path, """
connection link: serial { baud 9600 }
primitive p(x: int) on link pack ">B" (x)
interface go() { p(300) }
input i: Contact -> go()
""")


def test_syntax_error_in_the_robot_does_not_say_there_is_no_robot(tmp_path: Path) -> None:
    path = tmp_path / "robot.rdis"
    path.write_text('robot r { author }\nconnection link: serial { baud 9600 }\n', encoding="utf-8")
    assert [d.code for d in compile_path(str(path)).diagnostics.items] == ["E001"]
