"""An output's error models in JSON: `"noise": [{"field", "deviation", "unit"} or {"field",
"covariance"} or {"fields": [...], "covariance"}]` and `"filters": [{"field", "kalman": {"state", "covariance", ...}}]`, read as
the clauses the text writes (`noise FIELD ...`, `filter FIELD kalman { ... }`), so the checker
holds both alike."""

from __future__ import annotations

import math

from rdisc.json_import.reader import Members, Reader, present
from rdisc.json_import.values import JNumber, JObject, JValue
from rdisc.semantics.check.noise import WORDS
from rdisc.syntax import ast

_NOISE = ("field", "fields", "deviation", "covariance", "unit")
_FILTER = ("field", "kalman")


class ErrorModels(Reader):
    """The reading of an output's `noise` and `filters`."""

    def number(self, v: JValue, what: str) -> float | None:
        found = self.expect(v, JNumber, what, "a number")
        if found is None:
            return None
        if isinstance(found.value, bool) or not math.isfinite(found.value):
            self.error(found.span, f"{what} must be a finite number")
            return None
        return float(found.value)

    def rows(self, v: JValue, what: str, vector: bool = False) -> ast.NumberRows | None:
        """An array of numbers (`vector`: one row) or an array of rows of numbers."""
        rows = [self.array(v, what)] if vector else [self.array(row, what) for row in self.array(v, what)]
        if not rows or not all(rows):
            self.error(v.span, f"{what} must be {'numbers' if vector else 'rows of numbers'}, none empty")
            return None
        numbers = [[self.number(item, what) for item in row] for row in rows]
        if any(n is None for row in numbers for n in row):
            return None  # reported
        return ast.NumberRows(tuple(tuple(n for n in row if n is not None) for row in numbers), v.span)

    def noises(self, m: Members) -> tuple[ast.FieldNoise, ...]:
        found: list[ast.FieldNoise | None] = []
        for item in self.array(m.get("noise"), "`noise`"):
            obj = self.object(item, "a noise")
            if obj is None:
                continue
            given = self.members(obj, "a noise", _NOISE)
            if "fields" in given:
                found.append(self._joint(obj, given))
                continue
            field = self.required(obj, given, "field", "a noise", self.ident)
            found.append(None if field is None else self._error(obj, given, field))
        return present(found)

    def _joint(self, obj: JObject, given: Members) -> ast.FieldNoise | None:
        """`{"fields": [F, G, ...], "covariance": [...]}`: one covariance over several fields."""
        names = [self.ident(item, "a field of `fields`") for item in self.array(given["fields"], "`fields`")]
        if "field" in given or "deviation" in given or "unit" in given or "covariance" not in given \
                or len(names) < 2:
            self.error(self.opening(obj), "a noise over `fields` (two or more) has a `covariance` only")
            return None
        rows = self.rows(given["covariance"], "`covariance`")
        if rows is None or any(n is None for n in names):
            return None  # reported
        first, *others = present(names)
        return ast.FieldNoise(first, rows, None, obj.span, tuple(others))

    def state_noise(self, v: JValue | None, name: ast.Ident) -> ast.FieldNoise | None:
        """A state variable's `"noise": {"deviation", "unit"}` (or `"covariance"`), its field its name."""
        obj = None if v is None else self.object(v, "a noise")
        return None if obj is None else self._error(obj, self.members(obj, "a noise", _NOISE[2:]), name)

    def _error(self, obj: JObject, given: Members, field: ast.Ident) -> ast.FieldNoise | None:
        unit = self.string(given.get("unit"), "`unit`")
        value: float | ast.NumberRows | None = None
        if ("deviation" in given) == ("covariance" in given):
            self.error(self.opening(obj), "a noise has either a `deviation` or a `covariance`")
        elif "deviation" in given:
            value = self.number(given["deviation"], "`deviation`")
        else:
            value = self.rows(given["covariance"], "`covariance`")
        strings = None if unit is None else ast.StrLit(unit.value, unit.span)
        return None if value is None else ast.FieldNoise(field, value, strings, obj.span)

    def filters(self, m: Members) -> tuple[ast.FieldFilter, ...]:
        found: list[ast.FieldFilter | None] = []
        for item in self.array(m.get("filters"), "`filters`"):
            obj = self.object(item, "a filter")
            if obj is None:
                continue
            given = self.members(obj, "a filter", _FILTER)
            field = self.required(obj, given, "field", "a filter", self.ident)
            kalman = self.required(obj, given, "kalman", "a filter", self.object)
            if field is None or kalman is None:
                continue
            items: list[tuple[ast.Ident, float | ast.NumberRows]] = []
            for word, value in self.members(kalman, "a Kalman filter", WORDS).items():
                rows = self.rows(value, f"`{word}`", vector=word == "state")
                key = next(k for k, _ in kalman.members if k.value == word)
                if rows is not None:
                    items.append((ast.Ident(word, self.inner(key)), rows))
            found.append(ast.FieldFilter(field, tuple(items), obj.span))
        return present(found)

