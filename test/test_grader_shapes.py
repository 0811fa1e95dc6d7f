"""The grader end to end on each shape a submission is handed in as
(test/shape_fixtures.py, graded with the rest of the fixture folder by
test/grading_run.py): a catkin workspace as committed, three packages that
use each other, a repository of the course whose other assignments cannot
build here, and entries that are no submission at all, beside the others.
"""
import json
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import shape_fixtures  # noqa: E402

pytestmark = pytest.mark.xdist_group('grader')


def _page(graded, name, folder='pages'):
    with open(os.path.join(graded['out'], folder, name + '.html')) as f:
        return f.read()


def test_every_shape_gets_its_verdict_and_the_class_its_report(graded):
    got = {n: graded['by_name'][n]['verdict'] for n in shape_fixtures.EXPECTED}
    assert got == shape_fixtures.EXPECTED, {
        n: graded['by_name'][n]['reason'] for n in shape_fixtures.EXPECTED}
    reasons = {n: graded['by_name'][n]['reason'] for n in ('pipe', 'corrupt', 'elsewhere',
                                                           'nothing')}
    assert reasons == {
        'pipe': 'the submission: not a file nor a folder (a fifo, a socket or a device)',
        'corrupt': 'the submission: the archive does not unpack: File is not a zip file',
        'elsewhere': 'the submission: a link (-> /etc), not followed: put the submission '
                     'itself in the folder',
        'nothing': 'the submission: no package.xml in it (a catkin package has one)'}
    assert os.path.isfile(os.path.join(graded['out'], 'index.html'))
    assert 'Traceback' not in graded['proc'].stdout


def test_a_workspace_builds_its_package_and_leaves_catkins_link_out(graded):
    run = graded['runs']['workspace']
    assert run['packages'] == [{'name': 'exp_assignment2', 'rel': 'src/exp_assignment2',
                                'built': True, 'why': 'built: the run is about it'}]
    assert ('src/CMakeLists.txt: left out: a link out of the submission (-> %s)'
            % shape_fixtures.TOPLEVEL) in run['notes']
    # committed build/ and devel/ never reach the run
    work = os.path.join(graded['out'], 'runs', 'workspace', 'work')
    assert not os.path.exists(os.path.join(work, 'src', 'build'))


def test_three_packages_build_in_order_and_the_messages_are_used(graded):
    run = graded['runs']['three_packages']
    assert [(p['name'], p['built']) for p in run['packages']] == [
        ('exp_assignment2', True), ('dog_description', True), ('dog_msgs', True)]
    by = {p['name']: p['why'] for p in run['packages']}
    assert by['dog_msgs'] == by['dog_description'] == 'built: used by exp_assignment2'
    # the description's C++ tool needs liburdf-dev: installed before the run, outside it
    installed = subprocess.run(['dpkg-query', '-W', '-f=${Status}', 'liburdf-dev'],
                               stdout=subprocess.PIPE, universal_newlines=True).stdout
    assert installed.endswith(' installed'), installed
    assert 'liburdf-dev' in graded['proc'].stdout or 'liburdf-dev' not in run['notes']
    assert 'Packages (3 found, 3 built)' in _page(graded, 'three_packages')
    assert 'Packages (3 found, 3 built)' in _page(graded, 'three_packages', 'feedback')
    assert run['error_count'] == 0


def test_a_course_repository_runs_this_assignment_only(graded):
    run = graded['runs']['course_repo']
    assert run['commands'] == ['roslaunch exp_assignment2 gazebo_world.launch']
    built = {p['name']: (p['built'], p['why']) for p in run['packages']}
    assert built == {
        'assignment1': (False, 'not built: nothing the run starts uses it'),
        'exp_assignment2': (True, 'built: the run is about it'),
        'explorer': (False, 'not built: nothing the run starts uses it')}
    left = {c['command']: c['why'] for c in run['readme_commands'] if not c['ran']}
    assert left['roslaunch assignment1 turtles.launch'] == (
        "left out: another part of the README (`Assignment 1: turtles` of README.md) starts "
        "assignment1, not this assignment's exp_assignment2")
    assert 'Packages (3 found, 1 built)' in _page(graded, 'course_repo')


def test_the_report_json_has_a_row_for_every_entry(graded):
    with open(os.path.join(graded['out'], 'report.json')) as f:
        names = {s['name'] for s in json.load(f)['submissions']}
    assert set(shape_fixtures.EXPECTED) <= names
