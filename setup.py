"""Installs the exp_assignment2 Python library (src/exp_assignment2) for catkin:
every package under src/, found, so that a new one is never left out of the
install space."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import find_packages, setup

setup(**generate_distutils_setup(
    packages=find_packages('src'),
    package_dir={'': 'src'},
))
