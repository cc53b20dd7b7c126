"""The engine's Session: the channels a recording and `--foxglove` carry, each state variable as
its std_msgs message. Its schemas are held against rosbags's ROS 2 Humble definitions and its
messages, encoded as a recording encodes them, decoded by rosbags."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy
from mcap_ros2._dynamic import serialize_dynamic
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

from rdisc import engine
from rdisc.runtime import load

HUMBLE = get_typestore(Stores.ROS2_HUMBLE)
STATES = """\
robot states {
    description "a state variable of every kind"
}

setting address: int in 0x80..0x87 = 0x80
state count: int = -3
state level: float = 2.5
state moving: bool = True
state name: string = "ax"
state flags: bool[2] = [True, False]
state counts: int[2] = [1, -2]
state gains: float[2] = [0.5, 1.5]
state huge: int = 18446744073709551615

connection bus: serial {
    baud 9600
}

primitive ping() on bus pack "B" (1)
"""


def _device(tmp_path: Path) -> engine.Device:
    source = tmp_path / "states.rdis"
    source.write_text(STATES, encoding="utf-8")
    return load(source).device


def _parsed(name: str, text: str) -> dict[str, Any]:
    """A ros2msg schema's message and each one it uses, under its `MSG:` line, parsed by rosbags."""
    first, *used = text.split("=" * 80 + "\n")
    found = dict(get_types_from_msg(first, name))
    for part in used:
        head, _, body = part.partition("\n")
        package, _, message = head.removeprefix("MSG: ").partition("/")
        found.update(get_types_from_msg(body, f"{package}/msg/{message}"))
    return found


def test_each_state_variable_has_a_channel_of_its_std_msgs_type(tmp_path) -> None:
    topics = engine.session_topics(_device(tmp_path))
    assert [(topic.name, topic.type) for topic in topics] == [
        ("/state/address", "std_msgs/msg/Int64"),
        ("/state/count", "std_msgs/msg/Int64"),
        ("/state/level", "std_msgs/msg/Float64"),
        ("/state/moving", "std_msgs/msg/Bool"),
        ("/state/name", "std_msgs/msg/String"),
        ("/state/flags", "std_msgs/msg/String"),  # no std_msgs array of bools: JSON text
        ("/state/counts", "std_msgs/msg/Int64MultiArray"),
        ("/state/gains", "std_msgs/msg/Float64MultiArray"),
        ("/state/huge", "std_msgs/msg/Int64"),
        ("/rdisc/bus/write", "std_msgs/msg/UInt8MultiArray"),
        ("/rdisc/bus/read", "std_msgs/msg/UInt8MultiArray"),
        ("/rdisc/runs", "std_msgs/msg/String"),
        ("/rosout", "rcl_interfaces/msg/Log")]
    for topic in topics:
        for part, (kind, fields) in _parsed(topic.type, topic.schema).items():
            assert (kind, fields) == HUMBLE.fielddefs[part], part


def test_state_goes_to_the_sinks_that_take_it_once_a_value_changes(tmp_path) -> None:
    robot = engine.Robot(_device(tmp_path))
    session = engine.Session(robot)
    live: list[tuple[engine.Topic, dict[str, Any], int]] = []
    recorded: list[tuple[engine.Topic, dict[str, Any], int]] = []
    session.add(lambda *message: live.append(message))
    session.add(lambda *message: recorded.append(message), state=False)
    session.io("write", "bus", b"\x01")
    session.io("read", "bus", b"\x02")  # no value changed: no state sent again

    def decoded(topic: engine.Topic, message: dict[str, Any]) -> Any:
        raw = serialize_dynamic(topic.type, topic.schema)[topic.type](message)  # as a recording encodes it
        value = HUMBLE.deserialize_cdr(raw, topic.type).data
        return value.tolist() if isinstance(value, numpy.ndarray) else value

    assert [(topic.name, decoded(topic, message)) for topic, message, _ in live] == [
        ("/rdisc/bus/write", [1]),
        ("/state/address", 128), ("/state/count", -3), ("/state/level", 2.5), ("/state/moving", True),
        ("/state/name", "ax"), ("/state/flags", "[true, false]"), ("/state/counts", [1, -2]),
        ("/state/gains", [0.5, 1.5]),
        ("/state/huge", 2 ** 63 - 1),  # beyond int64: shown at its end
        ("/rdisc/bus/read", [2])]
    assert [topic.name for topic, _, _ in recorded] == ["/rdisc/bus/write", "/rdisc/bus/read"]
    stamps = [stamp for _, _, stamp in live]
    assert stamps == sorted(set(stamps))  # each later than the one before
