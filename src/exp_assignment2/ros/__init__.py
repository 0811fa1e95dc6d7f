"""ROS implementations of the behaviours' interfaces (rospy, actionlib).

The nodes in ``exp_assignment2.nodes`` wire these to the pure behaviours.
"""
