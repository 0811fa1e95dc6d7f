"""A goal sent while its action server was down (being respawned) is sent
again once the server is up, and a goal the server has is never sent twice
(a ROS master of the test's own, the package's client in a subprocess)."""
import os
import subprocess

import pytest

from original_env_helpers import PYTHON

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')

CLIENT = r'''
import threading, time
import actionlib, rospy
from exp_assignment2.msg import PlanningAction, PlanningResult
from exp_assignment2.ros.actions import PlanningClient
from exp_assignment2.ros.clock import RosClock

rospy.init_node('client', disable_signals=True)
client = PlanningClient('/reaching_goal', RosClock())
lost = client.go_to(1.0, 2.0)                  # no server yet: nobody gets it
time.sleep(1.0)
received = []
def serve(goal):
    received.append(goal.target_pose.pose.position.x)
    rospy.sleep(0.5)
    server.set_succeeded(PlanningResult())
server = actionlib.SimpleActionServer('/reaching_goal', PlanningAction, serve, False)
server.start()
deadline = time.monotonic() + 30
while not lost.done() and time.monotonic() < deadline:
    time.sleep(0.05)
print('LOST', lost.status, lost.sends, flush=True)
kept = client.go_to(3.0, 4.0)                  # the server is up: acknowledged at once
while not kept.done() and time.monotonic() < deadline + 30:
    time.sleep(0.05)
time.sleep(2.0)
print('KEPT', kept.status, kept.sends, received, flush=True)
rospy.signal_shutdown('done')
'''


def test_a_goal_the_server_never_got_is_sent_again_once(ros_master):
    proc = subprocess.run([PYTHON, '-c', CLIENT], env=ros_master, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, timeout=90)
    assert proc.returncode == 0, proc.stderr
    lines = [l for l in proc.stdout.splitlines() if l.startswith(('LOST', 'KEPT'))]
    assert lines == ['LOST 3 2', 'KEPT 3 1 [1.0, 3.0]'], proc.stdout + proc.stderr
    assert 'was not acknowledged by /reaching_goal' in proc.stderr + proc.stdout
