"""The ROS 2 transport's run-time code, as the node carries it: Cyclone DDS spoken the way a ROS 2
node speaks it (rmw_cyclonedds), without a ROS 2 installation. Text, not imported by rdisc: rdisc
never imports cyclonedds; the node does, and says so when it is missing.

What makes DDS traffic ROS 2 traffic: topic `rt/<name>` (`/ns/name` without its first slash after
`rt/`), type `pkg::msg::dds_::Name_`, CDR (XCDR1) encoding, ROS 2's QoS profiles, participant
user data `enclave=/;`, and the node announced on `ros_discovery_info` (rmw_dds_common's
ParticipantEntitiesInfo: the participant's gid, the node's name and namespace, and the gids of
its readers and writers), which `ros2 node list` and `ros2 topic info` read.
"""

HELPERS = '''\
# ---- the ROS 2 bridge (rdisc emit-ros2): DDS as ROS 2 speaks it, through Cyclone DDS -------------


def _ros2_check_installed() -> None:
    """Refuse to start, saying what is missing (exit status 2, no traceback), unless this python
    has Cyclone DDS's binding (`pip install cyclonedds`): the node's only dependency past the
    driver's."""
    import importlib.util

    if importlib.util.find_spec("cyclonedds") is None:
        raise _ros_refuse([f"Cyclone DDS is not here: {sys.executable} cannot import cyclonedds; pip install "
                           + "cyclonedds (a ROS 2 installation is not needed)"])


def _ros2_struct(name: str, members: tuple[tuple[str, Any, Any], ...]) -> Any:
    """The ROS 2 message `name` (`pkg/Type`) as a Cyclone DDS type: a dataclass of its `members`
    (name, DDS type, default: a value, or what makes one, as a list or a message is made anew for
    each message), named as rosidl's IDL names it, `pkg::msg::dds_::Type_`."""
    import types

    from cyclonedds.idl import IdlStruct

    package, _, message = name.partition("/")

    def body(namespace: dict[str, Any]) -> None:
        for member, kind, default in members:
            namespace["__annotations__"][member] = kind
            namespace[member] = field(default_factory=default) if callable(default) else default

    made = types.new_class(message, (IdlStruct,), {"typename": f"{package}::msg::dds_::{message}_"}, body)
    return dataclass(made)


def _ros2_time(nanoseconds: int, time_type: Any) -> Any:
    """A builtin_interfaces/Time of `nanoseconds` since the epoch."""
    return time_type(sec=nanoseconds // 1_000_000_000, nanosec=nanoseconds % 1_000_000_000)


_ROS2_OWN = ("port", "timeout", "trace", "publish_description", "joint_states_rate", "sim")  # the rest: settings


def _ros2_command_line(argv: list[str]) -> tuple[list[str], dict[str, str], dict[str, str]]:
    """A ROS 2 node's command line, `--ros-args -p NAME:=VALUE -r FROM:=TO ...`: the driver's options
    its parameters stand for (`port:=P` is `--port P`, `port_CONN:=P` `--port CONN=P`,
    `timeout:=S` `--timeout S`, `trace:=true` `--trace`, any other not the node's own `--set
    NAME=VALUE`), the node's own parameters (_ROS2_OWN), and the remappings; a word it does not take is a
    ValueError saying which."""
    words: list[str] = []
    parameters: dict[str, str] = {}
    remaps: dict[str, str] = {}
    ros_args = False
    pending = iter(argv)
    for word in pending:
        if word == "--ros-args":
            ros_args = True
            continue
        if word == "--" and ros_args:
            ros_args = False
            continue
        if not ros_args:
            raise ValueError(f"`{word}` is no option of this node: give --ros-args -p NAME:=VALUE (port, "
                             f"{', '.join(_ROS2_OWN[1:])} or a setting) and -r FROM:=TO")
        if word not in ("-p", "--param", "-r", "--remap"):
            raise ValueError(f"--ros-args {word}: this node takes -p NAME:=VALUE and -r FROM:=TO")
        pair = next(pending, "")
        name, sep, value = pair.partition(":=")
        if not sep or not name:
            raise ValueError(f"{word} `{pair}` is not NAME:=VALUE")
        if word in ("-r", "--remap"):
            remaps[name] = value
        elif name in parameters:
            raise ValueError(f"-p {name} given twice")
        else:
            parameters[name] = value
    for name, value in parameters.items():
        if name == "port":
            words += ["--port", value]
        elif name.startswith("port_"):
            words += ["--port", f"{name.removeprefix('port_')}={value}"]
        elif name == "timeout":
            words += ["--timeout", value]
        elif name == "trace":
            words += ["--trace"] if _ros2_flag(name, value) else []
        elif name not in _ROS2_OWN:
            words += ["--set", f"{name}={value}"]
    return words, {name: value for name, value in parameters.items() if name in _ROS2_OWN}, remaps


def _ros2_flag(name: str, value: str) -> bool:
    """A boolean parameter, as ROS 2 reads one (YAML's true and false)."""
    if value in ("true", "True", "false", "False"):
        return value in ("true", "True")
    raise ValueError(f"-p {name}:={value}: give true or false")


_ROS2_POLICIES = {2: "durability", 4: "deadline", 8: "liveliness", 11: "reliability", 25: "data representation"}


class _Ros2Node:
    """One ROS 2 node on its own DDS participant, in domain ROS_DOMAIN_ID (0 unset), with ROS 2's
    names and QoS, `messages` (`_ros2_messages()`) its types. Messages received are handled on the
    node's own thread, in order (a DDS write from Cyclone's receive thread, as an error published,
    could deadlock it); a QoS mismatch is reported on stderr and `~/errors`, never silent."""

    def __init__(self, name: str, remaps: dict[str, str], messages: Any) -> None:
        import queue

        from cyclonedds.core import Policy, Qos
        from cyclonedds.domain import DomainParticipant
        from cyclonedds.util import duration

        domain = os.environ.get("ROS_DOMAIN_ID", "0")
        if not domain.isdigit() or int(domain) > 232:
            raise _ros_refuse([f"ROS_DOMAIN_ID is {domain!r}: give a domain from 0 to 232"])
        self.name = remaps.get("__node", name)
        self.namespace = "/" + remaps.get("__ns", "/").strip("/")
        self.remaps = remaps
        self.types = messages.rmw_dds_common
        self.string = messages.std_msgs.String
        xcdr1 = Policy.DataRepresentation(use_cdrv0_representation=True)
        reliable = Policy.Reliability.Reliable(duration(milliseconds=100))
        # ROS 2's profiles: the default (subscriptions, errors, joint states) and the sensor-data
        # profile (outputs, as ROS 2 drivers publish readings); transient local for latched data.
        self.default = Qos(reliable, Policy.History.KeepLast(10), Policy.Durability.Volatile, xcdr1)
        self.sensor_data = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(5),
                               Policy.Durability.Volatile, xcdr1)
        self.latched = Qos(reliable, Policy.History.KeepLast(1), Policy.Durability.TransientLocal, xcdr1)
        # Made with the signals blocked, so Cyclone's threads leave SIGINT and SIGTERM to the main thread.
        enclave = Qos(Policy.Userdata(b"enclave=/;"))
        self.participant = without_signals(lambda: DomainParticipant(int(domain), qos=enclave))
        self.readers: list[Any] = []
        self.writers: list[Any] = []
        self.errors: Any = None
        self.received: queue.SimpleQueue[tuple[Callable[[Any], None], Any] | None] = queue.SimpleQueue()
        self.handler = threading.Thread(target=self.handle, name="ros2 subscriptions", daemon=True)
        without_signals(self.handler.start)
        self.publisher("ros_discovery_info", self.types.ParticipantEntitiesInfo, self.latched)  # writers[0]
        self.errors = self.publisher("~/errors", self.string, self.default)

    def topic(self, name: str) -> str:
        """The DDS topic of a ROS 2 topic name (`~/x` the node's own, `x` in its namespace), remapped."""
        name = self.remaps.get(name, name)
        if name.startswith("~/"):
            name = f"{self.namespace.rstrip('/')}/{self.name}/{name[2:]}"
        elif not name.startswith("/"):
            name = f"{self.namespace.rstrip('/')}/{name}"
        return "rt" + name

    def listener(self, topic: str, received: Callable[[Any], None] | None = None) -> Any:
        """Cyclone's callbacks for a reader or writer of `topic` (called as it is being made, too):
        QoS mismatches reported, messages queued for `received`."""
        from cyclonedds.core import Listener

        def mismatch(status: Any, what: str) -> None:
            policy = _ROS2_POLICIES.get(status.last_policy_id, f"QoS policy {status.last_policy_id}")
            text = f"{topic.removeprefix('rt')}: {what} ({policy}): no messages flow between them"
            threading.Thread(target=self.report, args=(text,), daemon=True).start()  # not on Cyclone's thread

        def available(reader: Any) -> None:
            assert received is not None
            # None: Cyclone calls while the reader is being made, before Python knows it (what came
            # then is taken once it is made), or while it goes.
            if reader is not None:
                self.take(reader, received)

        return Listener(  # type: ignore[no-untyped-call]
            on_offered_incompatible_qos=lambda _writer, status: mismatch(
                status, "a subscription asks for what this publisher does not offer"),
            on_requested_incompatible_qos=lambda _reader, status: mismatch(
                status, "a publisher does not offer what this subscription asks for"),
            **({"on_data_available": available} if received is not None else {}))

    def report(self, problem: str) -> None:
        """A problem of the node's, on stderr and on `~/errors`."""
        print(f"{os.path.basename(sys.argv[0])}: {problem}", file=sys.stderr, flush=True)
        if self.errors is not None:  # None only while the node is being made
            self.errors.write(self.string(data=problem))

    def handle(self) -> None:
        """Each message received, handled in order until `close`."""
        while (item := self.received.get()) is not None:
            received, msg = item
            received(msg)

    def take(self, reader: Any, received: Callable[[Any], None]) -> None:
        """Queue the messages `reader` holds for `received` (Cyclone's listener thread, or the one
        that made the reader)."""
        from cyclonedds.internal import InvalidSample

        for msg in reader.take(N=100):
            if not isinstance(msg, InvalidSample):  # a writer left or disposed: no message, no data
                self.received.put((received, msg))

    def publisher(self, name: str, message: Any, qos: Any) -> Any:
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        topic = self.topic(name)
        writer = DataWriter(self.participant, Topic(self.participant, topic, message), qos=qos,
                            listener=self.listener(topic))
        self.writers.append(writer)
        self.announce()
        return writer

    def subscription(self, name: str, message: Any, received: Callable[[Any], None]) -> Any:
        """A reader of `name` with the default profile, `received` called with each message."""
        from cyclonedds.sub import DataReader
        from cyclonedds.topic import Topic

        topic = self.topic(name)
        reader = DataReader(self.participant, Topic(self.participant, topic, message), qos=self.default,
                            listener=self.listener(topic, received))
        self.take(reader, received)  # what came while it was being made, which its listener could not take
        self.readers.append(reader)
        self.announce()
        return reader

    def gid(self, entity: Any) -> Any:
        """An entity's gid as rmw_cyclonedds makes it: its DDS GUID, zero-padded to the Gid's size."""
        size = len(self.types.Gid().data)
        return self.types.Gid(data=list(entity.guid.bytes.ljust(size, b"\\0")[:size]))

    def announce(self, *, leaving: bool = False) -> None:
        """The participant on `ros_discovery_info`: this node with its readers and writers (the
        announcing writer's own left out, as rmw does), or no node when `leaving`."""
        nodes = [] if leaving else [self.types.NodeEntitiesInfo(
            node_namespace=self.namespace, node_name=self.name,
            reader_gid_seq=[self.gid(reader) for reader in self.readers],
            writer_gid_seq=[self.gid(writer) for writer in self.writers[1:]])]
        self.writers[0].write(self.types.ParticipantEntitiesInfo(gid=self.gid(self.participant),
                                                                node_entities_info_seq=nodes))

    def close(self) -> None:
        """Leave the graph: no more messages handled, and the node announced gone."""
        self.received.put(None)
        self.handler.join(timeout=5)
        self.announce(leaving=True)'''
