"""The exchange with a device: the part of a robot that writes requests, reads replies, runs
their post-actions and tells the callbacks, one at a time. Apart from the lifecycle (`robot`),
so that each can be read on its own.
"""

from __future__ import annotations

import logging
import struct
import threading
import time
from collections import deque
from collections.abc import Callable, Mapping, Sequence
from typing import Any, assert_never

from rdisc.engine.codec import Match, Unpack
from rdisc.engine.errors import (
    RdisCallbackError,
    RdisConnectionError,
    RdisDeviceError,
    RdisError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)
from rdisc.engine.kalman import KalmanFilter
from rdisc.engine.operations import EVAL_ERRORS, MAX_ARRAY, MAX_INT, MAX_LINE, LookupMiss
from rdisc.engine.plans import (
    Device,
    ErrorReply,
    FixedReply,
    FramedReply,
    FrameUse,
    KeyedReply,
    LineReply,
    ListedReplies,
    NoReply,
    Output,
    Primitive,
    Records,
    Reply,
    SeveralReplies,
    SubPayloads,
    TaggedReply,
    TaggedStream,
)
from rdisc.engine.ports import Port, Simulator, _Lane, _Link, _Port, _write_timed_out
from rdisc.engine.values import (
    Args,
    ErrorCallback,
    IoCallback,
    OutputCallback,
    OutputMessage,
    TraceCallback,
    Value,
)
from rdisc.engine.wire import ChecksumError, FrameError, Incoming

_log = logging.getLogger("rdisc")

_ReplyPart = tuple[Primitive, Args, Sequence[Any]]
"""A reply read, or a part of one: the plan whose post-actions take it, what they read besides it
(the parameters' values, and a tag or a record's position after them), and its values."""


class Exchange:
    """The part of a Robot that talks to its devices: it writes requests, reads replies and
    decodes them, runs their post-actions, and tells the callbacks what happened (one at a
    time, a failing one reported). `Robot` is the rest of it, and sets what is declared here."""

    device: Device
    name: str
    timeout: float
    _state: dict[str, Value]
    _read_ns: int | None  # when a reply last changed the state (ns since the epoch); None: none has
    _state_lock: threading.Lock
    _callback_lock: threading.RLock
    _ticking: threading.local  # `.port`: the port this thread's tick holds whole (`threading single`), else None
    _filters: dict[tuple[str, str], KalmanFilter]  # (output, field): its running filter, made when first delivered
    _output_callbacks: list[OutputCallback]
    _error_callbacks: list[ErrorCallback]
    _io_callbacks: list[IoCallback]
    _trace_callbacks: list[TraceCallback]
    _watched: bool  # an I/O or trace callback is registered: the events are queued and shown
    # What crossed the wire (and each reply skipped), stamped and queued as it happens, under the
    # port's lock: the callbacks are shown it in that order, once the port is free (`_show`).
    _events: deque[tuple[float, str, str, bytes]]
    _events_lock: threading.Lock
    _clock: Callable[[], float]
    _run_callbacks: list[Callable[[str, str, str], object]]
    _links: dict[str, _Link]
    _ports: dict[str, _Port]  # each connection's port, for a plain write to find at once
    # Closing (`Robot.close`): from the moment it begins nothing is written but by the thread that
    # closes (`_closer`: the terminate hooks), and once they are done nothing at all (`_closer` None).
    _closed: bool
    _closer: int | None
    _sim: Simulator | None  # a simulated device in place of the ports (`_simulated`)

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

    def _read(self, plan: Primitive, shape: Reply, use: FrameUse | None, link: _Link, reader: Incoming,
              fields: list[Any], request: bytes, wait: float, local: Args) -> list[_ReplyPart]:
        """The reply, read from the port as `shape` says (through `use`, its frame), each part
        decoded and meeting its `expect`: the parts whose post-actions take it."""
        match shape:
            case NoReply():
                return [(plan, local, ())]
            case LineReply(decoder=decoder):
                end = link.connection.terminator
                line = reader.read_until(end, MAX_LINE)
                if not line:
                    raise RdisTimeout(f"{plan.name}: no reply within {wait:g} s")
                if not line.endswith(end):
                    raise RdisProtocolError(f"{plan.name}: reply line not terminated: {line.decode('latin-1')!r}")
                text = line[: -len(end)]
                if end == b"\n" and text.endswith(b"\r"):  # the default takes CR LF as well as LF
                    text = text[:-1]
                return [(plan, local, self._met(plan, local, decoder.decode(plan.name, text)))]
            case FixedReply(decoder=unpack, error=error):
                if error is not None and error.when is None:
                    self._unframed_error(plan, error, reader, local)
                data = reader.read(unpack.size)
                if not data:
                    raise RdisTimeout(f"{plan.name}: no reply within {wait:g} s")
                return [(plan, local, self._met(plan, local, self._refused(plan, error, local,
                                                                            unpack.decode(plan.name, data))))]
            case TaggedStream():
                return [self._read_tagged(plan, shape, reader, wait, local)]
            case FramedReply(decoder=decoding, skip=skip, error=error):
                # The decoding's size is the payload's, unless stuffing may have lengthened it on
                # the wire (then the constant after the payload ends it), or an error may stand in
                # the frame (then the frame says where the payload ends).
                assert use is not None
                stuffed = use.frame.stuffing is not None and any(side.delimiter for side in use.frame.replies)
                inside = error is not None and error.frame is None and error.when is None
                size = decoding.size if decoding is not None and not stuffed and not inside else -1

                def taken(payload: bytes) -> list[_ReplyPart]:
                    if inside and error is not None and payload.startswith(error.marker):
                        raise self._device_error(plan, error, payload[len(error.marker):])
                    return [(plan, local, self._met(plan, local, self._refused(
                        plan, error, local, decoding.decode(plan.name, payload)))
                             if decoding else ())]

                return self._framed(plan, use, reader, fields, request, wait, skip, size, taken,
                                    error if error is not None and error.frame is not None else None, local)
            case TaggedReply(skip=skip):
                return self._framed(plan, use, reader, fields, request, wait, skip, -1,
                                    lambda payload: [self._tagged(plan, shape, payload, local)])
            case SubPayloads(skip=skip):
                return self._framed(plan, use, reader, fields, request, wait, skip, -1,
                                    lambda payload: self._sub_payloads(plan, shape, payload, local))
            case Records(skip=skip):
                return self._framed(plan, use, reader, fields, request, wait, skip, -1,
                                    lambda payload: self._records(plan, shape, payload, local))
            case SeveralReplies(count=count, each=each, frames=frames, over=over):  # value i of them all, as one array
                turns: list[tuple[Primitive, Reply, FrameUse | None, Args]]
                if over >= 0:  # a reply for each element, its frame's arguments reading it after the parameters
                    given = local[: len(plan.params)]
                    turns = [(plan, each, frames[0], [*given, element]) for element in local[over]]
                else:
                    turns = [(plan, each, frames[n] if frames else use, local) for n in range(count)]
                got = self._in_turn(plan, turns, link, reader, fields, request, wait, local)
                return [(plan, local, tuple(zip(*(values for _, _, values in got))))]
            case ListedReplies(answers=answers):
                listed = [(answer, answer.reply, answer.frame, local) for answer in answers]
                return self._in_turn(plan, listed, link, reader, fields, request, wait, local)
            case KeyedReply():  # `Robot._primitive_in_full` runs the entry its key chooses
                raise AssertionError(f"{plan.name}: a reply table's entry is chosen before the exchange")
            case _:
                assert_never(shape)

    def _framed(self, plan: Primitive, use: FrameUse | None, reader: Incoming, fields: list[Any], request: bytes,
                wait: float, skip: bool, size: int, taken: Callable[[bytes], list[_ReplyPart]],
                error: ErrorReply | None = None, local: Args | None = None) -> list[_ReplyPart]:
        """A reply frame's payload (`size`: its decoding's, or -1), as `taken` reads it: once, or
        under `skip unmatched` until one is read, within the deadline.

        `skip unmatched` reads past a frame of another device or message (a constant or field
        not the request's, a tag without an entry, a payload that does not decode or meet the
        `expect`) and bytes that are no frame; it raises for a frame whose checksum is wrong (this
        device's reply, corrupted). The next frame is looked for from the byte after the start of
        the one read past, unless a checksum vouched for it whole. Each is told to the trace.

        `error`: an error reply in a frame of its own, tried first at each frame (`_framed_error`)."""
        assert use is not None
        frame = use.frame
        while True:
            raw = b""
            try:
                if error is not None:
                    self._framed_error(plan, error, reader, request, local or [])
                raw, payload = frame.read(reader, fields, request, size)
                return taken(payload)
            except (FrameError, RdisProtocolError) as err:
                nothing = isinstance(err, FrameError) and err.timeout
                if skip and not nothing and not isinstance(err, ChecksumError):
                    if raw and not frame.vouched:  # bytes that decoded as no reply of this one may hold its start
                        reader.put_back(raw[1:])
                    if self._trace_callbacks:
                        said = str(err) if isinstance(err, RdisProtocolError) else f"{plan.name}: {err}"
                        self._happened("skip", plan.connection, said.encode("utf-8"))
                    if reader.deadline is not None and time.monotonic() < reader.deadline:
                        continue
                if nothing or (skip and not isinstance(err, ChecksumError)):
                    raise RdisTimeout(f"{plan.name}: no {'matching reply' if skip else 'reply'} "
                                      f"within {wait:g} s") from None
                if isinstance(err, RdisProtocolError):
                    raise
                raise RdisProtocolError(f"{plan.name}: {err}") from None

    def _framed_error(self, plan: Primitive, error: ErrorReply, reader: Incoming, request: bytes,
                      local: Args) -> None:
        """Raise the device's error if the next frame is its error frame (with the bytes it starts
        with); else give back every byte read, for the reply to be read from its first. Nothing
        at all is a timeout, and an error frame whose checksum is wrong a FrameError (this
        device's error reply, corrupted). An error frame no longer than the reply costs nothing;
        a longer one is read to the deadline before the reply is."""
        use = error.frame
        assert use is not None
        try:
            fields = use.frame.values(plan.name, use.args(self._state, local))
        except (struct.error, *EVAL_ERRORS) as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        decoder = error.decoder
        headers = use.frame.headers
        if all(headers):  # where the reply starts: a frame's reader would skip bytes to find its header
            head = reader.read(max(len(header) for header in headers))
            reader.put_back(head)
            if not head:
                raise FrameError(f"{use.frame.name}: no reply", timeout=True)
            if not any(head.startswith(header) for header in headers):
                return
        try:
            raw, payload = use.frame.read(reader, fields, request, len(error.marker) + decoder.size, whole=True)
        except ChecksumError:
            raise
        except FrameError as err:
            if err.timeout:
                raise
            return
        if not payload.startswith(error.marker):
            reader.put_back(raw)
            return
        raise self._device_error(plan, error, payload[len(error.marker):])

    def _unframed_error(self, plan: Primitive, error: ErrorReply, reader: Incoming, local: Args) -> None:
        """Raise the device's error if the reply starts with its bytes (a NACK); else give them
        back, for the reply to be read from its first."""
        marker = error.marker
        head = reader.read(len(marker))
        if head != marker:
            reader.put_back(head)
            return
        size = error.decoder.size
        body = reader.read(size)
        if len(body) < size:
            raise RdisProtocolError(f"{plan.name}: an error reply {marker.hex(' ')} then {len(body)} bytes, "
                                    f"where its decoding takes {size}")
        raise self._device_error(plan, error, body)

    def _refused(self, plan: Primitive, error: ErrorReply | None, local: Args, reply: Sequence[Any]) -> Sequence[Any]:
        """The decoded reply, unless it is the device's error (`error when COND`: the condition
        over it holds), raised before its `expect` and post-actions, as an error reply is."""
        if error is None or error.when is None:
            return reply
        try:
            refused = error.when(self._state, local, reply)
        except EVAL_ERRORS as err:
            raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r}: its `error when` failed: {err}") from None
        if refused:
            raise device_error(plan, error, tuple(reply))
        return reply

    @staticmethod
    def _device_error(plan: Primitive, error: ErrorReply, body: bytes) -> RdisDeviceError:
        """The device's error: its bytes decoded, the first value its code, named by the enum."""
        return device_error(plan, error, tuple(error.decoder.decode(plan.name, body)))

    def _in_turn(self, plan: Primitive, turns: list[tuple[Primitive, Reply, FrameUse | None, Args]], link: _Link,
                 reader: Incoming, fields: list[Any], request: bytes, wait: float, local: Args) -> list[_ReplyPart]:
        """`replies N` and `replies { }`: a reply for each turn, read in turn as one is (each as
        its plan and shape say, meeting its `expect`; through its own frame, with its own field
        values over the turn's arguments, where it has one), all within the one deadline, in the
        order they came."""
        got: list[_ReplyPart] = []
        count = len(turns)
        for n, (own, shape, use, framed) in enumerate(turns):
            if use is not None and use is not plan.frame:
                try:
                    fields = use.frame.values(plan.name, use.args(self._state, framed))
                except (struct.error, *EVAL_ERRORS) as err:
                    raise RdisValueError(f"{plan.name}: {err}") from None
            try:
                got.append(self._read(own, shape, use, link, reader, fields, request, wait, local)[0])
            except RdisTimeout:
                if not n:
                    raise
                raise RdisTimeout(f"{plan.name}: {n} of {count} replies within {wait:g} s") from None
            except RdisProtocolError as err:
                raise RdisProtocolError(f"{plan.name}: reply {n + 1} of {count}: "
                                        f"{str(err).removeprefix(plan.name + ': ')}") from None
        return got

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

    def _given(self, sim: Simulator, plan: Primitive, local: Args) -> list[_ReplyPart]:
        """The replies a simulator gives in place of the port's (`Simulator.reply`), as the parts
        a reply of the plan's shape is read into: each meeting its plan's `expect`."""
        shape = plan.reply
        match shape:
            case NoReply():
                return [(plan, local, ())]
            case FixedReply(error=error) | FramedReply(error=error) if error is not None:
                failing = sim.error(plan, local)  # the device's error reply in place of its reply
                if failing is not None:
                    raise device_error(plan, error, tuple(failing))
                return [(plan, local, self._met(plan, local, sim.reply(plan, local, None)))]
            case LineReply() | FixedReply() | FramedReply() | TaggedReply() | TaggedStream():
                return [(plan, local, self._met(plan, local, sim.reply(plan, local, None)))]
            case SubPayloads() | Records():  # a simulator reports none
                return []
            case SeveralReplies(count=count, over=over):
                count = len(local[over]) if over >= 0 else count
                replies = [self._met(plan, local, sim.reply(plan, local, n)) for n in range(count)]
                return [(plan, local, tuple(zip(*replies)))]
            case ListedReplies(answers=answers):
                return [(answer, local, self._met(answer, local, sim.reply(plan, local, n)))
                        for n, answer in enumerate(answers)]
            case KeyedReply():
                raise AssertionError(f"{plan.name}: a reply table's entry is chosen before the exchange")
            case _:
                assert_never(shape)

    def _met(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> Sequence[Any]:
        """The reply, when it meets the primitive's `expect` and its post-actions find each key
        they look up (else, like a reply that does not decode, an RdisProtocolError, which
        `skip unmatched` reads past). The `expect` first: it may guard a lookup (`out[0] in T`)."""
        if plan.expect is not None:
            try:
                met = plan.expect(self._state, local, reply)
            except EVAL_ERRORS as err:
                raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r}: its `expect` failed: {err}") from None
            if not met:
                raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r} does not meet its `expect`")
        if plan.looks_up and (miss := self._missed_lookup(plan, local, reply)) is not None:
            raise RdisProtocolError(miss)
        return reply

    def _missed_lookup(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> str | None:
        """Why the reply is one the primitive cannot read, when its post-actions look up a key
        their table lacks (tried before the reply is taken, so `skip unmatched` reads past it)."""
        if not plan.looks_up or plan.actions is None:
            return None
        try:
            plan.actions(self._state, local, reply)
        except LookupMiss as err:
            return f"{plan.name}: reply {tuple(reply)!r}: {err}"
        except EVAL_ERRORS:
            pass  # raised as the reply is stored
        return None

    def _tagged(self, plan: Primitive, shape: TaggedReply, payload: bytes, local: Args) -> _ReplyPart:
        """The entry a framed reply's tag chooses, the tag after the parameters' values, and
        the rest of the payload decoded by the entry; one whose post-actions look up a key their
        table lacks is a reply this primitive cannot read (`skip unmatched` reads past it)."""
        tag = shape.tag_struct
        if len(payload) < tag.size:
            raise RdisProtocolError(f"{plan.name}: expected {tag.size} bytes or more, got {len(payload)}")
        value = tag.unpack_from(payload)[0]
        case = shape.table.get(value)
        if case is None:
            raise RdisProtocolError(f"{plan.name}: no reply entry for tag {value}")
        decoder = _entry_decoder(case)
        decoded = decoder.decode(plan.name, payload[tag.size :]) if decoder is not None else ()
        if case.looks_up and (miss := self._missed_lookup(case, [*local, value], decoded)) is not None:
            raise RdisProtocolError(miss)
        return case, [*local, value], decoded

    def _records(self, plan: Primitive, shape: Records, payload: bytes, local: Args) -> list[_ReplyPart]:
        """A payload of records, each ended by the marker where it first comes (Firmata's capability
        report: a pin's mode and resolution pairs, then 7F), each decoded by the primitive's decoder
        and meeting its `expect`, its position after the parameters' values (`index`). At most
        MAX_ARRAY of them; a payload whose end is not a marker is refused, as is a record that does
        not decode. All are decoded before any post-action runs, so a bad one changes no state."""
        marker = shape.marker
        decoder = shape.decoder
        parts: list[_ReplyPart] = []
        at = 0
        while at < len(payload):
            end = payload.find(marker, at)
            if end < 0:
                raise RdisProtocolError(f"{plan.name}: the reply's last {len(payload) - at} bytes end in no "
                                        f"{marker.hex(' ')}, so they are no record")
            if len(parts) == MAX_ARRAY:
                raise RdisProtocolError(f"{plan.name}: more than {MAX_ARRAY} records")
            index: Args = [*local, len(parts)]
            name = f"{plan.name}: record {len(parts)}"
            parts.append((plan, index, self._met(plan, index, decoder.decode(name, payload[at:end]))))
            at = end + len(marker)
        return parts

    def _sub_payloads(self, plan: Primitive, shape: SubPayloads, payload: bytes, local: Args) -> list[_ReplyPart]:
        """A payload of sub-payloads (Kobuki's feedback), in any order and any subset, until it
        ends: each its tag, its length when the table gives one, and its bytes, decoded by the
        entry the tag chooses (its plan, the tag after the parameters' values, its values). With
        a length, a tag without an entry is skipped (a newer firmware's) and a length that is
        not its entry's size refused; without one, the entry's size says where the next starts.
        All are decoded before any post-action runs, so a bad one changes no state; one whose
        post-actions look up a key their table lacks makes the reply one this primitive cannot
        read (`skip unmatched` reads past it)."""
        tag = shape.tag_struct
        size = shape.length_struct
        head = tag.size + (size.size if size is not None else 0)
        parts: list[_ReplyPart] = []
        at = 0
        while at < len(payload):
            if len(payload) - at < head:
                raise RdisProtocolError(f"{plan.name}: {len(payload) - at} bytes at offset {at} are no "
                                        f"sub-payload (its head is {head})")
            value = tag.unpack_from(payload, at)[0]
            case = shape.table.get(value)
            if case is None and size is None:
                raise RdisProtocolError(f"{plan.name}: no reply entry for tag {value} at offset {at}")
            decoder = _entry_decoder(case) if case is not None else None
            if size is not None:
                length = size.unpack_from(payload, at + tag.size)[0]
            else:
                assert decoder is not None
                length = decoder.size
            start = at + head
            if start + length > len(payload):
                raise RdisProtocolError(f"{plan.name}: the sub-payload of tag {value} at offset {at} is {length} "
                                        f"bytes, but {len(payload) - start} remain")
            at = start + length
            if case is None or decoder is None:
                continue
            if size is not None and decoder.size >= 0 and length != decoder.size:
                raise RdisProtocolError(f"{plan.name}: the sub-payload of tag {value} at offset {start - head} "
                                        f"is {length} bytes; its entry decodes {decoder.size}")
            decoded = decoder.decode(plan.name, payload[start:at])
            if case.looks_up and (miss := self._missed_lookup(case, [*local, value], decoded)) is not None:
                raise RdisProtocolError(miss)
            parts.append((case, [*local, value], decoded))
        return parts

    def _read_tagged(self, plan: Primitive, shape: TaggedStream, reader: Incoming, wait: float,
                     local: Args) -> _ReplyPart:
        """A tagged reply without a frame (Firmata's stream): the tag, then exactly the bytes its
        entry decodes (a fixed size: checked). Under `skip unmatched` a tag without an entry is
        read past one byte at a time, the next tag looked for from the byte after its first,
        until the reply's deadline."""
        tag = shape.tag_struct
        skip = shape.skip
        missed = f"{plan.name}: no {'matching reply' if skip else 'reply'} within {wait:g} s"
        while True:
            head = reader.read(tag.size)
            if len(head) < tag.size:  # the deadline passed
                if not head or skip:
                    raise RdisTimeout(missed)
                raise RdisProtocolError(f"{plan.name}: expected {tag.size} bytes, got {len(head)}")
            value = tag.unpack(head)[0]
            inner = shape.nested_structs.get(value)
            if inner is not None:  # a nested table: the next tag chooses its entry
                second = reader.read(inner.size)
                head += second
                if len(second) < inner.size:
                    if skip:
                        raise RdisTimeout(missed)
                    raise RdisProtocolError(f"{plan.name}: expected {inner.size} bytes after tag {value}, "
                                            f"got {len(second)}")
                sub_command = inner.unpack(second)[0]
                key: int | tuple[int, int] = (value, sub_command)
                value = sub_command  # the entry's `tag`
            else:
                key = value
            case = shape.table.get(key)
            if case is None:
                said = (f"{plan.name}: no reply entry for tag "
                        f"{' then '.join(map(str, key)) if isinstance(key, tuple) else key}")
                if not skip:
                    raise RdisProtocolError(said)
                if self._trace_callbacks:  # another message's tag: read past, and the trace says why
                    self._happened("skip", plan.connection, said.encode("utf-8"))
                if reader.deadline is not None and time.monotonic() >= reader.deadline:
                    raise RdisTimeout(missed)
                reader.put_back(head[1:])
                continue
            decoder = _entry_decoder(case)
            assert isinstance(decoder, Unpack)  # an unframed entry's size is fixed, or it has an end
            if decoder.until is not None:  # to its end marker, which is not the reply's
                body = reader.read_until(decoder.until)
                if not body.endswith(decoder.until):
                    if skip:
                        raise RdisTimeout(missed)
                    raise RdisProtocolError(f"{plan.name}: no end {decoder.until.hex(' ')} after tag {value} "
                                            f"within {wait:g} s")
                decoded = decoder.decode(plan.name, body[: -len(decoder.until)])
            else:
                body = reader.read(decoder.size)
                if len(body) < decoder.size:
                    if skip:
                        raise RdisTimeout(missed)
                    raise RdisProtocolError(f"{plan.name}: expected {decoder.size} bytes after tag {value}, "
                                            f"got {len(body)}")
                decoded = decoder.decode(plan.name, body)
            miss = self._missed_lookup(case, [*local, value], decoded)
            if miss is None:
                return case, [*local, value], decoded
            if not skip:
                raise RdisProtocolError(miss)
            if self._trace_callbacks:
                self._happened("skip", plan.connection, miss.encode("utf-8"))
            if reader.deadline is not None and time.monotonic() >= reader.deadline:
                raise RdisTimeout(missed)
            reader.put_back((head + body)[1:])  # a message of another kind: looked for from the byte after its tag

    def _port_error(self, plan: Primitive, err: BaseException) -> RdisError:
        """The typed error for what a port raised: a write that timed out, or a failed port."""
        if _write_timed_out(err):
            return RdisTimeout(f"{plan.name}: write not completed within {self.timeout:g} s")
        return RdisConnectionError(f"{plan.connection}: {err}")

    def _assign(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> None:
        """The post-actions: all values computed from one snapshot, then published together."""
        lock = self._state_lock
        lock.acquire()
        try:
            state = self._state
            try:
                changes = plan.actions(state, local, reply)  # type: ignore[misc]  # the caller's test
            except LookupMiss as err:  # a reply this primitive cannot read (a plain exchange's: `_ask`)
                raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r}: {err}") from None
            except EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
            if plan.checked:
                _check_widths(plan, changes)
            self._read_ns = time.time_ns()  # the reply just read: an output's `read_ns`
            self._state = changes if plan.renews else {**state, **changes}
        finally:
            lock.release()

    def _assign_each(self, parts: Sequence[tuple[Primitive, Args, Sequence[Any]]]) -> None:
        """The post-actions of each part in turn (sub-payloads, records), each part's computed from
        the state the one before left; all published together, or none when one fails."""
        with self._state_lock:
            state = self._state
            for plan, local, reply in parts:
                assert plan.actions is not None
                try:
                    changes = plan.actions(state, local, reply)
                except LookupMiss as err:  # a reply this primitive cannot read
                    raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r}: {err}") from None
                except EVAL_ERRORS as err:
                    raise RdisValueError(f"{plan.name}: {err}") from None
                _check_widths(plan, changes)
                state = changes if plan.renews else {**state, **changes}
            self._read_ns = time.time_ns()  # the reply just read: an output's `read_ns`
            self._state = state

    # ---- delivering to callbacks: one at a time, a failing one reported -----------------------------

    def _sense(self, names: tuple[str, ...]) -> None:
        """Make each named sensor fresh before it is read (the Robot's: `rdisc.engine.sensing`)."""
        raise NotImplementedError

    def _deliver(self, plan: Output) -> None:
        if plan.sensors:
            self._sense(plan.sensors)
        with self._state_lock:  # the snapshot and when it was read, together
            state, read_ns = self._state, self._read_ns
        try:
            contents = plan.fields(state)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        message = OutputMessage(plan.name, contents, time.time_ns() if read_ns is None else read_ns)
        port = self._take_turn()
        try:
            if plan.filters:
                message = OutputMessage(plan.name, self._filtered(plan, contents), message.read_ns)
            for callback in list(self._output_callbacks):
                try:
                    callback(message)
                except Exception as err:  # noqa: BLE001 - a user's callback must not stop delivery
                    error = RdisCallbackError(f"{plan.name}: output callback raised {type(err).__name__}: {err}")
                    error.__cause__ = err
                    self._report(error)
        finally:
            self._end_turn(port)

    def _take_turn(self) -> _Port | None:
        """The callbacks' turn (they run one at a time, under the callback lock). A tick that holds
        its port whole (`threading single`) and finds the turn taken lets the port go while it
        waits and runs the callbacks: the turn may be a callback's on another thread that is
        commanding the robot, which waits for the port. Returns that port, to take back after."""
        lock = self._callback_lock
        if lock.acquire(blocking=False):
            return None
        port: _Port | None = getattr(self._ticking, "port", None)
        if port is None:
            lock.acquire()
            return None
        port.lock.release()
        try:
            lock.acquire()
        except BaseException:  # a signal's exception while waiting: the tick holds its port again
            port.lock.acquire()
            raise
        return port

    def _end_turn(self, port: _Port | None) -> None:
        """The turn's end: the callback lock let go, then the tick's port taken back (never the
        port while holding the turn: a host's call holding its port may wait for the turn)."""
        self._callback_lock.release()
        if port is not None:
            port.lock.acquire()

    def _filtered(self, plan: Output, contents: dict[str, Value]) -> dict[str, Value]:
        """The fields a Kalman filter estimates, each filter stepped once by the value delivered
        (a number, or an array's values); under the callback lock, so deliveries step in turn."""
        for given in plan.filters:
            running = self._filters.get((plan.name, given.field))
            if running is None:
                running = self._filters[(plan.name, given.field)] = given.start()
            value = contents[given.field]
            if isinstance(value, (tuple, list)):
                contents = {**contents, given.field: type(value)(running.step(value))}
            else:
                contents = {**contents, given.field: running.step((float(value),))[0]}
        return contents

    def _happened(self, kind: str, connection: str, data: bytes) -> None:
        """An event as it happens, under the port's lock: stamped by the robot's clock and queued
        in the order of the wire, across threads and connections, for `_show`. "write" or "read"
        and the bytes, "lines" and the modem lines set (`_lines_text`), "skip" and why a reply
        was read past."""
        with self._events_lock:
            self._events.append((self._clock(), kind, connection, data))

    def _show(self) -> None:
        """The events queued, in order, to the callbacks, one at a time: the I/O callbacks every
        one but "skip", the trace callbacks every one with its stamp. A thread shows another's
        events that came before its own and are not shown yet (so a line never jumps the queue)."""
        port = self._take_turn()
        try:
            while True:
                with self._events_lock:
                    if not self._events:
                        return
                    when, kind, connection, data = self._events.popleft()
                if kind != "skip":
                    self._notify(self._io_callbacks, connection, kind, connection, data)
                self._notify(self._trace_callbacks, connection, when, kind, connection, data)
        finally:
            self._end_turn(port)

    def _notify(self, callbacks: Sequence[Callable[..., object]], connection: str, *event: Any) -> None:
        for callback in list(callbacks):
            try:
                callback(*event)
            except Exception as err:  # noqa: BLE001 - a user's callback must not stop the I/O
                error = RdisCallbackError(f"{connection}: I/O callback raised {type(err).__name__}: {err}")
                error.__cause__ = err
                self._report(error)

    def _notify_run(self, connection: str, kind: str, name: str) -> None:
        """Tell a recorder that a connection's thread starts a periodic interface or its keepalive."""
        port = self._take_turn()
        try:
            for callback in list(self._run_callbacks):
                callback(connection, kind, name)
        finally:
            self._end_turn(port)

    def _report(self, error: BaseException) -> None:
        port = self._take_turn()
        try:
            callbacks = list(self._error_callbacks)
            if not callbacks:
                _log.warning("%s: %s: %s", self.name, type(error).__name__, error)
            for callback in callbacks:
                try:
                    callback(error)
                except Exception:  # noqa: BLE001, S110 - the contract: an error callback's failure is ignored
                    pass
        finally:
            self._end_turn(port)


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


def device_error(plan: Primitive, error: ErrorReply, values: tuple[Any, ...]) -> RdisDeviceError:
    """The error a device answered instead of `plan`'s reply, as `error` decodes it (`values`): the
    first value its code, named by the enum (a simulated device's too: `Simulator.reply`)."""
    code = values[0] if values and type(values[0]) is int else None
    name = error.names.get(code) if code is not None else None
    if code is None:
        said = "an error reply" + (f" {values!r}" if values else "")
    elif not error.codes:
        said = f"error {code}"
    else:
        said = f"error {code} ({name if name is not None else 'not a member of ' + error.codes})"
    return RdisDeviceError(f"{plan.name}: the device answered {said}", code, name, values)


def _check_widths(plan: Primitive, changes: Mapping[str, Value]) -> None:
    """The post-actions' values that may be too wide (`Primitive.checked`) held to 64 bits and a sign."""
    for name in plan.checked:
        value = changes[name]
        if type(value) is int and not -MAX_INT <= value <= MAX_INT:
            raise RdisValueError(f"{plan.name}: {name} would be a {value.bit_length()}-bit integer; "
                                 "integers are limited to 64 bits and a sign")


def _entry_decoder(entry: Primitive) -> Unpack | Match | None:
    """What decodes a tag's entry: the decoder of its reply (after the tag, the rest of the
    frame's payload, or unframed the bytes it takes), None for an entry that decodes nothing."""
    reply = entry.reply
    return reply.decoder if isinstance(reply, (FixedReply, FramedReply, LineReply)) else None


def _lines_text(levels: Mapping[str, Value]) -> bytes:
    """The modem lines a primitive set and its break, as the I/O callbacks see them:
    b"dtr=False rts=True", b"break=10ms"."""
    return " ".join(f"break={_ms(level).replace(' ', '')}" if line == "break" else f"{line}={bool(level)}"
                    for line, level in levels.items()).encode("ascii")


def _ms(level: Value) -> str:
    """A break's duration as said: "10 ms"."""
    return f"{level:g} ms" if isinstance(level, (int, float)) else repr(level)
