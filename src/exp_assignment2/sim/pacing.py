"""Keeping simulated time in step with the wall clock (no ROS, no pybullet)."""
import time

# real_time_factor 0's ceiling: ROS nodes in other processes close their loops
# (odometry in, a velocity command out) in a few ms of wall time; at 20x that is
# a tenth of a simulated second, the most a 0.5 s command timeout and the
# controllers' gains can take. Unbounded, a world without a camera runs at
# 45-100x on 2 cores and its nodes' control diverges.
MAX_REAL_TIME_FACTOR = 20.0


class Pacer(object):
    """Holds simulated time to ``real_time_factor`` x wall time.

    After each physics step the loop asks :meth:`delay` how long to wait.
    ``real_time_factor`` 0 means as fast as possible, up to
    ``max_real_time_factor`` (0: no ceiling). A loop that falls more than
    ``max_lag`` s of simulated time behind (a slow frame, a pause) starts again
    from where it is instead of racing to catch up.
    """

    def __init__(self, real_time_factor, wall=time.monotonic, max_lag=0.25,
                 max_real_time_factor=MAX_REAL_TIME_FACTOR):
        for name, value in (('real_time_factor', real_time_factor),
                            ('max_real_time_factor', max_real_time_factor)):
            if not (value >= 0.0 and value != float('inf')):
                raise ValueError('%s must be >= 0 (0: as fast as possible), got %r'
                                 % (name, value))
        self.rtf, self.wall, self.max_lag = float(real_time_factor), wall, max_lag
        self.pace = self.rtf or float(max_real_time_factor)     # 0: no pace at all
        self.wall0 = self.sim0 = None

    def restart(self, sim_time):
        """Count from here (at start and after a pause)."""
        self.wall0, self.sim0 = self.wall(), sim_time

    def delay(self, sim_time):
        """Wall seconds to wait so that ``sim_time`` is not ahead of the wall."""
        if self.pace == 0.0:
            return 0.0
        if self.wall0 is None:
            self.restart(sim_time)
        due = self.sim0 + (self.wall() - self.wall0) * self.pace
        ahead = sim_time - due
        if ahead < -self.max_lag:
            self.restart(sim_time)
            return 0.0
        return max(ahead / self.pace, 0.0)
