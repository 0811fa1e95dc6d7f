"""The grader: a teacher's folder of submissions in, one report out
(``bash tools/run grade``, docs/grading.md).

Pure parts, unit-tested without ROS: :mod:`.submissions` (the folder, read
safely), :mod:`.commands` (how each is started), :mod:`.profiles` and
:mod:`.metrics` (what "works" means), :mod:`.verdicts`, :mod:`.report`.
The run itself: :mod:`.sandbox` (bubblewrap, control groups),
:mod:`.truth` (the simulator's ground truth, outside the sandbox),
:mod:`.inside` (the driver in the sandbox), :mod:`.runner`, :mod:`.cli`.
"""
