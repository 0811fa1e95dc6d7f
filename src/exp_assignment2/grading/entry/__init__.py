"""Entry: what each entry of the folder is, on the teacher's side, before any run
(no ROS, nothing of it run): the folder's entries (:mod:`.submissions`), their
files taken as handed in (:mod:`.unpacking`; a git repository's commit through
:mod:`.git_entries`, :mod:`.git_objects`, :mod:`.git_packs`, at a deadline:
:mod:`.deadlines`), the teacher's side's one copy of each (:mod:`.copies`), their
catkin packages and what a run builds of them (:mod:`.packages`), and what the
build needs from Debian (:mod:`.build_deps`); :mod:`.reading` reads a
submission's text files within a limit. How each is started is
:mod:`exp_assignment2.grading.plan`'s."""
