"""original-env --package: the user's package built in an overlay workspace
(:func:`build.build`), and its parts: the source tree, the catkin components'
stand-ins, Debian's development packages, the first error of a failed build,
this repository under a second name and the merged ``exp_assignment2``."""
