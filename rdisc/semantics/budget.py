"""The link budget: can each connection carry what the description schedules on it?

From the baud rate (10 bits a byte at 8N1, 12 at 8E2: the connection's serial line), each primitive's bytes on the wire
(request and reply), the periodic interfaces run every tick, the keepalive run
every interval and the declared delays, warn when the scheduled traffic exceeds
the link (W401) or a schedule's period is shorter than its exchange (W402). Under `threading
multiple` each periodic interface is its own thread: its work is held to its own period.
ASCII messages are counted at their shortest, so a warning is never a false alarm.
"""

from __future__ import annotations

from collections.abc import Iterator

from rdisc import TYPE_CHECKING
from rdisc.diagnostics import Diagnostics
from rdisc.semantics import formats
from rdisc.semantics import model as m
from rdisc.semantics.frame_facts import length_part, length_range

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.semantics.budget_methods import dataclass

from rdisc.frozen import Frozen

_SAMPLE: dict[m.AnyType, m.Value] = {m.Type.INT: 0, m.Type.FLOAT: 0.0, m.Type.BOOL: False, m.Type.STRING: ""}


@dataclass(frozen=True, slots=True)
class Exchange(metaclass=Frozen):
    """What running one interface costs on the wire."""

    interface: str
    bytes: int  # on this connection
    wire_ms: float
    delay_ms: float

    @property
    def total_ms(self) -> float:
        return self.wire_ms + self.delay_ms


@dataclass(frozen=True, slots=True)
class SensorLoad(metaclass=Frozen):
    """A sensor read on this connection: its exchange's bytes and time on the wire, and how
    often it is read (at most once per cache time: rdisc.semantics.sensed)."""

    sensor: str
    bytes: int
    wire_ms: float
    rate_hz: float


@dataclass(frozen=True, slots=True)
class ConnectionBudget(metaclass=Frozen):
    connection: str
    baud: int
    frequency_hz: float
    periodic: tuple[Exchange, ...]
    keepalive: Exchange | None
    keepalive_interval_ms: float | None
    baud_setting: str | None = None  # the setting giving the baud rate: `baud` is its default
    bits_per_byte: float = 10  # on the wire, a start bit and the serial line's character
    threading: str = "single"  # single and dual: one thread runs every periodic exchange each tick
    rates: tuple[float, ...] = ()  # each periodic exchange's runs a second (`Connection.rate_of`)

    def rate(self, index: int) -> float:
        """Runs a second of the periodic exchange `index`."""
        return self.rates[index] if index < len(self.rates) else self.frequency_hz
    sensed: tuple[SensorLoad, ...] = ()

    @property
    def baud_text(self) -> str:
        """`57600 baud`, or `57600 baud (the default of setting BAUD)`."""
        return f"{self.baud} baud" + ("" if self.baud_setting is None else f" (the default of setting `{self.baud_setting}`)")

    @property
    def capacity(self) -> float:
        """Bytes per second the link carries."""
        return self.baud / self.bits_per_byte

    @property
    def tick_ms(self) -> float:
        return 1000.0 / self.frequency_hz

    @property
    def tick_ms_needed(self) -> float:
        """The longest tick: its periodic work, and each sensor read in it."""
        return sum(e.total_ms for e in self.periodic) + sum(s.wire_ms for s in self.sensed)

    @property
    def load(self) -> float:
        """Bytes per second scheduled on the link."""
        per_tick = sum(e.bytes * self.rate(i) for i, e in enumerate(self.periodic))
        if self.keepalive and self.keepalive_interval_ms:
            per_tick += self.keepalive.bytes * 1000.0 / self.keepalive_interval_ms
        return per_tick + sum(s.bytes * s.rate_hz for s in self.sensed)

    def lines(self) -> list[str]:
        """The budget in words, for `rdisc check --verbose`."""
        out = [f"connection `{self.connection}`: {self.baud_text}, {self.capacity:g} bytes/s"]
        if self.periodic and self.threading == "multiple":
            for i, e in enumerate(self.periodic):  # a thread each, held to its own period
                hz = self.rate(i)
                out.append(f"  thread `{e.interface}` ({hz:g} Hz, {1000.0 / hz:.1f} ms):")
                out.append(f"    {_exchange(e)}")
                out.append(f"    {e.total_ms:.2f} ms of {1000.0 / hz:.1f} ms per run")
        elif self.periodic:
            dual = " on the periodic thread (a command waits for one exchange at most)" if self.threading == "dual" else ""
            out.append(f"  every tick ({self.frequency_hz:g} Hz, {self.tick_ms:.1f} ms){dual}:")
            out += [f"    {_exchange(e)}" for e in self.periodic]
            out.append(f"    {self.tick_ms_needed:.2f} ms of {self.tick_ms:.1f} ms per tick")
        if self.keepalive and self.keepalive_interval_ms:
            out.append(f"  keepalive every {self.keepalive_interval_ms:g} ms:")
            out.append(f"    {_exchange(self.keepalive)}")
        for s in self.sensed:
            out.append(f"  sensor {s.sensor}: {s.bytes} bytes, {s.wire_ms:.2f} ms on the wire, read at {s.rate_hz:g} Hz")
        share = 100.0 * self.load / self.capacity if self.capacity else 0.0
        out.append(f"  scheduled: {self.load:.1f} bytes/s, {share:.1f}% of the link")
        return out


def _exchange(e: Exchange) -> str:
    return (f"{e.interface}: {e.bytes} bytes, {e.wire_ms:.2f} ms on the wire + {e.delay_ms:g} ms of delays"
            f" = {e.total_ms:.2f} ms")


def budget(model: m.Model, diagnostics: Diagnostics) -> list[ConnectionBudget]:
    """Each connection's budget; warnings for the schedules that cannot hold."""
    budgets = []
    for conn in model.connections.values():
        periodic = tuple(
            exchange(model, iface, conn.name)
            for iface in model.interfaces.values()
            if iface.periodic and model.owner(iface) == conn.name
        )
        keepalive = exchange(model, model.interfaces[conn.keepalive.call.interface], conn.name) if conn.keepalive else None
        rates = tuple(conn.rate_of(iface) for iface in model.interfaces.values()
                      if iface.periodic and model.owner(iface) == conn.name)
        b = ConnectionBudget(conn.name, conn.baud, conn.frequency_hz, periodic, keepalive,
                             conn.keepalive.interval_ms if conn.keepalive else None, conn.baud_setting,
                             conn.bits_per_byte(), conn.threading, rates, tuple(_sensed(model, conn)))
        _warn(model, conn, b, diagnostics)
        budgets.append(b)
    return budgets


def _sensed(model: m.Model, conn: m.Connection) -> Iterator[SensorLoad]:
    """The sensors read on this connection, each at the rate it is read."""
    if not model.sensors:  # their rates' rules imported only then
        return
    from rdisc.semantics.sensed import read_rates

    for sensor, rate in read_rates(model):
        prim = model.primitives[sensor.primitive]
        if prim.connection == conn.name:
            size = message_bytes(prim, model.frames)
            yield SensorLoad(sensor.name, size, size * conn.bits_per_byte() * 1000.0 / conn.baud, rate)


def _warn(model: m.Model, conn: m.Connection, b: ConnectionBudget, diagnostics: Diagnostics) -> None:
    for i, e in enumerate(b.periodic if b.threading == "multiple" else ()):  # each thread its own period
        hz = b.rate(i)
        if e.total_ms > 1000.0 / hz:
            diagnostics.report(
                "W402", model.interfaces[e.interface].span,
                f"the periodic work of `{e.interface}` (its own thread on `{conn.name}`) takes {e.total_ms:.2f} ms "
                f"per run, longer than its {1000.0 / hz:.1f} ms period ({hz:g} Hz)",
                help="lower its rate, shorten the delays, or read less per run",
            )
    if b.threading != "multiple" and b.periodic and b.tick_ms_needed > b.tick_ms:
        first = model.interfaces[b.periodic[0].interface]
        diagnostics.report(
            "W402", first.span,
            f"the periodic work of `{conn.name}` takes {b.tick_ms_needed:.2f} ms per tick, longer than its "
            f"{b.tick_ms:.1f} ms period ({conn.frequency_hz:g} Hz)",
            help="lower the frequency, shorten the delays, or read less per tick",
        )
    if b.keepalive and b.keepalive_interval_ms and b.keepalive.total_ms > b.keepalive_interval_ms:
        diagnostics.report(
            "W402", conn.keepalive.call.span if conn.keepalive else conn.span,
            f"the keepalive `{b.keepalive.interface}` takes {b.keepalive.total_ms:.2f} ms, longer than its "
            f"{b.keepalive_interval_ms:g} ms interval",
        )
    if b.load > b.capacity:
        diagnostics.report(
            "W401", conn.span,
            f"`{conn.name}` schedules {b.load:.0f} bytes/s, more than {b.baud_text} carries "
            f"({b.capacity:g} bytes/s)",
            help="raise the baud rate, lower the frequency, or lengthen the keepalive interval",
        )


def exchange(model: m.Model, iface: m.Interface, connection: str) -> Exchange:
    """Bytes on `connection`, time on the wire and delays of one run of an interface, through
    the interfaces it calls (a call's delay counts after it, made or not). Each interface is
    costed once and its cost reused: loops call the same interface thousands of times."""
    return Exchange(iface.name, *_cost(model, connection, {}, iface))


def _cost(model: m.Model, connection: str, costs: dict[str, tuple[int, float, float]],
          called: m.Interface) -> tuple[int, float, float]:
    """`exchange`'s bytes, wire time and delays of one run of `called`, each interface's kept in
    `costs`. (A function of its own, not one nested in `exchange` that calls itself: that is a
    cycle, which waits for the collector.)"""
    if called.name not in costs:
        count, wire, delays = 0, 0.0, 0.0
        for call in called.calls:
            if call.interface:
                inner = _cost(model, connection, costs, model.interfaces[call.primitive])
            else:
                prim = model.primitives[call.primitive]
                size = message_bytes(prim, model.frames)
                line = model.connections[prim.connection]
                held = sum(level.value.value for level in prim.lines  # a break: time, no byte (ms)
                           if level.line == m.BREAK and isinstance(level.value, m.Const)
                           and isinstance(level.value.value, float))
                inner = (size if prim.connection == connection else 0, size * line.bits_per_byte() * 1000.0 / line.baud, held)
            count, wire, delays = count + inner[0], wire + inner[1], delays + inner[2] + call.delay_ms
        costs[called.name] = (count, wire, delays)
    return costs[called.name]


def message_bytes(prim: m.Primitive, frames: dict[str, m.Frame] | None = None, escaped: bool = True) -> int:
    """Bytes of the request and the reply, frames included (ASCII, and data of any
    length, counted at their shortest; a group repeated as the message says at its most
    rounds: an array's size, its count field's largest value or MAX_ARRAY, no more than the
    frame's length field states), the reply as many times as `replies` says, or each listed
    reply once (`replies { }`). Through a frame that escapes, at their worst (`escaped`):
    every byte between the flags escaped, so two."""
    frame = (frames or {}).get(prim.frame.frame) if prim.frame is not None else None
    match prim.encoding:
        case m.Pack(layout=layout, grouped=grouped):
            rest = prim.args[-1] if prim.args else None  # constant bytes for a `*` rest have their size
            extra = len(rest.value) if isinstance(rest, m.Const) and isinstance(rest.value, bytes) else 0
            rounds = formats.most_rounds(layout, [prim.args[i].type for i in formats.varying_args(layout, grouped)])
            request = layout.most(rounds) + extra
        case m.Format(template=template):
            values = [a.value if isinstance(a, m.Const) else _SAMPLE[a.type] for a in prim.args]
            request = len(template.format(*values).encode("utf-8"))
        case None:  # only modem lines set: no byte on the wire
            request = 0
    framing = 0  # the request's framing
    sent = request
    if frame is not None:  # the request's layout: the one its size picks
        written = (_written(frame.requests, request) if not frame.request_when  # else the longest a setting may pick
                   else max(frame.requests, key=frame_bytes))
        framing = frame_bytes(written)
        sent = _worst(frame, written, request + framing) if escaped else request + framing
    if prim.listed:  # each listed reply once, through its own frame or the primitive's
        return sent + sum(_reply_bytes(prim.listed_reply(r), frames, request, framing, escaped) for r in prim.listed)
    return sent + _reply_bytes(prim, frames, request, framing, escaped) * max(prim.replies, 1)


def _worst(frame: m.Frame, layout: tuple[m.FramePart, ...], size: int) -> int:
    """`size` bytes of a layout as sent at their worst: every byte between the flags escaped."""
    if frame.escaping is None or not layout:
        return size
    flags = sum(len(p.data) for p in (layout[0], layout[-1])
                if isinstance(p, m.FrameBytes) and p.role in ("header", "terminator"))
    return flags + 2 * (size - flags)


def _reply_bytes(prim: m.Primitive, frames: dict[str, m.Frame] | None, request: int, framing: int,
                 escaped: bool = True) -> int:
    """Bytes of one reply, its frame's shortest reply layout (without optional parts; the longest
    when a setting chooses it, `either when`) included;
    `request` and `framing`, the request's, which a table's entries are counted without."""
    use = prim.reply_frames[0] if prim.reply_frames else prim.frame  # replies through their own frames: all of one
    frame = (frames or {}).get(use.frame) if use is not None else None
    answer = 0
    if frame is not None and prim.expects_reply(frames or {}):
        counted = max if frame.reply_when else min  # the longest a setting may choose, else the shortest to come
        answer = counted((frame_bytes(parts, shortest=True) for parts in frame.replies), default=0)
    match prim.decoding:
        case m.Unpack(layout=layout, until=until):
            reply = layout.most(formats.most_rounds(layout, [])) + len(until or "")  # and its end marker
            if prim.records is not None:  # one record and its marker: a report's records are counted as one
                reply += len(prim.records)
            if layout.varying is not None and frame is not None:
                stated = [length_range(length)[1] for parts in frame.replies if (length := length_part(parts))]
                reply = min([reply, *stated])
        case m.Regex(pattern=pattern):
            reply = formats.regex_min_length(pattern) + 1  # and its line terminator
        case None if prim.table is not None:  # each entry's reply after its tag (and its length)
            t = prim.table
            head = sum(layout.size for layout in (t.tag_layout, t.length_layout) if layout is not None)
            sizes = [message_bytes(prim.case(c), frames, False) - request - framing - answer + head
                     + (0 if c.under_layout is None else c.under_layout.size) for c in t.cases]
            reply = sum(sizes) if t.each else max(sizes, default=0)  # sub-payloads: each entry's once
        case None:
            reply = 0
    return _worst(frame, frame.reply, reply + answer) if frame is not None and answer and escaped else reply + answer


def _written(layouts: tuple[tuple[m.FramePart, ...], ...], size: int) -> tuple[m.FramePart, ...]:
    """The layout a request of `size` bytes is written with: the first whose length field can state it."""
    for parts in layouts:
        length = length_part(parts)
        if length is None or size <= length_range(length)[1]:
            return parts
    return layouts[-1]


def frame_bytes(parts: tuple[m.FramePart, ...], shortest: bool = False) -> int:
    """Bytes of a frame layout's parts other than the payload; `shortest`: without its optional parts."""
    size = 0
    skip = 0
    for part in parts:
        if skip:
            skip -= 1
            continue
        match part:
            case m.FrameOptional(count=count) if shortest:
                skip = count
            case m.FrameBytes(data=data):
                size += len(data)
            case m.FrameField(layout=layout) | m.FrameLength(layout=layout) | m.FrameBits(layout=layout):
                size += layout.size
            case m.FrameChecksum(algorithm=a, layout=layout):
                size += layout.size if layout is not None else (a.width + 3) // 4
    return size
