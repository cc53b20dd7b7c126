"""An independent ROS 2 participant for the ROS 2 node's tests: Cyclone DDS with types built from
rosbags' ROS 2 message definitions (not rdisc's), named and encoded as ROS 2 does.

    python participant.py jazzy NODE      # in the node's ROS_DOMAIN_ID and CYCLONEDDS_URI

It publishes Twists on `set_velocity` (one a line of stdin, "linear angular"; `{"sent": T}` after
each, T from time.monotonic()), or for NODE `arm` JointStates on `joint_command` (a line of JSON,
`{"name": [...], "position": [...]}`), and prints one JSON line for each event: "matched" once the
node subscribes to what it publishes; each `joint_states` message as its CDR bytes; each `detect_bump` message (sensor-data profile) as its CDR bytes in
hex, for rosbags to decode; "incompatible" when its reliable reader of `detect_bump` is refused by
the node's best-effort writer; each `ros_discovery_info` naming the node; each error on
`/NODE/errors`. It ends at the end of stdin.
"""

from __future__ import annotations

import json
import os
import sys
import threading
import time
from typing import Any

from cyclonedds.core import Listener, Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import make_idl_struct
from cyclonedds.idl import types as dds
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration
from rosbags.typesys import Stores, get_typestore
from rosbags.typesys.store import Nodetype

STORES = {"humble": Stores.ROS2_HUMBLE, "jazzy": Stores.ROS2_JAZZY}
PRIMITIVES = {"bool": bool, "byte": dds.byte, "char": dds.uint8, "float32": dds.float32, "float64": dds.float64,
              "int8": dds.int8, "uint8": dds.uint8, "int16": dds.int16, "uint16": dds.uint16, "int32": dds.int32,
              "uint32": dds.uint32, "int64": dds.int64, "uint64": dds.uint64, "string": str}


class Types:
    """Cyclone DDS types of a rosbags typestore's messages, made as rosidl names them."""

    def __init__(self, distro: str) -> None:
        self.store = get_typestore(STORES[distro])
        self.made: dict[str, Any] = {}

    def __getitem__(self, name: str) -> Any:  # `pkg/msg/Type`
        if name not in self.made:
            _, members = self.store.fielddefs[name]
            package, _, message = name.split("/")
            self.made[name] = make_idl_struct(message, f"{package}::msg::dds_::{message}_",
                                              {member: self.kind(kind) for member, kind in members})
        return self.made[name]

    def kind(self, kind: Any) -> Any:
        node, detail = kind
        if node == Nodetype.BASE:
            name, bound = detail
            return dds.bounded_str(bound) if name == "string" and bound else PRIMITIVES[name]
        if node == Nodetype.NAME:
            return self[detail]
        inner, size = detail
        return dds.array(self.kind(inner), size) if node == Nodetype.ARRAY else dds.sequence(self.kind(inner))


SAYING = threading.Lock()  # Cyclone's threads and the main one: a line at a time


def say(**event: Any) -> None:
    with SAYING:
        print(json.dumps(event), flush=True)


def main() -> None:
    distro, node = sys.argv[1:3]
    types = Types(distro)
    xcdr1 = Policy.DataRepresentation(use_cdrv0_representation=True)
    default = Qos(Policy.Reliability.Reliable(duration(milliseconds=100)), Policy.History.KeepLast(10),
                  Policy.Durability.Volatile, xcdr1)
    sensor_data = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(5), Policy.Durability.Volatile, xcdr1)
    latched = Qos(Policy.Reliability.Reliable(duration(milliseconds=100)), Policy.History.KeepLast(1),
                  Policy.Durability.TransientLocal, xcdr1)
    participant = DomainParticipant(int(os.environ.get("ROS_DOMAIN_ID", "0")))
    matched = threading.Event()

    def topic(name: str, message: str) -> Topic:
        return Topic(participant, f"rt/{name}", types[message])

    twist, vector = types["geometry_msgs/msg/Twist"], types["geometry_msgs/msg/Vector3"]
    joints, header, stamp = (types["sensor_msgs/msg/JointState"], types["std_msgs/msg/Header"],
                             types["builtin_interfaces/msg/Time"])
    commanding = "joint_command" if node == "arm" else "set_velocity"
    writer = DataWriter(participant, topic(commanding, "sensor_msgs/msg/JointState" if node == "arm"
                                           else "geometry_msgs/msg/Twist"), qos=default,
                        listener=Listener(on_publication_matched=lambda _w, status: (
                            matched.set() if status.current_count > 0 else None)))
    states = DataReader(participant, topic("joint_states", "sensor_msgs/msg/JointState"), qos=default,
                        listener=Listener(on_data_available=lambda reader: [
                            say(joint_states=msg.serialize().hex()) for msg in reader.take(N=100)]))
    bumps = DataReader(participant, topic("detect_bump", "sensor_msgs/msg/Range"), qos=sensor_data,
                       listener=Listener(on_data_available=lambda reader: [
                           say(bump=msg.serialize().hex()) for msg in reader.take(N=100)]))
    refused = DataReader(participant, topic("detect_bump", "sensor_msgs/msg/Range"), qos=default,
                         listener=Listener(on_requested_incompatible_qos=lambda _r, status: say(
                             incompatible=status.last_policy_id, count=status.total_count)))
    discovery = DataReader(participant, topic("ros_discovery_info", "rmw_dds_common/msg/ParticipantEntitiesInfo"),
                           qos=latched, listener=Listener(on_data_available=lambda reader: [
                               say(discovery=msg.serialize().hex()) for msg in reader.take(N=100)
                               if any(node_info.node_name == node for node_info in msg.node_entities_info_seq)]))
    errors = DataReader(participant, topic(f"{node}/errors", "std_msgs/msg/String"), qos=default,
                        listener=Listener(on_data_available=lambda reader: [
                            say(error=msg.data) for msg in reader.take(N=100)]))
    if not matched.wait(30):
        say(unmatched=True)
        return
    say(matched=True)
    for line in sys.stdin:
        if node == "arm":
            given = json.loads(line)
            message = joints(header=header(stamp=stamp(sec=0, nanosec=0), frame_id=""), name=given["name"],
                             position=given.get("position", []), velocity=[], effort=[])
        else:
            linear, angular = map(float, line.split())
            message = twist(linear=vector(x=linear, y=0.0, z=0.0), angular=vector(x=0.0, y=0.0, z=angular))
        start = time.monotonic()
        writer.write(message)
        say(sent=start)
    del states, bumps, refused, discovery, errors


if __name__ == "__main__":
    main()
