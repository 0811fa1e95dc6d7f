"""smach_ros's ConditionState over :mod:`exp_assignment2.minismach`."""
import traceback

import rospy

from .ros_util import as_duration
from .states import InvalidUserCodeError, State
from .util import has_smach_interface


class ConditionState(State):
    """Asks ``cond_cb(userdata)`` every ``poll_rate`` (ROS time) until it is
    true ('true'), it has asked ``max_checks`` + 1 times or ``timeout`` has
    passed ('false'), or a preempt ('preempted'); ``max_checks`` -1 asks
    without end. As smach_ros's: the first answer is asked at once, a false
    one is followed by a sleep (also the last), an exception from the
    callback ends the state as InvalidUserCodeError, and a callback made with
    ``@smach.cb_interface`` adds its keys.
    """

    def __init__(self, cond_cb, input_keys=(), poll_rate=rospy.Duration(0.05), timeout=None,
                 max_checks=1):
        State.__init__(self, outcomes=['true', 'false', 'preempted'], input_keys=input_keys)
        self._cond_cb = cond_cb
        if has_smach_interface(cond_cb):
            self.register_input_keys(cond_cb.get_registered_input_keys())
            self.register_output_keys(cond_cb.get_registered_output_keys())
        self._poll_rate = poll_rate
        self._timeout = as_duration(timeout)
        self._max_checks = max_checks

    def execute(self, ud):
        start = rospy.Time.now()
        checks = 0
        while self._max_checks == -1 or checks <= self._max_checks:
            if self._timeout and rospy.Time.now() - start > self._timeout:
                break
            if self.preempt_requested():
                self.service_preempt()
                return 'preempted'
            try:
                if self._cond_cb(ud):
                    return 'true'
            except Exception:
                raise InvalidUserCodeError(
                    'Error thrown while executing condition callback %s: %s'
                    % (self._cond_cb, traceback.format_exc()))
            checks += 1
            rospy.sleep(self._poll_rate)
        return 'false'

