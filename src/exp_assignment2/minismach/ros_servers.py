"""smach_ros's server side over :mod:`exp_assignment2.minismach`:
:class:`ActionServerWrapper` (a container served as an action) and
:class:`IntrospectionServer` (what smach_viewer reads, :mod:`.introspection`).
The states are in :mod:`.ros_states`, which re-exports these."""
import rospy

from .introspection import IntrospectionServer  # noqa: F401  (smach_ros' name)
from .states import UserData


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
