"""The grader's fixture folder: submissions written here, one per way a
submission can end (test/fixtures/grading/base is the dog that works; the
others are it with one thing changed, e.g. ``missing_node``: its launch file
also names a node whose script is not there; those of roslaunch's rules for
a node that dies, and of a node in an xterm window, in
test/launch_rule_fixtures.py). ``make_folder(dest)`` writes them.

    /usr/bin/python3 test/grading_fixtures.py DEST    (for bench/ and by hand)
"""
import os
import re
import shutil
import sys
import tarfile
import zipfile

import launch_rule_fixtures
from broken_fixtures import BROKEN_CPP, HOSTILE, IDLE, RAISES  # noqa: F401 (as before)
import start_fixtures

HERE = os.path.dirname(os.path.abspath(__file__))
BASE = os.path.join(HERE, 'fixtures', 'grading', 'base')
STUDENT = os.path.join(HERE, 'fixtures', 'student_pkg')    # its robot and controllers
DOG = os.path.join('scripts', 'dog.py')

# name -> expected verdict ('raises': roslaunch runs on without the dog, and so does the run)
EXPECTED = {'works': 'passed', 'tabs': 'passed', 'cpp_broken': 'not_built',
            'raises': 'failed_checks', 'idle': 'failed_checks', 'hostile': None,
            'zipped': 'passed', 'tarred': 'passed', 'old_names': 'passed',
            'own_world': 'passed', 'alternatives': 'passed', 'other_name': 'passed',
            'missing_node': 'passed', 'imshow': 'passed', 'renamed': 'passed',
            'tutorials': 'passed', 'helper_dies': 'passed', 'required_dies': 'crashed',
            'xterm_dog': 'passed'}
EXPECTED.update(__import__('shape_fixtures').EXPECTED)     # each shape a submission comes in
EXPECTED.update(__import__('release_fixtures').EXPECTED)   # the ROS release it was written for
EXPECTED.update(__import__('py2_fixtures').EXPECTED)       # Python 2, and the keyboard
EXPECTED.update(start_fixtures.EXPECTED)     # a README's cd and typo, a start script's timing

# as the assignment's template does: every frame shown, in the subscriber's
# thread, with the circle found on the ball drawn on it
IMSHOW_TITLE = "dog's camera"
IMSHOW_FIND = """            self.ball = (x / image.shape[1] - 0.5, radius / image.shape[1])
"""
IMSHOW_DRAW = """            self.ball = (x / image.shape[1] - 0.5, radius / image.shape[1])
            cv2.circle(image, (int(x), int(y)), int(radius), (0, 255, 255), 2)
"""
IMSHOW_SHOW = """        else:
            self.ball = None
        cv2.imshow("%s", image)
        cv2.waitKey(1)
""" % IMSHOW_TITLE


def _imshow(dest):
    path = os.path.join(dest, DOG)
    with open(path) as f:
        text = f.read()
    shown = text.replace('(x, _), radius', '(x, y), radius').replace(
        IMSHOW_FIND, IMSHOW_DRAW).replace("""        else:
            self.ball = None
""", IMSHOW_SHOW)
    assert shown.count('cv2.') == text.count('cv2.') + 3
    _replace(dest, DOG, shown)


def _package(dest):
    """The dog that works: the base fixture with the student fixture's robot."""
    shutil.copytree(BASE, dest)
    os.makedirs(os.path.join(dest, 'config'))
    for rel in ('urdf/robot.xacro', 'urdf/robot.gazebo', 'config/motors_config.yaml'):
        shutil.copy(os.path.join(STUDENT, rel), os.path.join(dest, rel))
    os.chmod(os.path.join(dest, DOG), 0o755)


def _replace(dest, rel, text):
    with open(os.path.join(dest, rel), 'w') as f:
        f.write(text)
    os.chmod(os.path.join(dest, rel), 0o755)


def _tabs(dest):
    """Python 2's habit: eight spaces of indentation written as a tab, which
    Python 3 refuses beside four-space lines."""
    path = os.path.join(dest, DOG)
    with open(path) as f:
        text = f.read()
    with open(path, 'w') as f:
        f.write(re.sub(r'(?m)^        ', '\t', text))


def _cpp_broken(dest):
    os.makedirs(os.path.join(dest, 'src'))
    _replace(dest, 'src/counter.cpp', BROKEN_CPP)
    with open(os.path.join(dest, 'CMakeLists.txt')) as f:
        text = f.read().replace('COMPONENTS rospy', 'COMPONENTS roscpp rospy')
    text += ('include_directories(${catkin_INCLUDE_DIRS})\n'
             'add_executable(counter src/counter.cpp)\n'
             'target_link_libraries(counter ${catkin_LIBRARIES})\n')
    with open(os.path.join(dest, 'CMakeLists.txt'), 'w') as f:
        f.write(text)


LAUNCH = os.path.join('launch', 'gazebo_world.launch')
# a node whose script is not in the package: roslaunch says it cannot launch
# it and runs every other node, so the dog still does its work
MISSING_NODE = '  <node name="ghost" pkg="exp_assignment2" type="ghost.py" output="screen"/>\n'


def _missing_node(dest):
    path = os.path.join(dest, LAUNCH)
    with open(path) as f:
        text = f.read()
    with open(path, 'w') as f:
        f.write(text.replace('</launch>', MISSING_NODE + '</launch>'))


# a Kinetic-era launch file: robot_state_publisher's old node type
OLD_STATE_PUBLISHER = '''    <node name="robot_state_publisher" pkg="robot_state_publisher"
          type="state_publisher"/>
    <node name="controller_spawner"'''

# a package of the student's own name, in this package's world (its
# simulator.launch, the course robot) rather than a Gazebo world of its own
OWN_WORLD_PACKAGE = 'dog_on_sim'
OWN_WORLD_README = """# A dog on the course's simulator

    roslaunch exp_assignment2 simulator.launch robot_model:=original
    rosrun dog_on_sim dog.py
"""


def _own_world(dest):
    shutil.rmtree(os.path.join(dest, 'launch'))
    for name in ('package.xml', 'CMakeLists.txt', DOG):
        path = os.path.join(dest, name)
        with open(path) as f:
            text = f.read()
        text = text.replace('exp_assignment2', OWN_WORLD_PACKAGE)
        # the course robot's head controller, as this package's simulator names it
        text = text.replace('joint_head_controller', 'joint_position_controller')
        # the world's ball starts 2.2 m ahead: back away first, then play
        text = text.replace("""        twist = Twist()
""", """        twist = Twist()
        self.steps = getattr(self, 'steps', 0) + 1
        if self.steps <= 50:                # 5 s at the node's 10 Hz
            twist.linear.x = -0.6
            self.cmd.publish(twist)
            return
""")
        with open(path, 'w') as f:
            f.write(text)
    with open(os.path.join(dest, 'README.md'), 'w') as f:
        f.write(OWN_WORLD_README)


# Students rename things: the robot spawned as robot2 in its own namespace, its
# head turning on camera_joint moved by a camera_position_controller, the ball
# called toy. A teacher watching sees the dog play: judged by their roles.
RENAMED = (('joint_head_controller', 'camera_position_controller'),
           ('joint_head', 'camera_joint'), ('/robot/', '/robot2/'),
           ('ns="/robot"', 'ns="/robot2"'), ('name="robot/robot_description"',
                                             'name="robot2/robot_description"'),
           ('<group ns="robot">', '<group ns="robot2">'), ('-model robot ', '-model robot2 '),
           ('--namespace=/robot ', '--namespace=/robot2 '), ('-model ball ', '-model toy '))


def _renamed(dest):
    changed = []
    for rel in (LAUNCH, DOG, 'urdf/robot.xacro', 'config/motors_config.yaml'):
        path = os.path.join(dest, rel)
        with open(path) as f:
            text = f.read()
        for old, new in RENAMED:
            text = text.replace(old, new)
        changed.append(text)
        with open(path, 'w') as f:
            f.write(text)
    assert 'robot2' in changed[0] and '-model toy' in changed[0] and 'joint_head' not in \
        ''.join(changed), changed[0]


# A node that imports what ROS Noetic's desktop-full had and Debian's ROS has
# not: actionlib_tutorials' messages (a tutorial's client the student kept)
TUTORIALS_IMPORT = """import actionlib_tutorials.msg
from geometry_msgs.msg import Twist
"""


def _tutorials(dest):
    path = os.path.join(dest, DOG)
    with open(path) as f:
        text = f.read()
    text = text.replace('from geometry_msgs.msg import Twist\n', TUTORIALS_IMPORT).replace(
        "    rospy.init_node('dog')\n", "    rospy.init_node('dog')\n"
        "    GOAL = actionlib_tutorials.msg.FibonacciGoal(order=5)\n")
    assert text.count('actionlib_tutorials') == 2
    _replace(dest, DOG, text)
    path = os.path.join(dest, 'package.xml')
    with open(path) as f:
        text = f.read()
    with open(path, 'w') as f:
        f.write(text.replace('</package>', '  <exec_depend>actionlib_tutorials</exec_depend>\n'
                                           '</package>'))


def make_folder(dest, names=None):
    """Write the fixture submissions named (default: all) into ``dest``."""
    import py2_fixtures
    import release_fixtures
    import shape_fixtures
    os.makedirs(dest, exist_ok=True)
    with open(os.path.join(dest, 'grading.yaml'), 'w') as f:
        f.write(release_fixtures.FOLDER_SETTINGS + py2_fixtures.FOLDER_SETTINGS)
    names = list(names or EXPECTED)
    scratch = os.path.join(dest, '.scratch')
    for name in names:
        if name in shape_fixtures.EXPECTED:
            shape_fixtures.make(name, dest)
            continue
        if name in release_fixtures.EXPECTED:
            release_fixtures.make(name, dest)
            continue
        if name in py2_fixtures.EXPECTED:
            py2_fixtures.make(name, dest)
            continue
        if name in ('zipped', 'tarred'):
            package = os.path.join(scratch, name, 'my_dog')      # one level down
            _package(package)
            if name == 'zipped':
                with zipfile.ZipFile(os.path.join(dest, name + '.zip'), 'w') as archive:
                    for root, _dirs, files in os.walk(os.path.join(scratch, name)):
                        for f in files:
                            full = os.path.join(root, f)
                            info = zipfile.ZipInfo.from_file(
                                full, os.path.relpath(full, os.path.join(scratch, name)))
                            with open(full, 'rb') as src:
                                archive.writestr(info, src.read())
            else:
                with tarfile.open(os.path.join(dest, name + '.tar.gz'), 'w:gz') as archive:
                    archive.add(package, arcname='my_dog')
            continue
        package = os.path.join(dest, name)
        _package(package)
        if name == 'tabs':
            _tabs(package)
        elif name == 'cpp_broken':
            _cpp_broken(package)
        elif name == 'raises':
            _replace(package, DOG, RAISES)
        elif name == 'idle':
            _replace(package, DOG, IDLE)
        elif name == 'hostile':
            _replace(package, DOG, HOSTILE)
        elif name == 'missing_node':
            _missing_node(package)
        elif name == 'old_names':
            path = os.path.join(package, 'launch', 'gazebo_world.launch')
            with open(path) as f:
                text = f.read()
            with open(path, 'w') as f:
                f.write(text.replace('    <node name="controller_spawner"', OLD_STATE_PUBLISHER))
        elif name == 'own_world':
            _own_world(package)
        elif name == 'alternatives':
            start_fixtures.alternatives(package)
        elif name == 'other_name':
            _replace(package, 'README.md', start_fixtures.OTHER_NAME)
        elif name == 'imshow':
            _imshow(package)
        elif name == 'renamed':
            _renamed(package)
        elif name == 'tutorials':
            _tutorials(package)
        elif name in launch_rule_fixtures.FIXTURES:
            launch_rule_fixtures.FIXTURES[name](package)
        elif name in start_fixtures.MAKERS:
            start_fixtures.MAKERS[name](package)
    shutil.rmtree(scratch, ignore_errors=True)
    return dest


if __name__ == '__main__':
    print(make_folder(sys.argv[1], sys.argv[2:] or None))
