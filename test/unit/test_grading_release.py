"""The ROS release a submission runs in (exp_assignment2.grading.plan.ros_release)."""
import os

from exp_assignment2.grading.plan import ros_release

ALLOWED = ['kinetic', 'melodic', 'noetic']
DIFF_DRIVE = '''<robot><gazebo>
  <plugin name="differential_drive_controller" filename="libgazebo_ros_diff_drive.so">
    %s<leftJoint>joint_left_wheel</leftJoint>
  </plugin></gazebo></robot>'''


def write(root, rel, text):
    path = os.path.join(str(root), rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(text)


def test_what_the_submission_says(tmp_path):
    write(tmp_path / 'a', 'README.md', 'Tested on ROS Kinetic with Gazebo 7; also noetic.')
    assert ros_release.said(str(tmp_path / 'a')) == ('kinetic', 'its README.md says "Kinetic"')
    write(tmp_path / 'b', 'docker/Dockerfile', 'FROM osrf/ros:melodic-desktop-full\n')
    write(tmp_path / 'b', 'README.md', 'ROS Noetic')
    assert ros_release.said(str(tmp_path / 'b'))[0] == 'melodic'      # the image first
    write(tmp_path / 'c', 'README.md', 'Ubuntu 20.04, then `source /opt/ros/noetic/setup.bash`')
    assert ros_release.said(str(tmp_path / 'c'))[0] == 'noetic'
    write(tmp_path / 'd', 'README.md', 'run it')
    assert ros_release.said(str(tmp_path / 'd')) == (None, None)
    link = ('src/CMakeLists.txt: left out: a link out of the submission '
            '(-> /opt/ros/kinetic/share/catkin/cmake/toplevel.cmake)')
    assert ros_release.said(str(tmp_path / 'd'), [link]) == (
        'kinetic', 'its catkin workspace was made in ROS Kinetic (src/CMakeLists.txt)')


def test_a_vendored_package_s_readme_does_not_say_the_release(tmp_path):
    """A repository that carries slam_gmapping's sources: that package's README says
    "melodic"; the student's own README says Kinetic, once."""
    repo = tmp_path / 'repo'
    write(repo, 'README.md', 'Written for ROS Kinetic.')
    write(repo, 'my_dog/package.xml', '<package><name>my_dog</name></package>')
    write(repo, 'slam_gmapping/package.xml', '<package><name>slam_gmapping</name></package>')
    write(repo, 'slam_gmapping/README.md', 'melodic, melodic: see the melodic-devel branch')
    write(repo, 'slam_gmapping/docker/Dockerfile', 'FROM ros:melodic\n')
    got = ros_release.said(str(repo), package_dir=str(repo / 'my_dog'))
    assert got == ('kinetic', 'its README.md says "Kinetic"')
    # the graded package's own README counts, wherever it is
    write(repo, 'my_dog/README.md', 'Noetic, Noetic.')
    assert ros_release.said(str(repo), package_dir=str(repo / 'my_dog'))[0] == 'noetic'


def test_what_differs_between_releases_for_a_submission(tmp_path):
    write(tmp_path / 'legacy', 'urdf/robot.gazebo', DIFF_DRIVE % '<legacyMode>true</legacyMode>')
    found = ros_release.features(str(tmp_path / 'legacy'))
    assert found['legacy_mode'] == ['true'] and not found['frames']
    assert ros_release.differs('noetic', 'kinetic', found)
    assert not ros_release.differs('noetic', 'melodic', found)   # frames: its code reads none
    write(tmp_path / 'off', 'urdf/robot.gazebo', DIFF_DRIVE % '<legacyMode>false</legacyMode>')
    assert not ros_release.differs('noetic', 'kinetic', ros_release.features(
        str(tmp_path / 'off')))
    write(tmp_path / 'absent', 'urdf/robot.gazebo', DIFF_DRIVE % '')   # Kinetic's default
    assert ros_release.differs('noetic', 'kinetic', ros_release.features(
        str(tmp_path / 'absent')))
    write(tmp_path / 'legacy', 'scripts/where.py', 'listener.lookupTransform("odom", "b", t)')
    assert ros_release.differs('noetic', 'melodic', ros_release.features(
        str(tmp_path / 'legacy')))                                 # robot/odom in Melodic


def test_the_first_release_and_those_to_try_next(tmp_path):
    write(tmp_path, 'urdf/robot.gazebo', DIFF_DRIVE % '<legacyMode>true</legacyMode>')
    chosen = ros_release.choose(ALLOWED, 'noetic', None, str(tmp_path))
    assert chosen == {'release': 'noetic', 'next': ['kinetic'],
                      'why': "the course's first: the submission names none"}
    assert ros_release.choose(ALLOWED, 'noetic', 'melodic', str(tmp_path)) == {
        'release': 'melodic', 'why': 'grading.yaml names it', 'next': []}
    write(tmp_path, 'README.md', 'Built on ROS Kinetic.')
    assert ros_release.choose(ALLOWED, 'noetic', None, str(tmp_path))['release'] == 'kinetic'
    write(tmp_path, 'README.md', 'Built on ROS Indigo (Ubuntu 14.04).')    # not a course's
    assert ros_release.choose(ALLOWED, 'kinetic', None, str(tmp_path))['next'] == ['melodic']


def test_a_submission_without_a_robot_of_its_own_is_judged_on_the_course_robot(tmp_path):
    course = tmp_path / 'course'
    write(course, 'robot_original.urdf', DIFF_DRIVE % '<legacyMode>true</legacyMode>')
    write(tmp_path / 'mine', 'scripts/dog.py', 'print(1)')
    found = ros_release.features(str(tmp_path / 'mine'), str(course))
    assert found['legacy_mode'] == ['true']


def test_the_better_release_counts():
    runs = [{'name': 'a', 'release': 'noetic', 'label': 'a', 's': 60.0},
            {'name': 'a', 'release': 'kinetic', 'label': 'a-kinetic', 's': 100.0}]
    kept, others = ros_release.counted(runs, lambda r: r['s'])
    assert [r['label'] for r in kept] == ['a-kinetic'] and [r['label'] for r in others] == ['a']
    runs[1]['s'] = 60.0            # a tie: the one run first
    assert [r['label'] for r in ros_release.counted(runs, lambda r: r['s'])[0]] == ['a']
    assert ros_release.counted(runs[:1], lambda r: r['s']) == (runs[:1], [])
