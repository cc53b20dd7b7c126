"""The methods of the frozen dataclasses of rdisc/semantics/model_elements.py, written out ahead of time (why: rdisc/frozen.py).

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


_set_Robot_name = _unbound
_set_Robot_author = _unbound
_set_Robot_description = _unbound
_set_Robot_version = _unbound
_set_Robot_doc = _unbound
_set_Robot_span = _unbound


def _init_Robot(
    self: Any,
    name: Any,
    author: Any = DEFAULT,
    description: Any = DEFAULT,
    version: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_Robot_name(self, name)
    _set_Robot_author(self, author)
    _set_Robot_description(self, description)
    _set_Robot_version(self, version)
    _set_Robot_doc(self, doc)
    _set_Robot_span(self, span)


def _repr_Robot(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, author={self.author!r}, description={self.description!r}, version={self.version!r}, doc={self.doc!r})"


def _eq_Robot(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.author,
            self.description,
            self.version,
            self.doc,
        ) == (
            other.name,
            other.author,
            other.description,
            other.version,
            other.doc,
        )
    return NotImplemented


def _hash_Robot(self: Any) -> int:
    return hash((self.name, self.author, self.description, self.version, self.doc))


_set_StateVariable_name = _unbound
_set_StateVariable_type = _unbound
_set_StateVariable_initial = _unbound
_set_StateVariable_doc = _unbound
_set_StateVariable_span = _unbound
_set_StateVariable_noise = _unbound


def _init_StateVariable(
    self: Any,
    name: Any,
    type: Any,
    initial: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    noise: Any = DEFAULT,
) -> None:
    _set_StateVariable_name(self, name)
    _set_StateVariable_type(self, type)
    _set_StateVariable_initial(self, initial)
    _set_StateVariable_doc(self, doc)
    _set_StateVariable_span(self, span)
    _set_StateVariable_noise(self, noise)


def _repr_StateVariable(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, initial={self.initial!r}, doc={self.doc!r}, noise={self.noise!r})"


def _eq_StateVariable(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.initial,
            self.doc,
            self.noise,
        ) == (
            other.name,
            other.type,
            other.initial,
            other.doc,
            other.noise,
        )
    return NotImplemented


def _hash_StateVariable(self: Any) -> int:
    return hash((self.name, self.type, self.initial, self.doc, self.noise))


_set_Sensor_name = _unbound
_set_Sensor_type = _unbound
_set_Sensor_primitive = _unbound
_set_Sensor_cache_ms = _unbound
_set_Sensor_doc = _unbound
_set_Sensor_span = _unbound
_set_Sensor_noise = _unbound


def _init_Sensor(
    self: Any,
    name: Any,
    type: Any,
    primitive: Any,
    cache_ms: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    noise: Any = DEFAULT,
) -> None:
    _set_Sensor_name(self, name)
    _set_Sensor_type(self, type)
    _set_Sensor_primitive(self, primitive)
    _set_Sensor_cache_ms(self, cache_ms)
    _set_Sensor_doc(self, doc)
    _set_Sensor_span(self, span)
    _set_Sensor_noise(self, noise)


def _repr_Sensor(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, primitive={self.primitive!r}, cache_ms={self.cache_ms!r}, doc={self.doc!r}, noise={self.noise!r})"


def _eq_Sensor(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.primitive,
            self.cache_ms,
            self.doc,
            self.noise,
        ) == (
            other.name,
            other.type,
            other.primitive,
            other.cache_ms,
            other.doc,
            other.noise,
        )
    return NotImplemented


def _hash_Sensor(self: Any) -> int:
    return hash((self.name, self.type, self.primitive, self.cache_ms, self.doc, self.noise))


_set_Setting_name = _unbound
_set_Setting_type = _unbound
_set_Setting_default = _unbound
_set_Setting_low = _unbound
_set_Setting_high = _unbound
_set_Setting_doc = _unbound
_set_Setting_span = _unbound


def _init_Setting(
    self: Any,
    name: Any,
    type: Any,
    default: Any,
    low: Any = DEFAULT,
    high: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_Setting_name(self, name)
    _set_Setting_type(self, type)
    _set_Setting_default(self, default)
    _set_Setting_low(self, low)
    _set_Setting_high(self, high)
    _set_Setting_doc(self, doc)
    _set_Setting_span(self, span)


def _repr_Setting(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, default={self.default!r}, low={self.low!r}, high={self.high!r}, doc={self.doc!r})"


def _eq_Setting(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.default,
            self.low,
            self.high,
            self.doc,
        ) == (
            other.name,
            other.type,
            other.default,
            other.low,
            other.high,
            other.doc,
        )
    return NotImplemented


def _hash_Setting(self: Any) -> int:
    return hash((self.name, self.type, self.default, self.low, self.high, self.doc))


_set_HookCall_interface = _set_HookCall_args = _set_HookCall_span = _unbound


def _init_HookCall(self: Any, interface: Any, args: Any, span: Any = DEFAULT) -> None:
    _set_HookCall_interface(self, interface)
    _set_HookCall_args(self, args)
    _set_HookCall_span(self, span)


def _repr_HookCall(self: Any) -> str:
    return f"{self.__class__.__qualname__}(interface={self.interface!r}, args={self.args!r})"


def _eq_HookCall(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.interface, self.args) == (other.interface, other.args)
    return NotImplemented


def _hash_HookCall(self: Any) -> int:
    return hash((self.interface, self.args))


_set_Keepalive_call = _set_Keepalive_interval_ms = _unbound


def _init_Keepalive(self: Any, call: Any, interval_ms: Any) -> None:
    _set_Keepalive_call(self, call)
    _set_Keepalive_interval_ms(self, interval_ms)


def _repr_Keepalive(self: Any) -> str:
    return f"{self.__class__.__qualname__}(call={self.call!r}, interval_ms={self.interval_ms!r})"


def _eq_Keepalive(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (self.call, self.interval_ms) == (other.call, other.interval_ms)
    return NotImplemented


def _hash_Keepalive(self: Any) -> int:
    return hash((self.call, self.interval_ms))


_set_Connection_name = _unbound
_set_Connection_kind = _unbound
_set_Connection_baud = _unbound
_set_Connection_frequency_hz = _unbound
_set_Connection_startup = _unbound
_set_Connection_terminate = _unbound
_set_Connection_keepalive = _unbound
_set_Connection_doc = _unbound
_set_Connection_span = _unbound
_set_Connection_terminator = _unbound
_set_Connection_address = _unbound
_set_Connection_baud_setting = _unbound
_set_Connection_data_bits = _unbound
_set_Connection_parity = _unbound
_set_Connection_stop_bits = _unbound
_set_Connection_threading = _unbound


def _init_Connection(
    self: Any,
    name: Any,
    kind: Any,
    baud: Any,
    frequency_hz: Any,
    startup: Any = DEFAULT,
    terminate: Any = DEFAULT,
    keepalive: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    terminator: Any = DEFAULT,
    address: Any = DEFAULT,
    baud_setting: Any = DEFAULT,
    data_bits: Any = DEFAULT,
    parity: Any = DEFAULT,
    stop_bits: Any = DEFAULT,
    threading: Any = DEFAULT,
) -> None:
    _set_Connection_name(self, name)
    _set_Connection_kind(self, kind)
    _set_Connection_baud(self, baud)
    _set_Connection_frequency_hz(self, frequency_hz)
    _set_Connection_startup(self, startup)
    _set_Connection_terminate(self, terminate)
    _set_Connection_keepalive(self, keepalive)
    _set_Connection_doc(self, doc)
    _set_Connection_span(self, span)
    _set_Connection_terminator(self, terminator)
    _set_Connection_address(self, address)
    _set_Connection_baud_setting(self, baud_setting)
    _set_Connection_data_bits(self, data_bits)
    _set_Connection_parity(self, parity)
    _set_Connection_stop_bits(self, stop_bits)
    _set_Connection_threading(self, threading)


def _repr_Connection(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, kind={self.kind!r}, baud={self.baud!r}, frequency_hz={self.frequency_hz!r}, startup={self.startup!r}, terminate={self.terminate!r}, keepalive={self.keepalive!r}, doc={self.doc!r}, terminator={self.terminator!r}, address={self.address!r}, baud_setting={self.baud_setting!r}, data_bits={self.data_bits!r}, parity={self.parity!r}, stop_bits={self.stop_bits!r}, threading={self.threading!r})"


def _eq_Connection(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.kind,
            self.baud,
            self.frequency_hz,
            self.startup,
            self.terminate,
            self.keepalive,
            self.doc,
            self.terminator,
            self.address,
            self.baud_setting,
            self.data_bits,
            self.parity,
            self.stop_bits,
            self.threading,
        ) == (
            other.name,
            other.kind,
            other.baud,
            other.frequency_hz,
            other.startup,
            other.terminate,
            other.keepalive,
            other.doc,
            other.terminator,
            other.address,
            other.baud_setting,
            other.data_bits,
            other.parity,
            other.stop_bits,
            other.threading,
        )
    return NotImplemented


def _hash_Connection(self: Any) -> int:
    return hash((
        self.name,
        self.kind,
        self.baud,
        self.frequency_hz,
        self.startup,
        self.terminate,
        self.keepalive,
        self.doc,
        self.terminator,
        self.address,
        self.baud_setting,
        self.data_bits,
        self.parity,
        self.stop_bits,
        self.threading,
    ))


_set_Primitive_name = _unbound
_set_Primitive_params = _unbound
_set_Primitive_connection = _unbound
_set_Primitive_encoding = _unbound
_set_Primitive_args = _unbound
_set_Primitive_decoding = _unbound
_set_Primitive_actions = _unbound
_set_Primitive_doc = _unbound
_set_Primitive_span = _unbound
_set_Primitive_frame = _unbound
_set_Primitive_skip_unmatched = _unbound
_set_Primitive_table = _unbound
_set_Primitive_timeout_ms = _unbound
_set_Primitive_expect = _unbound
_set_Primitive_lines = _unbound
_set_Primitive_replies = _unbound
_set_Primitive_reply_frames = _unbound
_set_Primitive_records = _unbound
_set_Primitive_listed = _unbound
_set_Primitive_retries = _unbound
_set_Primitive_error = _unbound
_set_Primitive_each = _unbound


def _init_Primitive(
    self: Any,
    name: Any,
    params: Any,
    connection: Any,
    encoding: Any,
    args: Any,
    decoding: Any = DEFAULT,
    actions: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    frame: Any = DEFAULT,
    skip_unmatched: Any = DEFAULT,
    table: Any = DEFAULT,
    timeout_ms: Any = DEFAULT,
    expect: Any = DEFAULT,
    lines: Any = DEFAULT,
    replies: Any = DEFAULT,
    reply_frames: Any = DEFAULT,
    records: Any = DEFAULT,
    listed: Any = DEFAULT,
    retries: Any = DEFAULT,
    error: Any = DEFAULT,
    each: Any = DEFAULT,
) -> None:
    _set_Primitive_name(self, name)
    _set_Primitive_params(self, params)
    _set_Primitive_connection(self, connection)
    _set_Primitive_encoding(self, encoding)
    _set_Primitive_args(self, args)
    _set_Primitive_decoding(self, decoding)
    _set_Primitive_actions(self, actions)
    _set_Primitive_doc(self, doc)
    _set_Primitive_span(self, span)
    _set_Primitive_frame(self, frame)
    _set_Primitive_skip_unmatched(self, skip_unmatched)
    _set_Primitive_table(self, table)
    _set_Primitive_timeout_ms(self, timeout_ms)
    _set_Primitive_expect(self, expect)
    _set_Primitive_lines(self, lines)
    _set_Primitive_replies(self, replies)
    _set_Primitive_reply_frames(self, reply_frames)
    _set_Primitive_records(self, records)
    _set_Primitive_listed(self, listed)
    _set_Primitive_retries(self, retries)
    _set_Primitive_error(self, error)
    _set_Primitive_each(self, each)


def _repr_Primitive(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, connection={self.connection!r}, encoding={self.encoding!r}, args={self.args!r}, decoding={self.decoding!r}, actions={self.actions!r}, doc={self.doc!r}, frame={self.frame!r}, skip_unmatched={self.skip_unmatched!r}, table={self.table!r}, timeout_ms={self.timeout_ms!r}, expect={self.expect!r}, lines={self.lines!r}, replies={self.replies!r}, reply_frames={self.reply_frames!r}, records={self.records!r}, listed={self.listed!r}, retries={self.retries!r}, error={self.error!r}, each={self.each!r})"


def _eq_Primitive(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.connection,
            self.encoding,
            self.args,
            self.decoding,
            self.actions,
            self.doc,
            self.frame,
            self.skip_unmatched,
            self.table,
            self.timeout_ms,
            self.expect,
            self.lines,
            self.replies,
            self.reply_frames,
            self.records,
            self.listed,
            self.retries,
            self.error,
            self.each,
        ) == (
            other.name,
            other.params,
            other.connection,
            other.encoding,
            other.args,
            other.decoding,
            other.actions,
            other.doc,
            other.frame,
            other.skip_unmatched,
            other.table,
            other.timeout_ms,
            other.expect,
            other.lines,
            other.replies,
            other.reply_frames,
            other.records,
            other.listed,
            other.retries,
            other.error,
            other.each,
        )
    return NotImplemented


def _hash_Primitive(self: Any) -> int:
    return hash((
        self.name,
        self.params,
        self.connection,
        self.encoding,
        self.args,
        self.decoding,
        self.actions,
        self.doc,
        self.frame,
        self.skip_unmatched,
        self.table,
        self.timeout_ms,
        self.expect,
        self.lines,
        self.replies,
        self.reply_frames,
        self.records,
        self.listed,
        self.retries,
        self.error,
        self.each,
    ))


_set_PrimitiveCall_primitive = _unbound
_set_PrimitiveCall_args = _unbound
_set_PrimitiveCall_delay_ms = _unbound
_set_PrimitiveCall_priority = _unbound
_set_PrimitiveCall_span = _unbound
_set_PrimitiveCall_interface = _unbound
_set_PrimitiveCall_when = _unbound
_set_PrimitiveCall_until = _unbound
_set_PrimitiveCall_every_ms = _unbound
_set_PrimitiveCall_within_ms = _unbound


def _init_PrimitiveCall(
    self: Any,
    primitive: Any,
    args: Any,
    delay_ms: Any = DEFAULT,
    priority: Any = DEFAULT,
    span: Any = DEFAULT,
    interface: Any = DEFAULT,
    when: Any = DEFAULT,
    until: Any = DEFAULT,
    every_ms: Any = DEFAULT,
    within_ms: Any = DEFAULT,
) -> None:
    _set_PrimitiveCall_primitive(self, primitive)
    _set_PrimitiveCall_args(self, args)
    _set_PrimitiveCall_delay_ms(self, delay_ms)
    _set_PrimitiveCall_priority(self, priority)
    _set_PrimitiveCall_span(self, span)
    _set_PrimitiveCall_interface(self, interface)
    _set_PrimitiveCall_when(self, when)
    _set_PrimitiveCall_until(self, until)
    _set_PrimitiveCall_every_ms(self, every_ms)
    _set_PrimitiveCall_within_ms(self, within_ms)


def _repr_PrimitiveCall(self: Any) -> str:
    return f"{self.__class__.__qualname__}(primitive={self.primitive!r}, args={self.args!r}, delay_ms={self.delay_ms!r}, priority={self.priority!r}, interface={self.interface!r}, when={self.when!r}, until={self.until!r}, every_ms={self.every_ms!r}, within_ms={self.within_ms!r})"


def _eq_PrimitiveCall(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.primitive,
            self.args,
            self.delay_ms,
            self.priority,
            self.interface,
            self.when,
            self.until,
            self.every_ms,
            self.within_ms,
        ) == (
            other.primitive,
            other.args,
            other.delay_ms,
            other.priority,
            other.interface,
            other.when,
            other.until,
            other.every_ms,
            other.within_ms,
        )
    return NotImplemented


def _hash_PrimitiveCall(self: Any) -> int:
    return hash((
        self.primitive,
        self.args,
        self.delay_ms,
        self.priority,
        self.interface,
        self.when,
        self.until,
        self.every_ms,
        self.within_ms,
    ))


_set_Interface_name = _unbound
_set_Interface_params = _unbound
_set_Interface_periodic = _unbound
_set_Interface_calls = _unbound
_set_Interface_triggers = _unbound
_set_Interface_doc = _unbound
_set_Interface_span = _unbound
_set_Interface_rate_hz = _unbound


def _init_Interface(
    self: Any,
    name: Any,
    params: Any,
    periodic: Any,
    calls: Any,
    triggers: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    rate_hz: Any = DEFAULT,
) -> None:
    _set_Interface_name(self, name)
    _set_Interface_params(self, params)
    _set_Interface_periodic(self, periodic)
    _set_Interface_calls(self, calls)
    _set_Interface_triggers(self, triggers)
    _set_Interface_doc(self, doc)
    _set_Interface_span(self, span)
    _set_Interface_rate_hz(self, rate_hz)


def _repr_Interface(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, params={self.params!r}, periodic={self.periodic!r}, calls={self.calls!r}, triggers={self.triggers!r}, doc={self.doc!r}, rate_hz={self.rate_hz!r})"


def _eq_Interface(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.params,
            self.periodic,
            self.calls,
            self.triggers,
            self.doc,
            self.rate_hz,
        ) == (
            other.name,
            other.params,
            other.periodic,
            other.calls,
            other.triggers,
            other.doc,
            other.rate_hz,
        )
    return NotImplemented


def _hash_Interface(self: Any) -> int:
    return hash((self.name, self.params, self.periodic, self.calls, self.triggers, self.doc, self.rate_hz))


_set_AdapterField_name = _unbound
_set_AdapterField_type = _unbound
_set_AdapterField_unit = _unbound
_set_AdapterField_ros = _unbound
_set_AdapterField_doc = _unbound


def _init_AdapterField(
    self: Any,
    name: Any,
    type: Any,
    unit: Any = DEFAULT,
    ros: Any = DEFAULT,
    doc: Any = DEFAULT,
) -> None:
    _set_AdapterField_name(self, name)
    _set_AdapterField_type(self, type)
    _set_AdapterField_unit(self, unit)
    _set_AdapterField_ros(self, ros)
    _set_AdapterField_doc(self, doc)


def _repr_AdapterField(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, type={self.type!r}, unit={self.unit!r}, ros={self.ros!r}, doc={self.doc!r})"


def _eq_AdapterField(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.type,
            self.unit,
            self.ros,
            self.doc,
        ) == (
            other.name,
            other.type,
            other.unit,
            other.ros,
            other.doc,
        )
    return NotImplemented


def _hash_AdapterField(self: Any) -> int:
    return hash((self.name, self.type, self.unit, self.ros, self.doc))


_set_FrameworkMapping_framework = _unbound
_set_FrameworkMapping_title = _unbound
_set_FrameworkMapping_type = _unbound
_set_FrameworkMapping_paths = _unbound
_set_FrameworkMapping_schema_encoding = _unbound
_set_FrameworkMapping_message_encoding = _unbound


def _init_FrameworkMapping(
    self: Any,
    framework: Any,
    title: Any,
    type: Any,
    paths: Any,
    schema_encoding: Any = DEFAULT,
    message_encoding: Any = DEFAULT,
) -> None:
    _set_FrameworkMapping_framework(self, framework)
    _set_FrameworkMapping_title(self, title)
    _set_FrameworkMapping_type(self, type)
    _set_FrameworkMapping_paths(self, paths)
    _set_FrameworkMapping_schema_encoding(self, schema_encoding)
    _set_FrameworkMapping_message_encoding(self, message_encoding)


def _repr_FrameworkMapping(self: Any) -> str:
    return f"{self.__class__.__qualname__}(framework={self.framework!r}, title={self.title!r}, type={self.type!r}, paths={self.paths!r}, schema_encoding={self.schema_encoding!r}, message_encoding={self.message_encoding!r})"


def _eq_FrameworkMapping(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.framework,
            self.title,
            self.type,
            self.paths,
            self.schema_encoding,
            self.message_encoding,
        ) == (
            other.framework,
            other.title,
            other.type,
            other.paths,
            other.schema_encoding,
            other.message_encoding,
        )
    return NotImplemented


def _hash_FrameworkMapping(self: Any) -> int:
    return hash((
        self.framework,
        self.title,
        self.type,
        self.paths,
        self.schema_encoding,
        self.message_encoding,
    ))


_set_Adapter_name = _unbound
_set_Adapter_fields = _unbound
_set_Adapter_ros = _unbound
_set_Adapter_standard = _unbound
_set_Adapter_doc = _unbound
_set_Adapter_span = _unbound
_set_Adapter_frameworks = _unbound


def _init_Adapter(
    self: Any,
    name: Any,
    fields: Any,
    ros: Any = DEFAULT,
    standard: Any = DEFAULT,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    frameworks: Any = DEFAULT,
) -> None:
    _set_Adapter_name(self, name)
    _set_Adapter_fields(self, fields)
    _set_Adapter_ros(self, ros)
    _set_Adapter_standard(self, standard)
    _set_Adapter_doc(self, doc)
    _set_Adapter_span(self, span)
    _set_Adapter_frameworks(self, frameworks)


def _repr_Adapter(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, fields={self.fields!r}, ros={self.ros!r}, standard={self.standard!r}, doc={self.doc!r}, frameworks={self.frameworks!r})"


def _eq_Adapter(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.fields,
            self.ros,
            self.standard,
            self.doc,
            self.frameworks,
        ) == (
            other.name,
            other.fields,
            other.ros,
            other.standard,
            other.doc,
            other.frameworks,
        )
    return NotImplemented


def _hash_Adapter(self: Any) -> int:
    return hash((self.name, self.fields, self.ros, self.standard, self.doc, self.frameworks))


_set_DomainInput_name = _unbound
_set_DomainInput_adapter = _unbound
_set_DomainInput_interface = _unbound
_set_DomainInput_args = _unbound
_set_DomainInput_doc = _unbound
_set_DomainInput_span = _unbound


def _init_DomainInput(
    self: Any,
    name: Any,
    adapter: Any,
    interface: Any,
    args: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
) -> None:
    _set_DomainInput_name(self, name)
    _set_DomainInput_adapter(self, adapter)
    _set_DomainInput_interface(self, interface)
    _set_DomainInput_args(self, args)
    _set_DomainInput_doc(self, doc)
    _set_DomainInput_span(self, span)


def _repr_DomainInput(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, adapter={self.adapter!r}, interface={self.interface!r}, args={self.args!r}, doc={self.doc!r})"


def _eq_DomainInput(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.adapter,
            self.interface,
            self.args,
            self.doc,
        ) == (
            other.name,
            other.adapter,
            other.interface,
            other.args,
            other.doc,
        )
    return NotImplemented


def _hash_DomainInput(self: Any) -> int:
    return hash((self.name, self.adapter, self.interface, self.args, self.doc))


_set_Noise_field = _unbound
_set_Noise_covariance = _unbound
_set_Noise_deviation = _unbound
_set_Noise_unit = _unbound
_set_Noise_span = _unbound
_set_Noise_others = _unbound


def _init_Noise(
    self: Any,
    field: Any,
    covariance: Any,
    deviation: Any = DEFAULT,
    unit: Any = DEFAULT,
    span: Any = DEFAULT,
    others: Any = DEFAULT,
) -> None:
    _set_Noise_field(self, field)
    _set_Noise_covariance(self, covariance)
    _set_Noise_deviation(self, deviation)
    _set_Noise_unit(self, unit)
    _set_Noise_span(self, span)
    _set_Noise_others(self, others)


def _repr_Noise(self: Any) -> str:
    return f"{self.__class__.__qualname__}(field={self.field!r}, covariance={self.covariance!r}, deviation={self.deviation!r}, unit={self.unit!r}, others={self.others!r})"


def _eq_Noise(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.field,
            self.covariance,
            self.deviation,
            self.unit,
            self.others,
        ) == (
            other.field,
            other.covariance,
            other.deviation,
            other.unit,
            other.others,
        )
    return NotImplemented


def _hash_Noise(self: Any) -> int:
    return hash((self.field, self.covariance, self.deviation, self.unit, self.others))


_set_Kalman_field = _unbound
_set_Kalman_state = _unbound
_set_Kalman_covariance = _unbound
_set_Kalman_transition = _unbound
_set_Kalman_process = _unbound
_set_Kalman_measurement = _unbound
_set_Kalman_noise = _unbound
_set_Kalman_span = _unbound


def _init_Kalman(
    self: Any,
    field: Any,
    state: Any,
    covariance: Any,
    transition: Any,
    process: Any,
    measurement: Any,
    noise: Any,
    span: Any = DEFAULT,
) -> None:
    _set_Kalman_field(self, field)
    _set_Kalman_state(self, state)
    _set_Kalman_covariance(self, covariance)
    _set_Kalman_transition(self, transition)
    _set_Kalman_process(self, process)
    _set_Kalman_measurement(self, measurement)
    _set_Kalman_noise(self, noise)
    _set_Kalman_span(self, span)


def _repr_Kalman(self: Any) -> str:
    return f"{self.__class__.__qualname__}(field={self.field!r}, state={self.state!r}, covariance={self.covariance!r}, transition={self.transition!r}, process={self.process!r}, measurement={self.measurement!r}, noise={self.noise!r})"


def _eq_Kalman(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.field,
            self.state,
            self.covariance,
            self.transition,
            self.process,
            self.measurement,
            self.noise,
        ) == (
            other.field,
            other.state,
            other.covariance,
            other.transition,
            other.process,
            other.measurement,
            other.noise,
        )
    return NotImplemented


def _hash_Kalman(self: Any) -> int:
    return hash((
        self.field,
        self.state,
        self.covariance,
        self.transition,
        self.process,
        self.measurement,
        self.noise,
    ))


_set_DomainOutput_name = _unbound
_set_DomainOutput_adapter = _unbound
_set_DomainOutput_fields = _unbound
_set_DomainOutput_doc = _unbound
_set_DomainOutput_span = _unbound
_set_DomainOutput_frame = _unbound
_set_DomainOutput_noise = _unbound
_set_DomainOutput_filters = _unbound


def _init_DomainOutput(
    self: Any,
    name: Any,
    adapter: Any,
    fields: Any,
    doc: Any = DEFAULT,
    span: Any = DEFAULT,
    frame: Any = DEFAULT,
    noise: Any = DEFAULT,
    filters: Any = DEFAULT,
) -> None:
    _set_DomainOutput_name(self, name)
    _set_DomainOutput_adapter(self, adapter)
    _set_DomainOutput_fields(self, fields)
    _set_DomainOutput_doc(self, doc)
    _set_DomainOutput_span(self, span)
    _set_DomainOutput_frame(self, frame)
    _set_DomainOutput_noise(self, noise)
    _set_DomainOutput_filters(self, filters)


def _repr_DomainOutput(self: Any) -> str:
    return f"{self.__class__.__qualname__}(name={self.name!r}, adapter={self.adapter!r}, fields={self.fields!r}, doc={self.doc!r}, frame={self.frame!r}, noise={self.noise!r}, filters={self.filters!r})"


def _eq_DomainOutput(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.name,
            self.adapter,
            self.fields,
            self.doc,
            self.frame,
            self.noise,
            self.filters,
        ) == (
            other.name,
            other.adapter,
            other.fields,
            other.doc,
            other.frame,
            other.noise,
            other.filters,
        )
    return NotImplemented


def _hash_DomainOutput(self: Any) -> int:
    return hash((self.name, self.adapter, self.fields, self.doc, self.frame, self.noise, self.filters))


WRITTEN: dict[str, Written] = {
    "Robot": Written(
        (
            ("name", MISSING),
            ("author", DEFAULT),
            ("description", DEFAULT),
            ("version", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_Robot, "__repr__": _repr_Robot, "__eq__": _eq_Robot, "__hash__": _hash_Robot},
    ),
    "StateVariable": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("initial", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("noise", DEFAULT),
        ),
        {
            "__init__": _init_StateVariable,
            "__repr__": _repr_StateVariable,
            "__eq__": _eq_StateVariable,
            "__hash__": _hash_StateVariable,
        },
    ),
    "Sensor": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("primitive", MISSING),
            ("cache_ms", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("noise", DEFAULT),
        ),
        {"__init__": _init_Sensor, "__repr__": _repr_Sensor, "__eq__": _eq_Sensor, "__hash__": _hash_Sensor},
    ),
    "Setting": Written(
        (
            ("name", MISSING),
            ("type", MISSING),
            ("default", MISSING),
            ("low", DEFAULT),
            ("high", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_Setting,
            "__repr__": _repr_Setting,
            "__eq__": _eq_Setting,
            "__hash__": _hash_Setting,
        },
    ),
    "HookCall": Written(
        (("interface", MISSING), ("args", MISSING), ("span", FieldSpec(None, MISSING, False, False))),
        {
            "__init__": _init_HookCall,
            "__repr__": _repr_HookCall,
            "__eq__": _eq_HookCall,
            "__hash__": _hash_HookCall,
        },
    ),
    "Keepalive": Written(
        (("call", MISSING), ("interval_ms", MISSING)),
        {
            "__init__": _init_Keepalive,
            "__repr__": _repr_Keepalive,
            "__eq__": _eq_Keepalive,
            "__hash__": _hash_Keepalive,
        },
    ),
    "Connection": Written(
        (
            ("name", MISSING),
            ("kind", MISSING),
            ("baud", MISSING),
            ("frequency_hz", MISSING),
            ("startup", DEFAULT),
            ("terminate", DEFAULT),
            ("keepalive", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("terminator", DEFAULT),
            ("address", DEFAULT),
            ("baud_setting", DEFAULT),
            ("data_bits", DEFAULT),
            ("parity", DEFAULT),
            ("stop_bits", DEFAULT),
            ("threading", DEFAULT),
        ),
        {
            "__init__": _init_Connection,
            "__repr__": _repr_Connection,
            "__eq__": _eq_Connection,
            "__hash__": _hash_Connection,
        },
    ),
    "Primitive": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("connection", MISSING),
            ("encoding", MISSING),
            ("args", MISSING),
            ("decoding", DEFAULT),
            ("actions", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("frame", DEFAULT),
            ("skip_unmatched", DEFAULT),
            ("table", DEFAULT),
            ("timeout_ms", DEFAULT),
            ("expect", DEFAULT),
            ("lines", DEFAULT),
            ("replies", DEFAULT),
            ("reply_frames", DEFAULT),
            ("records", DEFAULT),
            ("listed", DEFAULT),
            ("retries", DEFAULT),
            ("error", DEFAULT),
            ("each", DEFAULT),
        ),
        {
            "__init__": _init_Primitive,
            "__repr__": _repr_Primitive,
            "__eq__": _eq_Primitive,
            "__hash__": _hash_Primitive,
        },
    ),
    "PrimitiveCall": Written(
        (
            ("primitive", MISSING),
            ("args", MISSING),
            ("delay_ms", DEFAULT),
            ("priority", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("interface", DEFAULT),
            ("when", DEFAULT),
            ("until", DEFAULT),
            ("every_ms", DEFAULT),
            ("within_ms", DEFAULT),
        ),
        {
            "__init__": _init_PrimitiveCall,
            "__repr__": _repr_PrimitiveCall,
            "__eq__": _eq_PrimitiveCall,
            "__hash__": _hash_PrimitiveCall,
        },
    ),
    "Interface": Written(
        (
            ("name", MISSING),
            ("params", MISSING),
            ("periodic", MISSING),
            ("calls", MISSING),
            ("triggers", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("rate_hz", DEFAULT),
        ),
        {
            "__init__": _init_Interface,
            "__repr__": _repr_Interface,
            "__eq__": _eq_Interface,
            "__hash__": _hash_Interface,
        },
    ),
    "AdapterField": Written(
        (("name", MISSING), ("type", MISSING), ("unit", DEFAULT), ("ros", DEFAULT), ("doc", DEFAULT)),
        {
            "__init__": _init_AdapterField,
            "__repr__": _repr_AdapterField,
            "__eq__": _eq_AdapterField,
            "__hash__": _hash_AdapterField,
        },
    ),
    "FrameworkMapping": Written(
        (
            ("framework", MISSING),
            ("title", MISSING),
            ("type", MISSING),
            ("paths", MISSING),
            ("schema_encoding", DEFAULT),
            ("message_encoding", DEFAULT),
        ),
        {
            "__init__": _init_FrameworkMapping,
            "__repr__": _repr_FrameworkMapping,
            "__eq__": _eq_FrameworkMapping,
            "__hash__": _hash_FrameworkMapping,
        },
    ),
    "Adapter": Written(
        (
            ("name", MISSING),
            ("fields", MISSING),
            ("ros", DEFAULT),
            ("standard", DEFAULT),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("frameworks", DEFAULT),
        ),
        {
            "__init__": _init_Adapter,
            "__repr__": _repr_Adapter,
            "__eq__": _eq_Adapter,
            "__hash__": _hash_Adapter,
        },
    ),
    "DomainInput": Written(
        (
            ("name", MISSING),
            ("adapter", MISSING),
            ("interface", MISSING),
            ("args", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {
            "__init__": _init_DomainInput,
            "__repr__": _repr_DomainInput,
            "__eq__": _eq_DomainInput,
            "__hash__": _hash_DomainInput,
        },
    ),
    "Noise": Written(
        (
            ("field", MISSING),
            ("covariance", MISSING),
            ("deviation", DEFAULT),
            ("unit", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("others", DEFAULT),
        ),
        {"__init__": _init_Noise, "__repr__": _repr_Noise, "__eq__": _eq_Noise, "__hash__": _hash_Noise},
    ),
    "Kalman": Written(
        (
            ("field", MISSING),
            ("state", MISSING),
            ("covariance", MISSING),
            ("transition", MISSING),
            ("process", MISSING),
            ("measurement", MISSING),
            ("noise", MISSING),
            ("span", FieldSpec(None, MISSING, False, False)),
        ),
        {"__init__": _init_Kalman, "__repr__": _repr_Kalman, "__eq__": _eq_Kalman, "__hash__": _hash_Kalman},
    ),
    "DomainOutput": Written(
        (
            ("name", MISSING),
            ("adapter", MISSING),
            ("fields", MISSING),
            ("doc", DEFAULT),
            ("span", FieldSpec(None, MISSING, False, False)),
            ("frame", DEFAULT),
            ("noise", DEFAULT),
            ("filters", DEFAULT),
        ),
        {
            "__init__": _init_DomainOutput,
            "__repr__": _repr_DomainOutput,
            "__eq__": _eq_DomainOutput,
            "__hash__": _hash_DomainOutput,
        },
    ),
}
dataclass = classes(WRITTEN)
