"""The original-code environment: code written for the original Gazebo
assignment runs unmodified against this package's simulator.

* ``environment``: the environment (a dict) for a command, with the user's
  package built (``overlay``); tools/original_env/shell.sh and the grader's
  driver both start commands with it.
* ``overlay``: the user's catkin package built in an overlay workspace.
* ``launch_packages``: ``stand_in_packages/`` (gazebo_ros, xacro,
  controller_manager, ...) copied where roslaunch can run them.
* Data, not modules: ``startup/`` (the directory first on PYTHONPATH:
  sitecustomize.py and the exp2_* hooks, importable on their own: Python 2's
  tab rule, cv2 HighGUI on one thread, rospy's XML-RPC end, node start),
  ``shims/`` (smach, smach_ros where none is installed), ``programs/`` (the
  ``python`` launcher and ``rosrun`` put first on PATH) and
  ``stand_in_packages/``.

tools/original_env/README.md describes what each piece does.
"""
