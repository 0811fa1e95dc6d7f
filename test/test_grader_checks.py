"""The checks a teacher would sign, end to end (docs/grading.md, "What works
means", "The same ball for everyone"): the course's reference dog
(config/grading/reference/dog: the follower that stops where the ball's radius
is 100 px of its 800 px image, with its walks, its sleep at home and its head's
turns) and the same dog that never sleeps, graded as a teacher grades them
under dog_course (the course's ball, seed 1, for both), in a folder of their
own: the reference passes every check, the sleepless one loses exactly the
sleep's points, the ball is the same in both runs, and the pages say which
ball it was and when each check was decided."""
import json
import os
import shutil
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
REFERENCE = os.path.join(REPO, 'config', 'grading', 'reference', 'dog')
GRADE = ['bash', os.path.join(REPO, 'tools', 'run'), 'grade']

pytestmark = pytest.mark.xdist_group('grader_checks')


def never_sleeps(dest):
    """The reference whose NORMAL never ends its walk: it never goes to sleep."""
    shutil.copytree(REFERENCE, dest)
    path = os.path.join(dest, 'scripts', 'state_machine.py')
    with open(path) as f:
        text = f.read()
    assert 'PLACES = (2, 3)' in text
    with open(path, 'w') as f:
        f.write(text.replace('PLACES = (2, 3)', 'PLACES = (10 ** 6, 10 ** 6)'))


@pytest.fixture(scope='module')
def checked(tmp_path_factory):
    base = tmp_path_factory.mktemp('checks')
    folder = base / 'class'
    shutil.copytree(REFERENCE, str(folder / 'reference'))
    never_sleeps(str(folder / 'never_sleeps'))
    out = str(base / 'report')
    proc = subprocess.run(GRADE + [str(folder), '--out', out, '--profile', 'dog_course',
                                   '--jobs', '2'], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=1500)
    assert os.path.exists(os.path.join(out, 'report.json')), proc.stdout[-3000:]
    with open(os.path.join(out, 'report.json')) as f:
        report = json.load(f)
    return {'out': out, 'proc': proc, 'runs': {r['label']: r for r in report['runs']},
            'by_name': {s['name']: s for s in report['submissions']}}


def said(run):
    return [(c['name'], c['value'], c['passed'], c['detail']) for c in run['checks']]


def test_the_courses_follower_passes_every_check(checked):
    run = checked['runs']['reference']
    assert run['verdict'] == 'passed', said(run)
    assert all(c['passed'] for c in run['checks']), said(run)      # judged, every one
    summary = checked['by_name']['reference']
    assert summary['score'] == 100 and not summary['pending'], said(run)
    reach = {c['metric']: c for c in run['checks']}['approaches']
    assert reach['value'] >= 1 and reach['at'] is not None


def test_a_dog_that_never_sleeps_loses_exactly_the_sleeps_points(checked):
    run = checked['runs']['never_sleeps']
    points = {c['name']: (c['points'], c['max_points'])
              for c in checked['by_name']['never_sleeps']['score_checks']}
    assert points.pop('sleeps at home') == (0, 10), said(run)
    assert all(got == full for got, full in points.values()), (points, said(run))
    assert checked['by_name']['never_sleeps']['score'] == 90
    assert run['reason'] == 'failed: sleeps at home', said(run)


def ball_course(label, out):
    """(the ball's script as the simulator said it, [(script time, where it was)])."""
    facts, where = None, []
    with open(os.path.join(out, 'runs', label, 'record', 'truth.jsonl')) as f:
        for line in f:
            record = json.loads(line)
            if record.get('kind') == 'model' and record['facts']['name'] == 'ball':
                facts = record['facts']['scripted']
            elif record.get('kind') == 'state' and facts and 'ball' in record['models']:
                where.append((record['t'] - facts['start'], record['models']['ball'][:3]))
    return facts, where


def test_the_scripted_ball_is_the_same_in_two_runs_of_one_seed(checked):
    """The same course (seed, legs), and in each run the ball at every state where
    that course has it at that time since its spawn (the spawns' times differ)."""
    from exp_assignment2.sim import ball_script
    first, first_where = ball_course('reference', checked['out'])
    second, second_where = ball_course('never_sleeps', checked['out'])
    assert first['seed'] == second['seed'] == 1 and first['legs'] == second['legs']
    course = ball_script.from_legs(first['legs'], None, {'duration': first['duration'],
                                                         'radius': 0.5, 'ground_z': 0.5})
    for where in (first_where, second_where):
        assert len(where) > 2000       # a state every 0.1 s of 240 s, a few dropped at most
        for t, (x, y, z) in where:
            there = ball_script.play(course, t)
            assert (x, y, z) == pytest.approx((there.x, there.y, there.z), abs=1e-3), t
    # the student's ball node (the reference's person) was ignored: the script's is the ball
    assert checked['runs']['reference']['roles']['ball']['why'].endswith(
        "the ball the course's script moves (seed 1)")


def test_the_pages_say_which_ball_and_when_each_check_was_decided(checked):
    with open(os.path.join(checked['out'], 'pages', 'reference.html')) as f:
        page = f.read()
    assert 'The ball followed the course&#x27;s script (seed 1, 240 s); the submission&#x27;s ' \
        'ball node&#x27;s ' in page and ' commands were ignored.' in page
    assert '<h2>When each check was decided</h2>' in page
    moments = [c for c in checked['runs']['reference']['checks'] if c['at'] is not None]
    assert len(moments) >= 7 and page.count('<img class="moment"') == len(moments)
    with open(os.path.join(checked['out'], 'feedback', 'reference.html')) as f:
        mine = f.read()
    assert 'your ball node&#x27;s ' in mine and '<h2>When each check was decided</h2>' in mine
