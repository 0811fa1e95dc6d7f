"""smach_ros's MonitorState over :mod:`exp_assignment2.minismach`:
``cond_cb(ud, msg)`` on each message of a topic; False ends it 'invalid',
``max_checks`` (> 0) Trues 'valid', a preempt 'preempted'; a callback that
raises logs it and ends the state 'invalid'; shutdown ends the wait."""
import threading
import traceback

import rospy

from .ros_states import WAIT_STEP
from .states import State


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
