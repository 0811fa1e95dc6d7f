"""smach_ros's states over :mod:`exp_assignment2.minismach` (Debian has no
smach_ros): what a SMACH state machine written for ROS uses.

* :class:`SimpleActionState`: a goal to an action server ('succeeded',
  'aborted', 'preempted'); the goal from ``goal``, ``goal_key``,
  ``goal_slots`` and/or ``goal_cb(ud, goal)``; ``feedback_cb(ud,
  feedback)``; the result to ``result_key``, ``result_slots`` and/or
  ``result_cb(ud, status, result)``, which may return the outcome;
* :class:`~.ros_monitor.MonitorState` (its own module);
* :class:`ServiceState`: one service call ('succeeded', 'aborted',
  'preempted'), the request and response as the action's goal and result;
* the server side (``ActionServerWrapper``, ``IntrospectionServer``) is in
  :mod:`.ros_servers`.

Semantics follow smach_ros: a preempt cancels the goal (or stops the
monitor) and the state ends 'preempted'; an action failure of any kind is
'aborted'; a callback that raises logs the traceback and ends the state
'aborted'. Unlike smach_ros, a state waiting for its result also ends when
the node shuts down.
"""
import threading
import traceback

import rospy

from .states import State
from .util import has_smach_interface

WAIT_STEP = 0.1        # wall s between checks for a preempt or shutdown while waiting


def _keys(cb, kind):
    """The ``kind`` ('input', 'output') keys of a callback made with @cb_interface."""
    if not has_smach_interface(cb):
        return []
    return list(getattr(cb, 'get_registered_%s_keys' % kind)())


def _cb_outcome(state, what, outcome):
    """A callback's outcome: None (none chosen), or one the state registered."""
    if outcome is not None and outcome not in state.get_registered_outcomes():
        rospy.logerr('%s returned %r, which is not one of the outcomes %s'
                     % (what, outcome, list(state.get_registered_outcomes())))
        return 'aborted'
    return outcome


class _Exchange(State):
    """A request/goal built from userdata, a reply written back: what the
    action and service states share."""

    def __init__(self, outcomes, value, key, slots, cb, cb_args, cb_kwargs, reply_key,
                 reply_slots, reply_cb, reply_cb_args, reply_cb_kwargs, input_keys, output_keys):
        if value is not None and key is not None:
            raise ValueError('give the %s or its userdata key, not both' % self._WHAT)
        State.__init__(self, ['succeeded', 'aborted', 'preempted'] + list(outcomes),
                       list(input_keys) + ([key] if key else []) + list(slots) + _keys(cb, 'input'),
                       list(output_keys) + ([reply_key] if reply_key else []) + list(reply_slots)
                       + _keys(reply_cb, 'output'))
        if has_smach_interface(reply_cb):
            self.register_outcomes(reply_cb.get_registered_outcomes())
        self.register_input_keys(_keys(reply_cb, 'input'))
        self.register_output_keys(_keys(cb, 'output'))
        self._value, self._key, self._slots = value, key, list(slots)
        self._cb, self._cb_args, self._cb_kwargs = cb, list(cb_args), dict(cb_kwargs or {})
        self._reply_key, self._reply_slots = reply_key, list(reply_slots)
        self._reply_cb, self._reply_cb_args = reply_cb, list(reply_cb_args)
        self._reply_cb_kwargs = dict(reply_cb_kwargs or {})

    def _build(self, ud):
        """The goal or request, or None (logged) when there is none."""
        value = ud[self._key] if self._key is not None else self._value
        if value is None:
            rospy.logerr('%s: no %s: the userdata key %s holds None'
                         % (self._name, self._WHAT, self._key))
            return None
        for slot in self._slots:
            setattr(value, slot, ud[slot])
        if self._cb is not None:
            try:
                changed = self._cb(ud, value, *self._cb_args, **self._cb_kwargs)
            except Exception:
                rospy.logerr('Could not execute %s callback: %s'
                             % (self._WHAT, traceback.format_exc()))
                return None
            if changed is not None:
                value = changed
        return value

    def _reply(self, ud, reply, *status):
        """Write the reply to userdata; the reply callback's outcome or None."""
        outcome = None
        if self._reply_cb is not None:
            try:
                outcome = self._reply_cb(ud, *(status + (reply,) + tuple(self._reply_cb_args)),
                                         **self._reply_cb_kwargs)
            except Exception:
                rospy.logerr('Could not execute %s callback: %s'
                             % (self._REPLY, traceback.format_exc()))
                return 'aborted'
            outcome = _cb_outcome(self, '%s callback of %s' % (self._REPLY, self._name), outcome)
        if self._reply_key is not None:
            ud[self._reply_key] = reply
        for slot in self._reply_slots:
            ud[slot] = getattr(reply, slot)
        return outcome


class SimpleActionState(_Exchange):
    """smach_ros's SimpleActionState (see the module)."""

    _WHAT, _REPLY = 'goal', 'result'

    def __init__(self, action_name, action_spec, goal=None, goal_key=None, goal_slots=(),
                 goal_cb=None, goal_cb_args=(), goal_cb_kwargs=None, result_key=None,
                 result_slots=(), result_cb=None, result_cb_args=(), result_cb_kwargs=None,
                 input_keys=(), output_keys=(), outcomes=(), exec_timeout=None,
                 preempt_timeout=None, server_wait_timeout=None, feedback_cb=None,
                 feedback_cb_args=(), feedback_cb_kwargs=None):
        import actionlib
        if goal is None and goal_key is None:       # an empty goal, as smach_ros
            goal = action_spec().action_goal.goal
        _Exchange.__init__(self, outcomes, goal, goal_key, goal_slots, goal_cb, goal_cb_args,
                           goal_cb_kwargs, result_key, result_slots, result_cb, result_cb_args,
                           result_cb_kwargs, input_keys, output_keys)
        self._name = action_name
        self._feedback_cb, self._feedback_cb_args = feedback_cb, list(feedback_cb_args)
        self._feedback_cb_kwargs = dict(feedback_cb_kwargs or {})
        self.register_input_keys(_keys(feedback_cb, 'input'))
        self.register_output_keys(_keys(feedback_cb, 'output'))
        self._exec_timeout = exec_timeout
        self._client = actionlib.SimpleActionClient(action_name, action_spec)
        self._server_wait_timeout = server_wait_timeout or rospy.Duration(60.0)
        self._connected = False
        self._waiter = threading.Thread(target=self._wait_for_server, daemon=True,
                                        name='SimpleActionState:' + action_name)
        self._waiter.start()
        self._done = threading.Condition()     # never held while calling actionlib
        self._status = self._result = None
        self._sends = 0

    def _wait_for_server(self):
        """Up to server_wait_timeout of ROS time (counted once it runs), or a preempt."""
        start = None
        while not (rospy.is_shutdown() or self.preempt_requested()):
            if self._client.wait_for_server(rospy.Duration(1.0)):
                self._connected = True
                return
            now = rospy.get_rostime()
            if not now.is_zero():
                start = start or now
                if now - start >= self._server_wait_timeout:
                    return

    def request_preempt(self):
        State.request_preempt(self)
        with self._done:         # the waiting execute cancels the goal (outside this lock:
            self._done.notify_all()     # actionlib calls _on_transition holding its own)

    def execute(self, ud):
        if not self._connected:
            rospy.logwarn("Still waiting for action server '%s' to start... is it running?"
                          % self._name)
            if self._waiter.is_alive():
                self._waiter.join()
            else:
                self._wait_for_server()
        if self.preempt_requested():
            rospy.loginfo('Preempting %s before sending goal.' % self._name)
            self.service_preempt()
            return 'preempted'
        if not self._connected:
            rospy.logfatal('Action server for %s is not running.' % self._name)
            return 'aborted'
        goal = self._build(ud)
        if goal is None:
            return 'aborted'
        with self._done:
            self._status = self._result = None
            self._sends += 1
            send = self._sends
        feedback = None
        if self._feedback_cb is not None:
            feedback = lambda _handle, msg: self._feedback_cb(       # noqa: E731
                ud, msg, *self._feedback_cb_args, **self._feedback_cb_kwargs)
        start = rospy.get_rostime()
        # a goal handle of its own (SimpleActionClient drops the callbacks that
        # come before send_goal has stored its handle: on a loaded machine,
        # the feedback and the goal's first transitions)
        handle = self._client.action_client.send_goal(
            goal, lambda gh: self._on_transition(gh, send), feedback)
        status, result = self._wait(start, handle)
        if status is None:                     # shut down while waiting
            return 'preempted' if self.preempt_requested() else 'aborted'
        from actionlib_msgs.msg import GoalStatus
        if status == GoalStatus.SUCCEEDED:
            outcome = 'succeeded'
        elif (status in (GoalStatus.PREEMPTED, GoalStatus.RECALLED)
              and self.preempt_requested()):
            outcome = 'preempted'
            self.service_preempt()
        else:
            outcome = 'aborted'
        return self._reply(ud, result, status) or outcome

    def _wait(self, start, handle):
        """(status, result) once the goal is done, or (None, None) at shutdown;
        cancels it on a preempt or after exec_timeout."""
        cancelled = False
        while True:
            with self._done:
                if self._status is None and (cancelled or not self.preempt_requested()):
                    self._done.wait(WAIT_STEP)
                status, result = self._status, self._result
            if status is not None or rospy.is_shutdown():
                return status, result
            late = (self._exec_timeout is not None
                    and rospy.get_rostime() - start > self._exec_timeout)
            if not cancelled and (late or self.preempt_requested()):
                if late:
                    rospy.logwarn('Action %s timed out after %s s.'
                                  % (self._name, self._exec_timeout.to_sec()))
                else:
                    rospy.loginfo("Preempt requested on action '%s'" % self._name)
                handle.cancel()
                cancelled = True

    def _on_transition(self, handle, send):
        import actionlib
        if handle.get_comm_state() == actionlib.CommState.DONE:
            with self._done:
                if send == self._sends and self._status is None:     # not an earlier goal
                    self._status, self._result = handle.get_goal_status(), handle.get_result()
                self._done.notify_all()


class ServiceState(_Exchange):
    """smach_ros's ServiceState (see the module)."""

    _WHAT, _REPLY = 'request', 'response'

    def __init__(self, service_name, service_spec, request=None, request_cb=None,
                 request_cb_args=(), request_cb_kwargs=None, request_key=None,
                 request_slots=(), response_cb=None, response_cb_args=(),
                 response_cb_kwargs=None, response_key=None, response_slots=(),
                 input_keys=(), output_keys=(), outcomes=()):
        if request is None and request_key is None:
            request = service_spec._request_class()
        _Exchange.__init__(self, outcomes, request, request_key, request_slots, request_cb,
                           request_cb_args, request_cb_kwargs, response_key, response_slots,
                           response_cb, response_cb_args, response_cb_kwargs, input_keys,
                           output_keys)
        self._name, self._spec = service_name, service_spec

    def execute(self, ud):
        if self.preempt_requested():
            self.service_preempt()
            return 'preempted'
        while True:
            try:
                rospy.wait_for_service(self._name, 1.0)
                break
            except rospy.ROSException:
                if self.preempt_requested():
                    self.service_preempt()
                    return 'preempted'
                if rospy.is_shutdown():
                    return 'aborted'
                rospy.logwarn("Still waiting for service '%s'..." % self._name)
        request = self._build(ud)
        if request is None:
            return 'aborted'
        try:
            response = rospy.ServiceProxy(self._name, self._spec)(request)
        except (rospy.ServiceException, rospy.ROSException) as exc:
            rospy.logerr("Exception when calling service '%s': %s" % (self._name, exc))
            return 'aborted'
        return self._reply(ud, response) or 'succeeded'
