"""Plan: how each submission is started, decided on the teacher's side before any
run (no ROS), from what :mod:`exp_assignment2.grading.entry` found it to be: its
main package (:mod:`.assignment`), the ROS release (:mod:`.ros_release`), the
profile and grading.yaml (:mod:`.profiles`, :mod:`.profile_keys`,
:mod:`.teacher_file`, :mod:`.calibration`, :mod:`.episodes`), the README read as a
person reads it (:mod:`.commands`, :mod:`.choose`, :mod:`.own_names`,
:mod:`.shell`, :mod:`.start_script`, :mod:`.launch_nodes`, :mod:`.defaults`) and
when each command starts (:mod:`.starts`); all of it one :class:`~.spec.RunSpec`
per run (:mod:`.planning`)."""
