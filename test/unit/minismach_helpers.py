"""A state both minismach test modules use (not a test by itself)."""
from exp_assignment2 import minismach as smach


class Returns(smach.State):
    """Returns ``outcome`` every time, counting its runs."""

    def __init__(self, outcome, outcomes=('a', 'b')):
        smach.State.__init__(self, outcomes=list(outcomes))
        self.outcome = outcome
        self.runs = 0

    def execute(self, ud):
        self.runs += 1
        return self.outcome
