"""The exchange with a device: the part of a robot that writes requests, reads replies, runs
their post-actions and tells the callbacks, one at a time. Apart from the lifecycle (`robot`),
so that each can be read on its own.
"""

from __future__ import annotations

import logging
import struct
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from rdisc.engine.codec import Match, Unpack
from rdisc.engine.errors import (
    RdisCallbackError,
    RdisConnectionError,
    RdisError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)
from rdisc.engine.operations import EVAL_ERRORS, MAX_ARRAY, MAX_INT, MAX_LINE
from rdisc.engine.plans import Output, Primitive
from rdisc.engine.ports import Port, _Link, _write_timed_out
from rdisc.engine.values import Args, ErrorCallback, IoCallback, OutputCallback, Value
from rdisc.engine.wire import FrameError, Incoming

_log = logging.getLogger("rdisc")


class Exchange:
    """The part of a Robot that talks to its devices: it writes requests, reads replies and
    decodes them, runs their post-actions, and tells the callbacks what happened (one at a
    time, a failing one reported). `Robot` is the rest of it, and sets what is declared here."""

    name: str
    timeout: float
    _state: dict[str, Value]
    _state_lock: threading.Lock
    _callback_lock: threading.RLock
    _output_callbacks: list[OutputCallback]
    _error_callbacks: list[ErrorCallback]
    _io_callbacks: list[IoCallback]
    _run_callbacks: list[Callable[[str, str, str], object]]
    _links: dict[str, _Link]
    # Closing (`Robot.close`): from the moment it begins nothing is written but by the thread that
    # closes (`_closer`: the terminate hooks), and once they are done nothing at all (`_closer` None).
    _closed: bool
    _closer: int | None

    # ---- writing requests, reading replies, running post-actions ------------------------------------

    def _write(self, plan: Primitive, request: bytes, levels: dict[str, Value] | None = None) -> None:
        """Under the port's lock set the modem lines, if any, then write a request that has no
        reply (if the primitive has one); then show the I/O callbacks."""
        link = self._links.get(plan.connection)
        if link is None:
            raise RdisConnectionError(f"{plan.connection}: not open")
        port = link.port
        lock = port.lock
        lock.acquire()  # acquire/release rather than `with`: cheaper, and this is every command's path
        try:
            if self._closed:  # under the lock: a write that got it before the terminate hooks comes before them
                self._refuse(plan)
            if levels is not None:
                self._set_lines(plan, port.io, levels)
            if plan.encoder is not None:
                port.io.write(request)
        except RdisError:
            raise
        except Exception as err:  # whatever the port raises, it failed
            raise self._port_error(plan, err) from err
        finally:
            lock.release()
        if self._io_callbacks:
            if levels is not None:
                self._notify_io("lines", plan.connection, _lines_text(levels))
            if plan.encoder is not None:
                self._notify_io("write", plan.connection, request)

    def _refuse(self, plan: Primitive) -> None:
        """While the robot closes, a write is refused unless the closing thread makes it (its
        terminate hooks); once they are done, every write is: the stop stays the last command."""
        closer = self._closer
        if closer is None or closer != threading.get_ident():
            raise RdisConnectionError(f"{self.name}: {plan.name} not sent: the robot is "
                                      f"{'closing' if closer is not None else 'closed'}")

    @staticmethod
    def _set_lines(plan: Primitive, io: Port, levels: dict[str, Value]) -> None:
        """Set the primitive's modem lines in the order written (pyserial's `dtr` and `rts`). A
        port that refuses (a pty, a port with no modem lines) is an RdisConnectionError."""
        for line, level in levels.items():
            try:
                if line == "dtr":
                    io.dtr = bool(level)
                else:
                    io.rts = bool(level)
            except Exception as err:  # whatever the port raises, it refused
                raise RdisConnectionError(f"{plan.connection}: {plan.name}: cannot set {line} = {bool(level)}: "
                                          f"{err}") from err

    def _exchange(self, plan: Primitive, values: Args, local: Args) -> None:
        """Encode and frame the request; under the port's lock write it and read the reply;
        then show the I/O callbacks every byte written and read, and run the post-actions.

        `local` is the primitive's parameters' values (a direct call passes its values)."""
        request, fields, levels = self._request(plan, values, local)
        if not plan.expects_reply:
            self._write(plan, request, levels)
            if plan.actions is not None:
                self._assign(plan, local, ())
            return
        link = self._links.get(plan.connection)
        if link is None:
            raise RdisConnectionError(f"{plan.connection}: not open")
        port = link.port
        io = port.io
        lock = port.lock
        reader = port.input
        wait = plan.timeout or self.timeout
        reply: Sequence[Any] = ()
        failed: BaseException | None = None
        lines_set = written = False
        lock.acquire()
        try:
            if self._closed:
                self._refuse(plan)
            if levels is not None:
                self._set_lines(plan, io, levels)
                lines_set = True
            if request:  # a listener (no request) keeps what has arrived: its reply is the next one
                io.reset_input_buffer()
                reader.clear()
                io.write(request)
                written = True
            if plan.timeout is not None:
                io.timeout = plan.timeout
            reader.begin(wait)
            if plan.answers:
                reply = self._read_replies(plan, link, reader, fields, request, wait, local)
            else:
                plan, local, reply = self._read_reply(plan, link, reader, fields, request, wait, local)
        except RdisError as err:
            failed = err
        except Exception as err:  # noqa: BLE001 - whatever the port raises, it failed
            failed = self._port_error(plan, err)
            failed.__cause__ = err
        finally:
            data = reader.end()
            if plan.timeout is not None:
                io.timeout = self.timeout
            lock.release()
        # I/O callbacks run once the port is free again: one that calls the robot (or
        # waits for a thread that does) cannot deadlock against this exchange. They see the
        # exchange's events together: no other thread's write comes between its write and its
        # reply (a recording would take the reply for that write's).
        if self._io_callbacks:
            with self._callback_lock:
                if lines_set and levels is not None:
                    self._notify_io("lines", plan.connection, _lines_text(levels))
                if written:
                    self._notify_io("write", plan.connection, request)
                if data:
                    self._notify_io("read", plan.connection, data)
        if failed is not None:
            raise failed
        self._store(plan, local, reply)

    def _store(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> None:
        """Run the post-actions on a reply read whole (every part decoded and met, so a bad one
        changed no state): each sub-payload's, record's or listed reply's in the order they came,
        published together; or the primitive's (`replies N`: value i of the replies as one array)."""
        if plan.in_parts:
            self._assign_each([part for part in reply if part[0].actions is not None])
        elif plan.answers and not plan.replies:
            self._assign_each([(answer, local, one) for answer, one in zip(plan.answers, reply)
                               if answer.actions is not None])
        elif plan.actions is not None:
            self._assign(plan, local, tuple(zip(*reply)) if plan.replies else reply)

    def _request(self, plan: Primitive, values: Args,
                 local: Args) -> tuple[bytes, list[Any], dict[str, Value] | None]:
        """The request encoded and framed, the frame's fields, and the modem lines' levels."""
        request = plan.encoder.encode(plan.name, values) if plan.encoder is not None else b""
        use = plan.frame
        fields: list[Any] = []
        if use is not None:
            try:
                fields = use.frame.values(plan.name, use.args(self._state, local))
                request = use.frame.wrap(request, fields)
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

    def _read_reply(self, plan: Primitive, link: _Link, reader: Incoming, fields: list[Any], request: bytes,
                    wait: float, local: Args) -> tuple[Primitive, Args, Sequence[Any]]:
        """The plan whose post-actions take the reply (a tag's entry), what they read besides
        it (the parameters' values, and a tag's after them), and the reply, decoded and meeting
        its `expect`."""
        decoder = plan.decoder
        use = plan.frame
        if use is None or not plan.framed_reply:
            if plan.tag_struct is not None:
                return self._read_tagged(plan, reader, wait, local)
            if isinstance(decoder, Match):  # one line
                end = link.connection.terminator
                line = reader.read_until(end, MAX_LINE)
                if not line:
                    raise RdisTimeout(f"{plan.name}: no reply within {wait:g} s")
                if not line.endswith(end):
                    raise RdisProtocolError(f"{plan.name}: reply line not terminated: {line.decode('latin-1')!r}")
                text = line[: -len(end)]
                if end == b"\n" and text.endswith(b"\r"):  # the default takes CR LF as well as LF
                    text = text[:-1]
                return plan, local, self._met(plan, local, decoder.decode(plan.name, text))
            assert decoder is not None
            data = reader.read(decoder.size)
            if not data:
                raise RdisTimeout(f"{plan.name}: no reply within {wait:g} s")
            return plan, local, self._met(plan, local, decoder.decode(plan.name, data))
        # The decoding's size is the payload's, unless a tag comes first or stuffing may have lengthened
        # it on the wire (then the constant after the payload ends it).
        stuffed = use.frame.stuffing is not None and any(side.delimiter for side in use.frame.replies)
        size = decoder.size if decoder is not None and plan.tag is None and plan.records is None and not stuffed else -1
        while True:  # once, or until a reply decodes when the primitive skips the others
            try:
                payload = use.frame.read(reader, fields, request, size)[1]
                if plan.each:
                    return plan, local, self._sub_payloads(plan, payload, local)
                if plan.records is not None:
                    return plan, local, self._records(plan, payload, local)
                if plan.tag_struct is not None:
                    return self._tagged(plan, payload, local)
                return plan, local, self._met(plan, local, decoder.decode(plan.name, payload)) if decoder else ()
            except (FrameError, RdisProtocolError) as err:
                nothing = isinstance(err, FrameError) and err.timeout
                if plan.skip and not nothing and reader.deadline is not None and time.monotonic() < reader.deadline:
                    continue
                if nothing or plan.skip:
                    raise RdisTimeout(f"{plan.name}: no {'matching reply' if plan.skip else 'reply'} "
                                      f"within {wait:g} s") from None
                if isinstance(err, RdisProtocolError):
                    raise
                raise RdisProtocolError(f"{plan.name}: {err}") from None

    def _read_replies(self, plan: Primitive, link: _Link, reader: Incoming, fields: list[Any], request: bytes,
                      wait: float, local: Args) -> list[Sequence[Any]]:
        """`replies N` and `replies { }`: a reply for each of the plan's answers, read in turn as
        one is (each decoded and meeting its `expect`; through its own frame, with its own field
        values, where it has one), all within the one deadline, in the order they came."""
        got: list[Sequence[Any]] = []
        count = len(plan.answers)
        for n, answer in enumerate(plan.answers):
            use = answer.frame
            if use is not None and use is not plan.frame:
                try:
                    fields = use.frame.values(plan.name, use.args(self._state, local))
                except (struct.error, *EVAL_ERRORS) as err:
                    raise RdisValueError(f"{plan.name}: {err}") from None
            try:
                got.append(self._read_reply(answer, link, reader, fields, request, wait, local)[2])
            except RdisTimeout:
                if not n:
                    raise
                raise RdisTimeout(f"{plan.name}: {n} of {count} replies within {wait:g} s") from None
            except RdisProtocolError as err:
                raise RdisProtocolError(f"{plan.name}: reply {n + 1} of {count}: "
                                        f"{str(err).removeprefix(plan.name + ': ')}") from None
        return got

    def _met(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> Sequence[Any]:
        """The reply, when it meets the primitive's `expect` (else, like a reply that does not
        decode, an RdisProtocolError, which `skip unmatched` reads past)."""
        if plan.expect is None:
            return reply
        try:
            met = plan.expect(self._state, local, reply)
        except EVAL_ERRORS as err:
            raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r}: its `expect` failed: {err}") from None
        if not met:
            raise RdisProtocolError(f"{plan.name}: reply {tuple(reply)!r} does not meet its `expect`")
        return reply

    @staticmethod
    def _tagged(plan: Primitive, payload: bytes, local: Args) -> tuple[Primitive, Args, Sequence[Any]]:
        """The entry a framed reply's tag chooses, the tag after the parameters' values, and
        the rest of the payload decoded by the entry."""
        tag = plan.tag_struct
        assert tag is not None and plan.table is not None
        if len(payload) < tag.size:
            raise RdisProtocolError(f"{plan.name}: expected {tag.size} bytes or more, got {len(payload)}")
        value = tag.unpack_from(payload)[0]
        case = plan.table.get(value)
        if case is None:
            raise RdisProtocolError(f"{plan.name}: no reply entry for tag {value}")
        rest = payload[tag.size :]
        return case, [*local, value], case.decoder.decode(plan.name, rest) if case.decoder is not None else ()

    def _records(self, plan: Primitive, payload: bytes, local: Args) -> list[tuple[Primitive, Args, Sequence[Any]]]:
        """A payload of records, each ended by the marker where it first comes (Firmata's capability
        report: a pin's mode and resolution pairs, then 7F), each decoded by the primitive's decoder
        and meeting its `expect`, its position after the parameters' values (`index`). At most
        MAX_ARRAY of them; a payload whose end is not a marker is refused, as is a record that does
        not decode. All are decoded before any post-action runs, so a bad one changes no state."""
        marker = plan.records
        decoder = plan.decoder
        assert marker is not None and decoder is not None
        parts: list[tuple[Primitive, Args, Sequence[Any]]] = []
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

    @staticmethod
    def _sub_payloads(plan: Primitive, payload: bytes, local: Args) -> list[tuple[Primitive, Args, Sequence[Any]]]:
        """A payload of sub-payloads (Kobuki's feedback), in any order and any subset, until it
        ends: each its tag, its length when the table gives one, and its bytes, decoded by the
        entry the tag chooses (its plan, the tag after the parameters' values, its values). With
        a length, a tag without an entry is skipped (a newer firmware's) and a length that is
        not its entry's size refused; without one, the entry's size says where the next starts.
        All are decoded before any post-action runs, so a bad one changes no state."""
        tag = plan.tag_struct
        size = plan.length_struct
        assert tag is not None and plan.table is not None
        head = tag.size + (size.size if size is not None else 0)
        parts: list[tuple[Primitive, Args, Sequence[Any]]] = []
        at = 0
        while at < len(payload):
            if len(payload) - at < head:
                raise RdisProtocolError(f"{plan.name}: {len(payload) - at} bytes at offset {at} are no "
                                        f"sub-payload (its head is {head})")
            value = tag.unpack_from(payload, at)[0]
            case = plan.table.get(value)
            if case is None and size is None:
                raise RdisProtocolError(f"{plan.name}: no reply entry for tag {value} at offset {at}")
            decoder = case.decoder if case is not None else None
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
            parts.append((case, [*local, value], decoder.decode(plan.name, payload[start:at])))
        return parts

    @staticmethod
    def _read_tagged(plan: Primitive, reader: Incoming, wait: float,
                     local: Args) -> tuple[Primitive, Args, Sequence[Any]]:
        """A tagged reply without a frame (Firmata's stream): the tag, then exactly the bytes its
        entry decodes (a fixed size: checked). Under `skip unmatched` a tag without an entry is
        read past one byte at a time, the next tag looked for from the byte after its first,
        until the reply's deadline."""
        tag = plan.tag_struct
        assert tag is not None and plan.table is not None
        missed = f"{plan.name}: no {'matching reply' if plan.skip else 'reply'} within {wait:g} s"
        while True:
            head = reader.read(tag.size)
            if len(head) < tag.size:  # the deadline passed
                if not head or plan.skip:
                    raise RdisTimeout(missed)
                raise RdisProtocolError(f"{plan.name}: expected {tag.size} bytes, got {len(head)}")
            value = tag.unpack(head)[0]
            case = plan.table.get(value)
            if case is None:
                if not plan.skip:
                    raise RdisProtocolError(f"{plan.name}: no reply entry for tag {value}")
                if reader.deadline is not None and time.monotonic() >= reader.deadline:
                    raise RdisTimeout(missed)
                reader.put_back(head[1:])
                continue
            decoder = case.decoder
            assert isinstance(decoder, Unpack)
            if decoder.until is not None:  # to its end marker, which is not the reply's
                body = reader.read_until(decoder.until)
                if not body.endswith(decoder.until):
                    if plan.skip:
                        raise RdisTimeout(missed)
                    raise RdisProtocolError(f"{plan.name}: no end {decoder.until.hex(' ')} after tag {value} "
                                            f"within {wait:g} s")
                return case, [*local, value], decoder.decode(plan.name, body[: -len(decoder.until)])
            body = reader.read(decoder.size)
            if len(body) < decoder.size:
                if plan.skip:
                    raise RdisTimeout(missed)
                raise RdisProtocolError(f"{plan.name}: expected {decoder.size} bytes after tag {value}, "
                                        f"got {len(body)}")
            return case, [*local, value], decoder.decode(plan.name, body)

    def _port_error(self, plan: Primitive, err: BaseException) -> RdisError:
        """The typed error for what a port raised: a write that timed out, or a failed port."""
        if _write_timed_out(err):
            return RdisTimeout(f"{plan.name}: write not completed within {self.timeout:g} s")
        return RdisConnectionError(f"{plan.connection}: {err}")

    def _assign(self, plan: Primitive, local: Args, reply: Sequence[Any]) -> None:
        """The post-actions: all values computed from one snapshot, then published together."""
        self._assign_each([(plan, local, reply)])

    def _assign_each(self, parts: Sequence[tuple[Primitive, Args, Sequence[Any]]]) -> None:
        """The post-actions of each part in turn (sub-payloads, records), each part's computed from
        the state the one before left; all published together, or none when one fails."""
        with self._state_lock:
            state = self._state
            for plan, local, reply in parts:
                assert plan.actions is not None
                try:
                    changes = plan.actions(state, local, reply)
                except EVAL_ERRORS as err:
                    raise RdisValueError(f"{plan.name}: {err}") from None
                for name in plan.checked:
                    value = changes[name]
                    if type(value) is int and not -MAX_INT <= value <= MAX_INT:
                        raise RdisValueError(f"{plan.name}: {name} would be a {value.bit_length()}-bit integer; "
                                             "integers are limited to 64 bits and a sign")
                state = {**state, **changes}
            self._state = state

    # ---- delivering to callbacks: one at a time, a failing one reported -----------------------------

    def _deliver(self, plan: Output) -> None:
        try:
            contents = plan.fields(self._state)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        message: dict[str, Any] = {"name": plan.name, "contents": contents}
        with self._callback_lock:
            for callback in list(self._output_callbacks):
                try:
                    callback(message)
                except Exception as err:  # noqa: BLE001 - a user's callback must not stop delivery
                    error = RdisCallbackError(f"{plan.name}: output callback raised {type(err).__name__}: {err}")
                    error.__cause__ = err
                    self._report(error)

    def _notify_io(self, direction: str, connection: str, data: bytes) -> None:
        """Show the I/O callbacks one event: "write" or "read" and the bytes, or "lines" and
        the modem lines set (`_lines_text`)."""
        with self._callback_lock:
            for callback in list(self._io_callbacks):
                try:
                    callback(direction, connection, data)
                except Exception as err:  # noqa: BLE001 - a user's callback must not stop the I/O
                    error = RdisCallbackError(f"{connection}: I/O callback raised {type(err).__name__}: {err}")
                    error.__cause__ = err
                    self._report(error)

    def _notify_run(self, connection: str, kind: str, name: str) -> None:
        """Tell a recorder that a connection's thread starts a periodic interface or its keepalive."""
        with self._callback_lock:
            for callback in list(self._run_callbacks):
                callback(connection, kind, name)

    def _report(self, error: BaseException) -> None:
        with self._callback_lock:
            callbacks = list(self._error_callbacks)
            if not callbacks:
                _log.warning("%s: %s: %s", self.name, type(error).__name__, error)
            for callback in callbacks:
                try:
                    callback(error)
                except Exception:  # noqa: BLE001, S110 - the contract: an error callback's failure is ignored
                    pass


def _lines_text(levels: Mapping[str, Value]) -> bytes:
    """The modem lines a primitive set, as the I/O callbacks see them: b"dtr=False rts=True"."""
    return " ".join(f"{line}={bool(level)}" for line, level in levels.items()).encode("ascii")
