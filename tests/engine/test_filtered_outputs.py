"""A filtered output publishes its Kalman filter's estimate (`filter FIELD kalman { ... }`): the
runtime and the generated driver alike, each delivery one predict and one update by the value
computed, the same values the engine's filter gives and filterpy's to 1e-9."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy
import pytest

from rdisc.engine.kalman import KalmanFilter
from tests.engine.test_one_engine import implementation_of
from tests.semantics.test_noise import HEAD, RANGE
from tests.support.ports import ScriptedPort

if TYPE_CHECKING:
    from filterpy.kalman import KalmanFilter as Reference

LEVELS = [100, 104, 97, 112, 108, 120, 115, 131, 126, 140]


def _reference() -> Reference:
    from filterpy.kalman import KalmanFilter as Reference  # SciPy's 1 s, in the worker that runs this only

    reference = Reference(dim_x=2, dim_z=1)
    reference.x = numpy.array([[0.0], [0.0]])
    reference.P = numpy.eye(2)
    reference.F = numpy.array([[1.0, 0.05], [0.0, 1.0]])
    reference.Q = numpy.array([[1e-6, 0.0], [0.0, 1e-4]])
    reference.H = numpy.array([[1.0, 0.0]])
    reference.R = numpy.array([[1e-4]])
    return reference


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_filtered_output_publishes_the_estimate(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, HEAD + RANGE, tmp_path, "ranger")
    delivered: list[dict[str, Any]] = []
    with implementation.connect(ScriptedPort(bytes(LEVELS)), threads=False, on_output=delivered.append) as robot:
        for _ in LEVELS:
            robot.call_interface("watch")
    ours = KalmanFilter([0.0, 0.0], [[1, 0], [0, 1]], [[1, 0.05], [0, 1]], [[1e-6, 0], [0, 1e-4]], [[1, 0]],
                        [[1e-4]])
    assert [d["contents"]["distance"] for d in delivered] == [ours.step([level / 1000.0])[0] for level in LEVELS]
    reference = _reference()
    for level, message in zip(LEVELS, delivered):
        reference.predict()
        reference.update(numpy.array([[level / 1000.0]]))
        assert abs(message["contents"]["distance"] - reference.x[0, 0]) < 1e-9
    assert delivered[0]["contents"]["distance"] == pytest.approx(0.0999, abs=1e-4)  # trusts the first reading
    assert delivered[-1]["contents"]["distance"] != LEVELS[-1] / 1000.0  # the estimate, not the reading


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_each_robot_runs_its_own_filter(kind: str, tmp_path: Path) -> None:
    implementation = implementation_of(kind, HEAD + RANGE, tmp_path, "ranger")
    firsts = []
    for _ in range(2):
        delivered: list[dict[str, Any]] = []
        with implementation.connect(ScriptedPort(bytes([100])), threads=False, on_output=delivered.append) as robot:
            robot.call_interface("watch")
        firsts.append(delivered[0]["contents"]["distance"])
    assert firsts[0] == firsts[1]
