"""smach's utilities (``smach.util``): the shutdown check and callback interfaces.

* ``is_shutdown()`` is False until :func:`set_shutdown_check` hands in
  another check (smach_ros hands ``rospy.is_shutdown``); a StateMachine or an
  Iterator stops stepping once it is true, and a Concurrence stops waiting
  for its children, as SMACH's do. The check in use is the package's
  ``is_shutdown``; :func:`shutting_down` asks it.
* ``@cb_interface(outcomes, input_keys, output_keys)`` wraps a callback in a
  :class:`CBInterface`, which says which outcomes it may return and which
  userdata keys it reads and writes; a CBState (and smach_ros' states) with
  such a callback register them (:func:`has_smach_interface`).
"""


def is_shutdown():
    return False


_current = {'is_shutdown': is_shutdown}


def set_shutdown_check(cb):
    """``cb()`` says from now on whether the containers should stop."""
    _current['is_shutdown'] = cb


def current_shutdown_check():
    return _current['is_shutdown']


def shutting_down():
    """What the shutdown check in use says now."""
    return bool(_current['is_shutdown']())


def has_smach_interface(obj):
    """Does ``obj`` say its outcomes and userdata keys (as states and CBInterface do)?"""
    return (hasattr(obj, 'get_registered_input_keys') and
            hasattr(obj, 'get_registered_output_keys') and
            hasattr(obj, 'get_registered_outcomes'))


class cb_interface(object):  # noqa: N801 (SMACH's name)
    """Decorator: ``@cb_interface(outcomes=[...], input_keys=[...], output_keys=[...])``
    makes the callback a :class:`CBInterface` (``io_keys``, beyond SMACH's
    arguments, are both)."""

    def __init__(self, outcomes=None, input_keys=None, output_keys=None, io_keys=None):
        self._outcomes = list(outcomes or [])
        self._input_keys = list(input_keys or [])
        self._output_keys = list(output_keys or [])
        self._io_keys = list(io_keys or [])

    def __call__(self, cb):
        return CBInterface(cb, self._outcomes, self._input_keys, self._output_keys,
                           self._io_keys)


class CBInterface(object):
    """A callback (called as it is) with the outcomes it may return and the
    userdata keys it reads and writes, for the state that calls it."""

    def __init__(self, cb, outcomes=None, input_keys=None, output_keys=None, io_keys=None):
        self._cb = cb
        self._outcomes = list(outcomes or [])
        self._input_keys = set(input_keys or []) | set(io_keys or [])
        self._output_keys = set(output_keys or []) | set(io_keys or [])
        self.__doc__ = getattr(cb, '__doc__', None)
        self.__name__ = getattr(cb, '__name__', type(cb).__name__)

    def __call__(self, *args, **kwargs):
        return self._cb(*args, **kwargs)

    def get_registered_input_keys(self):
        return tuple(self._input_keys)

    def get_registered_output_keys(self):
        return tuple(self._output_keys)

    def get_registered_outcomes(self):
        return tuple(self._outcomes)
