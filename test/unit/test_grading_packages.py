"""A submission's packages, what a run builds of them, and what they need
from Debian (exp_assignment2.grading.entry.packages, build_deps)."""
import os

from exp_assignment2.grading.entry import build_deps
from exp_assignment2.grading.entry import packages

MANIFEST = '''<package format="2"><name>%s</name><version>0.0.1</version>
%s</package>'''


def make(root, rel, name, depends=(), files=None):
    path = os.path.join(str(root), rel)
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, 'package.xml'), 'w') as f:
        f.write(MANIFEST % (name, ''.join('<depend>%s</depend>' % d for d in depends)))
    for file_rel, text in (files or {}).items():
        os.makedirs(os.path.dirname(os.path.join(path, file_rel)), exist_ok=True)
        with open(os.path.join(path, file_rel), 'w') as f:
            f.write(text)
    return path


def by_name(listed):
    return {p['name']: (p['built'], p['why']) for p in listed}


def test_three_packages_messages_description_state_machine(tmp_path):
    """The state machine imports the messages' types and its launch file
    finds the description: all three built, messages before their user."""
    make(tmp_path, 'pet_msgs', 'pet_msgs', ['message_generation'])
    make(tmp_path, 'pet_description', 'pet_description', files={'urdf/dog.urdf': '<robot/>'})
    make(tmp_path, 'pet_behaviour', 'pet_behaviour', ['rospy', 'pet_msgs'], {
        'scripts/fsm.py': 'from pet_msgs.msg import Command\n',
        'launch/all.launch': '<launch><param name="d" textfile="$(find pet_description)'
                             '/urdf/dog.urdf"/></launch>'})
    found = packages.find(str(tmp_path))
    main = packages.main_package(found, preferred=['pet_behaviour'])
    listed, built = packages.choose(found, main, ['roslaunch pet_behaviour all.launch'])
    assert [p.name for p in built] == ['pet_behaviour', 'pet_description', 'pet_msgs']
    assert by_name(listed)['pet_msgs'] == (True, 'built: used by pet_behaviour')
    assert by_name(listed)['pet_behaviour'] == (True, 'built: the run is about it')


def test_a_repository_of_the_whole_course_builds_what_the_run_uses(tmp_path):
    make(tmp_path, 'assignment1/src/pkg1', 'assignment1', ['turtlesim_extra'])
    make(tmp_path, 'assignment2/exp_assignment2', 'exp_assignment2',
         files={'launch/gazebo_world.launch': '<launch/>'})
    make(tmp_path, 'assignment3/explore', 'explore_lite', ['costmap_2d'])
    found = packages.find(str(tmp_path))
    main = packages.main_package(found, ['gazebo_world.launch'])
    assert main.name == 'exp_assignment2'
    listed, built = packages.choose(found, main, ['roslaunch exp_assignment2 gazebo_world.launch'])
    assert [p.name for p in built] == ['exp_assignment2']
    assert by_name(listed)['explore_lite'] == (
        False, 'not built: nothing the run starts uses it')


def test_a_solution_in_two_packages_started_by_their_own_launch_files(tmp_path):
    make(tmp_path, 'exp_assignment2', 'exp_assignment2',
         files={'launch/gazebo_world.launch': '<launch/>'})
    make(tmp_path, 'my_dog', 'my_dog', files={'launch/dog.launch': '<launch/>'})
    found = packages.find(str(tmp_path))
    main = packages.main_package(found, ['gazebo_world.launch'])
    listed, built = packages.choose(found, main, [
        'roslaunch exp_assignment2 gazebo_world.launch', 'roslaunch --wait my_dog dog.launch'])
    assert {p.name for p in built} == {'exp_assignment2', 'my_dog'}


def test_a_launch_file_given_by_its_path_starts_its_package(tmp_path):
    make(tmp_path, 'a', 'a', files={'launch/x.launch': '<launch/>'})
    make(tmp_path, 'b', 'b', files={'launch/run.launch': '<launch/>'})
    found = packages.find(str(tmp_path))
    listed, built = packages.choose(found, found[0], ['roslaunch launch/run.launch'])
    assert {p.name for p in built} == {'a', 'b'}


def test_two_packages_of_one_name_build_once(tmp_path):
    make(tmp_path, 'exp_assignment2', 'exp_assignment2')
    make(tmp_path, 'backup/old/exp_assignment2', 'exp_assignment2')
    found = packages.find(str(tmp_path))
    main = packages.main_package(found)
    listed, built = packages.choose(found, main, [])
    assert [p.rel for p in built] == ['exp_assignment2']
    assert listed[1]['why'] == ('not built: another package named exp_assignment2 '
                                '(exp_assignment2) is, as catkin takes one')


def test_a_broken_manifest_is_a_package_with_its_error(tmp_path):
    os.makedirs(str(tmp_path / 'bad'))
    (tmp_path / 'bad' / 'package.xml').write_text('<package><name>oops')
    found = packages.find(str(tmp_path))
    assert found[0].name == 'bad' and 'does not parse' in found[0].error


def test_what_debian_must_give_is_found_before_the_run(tmp_path):
    path = make(tmp_path, 'vision', 'vision', ['urdf', 'rospy', 'python-numpy', 'eigen',
                                               'no_such_thing_anywhere'], {
        'CMakeLists.txt': 'find_package(catkin REQUIRED COMPONENTS roscpp tf2_ros)\n'
                          'find_package(OpenCV REQUIRED)  # the camera\n'})
    known = {'liburdf-dev', 'python3-numpy', 'libeigen3-dev', 'libopencv-dev',
             'libtf2-ros-dev', 'python3-tf2-ros'}
    needs = build_deps.resolve([packages.Package('vision', '.', path, packages.read_manifest(
        path)[1])], provided={'rospy', 'roscpp'}, known=known)
    assert needs['debian'] == ['liburdf-dev', 'python3-numpy', 'libeigen3-dev',
                               'libtf2-ros-dev', 'python3-tf2-ros', 'libopencv-dev']
    assert needs['unresolved'] == {'vision': ['no_such_thing_anywhere']}
    assert needs['notes'] == ['rosdep: vision: Cannot locate rosdep definition for '
                              '[no_such_thing_anywhere] (no Debian package here; a build that '
                              'needs it fails)']


def test_candidates_are_debians_own_names():
    assert build_deps.candidates('image_transport', 'ros') == [
        'libimage-transport-dev', 'python3-image-transport', 'ros-image-transport']
    assert build_deps.candidates('python-scipy', 'ros') == ['python3-scipy']
    assert build_deps.candidates('Eigen3', 'cmake') == ['libeigen3-dev']
    assert build_deps.candidates('Threads', 'cmake') == []


def test_a_failed_build_says_what_rosdep_could_not_find():
    notes = ['rosdep: dog: Cannot locate rosdep definition for [pcl_ros] (no Debian package '
             'here; a build that needs it fails)', 'another note']
    said = build_deps.said_by_rosdep(
        'src/cloud.cpp:1: fatal error: pcl_ros/point_cloud.h: No such file or directory', notes)
    assert said.endswith('; rosdep: dog: Cannot locate rosdep definition for [pcl_ros]')
    unrelated = 'src/dog.cpp:3: expected ‘;’ before ‘return’'
    assert build_deps.said_by_rosdep(unrelated, notes) == unrelated
