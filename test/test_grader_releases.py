"""The grader end to end on the ROS release each submission was written for
(test/release_fixtures.py, graded with the fixture folder by
test/grading_run.py, whose grading.yaml makes Noetic the course's first)."""
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

pytestmark = pytest.mark.xdist_group('grader')


def _runs_of(graded, name):
    return [r for r in graded['report']['runs'] if r['name'] == name]


def test_a_kinetic_dog_that_says_so_runs_in_kinetic(graded):
    (run,) = _runs_of(graded, 'kinetic_dog')
    assert (run['release'], run['verdict']) == ('kinetic', 'passed'), run['reason']
    assert run['release_why'] == 'its README.md says "Kinetic"'


def test_a_silent_kinetic_dog_turns_away_in_noetic_and_counts_in_kinetic(graded):
    """In Noetic the Kinetic-steered dog turns away from the ball it sees; within the
    short run it still comes near the ball, but never to rest at it, so its head and
    most behaviours are not judged: the run shows the release was wrong, and Kinetic's
    run, judged on more, counts."""
    runs = {r['release']: r for r in _runs_of(graded, 'kinetic_silent')}
    evidence = runs['noetic']['release_evidence']
    assert evidence['release'] and 'turned away from the ball it saw' in evidence['why']
    assert runs['kinetic']['verdict'] == 'passed', runs['kinetic']['reason']
    assert runs['kinetic']['label'] == 'kinetic_silent-kinetic'
    assert "in ROS noetic (the course's first: the submission names none): run again in " \
        "kinetic" in runs['kinetic']['release_why']
    summary = graded['by_name']['kinetic_silent']
    assert summary['verdict'] == 'passed' and summary['main_run'] == 'kinetic_silent-kinetic'
    assert [(t['release'], t['counted']) for t in summary['releases']] == [
        ('noetic', False), ('kinetic', True)]
    with open(os.path.join(graded['out'], 'pages', 'kinetic_silent.html')) as f:
        page = f.read()
    assert 'ROS release: <b>kinetic</b>' in page and 'counts (the better)' in page


def test_a_workspace_made_in_kinetic_runs_there_and_the_others_in_the_courses(graded):
    (run,) = _runs_of(graded, 'workspace')
    assert run['release'] == 'kinetic' and run['verdict'] == 'passed', run['reason']
    assert run['release_why'] == ('its catkin workspace was made in ROS Kinetic '
                                  '(src/CMakeLists.txt)')
    (works,) = _runs_of(graded, 'works')
    assert (works['release'], works['release_why']) == ('noetic', 'its README.md says "Noetic"')
    (other,) = _runs_of(graded, 'other_name')        # its README names none: the course's
    assert other['release'] == 'noetic' and other['verdict'] == 'passed'
