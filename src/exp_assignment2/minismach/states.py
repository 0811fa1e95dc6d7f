"""SMACH's states, userdata and errors (see :mod:`exp_assignment2.minismach`)."""
from . import log
from .util import has_smach_interface


class SmachError(Exception):
    """Base class of every error raised by this module; as SMACH's, it is
    logged (``logerr``) when it is made, so a node's log says what went wrong
    even where the error is caught."""

    def __init__(self, message):
        log.error('%s: %s' % (type(self).__name__, message))
        Exception.__init__(self, message)


class InvalidStateError(SmachError):
    """A state is malformed (e.g. not a State, or its label is taken)."""


class InvalidTransitionError(SmachError):
    """An outcome has no valid target, or a state returned an unknown one."""


class InvalidUserCodeError(SmachError):
    """User code (a state's execute or a callback) raised an exception."""


class InvalidConstructionError(SmachError):
    """A container was used outside of its ``with`` block."""


class UserData(object):
    """Key/value store shared between the states of a container."""

    def __init__(self):
        object.__setattr__(self, '_data', {})

    def keys(self):
        return list(self._data.keys())

    def update(self, other):
        for key in other.keys():
            self._data[key] = other[key]

    def __contains__(self, key):
        return key in self._data

    def __getitem__(self, key):
        return self._data[key]

    def __setitem__(self, key, value):
        self._data[key] = value

    def __getattr__(self, name):
        try:
            return self._data[name]
        except KeyError:
            raise KeyError("SMACH userdata does not contain key '%s'" % name)

    def __setattr__(self, name, value):
        self._data[name] = value


class Remapper(object):
    """A state's view of its container's userdata.

    Only declared keys can be read (input and io keys) or written (output and
    io keys); ``remapping`` maps the state's key names to the container's.
    """

    def __init__(self, ud, input_keys, output_keys, remapping):
        object.__setattr__(self, '_ud', ud)
        object.__setattr__(self, '_input', set(input_keys))
        object.__setattr__(self, '_output', set(output_keys))
        object.__setattr__(self, '_map', dict(remapping))

    def _outer(self, key):
        return self._map.get(key, key)

    def __contains__(self, key):
        return key in self._input and self._outer(key) in self._ud

    def __getitem__(self, key):
        return self.__getattr__(key)

    def __setitem__(self, key, value):
        self.__setattr__(key, value)

    def __getattr__(self, name):
        if name not in self._input:
            raise KeyError("Reading userdata key '%s', but the state declared "
                           "only these input keys: %s" % (name, sorted(self._input)))
        return self._ud[self._outer(name)]

    def __setattr__(self, name, value):
        if name not in self._output:
            raise KeyError("Writing userdata key '%s', but the state declared "
                           "only these output keys: %s" % (name, sorted(self._output)))
        self._ud[self._outer(name)] = value


class State(object):
    """Base class of a state: override :meth:`execute` and return an outcome."""

    def __init__(self, outcomes=(), input_keys=(), output_keys=(), io_keys=()):
        self._outcomes = []
        self._input_keys = set()
        self._output_keys = set()
        self.register_outcomes(outcomes)
        self.register_input_keys(list(input_keys) + list(io_keys))
        self.register_output_keys(list(output_keys) + list(io_keys))
        self._preempt_requested = False

    def execute(self, ud):
        """Run the state; return one of its registered outcomes."""
        raise NotImplementedError('State.execute must be overridden')

    # outcomes and keys
    def register_outcomes(self, outcomes):
        for outcome in outcomes:
            if outcome not in self._outcomes:
                self._outcomes.append(outcome)

    def get_registered_outcomes(self):
        return tuple(self._outcomes)

    def register_io_keys(self, keys):
        self.register_input_keys(keys)
        self.register_output_keys(keys)

    def register_input_keys(self, keys):
        self._input_keys.update(keys)

    def register_output_keys(self, keys):
        self._output_keys.update(keys)

    def get_registered_input_keys(self):
        return tuple(self._input_keys)

    def get_registered_output_keys(self):
        return tuple(self._output_keys)

    # preemption
    def request_preempt(self):
        """Ask the state to stop as soon as it can."""
        self._preempt_requested = True

    def service_preempt(self):
        """Acknowledge a preempt request (the state has stopped)."""
        self._preempt_requested = False

    def recall_preempt(self):
        """Withdraw a preempt request."""
        self._preempt_requested = False

    def preempt_requested(self):
        return self._preempt_requested


class CBState(State):
    """A state that calls ``cb(userdata, *cb_args, **cb_kwargs)``."""

    def __init__(self, cb, cb_args=(), cb_kwargs=None, outcomes=(),
                 input_keys=(), output_keys=(), io_keys=()):
        State.__init__(self, outcomes, input_keys, output_keys, io_keys)
        self._cb = cb
        self._cb_args = list(cb_args)
        self._cb_kwargs = dict(cb_kwargs or {})
        if has_smach_interface(cb):     # a callback made with @cb_interface
            self.register_outcomes(cb.get_registered_outcomes())
            self.register_input_keys(cb.get_registered_input_keys())
            self.register_output_keys(cb.get_registered_output_keys())

    def execute(self, ud):
        return self._cb(ud, *self._cb_args, **self._cb_kwargs)
