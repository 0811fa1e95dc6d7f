"""smach_ros's states over :mod:`exp_assignment2.minismach` (Debian has no
smach_ros): what a SMACH state machine written for ROS uses.

* :class:`SimpleActionState`: a goal to an action server ('succeeded',
  'aborted', 'preempted'); the goal from ``goal``, ``goal_key``,
  ``goal_slots`` and/or ``goal_cb(ud, goal)``; ``feedback_cb(ud,
  feedback)``; the result to ``result_key``, ``result_slots`` and/or
  ``result_cb(ud, status, result)``, which may return the outcome;
* :class:`MonitorState`: ``cond_cb(ud, msg)`` on each message of a topic;
  False ends it 'invalid', ``max_checks`` (> 0) Trues 'valid';
* :class:`ServiceState`: one service call ('succeeded', 'aborted',
  'preempted'), the request and response as the action's goal and result;
* :class:`ActionServerWrapper`: a container served as an action;
* :class:`IntrospectionServer`: smach_viewer's, kept with its signature; it
  publishes nothing (smach_viewer is not in Debian either).

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

WAIT_STEP = 0.1        # wall s between checks for a preempt or shutdown while waiting


def _keys(cb, kind):
    return list(getattr(cb, '_smach_%s_keys' % kind, ())) if cb is not None else []


def _cb_outcome(state, what, outcome):
    """A callback's outcome: None (none chosen), or one the state registered."""
    if outcome is not None and outcome not in state.get_registered_outcomes():
        rospy.logerr('%s returned %r, which is not one of the outcomes %s'
                     % (what, outcome, list(state.get_registered_outcomes())))
        return 'aborted'
    return outcome


class IntrospectionServer(object):
    """``IntrospectionServer(server_name, state, path)``; start, stop and clear do nothing."""

    def __init__(self, server_name, state, path):
        self._server_name, self._state, self._path = server_name, state, path

    def start(self):
        pass

    def stop(self):
        pass

    def clear(self):
        pass


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
        self.register_outcomes(getattr(reply_cb, '_smach_outcomes', ()))
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


class MonitorState(State):
    """smach_ros's MonitorState (see the module)."""

    def __init__(self, topic, msg_type, cond_cb, max_checks=-1, input_keys=(), output_keys=()):
        State.__init__(self, ['valid', 'invalid', 'preempted'], input_keys, output_keys)
        self._topic, self._msg_type, self._cond_cb = topic, msg_type, cond_cb
        self._max_checks = max_checks
        self._trigger = threading.Event()
        self._checks = 0

    def execute(self, ud):
        if self.preempt_requested():
            self.service_preempt()
            return 'preempted'
        self._checks = 0
        self._trigger.clear()
        sub = rospy.Subscriber(self._topic, self._msg_type, self._on_message, callback_args=ud)
        try:
            while not self._trigger.wait(WAIT_STEP):
                if rospy.is_shutdown():
                    break
        finally:
            sub.unregister()
        if self.preempt_requested():
            self.service_preempt()
            return 'preempted'
        if self._max_checks > 0 and self._checks >= self._max_checks:
            return 'valid'
        return 'invalid'

    def _on_message(self, msg, ud):
        if self._trigger.is_set():
            return
        try:
            if self._cond_cb(ud, msg):
                self._checks += 1
            else:
                self._trigger.set()
        except Exception:
            rospy.logerr('Error thrown while executing condition callback %s: %s'
                         % (self._cond_cb, traceback.format_exc()))
            self._trigger.set()
        if self._max_checks > 0 and self._checks >= self._max_checks:
            self._trigger.set()

    def request_preempt(self):
        State.request_preempt(self)
        self._trigger.set()


class ActionServerWrapper(object):
    """smach_ros's ActionServerWrapper: a container run as an action server.

    Each goal runs the container (:meth:`run_server` starts the server): the
    goal in userdata ``goal_key`` (and its fields as ``goal_slots_map`` says,
    or all of them with ``expand_goal_slots``), an empty result in
    ``result_key``; the container's outcome ends the goal as
    ``succeeded_outcomes``, ``preempted_outcomes`` or else aborted, with the
    result from ``result_key`` (fields from ``result_slots_map``, or from
    userdata keys of the same names with ``pack_result_slots``). A cancel
    preempts the container; ``feedback_key`` in userdata is published as
    feedback at each of its transitions. The goal, feedback and result keys
    are made the container's own input and output keys.
    """

    def __init__(self, server_name, action_spec, wrapped_container, succeeded_outcomes=(),
                 aborted_outcomes=(), preempted_outcomes=(), goal_key='action_goal',
                 feedback_key='action_feedback', result_key='action_result',
                 goal_slots_map=None, feedback_slots_map=None, result_slots_map=None,
                 expand_goal_slots=False, pack_result_slots=False):
        import actionlib
        from .states import UserData
        self.wrapped_container, self.userdata = wrapped_container, UserData()
        self._succeeded, self._preempted = set(succeeded_outcomes), set(preempted_outcomes)
        self._aborted = set(aborted_outcomes)
        self._goal_key, self._feedback_key, self._result_key = goal_key, feedback_key, result_key
        self._goal_slots_map = dict(goal_slots_map or {})
        self._result_slots_map = dict(result_slots_map or {})
        self._expand_goal_slots, self._pack_result_slots = expand_goal_slots, pack_result_slots
        self._result_class = type(action_spec().action_result.result)
        goal_fields = list(action_spec().action_goal.goal.__slots__)
        wrapped_container.register_input_keys(
            [goal_key] + list(self._goal_slots_map.values())
            + (goal_fields if expand_goal_slots else []))
        wrapped_container.register_output_keys([feedback_key, result_key]
                                               + list(self._result_slots_map.values()))
        self._server = actionlib.SimpleActionServer(server_name, action_spec,
                                                    execute_cb=self.execute_cb, auto_start=False)
        self._server.register_preempt_callback(wrapped_container.request_preempt)
        wrapped_container.register_transition_cb(self._publish_feedback)

    def run_server(self):
        """Start the action server; returns it."""
        self._server.start()
        return self._server

    def _publish_feedback(self, userdata, *_args):
        if self._feedback_key in userdata:
            self._server.publish_feedback(userdata[self._feedback_key])

    def execute_cb(self, goal):
        ud = self.userdata
        ud[self._goal_key] = goal
        for field, key in self._goal_slots_map.items():
            ud[key] = getattr(goal, field)
        if self._expand_goal_slots:
            for field in goal.__slots__:
                ud[field] = getattr(goal, field)
        ud[self._result_key] = self._result_class()
        if self._server.is_preempt_requested():    # cancelled while it waited to start:
            self.wrapped_container.request_preempt()     # no preempt callback comes then
        try:
            outcome = self.wrapped_container.execute(ud)
        except Exception as exc:
            rospy.logerr('Exception thrown while executing the wrapped container: %s' % exc)
            outcome = None
        result = ud[self._result_key]
        for field, key in self._result_slots_map.items():
            setattr(result, field, ud[key])
        if self._pack_result_slots:
            for field in result.__slots__:
                if field in ud:
                    setattr(result, field, ud[field])
        if outcome in self._succeeded:
            self._server.set_succeeded(result)
        elif outcome in self._preempted:
            self._server.set_preempted(result)
        else:
            self._server.set_aborted(result)
