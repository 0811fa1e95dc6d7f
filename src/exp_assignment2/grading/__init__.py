"""The grader: a teacher's folder of submissions in, one report out
(``bash tools/run grade``, docs/grading.md).

Pure parts, unit-tested without ROS: :mod:`.submissions` (the folder, read
safely), :mod:`.commands` (how each is started), :mod:`.profiles` and
:mod:`.metrics` (what "works" means), :mod:`.verdicts`, :mod:`.report`,
:mod:`.windows` (what is kept of a run's windows, and when they showed it).
The run itself: :mod:`.sandbox` (bubblewrap, control groups),
:mod:`.truth` (the simulator's ground truth, outside the sandbox),
:mod:`.inside` (the driver in the sandbox), :mod:`.display` (the run's own
display, its windows captured), :mod:`.runner`, :mod:`.cli`.
"""
