"""Integers a description keeps (a table's keys and values, a stated number of stop bits) hold
64 bits and a sign, as constants do: found by the mutants (a table value `10 ** 400` was kept and
then refused by `rdisc import` of the JSON it built; `stopbits 2 ** 1100` raised OverflowError)."""

from __future__ import annotations

from rdisc.compile import compile_text

HEAD = 'robot r { author "a" }\n'


def messages(text: str) -> list[tuple[str, str]]:
    return [(d.code, d.message) for d in compile_text("huge.rdis", HEAD + text).diagnostics.sorted()]


def test_a_table_value_or_key_over_64_bits_is_e405() -> None:
    limit = "integers are limited to 64 bits and a sign (-18446744073709551615..18446744073709551615)"
    assert messages("const T = { 1: 10 ** 400 }\n") == [("E405", f"a 1329-bit integer is too large: {limit}")]
    assert messages("const T = { 2 ** 70: 1 }\n") == [("E405", f"{2 ** 70} is too large: {limit}")]


def test_stop_bits_of_a_huge_integer_are_refused_without_an_overflow() -> None:
    (found,) = messages("connection bus: serial { baud 9600 stopbits 2 ** 1100 }\n")
    assert found[0] == "E215" and found[1].endswith(f"stop bits, not {2 ** 1100}")
