"""Noise on a state variable (thesis §7.2.3): the error of the values a device reports into it,
`state level: float = 0.0 noise 0.5 "mm"` or a covariance over an array's values; checked as an
output's noise is (E731, E733), printed, and through JSON both ways."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import through_json

TEXT = '''robot ranger { author "t" }
state level: float = 0.0 noise 0.5 "mm"
state pair: int[2] = [0, 0] noise [1, 0.5; 0.5, 1]
state plain: int = 0
connection port: serial { baud 9600 }
primitive level() on port pack "B" (1) unpack "BBB" { level = out[0]  pair[0] = out[1]  pair[1] = out[2] }
interface watch() { level() }
'''


def errors(tmp_path: Path, text: str) -> list[tuple[str, str, str]]:
    path = tmp_path / "noise.rdis"
    path.write_text(text, encoding="utf-8")
    compilation = compile_path(str(path))
    return [(d.code, text[d.span.start:d.span.end], d.message) for d in compilation.diagnostics.sorted()
            if d.severity == 1]


def test_state_noise_is_in_the_model(tmp_path: Path) -> None:
    path = tmp_path / "ranger.rdis"
    path.write_text(TEXT, encoding="utf-8")
    model = compile_path(str(path)).model
    assert model is not None
    states = model.states
    assert states["level"].noise is not None and states["level"].noise.covariance == ((0.25,),)
    assert (states["level"].noise.deviation, states["level"].noise.unit) == (0.5, "mm")
    assert states["pair"].noise is not None and states["pair"].noise.covariance == ((1.0, 0.5), (0.5, 1.0))
    assert states["plain"].noise is None


SMALL = "the covariance of `pair` is 1 by 1, the state variable 2 values"
NOT_SEMIDEFINITE = ("the covariance of `pair` is not positive semi-definite: some combination of its values "
                    "would have a negative variance")


@pytest.mark.parametrize(("change", "found"), [
    (('noise 0.5 "mm"', "noise -0.5"), ("E731", "noise -0.5", "noise of `level` is a deviation of -0.5: not negative")),
    (("noise [1, 0.5; 0.5, 1]", "noise [1]"), ("E731", "[1]", SMALL)),
    (("noise [1, 0.5; 0.5, 1]", "noise [1, 2; 2, 1]"),
     ("E733", "[1, 2; 2, 1]", NOT_SEMIDEFINITE)),
    (("state plain: int = 0", 'state plain: string = "" noise 1'),
     ("E731", "noise 1", "state variable `plain` is string, not numbers: it has no noise")),
])
def test_each_refusal_says_what_is_wrong(tmp_path: Path, change: tuple[str, str], found: tuple[str, str, str]) -> None:
    assert TEXT.count(change[0]) == 1
    assert errors(tmp_path, TEXT.replace(change[0], change[1])) == [found]


def test_state_noise_prints_and_parses_back_alike() -> None:
    first = parse("a.rdis", TEXT, Diagnostics())
    printed = print_module(first)
    assert 'state level: float = 0.0 noise 0.5 "mm"\n' in printed
    assert "state pair: int[2] = [0, 0] noise [1.0, 0.5; 0.5, 1.0]\n" in printed
    assert parse("b.rdis", printed, Diagnostics()).decls == first.decls


def test_state_noise_goes_through_json_and_back(tmp_path: Path) -> None:
    _, built = through_json(TEXT, tmp_path, "ranger")
    states = {s["name"]: s for s in json.loads(built)["stateVariables"]}
    assert states["level"]["noise"] == {"deviation": 0.5, "unit": "mm"}
    assert states["pair"]["noise"] == {"covariance": [[1, 0.5], [0.5, 1]]}
    assert "noise" not in states["plain"]


SENSOR = '''robot ranger { author "t" }
connection port: serial { baud 9600 }
primitive distance() on port pack "B" (1) unpack "<f"
sensor range_m: float from distance() cache 100 ms noise 0.01 "m"
output range: Range { distance = range_m }
interface watch() triggers range {}
'''


def test_a_sensor_declares_noise_checked_printed_and_through_json(tmp_path: Path) -> None:
    compilation, built = through_json(SENSOR, tmp_path, "ranger")
    assert compilation.model is not None
    noise = compilation.model.sensors["range_m"].noise
    assert noise is not None and (noise.deviation, noise.unit, noise.covariance) == (0.01, "m", ((0.0001,),))
    (sensor,) = json.loads(built)["sensors"]
    assert sensor["noise"] == {"deviation": 0.01, "unit": "m"}
    first = parse("a.rdis", SENSOR, Diagnostics())
    printed = print_module(first)
    assert 'sensor range_m: float from distance() cache 100 ms noise 0.01 "m"\n' in printed
    assert parse("b.rdis", printed, Diagnostics()).decls == first.decls
    assert errors(tmp_path, SENSOR.replace("noise 0.01", "noise -0.01")) == [
        ("E731", 'noise -0.01 "m"', "noise of `range_m` is a deviation of -0.01: not negative")]
