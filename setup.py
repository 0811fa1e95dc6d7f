"""Installs the exp_assignment2 Python library (src/exp_assignment2) for catkin."""
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(
    packages=['exp_assignment2'],
    package_dir={'': 'src'},
))
