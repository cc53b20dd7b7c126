"""Small dense matrices as tuples of rows, written once for the Kalman filter (the engine is
standard library only, so no numpy): products, sums, transposes and the inverse by Gauss-Jordan
elimination with partial pivoting. Sizes are a filter's (a few states), so plain loops do.
"""

from __future__ import annotations

from collections.abc import Sequence

Matrix = tuple[tuple[float, ...], ...]
"""A matrix as its rows, each a tuple of floats; a column vector is a matrix of one column."""


def as_matrix(rows: Sequence[Sequence[float]]) -> Matrix:
    """A matrix of the given rows (ValueError if they are not all as long as the first)."""
    result = tuple(tuple(float(value) for value in row) for row in rows)
    if result and any(len(row) != len(result[0]) for row in result):
        raise ValueError("a matrix's rows differ in length")
    return result


def as_column(values: Sequence[float]) -> Matrix:
    """A column vector of `values`."""
    return tuple((float(value),) for value in values)


def matrix_identity(size: int) -> Matrix:
    """The identity of `size` rows."""
    return tuple(tuple(1.0 if row == place else 0.0 for place in range(size)) for row in range(size))


def matrix_shape(of: Matrix) -> tuple[int, int]:
    """Rows and columns."""
    return len(of), len(of[0]) if of else 0


def matrix_transpose(of: Matrix) -> Matrix:
    """Rows as columns."""
    return tuple(zip(*of)) if of else ()


def matrix_product(left: Matrix, right: Matrix) -> Matrix:
    """`left` times `right` (ValueError if `left`'s columns are not `right`'s rows)."""
    if matrix_shape(left)[1] != len(right):
        raise ValueError(f"cannot multiply {matrix_shape(left)} by {matrix_shape(right)}")
    columns = matrix_transpose(right)
    return tuple(tuple(sum(a * b for a, b in zip(row, each)) for each in columns) for row in left)


def matrix_sum(left: Matrix, right: Matrix, sign: float = 1.0) -> Matrix:
    """`left` plus `sign` times `right`, element by element (ValueError if their shapes differ)."""
    if matrix_shape(left) != matrix_shape(right):
        raise ValueError(f"cannot add {matrix_shape(left)} and {matrix_shape(right)}")
    return tuple(tuple(a + sign * b for a, b in zip(one, other)) for one, other in zip(left, right))


def matrix_inverse(of: Matrix) -> Matrix:
    """The inverse of a square matrix (ValueError if it is not square or is singular)."""
    size, columns = matrix_shape(of)
    if size != columns:
        raise ValueError(f"cannot invert {matrix_shape(of)}")
    work = [list(row) + list(unit) for row, unit in zip(of, matrix_identity(size))]
    for place in range(size):
        pivot = max(range(place, size), key=lambda row: abs(work[row][place]))
        if work[pivot][place] == 0.0:
            raise ValueError("a singular matrix has no inverse")
        work[place], work[pivot] = work[pivot], work[place]
        lead = work[place][place]
        work[place] = [value / lead for value in work[place]]
        for row in range(size):
            if row != place and work[row][place] != 0.0:
                factor = work[row][place]
                work[row] = [value - factor * other for value, other in zip(work[row], work[place])]
    return tuple(tuple(row[size:]) for row in work)
