"""Emulated serial devices on real pseudo-terminals, for tests of real serial I/O.

A device owns the master side of an `os.openpty()` pair; the code under test opens
the slave side through pyserial, by its tty name (`dev.port`), exactly as it would
open `/dev/ttyUSB0`. A background thread reads what the host writes and answers.

    with CreateEmulator() as dev:              # or KoalaEmulator, or pty_device(handler)
        robot = load("examples/create.rdis").connect(dev.port)
        ...
        dev.wait_for(5, timeout=2.0)           # until 5 bytes arrived (TimeoutError if not)
        assert dev.received[-5:] == bytes([137, 0, 0, 0, 0])

Every device records what it received (`received`, and `chunks` with their arrival
times), can answer late (`reply_delay`, seconds) and can disappear (`close_master()`:
the host's next read or write fails as an unplugged adapter does). Leaving the
`with` block stops the thread and closes both file descriptors.
"""

from __future__ import annotations

import os
import select
import threading
import time
import tty
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["BenchEmulator", "CreateEmulator", "KoalaEmulator", "PtyDevice", "pty_device"]


class PtyDevice:
    """The master side of a pty and a thread serving it; subclasses implement `handle`."""

    #: seconds to wait before each reply (a slow device)
    reply_delay: float = 0.0

    def __init__(self) -> None:
        self.port = ""
        self.chunks: list[tuple[float, bytes]] = []  # (time.monotonic(), bytes) as read
        self.sent: list[tuple[int, bytes]] = []  # (time.time_ns(), bytes) as written: the host's clock, as a stamp's
        self._received = bytearray()
        self._cond = threading.Condition()
        self._master: int | None = None
        self._slave: int | None = None
        self._wake_r, self._wake_w = -1, -1
        self._thread: threading.Thread | None = None
        self._stop = False
        self._close_requested = False

    # ---- for subclasses --------------------------------------------------------

    def handle(self, data: bytes) -> None:
        """Called on the device thread with each chunk the host wrote."""

    def send(self, data: bytes) -> None:
        """Write bytes to the host (after `reply_delay`); ignored once the master is closed."""
        if self.reply_delay:
            time.sleep(self.reply_delay)
        master = self._master
        if master is None or not data:
            return
        try:
            self.sent.append((time.time_ns(), data))  # before the host can read it
            os.write(master, data)
        except OSError:
            pass

    # ---- for tests ---------------------------------------------------------------

    @property
    def received(self) -> bytes:
        """Every byte the host wrote so far."""
        with self._cond:
            return bytes(self._received)

    def wait_for(self, n_bytes: int, timeout: float = 2.0) -> bytes:
        """Wait until at least `n_bytes` have arrived; return them all, or raise TimeoutError."""
        return self.wait_until(lambda: len(self._received) >= n_bytes, timeout,
                               f"{n_bytes} bytes")

    def wait_until(self, predicate: Callable[[], bool], timeout: float = 2.0, what: str = "a condition") -> bytes:
        """Wait until `predicate()` (called under the device's lock) is true; return `received`."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while not predicate():
                left = deadline - time.monotonic()
                if left <= 0:
                    raise TimeoutError(f"waited {timeout:g} s for {what}; received {bytes(self._received)!r}")
                self._cond.wait(left)
            return bytes(self._received)

    def clear(self) -> None:
        """Forget what was received so far."""
        with self._cond:
            self._received.clear()
            self.chunks.clear()
            self._cleared()

    def close_master(self) -> None:
        """Close the master side now: the device is gone (the host sees I/O errors)."""
        thread = self._thread
        if thread is not None and thread.is_alive() and thread is not threading.current_thread():
            with self._cond:
                self._close_requested = True
                os.write(self._wake_w, b"x")
                while self._master is not None and thread.is_alive():
                    self._cond.wait(0.1)
        self._close_fd()

    def _close_fd(self) -> None:
        with self._cond:
            if self._master is not None:
                os.close(self._master)
                self._master = None
            self._cond.notify_all()

    def _cleared(self) -> None:
        """Subclasses reset their own records here (called under the lock)."""

    # ---- lifecycle -------------------------------------------------------------------

    def __enter__(self) -> Self:
        master, slave = os.openpty()
        tty.setraw(master)
        tty.setraw(slave)
        self._master, self._slave = master, slave
        self.port = os.ttyname(slave)
        self._wake_r, self._wake_w = os.pipe()
        self._thread = threading.Thread(target=self._serve, name=f"pty-device {self.port}", daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop = True
        os.write(self._wake_w, b"x")
        if self._thread is not None:
            self._thread.join(timeout=5)
        self._close_fd()
        for fd in (self._slave, self._wake_r, self._wake_w):
            if fd is not None and fd >= 0:
                os.close(fd)
        self._slave, self._wake_r, self._wake_w = None, -1, -1

    def _serve(self) -> None:
        # The master descriptor is read, written and closed on this thread only.
        try:
            while not self._stop and not self._close_requested:
                master = self._master
                if master is None:
                    return
                ready, _, _ = select.select([master, self._wake_r], [], [])
                if self._wake_r in ready:
                    os.read(self._wake_r, 64)
                    continue
                try:
                    data = os.read(master, 4096)
                except OSError:  # no slave open right now
                    time.sleep(0.01)
                    continue
                if not data:
                    continue
                with self._cond:
                    self._received += data
                    self.chunks.append((time.monotonic(), data))
                self.handle(data)
                with self._cond:
                    self._cond.notify_all()
        finally:
            if self._close_requested:
                self._close_fd()


class _Handler(PtyDevice):
    def __init__(self, handler: Callable[[bytes], bytes | None]) -> None:
        super().__init__()
        self._handler = handler

    def handle(self, data: bytes) -> None:
        reply = self._handler(data)
        if reply:
            self.send(reply)


@contextmanager
def pty_device(handler: Callable[[bytes], bytes | None]) -> Iterator[PtyDevice]:
    """A device that answers each chunk it reads with `handler(chunk)` (None: no answer)."""
    with _Handler(handler) as dev:
        yield dev


from .bench import BenchEmulator
from .create import CreateEmulator
from .koala import KoalaEmulator
