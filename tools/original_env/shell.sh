#!/usr/bin/env bash
# A shell in which code written for the original Gazebo assignment runs
# unmodified against this package's simulator (opt-in: nothing outside this
# process's environment changes).
#   bash tools/original_env/shell.sh                 interactive shell
#   bash tools/original_env/shell.sh CMD [ARGS...]   run CMD in it
#   bash tools/original_env/shell.sh --package DIR [--with MORE]... [CMD...]
#       with the user's own package DIR built in an overlay workspace
#       (original_env/overlay/build.py): exp_assignment2 is then theirs, this one is
#       exp_assignment2_sim; each --with MORE (a catkin package, or a directory
#       of them) is built beside it, as what the class had installed
# It installs what the original imports and Debian can give (tf, scipy;
# imutils from PyPI), sources the catkin workspace, and sets PYTHONPATH so
# that cv2's HighGUI runs on one thread (the original calls cv2.imshow from
# several rospy callback threads, which hangs Debian's Qt-based OpenCV) and
# smach / smach_ros fall back to small replacements only where
# the real module does not import, and code that mixes tabs and spaces in its
# indentation is read as Python 2 read it. See tools/original_env/README.md.
# This file installs and execs; the environment itself is the library's
# (src/exp_assignment2/original_env/environment.py).
set -eo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
SRC="$(dirname "$(dirname "$HERE")")/src"
# ROS runs on Debian's python3, whatever python3 comes first on PATH.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"

# tf-tools, tf2-tools: rosrun tf tf_echo / view_frames, static_transform_publisher of tf and tf2_ros
# xterm: the terminal windows (gnome-terminal, launch-prefix="xterm -e") open in it
APT_PACKAGES=(python3-tf python3-scipy python3-opencv python3-numpy python3-pip python3-cv-bridge
              tf-tools tf2-tools xterm)
# The rest of ROS Noetic's desktop-full that Debian has and students' code may import or
# start, which every desktop-full install had (docs/original_env_supplies.md, "ROS Noetic
# desktop-full, package by package"); the -dev ones bring the package.xml that rosrun needs.
DESKTOP_FULL_PACKAGES=(
  python3-angles python3-bond python3-bondpy python3-smclib python3-nodelet
  python3-nodelet-topic-tools python3-dynamic-reconfigure libdynamic-reconfigure-config-init-mutex-dev
  python3-diagnostic-msgs python3-diagnostic-updater python3-diagnostic-analysis
  python3-diagnostic-common-diagnostics python3-shape-msgs python3-stereo-msgs python3-map-msgs
  python3-pcl-msgs python3-polled-camera python3-rviz python3-laser-geometry
  python3-interactive-markers python3-image-geometry python3-camera-calibration-parsers
  python3-tf-conversions python3-tf2-geometry-msgs python3-tf2-sensor-msgs python3-tf2-kdl
  python3-pykdl python3-actionlib-tools joint-state-publisher joint-state-publisher-gui
  ros-image-view libimage-view-dev
)
IMUTILS_VERSION=0.5.4
XACRO_VERSION=1.13.3    # ROS 1's xacro (PyPI's 2.x is ROS 2's), for $(find xacro)/xacro

log() { printf '[original-env] %s\n' "$*" >&2; }
# install_debian, install_pypi: one installer at a time
# shellcheck source=tools/install.sh
source "$HERE/../install.sh"

ENV_ARGS=()     # --package DIR, --with DIR (more catkin packages built beside it)
while [ $# -gt 0 ]; do
  case "$1" in
    --package) [ $# -ge 2 ] || { log "--package needs the directory of your package"; exit 2; }
               ENV_ARGS+=(--package "$2"); shift 2 ;;
    --package=*) ENV_ARGS+=(--package "${1#--package=}"); shift ;;
    --with) [ $# -ge 2 ] || { log "--with needs the directory of a catkin package"; exit 2; }
            ENV_ARGS+=(--with "$2"); shift 2 ;;
    --with=*) ENV_ARGS+=(--with "${1#--with=}"); shift ;;
    *) break ;;
  esac
done

# Installs are skipped when present, so this is cheap after the first run.
install_debian original-env "${APT_PACKAGES[@]}" "${DESKTOP_FULL_PACKAGES[@]}"
install_pypi original-env imutils "imutils==$IMUTILS_VERSION"
install_pypi original-env xacro "xacro==$XACRO_VERSION"

# The workspace sourced, the package built, the programs and stand-in packages
# in place, the start-up hooks on: the library says how (shell code) or why not.
# REPO/src first: the user's package may be called exp_assignment2 too.
env_code=$(/usr/bin/python3 -c 'import sys; sys.path.insert(0, sys.argv.pop(1))
from exp_assignment2.original_env.environment import main; sys.exit(main())' \
           "$SRC" "${ENV_ARGS[@]}") || exit 1
set +u
eval "$env_code"
log "enabled: $EXP2_ORIGINAL_ENV"

if [ $# -gt 0 ]; then
  exec "$@"
fi
# ~/.bashrc may put another python3 (pyenv) first again, or source another ROS
# setup: restore ours after it.
exec bash --rcfile <(printf '%s\n' '[ -f ~/.bashrc ] && . ~/.bashrc' \
  "export PATH=$(printf %q "$PATH") PYTHONPATH=$(printf %q "$PYTHONPATH")" \
  "export ROS_PACKAGE_PATH=$(printf %q "$ROS_PACKAGE_PATH")" \
  'PS1="(original-env) $PS1"') -i
