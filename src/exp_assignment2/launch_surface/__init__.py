"""The Gazebo launch surface for a user's own package and launch file.

What ``gazebo_ros``, ``xacro`` and ``controller_manager`` give a Gazebo
launch file, on this package's simulator: the executables in
``src/exp_assignment2/original_env/stand_in_packages/`` (on ROS_PACKAGE_PATH only inside
``tools/run original-env``) are two-line wrappers of the ``main`` functions
here. Command lines are read by plain functions (``*_args`` modules and
:func:`gzserver.translate`), unit-tested without ROS; the rest is rospy glue.

* ``gzserver``: Gazebo's server command line -> the simulator's.
* ``gzclient``: the viewer (rviz) when there is a display, else one line.
* ``spawn_args`` / ``spawn_model``: gazebo_ros' spawn_model.
* ``spawner_args`` / ``spawner``: controller_manager's spawner.
* ``xacro_runner``: xacro from PyPI (the ROS 1 one), ``--inorder`` accepted.
* ``model_markers``: /gazebo/model_states as rviz markers, for the viewer.
"""
