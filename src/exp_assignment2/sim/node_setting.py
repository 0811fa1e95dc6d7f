"""Where one of the simulator's settings comes from (no ROS): the node's
private parameter when given (a launch argument), else the environment
variable the grader sets in each run's sandbox (however the student's
launch files start the simulator), else the default. A bad value is an
error naming where it came from."""
import os


def chosen(parameter, name, env, read, environ=None):
    """``read(value)`` of the parameter ``name`` when given (not None nor ''),
    else of ``environ[env]`` (os.environ by default); ``read``'s ValueError
    comes back as the same type, its message led by where the value was."""
    environ = os.environ if environ is None else environ
    given, where = parameter, name
    if given is None or given == '':
        given, where = environ.get(env), env
    try:
        return read(given)
    except ValueError as exc:
        raise type(exc)('%s: %s' % (where, exc))
