"""An output's error models and Kalman filters (rdisc/semantics/check/noise.py, thesis §7.2.3),
each refusal with its exact diagnostic; the clauses through the printer and JSON both ways."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_module
from tests.engine.test_one_engine import through_json

HEAD = '''robot ranger { author "t" }
state level: int = 0
state counts: int = 0
connection port: serial { baud 9600 }
primitive level() on port pack "B" (1) unpack "B" { level = out[0] }
interface watch() triggers range { level() }
'''
FILTER = '''    filter distance kalman {
        state [0, 0]
        transition [1, 0.05; 0, 1]
        process [0.000001, 0; 0, 0.0001]
        measurement [1, 0]
        noise 0.0001
    }
'''
RANGE = 'output range: Range {\n    distance = level / 1000.0\n    noise distance 0.01 "m"\n' + FILTER + "}\n"


def errors(tmp_path: Path, text: str) -> list[tuple[str, str, str]]:
    path = tmp_path / "noise.rdis"
    path.write_text(HEAD + text, encoding="utf-8")
    compilation = compile_path(str(path))
    whole = HEAD + text
    return [(d.code, whole[d.span.start:d.span.end], d.message) for d in compilation.diagnostics.sorted()
            if d.severity == 1]


def test_a_range_with_noise_and_a_filter_checks(tmp_path: Path) -> None:
    assert errors(tmp_path, RANGE) == []


@pytest.mark.parametrize(("change", "found"), [
    (('noise distance 0.01 "m"', 'noise distance 0.01 "mm"'),
     ("E731", '"mm"', 'noise of `distance` is in "mm", the field in "m"')),
    (('noise distance 0.01 "m"', "noise distance -0.01"),
     ("E731", "noise distance -0.01", "noise of `distance` is a deviation of -0.01: not negative")),
    (('noise distance 0.01 "m"', "noise distance [1, 0; 0, 1]"),
     ("E731", "[1, 0; 0, 1]", "the covariance of `distance` is 2 by 2, the field 1 value")),
    (('noise distance 0.01 "m"', "noise distance [1, 2; 3, 4]"),
     ("E731", "[1, 2; 3, 4]",
      "the covariance of `distance` is not symmetric: row 2, column 1 is 3.0, row 1, column 2 2.0")),
    (('noise distance 0.01 "m"', "noise distance [-1]"),
     ("E731", "[-1]", "the covariance of `distance` has -1.0 on its diagonal: a variance is not negative")),
    (('noise distance 0.01 "m"', "noise distanse 0.01"),
     ("E731", "distanse", "adapter `Range` has no field `distanse`")),
    (("measurement [1, 0]", "measurement [1, 0; 0, 1]"),
     ("E732", "[1, 0; 0, 1]", "the filter's `measurement` has 2 rows, field `distance` 1 value")),
    (("transition [1, 0.05; 0, 1]", "transition [1, 0.05]"),
     ("E732", "[1, 0.05]", "the filter's `transition` is 1 by 2, not 2 by 2")),
    (("process [0.000001, 0; 0, 0.0001]", "process [0.000001, 1; 0, 0.0001]"),
     ("E732", "[0.000001, 1; 0, 0.0001]",
      "the filter's `process` is not symmetric: row 2, column 1 is 0.0, row 1, column 2 1.0")),
    (("noise 0.0001\n", "noise -0.0001\n"),
     ("E732", "noise", "the filter's `noise` has -0.0001 on its diagonal: a variance is not negative")),
    (("        noise 0.0001\n", ""),
     ("E732", FILTER.replace("        noise 0.0001\n", "").strip(), "the filter of `distance` does not give `noise`")),
    (("state [0, 0]", "state [0, 0]\n        state [0, 0]"),
     ("E732", "state", "the filter of `distance` gives `state` twice")),
])
def test_each_refusal_says_what_is_wrong(tmp_path: Path, change: tuple[str, str], found: tuple[str, str, str]) -> None:
    assert RANGE.count(change[0]) == 1
    assert errors(tmp_path, RANGE.replace(change[0], change[1])) == [found]


def test_a_filter_on_an_int_field_is_refused(tmp_path: Path) -> None:
    text = ("adapter Count { n: int }\n" + RANGE +
            "interface count() triggers tally { level() }\n"
            "output tally: Count {\n    n = level\n    filter n kalman { state [0] transition 1 process 1 "
            "measurement 1 noise 1 }\n}\n")
    assert errors(tmp_path, text) == [("E732", "n", "field `n` is int: a filter's estimate is a float")]


def test_the_clauses_print_and_parse_back_alike() -> None:
    first = parse("a.rdis", HEAD + RANGE, Diagnostics())
    printed = print_module(first)
    assert 'noise distance 0.01 "m"' in printed and "        transition [1.0, 0.05; 0.0, 1.0]" in printed
    assert parse("b.rdis", printed, Diagnostics()).decls == first.decls


def test_noise_and_filters_go_through_json_and_back(tmp_path: Path) -> None:
    _, built = through_json(HEAD + RANGE, tmp_path, "ranger")
    (output,) = json.loads(built)["domainOutputs"]
    assert output["noise"] == [{"field": "distance", "deviation": 0.01, "unit": "m"}]
    assert output["filters"] == [{"field": "distance", "kalman": {
        "state": [0, 0], "covariance": [[1, 0], [0, 1]], "transition": [[1, 0.05], [0, 1]],
        "process": [[1e-06, 0], [0, 0.0001]], "measurement": [[1, 0]], "noise": [[0.0001]]}}]


NOT_SEMIDEFINITE = ("the filter's `process` is not positive semi-definite: some combination of its values "
                    "would have a negative variance")


@pytest.mark.parametrize(("change", "found"), [
    (("process [0.000001, 0; 0, 0.0001]", "process [1, 2; 2, 1]"),
     ("E733", "[1, 2; 2, 1]", NOT_SEMIDEFINITE)),
    (("process [0.000001, 0; 0, 0.0001]", "process [0, 1; 1, 0.5]"),  # a zero variance with a covariance
     ("E733", "[0, 1; 1, 0.5]", NOT_SEMIDEFINITE)),
])
def test_a_covariance_that_is_not_semidefinite_is_refused(tmp_path: Path, change: tuple[str, str],
                                                          found: tuple[str, str, str]) -> None:
    assert errors(tmp_path, RANGE.replace(change[0], change[1])) == [found]


@pytest.mark.parametrize("matrix", ["[1, 1; 1, 1]", "[0, 0; 0, 0.0001]", "[4, 1.9; 1.9, 1]"])
def test_a_semidefinite_covariance_checks(tmp_path: Path, matrix: str) -> None:
    assert errors(tmp_path, RANGE.replace("process [0.000001, 0; 0, 0.0001]", f"process {matrix}")) == []
