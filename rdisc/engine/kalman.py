"""A linear Kalman filter, the estimate a `filter kalman` gives an output or state variable:
state x and covariance P, moved by the transition F with process noise Q, corrected by a
measurement z through H with noise R. The update keeps P in Joseph's form,
P = (I - KH) P (I - KH)' + K R K', which stays symmetric for any gain. An update whose state
or covariance would not be finite (a NaN or infinite reading, a jump past a float) is not made:
one bad reply from a device would otherwise make every later estimate NaN.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from rdisc.engine.matrices import (
    Matrix,
    as_column,
    as_matrix,
    matrix_identity,
    matrix_inverse,
    matrix_product,
    matrix_shape,
    matrix_sum,
    matrix_transpose,
)


class KalmanFilter:
    """One filter's matrices and its current state (`state`, a column; `covariance`). Shapes are
    checked once here (ValueError), as the checker checks a description's."""

    __slots__ = ("covariance", "measurement", "noise", "process", "state", "transition")

    def __init__(self, state: Sequence[float], covariance: Sequence[Sequence[float]],
                 transition: Sequence[Sequence[float]], process: Sequence[Sequence[float]],
                 measurement: Sequence[Sequence[float]], noise: Sequence[Sequence[float]]) -> None:
        self.state = as_column(state)
        self.covariance = as_matrix(covariance)
        self.transition = as_matrix(transition)
        self.process = as_matrix(process)
        self.measurement = as_matrix(measurement)
        self.noise = as_matrix(noise)
        states = len(self.state)
        measured = len(self.measurement)
        for name, of, expected in (("covariance", self.covariance, (states, states)),
                                   ("transition", self.transition, (states, states)),
                                   ("process", self.process, (states, states)),
                                   ("measurement", self.measurement, (measured, states)),
                                   ("noise", self.noise, (measured, measured))):
            if matrix_shape(of) != expected:
                raise ValueError(f"a Kalman filter's {name} is {matrix_shape(of)}, not {expected}")

    def predict(self) -> None:
        """x = F x; P = F P F' + Q."""
        self.state = matrix_product(self.transition, self.state)
        moved = matrix_product(matrix_product(self.transition, self.covariance), matrix_transpose(self.transition))
        self.covariance = matrix_sum(moved, self.process)

    def update(self, measured: Sequence[float]) -> None:
        """Corrects the state by one measurement (as many values as the measurement's rows), unless
        the correction is not finite."""
        z = as_column(measured)
        if len(z) != len(self.measurement):
            raise ValueError(f"a Kalman filter measures {len(self.measurement)} values, not {len(z)}")
        h = self.measurement
        residual = matrix_sum(z, matrix_product(h, self.state), -1.0)
        spread = matrix_product(self.covariance, matrix_transpose(h))
        gain = matrix_product(spread, matrix_inverse(matrix_sum(matrix_product(h, spread), self.noise)))
        state = matrix_sum(self.state, matrix_product(gain, residual))
        kept = matrix_sum(matrix_identity(len(self.state)), matrix_product(gain, h), -1.0)
        covariance = matrix_sum(matrix_product(matrix_product(kept, self.covariance), matrix_transpose(kept)),
                                matrix_product(matrix_product(gain, self.noise), matrix_transpose(gain)))
        if all(math.isfinite(value) for row in (*state, *covariance) for value in row):
            self.state, self.covariance = state, covariance

    def step(self, measured: Sequence[float]) -> tuple[float, ...]:
        """Predicts, then updates by `measured`: the estimate of what is measured (H x)."""
        self.predict()
        self.update(measured)
        return self.estimate()

    def estimate(self) -> tuple[float, ...]:
        """What the measurement would read in the state estimated (H x)."""
        return tuple(row[0] for row in matrix_product(self.measurement, self.state))


@dataclass(frozen=True, slots=True)
class FilterPlan:
    """What a description states of a field's Kalman filter (`filter FIELD kalman { ... }`): the
    field, and the matrices each robot starts its own running filter from."""

    field: str
    state: tuple[float, ...]
    covariance: Matrix
    transition: Matrix
    process: Matrix
    measurement: Matrix
    noise: Matrix

    def start(self) -> KalmanFilter:
        return KalmanFilter(self.state, self.covariance, self.transition, self.process, self.measurement, self.noise)
