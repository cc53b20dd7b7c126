"""Print each message on `joint_states` (`listen.py joint_states`), `/tf` (`listen.py tf`),
`odom` (`listen.py odom`), `imu` (`listen.py imu`) or a sensor_msgs/Range topic (`listen.py range TOPIC`) as one JSON
line, for the body's tests. Run by the system python3.

A JointState is its names, position, velocity and effort (NaN, which JSON lacks, as null)
and its stamp in seconds; a TFMessage is one line per transform: parent and child frame,
translation and rotation (x, y, z, w); an Odometry is its position's x and y, its frames and
stamp (ns) and its pose's and twist's covariances; an Imu is its three covariances; a Range is its
range, its header's stamp (ns) and frame id, and when it was received (ns, the host's clock). It ends by itself after a minute, so a test reading it
until some message never waits longer."""

import json
import math
import sys
import time

import rospy
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Imu, JointState, Range
from tf2_msgs.msg import TFMessage


def shown(values: list[float]) -> list[float | None]:
    return [None if math.isnan(v) else v for v in values]


def joint_state(msg: JointState) -> None:
    print(json.dumps({"name": list(msg.name), "position": shown(msg.position), "velocity": shown(msg.velocity),
                      "effort": shown(msg.effort), "stamp": msg.header.stamp.to_sec()}), flush=True)


def transforms(msg: TFMessage) -> None:
    for t in msg.transforms:
        move, turn = t.transform.translation, t.transform.rotation
        print(json.dumps({"parent": t.header.frame_id, "child": t.child_frame_id,
                          "translation": [move.x, move.y, move.z], "rotation": [turn.x, turn.y, turn.z, turn.w]}),
              flush=True)


def odometry(msg: Odometry) -> None:
    where = msg.pose.pose.position
    print(json.dumps({"x": where.x, "y": where.y, "frame_id": msg.header.frame_id, "child_frame_id": msg.child_frame_id,
                      "stamp": msg.header.stamp.to_nsec(), "pose_covariance": list(msg.pose.covariance),
                      "twist_covariance": list(msg.twist.covariance)}), flush=True)


def imu(msg: Imu) -> None:
    print(json.dumps({"yaw_rate": msg.angular_velocity.z, "orientation": list(msg.orientation_covariance),
                      "angular_velocity": list(msg.angular_velocity_covariance),
                      "linear_acceleration": list(msg.linear_acceleration_covariance)}), flush=True)


def ranged(msg: Range) -> None:
    received = time.time_ns()
    print(json.dumps({"range": msg.range, "stamp": msg.header.stamp.to_nsec(), "frame_id": msg.header.frame_id,
                      "received": received}), flush=True)


rospy.init_node("rdisc_listen", anonymous=True)
rospy.Timer(rospy.Duration(60), lambda _event: rospy.signal_shutdown("a minute has passed"), oneshot=True)
if sys.argv[1] == "tf":
    rospy.Subscriber("/tf", TFMessage, transforms, queue_size=100)
elif sys.argv[1] == "range":
    rospy.Subscriber(sys.argv[2], Range, ranged, queue_size=100)
elif sys.argv[1] == "imu":
    rospy.Subscriber("imu", Imu, imu, queue_size=100)
elif sys.argv[1] == "odom":
    rospy.Subscriber("odom", Odometry, odometry, queue_size=100)
else:
    rospy.Subscriber("joint_states", JointState, joint_state, queue_size=100)
rospy.spin()
