"""The grader's fixtures of each shape a submission is handed in as (issue 47):
a whole catkin workspace, three packages that use each other, a repository of
the course holding assignments that cannot build here, and entries that are
no submission at all beside them. Each is the working dog of
test/grading_fixtures.py (``_package``) put in that shape; ``make(name, dest)``
writes one into the class folder ``dest``.
"""
import os
import shutil

import grading_fixtures
import release_fixtures

# name -> expected verdict
EXPECTED = {'workspace': 'passed', 'three_packages': 'passed', 'course_repo': 'passed',
            'pipe': 'not_built', 'corrupt': 'not_built', 'elsewhere': 'not_built',
            'nothing': 'not_built'}
TOPLEVEL = '/opt/ros/kinetic/share/catkin/cmake/toplevel.cmake'   # catkin_init_workspace's

WORKSPACE_README = """# My dog

    cd ~/catkin_ws
    catkin_make
    source devel/setup.bash
    roslaunch exp_assignment2 gazebo_world.launch
"""


def _write(path, text, mode=0o644):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(text)
    os.chmod(path, mode)


def _edit(path, old, new):
    with open(path) as f:
        text = f.read()
    assert old in text, (path, old)
    _write(path, text.replace(old, new), os.stat(path).st_mode & 0o777)


def _workspace(dest):
    """catkin_make's workspace as committed by a Kinetic student: the toplevel
    link into /opt/ros/kinetic (which says the release), build/ and devel/."""
    release_fixtures.kinetic_package(os.path.join(dest, 'src', 'exp_assignment2'))
    os.remove(os.path.join(dest, 'src', 'exp_assignment2', 'README.md'))
    os.symlink(TOPLEVEL, os.path.join(dest, 'src', 'CMakeLists.txt'))
    _write(os.path.join(dest, '.catkin_workspace'), '# This file currently only serves '
           'to mark the location of a catkin workspace for tool integration\n')
    _write(os.path.join(dest, 'build', 'CMakeCache.txt'), 'CMAKE_HOME_DIRECTORY:INTERNAL='
           '/home/student/catkin_ws/src\n')
    _write(os.path.join(dest, 'devel', 'setup.bash'), 'source /opt/ros/kinetic/setup.bash\n')
    share = os.path.join(dest, 'devel', 'share', 'exp_assignment2')
    os.makedirs(share)          # catkin's copy of the manifest: never a second package
    shutil.copy(os.path.join(dest, 'src', 'exp_assignment2', 'package.xml'), share)
    _write(os.path.join(dest, 'README.md'), WORKSPACE_README)


MSGS_XML = """<?xml version="1.0"?>
<package format="2">
  <name>dog_msgs</name><version>0.1.0</version><description>the dog's messages</description>
  <maintainer email="s@example.com">Student</maintainer><license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <build_depend>message_generation</build_depend><exec_depend>message_runtime</exec_depend>
  <depend>std_msgs</depend>
</package>
"""
MSGS_CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(dog_msgs)
find_package(catkin REQUIRED COMPONENTS message_generation std_msgs)
add_message_files(FILES BallSeen.msg)
generate_messages(DEPENDENCIES std_msgs)
catkin_package(CATKIN_DEPENDS message_runtime std_msgs)
"""
DESCRIPTION_XML = """<?xml version="1.0"?>
<package format="2">
  <name>dog_description</name><version>0.1.0</version><description>the dog</description>
  <maintainer email="s@example.com">Student</maintainer><license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>urdf</depend><exec_depend>xacro</exec_depend>
</package>
"""
# a C++ check of the model with ROS's urdf parser: the build needs liburdf-dev, which
# the grader installs before the run (a sandbox never installs)
DESCRIPTION_CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(dog_description)
find_package(catkin REQUIRED COMPONENTS urdf)
catkin_package()
include_directories(${catkin_INCLUDE_DIRS})
add_executable(check_model src/check_model.cpp)
target_link_libraries(check_model ${catkin_LIBRARIES})
"""
CHECK_MODEL = """#include <urdf/model.h>
int main(int argc, char **argv) {
  urdf::Model model;
  return argc > 1 && model.initFile(argv[1]) ? 0 : 1;
}
"""
THREE_README = """# The dog, in three packages

Build the messages first, then the rest:

    catkin_make --only-pkg-with-deps dog_msgs
    catkin_make -DCATKIN_WHITELIST_PACKAGES=""

Run:

    roslaunch exp_assignment2 gazebo_world.launch
"""


def _three_packages(dest):
    """Messages, the robot's description (with a C++ tool) and the behaviour,
    whose node publishes the messages' type and whose launch file finds the
    description."""
    behaviour = os.path.join(dest, 'dog_behaviour')
    grading_fixtures._package(behaviour)
    description = os.path.join(dest, 'dog_description')
    os.makedirs(description)
    shutil.move(os.path.join(behaviour, 'urdf'), os.path.join(description, 'urdf'))
    shutil.move(os.path.join(behaviour, 'config'), os.path.join(description, 'config'))
    _edit(os.path.join(description, 'urdf', 'robot.xacro'), '$(find exp_assignment2)',
          '$(find dog_description)')
    _write(os.path.join(description, 'package.xml'), DESCRIPTION_XML)
    _write(os.path.join(description, 'CMakeLists.txt'), DESCRIPTION_CMAKE)
    _write(os.path.join(description, 'src', 'check_model.cpp'), CHECK_MODEL)
    msgs = os.path.join(dest, 'dog_msgs')
    _write(os.path.join(msgs, 'package.xml'), MSGS_XML)
    _write(os.path.join(msgs, 'CMakeLists.txt'), MSGS_CMAKE)
    _write(os.path.join(msgs, 'msg', 'BallSeen.msg'), 'float32 offset\nfloat32 radius\n')
    launch = os.path.join(behaviour, grading_fixtures.LAUNCH)
    for old in ('$(find exp_assignment2)/urdf/robot.xacro',
                '$(find exp_assignment2)/config/motors_config.yaml',
                '$(find exp_assignment2)/urdf/ball.urdf'):
        _edit(launch, old, old.replace('exp_assignment2', 'dog_description'))
    dog = os.path.join(behaviour, grading_fixtures.DOG)
    _edit(dog, 'from std_msgs.msg import Float64\n',
          'from std_msgs.msg import Float64\nfrom dog_msgs.msg import BallSeen\n')
    _edit(dog, "            self.ball = (x / image.shape[1] - 0.5, radius / image.shape[1])\n",
          "            self.ball = (x / image.shape[1] - 0.5, radius / image.shape[1])\n"
          "            self.seen_pub.publish(BallSeen(*self.ball))\n")
    _edit(dog, "        self.ball = None\n        self.looking_since = None\n",
          "        self.ball = None\n        self.looking_since = None\n"
          "        self.seen_pub = rospy.Publisher('ball_seen', BallSeen, queue_size=1)\n")
    _edit(os.path.join(behaviour, 'package.xml'), '  <depend>rospy</depend>\n',
          '  <depend>rospy</depend>\n  <depend>dog_msgs</depend>\n'
          '  <exec_depend>dog_description</exec_depend>\n')
    _write(os.path.join(dest, 'README.md'), THREE_README)


BROKEN_XML = """<?xml version="1.0"?>
<package format="2">
  <name>%s</name><version>0.1.0</version><description>another assignment</description>
  <maintainer email="s@example.com">Student</maintainer><license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend><depend>%s</depend>
</package>
"""
BROKEN_CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(%s)
find_package(catkin REQUIRED COMPONENTS roscpp %s)
catkin_package()
add_executable(node src/node.cpp)
"""
COURSE_README = """# Experimental Robotics Laboratory

## Assignment 1: turtles

    roslaunch assignment1 turtles.launch

## Assignment 2: the dog and the ball

    roslaunch exp_assignment2 gazebo_world.launch

## Assignment 3: exploring

    roslaunch explorer explore.launch
"""


def _course_repo(dest):
    """The whole course in one repository; assignments 1 and 3 cannot build
    here (a dependency the machine lacks, C++ that does not compile)."""
    grading_fixtures._package(os.path.join(dest, 'assignment2', 'exp_assignment2'))
    os.remove(os.path.join(dest, 'assignment2', 'exp_assignment2', 'README.md'))
    for rel, name, depend in (('assignment1', 'assignment1', 'turtle_extras_not_in_debian'),
                              ('assignment3/src/explorer', 'explorer', 'explore_lite')):
        path = os.path.join(dest, rel)
        _write(os.path.join(path, 'package.xml'), BROKEN_XML % (name, depend))
        _write(os.path.join(path, 'CMakeLists.txt'), BROKEN_CMAKE % (name, depend))
        _write(os.path.join(path, 'src', 'node.cpp'), 'int main( { return 0 }\n')
        _write(os.path.join(path, 'launch', {'assignment1': 'turtles.launch'}.get(
            name, 'explore.launch')), '<launch><node name="n" pkg="%s" type="node"/></launch>\n'
            % name)
    _write(os.path.join(dest, 'README.md'), COURSE_README)


def make(name, dest):
    """Write the fixture ``name`` into the class folder ``dest``."""
    path = os.path.join(dest, name)
    if name == 'workspace':
        _workspace(path)
    elif name == 'three_packages':
        _three_packages(path)
    elif name == 'course_repo':
        _course_repo(path)
    elif name == 'pipe':
        os.mkfifo(path)
    elif name == 'corrupt':
        with open(path + '.zip', 'wb') as f:
            f.write(b'PK\x03\x04' + b'\x00' * 40 + b'not a zip at all')
    elif name == 'elsewhere':
        os.symlink('/etc', path)
    elif name == 'nothing':
        _write(os.path.join(path, 'notes', 'todo.txt'), 'finish the assignment\n')
    else:
        raise KeyError(name)
