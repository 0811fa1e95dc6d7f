"""Sending PlanningAction goals with one goal handle per goal.

actionlib's SimpleActionClient tracks one goal at a time: a goal sent while
another is still finishing makes it log "Got a transition callback on a goal
handle that we're not tracking", and a hurried cancel "received DONE twice".
Each :class:`ActionGoal` here keeps its own handle of a plain ActionClient, so
every goal's transitions go to the object that waits for it.

A goal sent while its server is being restarted (respawned after a crash)
reaches nobody, and actionlib waits for its acknowledgement for ever. The
client reads the server's status messages: a goal that UNSEEN of them in a
row leave out, for at least RESEND_AFTER s of wall time, is sent again, with
one line. The status is published in ROS time, so a paused simulation sends
nothing again.
"""
import threading
import time

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus, GoalStatusArray

from exp_assignment2.msg import PlanningAction
from exp_assignment2.planning import make_goal
from exp_assignment2.ros.clock import RosClock


UNSEEN = 3             # status messages without the goal ...
RESEND_AFTER = 1.0     # ... and wall s since it was sent: it is sent again


class ActionGoal(object):
    """A goal under way (:class:`~exp_assignment2.behaviour.interfaces.Goal`);
    its end notifies the clock."""

    def __init__(self, client, goal, clock):
        self.clock, self.status, self.text = clock, None, ''
        self.goal, self.sends, self.lock = goal, 0, threading.Lock()
        self.cancelled, self.handle = False, None
        with self.lock:
            self._send(client)

    def resend(self, client):
        """Send the goal again, unless it was cancelled, ended or acknowledged
        meanwhile: the handle before is dropped, and cancelled in case it
        reached a server after all. True if sent."""
        with self.lock:
            if self.cancelled or not self.unacknowledged():
                return False
            old = self.handle
            self._send(client)
        old.cancel()
        return True

    def _send(self, client):
        """(self.lock held; actionlib never calls back into it)"""
        self.sends += 1
        self.sent_at, self.unseen = time.monotonic(), 0
        send = self.sends
        self.handle = client.send_goal(
            self.goal, transition_cb=lambda handle: self._on_transition(handle, send))

    def _on_transition(self, handle, send):
        if send != self.sends:             # a handle sent again since
            return
        if handle.get_comm_state() == actionlib.CommState.DONE and self.status is None:
            self.status = handle.get_goal_status()
            self.text = handle.get_goal_status_text()
            self.clock.notify()

    def unacknowledged(self):
        return (self.status is None and self.handle.get_comm_state()
                == actionlib.CommState.WAITING_FOR_GOAL_ACK)

    def goal_id(self):
        return self.handle.comm_state_machine.action_goal.goal_id.id

    def done(self):
        return self.status is not None

    def succeeded(self):
        return self.status == GoalStatus.SUCCEEDED

    def cancel(self):
        with self.lock:
            self.cancelled = True
            if self.status is None:
                self.handle.cancel()


class PlanningClient(object):
    """A client of one of the PlanningAction servers."""

    def __init__(self, name, clock):
        self.name, self.clock = name, clock
        self.client = actionlib.ActionClient(name, PlanningAction)
        self.lock, self.waiting = threading.Lock(), []     # goals not acknowledged yet
        # (no queue_size: rospy shares one subscription per topic with actionlib's)
        rospy.Subscriber(name + '/status', GoalStatusArray, self._on_status)

    def _on_status(self, msg):
        known = set(s.goal_id.id for s in msg.status_list)
        with self.lock:
            self.waiting = [g for g in self.waiting if g.unacknowledged()]
            for goal in self.waiting:
                if goal.goal_id() in known:
                    continue
                goal.unseen += 1
                waited = time.monotonic() - goal.sent_at
                if goal.unseen >= UNSEEN and waited >= RESEND_AFTER and \
                        goal.resend(self.client):
                    rospy.logwarn('%s: the goal (%s) was not acknowledged by %s in %.1f s (a '
                                  'restarted server never got it): sent again',
                                  rospy.get_name(), goal_text(goal.goal), self.name, waited)

    def wait_for_server(self, warn_every=30.0):
        """Wait until the server is up, however long it takes (the node has
        nothing to do without it); a warning every ``warn_every`` s of ROS
        time. Deadlines are computed only once ROS time runs. False on shutdown."""
        if not self.clock.wait_for_time():
            return False
        while not rospy.is_shutdown():
            if self.client.wait_for_server(rospy.Duration(warn_every)):
                return True
            if not rospy.is_shutdown():
                rospy.logwarn('%s: no %s action server yet; still waiting',
                              rospy.get_name(), self.name)
                self.reconnect()
        return False

    def reconnect(self):
        """Register the client's five topics afresh. The server counts as up
        once every one is connected to it, and on a loaded machine rospy once
        left one unconnected for good ("ready" at 0.27 s, still waited for at
        185 s); registering again brings every connection back."""
        old = self.client
        for topic in (old.pub_goal, old.pub_cancel, old.status_sub, old.result_sub,
                      old.feedback_sub):
            topic.unregister()       # first: a topic still held is shared, not renewed
        self.client = actionlib.ActionClient(self.name, PlanningAction)

    def go_to(self, x, y, z=0.0):
        """Send a goal; returns its :class:`ActionGoal`."""
        with self.lock:
            goal = ActionGoal(self.client, make_goal(x, y, z, stamp=rospy.Time.now()),
                              self.clock)
            self.waiting.append(goal)
        return goal


def goal_text(goal):
    p = goal.target_pose.pose.position
    return 'x, y, z = %.2f, %.2f, %.2f' % (p.x, p.y, p.z)


def start_client(node, action):
    """Start ``node`` with a clock and a client of ``action`` whose server is up:
    (clock, client), or (clock, None) when ROS shut down first."""
    rospy.init_node(node)
    clock = RosClock()
    client = PlanningClient(action, clock)
    return clock, client if client.wait_for_server() else None
