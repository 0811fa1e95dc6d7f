# Sourced with the workspace's setup.sh (catkin env hook).
#
# Debian's setuptools sends every `import distutils` to its own copy, which
# loads pkg_resources: 0.4 s of CPU in each roslaunch, rostest and rosclean
# (rosclean imports distutils for find_executable), or half of roslaunch's
# start. Python 3.11's own distutils does the same job at no cost. A value the
# user set is kept.
export SETUPTOOLS_USE_DISTUTILS="${SETUPTOOLS_USE_DISTUTILS:-stdlib}"
