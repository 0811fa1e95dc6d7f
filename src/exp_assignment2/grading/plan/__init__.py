"""Plan: what each submission is and how it is started, decided on the
teacher's side before any run (no ROS): the folder's entries
(:mod:`.submissions`, :mod:`.unpacking`), the teacher's side's one copy of
each (:mod:`.copies`), their catkin packages and what a run
builds (:mod:`.packages`, :mod:`.assignment`, :mod:`.build_deps`), the ROS
release (:mod:`.ros_release`), the profile and grading.yaml (:mod:`.profiles`,
:mod:`.teacher_file`), the README read as a person reads it (:mod:`.commands`,
:mod:`.choose`, :mod:`.own_names`, :mod:`.shell`, :mod:`.start_script`,
:mod:`.launch_nodes`) and when each command starts (:mod:`.starts`); all of it
one :class:`~.spec.RunSpec` per run (:mod:`.planning`)."""
