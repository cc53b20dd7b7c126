"""A primitive's request in one step (`Written`): when it is only written, or asked as a plain
exchange, its values packed by one struct and its frame folded into constant bytes around them;
and whether an interface is one plain write (`written_at_once`)."""

from __future__ import annotations

import dataclasses
import struct
from typing import Any

from rdisc import engine
from rdisc.engine.operations import EVAL_ERRORS
from rdisc.lowering.constructs import Construct
from rdisc.lowering.plans import (
    _NO_STATE,
    Code,
    FixedReply,
    Frame,
    FrameUse,
    Interface,
    NoReply,
    Primitive,
    Written,
)
from rdisc.lowering.whole_frame import whole_frame
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import prepare


def _written(plan: Primitive, params: tuple[m.Parameter, ...], encoding: m.Pack | m.Format | None) -> Written | None:
    """A primitive's request in one step, when it is only written (`engine.sent_at_once`)
    and its frame, if any, folds into constant bytes around a payload of a fixed size (then packed
    by one struct with them, `whole_frame`, where it can be)."""
    encoder = None if plan.encoder is None else plan.encoder.value
    sent = engine.sent_at_once(encoder=encoder, replies=not isinstance(plan.reply, NoReply),
                               acts=plan.actions is not None or plan.lines is not None,
                               dependent=any(prm.limits is not None for prm in params),
                               actuated=bool(plan.actuators))
    if not sent:
        return None
    written = _packed(plan, params)
    assert isinstance(encoder, engine.Pack)  # `sent`
    folded = written if plan.frame is None or written is None else _folded(written, plan.frame, encoder.struct.size)
    if folded is None:
        return None
    return _constant(dataclasses.replace(folded, whole=whole_frame(encoding, folded)), encoder)


def _asked(plan: Primitive, params: tuple[m.Parameter, ...]) -> Written | None:
    """A plain exchange's request in one step (`engine.asked_at_once`), when its values are packed
    as they are, its parameters' ranges not reading each other."""
    encoder = None if plan.encoder is None else plan.encoder.value
    reply = plan.reply
    decoder = reply.decoder.value if isinstance(reply, FixedReply) and reply.error is None else None
    asked = engine.asked_at_once(encoder=encoder, framed=plan.frame is not None, lines=plan.lines is not None,
                                 retries=plan.retries, decoder=decoder, actuated=bool(plan.actuators))
    written = _packed(plan, params) if asked and not any(prm.limits is not None for prm in params) else None
    return None if written is None or encoder is None else _constant(written, encoder)


def _packed(plan: Primitive, params: tuple[m.Parameter, ...]) -> Written | None:
    """A request whose values one struct packs as they are (no groups, varying counts, arrays)."""
    encoder = None if plan.encoder is None else plan.encoder.value
    if not isinstance(encoder, engine.Pack) or encoder.groups or encoder.varying \
            or any(key == "*" for key, _, _ in plan.values.items) or any(isinstance(prm.type, m.Array) for prm in params):
        return None
    return Written(params, plan.values, encoder.struct.format)


def _constant(folded: Written, encoder: engine.Pack | engine.Format) -> Written:
    """`folded` with its whole request, when that is always the same bytes (no parameters, constant values)."""
    assert isinstance(encoder, engine.Pack)
    if folded.params or not all(isinstance(e, m.Const) for _, e, _ in folded.values.items):
        return folded
    try:
        payload = encoder.struct.pack(*(e.value for _, e, _ in folded.values.items if isinstance(e, m.Const)))
    except struct.error:
        return folded  # the general way says what is wrong, each time
    check = b""
    if folded.checksum is not None:
        check = struct.pack(folded.check_format, folded.checksum.value(folded.covered + payload))
    return dataclasses.replace(folded, constant=folded.head + payload + check + folded.tail)


def _folded(written: Written, use: FrameUse, size: int) -> Written | None:
    """`written` with its frame's parts folded around its payload: the frame's arguments
    constants, nothing escaped or stuffed, one layout, no reply read; before the payload
    constant bytes, fields and the length only; after it a checksum of parts up to it, then
    constant bytes."""
    f = use.frame
    if f.stuffing is not None or f.escaping is not None or f.more_requests or _acknowledges(f) \
            or not all(isinstance(e, m.Const) for _, e, _ in use.args.items):
        return None
    args = [e.value for _, e, _ in use.args.items if isinstance(e, m.Const)]
    made = engine.Frame(f.name, [part.value for part in f.request], [], params=tuple(prm.value for prm in f.params),
                        fields=None if f.fields is None else _evaluated(f.fields))
    side = made.requests[0]
    payload_at = side.payload
    if payload_at < 0 or size > side.most or made.trim:  # a trimmed payload's size is not fixed
        return None
    try:
        fields = made.values("", args)
    except (engine.RdisValueError, *EVAL_ERRORS):
        return None
    before, after = side.parts[:payload_at], side.parts[payload_at + 1:]
    if not all(isinstance(part, (engine.Bytes, engine.Field, engine.Length)) for part in before):
        return None
    head_size = sum(side.sizes[:payload_at])
    try:
        framed = made.wrap(bytes(size), fields)
    except (ValueError, struct.error):
        return None
    head = framed[:head_size]
    check = after[0] if after and isinstance(after[0], engine.Check) else None
    if not all(isinstance(part, engine.Bytes) for part in after[1 if check else 0:]):
        return None
    tail = b"".join(part.data for part in after[1 if check else 0:] if isinstance(part, engine.Bytes))
    if check is None:
        return dataclasses.replace(written, head=head, tail=tail)
    if check.last != payload_at or check.struct is None or check.order is not None or check.with_request \
            or check.seed >= 0:
        return None
    construct = f.request[payload_at + 1].args[0]
    covered = head[sum(side.sizes[:check.first]):]
    partial = sum(covered) if check.checksum.kind == "sum" else None
    return dataclasses.replace(written, head=head, checksum=construct, check_format=check.struct.format,
                               check_size=check.struct.size, covered=covered, partial=partial, tail=tail)



def written_at_once(interface: Interface) -> bool:
    """Whether running the interface is one plain write: the engine's rule
    (`engine.written_at_once`), of this plan."""
    call = interface.calls[0] if len(interface.calls) == 1 else None
    prim = call.target if call is not None else None
    if call is None or not isinstance(prim, Primitive):
        return False
    return engine.written_at_once(
        calls=len(interface.calls), outputs=len(interface.outputs), ranged=_ranged(interface.params + prim.params),
        direct=call.direct, waits=bool(call.delay or call.when is not None or call.until is not None),
        encoder=None if prim.encoder is None else prim.encoder.value, replies=not isinstance(prim.reply, NoReply),
        framed=prim.frame is not None, acts=prim.actions is not None or prim.lines is not None)


def _ranged(params: tuple[Construct[engine.Param], ...]) -> bool:
    return any(prm.value.low is not None for prm in params)


def _acknowledges(f: Frame) -> bool:
    """Whether a frame's reply is an acknowledgement: constant parts only, no payload (the
    engine reads it, and there is nothing to decode)."""
    reply = engine.Side([part.value for part in f.reply])
    return bool(reply.parts) and reply.payload < 0


def _evaluated(code: Code) -> Any:
    """A frame's fields' values over its arguments (the runtime's closure of the Code)."""
    slots = {prm.name: i for i, prm in enumerate(code.params)}
    fs = [prepare(e, slots) for _, e, _ in code.items]
    return lambda args: [f(_NO_STATE, args, ()) for f in fs]
