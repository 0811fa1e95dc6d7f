"""The behaviours of both scenarios, in plain Python.

The states are written against small interfaces (:mod:`.interfaces`): a
clock, a body and the senses. ``exp_assignment2.ros`` implements them with
rospy; the unit tests implement them with fakes and a hand-turned clock, as
smach_ros hands rospy to smach.
"""
