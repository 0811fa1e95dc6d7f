"""The grading's report from the runs' records alone (exp_assignment2.grading.report.index)."""
import csv
import json
import os

from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.report import index as report

DOG = profiles.load('dog')


def write_run(runs_dir, label, name, verdict, head, rtf=1.0, seed=1, **more):
    record = os.path.join(runs_dir, label, 'record')
    os.makedirs(os.path.join(record, 'frames'))
    checks = [{'name': c['name'], 'metric': c['metric'], 'value': head, 'threshold': '>= 0.6',
               'passed': verdict == 'passed', 'detail': ''} for c in DOG['checks']]
    with open(os.path.join(record, 'truth.jsonl'), 'w') as f:
        for i in range(50):
            f.write(json.dumps({'kind': 'state', 't': i / 10, 'joints': {'robot': {
                'joint_head': head * (i % 2)}}, 'models': {'robot': [i / 10, 0, 0, 0],
                                                           'ball': [3, 0, 0.5, 0]}}) + '\n')
    with open(os.path.join(record, 'run.json'), 'w') as f:
        json.dump({'name': name, 'label': label, 'verdict': verdict, 'checks': checks,
                   'reason': '' if verdict == 'passed' else 'failed: x', 'seed': seed,
                   'real_time_factor': rtf, 'real_time_factor_asked': 1.0,
                   'commands': ['roslaunch p a.launch'], 'commands_from': 'README.md',
                   'truth': {'sim_time': 5.0}, 'wall_time': 6.0, **more}, f)


def test_repeats_give_the_majority_and_the_median_and_say_flaky(tmp_path):
    runs = str(tmp_path / 'runs')
    write_run(runs, 'ann-r1', 'ann', 'passed', 1.0, seed=1)
    write_run(runs, 'ann-r2', 'ann', 'failed_checks', 0.2, seed=2)
    write_run(runs, 'ann-r3', 'ann', 'passed', 0.8, seed=3, rtf=0.7)
    write_run(runs, 'ben', 'ben', 'passed', 1.2)
    summaries = report.write(str(tmp_path), DOG)
    ann, ben = summaries['ann'], summaries['ben']
    assert (ann['verdict'], ann['flaky'], ann['verdicts']) == (
        'passed', True, ['passed', 'failed_checks', 'passed'])
    assert ann['checks'][0]['value'] == 0.8 and ann['checks'][0]['passed']
    assert ann['slow'] and not ben['slow']        # a run below 0.95 of its factor is marked
    assert (ben['verdict'], ben['flaky']) == ('passed', False)
    with open(str(tmp_path / 'grades.csv')) as f:
        rows = list(csv.reader(f))
    assert rows[0][:3] == ['submission', 'verdict', 'flaky']
    assert [r[:3] for r in rows[1:]] == [['ann', 'passed', '1'], ['ben', 'passed', '0']]
    with open(str(tmp_path / 'report.json')) as f:
        data = json.load(f)
    assert {s['name']: s['verdict'] for s in data['submissions']} == {'ann': 'passed',
                                                                        'ben': 'passed'}
    assert all({'value', 'threshold', 'passed'} <= set(c) for s in data['submissions']
               for c in s['checks'])
    index = (tmp_path / 'index.html').read_text()
    # the stylesheet names .flaky on every page: the mark itself, on ann's row only
    rows = {name: row for name, row in (r.split('</td>', 1) for r in
                                        index.split('<tr><td><a href="pages/')[1:])}
    assert set(rows) == {'ann.html">ann</a>', 'ben.html">ben</a>'}
    assert '<span class="flaky">flaky</span>' in rows['ann.html">ann</a>']
    assert '<span class="flaky">flaky</span>' not in rows['ben.html">ben</a>']
    page = (tmp_path / 'pages' / 'ann.html').read_text()
    for img in ('img/ann-r1_top.png', 'img/ann-r1_head.png'):
        assert img in page and os.path.exists(str(tmp_path / 'pages' / img))
    assert '(below 0.95: starved)' in page


def test_a_page_says_why_a_node_died_and_which_could_not_start(tmp_path):
    runs = str(tmp_path / 'runs')
    died = [{'node': 'viewer-3', 'code': -6, 'exit': '-6 (SIGABRT)', 'cmd': 'viewer.py',
             'log': 'logs/command-0.log', 'output': 'the camera is up\nqt.qpa.xcb: could not '
             'connect to display', 'abort': 'qt.qpa.xcb: could not connect to display',
             'node_logs': [{'log': 'ros_home/log/abc/viewer-3.log', 'tail': 'init_node'}]}]
    missing = [{'command': 'roslaunch p a.launch', 'log': 'logs/command-0.log',
                'line': 'ERROR: cannot launch node of type [p/ghost.py]: Cannot locate'}]
    respawned = [{'node': 'robot_state_publisher-3', 'code': 1, 'exit': '1', 'cmd': 'rsp',
                  'log': 'logs/command-0.log', 'deaths': 4, 'restarted': 3, 'required': False},
                 dict(died[0], node='dog-5', code=1, exit='1', abort='', required=True)]
    write_run(runs, 'cat', 'cat', 'crashed', 0.0, died=died)
    write_run(runs, 'dan', 'dan', 'passed', 1.0, launch_errors=missing, died=respawned)
    write_run(runs, 'eve', 'eve', 'passed', 1.0)
    summaries = report.write(str(tmp_path), DOG)
    cat = (tmp_path / 'pages' / 'cat.html').read_text()
    assert '<h3>viewer-3: exit code -6 (SIGABRT)</h3>' in cat
    assert '<pre class="abort">qt.qpa.xcb: could not connect to display</pre>' in cat
    assert 'the camera is up' in cat and 'ros_home/log/abc/viewer-3.log' in cat
    dan = (tmp_path / 'pages' / 'dan.html').read_text()
    assert '<h2>Nodes that could not start (1)</h2>' in dan
    assert '<code>roslaunch p a.launch</code>: ERROR: cannot launch node of type' in dan
    # what roslaunch did about each death: restarted it, or shut its launch down
    assert '<h3>robot_state_publisher-3: exit code 1 (died 4 times; roslaunch restarted it 3 ' \
        'times (respawn=&quot;true&quot;))</h3>' in dan
    assert '<h3>dog-5: exit code 1 (required=&quot;true&quot;: roslaunch shut its launch ' \
        'down)</h3>' in dan
    eve = (tmp_path / 'pages' / 'eve.html').read_text()
    assert 'Nodes that could not start' not in eve and 'Nodes that died' not in eve
    # and in report.json, for a program to read
    assert summaries['cat']['died'][0]['abort'] == 'qt.qpa.xcb: could not connect to display'
    with open(str(tmp_path / 'report.json')) as f:
        data = {s['name']: s for s in json.load(f)['submissions']}
    assert data['dan']['launch_errors'] == missing and data['cat']['died'] == died


def test_a_tie_goes_to_the_worse_verdict():
    assert report._majority(['passed', 'crashed']) == 'crashed'


def test_the_page_lists_every_readme_command_ran_or_left_out(tmp_path):
    runs = str(tmp_path / 'runs')
    write_run(runs, 'ann', 'ann', 'passed', 1.0)
    path = os.path.join(runs, 'ann', 'record', 'run.json')
    with open(path) as f:
        run = json.load(f)
    run['readme_commands'] = [
        {'command': 'roslaunch p a.launch', 'ran': True, 'why': ''},
        {'command': 'roslaunch p b.launch', 'ran': False,
         'why': 'left out: also starts /gazebo, an alternative to `roslaunch p a.launch`'},
        {'command': 'rosrun p x.py', 'ran': True, 'why': '', 'from': 'run.sh'}]
    with open(path, 'w') as f:
        json.dump(run, f)
    report.write(str(tmp_path), DOG)
    page = (tmp_path / 'pages' / 'ann.html').read_text()
    assert ('<code>roslaunch p b.launch</code></td><td>left out</td><td>left out: also starts '
            '/gazebo, an alternative to `roslaunch p a.launch`</td>') in page
    assert '<code>rosrun p x.py</code> (in run.sh)</td><td>ran</td>' in page
    with open(str(tmp_path / 'report.json')) as f:
        assert json.load(f)['runs'][0]['readme_commands'] == run['readme_commands']
