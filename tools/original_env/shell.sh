#!/usr/bin/env bash
# A shell in which code written for the original Gazebo assignment runs
# unmodified against this package's simulator (opt-in: nothing outside this
# process's environment changes).
#   bash tools/original_env/shell.sh                 interactive shell
#   bash tools/original_env/shell.sh CMD [ARGS...]   run CMD in it
#   bash tools/original_env/shell.sh --package DIR [--with MORE]... [CMD...]
#       with the user's own package DIR built in an overlay workspace
#       (overlay/build.py): exp_assignment2 is then theirs, this one is
#       exp_assignment2_sim; each --with MORE (a catkin package, or a directory
#       of them) is built beside it, as what the class had installed
# It installs what the original imports and Debian can give (tf, scipy;
# imutils from PyPI), sources the catkin workspace, and sets PYTHONPATH so
# that cv2's HighGUI runs on one thread (the original calls cv2.imshow from
# several rospy callback threads, which hangs Debian's Qt-based OpenCV) and
# smach / smach_ros fall back to small replacements only where
# the real module does not import, and code that mixes tabs and spaces in its
# indentation is read as Python 2 read it. See tools/original_env/README.md.
set -eo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
WS="${EXP2_WS:-$HOME/.cache/exp_assignment2_ws}"
# ROS runs on Debian's python3, whatever python3 comes first on PATH.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"

# tf-tools, tf2-tools: rosrun tf tf_echo / view_frames, static_transform_publisher of tf and tf2_ros
APT_PACKAGES=(python3-tf python3-scipy python3-opencv python3-numpy python3-pip python3-cv-bridge
              tf-tools tf2-tools)
IMUTILS_VERSION=0.5.4
XACRO_VERSION=1.13.3    # ROS 1's xacro (PyPI's 2.x is ROS 2's), for $(find xacro)/xacro

log() { printf '[original-env] %s\n' "$*" >&2; }
# install_debian, install_pypi: one installer at a time
# shellcheck source=tools/install.sh
source "$HERE/../install.sh"

PACKAGE_DIR=
WITH_DIRS=()    # --with DIR: more catkin packages built beside it (a class's own packages)
while [ $# -gt 0 ]; do
  case "$1" in
    --package) [ $# -ge 2 ] || { log "--package needs the directory of your package"; exit 2; }
               PACKAGE_DIR=$2; shift 2 ;;
    --package=*) PACKAGE_DIR=${1#--package=}; shift ;;
    --with) [ $# -ge 2 ] || { log "--with needs the directory of a catkin package"; exit 2; }
            WITH_DIRS+=("$2"); shift 2 ;;
    --with=*) WITH_DIRS+=("${1#--with=}"); shift ;;
    *) break ;;
  esac
done
# --with alone: the first of them is built as --package would be
if [ -z "$PACKAGE_DIR" ] && [ ${#WITH_DIRS[@]} -gt 0 ]; then
  PACKAGE_DIR=${WITH_DIRS[0]}
  WITH_DIRS=("${WITH_DIRS[@]:1}")
fi

# Installs are skipped when present, so this is cheap after the first run.
install_debian original-env "${APT_PACKAGES[@]}"
install_pypi original-env imutils "imutils==$IMUTILS_VERSION"
install_pypi original-env xacro "xacro==$XACRO_VERSION"

if [ ! -f "$WS/devel/setup.bash" ]; then
  log "no catkin workspace at $WS: build it first with: bash tools/run setup"
  exit 1
fi
set +u
# shellcheck disable=SC1091
source "$WS/devel/setup.bash"
export ROS_HOME="${ROS_HOME:-$WS/ros_home}"

if [ -n "$PACKAGE_DIR" ]; then
  with_args=()
  for dir in "${WITH_DIRS[@]}"; do with_args+=(--with "$dir"); done
  overlay_env=$(/usr/bin/python3 "$HERE/overlay/build.py" --workspace "$WS" "${with_args[@]}" \
                "$PACKAGE_DIR") || exit 1
  eval "$overlay_env"
fi

# The original's scripts start with "#!/usr/bin/env python": Debian has no
# "python", and another one later on PATH could not import Debian's rospy.
# python_launcher.sh is /usr/bin/python3 that also starts a script mixing tabs
# and spaces in its indentation with Python 2's tab rule. Copied (renamed into
# place, so a program starting now never misses it), not linked: an executable
# file in the package would be one catkin does not install.
export EXP2_ORIGINAL_BIN="$WS/original_env_bin"
mkdir -p "$EXP2_ORIGINAL_BIN"
# python2 too: `#!/usr/bin/env python2` ran on the students' machines.
for name in python python2 python3; do
  install -m 0755 "$HERE/python_launcher.sh" "$EXP2_ORIGINAL_BIN/.$name.$$"
  mv -f "$EXP2_ORIGINAL_BIN/.$name.$$" "$EXP2_ORIGINAL_BIN/$name"
done
# rosrun: ROS's, but a script naming Python 2 in its first line, or without its
# execute bit, starts as on the students' machines (gui/exp2_node_start.py;
# roslaunch gets the same through sitecustomize.py)
install -m 0755 "$HERE/rosrun.py" "$EXP2_ORIGINAL_BIN/.rosrun.$$"
mv -f "$EXP2_ORIGINAL_BIN/.rosrun.$$" "$EXP2_ORIGINAL_BIN/rosrun"

# gazebo_ros, xacro and controller_manager for the user's launch files, executable
# (packages/README.md); env.py puts them first on ROS_PACKAGE_PATH.
EXP2_LAUNCH_PACKAGES=$(/usr/bin/python3 "$HERE/launch_packages.py" "$WS")
export EXP2_LAUNCH_PACKAGES
# `xacro` on PATH is that xacro too, as ROS's is (command="xacro ..." in a
# launch file), not PyPI's script, whose load_yaml fails under Debian's PyYAML 6
ln -sfn "$EXP2_LAUNCH_PACKAGES/xacro/xacro" "$EXP2_ORIGINAL_BIN/.xacro.$$"
mv -fT "$EXP2_ORIGINAL_BIN/.xacro.$$" "$EXP2_ORIGINAL_BIN/xacro"

# Decided now, with the real interpreter and the workspace's PYTHONPATH, so a
# real smach (or smach_ros) is never shadowed.
eval "$(/usr/bin/python3 "$HERE/env.py")"
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
