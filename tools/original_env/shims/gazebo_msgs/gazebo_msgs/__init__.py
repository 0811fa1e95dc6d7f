"""``gazebo_msgs`` for the original-code environment: its state messages only.

Debian has no gazebo_msgs, and the original state_machine.py starts with
``from gazebo_msgs.msg import LinkState`` (never used afterwards). This
directory is on PYTHONPATH only inside tools/original_env/shell.sh, and only
when ``import gazebo_msgs.msg`` failed there before. There are no Gazebo
services or topics behind these types.
"""
