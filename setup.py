"""Installs the exp_assignment2 Python library (src/exp_assignment2) for catkin:
every package under src/, found, so that a new one is never left out of the
install space; and the data folders inside it that are not Python packages
(original_env's start-up hooks, programs, shims and launch-surface stand-in
packages), which the original-code environment and the grader read from
beside the library (exp_assignment2.layout)."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import find_packages, setup

setup(**generate_distutils_setup(
    packages=find_packages('src'),
    package_dir={'': 'src'},
    package_data={'exp_assignment2.original_env': [
        'startup/*.py', 'programs/*', 'shims/**/*.py', 'stand_in_packages/**/*']},
))
