"""Publish Twists on `set_velocity`, one a line of stdin ("linear angular"), waiting for
a subscriber first; print "sent T" after each (T: time.monotonic() just before publishing, the same clock
in every process). Run by the system python3, where rospy lives; the ROS latency
benchmark uses it too."""

import sys
import time

import rospy
from geometry_msgs.msg import Twist

rospy.init_node("rdisc_test_twists", anonymous=True)
publisher = rospy.Publisher("set_velocity", Twist, queue_size=100)
while publisher.get_num_connections() == 0 and not rospy.is_shutdown():
    rospy.sleep(0.05)
print("ready", flush=True)
for line in sys.stdin:
    linear, angular = map(float, line.split())
    message = Twist()
    message.linear.x, message.angular.z = linear, angular
    start = time.monotonic()
    publisher.publish(message)
    print("sent", start, flush=True)
