"""Ports: what the robot needs of one (pyserial's `Serial` has it all), a simulated device in
their place, and opening one by name with pyserial, imported only then.
"""

from __future__ import annotations

import os
import sys
import threading
from collections import deque
from collections.abc import Callable, Mapping, Sequence
from typing import Any, Protocol

from rdisc.engine.errors import RdisConnectionError
from rdisc.engine.plans import Connection, Interface, Primitive
from rdisc.engine.values import Args
from rdisc.engine.wire import Incoming


class Port(Protocol):
    """What the robot needs of an open port; pyserial's `Serial` has all of it (`dtr` and `rts`,
    its modem lines, only a primitive with `lines` sets)."""

    timeout: float | None
    dtr: bool
    rts: bool

    def write(self, data: bytes, /) -> int | None: ...

    def read(self, size: int = 1, /) -> bytes: ...

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes: ...

    def reset_input_buffer(self) -> None: ...

    def close(self) -> None: ...


PortSpec = str | os.PathLike[str] | Port | Mapping[str, "str | os.PathLike[str] | Port"]
"""A port for every connection (a pyserial port name or URL, or an open port), or a dict
from connection name to port."""


class Simulator(Protocol):
    """A simulated device in place of the ports (`Robot.open(sim=...)`; `rdisc.sim` gives one
    over MuJoCo): it takes what the host commands, by primitive and interface with their
    parameters' values (`interface`, `exchange`), and answers each reply a primitive reads with
    its values (`reply`; `place`, the reply's among `replies N` or `replies { }`, None for a
    primitive's one reply), the reply's shape (`Primitive.reply`) saying which it reads, or, for
    a primitive with an `error` reply, that reply's values in its place (`error`; None: none). In
    simulated time (`realtime` False) the robot runs no threads: its schedule and delays advance
    the simulation."""

    realtime: bool

    def interface(self, plan: Interface, args: Args, /) -> None: ...

    def exchange(self, plan: Primitive, local: Args, /) -> None: ...

    def reply(self, plan: Primitive, local: Args, place: int | None, /) -> Sequence[Any]: ...

    def error(self, plan: Primitive, local: Args, /) -> Sequence[Any] | None: ...

    def advance(self, seconds: float, /) -> None: ...

    def now(self) -> float: ...


class _Lock(Protocol):
    """A port's exchange lock: re-entrant (a `threading.RLock`, or `schedule._FairLock`)."""

    def acquire(self) -> bool: ...
    def release(self) -> None: ...


class _FairLock:
    """A port's lock under `dual` and `multiple` (`fair`): re-entrant as the port's own, and handed over in
    the order it was asked for. A plain lock lets the thread that releases it take it straight
    back, so a periodic thread going from one exchange to the next could keep a waiting command
    out for ever; this one gives the port to the command when the exchange in flight ends."""

    __slots__ = ("_depth", "_guard", "_owner", "_queue")

    def __init__(self) -> None:
        self._guard = threading.Lock()
        self._owner: int | None = None  # None only while nobody waits: a release hands it over
        self._depth = 0
        self._queue: deque[tuple[int, threading.Lock]] = deque()

    def acquire(self) -> bool:
        me = threading.get_ident()
        with self._guard:
            if self._owner == me:
                self._depth += 1
                return True
            if self._owner is None:
                self._owner, self._depth = me, 1
                return True
            gate = threading.Lock()
            gate.acquire()
            self._queue.append((me, gate))
        try:
            gate.acquire()  # released when the lock is handed to this thread
        except BaseException:  # a signal's exception while waiting: leave the queue, or give it on
            with self._guard:
                if self._owner != me:
                    self._queue.remove((me, gate))
                    raise
                self._depth = 1
            self.release()
            raise
        return True

    def _is_owned(self) -> bool:
        """Held by this thread: the name of an RLock's own test (which `threading.Condition` uses)."""
        return self._owner == threading.get_ident()

    def release(self) -> None:
        with self._guard:
            if self._owner != threading.get_ident():
                raise RuntimeError("cannot release a lock this thread does not hold")
            self._depth -= 1
            if self._depth:
                return
            if not self._queue:
                self._owner = None
                return
            self._owner, gate = self._queue.popleft()
            self._depth = 1
        gate.release()


_Lane = tuple[Callable[[], bool], Callable[[], None], Callable[[bytes], "int | None"]]
"""A port's lock taken and let go, and its write, bound once (`_Port.lane`): what a driver's
typed method writes a plain command through itself, inline (`Exchange._lanes`)."""


class _Port:
    """One open port, shared by the connections given the same one, with its exchange lock."""

    __slots__ = ("input", "io", "lock", "owned", "write")

    def __init__(self, io: Port, owned: bool, fair: bool = False) -> None:
        self.io = io
        self.write = io.write  # bound once: a plain command's one call of the port
        self.input = Incoming(io)  # what replies are read from: bytes put back, bytes taken, the deadline
        self.owned = owned  # opened by the robot, so closed by it too
        # Re-entrant: a signal landing between a command's `acquire` and its `try` leaves the lock
        # held by the interrupted thread, which must still write the terminate hook's stop command.
        # Fair when a connection on it is `threading dual` or `multiple`: made so here, before any
        # write binds the lock.
        self.lock: _Lock = _FairLock() if fair else threading.RLock()

    def held_here(self) -> bool:
        """Whether this thread holds the port's lock."""
        owned: Callable[[], bool] = getattr(self.lock, "_is_owned")  # noqa: B009 - not in RLock's stub
        return owned()

    def lane(self) -> _Lane:
        return self.lock.acquire, self.lock.release, self.write


class _Link:
    """A connection and its port."""

    __slots__ = ("connection", "port")

    def __init__(self, connection: Connection, port: _Port) -> None:
        self.connection = connection
        self.port = port


def _open_port(connection: Connection, url: str, timeout: float, baud: int) -> Port:
    """A port opened with pyserial (any port name or URL it knows) at `baud`, its character the
    connection's serial line (8N1 unless the description says otherwise: S.BUS is 8E2)."""
    try:
        import serial  # type: ignore[import-untyped, import-not-found, unused-ignore]
    except ImportError as err:
        raise RdisConnectionError(f"{connection.name}: opening {url} needs pyserial (pip install pyserial)") from err
    try:
        port: Port = serial.serial_for_url(url, baudrate=baud, bytesize=connection.data_bits,
                                           parity=connection.parity[0].upper(),  # pyserial's "N", "E", ...
                                           stopbits=connection.stop_bits,
                                           timeout=timeout, write_timeout=timeout)
    except (serial.SerialException, OSError, ValueError) as err:
        raise RdisConnectionError(f"{connection.name}: cannot open {url}: {err}") from err
    return port


def _write_timed_out(err: BaseException) -> bool:
    """Whether a port's exception is pyserial's for a write that could not complete in time."""
    serial = sys.modules.get("serial")  # a port that raises it has imported it
    timeout_type = getattr(serial, "SerialTimeoutException", None) if serial is not None else None
    return timeout_type is not None and isinstance(err, timeout_type)
