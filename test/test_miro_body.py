"""MiRo's body over ROS (exp_assignment2.ros.miro.RosMiroBody) against a
grounding node that is slow and answers twice, at 20x real time (a ROS
master of the test's own, the body in a subprocess that also publishes the
clock): an order is not sent again before a second of wall time, and an
order grounded twice waits for the later target, the one the controller
drives to; an arrival that comes before its target (MiRo already there)
counts."""
import os
import subprocess

import pytest

from original_env_helpers import PYTHON

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')

BODY = r'''
import threading, time
import rospy
from rosgraph_msgs.msg import Clock
from std_msgs.msg import Float64MultiArray, Int64MultiArray, MultiArrayDimension, String
from exp_assignment2.ros.clock import RosClock
from exp_assignment2.ros.miro import RosMiroBody

rospy.init_node('body', disable_signals=True)
clock_pub = rospy.Publisher('/clock', Clock, queue_size=10)

def run_clock():                  # 20x: 20 ms of ROS time a wall millisecond
    ns = 0
    while not rospy.is_shutdown():
        ns += 20000000
        clock_pub.publish(Clock(clock=rospy.Time(ns // 10**9, ns % 10**9)))
        time.sleep(0.001)
threading.Thread(target=run_clock, daemon=True).start()

targets = rospy.Publisher('/target_pos', Int64MultiArray, queue_size=10)
arrivals = rospy.Publisher('/arrival', Float64MultiArray, queue_size=10)
ANSWERS = {'go_home': [(3, 3)], 'go_rand': [(6, 6), (0, 4)],     # go_rand: grounded twice
           'go to 7 1': [(7, 1)]}
heard = []

def ground(msg):                  # a grounding node 0.2 s late: 4 s of ROS time
    heard.append(msg.data)
    def answer():
        if msg.data == 'go to 7 1':     # MiRo is there: the controller answers first
            arrivals.publish(Float64MultiArray(data=[7, 1, 7.0, 1.0, 3]))
        time.sleep(0.2)
        for xy in ANSWERS[msg.data]:
            out = Int64MultiArray(data=list(xy))
            out.layout.dim = [MultiArrayDimension(label=msg.data, size=2, stride=2)]
            targets.publish(out)
    threading.Thread(target=answer, daemon=True).start()
rospy.Subscriber('/command', String, ground, queue_size=10)

clock = RosClock()
clock.wait_for_time()
body = RosMiroBody(clock)
deadline = time.monotonic() + 20
while (body.pub.get_num_connections() < 1 or targets.get_num_connections() < 1
       or arrivals.get_num_connections() < 1) and time.monotonic() < deadline:
    time.sleep(0.05)

goal = body.go('go_home')
print('HOME', heard, goal.target, flush=True)
goal = body.go('go_rand')
time.sleep(0.5)                   # the second answer lands
print('RAND', heard, goal.target, flush=True)
arrivals.publish(Float64MultiArray(data=[6, 6, 6.0, 6.0, 1]))
time.sleep(0.5)
print('STALE', goal.done(), flush=True)
arrivals.publish(Float64MultiArray(data=[0, 4, 0.0, 4.0, 2]))
time.sleep(0.5)
print('ARRIVED', goal.succeeded(), flush=True)
goal = body.go('go to 7 1')
time.sleep(0.5)
print('EARLY', goal.target, goal.succeeded(), flush=True)
rospy.signal_shutdown('done')
'''


def test_a_slow_answer_is_waited_for_and_a_double_one_takes_the_later_target(ros_master):
    subprocess.run(['rosparam', 'set', '/use_sim_time', 'true'], env=ros_master, check=True)
    proc = subprocess.run([PYTHON, '-c', BODY], env=ros_master, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, timeout=90)
    assert proc.returncode == 0, proc.stderr
    lines = [l for l in proc.stdout.splitlines() if l.split()[0] in
             ('HOME', 'RAND', 'STALE', 'ARRIVED', 'EARLY')]
    assert lines == ["HOME ['go_home'] (3, 3)",
                     "RAND ['go_home', 'go_rand'] (0, 4)",
                     'STALE False', 'ARRIVED True', 'EARLY (7, 1) True'], proc.stdout + proc.stderr
