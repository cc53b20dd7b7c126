"""The engine's Kalman filter (rdisc.engine.kalman) held against filterpy's on the same inputs:
the state and covariance after every predict and update agree to 1e-9, for a constant-velocity
model over a few hundred random measurements, a 1-D model, and small random matrices."""

from __future__ import annotations

import math
import random
from typing import TYPE_CHECKING

import numpy
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.engine import matrices
from rdisc.engine.kalman import KalmanFilter

if TYPE_CHECKING:
    from filterpy.kalman import KalmanFilter as Reference

TOLERANCE = 1e-9


def _reference(state, covariance, transition, process, measurement, noise) -> Reference:
    from filterpy.kalman import KalmanFilter as Reference  # SciPy's 1 s, in the worker that runs this only

    reference = Reference(dim_x=len(state), dim_z=len(measurement))
    reference.x = numpy.array([[value] for value in state], dtype=float)
    reference.P = numpy.array(covariance, dtype=float)
    reference.F = numpy.array(transition, dtype=float)
    reference.Q = numpy.array(process, dtype=float)
    reference.H = numpy.array(measurement, dtype=float)
    reference.R = numpy.array(noise, dtype=float)
    return reference


def _agree(ours: KalmanFilter, reference: Reference) -> None:
    assert numpy.allclose(numpy.array(ours.state), reference.x, rtol=0, atol=TOLERANCE)
    assert numpy.allclose(numpy.array(ours.covariance), reference.P, rtol=0, atol=TOLERANCE)


def _run(matrices_given: tuple, measurements: list[list[float]]) -> KalmanFilter:
    ours = KalmanFilter(*matrices_given)
    reference = _reference(*matrices_given)
    for measured in measurements:
        ours.predict()
        reference.predict()
        _agree(ours, reference)
        ours.update(measured)
        reference.update(numpy.array([[value] for value in measured]))
        _agree(ours, reference)
        assert ours.estimate() == pytest.approx(tuple((reference.H @ reference.x).ravel()), abs=TOLERANCE)
    return ours


def test_constant_velocity_over_three_hundred_noisy_positions() -> None:
    chance = random.Random(25)
    period = 0.05
    given_matrices = ([0.0, 0.0], [[1.0, 0.0], [0.0, 1.0]], [[1.0, period], [0.0, 1.0]],
                      [[1e-6, 0.0], [0.0, 1e-4]], [[1.0, 0.0]], [[0.01 ** 2]])
    positions = [[0.3 * step * period + chance.gauss(0.0, 0.01)] for step in range(300)]
    ours = _run(given_matrices, positions)
    assert ours.state[1][0] == pytest.approx(0.3, abs=0.05)  # the speed it was never told


def test_one_dimensional_model_settles_on_the_constant() -> None:
    chance = random.Random(7)
    ours = _run(([0.0], [[100.0]], [[1.0]], [[1e-5]], [[1.0]], [[0.25]]),
                [[2.5 + chance.gauss(0.0, 0.5)] for _ in range(400)])
    assert ours.estimate()[0] == pytest.approx(2.5, abs=0.1)


def test_step_predicts_then_updates() -> None:
    ours = KalmanFilter([0.0], [[1.0]], [[1.0]], [[1.0]], [[1.0]], [[1.0]])
    # P = 1 + 1 = 2, K = 2 / 3, x = 2/3 * 3 = 2, P = (1/3)^2 * 2 + (2/3)^2 = 2/3
    assert ours.step([3.0]) == (2.0,)
    assert ours.covariance[0][0] == pytest.approx(2 / 3, abs=1e-15)


def test_shapes_that_disagree_are_refused() -> None:
    with pytest.raises(ValueError, match=r"a Kalman filter's noise is \(1, 2\), not \(1, 1\)"):
        KalmanFilter([0.0, 0.0], [[1, 0], [0, 1]], [[1, 0], [0, 1]], [[1, 0], [0, 1]], [[1, 0]], [[1, 0]])
    with pytest.raises(ValueError, match="measures 1 values, not 2"):
        KalmanFilter([0.0], [[1]], [[1]], [[1]], [[1]], [[1]]).update([1.0, 2.0])
    with pytest.raises(ValueError, match="singular"):
        matrices.matrix_inverse(((1.0, 2.0), (2.0, 4.0)))


def _square(size: int, low: float, high: float) -> st.SearchStrategy[list[list[float]]]:
    value = st.floats(low, high, allow_nan=False, allow_infinity=False)
    return st.lists(st.lists(value, min_size=size, max_size=size), min_size=size, max_size=size)


@st.composite
def _filters(draw: st.DrawFn) -> tuple[tuple, list[list[float]]]:
    states = draw(st.integers(1, 3))
    measured = draw(st.integers(1, states))

    def covariance(size: int) -> list[list[float]]:
        # A A' + I/10: symmetric and positive definite, so every S inverts.
        a = numpy.array(draw(_square(size, -1.0, 1.0)))
        return (a @ a.T + 0.1 * numpy.eye(size)).tolist()

    transition = draw(_square(states, -1.2, 1.2))
    value = st.floats(-2.0, 2.0, allow_nan=False, allow_infinity=False)
    measurement = draw(st.lists(st.lists(value, min_size=states, max_size=states), min_size=measured,
                                max_size=measured))
    state = draw(st.lists(value, min_size=states, max_size=states))
    steps = draw(st.lists(st.lists(value, min_size=measured, max_size=measured), min_size=1, max_size=8))
    return (state, covariance(states), transition, covariance(states), measurement, covariance(measured)), steps


@settings(max_examples=60, deadline=None)
@given(_filters())
def test_small_random_filters_agree_with_filterpy(case: tuple[tuple, list[list[float]]]) -> None:
    _run(*case)


def test_inverse_undoes_a_product() -> None:
    given_matrix = ((4.0, 7.0, 2.0), (3.0, 6.0, 1.0), (2.0, 5.0, 3.0))
    assert numpy.allclose(numpy.array(matrices.matrix_product(given_matrix, matrices.matrix_inverse(given_matrix))),
                          numpy.eye(3), rtol=0, atol=1e-12)


def test_a_reading_that_is_not_finite_leaves_the_filter_as_a_prediction_would() -> None:
    matrices_given = ([0.0], [[1.0]], [[1.0]], [[1e-4]], [[1.0]], [[0.01]])
    skipped, never = KalmanFilter(*matrices_given), KalmanFilter(*matrices_given)
    for bad in (float("nan"), float("inf"), -float("inf")):  # a reply's float as the device sent it
        skipped.step((bad,))
        never.predict()
    assert skipped.step((1.0,)) == never.step((1.0,))
    assert (skipped.state, skipped.covariance) == (never.state, never.covariance)
    jumped = KalmanFilter(*matrices_given)
    jumped.step((1e308,))
    jumped.step((-1e308,))  # a residual past a float: -inf
    assert math.isfinite(jumped.state[0][0]) and math.isfinite(jumped.step((0.5,))[0])
