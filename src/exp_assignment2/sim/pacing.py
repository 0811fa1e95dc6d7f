"""Keeping simulated time in step with the wall clock (no ROS, no pybullet)."""
import time


class Pacer(object):
    """Holds simulated time to ``real_time_factor`` x wall time.

    After each physics step the loop asks :meth:`delay` how long to wait.
    ``real_time_factor`` 0 means as fast as possible. A loop that falls more
    than ``max_lag`` s of simulated time behind (a slow frame, a pause) starts
    again from where it is instead of racing to catch up.
    """

    def __init__(self, real_time_factor, wall=time.monotonic, max_lag=0.25):
        if not (real_time_factor >= 0.0 and real_time_factor != float('inf')):
            raise ValueError('real_time_factor must be >= 0 (0: as fast as possible), got %r'
                             % (real_time_factor,))
        self.rtf, self.wall, self.max_lag = float(real_time_factor), wall, max_lag
        self.wall0 = self.sim0 = None

    def restart(self, sim_time):
        """Count from here (at start and after a pause)."""
        self.wall0, self.sim0 = self.wall(), sim_time

    def delay(self, sim_time):
        """Wall seconds to wait so that ``sim_time`` is not ahead of the wall."""
        if self.rtf == 0.0:
            return 0.0
        if self.wall0 is None:
            self.restart(sim_time)
        due = self.sim0 + (self.wall() - self.wall0) * self.rtf
        ahead = sim_time - due
        if ahead < -self.max_lag:
            self.restart(sim_time)
            return 0.0
        return max(ahead / self.rtf, 0.0)
