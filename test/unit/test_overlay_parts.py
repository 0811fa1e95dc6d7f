"""The plain-Python parts of original-env --package (src/exp_assignment2/original_env/overlay/):
what of a package directory counts, the first error of a build log, the catkin
components a CMakeLists.txt names, the launch files of the second package name,
and the merged exp_assignment2 Python package. No ROS, no build."""
import os
import subprocess
import sys
import textwrap

import pytest

from exp_assignment2.original_env.overlay import (build_errors, python_package, sim_package,
                                                  source_tree, stand_ins)



def write(path, text='', mode=None):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(text)
    if mode:
        os.chmod(path, mode)


# ---- source_tree ---------------------------------------------------------

@pytest.fixture
def package(tmp_path):
    root = tmp_path / 'pkg'
    write(str(root / 'package.xml'), '<package/>')
    write(str(root / 'scripts' / 'node.py'), 'print(1)\n', 0o755)
    return str(root)


def test_build_outputs_and_version_control_do_not_count(package):
    before = source_tree.content_hash(package)
    for junk in ('build/x.o', 'devel/setup.bash', 'install/a', '.git/HEAD',
                 'scripts/__pycache__/node.cpython-311.pyc', 'scripts/old.pyc'):
        write(os.path.join(package, junk), 'junk')
    assert source_tree.content_hash(package) == before
    assert source_tree.counted_entries(package) == ['package.xml', 'scripts']


@pytest.mark.parametrize('change', ['content', 'mode', 'new file', 'nested build dir'])
def test_any_change_of_the_package_counts(package, change):
    before = source_tree.content_hash(package)
    script = os.path.join(package, 'scripts', 'node.py')
    if change == 'content':
        write(script, 'print(2)\n', 0o755)
    elif change == 'mode':
        os.chmod(script, 0o644)
    elif change == 'new file':
        write(os.path.join(package, 'msg', 'Ball.msg'), 'float64 x\n')
    else:   # only the top-level build/ is a build's
        write(os.path.join(package, 'docs', 'build', 'index.html'), 'x')
    assert source_tree.content_hash(package) != before


def test_link_farm_links_what_counts_and_is_rebuilt(package, tmp_path):
    write(os.path.join(package, 'build', 'x.o'), 'junk')
    farm = str(tmp_path / 'ws' / 'src' / 'pkg')
    source_tree.link_farm(package, farm)
    assert sorted(os.listdir(farm)) == ['package.xml', 'scripts']
    assert os.readlink(os.path.join(farm, 'scripts')) == os.path.join(package, 'scripts')
    os.unlink(os.path.join(package, 'scripts', 'node.py'))
    os.rmdir(os.path.join(package, 'scripts'))
    source_tree.link_farm(package, farm)
    assert os.listdir(farm) == ['package.xml']


# ---- build_errors --------------------------------------------------------

OV = '/ov/src/upkg'


def to_user(path):
    return '/home/me/upkg' + path[len(OV):] if path == OV or path.startswith(OV + '/') else None


def first(log):
    return build_errors.first_error(textwrap.dedent(log), to_user, '/ov/src')


def test_a_compiler_error_names_the_users_file_and_line():
    assert first('''\
        [ 96%] Building CXX object upkg/CMakeFiles/n.dir/src/n.cpp.o
        /ov/src/upkg/src/n.cpp: In function 'int main(int, char**)':
        /ov/src/upkg/src/n.cpp:17:17: error: 'centre' was not declared in this scope
        make[2]: *** [upkg/CMakeFiles/n.dir/build.make:76: n.cpp.o] Error 1
        ''') == ('/home/me/upkg/src/n.cpp:17', "'centre' was not declared in this scope")


def test_genmsg_names_the_message_file():
    # catkin_make's output for a field of an unknown type
    where, message = first('''\
        Generating for action Planning
        CMake Error at /ov/build/upkg/cmake/exp_assignment2-genmsg.cmake:3 (message):
          Could not find messages which
          '/ov/src/upkg/msg/BallSighting.msg' depends on.  Did you
          forget to specify generate_messages(DEPENDENCIES ...)?

          Cannot locate message [floot64] in package [exp_assignment2] with paths
          [['/ov/src/upkg/msg',
          '/ov/devel/share/exp_assignment2/msg']]
        Call Stack (most recent call first):
          /usr/share/genmsg/cmake/genmsg-extras.cmake:311 (include)
          upkg/CMakeLists.txt:30 (generate_messages)


        -- Configuring incomplete, errors occurred!
        ''')
    assert where == '/home/me/upkg/msg/BallSighting.msg'
    assert 'Cannot locate message [floot64]' in message and '/ov/src' not in message
    assert '\n' not in message


def test_a_generators_error_names_the_message_file_once():
    # empy's line for a field without a name (genmsg's InvalidMsgSpec)
    assert first('''\
        /usr/share/genmsg/cmake/pkg-genmsg.cmake.em:56: error: <class 'genmsg.base.InvalidMsgSpec'>: /ov/src/upkg/msg/Ball.msg: Invalid declaration: float64
        Traceback (most recent call last):
        ''') == ('/home/me/upkg/msg/Ball.msg', 'Invalid declaration: float64')


def test_a_cmake_error_in_cmakelists_names_its_line():
    where, message = first('''\
        CMake Error at upkg/CMakeLists.txt:21 (find_package):
          By not providing "FindNoSuchThing.cmake" in CMAKE_MODULE_PATH this project
          has asked CMake to find a package configuration file provided by
          "NoSuchThing", but CMake did not find one.

        -- Configuring incomplete, errors occurred!
        ''')
    assert where == '/home/me/upkg/CMakeLists.txt:21'
    assert message.startswith('By not providing "FindNoSuchThing.cmake"')


def test_a_cmake_error_outside_names_the_call_in_cmakelists():
    where, _ = first('''\
        CMake Error at /usr/share/catkin/cmake/safe_execute_process.cmake:11 (message):
          execute_process(...) returned error code 1
        Call Stack (most recent call first):
          /usr/share/catkin/cmake/em_expand.cmake:25 (safe_execute_process)
          upkg/CMakeLists.txt:30 (generate_messages)

        ''')
    assert where == '/home/me/upkg/CMakeLists.txt:30'


def test_a_link_error_names_the_source_of_the_object(tmp_path):
    src = tmp_path / 'src'
    write(str(src / 'upkg' / 'src' / 'n.cpp'))

    def user(path):
        prefix = str(src / 'upkg')
        return '/home/me/upkg' + path[len(prefix):] if path.startswith(prefix + '/') else None
    log = ("/usr/bin/ld: CMakeFiles/n.dir/src/n.cpp.o: in function `main':\n"
           "n.cpp:(.text+0x21b): undefined reference to `helper()'\n"
           "collect2: error: ld returned 1 exit status\n")
    assert build_errors.first_error(log, user, str(src)) == (
        '/home/me/upkg/src/n.cpp', "undefined reference to `helper()'")


def test_a_compiler_path_relative_to_the_build_directory_is_the_users(tmp_path):
    # with ccache's base_dir the compiler, run in build/upkg, is given relative paths
    src = tmp_path / 'src'
    write(str(src / 'upkg' / 'src' / 'n.cpp'))
    os.makedirs(str(tmp_path / 'build' / 'upkg'))

    def user(path):
        prefix = str(src / 'upkg')
        return '/home/me/upkg' + path[len(prefix):] if path.startswith(prefix + '/') else None
    log = "../../src/upkg/src/n.cpp:17:17: error: 'centre' was not declared in this scope\n"
    assert build_errors.first_error(log, user, str(src)) == (
        '/home/me/upkg/src/n.cpp:17', "'centre' was not declared in this scope")


def test_anything_else_gives_the_first_line_saying_error():
    assert first('ok\nmake: *** [all] Error 2\n') == (None, 'make: *** [all] Error 2')
    assert first('all fine\n') is None


def test_a_long_message_is_one_line_of_bounded_length():
    text = build_errors.one_line('word\n  ' * 200)
    assert '\n' not in text and len(text) == build_errors.MAX_MESSAGE and text.endswith('…')


# ---- stand_ins -----------------------------------------------------------

def test_the_catkin_components_are_read_as_cmake_would():
    text = '''
    find_package(catkin REQUIRED COMPONENTS
      roscpp   # the C++ client
      # gazebo_ros   (commented out)
      tf
      message_generation)
    find_package(OpenCV REQUIRED)
    find_package(catkin REQUIRED COMPONENTS roscpp xacro)
    '''
    assert stand_ins.catkin_components(text) == ['roscpp', 'tf', 'message_generation', 'xacro']
    assert stand_ins.catkin_components('find_package(catkin REQUIRED)') == []


def test_the_probe_says_what_is_missing():
    out = ('-- exp2-probe found roscpp\n-- exp2-probe missing gazebo_ros\n'
           '-- Configuring done\n')
    assert stand_ins.parse_probe(out) == (['roscpp'], ['gazebo_ros'])


def test_a_stand_in_is_an_empty_catkin_package_config(tmp_path):
    stand_ins.write_stand_ins(['gazebo_ros'], str(tmp_path))
    with open(str(tmp_path / 'share' / 'gazebo_ros' / 'cmake' / 'gazebo_rosConfig.cmake')) as f:
        config = f.read()
    assert 'set(gazebo_ros_FOUND TRUE)' in config
    assert 'set(gazebo_ros_INCLUDE_DIRS "")' in config and 'set(gazebo_ros_LIBRARIES "")' in config


# ---- sim_package ---------------------------------------------------------

def test_launch_files_refer_to_the_second_name():
    text = '''<launch>
      <arg name="world" default="$(find exp_assignment2)/config/world_dog.yaml"/>
      <param name="d" textfile="$(eval find('exp_assignment2') + '/urdf/robot.urdf')"/>
      <node name="gazebo" pkg="exp_assignment2" type="simulator.py"/>
      <node pkg='exp_assignment2' type="x.py"/>
      <include file="$(find gazebo_ros)/launch/empty_world.launch"/>
      <node pkg="robot_state_publisher" type="robot_state_publisher" name="exp_assignment2"/>
    </launch>'''
    out = sim_package.rewrite_launch(text)
    assert 'exp_assignment2_sim)/config' in out and "find('exp_assignment2_sim')" in out
    assert out.count('pkg="exp_assignment2_sim"') == 1 and "pkg='exp_assignment2_sim'" in out
    assert '$(find gazebo_ros)' in out and 'name="exp_assignment2"' in out


def test_the_second_package_links_the_repository(tmp_path):
    repo = tmp_path / 'repo'
    write(str(repo / 'package.xml'), '<package/>')
    write(str(repo / 'launch' / 'sim.launch'), '<node pkg="exp_assignment2" type="a"/>')
    write(str(repo / 'launch' / 'include' / 'n.launch'), '$(find exp_assignment2)')
    write(str(repo / 'scripts' / 'a'), '', 0o755)
    target = str(tmp_path / 'packages' / sim_package.NAME)
    sim_package.write_package(str(repo), target)
    sim_package.write_package(str(repo), target)        # again: replaced, not failing
    assert sorted(os.listdir(target)) == ['launch', 'package.xml', 'scripts']
    assert os.path.islink(os.path.join(target, 'scripts'))
    with open(os.path.join(target, 'launch', 'include', 'n.launch')) as f:
        assert f.read() == '$(find exp_assignment2_sim)'
    with open(os.path.join(target, 'package.xml')) as f:
        assert '<name>exp_assignment2_sim</name>' in f.read()


# ---- python_package ------------------------------------------------------

def test_the_merged_package_gives_the_users_types_then_ours(tmp_path):
    def devel(root, types):
        pkg = root / 'devel' / 'exp_assignment2'
        write(str(pkg / '__init__.py'))
        write(str(pkg / 'msg' / '__init__.py'),
              ''.join('from ._%s import *\n' % t for t in types))
        for t in types:
            write(str(pkg / 'msg' / ('_%s.py' % t)), '%s = %r\n' % (t, str(root.name)))
        return pkg
    user = devel(tmp_path / 'user', ['Planning', 'Ball'])
    ours = devel(tmp_path / 'ours', ['Planning', 'Gesture'])
    # ours has a library, as catkin_python_setup's devel __init__.py says
    src = tmp_path / 'ours' / 'src'
    write(str(src / 'exp_assignment2' / 'vision.py'), 'WHO = "ours"\n')
    write(str(src / 'exp_assignment2' / '__init__.py'), 'LIBRARY = True\n')
    write(str(ours / '__init__.py'), "__extended_path = '%s'.split(';')\n" % src)
    merged = tmp_path / 'merged' / 'exp_assignment2'
    python_package.write_merged(str(merged), str(user), str(ours))
    code = ('import exp_assignment2, exp_assignment2.vision as v\n'
            'from exp_assignment2.msg import Planning, Ball, Gesture\n'
            'print(Planning, Ball, Gesture, v.WHO, exp_assignment2.LIBRARY)\n')
    out = subprocess.run([sys.executable, '-c', code], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, universal_newlines=True, cwd=str(tmp_path),
                         env=dict(os.environ, PYTHONPATH=str(tmp_path / 'merged')))
    assert out.stdout.split() == ['user', 'user', 'ours', 'ours', 'True'], out.stdout
