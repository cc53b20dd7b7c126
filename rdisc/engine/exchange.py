"""The exchange with a device: the part of a robot that writes requests, reads replies, runs
their post-actions and tells the callbacks, one at a time. Apart from the lifecycle (`robot`),
so that each can be read on its own.
"""

from __future__ import annotations

import struct
import threading
import time
from collections.abc import Callable, Mapping
from typing import Any

from rdisc.engine.errors import (
    RdisConnectionError,
    RdisError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)
from rdisc.engine.operations import EVAL_ERRORS
from rdisc.engine.plans import (
    FixedReply,
    NoReply,
    Primitive,
    SeveralReplies,
)
from rdisc.engine.ports import Port, Simulator, _Lane, _Port
from rdisc.engine.replies import Replies, _ReplyPart
from rdisc.engine.telling import _lines_text, _ms
from rdisc.engine.values import (
    Args,
    Value,
)


class Exchange(Replies):
    """The part of a Robot that talks to its devices: it writes requests, reads replies and
    decodes them, runs their post-actions, and tells the callbacks what happened (one at a
    time, a failing one reported). `Robot` is the rest of it, and sets what is declared here."""

    # ---- writing requests, reading replies, running post-actions ------------------------------------

    # The write of a request that has no reply and sets no modem line (every plain command's path):
    # `_write_watched`, or on ports no I/O or trace callback watches `_unwatched_write`'s, which
    # does the same but tell the callbacks. Chosen when the ports open and when a callback comes
    # (`_choose_write`), not tested at each write.
    _write: Callable[[Primitive, bytes], None]
    # Each connection's lane (`_Port.lane`: its port's lock and write), in the order of the
    # connections, through which a driver's typed method writes a plain command itself:
    # `_lane_write`'s statements in the method, one call fewer on every command's path
    # (by position: a tuple's item is found faster than a dict's). None while the robot is not
    # running on ports (`_direct`) or a callback watches the writes: the method then goes the
    # general way.
    _lanes: tuple[_Lane | None, ...]
    _direct: bool

    def _choose_write(self) -> None:
        """Put the write that fits in place: the plain one on open ports no callback watches, and
        the lanes to them. Under the callback lock, which a callback's registration holds: the
        last choice sees the last callback."""
        with self._callback_lock:
            plain = not self._watched and bool(self._ports)
            self._write = _unwatched_write(self, self._ports) if plain else self._write_watched
            ports = self._ports if plain and self._direct else {}
            self._lanes = tuple(ports[name].lane() if name in ports else None for name in self.device.connections)

    def _write_watched(self, plan: Primitive, request: bytes) -> None:
        """Under the port's lock write a request that has no reply and sets no modem line (the
        port and its lock found once, nothing allocated); then show the callbacks.
        `_write_lines` is the way of one that sets lines or writes nothing."""
        try:
            port = self._ports[plan.connection]
        except KeyError:
            raise RdisConnectionError(f"{plan.connection}: not open") from None
        lock = port.lock
        lock.acquire()  # acquire/release rather than `with`: cheaper, and this is every command's path
        try:
            if self._closed:  # under the lock: a write that got it before the terminate hooks comes before them
                self._refuse(plan)
            port.write(request)
            if self._watched:
                self._happened("write", plan.connection, request)
        except RdisError:
            raise
        except Exception as err:  # whatever the port raises, it failed
            raise self._port_error(plan, err) from err
        finally:
            lock.release()
            if self._watched:
                self._show()

    def _write_lines(self, plan: Primitive, request: bytes, levels: dict[str, Value] | None) -> None:
        """`_write` of a primitive with no reply that sets modem lines first, or writes nothing
        (no encoder: only lines)."""
        link = self._links.get(plan.connection)
        if link is None:
            raise RdisConnectionError(f"{plan.connection}: not open")
        port = link.port
        watched = self._watched
        port.lock.acquire()
        try:
            if self._closed:
                self._refuse(plan)
            if levels is not None:
                self._set_lines(plan, port.io, levels)
                if watched:
                    self._happened("lines", plan.connection, _lines_text(levels))
            if plan.encoder is not None:
                port.write(request)
                if watched:
                    self._happened("write", plan.connection, request)
        except RdisError:
            raise
        except Exception as err:  # whatever the port raises, it failed
            raise self._port_error(plan, err) from err
        finally:
            port.lock.release()
            if watched:
                self._show()

    def _refuse(self, plan: Primitive) -> None:
        """While the robot closes, a write is refused unless the closing thread makes it (its
        terminate hooks); once they are done, every write is: the stop stays the last command."""
        closer = self._closer
        if closer is None or closer != threading.get_ident():
            raise RdisConnectionError(f"{self.name}: {plan.name} not sent: the robot is "
                                      f"{'closing' if closer is not None else 'closed'}")

    @staticmethod
    def _set_lines(plan: Primitive, io: Port, levels: dict[str, Value]) -> None:
        """Set the primitive's modem lines and send its break in the order written (pyserial's
        `dtr`, `rts`, and `break_condition` held `level` ms: its `send_break` rounds a POSIX
        break to 0.25 s steps, which no short break survives). A port that refuses (a pty, a
        port with no modem lines) is an RdisConnectionError."""
        for line, level in levels.items():
            try:
                if line == "dtr":
                    io.dtr = bool(level)
                elif line == "rts":
                    io.rts = bool(level)
                else:
                    assert isinstance(level, float)  # the checker's: a constant, in ms
                    if not hasattr(io, "break_condition"):
                        raise RdisConnectionError(f"{plan.connection}: {plan.name}: cannot send a break of "
                                                  f"{level:g} ms: the port has no `break_condition`")
                    io.break_condition = True
                    try:
                        time.sleep(level / 1000.0)
                    finally:
                        io.break_condition = False
            except RdisError:
                raise
            except Exception as err:  # whatever the port raises, it refused
                said = f"send a break of {_ms(level)}" if line == "break" else f"set {line} = {bool(level)}"
                raise RdisConnectionError(f"{plan.connection}: {plan.name}: cannot {said}: {err}") from err

    def _exchange(self, plan: Primitive, values: Args, local: Args) -> None:
        """Encode and frame the request; under the port's lock write it and read the reply;
        then show the I/O callbacks every byte written and read, and run the post-actions. After
        a timeout or a reply that does not match, the same request again, `retry N` more times.

        `local` is the primitive's parameters' values (a direct call passes its values)."""
        if self._sim is not None:
            self._simulated(self._sim, plan, values, local)
            return
        request, fields, levels = self._request(plan, values, local)
        if isinstance(plan.reply, NoReply):
            if levels is None and plan.encoder is not None:
                self._write(plan, request)
            else:
                self._write_lines(plan, request, levels)
            if plan.actions is not None:
                self._assign(plan, local, ())
            return
        tries = plan.retries + 1 if request else 1  # a listener has nothing to resend
        for tried in range(1, tries + 1):  # `retry N`: the same bytes again, as published drivers resend
            try:
                self._exchange_once(plan, request, fields, levels, local)
                return
            except (RdisTimeout, RdisProtocolError) as err:
                if tried == tries:
                    if tries == 1:
                        raise
                    raise type(err)(f"{err} ({tries} tries)") from None

    def _ask(self, plan: Primitive, request: bytes, local: Args) -> None:
        """A plain exchange (`Primitive.asked`) in one step: what `_exchange` does for it, with the
        reply's known size read from the port in one read and decoded by its precompiled struct.
        The callbacks see what they see of any exchange, and a failure is the same typed error."""
        try:
            port = self._ports[plan.connection]
        except KeyError:
            raise RdisConnectionError(f"{plan.connection}: not open") from None
        io = port.io
        lock = port.lock
        shape: FixedReply = plan.reply  # type: ignore[assignment]  # (`_asked_at_once`)
        decoder = shape.decoder
        watched = self._watched
        data = b""
        lock.acquire()
        try:
            if self._closed:
                self._refuse(plan)
            io.reset_input_buffer()
            port.input.pending.clear()  # (the reader's `clear`: no byte put back is the reply's)
            port.write(request)
            if watched:
                self._happened("write", plan.connection, request)
            if plan.timeout is not None:
                io.timeout = plan.timeout
            data = io.read(decoder.size)
        except RdisError:
            raise
        except Exception as err:  # whatever the port raises, it failed
            raise self._port_error(plan, err) from err
        finally:
            try:
                if data and watched:  # stamped when its last byte came
                    self._happened("read", plan.connection, data)
                if plan.timeout is not None:
                    io.timeout = self.timeout
            finally:
                lock.release()
                if watched:
                    self._show()
        if not data:
            raise RdisTimeout(f"{plan.name}: no reply within {plan.timeout or self.timeout:g} s")
        reply = (decoder.struct.unpack(data) if decoder.plain and len(data) == decoder.size
                 else decoder.decode(plan.name, data))
        if plan.expect is not None:
            self._met(plan, local, reply)
        if plan.actions is not None:
            self._assign(plan, local, reply)

    def _exchange_once(self, plan: Primitive, request: bytes, fields: list[Any], levels: dict[str, Value] | None,
                       local: Args) -> None:
        """One try: under the port's lock write the request and read the reply; then show the
        I/O callbacks every byte written and read, and run the post-actions."""
        link = self._links.get(plan.connection)
        if link is None:
            raise RdisConnectionError(f"{plan.connection}: not open")
        port = link.port
        io = port.io
        lock = port.lock
        reader = port.input
        wait = plan.timeout or self.timeout
        parts: list[_ReplyPart] = []
        failed: BaseException | None = None
        watched = self._watched
        lock.acquire()
        try:
            if self._closed:
                self._refuse(plan)
            if levels is not None:
                self._set_lines(plan, io, levels)
                if watched:
                    self._happened("lines", plan.connection, _lines_text(levels))
            if request:  # a listener (no request) keeps what has arrived: its reply is the next one
                io.reset_input_buffer()
                reader.clear()
                io.write(request)
                if watched:
                    self._happened("write", plan.connection, request)
            if plan.timeout is not None:
                io.timeout = plan.timeout
            reader.begin(wait)
            parts = self._read(plan, plan.reply, plan.frame, link, reader, fields, request, wait, local)
        except RdisError as err:
            failed = err
        except Exception as err:  # noqa: BLE001 - whatever the port raises, it failed
            failed = self._port_error(plan, err)
            failed.__cause__ = err
        finally:
            data = reader.end()
            if data and watched:  # stamped when its last byte came
                self._happened("read", plan.connection, data)
            if plan.timeout is not None:
                io.timeout = self.timeout
            lock.release()
        # The callbacks run once the port is free again: one that calls the robot (or waits for a
        # thread that does) cannot deadlock against this exchange. They see what crossed the wire
        # in the order it did: no other thread's write comes between this write and its reply.
        if watched:
            self._show()
        if failed is not None:
            raise failed
        self._store(parts)

    def _store(self, parts: list[_ReplyPart]) -> None:
        """Run the post-actions on a reply read whole (every part decoded and met, so a bad one
        changed no state): each sub-payload's, record's or listed reply's in the order they came,
        published together."""
        taken = [part for part in parts if part[0].actions is not None]
        if taken:
            self._assign_each(taken)

    def _request(self, plan: Primitive, values: Args,
                 local: Args) -> tuple[bytes, list[Any], dict[str, Value] | None]:
        """The request encoded and framed, the frame's fields, and the modem lines' levels. A
        reply for each element of an empty array is none to read: refused before anything is written."""
        shape = plan.reply
        if type(shape) is SeveralReplies and shape.over >= 0 and not local[shape.over]:
            raise RdisValueError(f"{plan.name}: parameter {plan.params[shape.over].name} is empty: "
                                 "a reply for each of its elements is none to read")
        request = plan.encoder.encode(plan.name, values) if plan.encoder is not None else b""
        use = plan.frame
        fields: list[Any] = []
        if use is not None:
            try:
                given = use.args(self._state, local)
                fields = use.frame.values(plan.name, given)
                request = use.frame.wrap(request, fields, use.frame.layout(plan.name, given))
            except RdisError:
                raise
            except (struct.error, *EVAL_ERRORS) as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
        levels = None
        if plan.lines is not None:
            try:
                levels = plan.lines(self._state, local)
            except EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
        return request, fields, levels

    def _simulated(self, sim: Simulator, plan: Primitive, values: Args, local: Args) -> None:
        """A primitive against the simulator: its request is encoded as for a port (the I/O
        callbacks see it written, and what a port refuses is refused), the simulator takes the
        parameters' values and gives each reply's, which meet the `expect` and go to the
        post-actions as a reply read from a port would."""
        if self._closed:
            self._refuse(plan)
        request, _fields, levels = self._request(plan, values, local)
        sim.exchange(plan, local)
        if self._watched:
            if levels is not None:
                self._happened("lines", plan.connection, _lines_text(levels))
            if request:
                self._happened("write", plan.connection, request)
            self._show()
        self._store(self._given(sim, plan, local))


def _unwatched_write(robot: Exchange, ports: Mapping[str, _Port]) -> Callable[[Primitive, bytes], None]:
    """`Exchange._write_watched` on ports no callback watches: each port's `_lane_write`, the one
    itself when every connection shares one port."""
    writes = {id(port): _lane_write(robot, port) for port in ports.values()}
    if len(writes) == 1:
        (write_one,) = writes.values()
        return write_one
    by_connection = {name: writes[id(port)] for name, port in ports.items()}

    def write_any(plan: Primitive, request: bytes) -> None:
        by_connection[plan.connection](plan, request)  # every connection has its port once they are open

    return write_any


def _lane_write(robot: Exchange, port: _Port) -> Callable[[Primitive, bytes], None]:
    """The plain write on one port, as one closure over its lane (the port's lock and write,
    bound once): the lock around the write, the refusal while closing, the typed errors of
    `_write_watched`. A driver's typed method writes a plain command with `write_one`'s
    statements, which the emitter takes from this text (rdisc.emit.python_lane): the rule is
    written here only."""
    acquire, release, write = port.lane()

    def write_one(plan: Primitive, request: bytes) -> None:
        acquire()  # no `with`: cheaper; a signal before the `try` leaves the lock to this thread, re-entrant
        try:
            if robot._closed:  # under the lock: a write that got it first precedes the terminate hooks' stop
                robot._refuse(plan)
            write(request)
        except RdisError:
            raise
        except Exception as err:  # whatever the port raises, it failed
            raise robot._port_error(plan, err) from err
        finally:
            release()

    return write_one
