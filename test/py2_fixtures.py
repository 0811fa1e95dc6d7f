"""The grader's fixture of a submission written for Python 2 (issue 48): the
dog that works, its node in Python 2 (print statements, ``except E, e``,
``xrange``, ``iteritems``, ``has_key``, integer division, tabs), started with
two keyboard nodes as the assignment's "person" was written
(``raw_input`` in an ``output="screen"`` node): one is given lines to type
by the fixture folder's grading.yaml (``FOLDER_SETTINGS``), the other waits
as on a terminal nobody types into.
"""
import os

import grading_fixtures

EXPECTED = {'py2_keyboard': 'passed'}
FOLDER_SETTINGS = """submissions:
  py2_keyboard:
    commands:
      - run: roslaunch exp_assignment2 gazebo_world.launch
        input: {ball_request.py: [{at: 2, text: m}, {at: 4, text: d}]}
"""

# the dog of the base fixture, as a Python 2 student wrote it (8-space levels as tabs)
DOG = '''#!/usr/bin/env python
"""Turn until the green ball is in view, drive to it, then look left and right."""
import cv2
import numpy as np
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import CompressedImage
from std_msgs.msg import Float64

GAINS = {'turn': 2, 'forward': 6}


class Dog(object):
    def __init__(self):
        self.cmd = rospy.Publisher('/robot/cmd_vel', Twist, queue_size=1)
        self.head = rospy.Publisher('/robot/joint_head_controller/command', Float64,
                                    queue_size=1)
        self.ball = None
        self.looking_since = None
        rospy.Subscriber('/robot/camera1/image_raw/compressed', CompressedImage, self.seen,
                         queue_size=1, buff_size=2 ** 22)

    def seen(self, msg):
        try:
            image = cv2.imdecode(np.frombuffer(msg.data, np.uint8), cv2.IMREAD_COLOR)
        except cv2.error, e:
            print "cannot decode:", e
            return
        mask = cv2.inRange(cv2.cvtColor(image, cv2.COLOR_BGR2HSV), (50, 50, 20), (70, 255, 255))
        found = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)[-2]
        if found:
\t    (x, _), radius = cv2.minEnclosingCircle(max(found, key=cv2.contourArea))
\t    half = image.shape[1] / 2
\t    self.ball = ((x - half) / (2.0 * half), radius / image.shape[1])
        else:
\t    self.ball = None

    def step(self):
        twist = Twist()
        if self.looking_since is not None:
\t    elapsed = (rospy.Time.now() - self.looking_since).to_sec()
\t    self.head.publish(Float64(0.9 if elapsed % 8 < 4 else -0.9))
        elif self.ball is None:
\t    twist.angular.z = -0.5          # the course robot turns right for +z
        else:
\t    offset, radius = self.ball
\t    twist.angular.z = GAINS['turn'] * offset
\t    twist.linear.x = GAINS['forward'] / 10.0 if radius < 0.2 else 0.0
\t    if radius >= 0.2 and abs(offset) < 0.1:
\t\tself.looking_since = rospy.Time.now()
\t\tprint "found the ball after", rospy.get_time(), "s"
        self.cmd.publish(twist)


if __name__ == '__main__':
    rospy.init_node('dog')
    for name, value in GAINS.iteritems():
        if GAINS.has_key(name):
            print "gain %s = %d" % (name, value)
    assert 7 / 2 == 3, "Python 2 divides ints to an int"
    dog = Dog()
    rate = rospy.Rate(10)
    for _ in xrange(10 ** 9):
        if rospy.is_shutdown():
            break
        dog.step()
        rate.sleep()
'''
# the assignment's "person", asking for a command on its terminal
REQUEST = '''#!/usr/bin/env python
import rospy
rospy.init_node('%s')
while not rospy.is_shutdown():
    choice = raw_input("Command: (m)ove ball, (d)isappear ball: ")
    print "got", choice
'''
NODES = ('  <node name="ball_request" pkg="exp_assignment2" type="ball_request.py" '
         'output="screen"/>\n  <node name="human" pkg="exp_assignment2" type="human.py" '
         'output="screen"/>\n')


def make(name, dest):
    """Write the fixture ``name`` into the class folder ``dest``."""
    if name != 'py2_keyboard':
        raise KeyError(name)
    path = os.path.join(dest, name)
    grading_fixtures._package(path)
    grading_fixtures._replace(path, grading_fixtures.DOG, DOG)
    for script, node in (('ball_request.py', 'ball_request'), ('human.py', 'human')):
        grading_fixtures._replace(path, os.path.join('scripts', script), REQUEST % node)
    launch = os.path.join(path, grading_fixtures.LAUNCH)
    with open(launch) as f:
        text = f.read()
    with open(launch, 'w') as f:
        f.write(text.replace('</launch>', NODES + '</launch>'))
