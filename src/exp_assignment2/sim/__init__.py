"""The simulator that stands in for Gazebo; the only package that imports pybullet."""
