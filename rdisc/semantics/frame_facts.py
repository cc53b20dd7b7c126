"""What later passes read of a checked frame: where its payload ends, its length part and the
range it gives, and the messages a checksum's seed table has no entry for (W501)."""

from __future__ import annotations

from rdisc.diagnostics import Diagnostics
from rdisc.semantics import model as m
from rdisc.syntax import ast


def unseeded(frames: dict[str, m.Frame], primitives: dict[str, m.Primitive],
             decls: dict[str, ast.PrimitiveDecl], d: Diagnostics) -> None:
    """W501: a message a primitive frames (its frame arguments constants, so its `seed` field's
    value known) that the checksum's seed table has no entry for: its request cannot be framed,
    or its reply cannot be checked."""
    if not any(isinstance(part, m.FrameChecksum) and part.seed is not None for frame in frames.values()
               for parts in (*frame.requests, *frame.replies) for part in parts):
        return
    from rdisc.semantics.evaluate import prepare  # the runtime's own interpreter: the value is the one framed

    for name, p in primitives.items():
        decl = decls.get(name)
        if decl is None:
            continue
        at = next((c.span for c in decl.clauses if isinstance(c, ast.Framed)), decl.name.span)
        uses: list[tuple[m.FrameUse, tuple[str, ...]]] = [(p.frame, ("request", "reply"))] if p.frame else []
        uses += [(use, ("reply",)) for use in (*p.reply_frames, *(r.frame for r in p.listed if r.frame),
                                              *((p.error.frame,) if p.error is not None and p.error.frame else ()))]
        told: set[tuple[str, int]] = set()
        for use, sides in uses:
            frame = frames.get(use.frame)
            if frame is None:
                continue
            args = [a.value if isinstance(a, m.Const) else None for a in use.args]
            slots = {param.name: i for i, param in enumerate(frame.params)}
            for side in sides:
                for parts in frame.requests if side == "request" else frame.replies if frame.reply else ():
                    for part in parts:
                        seed = part.seed if isinstance(part, m.FrameChecksum) else None
                        field = parts[seed.part] if seed is not None else None
                        if seed is None or not isinstance(field, m.FrameField):
                            continue
                        try:
                            value = prepare(field.value, slots)({}, args, ())
                        except Exception:  # noqa: BLE001, S112 - a value known only at run time: not checked here
                            continue
                        if type(value) is not int or value in dict(seed.entries) or (seed.table, value) in told:
                            continue
                        told.add((seed.table, value))
                        what = ("its request cannot be framed (an RdisValueError)" if side == "request"
                                else "no reply of it can be checked")
                        d.report("W501", at, f"`{name}` frames {field.name} {value} with `{frame.name}`, but its "
                                 f"seed table `{seed.table}` has no entry for {value}: {what}",
                                 help=f"add the message's byte to the table: `{value}: ...` in `{seed.table}`")


def payload_end_known(frame: m.Frame, size_known: bool) -> bool:
    """Whether a reader can find where the reply's payload ends, in each layout."""
    if frame.escaping is not None:  # read up to its terminator (E510 otherwise)
        return True
    size_known = size_known and frame.stuffing is None  # stuffing makes a payload longer on the wire
    return all(_end_known(reply, size_known) for reply in frame.replies)


def _end_known(reply: tuple[m.FramePart, ...], size_known: bool) -> bool:
    at = next((i for i, p in enumerate(reply) if isinstance(p, m.FramePayload)), None)
    if at is None or size_known or length_part(reply) is not None:
        return True
    after = at + 1
    optional = reply[after] if after < len(reply) else None
    if isinstance(optional, m.FrameOptional):  # the constant after it ends both
        after += 1 + optional.count
    return after < len(reply) and isinstance(reply[after], m.FrameBytes)




def length_part(parts: tuple[m.FramePart, ...]) -> m.FrameLength | m.FrameBits | None:
    """The part of a layout holding its length: a `length`, or a `bits` with a length field in it."""
    return next((p for p in parts if isinstance(p, m.FrameLength)
                 or (isinstance(p, m.FrameBits) and p.length is not None)), None)


def length_words(part: m.FrameLength | m.FrameBits) -> str:
    """How a message names a length field: `"B"`, or `"<I" bits 0..29` in a `bits`."""
    if isinstance(part, m.FrameLength):
        return f'"{part.format}"'
    low = 0
    for bit in part.fields:
        if bit.value is None:
            return f'"{part.format}" bits {low}..{low + bit.width - 1}'
        low += bit.width
    raise AssertionError(part)


def length_range(part: m.FrameLength | m.FrameBits) -> tuple[int, int]:
    """The payload sizes a length field can state (none, when its format was refused)."""
    if isinstance(part, m.FrameBits):
        length = part.length
        assert length is not None
        return max(0, -length.adjust), (1 << length.width) - 1 - length.adjust
    if not part.layout.slots:  # refused: reported where the frame is checked
        return 0, -1
    slot = part.layout.slots[0]
    return max(0, (slot.low or 0) - part.adjust), (slot.high or 0) - part.adjust

