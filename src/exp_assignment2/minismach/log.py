"""smach's logging (``smach.log``): what the containers report, and where it goes.

As in SMACH, the containers say what they do (a machine starting, each
transition, its end; an error as it is raised) through four functions that
print to stdout until someone hands in others with :func:`set_loggers`:
smach_ros hands rospy's (``set_loggers(rospy.loginfo, rospy.logwarn,
rospy.logdebug, rospy.logerr)``), so a ROS node's state machine reports in
its ROS log. The functions in use are the package's ``loginfo``, ``logwarn``,
``logdebug`` and ``logerr`` (``smach.loginfo is rospy.loginfo`` once
smach_ros is imported, as in SMACH); the ones defined here are the printing
defaults, as ``smach.log``'s are.
"""


def loginfo(msg):
    print('[  INFO ] : ' + str(msg))


def logwarn(msg):
    print('[  WARN ] : ' + str(msg))


def logdebug(msg):
    print('[ DEBUG ] : ' + str(msg))


def logerr(msg):
    print('[ ERROR ] : ' + str(msg))


NAMES = ('loginfo', 'logwarn', 'logdebug', 'logerr')
_current = {'loginfo': loginfo, 'logwarn': logwarn, 'logdebug': logdebug, 'logerr': logerr}


def set_loggers(info, warn, debug, error):
    """Send what SMACH reports to these four functions (SMACH's argument order)."""
    _current.update(loginfo=info, logwarn=warn, logdebug=debug, logerr=error)


def current(name):
    """The function now in use for ``name`` (one of :data:`NAMES`)."""
    return _current[name]


def info(msg):
    _current['loginfo'](msg)


def warn(msg):
    _current['logwarn'](msg)


def debug(msg):
    _current['logdebug'](msg)


def error(msg):
    _current['logerr'](msg)
