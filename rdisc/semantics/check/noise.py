"""An output's error models and Kalman filters (thesis §7.2.3): `noise FIELD ...` and
`filter FIELD kalman { ... }` held to the adapter's fields and to the shapes a linear filter
needs, every matrix square where it must be, symmetric where it is a covariance, and agreeing
in size with the state and the field it measures."""

from __future__ import annotations

from rdisc.diagnostics import Diagnostics, Label
from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.source import Span
from rdisc.syntax import ast

WORDS = ("state", "covariance", "transition", "process", "measurement", "noise")
"""A Kalman filter's matrices in the order they are written; all but `covariance` (the identity) needed."""

MAX_STATES = 64  # a filter's states: its matrices are products of loops in pure Python


def _rows(value: float | ast.NumberRows) -> m.Rows:
    return ((value,),) if isinstance(value, float) else value.rows


def _span(value: float | ast.NumberRows, fallback: Span | None) -> Span | None:
    return value.span if isinstance(value, ast.NumberRows) else fallback


def _field(d: Diagnostics, code: str, field: ast.Ident, adapter: m.Adapter) -> m.AdapterField | None:
    """The adapter's field a clause names, if it is numbers: one, or an array of them."""
    found = adapter.field(field.text)
    if found is None:
        d.report(code, field.span, f"adapter `{adapter.name}` has no field `{field.text}`",
                 help="its fields are " + ", ".join(f"`{f.name}`" for f in adapter.fields))
        return None
    element = found.type.element if isinstance(found.type, m.Array) else found.type
    if element not in (Type.INT, Type.FLOAT):
        d.report(code, field.span, f"field `{found.name}` is {found.type.value}, not numbers: it has no noise")
        return None
    return found


def _size(found: m.AdapterField) -> int | None:
    """How many values a field measures: one, an array's size, or None (an open array)."""
    return (found.type.size or None) if isinstance(found.type, m.Array) else 1


def _semidefinite(rows: m.Rows) -> bool:
    """Whether a symmetric matrix is positive semi-definite: its LDL' factors' pivots are none
    negative (to a tolerance relative to its largest value), and a zero pivot's column is zero."""
    size = len(rows)
    scale = max((abs(v) for row in rows for v in row), default=0.0) or 1.0
    tolerance = 1e-12 * scale * size
    a = [list(row) for row in rows]
    for k in range(size):
        pivot = a[k][k]
        if pivot < -tolerance:
            return False
        if pivot <= tolerance:
            if any(abs(a[i][k]) > tolerance for i in range(k + 1, size)):
                return False
            continue
        for i in range(k + 1, size):
            factor = a[i][k] / pivot
            for j in range(k + 1, size):
                a[i][j] -= factor * a[k][j]
    return True


def _covariance(d: Diagnostics, code: str, rows: m.Rows, span: Span | None, what: str) -> bool:
    """Whether rows are a covariance: square, symmetric, none negative on the diagonal, and
    positive semi-definite (E733: no direction of the values has a negative variance)."""
    size = len(rows)
    if any(len(row) != size for row in rows):
        d.report(code, span, f"{what} is not square: {size} rows of {', '.join(str(len(r)) for r in rows)}")
        return False
    for i in range(size):
        if rows[i][i] < 0:
            d.report(code, span, f"{what} has {rows[i][i]!r} on its diagonal: a variance is not negative")
            return False
        for j in range(i):
            if rows[i][j] != rows[j][i]:
                d.report(code, span, f"{what} is not symmetric: row {i + 1}, column {j + 1} is {rows[i][j]!r}, "
                         f"row {j + 1}, column {i + 1} {rows[j][i]!r}")
                return False
    if not _semidefinite(rows):
        d.report("E733", span, f"{what} is not positive semi-definite: some combination of its values "
                 "would have a negative variance", help="each off-diagonal value is at most the square root "
                 "of the product of its row's and its column's variances")
        return False
    return True


def noise(d: Diagnostics, given: ast.FieldNoise, adapter: m.Adapter) -> m.Noise | None:
    """A field's noise: a deviation (its square the variance) in the field's unit, or a covariance."""
    if given.others:
        return _joint(d, given, adapter)
    found = _field(d, "E731", given.field, adapter)
    return None if found is None else _error(d, given, found.name, found.type, found.unit, "field")


def _joint(d: Diagnostics, given: ast.FieldNoise, adapter: m.Adapter) -> m.Noise | None:
    """One covariance over several number fields (`noise (x, y) [...]`), each named once, in its
    order: it says how their errors go together (a pose's x and y), which separate deviations cannot."""
    names: list[str] = []
    for ident in (given.field, *given.others):
        found = _field(d, "E731", ident, adapter)
        if found is None:
            return None
        if isinstance(found.type, m.Array):
            d.report("E731", ident.span, f"field `{found.name}` is {found.type.value}: a covariance over several "
                     "fields is over numbers, one value each")
            return None
        if found.name in names:
            d.report("E731", ident.span, f"field `{found.name}` is named twice in one noise")
            return None
        names.append(found.name)
    what = f"the covariance of ({', '.join(names)})"
    rows, span = _rows(given.value), _span(given.value, given.span)
    if not _covariance(d, "E731", rows, span, what):
        return None
    if len(rows) != len(names):
        d.report("E731", span, f"{what} is {len(rows)} by {len(rows)}, over {len(names)} fields")
        return None
    return m.Noise(names[0], rows, None, None, given.span, tuple(names[1:]))


def value_noise(d: Diagnostics, given: ast.FieldNoise, name: str, type_: m.AnyType, what: str) -> m.Noise | None:
    """A state variable's or a sensor's noise: the error of the values a device reports into it."""
    if (type_.element if isinstance(type_, m.Array) else type_) not in (Type.INT, Type.FLOAT):
        d.report("E731", given.span, f"{what} `{name}` is {type_.value}, not numbers: it has no noise")
        return None
    return _error(d, given, name, type_, None, what)


def _error(d: Diagnostics, given: ast.FieldNoise, name: str, type_: m.AnyType, expected: str | None,
           what: str) -> m.Noise | None:
    """A noise of the values named `name`: a deviation in their unit (`expected`), or a covariance."""
    unit = None if given.unit is None else given.unit.value
    if unit is not None and expected is not None and unit != expected:
        d.report("E731", given.unit.span if given.unit else given.span,
                 f"noise of `{name}` is in \"{unit}\", the {what} in \"{expected}\"",
                 help=f"write the deviation in \"{expected}\"")
        return None
    if isinstance(given.value, float):
        if given.value < 0:
            d.report("E731", given.span, f"noise of `{name}` is a deviation of {given.value!r}: not negative")
            return None
        return m.Noise(name, ((given.value * given.value,),), given.value, unit, given.span)
    rows = given.value.rows
    if not _covariance(d, "E731", rows, given.value.span, f"the covariance of `{name}`"):
        return None
    size = (type_.size or None) if isinstance(type_, m.Array) else 1
    if size is not None and size != len(rows):
        d.report("E731", given.value.span, f"the covariance of `{name}` is {len(rows)} by {len(rows)}, "
                 f"the {what} {size} value{'s' * (size != 1)}")
        return None
    return m.Noise(name, rows, None, unit, given.span)


def kalman(d: Diagnostics, given: ast.FieldFilter, adapter: m.Adapter) -> m.Kalman | None:
    """A field's Kalman filter, its matrices' shapes agreeing (n states, k values measured)."""
    found = _field(d, "E732", given.field, adapter)
    if found is None:
        return None
    if (found.type.element if isinstance(found.type, m.Array) else found.type) is not Type.FLOAT:
        d.report("E732", given.field.span, f"field `{found.name}` is {found.type.value}: a filter's estimate is a float")
        return None
    words: dict[str, tuple[m.Rows, Span | None]] = {}
    for word, value in given.items:
        if word.text in words:
            d.report("E732", word.span, f"the filter of `{found.name}` gives `{word.text}` twice")
            return None
        words[word.text] = _rows(value), _span(value, word.span)
    missing = [w for w in WORDS if w not in words and w != "covariance"]
    if missing:
        d.report("E732", given.span, f"the filter of `{found.name}` does not give "
                 + ", ".join(f"`{w}`" for w in missing), help="a Kalman filter states " + ", ".join(WORDS[:-1])
                 + " (the identity when not given) and " + WORDS[-1])
        return None
    state_rows, state_span = words["state"]
    if len(state_rows) != 1:
        d.report("E732", state_span, f"the filter's `state` is one row of numbers, not {len(state_rows)}")
        return None
    states = len(state_rows[0])
    if states > MAX_STATES:
        d.report("E732", state_span, f"the filter has {states} states, more than {MAX_STATES}")
        return None
    identity = tuple(tuple(1.0 if i == j else 0.0 for j in range(states)) for i in range(states))
    words.setdefault("covariance", (identity, given.span))
    measured = len(words["measurement"][0])
    size = _size(found)
    if size is not None and measured != size:
        d.report("E732", words["measurement"][1], f"the filter's `measurement` has {measured} "
                 f"row{'s' * (measured != 1)}, field `{found.name}` {size} value{'s' * (size != 1)}")
        return None
    expected = {"covariance": (states, states), "transition": (states, states), "process": (states, states),
                "measurement": (measured, states), "noise": (measured, measured)}
    for name, (rows, columns) in expected.items():
        matrix, span = words[name]
        shape = (len(matrix), len(matrix[0]))
        if len(matrix) != rows or any(len(row) != columns for row in matrix):
            labels = (Label(state_span, f"{states} state{'s' * (states != 1)}"),) if state_span else ()
            d.report("E732", span, f"the filter's `{name}` is {shape[0]} by {shape[1]}, not {rows} by {columns}",
                     labels=labels)
            return None
        if name in ("covariance", "process", "noise") and not _covariance(d, "E732", matrix, span,
                                                                          f"the filter's `{name}`"):
            return None
    return m.Kalman(found.name, state_rows[0], words["covariance"][0], words["transition"][0], words["process"][0],
                    words["measurement"][0], words["noise"][0], given.span)


def errors(d: Diagnostics, decl: ast.OutputDecl, adapter: m.Adapter) -> tuple[tuple[m.Noise, ...], tuple[m.Kalman, ...]]:
    """An output's noise and filters, each field's at most once."""
    noises: dict[str, m.Noise] = {}
    for given in decl.noises:
        made = noise(d, given, adapter)
        again = None if made is None else next((f for f in made.fields if f in noises), None)
        if made is not None and again is not None:
            at = next(i for i in (given.field, *given.others) if i.text == again)
            d.report("E731", at.span, f"the noise of `{again}` is given twice")
        elif made is not None:
            noises.update(dict.fromkeys(made.fields, made))
    filters: dict[str, m.Kalman] = {}
    for each in decl.filters:
        filtered = kalman(d, each, adapter)
        if filtered is not None and filtered.field in filters:
            d.report("E732", each.field.span, f"field `{filtered.field}` has two filters")
        elif filtered is not None:
            filters[filtered.field] = filtered
    return tuple(dict.fromkeys(noises.values())), tuple(filters.values())
