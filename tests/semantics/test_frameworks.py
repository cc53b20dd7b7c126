"""What each adapter is in each framework (thesis §7.2.5), read into the Model as
`Adapter.frameworks`: each column of stdlib/frameworks.txt makes it of the adapter's `ros`
annotations, standard adapters included, naming only ROS types and paths rdisc can speak, and it
drives every output. A test-local copy of the table with a row for one adapter, one path or schema
otherwise, changes the ROS 2 node, the recording's (and the live Foxglove session's) schema and
`rdisc adapters`, and nothing else; a fifth column is one more framework everywhere."""

from __future__ import annotations

import json

import pytest

from rdisc.compile import compile_path, compile_text
from rdisc.emit.ros import to_ros
from rdisc.emit.ros2 import to_ros2
from rdisc.engine.recording import session_topics
from rdisc.lower import lower
from rdisc.lowering import messages
from rdisc.resources import frameworks_file
from rdisc.semantics import frameworks, ros
from rdisc.semantics import model as m
from tests.conftest import REPO, run_rdisc

TABLE = open(frameworks_file(), encoding="utf-8").read()  # noqa: SIM115 - read once
CREATE = str(REPO / "examples" / "create.rdis")


def _model(path: str = CREATE) -> m.Model:
    compilation = compile_path(path)
    assert compilation.model is not None and not compilation.diagnostics.has_errors()
    return compilation.model


def _use(monkeypatch: pytest.MonkeyPatch, text: str) -> None:
    """Check descriptions with `text` as the table rdisc ships."""
    monkeypatch.setattr(frameworks, "_standard", [frameworks.parse(text)])


def _edit(old: str, new: str) -> str:
    assert TABLE.count(old) == 1, old
    return TABLE.replace(old, new)


def _row(*lines: str) -> str:
    """The table with a row for one adapter (and its fields') below the head."""
    return TABLE + "\n" + "".join(line + "\n" for line in lines)


def test_each_standard_adapter_is_what_its_annotations_make_it_in_each_column_and_speakable() -> None:
    model = _model()
    table = frameworks.standard()
    standard = {a.name: a for a in model.adapters.values() if a.standard}
    assert table.adapters == {}  # no framework names a standard adapter otherwise than its shorthand
    assert list(standard) == ["DifferentialSpeed", "Range", "Contact", "Battery", "Odometry", "Pose2D",
                              "JointPosition", "JointState", "Temperature"]
    assert [f[:4] for f in table.frameworks] == [("ros1", "ROS 1", None, None), ("ros2", "ROS 2", None, None),
                                                 ("foxglove", "Foxglove", "ros2msg", "cdr")]
    for adapter in standard.values():
        assert [each.framework for each in adapter.frameworks] == ["ros1", "ros2", "foxglove"]
        ros1, ros2, foxglove = adapter.frameworks
        assert ros.message_problem(ros1.type) is None and ros1.type in messages.DEFINITIONS
        assert ros2.type == foxglove.type == messages.ros2_name(ros1.type)
        for mapping in adapter.frameworks:
            assert all(path is not None and ros.path_problem(path) is None for path in mapping.paths)
        assert (adapter.ros, tuple(f.ros for f in adapter.fields)) == (ros1.type, ros1.paths)  # what reads `ros`


def test_a_description_s_ros_shorthand_is_each_column_s_shorthand() -> None:
    compilation = compile_text("d.rdis", 'robot d { author "t" }\nadapter Turning ros "sensor_msgs/Imu" {\n'
                               '    rate: float ros "angular_velocity.z"\n    heading: float\n}\n'
                               "adapter Opening {\n    width: float\n}\n")
    assert compilation.model is not None
    turning, opening = compilation.model.adapters["Turning"], compilation.model.adapters["Opening"]
    assert turning.frameworks == (
        m.FrameworkMapping("ros1", "ROS 1", "sensor_msgs/Imu", ("angular_velocity.z", None)),
        m.FrameworkMapping("ros2", "ROS 2", "sensor_msgs/msg/Imu", ("angular_velocity.z", None)),
        m.FrameworkMapping("foxglove", "Foxglove", "sensor_msgs/msg/Imu", ("angular_velocity.z", None),
                           "ros2msg", "cdr"))
    assert opening.frameworks == () and opening.mapping("ros2") is None


def test_a_changed_ros2_path_changes_the_ros2_node_only(monkeypatch: pytest.MonkeyPatch) -> None:
    ros1, ros2 = to_ros(_model(), "create.rdis"), to_ros2(_model(), "create.rdis")
    recorded = lower(_model()).device.messages
    _use(monkeypatch, _row("DifferentialSpeed  geometry_msgs/Twist  geometry_msgs/msg/Twist  geometry_msgs/msg/Twist",
                           "    linear         linear.x             linear.x                 linear.x",
                           "    angular        angular.z            angular.y                angular.z"))
    changed = to_ros2(_model(), "create.rdis")
    assert changed == ros2.replace('return {"linear": msg.linear.x, "angular": msg.angular.z}',
                                   'return {"linear": msg.linear.x, "angular": msg.angular.y}')
    assert changed != ros2
    assert to_ros(_model(), "create.rdis") == ros1
    assert lower(_model()).device.messages == recorded


def test_a_changed_foxglove_schema_and_path_change_the_recording_and_the_live_session_only(
        monkeypatch: pytest.MonkeyPatch) -> None:
    ros2 = to_ros2(_model(), "create.rdis")
    _use(monkeypatch, _row("Range              sensor_msgs/Range    sensor_msgs/msg/Range    sensor_msgs/msg/Temperature",
                           "    distance       range                range                    temperature"))
    device = lower(_model()).device
    assert device.messages["Range"].type == "sensor_msgs/msg/Temperature"
    assert device.messages["Range"].paths == ("temperature",)
    topic = next(t for t in session_topics(device) if t.name == "/detect_bump")
    assert (topic.type, topic.schema) == ("sensor_msgs/msg/Temperature", messages.definition("sensor_msgs/Temperature"))
    node = to_ros2(_model(), "create.rdis")  # its driver records so, too; its ROS 2 messages are as they were
    assert '"sensor_msgs/msg/Temperature"' in node and '"sensor_msgs/msg/Temperature"' not in ros2
    bridge = "def _ros2_messages() -> Any:"
    assert node[node.index(bridge):] == ros2[ros2.index(bridge):]


FIFTH = _edit("framework  ros1                      ros2                          foxglove\n"
              "title      ROS_1                     ROS_2                         Foxglove\n"
              "schema     -                         -                             ros2msg\n"
              "message    -                         -                             cdr\n"
              "shorthand  {package}/{message}       {package}/msg/{message}       {package}/msg/{message}\n",
              "framework  ros1                      ros2                          foxglove                 viewer\n"
              "title      ROS_1                     ROS_2                         Foxglove                 Viewer\n"
              "schema     -                         -                             ros2msg                  json\n"
              "message    -                         -                             cdr                      json\n"
              "shorthand  {package}/{message}       {package}/msg/{message}       {package}/msg/{message}  -\n"
              ) + ("\nContact  std_msgs/Bool  std_msgs/msg/Bool  std_msgs/msg/Bool  viewer.Contact\n"
                   "    contact  data  data  data  pressed\n")


def test_one_more_column_is_one_more_framework_in_rdisc_adapters(monkeypatch: pytest.MonkeyPatch) -> None:
    _use(monkeypatch, FIFTH)  # every other adapter is nothing in the viewer: its shorthand there is `-`
    result = run_rdisc("adapters", "Contact", "Range")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == """\
Contact
  A binary contact: a bumper, a cliff or wheel-drop switch, a limit switch.
  ROS 1 std_msgs/Bool   ROS 2 std_msgs/msg/Bool   Foxglove std_msgs/msg/Bool (ros2msg, CDR)   Viewer viewer.Contact \
(json, JSON)
  contact  bool  -  ROS 1 data, ROS 2 data, Foxglove data, Viewer pressed

Range
  The distance to the nearest obstacle seen by a one-dimensional range sensor: a sonar, an infrared sensor, a \
laser beam, or a bumper read as "touching" (0 m) or "clear" (thesis section 4.11.1). The other members of \
sensor_msgs/Range (radiation type, field of view, limits) are not part of the adapter.
  ROS 1 sensor_msgs/Range   ROS 2 sensor_msgs/msg/Range   Foxglove sensor_msgs/msg/Range (ros2msg, CDR)
  distance  float  m  range
"""
    contact, range_ = json.loads(run_rdisc("adapters", "Contact", "Range", "--format", "json").stdout)
    assert contact["viewer"] == {"schema": "viewer.Contact", "schemaEncoding": "json", "messageEncoding": "json"}
    assert contact["fields"][0]["paths"] == {"ros1": "data", "ros2": "data", "foxglove": "data", "viewer": "pressed"}
    assert range_["viewer"] is None and "paths" not in range_["fields"][0]


@pytest.mark.parametrize(("text", "message"), [
    ("framework a\n", "t.txt: does not start with the rows framework, title, schema, message, shorthand"),
    ("framework a b\ntitle A B\nschema - -\nmessage - -\nshorthand - -\nX t u v\n", "t.txt:6: 3 columns, the frameworks 2"),
    ("framework a\ntitle A\nschema -\nmessage -\nshorthand -\n  f p\n", "t.txt:6: field f under no adapter"),
    ("framework a\ntitle A\nschema -\nmessage -\nshorthand -\nX t\n  f p\n  f q\n", "t.txt:8: field f has two rows"),
    ("framework a\ntitle A\nschema -\nmessage -\nshorthand -\nX t\n# a comment\nX u\n", "t.txt:8: adapter X has two rows"),
])
def test_a_table_that_does_not_say_what_each_adapter_is_is_refused_with_its_line(text: str, message: str) -> None:
    with pytest.raises(frameworks.TableError) as raised:
        frameworks.parse(text, "t.txt")
    assert str(raised.value) == message


def test_a_table_whose_ros_1_column_is_not_what_adapters_rdis_says_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    """The standard adapters' `ros` annotations are the shorthand a description writes: the table
    may not say otherwise in the column that shorthand is (ROS 1's)."""
    _use(monkeypatch, _row("Range              sensor_msgs/Range    sensor_msgs/msg/Range    sensor_msgs/msg/Range",
                           "    distance       min_range            range                    range"))
    with pytest.raises(frameworks.TableError) as raised:
        compile_text("d.rdis", 'robot d { author "t" }\n')
    assert str(raised.value) == "frameworks.txt: adapter Range is not what its `ros` annotations in adapters.rdis say"


def test_a_row_that_says_what_the_shorthand_says_is_refused_as_a_second_writing(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """A standard adapter's types and paths are written once, as its `ros` annotations: the table
    may not write them again."""
    _use(monkeypatch, _row("Range              sensor_msgs/Range    sensor_msgs/msg/Range    sensor_msgs/msg/Range",
                           "    distance       range                range                    range"))
    with pytest.raises(frameworks.TableError) as raised:
        compile_text("d.rdis", 'robot d { author "t" }\n')
    assert str(raised.value) == ("frameworks.txt: the rows of adapter Range say what its `ros` shorthand does: "
                                 "only a framework that names it otherwise needs a row")


def test_a_row_without_one_for_each_field_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    _use(monkeypatch, _row("Contact  std_msgs/Bool  std_msgs/msg/Bool  std_msgs/msg/Int8",
                           "    pressed  data  data  data"))
    with pytest.raises(frameworks.TableError) as raised:
        compile_text("d.rdis", 'robot d { author "t" }\n')
    assert str(raised.value) == "frameworks.txt: the rows of adapter Contact are not one for each of its fields"
