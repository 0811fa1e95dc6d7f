"""The grader: a teacher's folder of submissions in, one report out
(``bash tools/run grade``, docs/grading.md). A submission's trip, a room each:

* :mod:`.plan`: what each entry of the folder is, its packages, its ROS
  release, its commands and when each starts, decided on the teacher's side
  before any run (a :class:`~.plan.spec.RunSpec` per run);
* :mod:`.run`: the run in its sandbox, with its display, its driver inside
  and the ground truth outside, here or on a Dask worker;
* :mod:`.judge`: its verdict from what was seen outside the student's code,
  its robot, head and ball by their roles, its checks and points;
* :mod:`.report`: the class's pages, the students' pages, Gradescope's files;
* :mod:`.similarity`: the code submissions share, for a person to read.

On top: :mod:`.cli` (the command line), :mod:`.record` (a run's record: its
declared fields, its one writer and reader), :mod:`.progress` (the terminal's line) and
:mod:`.paths` (where things are in the repository).
"""
