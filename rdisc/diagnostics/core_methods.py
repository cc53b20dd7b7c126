"""The methods of the frozen dataclasses of rdisc/diagnostics/core.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import DEFAULT, MISSING, Written, classes, field

if TYPE_CHECKING:
    from typing import Any

__all__ = ["dataclass", "field"]

# Each field's setter, `_set_<class>_<field>(instance, value)`: its slot's own `__set__`, bound by
# rdisc.frozen when it makes the class (a third faster than object.__setattr__ with the field's name).
_unbound: Any = None


_set_Label_span = _set_Label_message = _unbound


def _init_Label(self: Any, span: Any, message: Any) -> None:
    _set_Label_span(self, span)
    _set_Label_message(self, message)


def _repr_Label(self: Any) -> str:
    return f"{self.__class__.__qualname__}(span={self.span!r}, message={self.message!r})"


def _eq_Label(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.span, self.message) == (other.span, other.message)
    return NotImplemented


def _hash_Label(self: Any) -> int:
    return hash((self.span, self.message))


_set_Diagnostic_code = _unbound
_set_Diagnostic_severity = _unbound
_set_Diagnostic_message = _unbound
_set_Diagnostic_span = _unbound
_set_Diagnostic_label = _unbound
_set_Diagnostic_labels = _unbound
_set_Diagnostic_help = _unbound


def _init_Diagnostic(
    self: Any,
    code: Any,
    severity: Any,
    message: Any,
    span: Any,
    label: Any = DEFAULT,
    labels: Any = DEFAULT,
    help: Any = DEFAULT,
) -> None:
    _set_Diagnostic_code(self, code)
    _set_Diagnostic_severity(self, severity)
    _set_Diagnostic_message(self, message)
    _set_Diagnostic_span(self, span)
    _set_Diagnostic_label(self, label)
    _set_Diagnostic_labels(self, labels)
    _set_Diagnostic_help(self, help)


def _repr_Diagnostic(self: Any) -> str:
    return f"{self.__class__.__qualname__}(code={self.code!r}, severity={self.severity!r}, message={self.message!r}, span={self.span!r}, label={self.label!r}, labels={self.labels!r}, help={self.help!r})"


def _eq_Diagnostic(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.code,
            self.severity,
            self.message,
            self.span,
            self.label,
            self.labels,
            self.help,
        ) == (
            other.code,
            other.severity,
            other.message,
            other.span,
            other.label,
            other.labels,
            other.help,
        )
    return NotImplemented


def _hash_Diagnostic(self: Any) -> int:
    return hash((self.code, self.severity, self.message, self.span, self.label, self.labels, self.help))


WRITTEN: dict[str, Written] = {
    "Label": Written(
        (("span", MISSING), ("message", MISSING)),
        {"__init__": _init_Label, "__repr__": _repr_Label, "__eq__": _eq_Label, "__hash__": _hash_Label},
    ),
    "Diagnostic": Written(
        (
            ("code", MISSING),
            ("severity", MISSING),
            ("message", MISSING),
            ("span", MISSING),
            ("label", DEFAULT),
            ("labels", DEFAULT),
            ("help", DEFAULT),
        ),
        {
            "__init__": _init_Diagnostic,
            "__repr__": _repr_Diagnostic,
            "__eq__": _eq_Diagnostic,
            "__hash__": _hash_Diagnostic,
        },
    ),
}
dataclass = classes(WRITTEN)
