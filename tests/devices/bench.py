"""An emulated bench device on a pty, as tests/runtime/data/bench.rdis describes it: one command
per line, one reply line each, fixed readings (`READINGS`) to `S`. `answers` replaces the reply to
a command letter; None leaves the command unanswered (the host times out). Received lines
(without their ending) are in `lines`."""

from __future__ import annotations

from . import PtyDevice

READINGS = "0.5,1,12.25,-1.5,2.0,4.0,0.75,1.5,-2.0,0.5,0.25,-0.125,0.1,0.2,-0.3,36.5"


class BenchEmulator(PtyDevice):
    def __init__(self, answers: dict[str, str | None] | None = None) -> None:
        super().__init__()
        self.answers: dict[str, str | None] = {"V": "v", "P": "p", "J": "j", "M": "m", "Q": "q",
                                               "S": f"s,{READINGS}", **(answers or {})}
        self.lines: list[str] = []
        self._pending = bytearray()

    def handle(self, data: bytes) -> None:
        self._pending += data
        while b"\n" in self._pending:
            line, _, rest = bytes(self._pending).partition(b"\n")
            self._pending[:] = rest
            text = line.decode("ascii")
            with self._cond:
                self.lines.append(text)
            answer = self.answers.get(text.split(",")[0])
            if answer is not None:
                self.send(answer.encode("ascii") + b"\n")

    def _cleared(self) -> None:
        self.lines.clear()
