"""A ROS 2 reader of any topics, for the ROS 2 node's tests: Cyclone DDS with types built from
rosbags' ROS 2 message definitions (participant.py's `Types`, not rdisc's).

    python reader.py jazzy odom=nav_msgs/msg/Odometry imu=sensor_msgs/msg/Imu

in the node's ROS_DOMAIN_ID and CYCLONEDDS_URI. A best-effort reader of each topic (it matches
a reliable writer and a sensor-data one alike) prints each message as one JSON line, `{"topic":
NAME, "cdr": HEX}`, for rosbags to decode; robot_description's reader is reliable and transient
local, as the node's latched writer, so it has the message however late it matches. It ends at
the end of stdin.
"""

from __future__ import annotations

import os
import sys

from cyclonedds.core import Listener, Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration
from participant import Types, say


def main() -> None:
    distro, *wanted = sys.argv[1:]
    types = Types(distro)
    qos = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(10), Policy.Durability.Volatile,
              Policy.DataRepresentation(use_cdrv0_representation=True))
    participant = DomainParticipant(int(os.environ.get("ROS_DOMAIN_ID", "0")))
    latched = Qos(Policy.Reliability.Reliable(duration(seconds=1)), Policy.History.KeepLast(1),
                  Policy.Durability.TransientLocal, Policy.DataRepresentation(use_cdrv0_representation=True))
    readers = []
    for given in wanted:
        name, _, message = given.partition("=")

        def said(reader: DataReader, name: str = name) -> None:
            for sample in reader.take(N=100):
                say(topic=name, cdr=sample.serialize().hex())
        readers.append(DataReader(participant, Topic(participant, f"rt/{name}", types[message]),
                                  qos=latched if name == "robot_description" else qos,
                                  listener=Listener(on_data_available=said)))
    say(ready=True)
    for _ in sys.stdin:
        pass
    del readers


if __name__ == "__main__":
    main()
