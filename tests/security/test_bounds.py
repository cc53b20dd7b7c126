"""Integers have one width everywhere: 64 bits and a sign, in literals, constant folding,
state and at run time, in the runtime and in generated drivers alike; nothing a
description does can make a number grow without bound."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import check_text, run_rdisc

from rdisc import engine, limits
from rdisc.emit.python import import_driver
from rdisc.runtime import load
from tests.support.ports import ScriptedPort


def test_the_engine_keeps_the_same_width() -> None:
    assert engine.MAX_INT == limits.MAX_INT == 2**64 - 1


def test_constants_that_grow_are_refused_at_the_first_that_does_not_fit(tmp_path: Path) -> None:
    """The issue's chain: 2 ** 2000, then 22 squarings (78 s and 4.3 GB before). One error,
    at the first constant; the ones built on it are not reported again."""
    lines = ['robot r { author "tests" }', "const A0 = 2 ** 2000"]
    lines += [f"const A{i} = A{i - 1} * A{i - 1}" for i in range(1, 23)]
    source, result = check_text(tmp_path, "\n".join(lines) + "\n")
    assert result.returncode == 1
    assert result.stderr.startswith(
        "error[E405]: a 2001-bit integer is too large: integers are limited to 64 bits and a sign "
        "(-18446744073709551615..18446744073709551615)\n"
        f" --> {source}:2:12\n"), result.stderr
    assert result.stderr.count("error[") == 1


# Literals and folded constants within 64 bits, and the largest kept: tests/semantics/cases/security_bounds.rdis.


def test_a_json_integer_past_64_bits_is_refused(tmp_path: Path) -> None:
    source = tmp_path / "d.json"
    source.write_text('{"name": "r", "constants": {"A": 18446744073709551616}}', encoding="utf-8")
    result = run_rdisc("check", source)
    assert result.returncode == 1
    assert ("error[E004]: integer 18446744073709551616 is too large: integers are limited to 64 bits and a sign "
            "(at most 18446744073709551615 either way)\n") in result.stderr, result.stderr


SQUARING = """\
robot squaring { author "tests" }
state x: int = 3
state y: int = 0
connection c: serial { baud 9600 }
primitive square() on c pack "B" (1) { x = x * x }
primitive tower() on c pack "B" (2) { y = ((((x * x) * (x * x)) * ((x * x) * (x * x))) * (((x * x) * (x * x)) * ((x * x) * (x * x)))) }
"""


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_post_action_cannot_grow_a_number_without_bound(tmp_path: Path, kind: str) -> None:
    """`x = x * x` again and again: the call that would store more than 64 bits is refused
    with a typed error naming the primitive; the state keeps its last value."""
    source = tmp_path / "squaring.rdis"
    source.write_text(SQUARING, encoding="utf-8")
    implementation = load(source) if kind == "runtime" else import_driver(source, tmp_path, "squaring_driver")
    value_error = engine.RdisValueError if kind == "runtime" else implementation.RdisValueError
    with implementation.connect(ScriptedPort(timeout=1.0), threads=False) as robot:
        for expected in (9, 81, 6561, 43046721, 1853020188851841, 3433683820292512484657849089281):
            if expected > limits.MAX_INT:
                with pytest.raises(value_error, match=r"^square: x would be a 102-bit integer; integers are "
                                                      r"limited to 64 bits and a sign$"):
                    robot.call_primitive("square")
                assert robot.state["x"] == 1853020188851841
                break
            robot.call_primitive("square")
            assert robot.state["x"] == expected
        with pytest.raises(value_error, match=r"^tower: "):  # 2**16 times the bits of x inside one expression
            robot.call_primitive("tower")


def test_a_line_past_the_limit_is_refused_before_parsing(tmp_path: Path) -> None:
    """The issue's 8 MB string literal (29 s and 3.4 GB before): refused at the line, which the
    parser never sees; so is a chain of a million `+` on one line."""
    text = 'robot r { author "tests" }\nconst S = "' + "a" * 100_000 + '"\nconst T = ' + " + ".join(["1"] * 30_000)
    _source, result = check_text(tmp_path, text + "\n")
    assert result.returncode == 1
    errors = [line for line in result.stderr.splitlines() if line.startswith("error[")]
    assert errors == ["error[E005]: line of 100012 characters; the limit is 65536",
                      "error[E005]: line of 120007 characters; the limit is 65536"], result.stderr[:2000]
    assert max(len(line) for line in result.stderr.splitlines()) < 300  # the excerpt shows a window of the line


def test_a_declaration_of_too_many_tokens_is_refused_before_parsing(tmp_path: Path) -> None:
    text = 'robot r { author "tests" }\nconst T = 0\n' + "".join("    + 1\n" for _ in range(12_000))
    source, result = check_text(tmp_path, text)
    assert result.returncode == 1
    assert result.stderr.startswith(
        "error[E005]: declaration has more than 20000 tokens; split it, or make it simpler\n"
        f" --> {source}:2:1\n"), result.stderr[:2000]


# A range's bound is a finite number, a default is kept in 64 bits: tests/semantics/cases/security_bounds.rdis.
