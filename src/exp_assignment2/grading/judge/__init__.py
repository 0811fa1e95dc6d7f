"""Judge: what a run did, read outside the student's code (no ROS): its logs
(:mod:`.logs`), the facts gathered once (:mod:`.seen`), the verdict as one
ordered table of rules (:mod:`.verdicts`), the robot, head and ball by their
roles (:mod:`.roles`, :mod:`.model_parts`), the checks' figures
(:mod:`.metrics`) and their points (:mod:`.scores`)."""
