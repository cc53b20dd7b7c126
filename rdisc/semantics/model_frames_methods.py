"""The methods of the frozen dataclasses of rdisc/semantics/model_frames.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import DEFAULT, MISSING, FieldSpec, Written, classes, field

if TYPE_CHECKING:
    from typing import Any

__all__ = ["dataclass", "field"]

# Each field's setter, `_set_<class>_<field>(instance, value)`: its slot's own `__set__`, bound by
# rdisc.frozen when it makes the class (a third faster than object.__setattr__ with the field's name).
_unbound: Any = None


_set_ChecksumAlgorithm_kind = _unbound
_set_ChecksumAlgorithm_width = _unbound
_set_ChecksumAlgorithm_poly = _unbound
_set_ChecksumAlgorithm_init = _unbound
_set_ChecksumAlgorithm_reflect_in = _unbound
_set_ChecksumAlgorithm_reflect_out = _unbound
_set_ChecksumAlgorithm_xorout = _unbound
_set_ChecksumAlgorithm_inverted = _unbound
_set_ChecksumAlgorithm_mask = _unbound
_set_ChecksumAlgorithm_name = _unbound


def _init_ChecksumAlgorithm(
    self: Any,
    kind: Any,
    width: Any,
    poly: Any = DEFAULT,
    init: Any = DEFAULT,
    reflect_in: Any = DEFAULT,
    reflect_out: Any = DEFAULT,
    xorout: Any = DEFAULT,
    inverted: Any = DEFAULT,
    mask: Any = DEFAULT,
    name: Any = DEFAULT,
) -> None:
    _set_ChecksumAlgorithm_kind(self, kind)
    _set_ChecksumAlgorithm_width(self, width)
    _set_ChecksumAlgorithm_poly(self, poly)
    _set_ChecksumAlgorithm_init(self, init)
    _set_ChecksumAlgorithm_reflect_in(self, reflect_in)
    _set_ChecksumAlgorithm_reflect_out(self, reflect_out)
    _set_ChecksumAlgorithm_xorout(self, xorout)
    _set_ChecksumAlgorithm_inverted(self, inverted)
    _set_ChecksumAlgorithm_mask(self, mask)
    _set_ChecksumAlgorithm_name(self, name)


def _repr_ChecksumAlgorithm(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, width={self.width!r}, poly={self.poly!r}, init={self.init!r}, reflect_in={self.reflect_in!r}, reflect_out={self.reflect_out!r}, xorout={self.xorout!r}, inverted={self.inverted!r}, mask={self.mask!r}, name={self.name!r})"


def _eq_ChecksumAlgorithm(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.kind,
            self.width,
            self.poly,
            self.init,
            self.reflect_in,
            self.reflect_out,
            self.xorout,
            self.inverted,
            self.mask,
            self.name,
        ) == (
            other.kind,
            other.width,
            other.poly,
            other.init,
            other.reflect_in,
            other.reflect_out,
            other.xorout,
            other.inverted,
            other.mask,
            other.name,
        )
    return NotImplemented


def _hash_ChecksumAlgorithm(self: Any) -> int:
    return hash((
        self.kind,
        self.width,
        self.poly,
        self.init,
        self.reflect_in,
        self.reflect_out,
        self.xorout,
        self.inverted,
        self.mask,
        self.name,
    ))


_set_FrameBytes_role = _set_FrameBytes_data = _unbound


def _init_FrameBytes(self: Any, role: Any, data: Any) -> None:
    _set_FrameBytes_role(self, role)
    _set_FrameBytes_data(self, data)


def _repr_FrameBytes(self: Any) -> str:
    return f"{self.__class__.__qualname__}(role={self.role!r}, data={self.data!r})"


def _eq_FrameBytes(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.role, self.data) == (other.role, other.data)
    return NotImplemented


def _hash_FrameBytes(self: Any) -> int:
    return hash((self.role, self.data))


_set_FrameField_name = _set_FrameField_format = _set_FrameField_value = _set_FrameField_layout = _unbound


def _init_FrameField(self: Any, name: Any, format: Any, value: Any, layout: Any) -> None:
    _set_FrameField_name(self, name)
    _set_FrameField_format(self, format)
    _set_FrameField_value(self, value)
    _set_FrameField_layout(self, layout)


def _repr_FrameField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, format={self.format!r}, value={self.value!r})"


def _eq_FrameField(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.name, self.format, self.value) == (other.name, other.format, other.value)
    return NotImplemented


def _hash_FrameField(self: Any) -> int:
    return hash((self.name, self.format, self.value))


_set_FrameLength_format = _set_FrameLength_adjust = _set_FrameLength_layout = _unbound


def _init_FrameLength(self: Any, format: Any, adjust: Any, layout: Any) -> None:
    _set_FrameLength_format(self, format)
    _set_FrameLength_adjust(self, adjust)
    _set_FrameLength_layout(self, layout)


def _repr_FrameLength(self: Any) -> str:
    return f"{self.__class__.__qualname__}(format={self.format!r}, adjust={self.adjust!r})"


def _eq_FrameLength(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.format, self.adjust) == (other.format, other.adjust)
    return NotImplemented


def _hash_FrameLength(self: Any) -> int:
    return hash((self.format, self.adjust))


_set_FramePayload_trimmed = _unbound


def _init_FramePayload(self: Any, trimmed: Any = DEFAULT) -> None:
    _set_FramePayload_trimmed(self, trimmed)


def _repr_FramePayload(self: Any) -> str:
    return f"{self.__class__.__qualname__}(trimmed={self.trimmed!r})"


def _eq_FramePayload(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.trimmed,) == (other.trimmed,)
    return NotImplemented


def _hash_FramePayload(self: Any) -> int:
    return hash((self.trimmed,))


_set_FrameSeed_table = _set_FrameSeed_field = _set_FrameSeed_part = _set_FrameSeed_entries = _unbound


def _init_FrameSeed(self: Any, table: Any, field: Any, part: Any, entries: Any) -> None:
    _set_FrameSeed_table(self, table)
    _set_FrameSeed_field(self, field)
    _set_FrameSeed_part(self, part)
    _set_FrameSeed_entries(self, entries)


def _repr_FrameSeed(self: Any) -> str:
    return f"{self.__class__.__qualname__}(table={self.table!r}, field={self.field!r}, part={self.part!r}, entries={self.entries!r})"


def _eq_FrameSeed(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.table,
            self.field,
            self.part,
            self.entries,
        ) == (
            other.table,
            other.field,
            other.part,
            other.entries,
        )
    return NotImplemented


def _hash_FrameSeed(self: Any) -> int:
    return hash((self.table, self.field, self.part, self.entries))


_set_FrameChecksum_algorithm = _unbound
_set_FrameChecksum_format = _unbound
_set_FrameChecksum_first = _unbound
_set_FrameChecksum_last = _unbound
_set_FrameChecksum_with_request = _unbound
_set_FrameChecksum_layout = _unbound
_set_FrameChecksum_seed = _unbound


def _init_FrameChecksum(
    self: Any,
    algorithm: Any,
    format: Any,
    first: Any,
    last: Any,
    with_request: Any = DEFAULT,
    layout: Any = DEFAULT,
    seed: Any = DEFAULT,
) -> None:
    _set_FrameChecksum_algorithm(self, algorithm)
    _set_FrameChecksum_format(self, format)
    _set_FrameChecksum_first(self, first)
    _set_FrameChecksum_last(self, last)
    _set_FrameChecksum_with_request(self, with_request)
    _set_FrameChecksum_layout(self, layout)
    _set_FrameChecksum_seed(self, seed)


def _repr_FrameChecksum(self: Any) -> str:
    return f"{self.__class__.__qualname__}(algorithm={self.algorithm!r}, format={self.format!r}, first={self.first!r}, last={self.last!r}, with_request={self.with_request!r}, seed={self.seed!r})"


def _eq_FrameChecksum(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.algorithm,
            self.format,
            self.first,
            self.last,
            self.with_request,
            self.seed,
        ) == (
            other.algorithm,
            other.format,
            other.first,
            other.last,
            other.with_request,
            other.seed,
        )
    return NotImplemented


def _hash_FrameChecksum(self: Any) -> int:
    return hash((self.algorithm, self.format, self.first, self.last, self.with_request, self.seed))


_set_FrameOptional_count = _unbound


def _init_FrameOptional(self: Any, count: Any) -> None:
    _set_FrameOptional_count(self, count)


def _repr_FrameOptional(self: Any) -> str:
    return f"{self.__class__.__qualname__}(count={self.count!r})"


def _eq_FrameOptional(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.count,) == (other.count,)
    return NotImplemented


def _hash_FrameOptional(self: Any) -> int:
    return hash((self.count,))


_set_BitField_name = _set_BitField_width = _set_BitField_value = _set_BitField_adjust = _unbound


def _init_BitField(self: Any, name: Any, width: Any, value: Any = DEFAULT, adjust: Any = DEFAULT) -> None:
    _set_BitField_name(self, name)
    _set_BitField_width(self, width)
    _set_BitField_value(self, value)
    _set_BitField_adjust(self, adjust)


def _repr_BitField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, width={self.width!r}, value={self.value!r}, adjust={self.adjust!r})"


def _eq_BitField(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.width,
            self.value,
            self.adjust,
        ) == (
            other.name,
            other.width,
            other.value,
            other.adjust,
        )
    return NotImplemented


def _hash_BitField(self: Any) -> int:
    return hash((self.name, self.width, self.value, self.adjust))


_set_FrameBits_format = _set_FrameBits_fields = _set_FrameBits_layout = _unbound


def _init_FrameBits(self: Any, format: Any, fields: Any, layout: Any) -> None:
    _set_FrameBits_format(self, format)
    _set_FrameBits_fields(self, fields)
    _set_FrameBits_layout(self, layout)


def _repr_FrameBits(self: Any) -> str:
    return f"{self.__class__.__qualname__}(format={self.format!r}, fields={self.fields!r})"


def _eq_FrameBits(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.format, self.fields) == (other.format, other.fields)
    return NotImplemented


def _hash_FrameBits(self: Any) -> int:
    return hash((self.format, self.fields))


_set_Escaping_escape = _set_Escaping_table = _unbound


def _init_Escaping(self: Any, escape: Any, table: Any) -> None:
    _set_Escaping_escape(self, escape)
    _set_Escaping_table(self, table)


def _repr_Escaping(self: Any) -> str:
    return f"{self.__class__.__qualname__}(escape={self.escape!r}, table={self.table!r})"


def _eq_Escaping(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.escape, self.table) == (other.escape, other.table)
    return NotImplemented


def _hash_Escaping(self: Any) -> int:
    return hash((self.escape, self.table))


_set_Frame_name = _unbound
_set_Frame_params = _unbound
_set_Frame_request = _unbound
_set_Frame_reply = _unbound
_set_Frame_doc = _unbound
_set_Frame_span = _unbound
_set_Frame_stuffing = _unbound
_set_Frame_more_requests = _unbound
_set_Frame_more_replies = _unbound
_set_Frame_escaping = _unbound
_set_Frame_request_when = _unbound
_set_Frame_reply_when = _unbound


def _init_Frame(
    self: Any,
    name: Any,
    params: Any,
    request: Any,
    reply: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    stuffing: Any = DEFAULT,
    more_requests: Any = DEFAULT,
    more_replies: Any = DEFAULT,
    escaping: Any = DEFAULT,
    request_when: Any = DEFAULT,
    reply_when: Any = DEFAULT,
) -> None:
    _set_Frame_name(self, name)
    _set_Frame_params(self, params)
    _set_Frame_request(self, request)
    _set_Frame_reply(self, reply)
    _set_Frame_doc(self, doc)
    _set_Frame_span(self, span)
    _set_Frame_stuffing(self, stuffing)
    _set_Frame_more_requests(self, more_requests)
    _set_Frame_more_replies(self, more_replies)
    _set_Frame_escaping(self, escaping)
    _set_Frame_request_when(self, request_when)
    _set_Frame_reply_when(self, reply_when)


def _repr_Frame(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, request={self.request!r}, reply={self.reply!r}, doc={self.doc!r}, stuffing={self.stuffing!r}, more_requests={self.more_requests!r}, more_replies={self.more_replies!r}, escaping={self.escaping!r}, request_when={self.request_when!r}, reply_when={self.reply_when!r})"


def _eq_Frame(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.request,
            self.reply,
            self.doc,
            self.stuffing,
            self.more_requests,
            self.more_replies,
            self.escaping,
            self.request_when,
            self.reply_when,
        ) == (
            other.name,
            other.params,
            other.request,
            other.reply,
            other.doc,
            other.stuffing,
            other.more_requests,
            other.more_replies,
            other.escaping,
            other.request_when,
            other.reply_when,
        )
    return NotImplemented


def _hash_Frame(self: Any) -> int:
    return hash((
        self.name,
        self.params,
        self.request,
        self.reply,
        self.doc,
        self.stuffing,
        self.more_requests,
        self.more_replies,
        self.escaping,
        self.request_when,
        self.reply_when,
    ))


_set_FrameUse_frame = _set_FrameUse_args = _unbound


def _init_FrameUse(self: Any, frame: Any, args: Any) -> None:
    _set_FrameUse_frame(self, frame)
    _set_FrameUse_args(self, args)


def _repr_FrameUse(self: Any) -> str:
    return f"{self.__class__.__qualname__}(frame={self.frame!r}, args={self.args!r})"


def _eq_FrameUse(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.frame, self.args) == (other.frame, other.args)
    return NotImplemented


def _hash_FrameUse(self: Any) -> int:
    return hash((self.frame, self.args))


_set_ReplyCase_value = _unbound
_set_ReplyCase_decoding = _unbound
_set_ReplyCase_actions = _unbound
_set_ReplyCase_last = _unbound
_set_ReplyCase_under = _unbound
_set_ReplyCase_under_tag = _unbound
_set_ReplyCase_under_layout = _unbound


def _init_ReplyCase(
    self: Any,
    value: Any,
    decoding: Any,
    actions: Any = DEFAULT,
    last: Any = DEFAULT,
    under: Any = DEFAULT,
    under_tag: Any = DEFAULT,
    under_layout: Any = DEFAULT,
) -> None:
    _set_ReplyCase_value(self, value)
    _set_ReplyCase_decoding(self, decoding)
    _set_ReplyCase_actions(self, actions)
    _set_ReplyCase_last(self, last)
    _set_ReplyCase_under(self, under)
    _set_ReplyCase_under_tag(self, under_tag)
    _set_ReplyCase_under_layout(self, under_layout)


def _repr_ReplyCase(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r}, decoding={self.decoding!r}, actions={self.actions!r}, last={self.last!r}, under={self.under!r}, under_tag={self.under_tag!r})"


def _eq_ReplyCase(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.value,
            self.decoding,
            self.actions,
            self.last,
            self.under,
            self.under_tag,
        ) == (
            other.value,
            other.decoding,
            other.actions,
            other.last,
            other.under,
            other.under_tag,
        )
    return NotImplemented


def _hash_ReplyCase(self: Any) -> int:
    return hash((self.value, self.decoding, self.actions, self.last, self.under, self.under_tag))


_set_ListedReply_decoding = _unbound
_set_ListedReply_frame = _unbound
_set_ListedReply_expect = _unbound
_set_ListedReply_actions = _unbound


def _init_ListedReply(
    self: Any,
    decoding: Any,
    frame: Any = DEFAULT,
    expect: Any = DEFAULT,
    actions: Any = DEFAULT,
) -> None:
    _set_ListedReply_decoding(self, decoding)
    _set_ListedReply_frame(self, frame)
    _set_ListedReply_expect(self, expect)
    _set_ListedReply_actions(self, actions)


def _repr_ListedReply(self: Any) -> str:
    return f"{self.__class__.__qualname__}(decoding={self.decoding!r}, frame={self.frame!r}, expect={self.expect!r}, actions={self.actions!r})"


def _eq_ListedReply(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.decoding,
            self.frame,
            self.expect,
            self.actions,
        ) == (
            other.decoding,
            other.frame,
            other.expect,
            other.actions,
        )
    return NotImplemented


def _hash_ListedReply(self: Any) -> int:
    return hash((self.decoding, self.frame, self.expect, self.actions))


_set_RepliesEach_var = _set_RepliesEach_over = _unbound


def _init_RepliesEach(self: Any, var: Any, over: Any) -> None:
    _set_RepliesEach_var(self, var)
    _set_RepliesEach_over(self, over)


def _repr_RepliesEach(self: Any) -> str:
    return f"{self.__class__.__qualname__}(var={self.var!r}, over={self.over!r})"


def _eq_RepliesEach(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.var, self.over) == (other.var, other.over)
    return NotImplemented


def _hash_RepliesEach(self: Any) -> int:
    return hash((self.var, self.over))


_set_ErrorReply_decoding = _unbound
_set_ErrorReply_frame = _unbound
_set_ErrorReply_marker = _unbound
_set_ErrorReply_codes = _unbound
_set_ErrorReply_when = _unbound


def _init_ErrorReply(
    self: Any,
    decoding: Any,
    frame: Any = DEFAULT,
    marker: Any = DEFAULT,
    codes: Any = DEFAULT,
    when: Any = DEFAULT,
) -> None:
    _set_ErrorReply_decoding(self, decoding)
    _set_ErrorReply_frame(self, frame)
    _set_ErrorReply_marker(self, marker)
    _set_ErrorReply_codes(self, codes)
    _set_ErrorReply_when(self, when)


def _repr_ErrorReply(self: Any) -> str:
    return f"{self.__class__.__qualname__}(decoding={self.decoding!r}, frame={self.frame!r}, marker={self.marker!r}, codes={self.codes!r}, when={self.when!r})"


def _eq_ErrorReply(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.decoding,
            self.frame,
            self.marker,
            self.codes,
            self.when,
        ) == (
            other.decoding,
            other.frame,
            other.marker,
            other.codes,
            other.when,
        )
    return NotImplemented


def _hash_ErrorReply(self: Any) -> int:
    return hash((self.decoding, self.frame, self.marker, self.codes, self.when))


_set_ReplyTable_key = _unbound
_set_ReplyTable_cases = _unbound
_set_ReplyTable_tag = _unbound
_set_ReplyTable_each = _unbound
_set_ReplyTable_length = _unbound
_set_ReplyTable_tag_layout = _unbound
_set_ReplyTable_length_layout = _unbound


def _init_ReplyTable(
    self: Any,
    key: Any,
    cases: Any,
    tag: Any = DEFAULT,
    each: Any = DEFAULT,
    length: Any = DEFAULT,
    tag_layout: Any = DEFAULT,
    length_layout: Any = DEFAULT,
) -> None:
    _set_ReplyTable_key(self, key)
    _set_ReplyTable_cases(self, cases)
    _set_ReplyTable_tag(self, tag)
    _set_ReplyTable_each(self, each)
    _set_ReplyTable_length(self, length)
    _set_ReplyTable_tag_layout(self, tag_layout)
    _set_ReplyTable_length_layout(self, length_layout)


def _repr_ReplyTable(self: Any) -> str:
    return f"{self.__class__.__qualname__}(key={self.key!r}, cases={self.cases!r}, tag={self.tag!r}, each={self.each!r}, length={self.length!r})"


def _eq_ReplyTable(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.key,
            self.cases,
            self.tag,
            self.each,
            self.length,
        ) == (
            other.key,
            other.cases,
            other.tag,
            other.each,
            other.length,
        )
    return NotImplemented


def _hash_ReplyTable(self: Any) -> int:
    return hash((self.key, self.cases, self.tag, self.each, self.length))


WRITTEN: dict[str, Written] = {
    "ChecksumAlgorithm": Written(
        (
            ("kind", MISSING),
            ("width", MISSING),
            ("poly", DEFAULT),
            ("init", DEFAULT),
            ("reflect_in", DEFAULT),
            ("reflect_out", DEFAULT),
            ("xorout", DEFAULT),
            ("inverted", DEFAULT),
            ("mask", DEFAULT),
            ("name", DEFAULT),
        ),
        {
            "__init__": _init_ChecksumAlgorithm,
            "__repr__": _repr_ChecksumAlgorithm,
            "__eq__": _eq_ChecksumAlgorithm,
            "__hash__": _hash_ChecksumAlgorithm,
        },
    ),
    "FrameBytes": Written(
        (("role", MISSING), ("data", MISSING)),
        {
            "__init__": _init_FrameBytes,
            "__repr__": _repr_FrameBytes,
            "__eq__": _eq_FrameBytes,
            "__hash__": _hash_FrameBytes,
        },
    ),
    "FrameField": Written(
        (
            ("name", MISSING),
            ("format", MISSING),
            ("value", MISSING),
            ("layout", FieldSpec(MISSING, MISSING, False, False)),
        ),
        {
            "__init__": _init_FrameField,
            "__repr__": _repr_FrameField,
            "__eq__": _eq_FrameField,
            "__hash__": _hash_FrameField,
        },
    ),
    "FrameLength": Written(
        (("format", MISSING), ("adjust", MISSING), ("layout", FieldSpec(MISSING, MISSING, False, False))),
        {
            "__init__": _init_FrameLength,
            "__repr__": _repr_FrameLength,
            "__eq__": _eq_FrameLength,
            "__hash__": _hash_FrameLength,
        },
    ),
    "FramePayload": Written(
        (("trimmed", DEFAULT),),
        {
            "__init__": _init_FramePayload,
            "__repr__": _repr_FramePayload,
            "__eq__": _eq_FramePayload,
            "__hash__": _hash_FramePayload,
        },
    ),
    "FrameSeed": Written(
        (("table", MISSING), ("field", MISSING), ("part", MISSING), ("entries", MISSING)),
        {
            "__init__": _init_FrameSeed,
            "__repr__": _repr_FrameSeed,
            "__eq__": _eq_FrameSeed,
            "__hash__": _hash_FrameSeed,
        },
    ),
    "FrameChecksum": Written(
        (
            ("algorithm", MISSING),
            ("format", MISSING),
            ("first", MISSING),
            ("last", MISSING),
            ("with_request", DEFAULT),
            ("layout", FieldSpec(None, MISSING, False, False)),
            ("seed", DEFAULT),
        ),
        {
            "__init__": _init_FrameChecksum,
            "__repr__": _repr_FrameChecksum,
            "__eq__": _eq_FrameChecksum,
            "__hash__": _hash_FrameChecksum,
        },
    ),
    "FrameOptional": Written(
        (("count", MISSING),),
        {
            "__init__": _init_FrameOptional,
            "__repr__": _repr_FrameOptional,
            "__eq__": _eq_FrameOptional,
            "__hash__": _hash_FrameOptional,
        },
    ),
    "BitField": Written(
        (("name", MISSING), ("width", MISSING), ("value", DEFAULT), ("adjust", DEFAULT)),
        {
            "__init__": _init_BitField,
            "__repr__": _repr_BitField,
            "__eq__": _eq_BitField,
            "__hash__": _hash_BitField,
        },
    ),
    "FrameBits": Written(
        (("format", MISSING), ("fields", MISSING), ("layout", FieldSpec(MISSING, MISSING, False, False))),
        {
            "__init__": _init_FrameBits,
            "__repr__": _repr_FrameBits,
            "__eq__": _eq_FrameBits,
            "__hash__": _hash_FrameBits,
        },
    ),
    "Escaping": Written(
        (("escape", MISSING), ("table", MISSING)),
        {
            "__init__": _init_Escaping,
            "__repr__": _repr_Escaping,
            "__eq__": _eq_Escaping,
            "__hash__": _hash_Escaping,
        },
    ),
    "Frame": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("request", MISSING),
            ("reply", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("stuffing", DEFAULT),
            ("more_requests", DEFAULT),
            ("more_replies", DEFAULT),
            ("escaping", DEFAULT),
            ("request_when", DEFAULT),
            ("reply_when", DEFAULT),
        ),
        {"__init__": _init_Frame, "__repr__": _repr_Frame, "__eq__": _eq_Frame, "__hash__": _hash_Frame},
    ),
    "FrameUse": Written(
        (("frame", MISSING), ("args", MISSING)),
        {
            "__init__": _init_FrameUse,
            "__repr__": _repr_FrameUse,
            "__eq__": _eq_FrameUse,
            "__hash__": _hash_FrameUse,
        },
    ),
    "ReplyCase": Written(
        (
            ("value", MISSING),
            ("decoding", MISSING),
            ("actions", DEFAULT),
            ("last", DEFAULT),
            ("under", DEFAULT),
            ("under_tag", DEFAULT),
            ("under_layout", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_ReplyCase,
            "__repr__": _repr_ReplyCase,
            "__eq__": _eq_ReplyCase,
            "__hash__": _hash_ReplyCase,
        },
    ),
    "ListedReply": Written(
        (("decoding", MISSING), ("frame", DEFAULT), ("expect", DEFAULT), ("actions", DEFAULT)),
        {
            "__init__": _init_ListedReply,
            "__repr__": _repr_ListedReply,
            "__eq__": _eq_ListedReply,
            "__hash__": _hash_ListedReply,
        },
    ),
    "RepliesEach": Written(
        (("var", MISSING), ("over", MISSING)),
        {
            "__init__": _init_RepliesEach,
            "__repr__": _repr_RepliesEach,
            "__eq__": _eq_RepliesEach,
            "__hash__": _hash_RepliesEach,
        },
    ),
    "ErrorReply": Written(
        (
            ("decoding", MISSING),
            ("frame", DEFAULT),
            ("marker", DEFAULT),
            ("codes", DEFAULT),
            ("when", DEFAULT),
        ),
        {
            "__init__": _init_ErrorReply,
            "__repr__": _repr_ErrorReply,
            "__eq__": _eq_ErrorReply,
            "__hash__": _hash_ErrorReply,
        },
    ),
    "ReplyTable": Written(
        (
            ("key", MISSING),
            ("cases", MISSING),
            ("tag", DEFAULT),
            ("each", DEFAULT),
            ("length", DEFAULT),
            ("tag_layout", FieldSpec(None, MISSING, False, False)),
            ("length_layout", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_ReplyTable,
            "__repr__": _repr_ReplyTable,
            "__eq__": _eq_ReplyTable,
            "__hash__": _hash_ReplyTable,
        },
    ),
}
dataclass = classes(WRITTEN)
