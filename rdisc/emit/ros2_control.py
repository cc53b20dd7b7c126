"""The `<ros2_control>` block of `rdisc emit-urdf --ros2-control`: how ros2_control's controller
manager reaches the body's joints, so that the standard controllers (joint_trajectory_controller,
diff_drive_controller) drive an rdisc robot.

The hardware is ros-controls' topic-based system (`joint_state_topic_hardware_interface`,
formerly PickNik's `topic_based_ros2_control`): it publishes joint commands as a
`sensor_msgs/JointState` and reads joint states from one, which are exactly the ROS 2 node's
`joint_command` and `joint_states` topics (`rdisc emit-ros2`); the node converts each joint's
value through its transmission, so ros2_control sees joint space and needs no transmission of
its own. `mock` writes `mock_components/GenericSystem` instead, for running the controllers
without the robot.

Each joint a transmission binds gets a command interface per quantity its transmissions command
(`position`, `velocity`, `effort`), bounded by the range the checker held against the device
(E606: its `limit`, ±`velocity`, ±`effort`) as `min` and `max`, and a state interface per quantity
they measure: what the node publishes on `joint_states`. A mock mirrors its commands, so it also
states what is commanded, and integrates a velocity or effort into a position.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from rdisc.emit.body_xml import BodyError, child, comment, number
from rdisc.semantics import model as m
from rdisc.semantics.body_values import joint_range

TOPIC_PLUGIN = "joint_state_topic_hardware_interface/JointStateTopicSystem"
MOCK_PLUGIN = "mock_components/GenericSystem"
COMMANDS_TOPIC = "/joint_command"  # the ROS 2 node's, as `rdisc emit-ros2` names them
STATES_TOPIC = "/joint_states"


def ros2_control(robot: ET.Element, model: m.Model, hardware: str) -> None:
    """Append the `<ros2_control>` element for `hardware` ("topic" or "mock") to `robot`; a
    BodyError when no transmission binds a joint (nothing for ros2_control to drive)."""
    joints = _interfaces(model)
    if not joints:
        raise BodyError(f"robot `{model.robot.name}` has no transmission: ros2_control has no joint to drive "
                        "(bind one with `transmission NAME: JOINT { command ... }`)")
    block = ET.SubElement(robot, "ros2_control", name=model.robot.name, type="system")
    if hardware == "mock":
        comment(block, "The joints without the robot: each state follows its command.")
        part = child(block, "hardware")
        child(part, "plugin", MOCK_PLUGIN)
        child(part, "param", "true", name="calculate_dynamics")
    else:
        comment(block, f"The joints through the rdisc ROS 2 node (rdisc emit-ros2): commands on {COMMANDS_TOPIC}, "
                       f"states on {STATES_TOPIC}, each converted by its transmission there.")
        part = child(block, "hardware")
        child(part, "plugin", TOPIC_PLUGIN)
        child(part, "param", COMMANDS_TOPIC, name="joint_commands_topic")
        child(part, "param", STATES_TOPIC, name="joint_states_topic")
    for name, (commanded, measured) in joints.items():
        joint = model.joints[name]
        element = child(block, "joint", name=name)
        for quantity in commanded:
            interface = child(element, "command_interface", name=quantity.value)
            low, high, _ = joint_range(joint, quantity)
            if low is not None and high is not None:
                child(interface, "param", number(low), name="min")
                child(interface, "param", number(high), name="max")
        stated = measured if hardware == "topic" else [q for q in m.Quantity if q in commanded or q in measured]
        for quantity in stated:
            child(element, "state_interface", name=quantity.value)


def _interfaces(model: m.Model) -> dict[str, tuple[list[m.Quantity], list[m.Quantity]]]:
    """Each joint a transmission binds, in the body's order: the quantities commanded and those
    measured, each in the order position, velocity, effort."""
    commanded: dict[str, set[m.Quantity]] = {}
    measured: dict[str, set[m.Quantity]] = {}
    for transmission in model.transmissions.values():
        commanded.setdefault(transmission.joint, set()).update(b.quantity for b in transmission.commands)
        measured.setdefault(transmission.joint, set()).update(b.quantity for b in transmission.measures)
    return {name: ([q for q in m.Quantity if q in commanded[name]], [q for q in m.Quantity if q in measured[name]])
            for name in model.joints if name in commanded}
