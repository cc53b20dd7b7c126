"""The ROS 2 node's message types, held against an independent oracle: for each standard message the
adapters use (and those the node itself speaks: String, JointState, the discovery messages), for
ROS 2 Humble and Jazzy, the DDS types `rdisc emit-ros2 --distro D` writes serialise the same values
to the same CDR bytes as rosbags' typestore of that distribution (its own definitions and encoder).
The values are made from rosbags' field definitions: every member given, a different value each."""

from __future__ import annotations

import importlib.util
import sys
from typing import Any

import pytest
from conftest import run_rdisc

from rdisc.compile import compile_text

pytest.importorskip("cyclonedds")
np = pytest.importorskip("numpy")
typesys = pytest.importorskip("rosbags.typesys")
from rosbags.typesys.store import Nodetype

STORES = {"humble": typesys.Stores.ROS2_HUMBLE, "jazzy": typesys.Stores.ROS2_JAZZY}

# Every standard adapter, as an output (and one as an input): the node speaks each one's message; and an
# Imu, which no standard adapter is, for the covariances a description's own adapter may carry.
EVERY_ADAPTER = """\
robot every_adapter { author "tests" }
state v: float = 0.5
connection c: serial { baud 9600 }
primitive poll() on c pack "B" (1)
interface tick() periodic triggers twist, range, contact, battery, odometry, pose, joint, joints, temperature, imu {
    poll()
}
interface go(a: float, b: float) { poll() }
output twist: DifferentialSpeed { linear = v  angular = v }
output range: Range { distance = v }
output contact: Contact { contact = v > 0.0 }
output battery: Battery { voltage = v  current = v  charge = v  capacity = v  percentage = v }
output odometry: Odometry { x = v  y = v  theta = v  linear = v  angular = v }
output pose: Pose2D { x = v  y = v  theta = v }
output joint: JointPosition { name = "j"  position = v }
output joints: JointState { name = ["a"]  position = [v] }
output temperature: Temperature { temperature = v  variance = v }
adapter Turning ros "sensor_msgs/Imu" { rate: float unit "rad/s" ros "angular_velocity.z" }
output imu: Turning { rate = v }
input drive: DifferentialSpeed -> go(linear, angular)
"""

NUMPY = {"bool": np.bool_, "byte": np.uint8, "char": np.uint8, "float32": np.float32, "float64": np.float64,
         "int8": np.int8, "uint8": np.uint8, "int16": np.int16, "uint16": np.uint16, "int32": np.int32,
         "uint32": np.uint32, "int64": np.int64, "uint64": np.uint64}


@pytest.fixture(scope="module", params=["humble", "jazzy"])
def distro(request: pytest.FixtureRequest) -> str:
    return str(request.param)


@pytest.fixture(scope="module")
def node_messages(distro: str, tmp_path_factory: pytest.TempPathFactory) -> Any:
    """The `_ros2_messages()` of the node `rdisc emit-ros2 --distro D` writes for EVERY_ADAPTER."""
    folder = tmp_path_factory.mktemp(f"node_{distro}")
    source = folder / "every_adapter.rdis"
    source.write_text(EVERY_ADAPTER, encoding="utf-8")
    path = folder / "every_adapter_node.py"
    done = run_rdisc("emit-ros2", source, "-o", path, "--distro", distro)
    assert done.returncode == 0, done.stderr
    spec = importlib.util.spec_from_file_location(f"every_adapter_node_{distro}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up by name
    spec.loader.exec_module(module)
    return module._ros2_messages()


def _standard_messages() -> list[str]:
    """The messages of every standard adapter (EVERY_ADAPTER's outputs use each), and those the node speaks."""
    compilation = compile_text("every_adapter.rdis", EVERY_ADAPTER)
    assert compilation.model is not None
    model = compilation.model
    assert {o.adapter for o in model.outputs.values()} == set(model.adapters)
    names = {a.ros for a in model.adapters.values() if a.ros is not None}
    return sorted(names | {"std_msgs/String", "std_msgs/Header", "builtin_interfaces/Time",
                           "rmw_dds_common/ParticipantEntitiesInfo"})


class Sample:
    """A value of each member of a message, all different, as rosbags takes them and as plain data."""

    def __init__(self, store: Any) -> None:
        self.store = store
        self.count = 0

    def next(self) -> int:
        self.count += 1
        return self.count

    def message(self, name: str) -> tuple[Any, dict[str, Any]]:
        """(rosbags' message, the same values as a dict of members)."""
        _, members = self.store.fielddefs[name]
        ours, plain = {}, {}
        for member, kind in members:
            ours[member], plain[member] = self.value(kind)
        return self.store.types[name](**ours), plain

    def primitive(self, name: str) -> Any:
        k = self.next()
        if name == "string":
            return f"frame {k}"
        if name == "bool":
            return k % 2 == 1
        if name.startswith("float"):
            return k + 0.5  # exact in float32 too
        return k % 100

    def value(self, kind: Any) -> tuple[Any, Any]:
        node, detail = kind
        if node == Nodetype.BASE:
            value = self.primitive(detail[0])
            return value, value
        if node == Nodetype.NAME:
            return self.message(detail)
        inner, size = detail
        items = [self.value(inner) for _ in range(size if node == Nodetype.ARRAY else 2)]
        if inner[0] == Nodetype.BASE and inner[1][0] in NUMPY:
            return np.array([a for a, _ in items], dtype=NUMPY[inner[1][0]]), [b for _, b in items]
        return [a for a, _ in items], [b for _, b in items]


def _node_value(messages: Any, store: Any, name: str, plain: dict[str, Any]) -> Any:
    """The node's message `name` (`pkg/msg/Type`) with `plain`'s values, nested messages made too."""
    package, _, message = name.split("/")
    cls = getattr(getattr(messages, package), message)
    values = {}
    for member, kind in store.fielddefs[name][1]:
        value = plain[member]
        node, detail = kind
        if node == Nodetype.NAME:
            value = _node_value(messages, store, detail, value)
        elif node != Nodetype.BASE and detail[0][0] == Nodetype.NAME:
            value = [_node_value(messages, store, detail[0][1], item) for item in value]
        values[member] = value
    return cls(**values)


@pytest.mark.parametrize("name", _standard_messages())
def test_the_node_s_types_encode_as_rosbags_does(distro: str, node_messages: Any, name: str) -> None:
    store = typesys.get_typestore(STORES[distro])
    full = name.replace("/", "/msg/")
    theirs, plain = Sample(store).message(full)
    ours = _node_value(node_messages, store, full, plain)
    assert ours.serialize() == store.serialize_cdr(theirs, full)


def test_jazzy_s_range_has_a_variance_and_humble_s_has_none(node_messages: Any, distro: str) -> None:
    members = set(node_messages.sensor_msgs.Range.__dataclass_fields__)
    assert ("variance" in members) == (distro == "jazzy")
    assert len(node_messages.rmw_dds_common.Gid().data) == {"humble": 24, "jazzy": 16}[distro]
