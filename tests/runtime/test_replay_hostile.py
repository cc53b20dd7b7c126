"""`rdisc replay` of recordings built to hurt: each is refused with exit status 2 and one line,
never a traceback or an internal error, and a recording of millions of messages is refused by
its count before any message is decoded."""

from __future__ import annotations

import json
import struct
from pathlib import Path
from typing import Any

import pytest
import zstandard
from conftest import run_rdisc_here
from mcap.data_stream import RecordBuilder
from mcap.records import Channel, Chunk, Message, Schema
from mcap.stream_reader import StreamReader
from mcap.writer import Writer as McapWriter
from mcap_ros2.writer import Writer
from runtime_support import CREATE

from rdisc import recordings
from rdisc.engine.recording import _BYTES_SCHEMA, _LOG_SCHEMA, _TEXT_SCHEMA

TEXT = ("std_msgs/msg/String", _TEXT_SCHEMA)
BYTES = ("std_msgs/msg/UInt8MultiArray", _BYTES_SCHEMA)
LOG = ("rcl_interfaces/msg/Log", _LOG_SCHEMA)
GOOD_RUN = {"call": "input", "name": "set_velocity", "values": {"linear": 0.1, "angular": 0.0}}


def recording(path: Path, messages: list[tuple[str, tuple[str, str], dict[str, Any]]],
              settings: str = "{}") -> Path:
    """A recording of these (topic, (type, schema), message), with rdisc's metadata."""
    with path.open("wb") as f:
        writer = Writer(f)
        writer.add_metadata("rdisc", {"robot": "create", "timeout": "1", "settings": settings})
        registered: dict[str, Any] = {}
        for n, (topic, (kind, schema), message) in enumerate(messages, start=1):
            if kind not in registered:
                registered[kind] = writer.register_msgdef(kind, schema)
            writer.write_message(topic, registered[kind], message, log_time=n)
        writer.finish()
    return path


def replay(path: Path) -> tuple[int, str]:
    result = run_rdisc_here("replay", path, CREATE)
    assert "Traceback" not in result.stderr and "internal error" not in result.stderr, result.stderr
    assert len(result.stderr.splitlines()) == 1, result.stderr
    return result.returncode, result.stderr


def run(value: Any) -> tuple[str, tuple[str, str], dict[str, Any]]:
    return ("/rdisc/runs", TEXT, {"data": json.dumps(value)})


@pytest.mark.parametrize(("name", "messages", "settings", "message"), [
    ("deep settings", [run(GOOD_RUN)], "[" * 100_000 + "]" * 100_000, "nested too deep"),
    ("settings not names", [run(GOOD_RUN)], '{"a": {"b": 1}}', "its settings are not names with values"),
    ("missing name", [run({"call": "input", "values": {}})], "{}", "a run that is not a call"),
    ("values a list", [run({"call": "input", "name": "set_velocity", "values": [0.1, 0]})], "{}",
     "a run that is not a call"),
    ("a run a list", [run([1, 2])], "{}", "a run that is not a call"),
    ("a connection's work of no name", [run({"periodic": 3, "connection": "btserial"})], "{}",
     "a run that is not a call"),
    ("runs of the wrong schema", [("/rdisc/runs", LOG, {"msg": "hi"})], "{}",
     "/rdisc/runs is rcl_interfaces/msg/Log, not the std_msgs/msg/String rdisc writes"),
    ("bytes of the wrong schema", [("/rdisc/btserial/write", TEXT, {"data": "89"})], "{}",
     "/rdisc/btserial/write is std_msgs/msg/String, not the std_msgs/msg/UInt8MultiArray rdisc writes"),
    ("errors of the wrong schema", [("/rosout", TEXT, {"data": "x"})], "{}",
     "/rosout is std_msgs/msg/String, not the rcl_interfaces/msg/Log rdisc writes"),
    ("contents not fields", [("/detect_bump", TEXT, {"data": "[1, 2]"})], "{}", "/detect_bump holds list"),
    ("contents nested deep", [("/detect_bump", TEXT, {"data": "[" * 5000 + "]" * 5000})], "{}", "nested too deep"),
])
def test_a_malformed_recording_is_refused_in_a_line(name: str, messages: list[Any], settings: str, message: str,
                                                    tmp_path: Path) -> None:
    path = recording(tmp_path / "bad.mcap", messages, settings)
    status, stderr = replay(path)
    assert status == 2, stderr
    assert stderr.startswith(f"rdisc replay: {path}: "), stderr
    assert message in stderr, stderr


def test_a_schema_that_holds_itself_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "loop.mcap"
    with path.open("wb") as f:
        writer = McapWriter(f)
        writer.start("ros2", "tests")
        writer.add_metadata("rdisc", {"robot": "create", "timeout": "1", "settings": "{}"})
        schema = writer.register_schema("tests/msg/Loop", "ros2msg", b"tests/Loop inner\n")
        channel = writer.register_channel("/detect_bump", "cdr", schema)
        writer.add_message(channel, 1, b"\x00\x01\x00\x00" + b"\x00" * 64, 1)
        writer.finish()
    status, stderr = replay(path)
    assert status == 2 and stderr.startswith(f"rdisc replay: {path}: not a readable recording"), stderr


def test_a_chunk_with_flipped_bytes_is_refused(tmp_path: Path) -> None:
    path = recording(tmp_path / "flipped.mcap", [run(GOOD_RUN)] + [
        ("/rdisc/btserial/write", BYTES, {"data": list(range(n % 200))}) for n in range(300)])
    data = bytearray(path.read_bytes())
    with path.open("rb") as f:
        chunks = [r for r in StreamReader(f, emit_chunks=True).records if isinstance(r, Chunk)]
    assert chunks and chunks[0].compression == "zstd"
    where = data.find(chunks[0].data) + len(chunks[0].data) // 2
    data[where:where + 16] = bytes(b ^ 0xFF for b in data[where:where + 16])
    path.write_bytes(bytes(data))
    status, stderr = replay(path)
    assert status == 2 and stderr.startswith(f"rdisc replay: {path}: not a readable recording"), stderr


def test_millions_of_messages_are_refused_by_their_count_before_any_is_decoded(tmp_path: Path,
                                                                               monkeypatch) -> None:
    """Four chunks of a million identical messages each, a few KiB of zstd apiece: counted as
    they are read, and refused at MAX_MESSAGES, before a single one is decoded."""
    each = 1_000_000
    assert recordings.MAX_MESSAGES < 4 * each
    builder = RecordBuilder()
    Schema(id=1, name="std_msgs/msg/String", encoding="ros2msg", data=_TEXT_SCHEMA.encode()).write(builder)
    Channel(id=1, schema_id=1, topic="/detect_bump", message_encoding="cdr", metadata={}).write(builder)
    head = builder.end()
    Message(channel_id=1, sequence=0, log_time=1, publish_time=1, data=b"\x00\x01\x00\x00\x03\x00\x00\x00{}\x00").write(builder)
    body = head + builder.end() * each
    assert len(body) < recordings.MAX_CHUNK and 4 * len(body) < recordings.MAX_BYTES
    compressed = zstandard.ZstdCompressor().compress(body)
    path = tmp_path / "millions.mcap"
    with path.open("wb") as f:
        writer = McapWriter(f)
        writer.start("ros2", "tests")
        writer.add_metadata("rdisc", {"robot": "create", "timeout": "1", "settings": "{}"})
        writer.finish()
    chunk = Chunk(compression="zstd", data=compressed, message_start_time=1, message_end_time=1,
                  uncompressed_crc=0, uncompressed_size=len(body))
    for _ in range(4):
        chunk.write(builder)
    chunks = builder.end()
    data = path.read_bytes()
    start = data.index(b"rdisc")  # after the metadata record, before the data end: the chunks go there
    end = data.index(bytes([0x0F]), start)  # the DataEnd record's opcode
    path.write_bytes(data[:end] + chunks + data[end:])
    assert path.stat().st_size < 200_000
    decoded: list[Any] = []
    taken = recordings._take
    monkeypatch.setattr(recordings, "_take", lambda *args: decoded.append(args) or taken(*args))
    status, stderr = replay(path)
    assert status == 2, stderr
    assert stderr == f"rdisc replay: {path}: too many messages: more than {recordings.MAX_MESSAGES}\n"
    assert decoded == []


@pytest.mark.parametrize("realtime", [False, True])
def test_delays_are_slept_only_with_realtime(realtime: bool, tmp_path: Path, monkeypatch) -> None:
    """The Create's startup hooks each wait 1000 ms: a replay waits for none unless --realtime
    (the robot's delays are its `_delay`, which replay puts aside unless asked)."""
    from rdisc.engine.robot import Robot

    slept: list[float] = []
    monkeypatch.setattr(Robot, "_delay", lambda robot, seconds: slept.append(seconds))
    path = recording(tmp_path / "calls.mcap", [run(GOOD_RUN)])
    result = run_rdisc_here("replay", path, CREATE, *(["--realtime"] if realtime else []))
    assert result.returncode in (0, 1), result.stderr
    assert (1.0 in slept) is realtime, slept


@pytest.mark.parametrize(("schema", "said"), [
    ("byte X=2 ** 64", "can not be converted to type 'byte'"),
    ("=== not a field", "'===' is an invalid message name"),
    ("string =1", "invalid constant name"),
    ("1e39 data", "invalid message name"),
])
def test_a_schema_its_parser_refuses_is_refused_in_a_line(schema: str, said: str, tmp_path: Path) -> None:
    """The ROS 2 message parser raises its own errors (and prints them) for a schema it cannot
    read: each is the recording's fault, said in one line."""
    path = tmp_path / "schema.mcap"
    with path.open("wb") as f:
        writer = McapWriter(f)
        writer.start("ros2", "tests")
        writer.add_metadata("rdisc", {"robot": "create", "timeout": "1", "settings": "{}"})
        channel = writer.register_channel("/rdisc/runs", "cdr", writer.register_schema(TEXT[0], "ros2msg",
                                                                                       schema.encode()))
        writer.add_message(channel, 1, b"\x00\x01\x00\x00\x01\x00\x00\x00\x00", 1)
        writer.finish()
    status, stderr = replay(path)
    assert status == 2 and stderr.startswith(f"rdisc replay: {path}: not a readable recording: the schema "
                                             f"{TEXT[0]} of /rdisc/runs: "), stderr
    assert said in stderr, stderr


def test_a_chunk_whose_records_say_a_length_past_any_size_is_refused(tmp_path: Path) -> None:
    """A chunk of 60 bytes whose records' length is 2**63 + 1 (the mcap reader's read of it overflows)."""

    def record(opcode: int, body: bytes) -> bytes:
        return struct.pack("<BQ", opcode, len(body)) + body

    def text(value: str) -> bytes:
        return struct.pack("<I", len(value)) + value.encode()

    chunk = struct.pack("<QQQI", 0, 0, 10, 0) + text("zstd") + struct.pack("<Q", 2**63 + 1) + bytes(20)
    path = tmp_path / "long.mcap"
    path.write_bytes(b"\x89MCAP0\r\n" + record(0x01, text("ros2") + text("tests")) + record(0x06, chunk))
    status, stderr = replay(path)
    assert status == 2 and stderr.startswith(f"rdisc replay: {path}: not a readable recording"), stderr
