"""A live session served through the Foxglove WebSocket protocol (`rdisc run --foxglove`,
`rdisc console --foxglove`): Foxglove opens a running robot as it opens a recording.

The server is a sink of the robot's `engine.Session`, the observer a recording is written
from, so it carries the same channels with the same schemas (`engine.session_topics`): each
input and output as its adapter's ROS 2 message, each state variable on `/state/NAME`, the
bytes each way, what ran, errors; every schema `ros2msg`, every message CDR, encoded by the
encoder the recording's (`mcap-ros2-support`). All channels are advertised when the server
starts; a message is encoded only while some client is subscribed to its channel. Clients
only watch: the server offers no publishing, services or parameters.

Needs the `foxglove-sdk` and `mcap-ros2-support` packages (`pip install '.[foxglove]'`),
imported here only (ImportError without).
"""

from __future__ import annotations

from typing import Any

from rdisc import engine


class FoxgloveServer:
    """A Foxglove WebSocket server on HOST:PORT (port 0: a free one, `port` says which)
    serving `session`'s channels until `stop`. RuntimeError if it cannot listen there."""

    def __init__(self, session: engine.Session, name: str, host: str, port: int) -> None:
        import foxglove  # only a live session needs these
        from mcap_ros2._dynamic import serialize_dynamic

        self._foxglove: Any = foxglove
        self._serialize: Any = serialize_dynamic
        self._context: Any = foxglove.Context()  # its own: nothing else's channels reach this server
        self._channels: dict[str, Any] = {}
        self._encoders: dict[str, Any] = {}
        for topic in session.topics.values():
            self._channel(topic)
        self._server: Any = foxglove.start_server(name=name, host=host, port=port, context=self._context)
        session.add(self.send)

    @property
    def port(self) -> int:
        """The port it listens on."""
        return int(self._server.port)

    def send(self, topic: engine.Topic, message: dict[str, Any], stamp: int) -> None:
        """One message of the session, to the clients subscribed to its channel."""
        channel = self._channels.get(topic.name) or self._channel(topic)
        if not channel.has_sinks():
            return
        encode = self._encoders.get(topic.type)
        if encode is None:
            encode = self._encoders[topic.type] = self._serialize(topic.type, topic.schema)[topic.type]
        channel.log(encode(message), log_time=stamp)

    def stop(self) -> None:
        """Close every client's connection and stop listening."""
        self._server.stop()

    def _channel(self, topic: engine.Topic) -> Any:
        schema = self._foxglove.Schema(name=topic.type, encoding="ros2msg", data=topic.schema.encode())
        channel = self._foxglove.Channel(topic.name, schema=schema, message_encoding="cdr", context=self._context)
        self._channels[topic.name] = channel
        return channel
