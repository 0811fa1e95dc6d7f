"""The grading's report from the runs' records alone (exp_assignment2.grading.report)."""
import csv
import json
import os

from exp_assignment2.grading import profiles, report

DOG = profiles.load('dog')


def write_run(runs_dir, label, name, verdict, head, rtf=1.0, seed=1):
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
                   'truth': {'sim_time': 5.0}, 'wall_time': 6.0}, f)


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
    assert 'flaky' in index and 'pages/ann.html' in index
    page = (tmp_path / 'pages' / 'ann.html').read_text()
    for img in ('img/ann-r1_top.png', 'img/ann-r1_head.png'):
        assert img in page and os.path.exists(str(tmp_path / 'pages' / img))
    assert '(below 0.95: starved)' in page


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
