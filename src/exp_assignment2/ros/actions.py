"""Sending PlanningAction goals with one goal handle per goal.

actionlib's SimpleActionClient tracks one goal at a time: a goal sent while
another is still finishing makes it log "Got a transition callback on a goal
handle that we're not tracking", and a hurried cancel "received DONE twice".
Each :class:`ActionGoal` here keeps its own handle of a plain ActionClient, so
every goal's transitions go to the object that waits for it.
"""
import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus

from exp_assignment2.msg import PlanningAction
from exp_assignment2.planning import make_goal
from exp_assignment2.ros.clock import RosClock


class ActionGoal(object):
    """A goal under way (:class:`~exp_assignment2.behaviour.interfaces.Goal`);
    its end notifies the clock."""

    def __init__(self, client, goal, clock):
        self.clock, self.status, self.text = clock, None, ''
        self.handle = client.send_goal(goal, transition_cb=self._on_transition)

    def _on_transition(self, handle):
        if handle.get_comm_state() == actionlib.CommState.DONE and self.status is None:
            self.status = handle.get_goal_status()
            self.text = handle.get_goal_status_text()
            self.clock.notify()

    def done(self):
        return self.status is not None

    def succeeded(self):
        return self.status == GoalStatus.SUCCEEDED

    def cancel(self):
        if self.status is None:
            self.handle.cancel()


class PlanningClient(object):
    """A client of one of the PlanningAction servers."""

    def __init__(self, name, clock):
        self.name, self.clock = name, clock
        self.client = actionlib.ActionClient(name, PlanningAction)

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
        return ActionGoal(self.client, make_goal(x, y, z, stamp=rospy.Time.now()), self.clock)


def start_client(node, action):
    """Start ``node`` with a clock and a client of ``action`` whose server is up:
    (clock, client), or (clock, None) when ROS shut down first."""
    rospy.init_node(node)
    clock = RosClock()
    client = PlanningClient(action, clock)
    return clock, client if client.wait_for_server() else None
