"""Print "got T" (time.monotonic()) for each Twist on `set_velocity`: the floor a bare
rospy subscriber sets, for the ROS latency benchmark. Run by the system python3."""

import time

import rospy
from geometry_msgs.msg import Twist

rospy.init_node("rdisc_twist_listener", anonymous=True)
rospy.Subscriber("set_velocity", Twist, lambda _msg: print("got", time.monotonic(), flush=True), queue_size=1000)
print("ready", flush=True)
rospy.spin()
