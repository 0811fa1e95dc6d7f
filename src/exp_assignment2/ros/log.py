"""rospy's loggers in the shapes the pure modules take."""
import rospy

from exp_assignment2.refusal import RefusalLog


class RosLog(object):
    """``info``/``warn``/``error`` with (fmt, *args), as :class:`~exp_assignment2.behaviour.interfaces.Log`."""

    def __init__(self, prefix=''):
        self.prefix = prefix

    def info(self, fmt, *args):
        rospy.loginfo(self.prefix + fmt, *args)

    def warn(self, fmt, *args):
        rospy.logwarn(self.prefix + fmt, *args)

    def error(self, fmt, *args):
        rospy.logerr(self.prefix + fmt, *args)


def refusal_log(interface):
    """Throttled ERROR lines for refused input on ``interface``."""
    return RefusalLog(interface, rospy.logerr)
