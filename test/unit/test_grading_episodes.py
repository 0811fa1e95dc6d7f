"""The same ball for everyone (no ROS): a profile's ``ball`` with the course's
script, ``base``, the episodes ``--episodes N`` plans with their seeds and
visibility, the ball's setting each run's sandbox gets, the scripted ball's
role, and what the pages say of it and of each check's moment."""
import json
import os

import pytest

from exp_assignment2.grading import options
from exp_assignment2.grading.judge import metrics, roles
from exp_assignment2.grading.plan import episodes, profiles
from exp_assignment2.grading.plan.spec import RunSpec
from exp_assignment2.grading.report import index as report
from exp_assignment2.sim.ball_setting import parse

DOG = profiles.load('dog')


def scripted(script):
    return profiles.check(dict(_raw(), ball={'name': 'ball', 'script': script}), 'mine.yaml')


def _raw():
    return {k: v for k, v in DOG.items() if k not in ('ball_script',)}


def test_a_profile_scripts_the_ball_or_leaves_it_to_the_student():
    assert DOG['ball'] == 'ball' and DOG['ball_script'] is None
    assert scripted(True)['ball_script'] == {'seeds': None, 'hidden': [], 'model': None}
    got = scripted({'seeds': [3, 8, 13], 'hidden': [13], 'model': 'ball'})
    assert got['ball'] == 'ball' and got['ball_script'] == {
        'seeds': [3, 8, 13], 'hidden': [13], 'model': 'ball'}
    assert profiles.check(dict(got), 'again.yaml')['ball_script'] == got['ball_script']
    with pytest.raises(profiles.ProfileError, match="ball: script: give seed or seeds, not both"):
        scripted({'seed': 1, 'seeds': [2]})
    with pytest.raises(profiles.ProfileError, match='seeds are whole numbers'):
        scripted({'seed': -1})


def test_a_profile_on_a_base_takes_its_keys(tmp_path):
    (tmp_path / 'mine.yaml').write_text('base: dog\nname: mine\nduration: 90\nreach: 3.0\n')
    mine = profiles.load(str(tmp_path / 'mine.yaml'))
    assert (mine['name'], mine['duration'], mine['reach']) == ('mine', 90, 3.0)
    assert mine['checks'] == DOG['checks'] and mine['ball_script'] is None
    (tmp_path / 'loop.yaml').write_text('base: loop.yaml\nname: loop\n')
    with pytest.raises(profiles.ProfileError, match='base'):
        profiles.load(str(tmp_path / 'loop.yaml'))


def test_episodes_each_a_seed_of_the_ball_some_hidden():
    course = scripted({'seeds': [3, 8], 'hidden': [8]})
    assert episodes.default_count(course) == 2 and episodes.default_count(DOG) == 1
    got = episodes.episodes(course, 4, first_seed=1)
    assert [(e['seed'], e['visibility']) for e in got] == [
        (3, 'visible'), (8, 'hidden'), (9, 'visible'), (10, 'visible')]
    assert [e['seed'] for e in episodes.episodes(scripted(True), 3, 5)] == [5, 6, 7]
    assert [e['seed'] for e in episodes.episodes(DOG, 2, 1)] == [None, None]
    setting = episodes.ball_script(course, got[1], 60.0)
    assert setting == {'seed': 8, 'duration': 60.0}
    assert parse(json.dumps(setting)).seed == 8          # what the simulator reads
    assert episodes.ball_script(DOG, got[1], 60.0) is None
    assert episodes.label('ann', got[1], 0, 4, 1) == 'ann-e2'
    assert episodes.label('ann', got[0], 1, 1, 2) == 'ann-r2'
    assert episodes.label('ann', got[0], 0, 1, 1) == 'ann'


def test_a_run_carries_its_episode_and_the_balls_setting():
    spec = RunSpec(name='ann', path='/x', kind='dir', profile=DOG, duration=200,
                   episode={'index': 0, 'seed': 3, 'visibility': 'visible'},
                   ball_script={'seed': 3, 'duration': 200.0})
    again = RunSpec.from_dict(json.loads(json.dumps(spec.to_dict())))
    assert again.ball_script == {'seed': 3, 'duration': 200.0} and again.episode['seed'] == 3
    assert RunSpec(name='b', path='/x', kind='dir').ball_script is None


def test_the_command_line_takes_episodes_and_calibrate():
    args = options.parse_args(['class', '--episodes', '3'])
    assert args.episodes == 3 and args.calibrate is None
    args = options.parse_args(['--calibrate'])
    assert args.calibrate == '' and args.submissions is None
    assert options.parse_args(['--calibrate', 'ref']).calibrate == 'ref'
    with pytest.raises(SystemExit):
        options.parse_args([])
    with pytest.raises(SystemExit):
        options.parse_args(['class', '--episodes', '0'])


def ball_facts(name, scripted_by=None):
    return {'name': name, 'sphere': 0.5, 'static': False, 'joints': {}, 'sensors': [],
            'plugins': [{'file': 'libgazebo_ros_planar_move.so', 'drive': True,
                         'command': '/%s/cmd_vel' % name}],
            'scripted': scripted_by}


SCRIPT = {'seed': 3, 'start': 0.5, 'duration': 200.0, 'legs': [{'hide': 20.0}]}


def test_the_scripted_ball_is_the_ball_though_nothing_moved_it():
    """Its commands were ignored (zero fed, zero placed): its script says it is the ball."""
    states = [{'t': t / 10.0, 'models': {'ball': [4, 0, 0.5, 0], 'toy': [1, 1, 0.5, 0]},
               'joints': {}, 'fed': {'ball': 10}, 'ignored': {'toy': t}} for t in range(20)]
    trace = metrics.Trace(states, models={'ball': ball_facts('ball'),
                                          'toy': ball_facts('toy', SCRIPT)})
    found = roles.find_ball(trace, DOG, roles.NO_ROLE)
    assert found.name == 'toy'
    assert found.why == "`toy`: the ball the course's script moves (seed 3) (no model `ball` is)"
    assert trace.counter('ignored', 'toy') == 19 and trace.counter('fed', 'toy') == 0


def test_a_page_says_which_ball_and_shows_each_checks_moment(tmp_path):
    from test_grading_report import write_run
    runs = str(tmp_path / 'runs')
    for k, seed in enumerate((3, 8)):
        label = 'ann-e%d' % (k + 1)
        write_run(runs, label, 'ann', 'passed', 1.0, seed=k + 1,
                  episode={'index': k, 'seed': seed, 'visibility': 'visible' if k == 0
                           else 'hidden'})
        record = os.path.join(runs, label, 'record')
        with open(os.path.join(record, 'run.json')) as f:
            run = json.load(f)
        for i, check in enumerate(run['checks']):
            check['at'] = 1.0 + i if i < 2 else None
        with open(os.path.join(record, 'run.json'), 'w') as f:
            json.dump(run, f)
        with open(os.path.join(record, 'truth.jsonl'), 'a') as f:
            f.write(json.dumps({'kind': 'model', 't': 0.0, 'facts': ball_facts('ball', dict(
                SCRIPT, seed=seed))}) + '\n')
            f.write(json.dumps({'kind': 'state', 't': 4.95, 'models': {
                'robot': [4.9, 0, 0, 0], 'ball': [3, 0, 0.5, 0]}, 'ignored': {'ball': 7}}) + '\n')
        for t in (0.0, 1.0, 2.0, 3.0):       # the camera's frames (the record's names)
            (tmp_path / 'runs' / label / 'record' / 'frames' / (
                'robot_camera1_%08.2f.jpg' % t)).write_bytes(b'\xff\xd8 not a real jpeg')
    summaries = report.write(str(tmp_path), DOG)
    page = (tmp_path / 'pages' / 'ann.html').read_text()
    assert "The ball followed the course&#x27;s script (seed 3, 200 s); the submission&#x27;s " \
        "ball node&#x27;s 7 commands were ignored." in page
    assert '2 episodes (seeds 3, 8; 1 hidden): each check&#x27;s figure is the median' in page
    assert '<h2>When each check was decided</h2>' in page
    assert page.count('<img class="moment"') == 2 and 'ann-e1_check1.jpg' in page
    mine = (tmp_path / 'feedback' / 'ann.html').read_text()
    assert summaries['ann']['main_run'] == 'ann-e1'
    assert "your ball node&#x27;s 7 commands were ignored" in mine
    assert 'seeds 3, 8' not in mine        # the hidden episode's seed is the teacher's
