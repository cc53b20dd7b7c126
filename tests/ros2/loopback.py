"""Cyclone DDS on loopback only, as CYCLONEDDS_URI: the ROS 2 tests' and benchmark's participants
find each other there by unicast (loopback has no multicast)."""

LOOPBACK = ('<CycloneDDS><Domain id="any"><General><Interfaces><NetworkInterface name="lo"/></Interfaces>'
            "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
            '<Peers><Peer address="127.0.0.1"/></Peers></Discovery></Domain></CycloneDDS>')
