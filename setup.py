"""Installs the exp_assignment2 Python library (src/exp_assignment2) for catkin."""
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(
    packages=['exp_assignment2', 'exp_assignment2.behaviour', 'exp_assignment2.minismach',
              'exp_assignment2.nodes', 'exp_assignment2.original_env',
              'exp_assignment2.original_env.overlay', 'exp_assignment2.ros', 'exp_assignment2.sim',
              'exp_assignment2.sim.gl', 'exp_assignment2.sim.plugins'],
    package_dir={'': 'src'},
))
