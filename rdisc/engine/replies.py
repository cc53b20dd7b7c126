"""The exchange's reading: replies read, decoded and checked, their post-actions run."""

from __future__ import annotations

import struct
import time
from collections.abc import Callable, Mapping, Sequence
from typing import Any, assert_never

from rdisc.engine.codec import Match, Unpack
from rdisc.engine.errors import (
    RdisConnectionError,
    RdisDeviceError,
    RdisError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)
from rdisc.engine.operations import EVAL_ERRORS, MAX_ARRAY, MAX_INT, MAX_LINE, LookupMiss
from rdisc.engine.plans import (
    ErrorReply,
    FixedReply,
    FramedReply,
    FrameUse,
    KeyedReply,
    LineReply,
    ListedReplies,
    NoReply,
    Primitive,
    Records,
    Reply,
    SeveralReplies,
    SubPayloads,
    TaggedReply,
    TaggedStream,
)
from rdisc.engine.ports import Simulator, _Link, _write_timed_out
from rdisc.engine.telling import Telling
from rdisc.engine.values import (
    Args,
    Value,
)
from rdisc.engine.wire import ChecksumError, FrameError, Incoming

_ReplyPart = tuple[Primitive, Args, Sequence[Any]]
"""A reply read, or a part of one: the plan whose post-actions take it, what they read besides it
(the parameters' values, and a tag or a record's position after them), and its values."""


class Replies(Telling):
    """The part of an Exchange that reads replies and runs their post-actions."""

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
