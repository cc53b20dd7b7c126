"""The diagnostic value and the collector every stage reports into."""

from __future__ import annotations

import enum

from rdisc import TYPE_CHECKING
from rdisc.source import Span

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.diagnostics.core_methods import dataclass

from rdisc.frozen import Frozen


def abbreviate(text: str, limit: int = 24) -> str:
    """Text quoted in a message: escaped to ASCII, long text cut."""
    shown = text.encode("unicode_escape").decode("ascii")
    return shown if len(shown) <= limit else shown[: limit - 3] + "..."


class Severity(enum.IntEnum):
    """Ordered as LSP numbers them: lower is more severe."""

    ERROR = 1
    WARNING = 2
    INFORMATION = 3
    HINT = 4


@dataclass(frozen=True, slots=True)
class Label(metaclass=Frozen):
    """A secondary place that explains the primary one."""

    span: Span
    message: str


@dataclass(frozen=True, slots=True)
class Diagnostic(metaclass=Frozen):
    code: str
    severity: Severity
    message: str
    span: Span | None
    label: str | None = None
    labels: tuple[Label, ...] = ()
    help: str | None = None

    @property
    def name(self) -> str:
        # The table of codes (each with its explanation) is imported when a diagnostic is shown: a
        # clean `rdisc check` never reads it, and importing it is a millisecond of one.
        from rdisc.diagnostics.codes import CODES

        return CODES[self.code].name


class Diagnostics:
    """Collects every problem of a run, each fault once, in report order."""

    def __init__(self) -> None:
        self.items: list[Diagnostic] = []
        self._seen: set[tuple[str, Span | None, str]] = set()

    def report(
        self,
        code: str,
        span: Span | None,
        message: str,
        *,
        label: str | None = None,
        labels: tuple[Label, ...] = (),
        help: str | None = None,
    ) -> None:
        key = (code, span, message)
        if key in self._seen:
            return
        self._seen.add(key)
        severity = Severity.ERROR if code.startswith("E") else Severity.WARNING
        self.items.append(Diagnostic(code, severity, message, span, label, labels, help))

    @property
    def error_count(self) -> int:
        return sum(1 for d in self.items if d.severity is Severity.ERROR)

    @property
    def warning_count(self) -> int:
        return sum(1 for d in self.items if d.severity is Severity.WARNING)

    def has_errors(self) -> bool:
        return any(d.severity is Severity.ERROR for d in self.items)

    def sorted(self) -> list[Diagnostic]:
        """In source order (file, offset), the way a reader walks the file."""
        return sorted(
            self.items,
            key=lambda d: (d.span.path, d.span.start) if d.span else ("", -1),
        )
