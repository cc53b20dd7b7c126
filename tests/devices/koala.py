"""An emulated K-Team Koala (ASCII serial protocol) on a pty, as examples/koala.rdis
describes it: one command per line, one reply line each ("\\r\\n" terminated).

    D,l,r  -> d            set `speeds`
    E      -> e,l,r        `speeds`
    G,l,r  -> g            set `counters`
    H      -> h,l,r        `counters`
    N      -> n,s0,...,s15 `proximity` (16 readings)
    other  -> z

`mode`: "normal" answers; "silent" never answers; "garbage" answers a line no
reply regex of the description matches; "unterminated" answers without the line
ending. Received lines (without their ending) are in `lines`, with arrival
times in `timed_lines`.
"""

from __future__ import annotations

import time

from . import PtyDevice

GARBAGE = b"#?garbage!\r\n"


class KoalaEmulator(PtyDevice):
    def __init__(self, mode: str = "normal", reply_delay: float = 0.0) -> None:
        super().__init__()
        self.mode = mode
        self.reply_delay = reply_delay
        self.speeds: tuple[int, int] = (0, 0)
        self.counters: tuple[int, int] = (0, 0)
        self.proximity: list[int] = [0] * 16
        self.timed_lines: list[tuple[float, str]] = []
        self._pending = bytearray()

    @property
    def lines(self) -> list[str]:
        with self._cond:
            return [line for _, line in self.timed_lines]

    def wait_for_lines(self, n: int, timeout: float = 2.0, prefix: str = "") -> list[str]:
        """Wait until `n` lines (starting with `prefix`) arrived; return those lines."""
        def matching() -> list[str]:
            return [line for _, line in self.timed_lines if line.startswith(prefix)]

        self.wait_until(lambda: len(matching()) >= n, timeout, f"{n} lines starting {prefix!r}")
        with self._cond:
            return matching()

    def _cleared(self) -> None:
        self.timed_lines.clear()
        self._pending.clear()

    def handle(self, data: bytes) -> None:
        now = time.monotonic()
        with self._cond:
            self._pending += data
            lines = []
            while b"\n" in self._pending:
                raw, _, rest = bytes(self._pending).partition(b"\n")
                self._pending[:] = rest
                line = raw.rstrip(b"\r").decode("latin-1")
                self.timed_lines.append((now, line))
                lines.append(line)
        for line in lines:
            reply = self.answer(line)
            if self.mode == "silent":
                continue
            if self.mode == "garbage":
                reply = GARBAGE.decode()
            elif self.mode == "unterminated":
                reply = reply.rstrip("\r\n")
            self.send(reply.encode("latin-1"))

    def answer(self, line: str) -> str:
        """The reply to one command line (and its effect on the robot)."""
        command, *args = line.split(",")
        try:
            values = [int(a) for a in args]
        except ValueError:
            return "z\r\n"
        if command == "D" and len(values) == 2:
            self.speeds = (values[0], values[1])
            return "d\r\n"
        if command == "E" and not values:
            return "e,{},{}\r\n".format(*self.speeds)
        if command == "G" and len(values) == 2:
            self.counters = (values[0], values[1])
            return "g\r\n"
        if command == "H" and not values:
            return "h,{},{}\r\n".format(*self.counters)
        if command == "N" and not values:
            return "n," + ",".join(str(v) for v in self.proximity) + "\r\n"
        return "z\r\n"
