"""exp_assignment2: pet-robot behaviours on a pybullet stand-in for Gazebo.

* Plain Python, no ROS needed (unit-tested without a master): ``arena``,
  ``grid``, ``geometry``, ``grammar``, ``grounding``, ``planning``,
  ``control``, ``vision``, ``refusal``, ``waiting``, ``minismach`` and the
  ``behaviour`` package (the states of both scenarios).
* ``sim``: the simulator; the only package that imports pybullet. Its
  ``plugins`` are its ROS side.
* ``ros``: rospy implementations of the behaviours' interfaces.
* ``nodes``: one module per executable in ``scripts/``.
"""
