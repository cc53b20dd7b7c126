"""An rdisc recording read back (`read_recording`): the runs, the bytes each way on every
connection and the messages an MCAP file of `rdisc run --record` holds, every part checked for
the type and shape rdisc writes, and every size bounded before it is decoded. The replay
(rdisc.runtime.replay) runs it again; `rdisc decode` (rdisc.capture) reads its bytes.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import os
import struct
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from rdisc import engine
from rdisc.engine.recording import BYTES_TYPE, LOG_TYPE, TEXT_TYPE

__all__ = ["MAX_BYTES", "MAX_CHUNK", "MAX_MESSAGES", "Recording", "RecordingError", "read_recording"]


class RecordingError(Exception):
    """A file that is not a recording rdisc can read."""


@dataclass
class Recording:
    """What a replay needs of a recording, and what it compares."""

    settings: dict[str, Any] = field(default_factory=dict)
    timeout: float | None = None  # the reply timeout of the session; None in a recording older than it
    runs: list[dict[str, Any]] = field(default_factory=list)  # in order
    exchanges: dict[str, list[tuple[bytes | None, bytes]]] = field(default_factory=dict)  # by connection
    run_times: list[int] = field(default_factory=list)  # when each run began (ns, the recording's clock)
    exchange_times: dict[str, list[int]] = field(default_factory=dict)  # when each exchange ended, likewise
    writes: dict[str, list[bytes]] = field(default_factory=dict)  # by connection
    messages: dict[str, list[dict[str, Any]]] = field(default_factory=dict)  # by input or output, flattened
    errors: list[str] = field(default_factory=list)  # `Type: message`, in order


MAX_MESSAGES = 1_000_000
"""The messages a recording may hold: a session of hours; counted before any is decoded."""
MAX_CHUNK = 64 * 2**20
"""The bytes a chunk may hold once decompressed (the recorder writes chunks of 1 MiB)."""
MAX_BYTES = 512 * 2**20
"""The bytes a recording may hold once decompressed, in all."""
_SCALAR = (str, int, float, bool)


def read_recording(source: str | os.PathLike[str] | io.BytesIO) -> Recording:
    """A recording's runs, exchanges, writes and messages; RecordingError, in a line, if it is
    none: not MCAP, damaged, past the bounds above, or holding a message of a type or shape
    rdisc does not write."""
    try:
        from mcap.exceptions import McapError
        from mcap_ros2.decoder import DecoderFactory
    except ImportError as err:
        raise RecordingError("replaying needs the mcap and mcap-ros2-support packages "
                             "(pip install 'rdisc[record]')") from err
    recording = Recording()
    try:
        stream = open(source, "rb") if isinstance(source, (str, os.PathLike)) else source  # noqa: SIM115
        with stream:
            found, schemas, channels, messages = _records(stream)
            if found is None:
                raise RecordingError("not a recording of rdisc (it has no `rdisc` metadata)")
            _metadata(recording, found)
            messages.sort(key=lambda m: m[0])  # stable: the file's order among equal times
            factory = DecoderFactory()
            decoders: dict[int, tuple[str, str, Any]] = {}
            for log_time, channel_id, data in messages:
                if channel_id not in decoders:
                    decoders[channel_id] = _decoder(factory, channel_id, channels, schemas)
                topic, schema_name, decode = decoders[channel_id]
                _take(recording, topic, schema_name, decode(data), log_time)
    except RecordingError:
        raise
    except OSError as err:
        raise RecordingError(err.strerror or str(err)) from None
    except RecursionError:
        raise RecordingError("not a readable recording: nested too deep") from None
    except (McapError, ValueError, KeyError, TypeError, IndexError, NotImplementedError, AttributeError,
            struct.error, EOFError, OverflowError) as err:  # OverflowError: a record's length past any size
        said = str(err).splitlines()[0] if str(err) else type(err).__name__
        raise RecordingError(f"not a readable recording: {said}") from None
    return recording


_Records = tuple[dict[str, str] | None, dict[int, Any], dict[int, Any], list[tuple[int, int, bytes]]]


def _records(stream: Any) -> _Records:
    """The `rdisc` metadata, schemas and channels by id, and each message (log time, channel,
    data) undecoded: chunks decompressed one at a time within MAX_CHUNK and MAX_BYTES, the
    messages counted within MAX_MESSAGES."""
    from mcap.records import Channel, Chunk, Message, Metadata, Schema
    from mcap.stream_reader import StreamReader

    found: dict[str, str] | None = None
    schemas: dict[int, Any] = {}
    channels: dict[int, Any] = {}
    messages: list[tuple[int, int, bytes]] = []
    total = 0
    for record in StreamReader(stream, emit_chunks=True, record_size_limit=MAX_CHUNK).records:
        if isinstance(record, Chunk):
            total += record.uncompressed_size
            if record.uncompressed_size > MAX_CHUNK or total > MAX_BYTES:
                raise RecordingError(f"too large: more than {MAX_BYTES // 2**20} MiB decompressed in all, or "
                                     f"{MAX_CHUNK // 2**20} MiB in a chunk")
            _chunk_records(_decompressed(record), schemas, channels, messages)
        elif isinstance(record, Message):
            messages.append((record.log_time, record.channel_id, record.data))
        elif isinstance(record, Schema):
            schemas[record.id] = record
        elif isinstance(record, Channel):
            channels[record.id] = record
        elif isinstance(record, Metadata) and record.name == "rdisc":
            found = record.metadata
        if len(messages) > MAX_MESSAGES:
            raise RecordingError(f"too many messages: more than {MAX_MESSAGES}")
    return found, schemas, channels, messages


def _decompressed(chunk: Any) -> bytes:
    """A chunk's records, decompressed no further than the size it says (and refused if they are more)."""
    size = chunk.uncompressed_size
    if chunk.compression == "zstd":
        import zstandard

        try:
            data = zstandard.ZstdDecompressor().stream_reader(io.BytesIO(chunk.data)).read(size + 1)
        except zstandard.ZstdError as err:
            raise RecordingError(f"not a readable recording: a damaged chunk ({err})") from None
    elif chunk.compression == "lz4":
        import lz4.frame  # type: ignore[import-untyped]

        try:
            data = lz4.frame.LZ4FrameDecompressor().decompress(chunk.data, max_length=size + 1)
        except RuntimeError as err:
            raise RecordingError(f"not a readable recording: a damaged chunk ({err})") from None
    elif chunk.compression == "":
        data = chunk.data
    else:
        raise RecordingError(f"not a readable recording: a chunk compressed with {chunk.compression!r}")
    if len(data) != size:
        raise RecordingError(f"not a readable recording: a chunk of {len(data)} bytes or more that says it "
                             f"has {size}")
    return bytes(data)


def _chunk_records(data: bytes, schemas: dict[int, Any], channels: dict[int, Any],
                   messages: list[tuple[int, int, bytes]]) -> None:
    """The schemas, channels and messages of a decompressed chunk; messages counted as they come."""
    from mcap.data_stream import ReadDataStream
    from mcap.records import Channel, Schema

    pos, end = 0, len(data)
    while pos < end:
        opcode, length = struct.unpack_from("<BQ", data, pos)
        body = pos + 9
        pos = body + length
        if pos > end:
            raise RecordingError("not a readable recording: a record past the end of its chunk")
        if opcode == 0x05:  # Message
            channel_id, _, log_time = struct.unpack_from("<HIQ", data, body)
            if length < 22:
                raise RecordingError("not a readable recording: a message record too short")
            messages.append((log_time, channel_id, data[body + 22:pos]))
            if len(messages) > MAX_MESSAGES:
                raise RecordingError(f"too many messages: more than {MAX_MESSAGES}")
        elif opcode == 0x03:
            schema = Schema.read(ReadDataStream(io.BytesIO(data[body:pos])))
            schemas[schema.id] = schema
        elif opcode == 0x04:
            channel = Channel.read(ReadDataStream(io.BytesIO(data[body:pos])))
            channels[channel.id] = channel


def _metadata(recording: Recording, metadata: Mapping[str, str]) -> None:
    """The session's settings and reply timeout, checked for their types."""
    settings = json.loads(metadata.get("settings", "{}"))
    if not isinstance(settings, dict) or not all(
            isinstance(v, _SCALAR) or isinstance(v, list) and all(isinstance(i, _SCALAR) for i in v)
            for v in settings.values()):
        raise RecordingError("not a readable recording: its settings are not names with values")
    recording.settings = settings
    timeout = json.loads(metadata.get("timeout", "null"))
    recording.timeout = (float(timeout) if isinstance(timeout, (int, float)) and not isinstance(timeout, bool)
                         and 0 < timeout < math.inf else None)


def _decoder(factory: Any, channel_id: int, channels: Mapping[int, Any],
             schemas: Mapping[int, Any]) -> tuple[str, str, Any]:
    """A channel's topic, schema name and decoding function."""
    channel = channels.get(channel_id)
    schema = schemas.get(channel.schema_id) if channel is not None else None
    if channel is None or schema is None:
        raise RecordingError(f"not a readable recording: a message of channel {channel_id}, which it does "
                             "not describe")
    from mcap_ros2._vendor.rosidl_adapter.parser import InvalidSpecification, InvalidValue

    try:  # the schema's text is parsed here; its parser prints what it refuses, so that is kept from stderr
        with contextlib.redirect_stderr(io.StringIO()):
            decode = factory.decoder_for(channel.message_encoding, schema)
    except (InvalidSpecification, InvalidValue, NameError) as err:  # NameError: its word for a constant's bad name
        said = str(err).splitlines()[0] if str(err) else type(err).__name__
        raise RecordingError(f"not a readable recording: the schema {schema.name} of {channel.topic}: {said}"
                             ) from None
    if decode is None:
        raise RecordingError(f"not a readable recording: topic {channel.topic} is not ROS 2 messages in CDR")
    return channel.topic, schema.name, decode


_SCHEMAS = {"write": BYTES_TYPE, "read": BYTES_TYPE, "lines": TEXT_TYPE}


def _take(recording: Recording, topic: str, schema: str, message: Any, log_time: int = 0) -> None:
    """One message of the recording, in order, of the type rdisc writes on its topic, recorded at `log_time`."""
    parts = topic.split("/")
    if topic == engine.RUNS_TOPIC:
        recording.runs.append(_run_of(_field(topic, schema, TEXT_TYPE, message, "data", str)))
        recording.run_times.append(log_time)
    elif len(parts) == 4 and parts[1] == "rdisc" and parts[3] in _SCHEMAS:
        if parts[3] == "lines":
            _field(topic, schema, TEXT_TYPE, message, "data", str)
            return
        data = _field(topic, schema, BYTES_TYPE, message, "data", (bytes, list))
        connection, data = parts[2], bytes(data)
        exchanges = recording.exchanges.setdefault(connection, [])
        times = recording.exchange_times.setdefault(connection, [])
        if parts[3] == "write":
            recording.writes.setdefault(connection, []).append(data)
            exchanges.append((data, b""))
            times.append(log_time)
        elif exchanges and exchanges[-1][0] is not None and not exchanges[-1][1]:
            exchanges[-1] = (exchanges[-1][0], data)  # the reply to that write
            times[-1] = log_time
        else:
            exchanges.append((None, data))  # read with nothing written: a listener's
            times.append(log_time)
    elif topic == "/rosout":
        recording.errors.append(_field(topic, schema, LOG_TYPE, message, "msg", str))
    elif len(parts) == 2 and parts[1]:
        if schema == TEXT_TYPE:
            contents = json.loads(_field(topic, schema, TEXT_TYPE, message, "data", str))
            if not isinstance(contents, dict):
                raise RecordingError(f"not a readable recording: {topic} holds {type(contents).__name__}, "
                                     "not fields")
        else:
            contents = message
        recording.messages.setdefault(parts[1], []).append(  # a header's stamp is when it was recorded
            {path: value for path, value in _flat(contents) if not path.startswith("header.stamp.")})


def _field(topic: str, schema: str, expected: str, message: Any, name: str,
           kind: type | tuple[type, ...]) -> Any:
    """A message's field, of the schema and type rdisc writes on that topic; else RecordingError."""
    value = getattr(message, name, None)
    if schema != expected or not isinstance(value, kind):
        raise RecordingError(f"not a readable recording: {topic} is {schema}, not the {expected} rdisc "
                             "writes")
    return value


def _run_of(text: str) -> dict[str, Any]:
    """A recorded run: `{"call": KIND, "name": NAME, "values": {...}}` or `{"periodic" | "keepalive":
    NAME, "connection": CONNECTION}`, each member of its type; else RecordingError."""
    run = json.loads(text)
    if isinstance(run, dict) and "call" in run:
        values = run.get("values")
        if (run["call"] in ("input", "interface", "primitive") and isinstance(run.get("name"), str)
                and isinstance(values, dict) and all(
                    isinstance(v, _SCALAR) or isinstance(v, list) and all(isinstance(i, _SCALAR) for i in v)
                    for v in values.values())):
            return run
    elif isinstance(run, dict) and isinstance(run.get("connection"), str) and (
            isinstance(run.get("periodic"), str) or isinstance(run.get("keepalive"), str)):
        return run
    shown = text if len(text) <= 80 else text[:77] + "..."
    raise RecordingError("not a readable recording: a run that is not a call or a connection's work: "
                         f"{shown}")


def _flat(value: Any, prefix: str = "") -> Iterable[tuple[str, Any]]:
    """A decoded message (or JSON contents) as (field path, value) pairs: `linear.x`, `name[0]`."""
    if isinstance(value, dict):
        members: Iterable[tuple[str, Any]] = value.items()
    elif hasattr(value, "__slots__") and not isinstance(value, (str, bytes)):
        members = ((name, getattr(value, name)) for name in value.__slots__ if not name.startswith("_"))
    elif isinstance(value, (list, tuple, bytes)):
        for i, item in enumerate(value):
            yield from _flat(item, f"{prefix}[{i}]")
        return
    else:
        yield prefix, value
        return
    for name, member in members:
        yield from _flat(member, f"{prefix}.{name}" if prefix else name)
