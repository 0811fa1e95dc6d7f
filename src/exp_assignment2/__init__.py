"""exp_assignment2: pet-robot behaviours on a pybullet stand-in for Gazebo.

Plain-Python modules (no ROS needed): ``minismach``, ``vision``, ``control``,
``commands``, ``world``, ``simulator``. ROS glue lives in the ``*_node``
modules, which the thin executables in ``scripts/`` start.
"""
