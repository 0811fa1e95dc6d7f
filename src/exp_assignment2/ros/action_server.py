"""A SimpleActionServer that refuses bad goals before they touch the running one.

actionlib's SimpleActionServer accepts every goal it receives, and so
preempts the goal it is executing, before ``execute`` can look at the new
one: a goal with x = NaN ended a valid goal as PREEMPTED. Here a goal that
``check`` refuses is REJECTED in the goal callback, as actionlib's goal
callback allows, with one (throttled) log line; the running goal goes on.
Valid goals keep SimpleActionServer's semantics: the newest preempts.

Also, against what actionlib does by itself:

* cancels naming a goal the server never had: actionlib keeps the first (the
  goal may still be on its way) but logs two errors about an "uninitialized
  ServerGoalHandle" for every repeat; here a repeat is refused in one
  throttled line naming the interface.
* ROS time jumping (a second ``/clock``, a reset of the simulation): the status
  timer survives a backwards jump, and a goal stamped before the jump no
  longer makes every later goal look older than it (SimpleActionServer
  cancels a goal older than the one it holds).
"""
import actionlib
import rospy
from actionlib.handle_tracker_deleter import HandleTrackerDeleter
from actionlib.server_goal_handle import ServerGoalHandle
from actionlib.status_tracker import StatusTracker
from actionlib_msgs.msg import GoalStatus

from exp_assignment2.grammar import quote

CANCEL_USAGE = 'accepted: the id of a goal this server holds, or an empty id (every goal)'
FUTURE = rospy.Duration(1.0)     # a goal stamped this far ahead was stamped before a jump
STATUS_TIMER_JOIN = 2.0          # wall s at most (a paused simulator holds ROS time)


class CheckedActionServer(actionlib.SimpleActionServer):
    """:class:`actionlib.SimpleActionServer`, started, whose goals pass ``check``.

    :param check: ``check(goal)`` is why the goal cannot be executed, or None
    :param refuse: ``refuse(reason)`` logs a refused goal (a RefusalLog)
    :param refuse_cancel: the same for refused cancels
    """

    def __init__(self, name, spec, execute, check, refuse, refuse_cancel):
        self.check, self.refuse, self.refuse_cancel = check, refuse, refuse_cancel
        actionlib.SimpleActionServer.__init__(self, name, spec, execute, auto_start=False)
        # read when start() subscribes to <name>/cancel
        self.action_server.internal_cancel_callback = self._on_cancel

    def start(self):
        actionlib.SimpleActionServer.start(self)
        server = self.action_server
        if server.status_timer is not None:     # actionlib's dies when time goes back
            server.status_timer.shutdown()
            # it ends after its current period (0.2 s of ROS time): gone before any jump
            server.status_timer.join(STATUS_TIMER_JOIN)
            server.status_timer = rospy.Timer(rospy.Duration(1.0 / server.status_frequency),
                                              server.publish_status_async, reset=True)

    def internal_goal_callback(self, goal):
        error = self.check(goal.get_goal())
        if error:
            self.refuse('rejected: %s' % error)
            goal.set_rejected(None, error)
            return
        self._forget_stamps_from_before_a_jump()
        actionlib.SimpleActionServer.internal_goal_callback(self, goal)

    def _forget_stamps_from_before_a_jump(self):
        """A goal held here that is stamped in the future was stamped before ROS
        time went back: its stamp no longer orders goals."""
        latest = rospy.Time.now() + FUTURE
        with self.action_server.lock:
            for held in (self.current_goal, self.next_goal):
                if held.get_goal() is not None and held.get_goal_id().stamp > latest:
                    held.get_goal_id().stamp = rospy.Time()

    def _on_cancel(self, goal_id):
        """actionlib's cancel callback, without touching the goal-less entries a
        cancel of an unknown goal leaves behind."""
        server = self.action_server
        zero = rospy.Time()
        with server.lock:
            if not server.started:
                return
            everything = not goal_id.id and goal_id.stamp == zero
            named = []
            for tracker in list(server.status_list):
                same = bool(goal_id.id) and tracker.status.goal_id.id == goal_id.id
                older = goal_id.stamp != zero and tracker.status.goal_id.stamp <= goal_id.stamp
                if same:
                    named.append(tracker)
                if (everything or same or older) and tracker.goal is not None:
                    self._request_cancel(tracker)
            if goal_id.id and not named:
                # kept, as actionlib keeps it: the goal may still be on its way
                kept = StatusTracker(goal_id, GoalStatus.RECALLING)
                kept.handle_destruction_time = rospy.Time.now()
                server.status_list.append(kept)
            if goal_id.stamp > server.last_cancel:
                server.last_cancel = goal_id.stamp
        if named and all(tracker.goal is None for tracker in named):
            self.refuse_cancel('cancel of goal %s refused: this server has no such goal (a '
                               'cancel of it is already kept in case it arrives); %s'
                               % (quote(goal_id.id), CANCEL_USAGE))

    def _request_cancel(self, tracker):
        server = self.action_server
        if tracker.handle_tracker is None:
            tracker.handle_tracker = HandleTrackerDeleter(server, tracker)
            tracker.handle_destruction_time = rospy.Time.now()
        handle = ServerGoalHandle(tracker, server, tracker.handle_tracker)
        if handle.set_cancel_requested():
            server.cancel_callback(handle)
