"""`rdisc decode`: captured traffic told as a description's requests and replies, as `cantools
decode` tells CAN frames. Each message written is held against every primitive's request table
(`rdisc dump`'s, its constants and text checked), each message read against the reply tables of
the request before it first, then every primitive's; the first that fits names it, its fields
shown as `rdisc dump --args` shows them. Bytes that fit none are shown as unknown."""

from __future__ import annotations

import struct
from collections.abc import Sequence
from typing import Any

from rdisc import engine
from rdisc.capture import Message
from rdisc.emit.dump import Layout, Written, held_table, matched, reply_layouts, request_layouts
from rdisc.engine.wire import Field, FrameError, Incoming
from rdisc.semantics import model as m


def decode(model: m.Model, device: engine.Device, messages: Sequence[Message]) -> str:
    """Each message and what it is (`device`: the model's plans, whose frames check a message
    whole: its length, fields and checksum)."""
    teller = Teller(model, device)
    lines: list[str] = []
    for message in _as_lines(model, device, messages):
        on = f"{message.connection} " if message.connection is not None else ""
        lines.append(f"{on}{'>' if message.write else '<'} {message.data.hex(' ').upper()}".rstrip())
        found = teller.tell(message)
        if not found:
            side = "request" if message.write else "reply"
            lines.append(f"  unknown: no primitive's {side} is these {len(message.data)} bytes")
            continue
        said, rows, regex, data = found[0]
        others = list(dict.fromkeys(other.rsplit(" ", 1)[-1] for other, _, _, _ in found[1:]))
        also = f" (also fits: {', '.join(others)})" if others else ""
        lines.append(f"  {said}{also}")
        if data != message.data:  # unescaped, unstuffed or zero-filled: the table holds what the engine reads
            lines.append(f"  read as {len(data)} bytes ({_changed(teller, said, message.data, data)}): "
                         f"{data.hex(' ').upper()}")
        lines += held_table(rows, data)
        if said.startswith("error of "):
            lines += _code_named(model, model.primitives[said.removeprefix("error of ").split(",")[0]], rows, data)
        if regex is not None:  # its groups, as the engine's decoder reads the payload's text
            try:
                lines.append(f"  out = {list(engine.Match(regex).decode(said, _text_of(rows, data)))!r}")
            except engine.RdisError:
                pass
    return "\n".join(lines) + "\n" if lines else ""


def _as_lines(model: m.Model, device: engine.Device, messages: Sequence[Message]) -> list[Message]:
    """The messages, each read on a connection of lines cut into the lines the engine's reader
    takes from it, one reply a line (`CR`, then `V1013 CR`: an empty line, then a reply); a
    capture joins what came in a row (a spy log's rows, a recording's exchange)."""
    ends = _line_ends(model, device)
    out: list[Message] = []
    for message in messages:
        end = ends.get(message.connection) if message.connection is not None or len(model.connections) != 1 \
            else ends.get(next(iter(model.connections)))
        if message.write or end is None:
            out.append(message)
            continue
        port = Incoming(_Bytes(message.data))  # the engine's reader, over the message
        while line := port.read_until(end):
            out.append(Message(False, line, message.connection))
    return out


def _line_ends(model: m.Model, device: engine.Device) -> dict[str | None, bytes]:
    """Each connection every reply on which is a line (up to the connection's terminator, or a
    frame's delimiter with nothing before its payload), and that line's end."""
    ends: dict[str, set[bytes]] = {}
    for plan in device.primitives.values():
        reply, use = plan.reply, plan.frame
        end = b""
        if isinstance(reply, engine.NoReply):
            continue
        if isinstance(reply, engine.LineReply):
            end = model.connections[plan.connection].terminator_bytes()
        elif use is not None and isinstance(reply, (engine.FramedReply, engine.TaggedReply)) \
                and len(use.frame.replies) == 1 and use.frame.escaping is None and use.frame.stuffing is None:
            side = use.frame.reply
            end = side.delimiter if side.payload >= 0 and not side.prefix and not side.header else b""
        ends.setdefault(plan.connection, set()).add(end)
    return {name: found.pop() for name, found in ends.items() if len(found) == 1 and b"" not in found}


_Told = tuple[str, list[tuple[int, str, str]], str | None, bytes]
"""What a message was told to be (`request drive`, `reply of status`), its rows, a reply's regex,
and its bytes as the engine's reader takes them (unescaped, unstuffed, zero-filled), which the
rows hold."""


class Teller:
    """Tells messages one at a time, in the order they crossed the wire: a reply is held against
    the reply tables of the request before it on its connection first (`decode`; the console
    names the primitive of each line of its byte trace with it)."""

    def __init__(self, model: m.Model, device: engine.Device) -> None:
        self.model, self.device = model, device
        self.checks = {name: _checks(model, device, name) for name in model.primitives}
        self.requests = {name: request_layouts(model, p, as_read=True) for name, p in model.primitives.items()}
        self.replies = {name: reply_layouts(model, p, as_read=True) for name, p in model.primitives.items()}
        self.errors = {name: _error_checks(device, name) for name in model.primitives}
        self.answered = {name for name, plan in device.primitives.items()  # settings chose the reply's layout
                         if plan.frame is not None and plan.frame.frame.answer is not None and len(self.checks[name][1]) > 1}
        self.sizes = {name: _sizes(device.primitives[name]) for name in model.primitives}
        self.written: dict[str | None, bytes] = {}  # the last request on each connection (a checksum may cover it)
        self.carried: dict[str | None, _Fields] = {}  # its frame's fields, which its reply must carry too
        self.asked: dict[str | None, str] = {}  # the primitive of the last request on each connection

    def held(self, name: str, n: int, said: str, frames: _Check) -> _Check:
        """The frames that hold the `n`-th reply table of `name`: when settings chose the reply's
        layout (`either when`), the one of its layout (the tables come a layout each, in order)."""
        if name not in self.answered or said == "error":
            return frames
        return (frames[n % len(frames)],)

    def primitive(self, message: Message) -> str | None:
        """The primitive whose request or reply the message is, if one's is."""
        found = self.tell(message)
        return found[0][0].split(",")[0].rsplit(" ", 1)[-1] if found else None

    def tell(self, message: Message) -> list[_Told]:
        """What the message may be, the likeliest first (none: unknown)."""
        model, checks, replies = self.model, self.checks, self.replies
        names = [name for name, p in model.primitives.items()
                 if message.connection is None or p.connection == message.connection]
        found: list[_Told] = []
        if message.write:
            self.written[message.connection] = message.data
            fixes: dict[str, int] = {}  # how much of its text each fitting request's format fixes
            for name in names:
                data = _as_read(checks[name][0], message.data, b"", self.sizes[name][0])
                first = _first(self.requests[name], data)
                if first is not None and _whole(checks[name][0], message.data, b""):
                    fixes[name] = first[1].literal if isinstance(first[1], Written) else 0
                    found.append((f"request {name}", first[0], None, data))
            # the most specific first: a format fixing more text ("V" before "{}", which any text fits),
            # those fixing less not listed; then one whose frame's fields are constants (broadcast: *_all)
            most = max(fixes.values(), default=0)
            found = [one for one in found if fixes[one[0].removeprefix("request ")] == most]
            found.sort(key=lambda one: not _fixed(checks[one[0].removeprefix("request ")][0]))
            if found:
                name = found[0][0].removeprefix("request ")
                self.asked[message.connection] = name
                self.carried[message.connection] = _fields_of(checks[name][0], found[0][3])
            else:
                self.asked.pop(message.connection, None)
            return found
        before = self.asked.get(message.connection)
        ordered = ([before] if before in names else []) + [name for name in names if name != before]
        request = self.written.get(message.connection, b"")
        # the request's frame fields, which its reply carries when it comes in the same frame
        carried = self.carried.get(message.connection) if before and not model.primitives[before].reply_frames else None
        for name in ordered:
            for n, (said, (table, pattern)) in enumerate(replies[name]):
                frames = checks[name][1] if said != "error" or self.errors[name] is None else self.errors[name] or ()
                own = frames is checks[name][1]
                frames = self.held(name, n, said, frames)
                data = _as_read(frames, message.data, request, self.sizes[name][1])
                rows = matched((table, pattern), data)
                if rows is not None and _whole(frames, message.data, request,
                                               carried if name == before and own else None) \
                        and self._as_said(name, said, message.data, request):
                    found.append((f"{said} of {name}", rows, pattern if isinstance(pattern, str) else None, data))
        if found and found[0][0].endswith(f" of {before}"):  # the request's own reply: no other is meant
            return found[:1]
        if before in names:  # its shape, but not its request's fields (another servo's status)
            assert before is not None
            for n, (said, (table, pattern)) in enumerate(replies[before]):
                frames = self.held(before, n, said, checks[before][1])
                data = _as_read(frames, message.data, request, self.sizes[before][1])
                rows = matched((table, pattern), data)
                if rows is not None and _whole(frames, message.data, request) \
                        and self._as_said(before, said, message.data, request):
                    wrong = _misread(frames, message.data, request, carried)
                    return [(f"{said} of {before}, but {wrong}", rows, None, data)]
        return found

    def _as_said(self, name: str, said: str, sent: bytes, request: bytes) -> bool:
        """Whether a reply of `name` that fits the table `said` is what it says: under `error when
        COND`, the reply is its `error` when the condition holds over its values as the engine
        decodes them (the call's arguments unknown: a condition over them is not held), else its
        `reply`; any other table, as it fits."""
        plan = self.device.primitives[name]
        reply = plan.reply
        if said not in ("reply", "error") or not isinstance(reply, (engine.FixedReply, engine.FramedReply)) \
                or reply.error is None or reply.error.when is None:
            return True
        when, refused = reply.error.when, False
        if isinstance(reply.decoder, engine.Unpack):
            payload = sent
            any_fields: Any = _Fields()
            for frame, _ in self.checks[name][1]:  # the payload, as the frame reads it
                try:
                    payload = frame.read(_Bytes(sent), any_fields, request, self.sizes[name][1])[1]
                    break
                except (FrameError, engine.RdisError, struct.error, ValueError, IndexError, TypeError):
                    continue
            try:
                values = reply.decoder.decode(name, payload)
                refused = bool(when(self.device.state, [None] * len(plan.params), values))
            except (engine.RdisError, struct.error, *engine.EVAL_ERRORS):
                pass
        return refused == (said == "error")


def _sizes(plan: engine.Primitive) -> tuple[int, int]:
    """The sizes of a request's and a reply's payload as packed and decoded (-1: not fixed): what a
    trimmed payload is zero-filled to."""
    encoder = plan.encoder
    request = (encoder.struct.size if isinstance(encoder, engine.Pack) and not encoder.rest
               and encoder.varying is None and not encoder.groups else -1)
    reply = plan.reply.each if isinstance(plan.reply, engine.SeveralReplies) else plan.reply
    decoder = reply.decoder if isinstance(reply, engine.FramedReply) else None
    return request, decoder.size if decoder is not None else -1


def _as_read(frames: _Check, data: bytes, request: bytes, size: int) -> bytes:
    """`data` as the engine's reader takes it when its frame escapes, stuffs or trims (`Frame.read`:
    unescaped, unstuffed, its payload zero-filled to `size`), for the frame's table to hold it;
    else, or when no frame reads it whole, `data` itself."""
    for frame, fields in frames:
        side = frame.reply
        if (frame.escaping is None and frame.stuffing is None and not frame.fill) or side.group or side.payload < 0:
            return data
        port = _Bytes(data)
        try:
            raw, payload = frame.read(port, fields, request, size)
        except (FrameError, engine.RdisError, struct.error, ValueError, IndexError, TypeError):
            continue
        if port.at != len(data):
            continue
        if frame.escaping is not None:  # the packet between its flags, as `Frame._read_escaped` unescapes it
            end = len(raw) - len(side.terminator)
            raw = raw[: len(side.header)] + frame.escaping.unescaped(raw[len(side.header) : end], frame.name) + raw[end:]
        before = sum(side.sizes[: side.payload])
        sent = len(raw) - sum(n for i, n in enumerate(side.sizes) if i != side.payload)  # the payload's bytes
        return raw[:before] + payload + raw[before + sent :]
    return data


def _changed(teller: Teller, said: str, sent: bytes, data: bytes) -> str:
    """What the engine's reader did to a message: "unescaped", "unstuffed", "zero-filled"."""
    name = said.split(",")[0].rsplit(" ", 1)[-1]
    frames = teller.checks[name][0 if said.startswith("request ") else 1] or teller.errors[name] or ()
    frame = frames[0][0] if frames else None
    done = [word for word, applies in (("unescaped", frame is not None and frame.escaping is not None),
                                       ("unstuffed", frame is not None and frame.stuffing is not None),
                                       ("payload zero-filled", frame is not None and frame.fill))
            if applies]
    return ", ".join(done) or "as the engine reads it"


def _code_named(model: m.Model, p: m.Primitive, rows: list[tuple[int, str, str]], data: bytes) -> list[str]:
    """An error reply's code and the member of its enum of that value: `  error 2: ILLEGAL_DATA_ADDRESS`."""
    if p.error is None or p.error.codes is None:
        return []
    offset = 0
    for size, _, detail in rows:
        if detail.startswith("code, named by"):
            layout = p.error.decoding.layout
            code = struct.unpack_from(layout.order + layout.slots[0].code, data, offset)[0]
            names = {value: member for member, value in model.enums[p.error.codes].items()}
            return [f"  error {code}: {names.get(code, f'not a member of {p.error.codes}')}"]
        offset += size
    return []


def _text_of(rows: list[tuple[int, str, str]], data: bytes) -> bytes:
    """The bytes of a message's text (its payload's, without a frame's header and terminator)."""
    offset = 0
    for size, what, _ in rows:
        if what in ("text", "payload text"):
            return data[offset : offset + size]
        offset += size
    return data


def _first(layouts: list[Layout], data: bytes) -> tuple[list[tuple[int, str, str]], str | Written | None] | None:
    """The rows of the first layout that fits `data`, and that layout's pattern."""
    return next(((rows, layout[1]) for layout in layouts if (rows := matched(layout, data)) is not None), None)


class _Whatever:
    """A frame field's expected value, equal to any: a capture is read without its call's values."""

    __hash__ = None  # type: ignore[assignment]

    def __eq__(self, other: object) -> bool:
        return True

    def __ne__(self, other: object) -> bool:
        return False


class _Fields:
    """A frame's field values by index, those not known equal to any."""

    def __init__(self, known: dict[int, int] | None = None) -> None:
        self.known = known or {}

    def __getitem__(self, index: int) -> int | _Whatever:
        return self.known.get(index, _Whatever())



def _fields_of(frames: _Check, data: bytes) -> _Fields:
    """The field values a request read whole by one of `frames` carries (`dxl`'s ID), by index."""
    for frame, _ in frames:
        side = frame.reply
        payload = len(data) - sum(n for i, n in enumerate(side.sizes) if i != side.payload)
        if side.group or payload < 0:  # optional parts: where each field stands is not one sum
            continue
        known, at = {}, 0
        for i, (part, size) in enumerate(zip(side.parts, side.sizes)):
            size = payload if i == side.payload else size
            if isinstance(part, Field):
                known[part.index] = part.struct.unpack(data[at : at + size])[0]
            at += size
        return _Fields(known)
    return _Fields()


class _Bytes:
    """A message as a port the frame reads it from."""

    timeout: float | None = 0.0

    def __init__(self, data: bytes) -> None:
        self.data, self.at = data, 0

    def read(self, size: int = 1, /) -> bytes:
        chunk = self.data[self.at : self.at + size]
        self.at += len(chunk)
        return chunk

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes:
        end = self.data.find(expected, self.at) if expected else -1
        stop = len(self.data) if end < 0 else end + len(expected)
        return self.read(stop - self.at if size is None else min(size, stop - self.at))


_Check = tuple[tuple[engine.Frame, Any], ...]  # a frame that reads the message, the fields it must carry


def _checks(model: m.Model, device: engine.Device, name: str) -> tuple[_Check, _Check]:
    """The engine's frames that read a request of `name` (one per layout) and its reply, as a
    device and the host read them; none where a message has no frame of its own to check
    (unframed, or a reply through another frame)."""
    use = device.primitives[name].frame
    p = model.primitives[name]
    if use is None or p.frame is None:
        return (), ()
    frame = use.frame
    fields: Any = _Fields()
    if all(isinstance(arg, m.Const) for arg in p.frame.args):  # `dxl(BROADCAST)`: the fields are known
        try:
            fields = frame.values(name, use.args(device.state, [None] * len(p.params)))
        except (engine.RdisError, *engine.EVAL_ERRORS):
            pass
    requests = tuple((engine.Frame(frame.name, side.parts, side.parts, frame.stuffing, escaping=frame.escaping), fields)
                     for side in frame.requests)
    framed = frame.reply.parts and not p.reply_frames and not p.listed
    reply = device.primitives[name].reply
    if isinstance(reply, engine.SeveralReplies) and reply.frames:  # `replies id in ids frame status(id)`: any id
        return requests, ((reply.frames[0].frame, _Fields()),)
    if framed and frame.answer is not None:  # settings chose the reply's layout (`either when`): any may come
        return requests, tuple((engine.Frame(frame.name, side.parts, side.parts, frame.stuffing,
                                             escaping=frame.escaping), fields) for side in frame.replies)
    return requests, ((frame, fields),) if framed else ()


def _error_checks(device: engine.Device, name: str) -> _Check | None:
    """The frame of the error reply that may come instead of `name`'s, if it has one of its own
    (its fields, such as Modbus's function code with 0x80 set, equal to any); None: the reply's."""
    reply = device.primitives[name].reply
    error = reply.error if isinstance(reply, (engine.FixedReply, engine.FramedReply)) else None
    if error is None or error.frame is None:
        return None
    return ((error.frame.frame, _Fields()),)


def _fixed(frames: _Check) -> bool:
    """Whether the frame's fields are constants (`dxl(BROADCAST)`): such a primitive is named before
    one whose fields are its parameters' and that the same bytes fit too."""
    return bool(frames) and not isinstance(frames[0][1], _Fields)


def _whole(frames: _Check, data: bytes, request: bytes, carried: _Fields | None = None) -> bool:
    """Whether one of `frames` reads `data` whole, its constants, fields (those `carried` by its
    request, if given), length and checksum right (no frames: nothing to check)."""
    return _misread(frames, data, request, carried) is None


def _misread(frames: _Check, data: bytes, request: bytes, carried: _Fields | None = None) -> str | None:
    """`_whole`'s answer: None, or what the engine's frame found wrong (the last layout's)."""
    wrong = None
    for frame, own in frames:
        fields: Any = carried if carried is not None and isinstance(own, _Fields) else own
        side = frame.reply
        size = len(data) - sum(n for i, n in enumerate(side.sizes) if i != side.payload)
        port = _Bytes(data)
        try:
            raw, _ = frame.read(port, fields, request, size)
        except (FrameError, engine.RdisError, struct.error, ValueError, IndexError, TypeError) as err:
            wrong = str(err)
            continue
        if raw == data and port.at == len(data):
            return None
        wrong = f"{frame.name}: {len(data) - port.at} bytes after the frame"
    return wrong
