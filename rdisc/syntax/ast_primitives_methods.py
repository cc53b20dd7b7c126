"""The methods of the frozen dataclasses of rdisc/syntax/ast_primitives.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_On_connection = _set_On_span = _unbound


def _init_On(self: Any, connection: Any, span: Any = DEFAULT) -> None:
    _set_On_connection(self, connection)
    _set_On_span(self, span)


def _repr_On(self: Any) -> str:
    return f"{self.__class__.__qualname__}(connection={self.connection!r})"


def _eq_On(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.connection,) == (other.connection,)
    return NotImplemented


def _hash_On(self: Any) -> int:
    return hash((self.connection,))


_set_Encoding_kind = _set_Encoding_template = _set_Encoding_args = _set_Encoding_span = _unbound


def _init_Encoding(self: Any, kind: Any, template: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_Encoding_kind(self, kind)
    _set_Encoding_template(self, template)
    _set_Encoding_args(self, args)
    _set_Encoding_span(self, span)


def _repr_Encoding(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, template={self.template!r}, args={self.args!r})"


def _eq_Encoding(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.kind, self.template, self.args) == (other.kind, other.template, other.args)
    return NotImplemented


def _hash_Encoding(self: Any) -> int:
    return hash((self.kind, self.template, self.args))


_set_Decoding_kind = _set_Decoding_template = _set_Decoding_span = _unbound


def _init_Decoding(self: Any, kind: Any, template: Any, span: Any = DEFAULT) -> None:
    _set_Decoding_kind(self, kind)
    _set_Decoding_template(self, template)
    _set_Decoding_span(self, span)


def _repr_Decoding(self: Any) -> str:
    return f"{self.__class__.__qualname__}(kind={self.kind!r}, template={self.template!r})"


def _eq_Decoding(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.kind, self.template) == (other.kind, other.template)
    return NotImplemented


def _hash_Decoding(self: Any) -> int:
    return hash((self.kind, self.template))


_set_Actions_assigns = _set_Actions_span = _unbound


def _init_Actions(self: Any, assigns: Any, span: Any = DEFAULT) -> None:
    _set_Actions_assigns(self, assigns)
    _set_Actions_span(self, span)


def _repr_Actions(self: Any) -> str:
    return f"{self.__class__.__qualname__}(assigns={self.assigns!r})"


def _eq_Actions(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.assigns,) == (other.assigns,)
    return NotImplemented


def _hash_Actions(self: Any) -> int:
    return hash((self.assigns,))


_set_Framed_frame = _set_Framed_args = _set_Framed_span = _unbound


def _init_Framed(self: Any, frame: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_Framed_frame(self, frame)
    _set_Framed_args(self, args)
    _set_Framed_span(self, span)


def _repr_Framed(self: Any) -> str:
    return f"{self.__class__.__qualname__}(frame={self.frame!r}, args={self.args!r})"


def _eq_Framed(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.frame, self.args) == (other.frame, other.args)
    return NotImplemented


def _hash_Framed(self: Any) -> int:
    return hash((self.frame, self.args))


_set_SkipUnmatched_span = _unbound


def _init_SkipUnmatched(self: Any, span: Any = DEFAULT) -> None:
    _set_SkipUnmatched_span(self, span)


def _repr_SkipUnmatched(self: Any) -> str:
    return f"{self.__class__.__qualname__}()"


def _eq_SkipUnmatched(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return () == ()
    return NotImplemented


def _hash_SkipUnmatched(self: Any) -> int:
    return hash(())


_set_ReplyEntry_value = _unbound
_set_ReplyEntry_decoding = _unbound
_set_ReplyEntry_actions = _unbound
_set_ReplyEntry_span = _unbound
_set_ReplyEntry_last = _unbound
_set_ReplyEntry_until = _unbound
_set_ReplyEntry_table = _unbound


def _init_ReplyEntry(
    self: Any,
    value: Any,
    decoding: Any,
    actions: Any,
    span: Any = DEFAULT,
    last: Any = DEFAULT,
    until: Any = DEFAULT,
    table: Any = DEFAULT,
) -> None:
    _set_ReplyEntry_value(self, value)
    _set_ReplyEntry_decoding(self, decoding)
    _set_ReplyEntry_actions(self, actions)
    _set_ReplyEntry_span(self, span)
    _set_ReplyEntry_last(self, last)
    _set_ReplyEntry_until(self, until)
    _set_ReplyEntry_table(self, table)


def _repr_ReplyEntry(self: Any) -> str:
    return f"{self.__class__.__qualname__}(value={self.value!r}, decoding={self.decoding!r}, actions={self.actions!r}, last={self.last!r}, until={self.until!r}, table={self.table!r})"


def _eq_ReplyEntry(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.value,
            self.decoding,
            self.actions,
            self.last,
            self.until,
            self.table,
        ) == (
            other.value,
            other.decoding,
            other.actions,
            other.last,
            other.until,
            other.table,
        )
    return NotImplemented


def _hash_ReplyEntry(self: Any) -> int:
    return hash((self.value, self.decoding, self.actions, self.last, self.until, self.table))


_set_ReplyTable_key = _unbound
_set_ReplyTable_entries = _unbound
_set_ReplyTable_span = _unbound
_set_ReplyTable_tag = _unbound
_set_ReplyTable_each = _unbound
_set_ReplyTable_length = _unbound


def _init_ReplyTable(
    self: Any,
    key: Any,
    entries: Any,
    span: Any = DEFAULT,
    tag: Any = DEFAULT,
    each: Any = DEFAULT,
    length: Any = DEFAULT,
) -> None:
    _set_ReplyTable_key(self, key)
    _set_ReplyTable_entries(self, entries)
    _set_ReplyTable_span(self, span)
    _set_ReplyTable_tag(self, tag)
    _set_ReplyTable_each(self, each)
    _set_ReplyTable_length(self, length)


def _repr_ReplyTable(self: Any) -> str:
    return f"{self.__class__.__qualname__}(key={self.key!r}, entries={self.entries!r}, tag={self.tag!r}, each={self.each!r}, length={self.length!r})"


def _eq_ReplyTable(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.key,
            self.entries,
            self.tag,
            self.each,
            self.length,
        ) == (
            other.key,
            other.entries,
            other.tag,
            other.each,
            other.length,
        )
    return NotImplemented


def _hash_ReplyTable(self: Any) -> int:
    return hash((self.key, self.entries, self.tag, self.each, self.length))


_set_Retry_count = _set_Retry_span = _unbound


def _init_Retry(self: Any, count: Any, span: Any = DEFAULT) -> None:
    _set_Retry_count(self, count)
    _set_Retry_span(self, span)


def _repr_Retry(self: Any) -> str:
    return f"{self.__class__.__qualname__}(count={self.count!r})"


def _eq_Retry(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.count,) == (other.count,)
    return NotImplemented


def _hash_Retry(self: Any) -> int:
    return hash((self.count,))


_set_ReplyTimeout_duration = _set_ReplyTimeout_span = _unbound


def _init_ReplyTimeout(self: Any, duration: Any, span: Any = DEFAULT) -> None:
    _set_ReplyTimeout_duration(self, duration)
    _set_ReplyTimeout_span(self, span)


def _repr_ReplyTimeout(self: Any) -> str:
    return f"{self.__class__.__qualname__}(duration={self.duration!r})"


def _eq_ReplyTimeout(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.duration,) == (other.duration,)
    return NotImplemented


def _hash_ReplyTimeout(self: Any) -> int:
    return hash((self.duration,))


_set_Replies_over = _set_Replies_span = _set_Replies_var = _set_Replies_high = _set_Replies_frame = _unbound


def _init_Replies(
    self: Any,
    over: Any,
    span: Any = DEFAULT,
    var: Any = DEFAULT,
    high: Any = DEFAULT,
    frame: Any = DEFAULT,
) -> None:
    _set_Replies_over(self, over)
    _set_Replies_span(self, span)
    _set_Replies_var(self, var)
    _set_Replies_high(self, high)
    _set_Replies_frame(self, frame)


def _repr_Replies(self: Any) -> str:
    return f"{self.__class__.__qualname__}(over={self.over!r}, var={self.var!r}, high={self.high!r}, frame={self.frame!r})"


def _eq_Replies(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.over,
            self.var,
            self.high,
            self.frame,
        ) == (
            other.over,
            other.var,
            other.high,
            other.frame,
        )
    return NotImplemented


def _hash_Replies(self: Any) -> int:
    return hash((self.over, self.var, self.high, self.frame))


_set_ListedReply_decoding = _unbound
_set_ListedReply_span = _unbound
_set_ListedReply_frame = _unbound
_set_ListedReply_expect = _unbound
_set_ListedReply_actions = _unbound


def _init_ListedReply(
    self: Any,
    decoding: Any,
    span: Any = DEFAULT,
    frame: Any = DEFAULT,
    expect: Any = DEFAULT,
    actions: Any = DEFAULT,
) -> None:
    _set_ListedReply_decoding(self, decoding)
    _set_ListedReply_span(self, span)
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


_set_ReplyList_replies = _set_ReplyList_span = _unbound


def _init_ReplyList(self: Any, replies: Any, span: Any = DEFAULT) -> None:
    _set_ReplyList_replies(self, replies)
    _set_ReplyList_span(self, span)


def _repr_ReplyList(self: Any) -> str:
    return f"{self.__class__.__qualname__}(replies={self.replies!r})"


def _eq_ReplyList(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.replies,) == (other.replies,)
    return NotImplemented


def _hash_ReplyList(self: Any) -> int:
    return hash((self.replies,))


_set_Expect_condition = _set_Expect_span = _unbound


def _init_Expect(self: Any, condition: Any, span: Any = DEFAULT) -> None:
    _set_Expect_condition(self, condition)
    _set_Expect_span(self, span)


def _repr_Expect(self: Any) -> str:
    return f"{self.__class__.__qualname__}(condition={self.condition!r})"


def _eq_Expect(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.condition,) == (other.condition,)
    return NotImplemented


def _hash_Expect(self: Any) -> int:
    return hash((self.condition,))


_set_Records_marker = _set_Records_span = _unbound


def _init_Records(self: Any, marker: Any, span: Any = DEFAULT) -> None:
    _set_Records_marker(self, marker)
    _set_Records_span(self, span)


def _repr_Records(self: Any) -> str:
    return f"{self.__class__.__qualname__}(marker={self.marker!r})"


def _eq_Records(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.marker,) == (other.marker,)
    return NotImplemented


def _hash_Records(self: Any) -> int:
    return hash((self.marker,))


_set_LineBreak_duration = _set_LineBreak_span = _unbound


def _init_LineBreak(self: Any, duration: Any, span: Any = DEFAULT) -> None:
    _set_LineBreak_duration(self, duration)
    _set_LineBreak_span(self, span)


def _repr_LineBreak(self: Any) -> str:
    return f"{self.__class__.__qualname__}(duration={self.duration!r})"


def _eq_LineBreak(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.duration,) == (other.duration,)
    return NotImplemented


def _hash_LineBreak(self: Any) -> int:
    return hash((self.duration,))


_set_Lines_settings = _set_Lines_span = _unbound


def _init_Lines(self: Any, settings: Any, span: Any = DEFAULT) -> None:
    _set_Lines_settings(self, settings)
    _set_Lines_span(self, span)


def _repr_Lines(self: Any) -> str:
    return f"{self.__class__.__qualname__}(settings={self.settings!r})"


def _eq_Lines(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.settings,) == (other.settings,)
    return NotImplemented


def _hash_Lines(self: Any) -> int:
    return hash((self.settings,))


_set_ErrorReply_decoding = _unbound
_set_ErrorReply_span = _unbound
_set_ErrorReply_frame = _unbound
_set_ErrorReply_marker = _unbound
_set_ErrorReply_codes = _unbound
_set_ErrorReply_when = _unbound


def _init_ErrorReply(
    self: Any,
    decoding: Any,
    span: Any = DEFAULT,
    frame: Any = DEFAULT,
    marker: Any = DEFAULT,
    codes: Any = DEFAULT,
    when: Any = DEFAULT,
) -> None:
    _set_ErrorReply_decoding(self, decoding)
    _set_ErrorReply_span(self, span)
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


_set_PrimitiveDecl_name = _unbound
_set_PrimitiveDecl_params = _unbound
_set_PrimitiveDecl_clauses = _unbound
_set_PrimitiveDecl_span = _unbound
_set_PrimitiveDecl_doc = _unbound


def _init_PrimitiveDecl(
    self: Any,
    name: Any,
    params: Any,
    clauses: Any,
    span: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_PrimitiveDecl_name(self, name)
    _set_PrimitiveDecl_params(self, params)
    _set_PrimitiveDecl_clauses(self, clauses)
    _set_PrimitiveDecl_span(self, span)
    _set_PrimitiveDecl_doc(self, doc)


def _repr_PrimitiveDecl(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, clauses={self.clauses!r}, doc={self.doc!r})"


def _eq_PrimitiveDecl(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.clauses,
            self.doc,
        ) == (
            other.name,
            other.params,
            other.clauses,
            other.doc,
        )
    return NotImplemented


def _hash_PrimitiveDecl(self: Any) -> int:
    return hash((self.name, self.params, self.clauses, self.doc))


WRITTEN: dict[str, Written] = {
    "On": Written(
        (("connection", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_On, "__repr__": _repr_On, "__eq__": _eq_On, "__hash__": _hash_On},
    ),
    "Encoding": Written(
        (
            ("kind", MISSING),
            ("template", MISSING),
            ("args", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_Encoding,
            "__repr__": _repr_Encoding,
            "__eq__": _eq_Encoding,
            "__hash__": _hash_Encoding,
        },
    ),
    "Decoding": Written(
        (("kind", MISSING), ("template", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Decoding,
            "__repr__": _repr_Decoding,
            "__eq__": _eq_Decoding,
            "__hash__": _hash_Decoding,
        },
    ),
    "Actions": Written(
        (("assigns", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Actions,
            "__repr__": _repr_Actions,
            "__eq__": _eq_Actions,
            "__hash__": _hash_Actions,
        },
    ),
    "Framed": Written(
        (("frame", MISSING), ("args", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Framed, "__repr__": _repr_Framed, "__eq__": _eq_Framed, "__hash__": _hash_Framed},
    ),
    "SkipUnmatched": Written(
        (("span", FieldSpec(None, MISSING, False, False)),),
        {
            "__init__": _init_SkipUnmatched,
            "__repr__": _repr_SkipUnmatched,
            "__eq__": _eq_SkipUnmatched,
            "__hash__": _hash_SkipUnmatched,
        },
    ),
    "ReplyEntry": Written(
        (
            ("value", MISSING),
            ("decoding", MISSING),
            ("actions", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("last", DEFAULT),
            ("until", DEFAULT),
            ("table", DEFAULT),
        ),
        {
            "__init__": _init_ReplyEntry,
            "__repr__": _repr_ReplyEntry,
            "__eq__": _eq_ReplyEntry,
            "__hash__": _hash_ReplyEntry,
        },
    ),
    "ReplyTable": Written(
        (
            ("key", MISSING),
            ("entries", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("tag", DEFAULT),
            ("each", DEFAULT),
            ("length", DEFAULT),
        ),
        {
            "__init__": _init_ReplyTable,
            "__repr__": _repr_ReplyTable,
            "__eq__": _eq_ReplyTable,
            "__hash__": _hash_ReplyTable,
        },
    ),
    "Retry": Written(
        (("count", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Retry, "__repr__": _repr_Retry, "__eq__": _eq_Retry, "__hash__": _hash_Retry},
    ),
    "ReplyTimeout": Written(
        (("duration", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_ReplyTimeout,
            "__repr__": _repr_ReplyTimeout,
            "__eq__": _eq_ReplyTimeout,
            "__hash__": _hash_ReplyTimeout,
        },
    ),
    "Replies": Written(
        (
            ("over", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("var", DEFAULT),
            ("high", DEFAULT),
            ("frame", DEFAULT),
        ),
        {
            "__init__": _init_Replies,
            "__repr__": _repr_Replies,
            "__eq__": _eq_Replies,
            "__hash__": _hash_Replies,
        },
    ),
    "ListedReply": Written(
        (
            ("decoding", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("frame", DEFAULT),
            ("expect", DEFAULT),
            ("actions", DEFAULT),
        ),
        {
            "__init__": _init_ListedReply,
            "__repr__": _repr_ListedReply,
            "__eq__": _eq_ListedReply,
            "__hash__": _hash_ListedReply,
        },
    ),
    "ReplyList": Written(
        (("replies", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_ReplyList,
            "__repr__": _repr_ReplyList,
            "__eq__": _eq_ReplyList,
            "__hash__": _hash_ReplyList,
        },
    ),
    "Expect": Written(
        (("condition", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Expect, "__repr__": _repr_Expect, "__eq__": _eq_Expect, "__hash__": _hash_Expect},
    ),
    "Records": Written(
        (("marker", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_Records,
            "__repr__": _repr_Records,
            "__eq__": _eq_Records,
            "__hash__": _hash_Records,
        },
    ),
    "LineBreak": Written(
        (("duration", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_LineBreak,
            "__repr__": _repr_LineBreak,
            "__eq__": _eq_LineBreak,
            "__hash__": _hash_LineBreak,
        },
    ),
    "Lines": Written(
        (("settings", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {"__init__": _init_Lines, "__repr__": _repr_Lines, "__eq__": _eq_Lines, "__hash__": _hash_Lines},
    ),
    "ErrorReply": Written(
        (
            ("decoding", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
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
    "PrimitiveDecl": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("clauses", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("doc", DEFAULT),
        ),
        {
            "__init__": _init_PrimitiveDecl,
            "__repr__": _repr_PrimitiveDecl,
            "__eq__": _eq_PrimitiveDecl,
            "__hash__": _hash_PrimitiveDecl,
        },
    ),
}
dataclass = classes(WRITTEN)
