"""When each command starts (exp_assignment2.grading.plan.start_script, .starts):
a start script as its shell runs it, a README's commands typed a few seconds
apart, grading.yaml's own timing, and the driver's loop on a hand-turned
clock (no process, no ROS)."""
import json
import os

import pytest

from exp_assignment2.grading.plan import start_script
from exp_assignment2.grading.plan import starts
from exp_assignment2.grading.plan.planning import resolve
from exp_assignment2.grading.plan.start_script import TERMINAL_OPEN
from exp_assignment2.grading.plan.teacher_file import TeacherFileError, read_teacher_file

# a real MiRo solution's shape: three terminals, then the launch file in the script itself
MIRO_SH = '''#!/bin/bash
cd ~/catkin_ws && source devel/setup.bash
gnome-terminal -x sh -c "rosrun my_pkg state_manager.py; bash"
gnome-terminal -x sh -c "rosrun my_pkg user.py; bash"
gnome-terminal -- bash -c 'sleep 1; rosrun my_pkg planner.py; exec bash'
roslaunch --wait my_pkg launch_all.launch
rosrun my_pkg after_the_launch.py
'''


def read(text, cwd=''):
    return start_script.read(text, cwd, lambda tool, here, target: target.strip('~/'))


def test_terminals_open_late_and_the_script_runs_its_own_line_at_once():
    got = [(s['command'], s['after'], s['since']) for s in read(MIRO_SH)]
    assert got == [('rosrun my_pkg state_manager.py', TERMINAL_OPEN, None),
                   ('rosrun my_pkg user.py', TERMINAL_OPEN, None),
                   ('rosrun my_pkg planner.py', TERMINAL_OPEN + 1, None),
                   ('roslaunch --wait my_pkg launch_all.launch', 0.0, None),
                   # the shell waits for the launch: this line runs when (if) it ends
                   ('rosrun my_pkg after_the_launch.py', 0.0, ('end', 3))]
    assert {s['cwd'] for s in read(MIRO_SH)} == {'catkin_ws'}


@pytest.mark.parametrize('text, expected', [
    # sleeps add up; a background command lets the script go on
    ('roslaunch p a.launch &\nsleep 3\nrosrun p b.py &\nsleep 0.5s; rosrun p c.py\n',
     [('roslaunch p a.launch', 0.0, None), ('rosrun p b.py', 3.0, None),
      ('rosrun p c.py', 3.5, None)]),
    # xterm -e takes the rest of the line; several tabs are several shells
    ("xterm -e roslaunch p a.launch &\nsleep 1m\n"
     "gnome-terminal --tab -e 'rosrun p b.py' --tab --command='rosrun p c.py'\n",
     [('roslaunch p a.launch', TERMINAL_OPEN, None), ('rosrun p b.py', 60 + TERMINAL_OPEN, None),
      ('rosrun p c.py', 60 + TERMINAL_OPEN, None)]),
    # inside one terminal's shell, the second waits for the first; the script does not
    ('gnome-terminal -x bash -c "rosrun p a.py; sleep 2; rosrun p b.py"\nrosrun p c.py &\n',
     [('rosrun p a.py', TERMINAL_OPEN, None), ('rosrun p b.py', 2.0, ('end', 0)),
      ('rosrun p c.py', 0.0, None)]),
    # a sleep in the background and roscore (the grader's master) take no time
    ('roscore &\nsleep 5 &\n# rosrun p commented.py\nrosrun p a.py 2>&1 | tee log\n',
     [('rosrun p a.py 2>&1', 0.0, None)]),
])
def test_a_script_is_timed_as_its_shell_runs_it(text, expected):
    assert [(s['command'], s['after'], s['since']) for s in read(text)] == expected


def test_cd_in_a_script_and_inside_a_terminal(tmp_path):
    from exp_assignment2.grading.plan import own_names
    (tmp_path / 'launch').mkdir()
    got = start_script.read('cd $(rospack find p)/launch\nrosrun p a.py\n', '', lambda tool,
                            here, target: own_names.cd(str(tmp_path), here, target,
                                                       {'p': str(tmp_path)}))
    assert got[0]['cwd'] == 'launch'
    got = read('cd launch\nroslaunch a.launch &\n'
               'gnome-terminal -x sh -c "cd ~/scripts; rosrun p b.py"\nrosrun p c.py\n')
    assert [(s['command'], s['cwd']) for s in got] == [
        ('roslaunch a.launch', 'launch'), ('rosrun p b.py', 'scripts'), ('rosrun p c.py', 'launch')]


class HandTurnedStop(object):
    """threading.Event's face for starts.follow: waiting turns the clock."""

    def __init__(self, until):
        self.now, self.until = 0.0, until

    def is_set(self):
        return self.now >= self.until

    def wait(self, seconds):
        self.now += max(seconds, 0.01)
        return self.is_set()


def follow(plan, lifetimes, until=60.0, cannot=()):
    """Run starts.follow on a hand-turned clock: command i lives lifetimes[i]
    s (None: for ever); {index: (started at, ended at)}, never started."""
    stop = HandTurnedStop(until)
    schedule = starts.Schedule(plan, 0.0)
    began, over = {}, {}

    def launch(i, at):
        began[i] = stop.now
        if i in cannot:
            over[i] = stop.now
        return i not in cannot

    def poll_exits():
        ended = [i for i in began if i not in over and lifetimes.get(i) is not None
                 and stop.now >= began[i] + lifetimes[i]]
        over.update((i, stop.now) for i in ended)
        return ended
    told = []
    starts.follow(schedule, launch, poll_exits, told.extend, stop, lambda: stop.now)
    assert sorted(told) == sorted(i for i in over if i not in cannot)
    return {i: (round(began[i], 1), round(over[i], 1) if i in over else None)
            for i in began}, schedule.never_started()


def test_the_launch_file_of_a_script_is_up_before_the_terminals_nodes(tmp_path):
    """The start plan resolve makes of a README running that script, followed
    on a hand-turned clock: the world, then the script typed `delay` s later,
    its own roslaunch at once, the terminals' nodes TERMINAL_OPEN s after it."""
    root = tmp_path / 'my_pkg'
    (root / 'launch').mkdir(parents=True)
    (root / 'package.xml').write_text('<package><name>my_pkg</name></package>')
    (root / 'README.md').write_text('Run `./start.sh`\n')
    (root / 'start.sh').write_text(MIRO_SH)
    profile = {'world_commands': ['roslaunch {sim} miro_world.launch'], 'default_commands': [],
               'delay': 5}
    got = resolve(str(root), 'my_pkg', 'a', {}, profile, set(), lambda requests, packages: {
        r['key']: {'nodes': ['/%s' % r['key']]} for r in requests})
    assert got['commands'][4] == 'roslaunch --wait my_pkg launch_all.launch'
    times, never = follow(got['starts'], {})
    assert [times[i][0] for i in range(5)] == [0.0, 7.0, 7.0, 8.0, 5.0]
    assert never == [5]         # the line after the launch: its shell still waits
    # as the whole class's commands: the launch file's end lets the last line run
    times, never = follow(got['starts'], {4: 10.0})
    assert times[5] == (15.0, None) and never == []


def test_readme_commands_are_typed_delay_apart_and_a_failed_start_ends_at_once():
    plan = starts.typed(['roslaunch p w.launch', 'rosrun p a.py', 'rosrun p b.py'], 5.0)
    times, _ = follow(plan, {}, cannot={1})
    assert times == {0: (0.0, None), 1: (5.0, 5.0), 2: (10.0, None)}
    times, _ = follow(starts.typed(['a x y', 'b x y', 'c x y'], 0.0), {})
    assert {t[0] for t in times.values()} == {0.0}      # delay: 0, all at the same instant


def test_the_plans_span_is_what_is_known_in_advance():
    plan = starts.typed(['a x y', 'b x y'], 5.0) + [
        {'command': 'c x y', 'after': 60, 'since': ['start', 1]},
        {'command': 'd x y', 'after': 1, 'since': ['end', 0]},
        {'command': 'e x y', 'after': 1, 'since': ['start', 3]}]
    assert starts.span(plan) == 65.0 and starts.span([]) == 0.0


def test_stop_is_honoured_while_a_command_waits():
    plan = starts.typed(['roslaunch p w.launch', 'rosrun p a.py'], 30.0)
    times, never = follow(plan, {}, until=10.0)
    assert list(times) == [0] and never == [1]


def test_grading_yaml_says_when_and_where(tmp_path):
    path = tmp_path / 'grading.yaml'
    path.write_text('delay: 4\ncommands:\n  - roslaunch p w.launch\n'
                    '  - {run: "rosrun p b.py", after: 0, cwd: scripts}\n'
                    '  - {run: "rosrun p c.py", at: 20}\n  - rosrun p d.py\n')
    teacher = read_teacher_file(str(path))
    plan = starts.from_teacher(teacher['commands'], teacher['delay'])
    assert [(s['after'], s['since'], s['cwd']) for s in plan] == [
        (0.0, None, ''), (0.0, ['start', 0], 'scripts'), (20.0, None, ''),
        (4.0, ['start', 2], '')]
    times, _ = follow(plan, {})
    assert [times[i][0] for i in range(4)] == [0.0, 0.0, 20.0, 24.0]


@pytest.mark.parametrize('command, message', [
    ('{run: x y z, aftr: 3}', "unknown key 'aftr' (did you mean 'after'?)"),
    ('{after: 3}', 'has no run:'),
    ('{run: x y z, after: 1, at: 2}', 'after: or at:, not both'),
    ('{run: x y z, after: -1}', 'after: -1 is out of range'),
    ('{run: x y z, cwd: ../other}', "cwd: '../other' must be a folder of the submission"),
    ('{run: x y z, after: soon}', "after: 'soon' is not a"),
])
def test_a_mistake_in_a_commands_timing_is_one_line(tmp_path, command, message):
    path = tmp_path / 'grading.yaml'
    path.write_text('commands:\n  - %s\n' % command)
    with pytest.raises(TeacherFileError) as error:
        read_teacher_file(str(path))
    assert message in str(error.value) and '\n' not in str(error.value)


def test_the_plan_in_words():
    commands = ['roslaunch p w.launch', 'rosrun p a.py', 'rosrun p b.py']
    assert [starts.describe(s, commands) for s in [
        {'after': 0, 'since': None}, {'after': 5, 'since': ['start', 0]},
        {'after': 0, 'since': ['end', 1]}, {'after': 0, 'since': ['start', 0]},
        {'after': 2, 'since': None}]] == [
        'at once', '5 s after `roslaunch p w.launch` started',
        'as soon as `rosrun p a.py` ended', 'with `roslaunch p w.launch`',
        '2 s after the master']


def test_the_runs_plan_gives_each_start_a_folder_inside_the_submission(tmp_path):
    from exp_assignment2.grading.run.runner import Run, RunSettings
    from exp_assignment2.grading.plan.spec import RunSpec
    plan = [dict(s, cwd=cwd) for s, cwd in zip(
        starts.typed(['roslaunch a.launch', 'rosrun p b.py', 'rosrun p c.py'], 5), (
            'my_pkg/launch', '../../outside', ''))]
    spec = RunSpec(name='ann', path=str(tmp_path), kind='dir', profile={'duration': 10},
                   commands=starts.commands_of(plan), starts=plan)
    run = Run(RunSettings({'duration': 10, 'delay': 5}, str(tmp_path / 'runs')), spec)
    run._fresh_dirs()
    root = os.path.join(run.work, 'src')
    package_dir = os.path.join(root, 'my_pkg')
    written = load(run._plan(package_dir, root=root))
    assert [s['dir'] for s in written['starts']] == [
        os.path.join(root, 'my_pkg', 'launch'), root, root]
    assert written['commands'] == spec.commands and written['delay'] == 5
    # a spec from before there were plans: its commands delay apart, from the root
    old = RunSpec(name='ann', path=str(tmp_path), kind='dir', profile={'duration': 10},
                  commands=['roslaunch p a.launch', 'rosrun p b.py'])
    run = Run(RunSettings({'duration': 10, 'delay': 3}, str(tmp_path / 'runs')), old)
    written = load(run._plan(package_dir))
    assert [(s['after'], s['dir']) for s in written['starts']] == [
        (0.0, package_dir), (3.0, package_dir)]


def load(path):
    with open(path) as f:
        return json.load(f)


def test_the_driver_starts_each_command_in_its_folder_when_due(tmp_path, capsys):
    """inside.follow_plan with real processes: the second waits for the
    first's end, each runs in its folder, the events say when and where."""
    import sys
    import threading
    from exp_assignment2.grading import paths
    here = os.path.dirname(paths.INSIDE)
    sys.path.insert(0, here)      # as the sandbox runs it: a script of its own
    try:
        import inside
    finally:
        sys.path.remove(here)
    (tmp_path / 'launch').mkdir()
    plan = {'package': str(tmp_path), 'logs': str(tmp_path / 'logs'), 'starts': [
        {'command': "sh -c 'pwd > here; sleep 0.3'", 'cwd': 'launch', 'after': 0.0,
         'since': None, 'dir': str(tmp_path / 'launch')},
        {'command': 'touch after', 'cwd': '', 'after': 0.2, 'since': ['end', 0],
         'dir': str(tmp_path)},
        {'command': 'no_such_program_here', 'cwd': '', 'after': 0.0, 'since': ['start', 0],
         'dir': str(tmp_path)},
        {'command': 'sleep 5', 'cwd': '', 'after': 0.0, 'since': ['end', 1]},
        {'command': 'true', 'cwd': '', 'after': 0.0, 'since': ['end', 3]}]}
    (tmp_path / 'logs').mkdir()
    stop = threading.Event()
    threading.Timer(3.0, stop.set).start()
    commands, exited = inside.follow_plan(plan, None, stop)
    inside.end_all([proc for _, _, proc in commands])
    events = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    said = {(e['event'], e['index']): e for e in events}
    assert (tmp_path / 'launch' / 'here').read_text().strip() == str(tmp_path / 'launch')
    assert (tmp_path / 'after').exists()
    assert said[('started', 0)]['cwd'] == 'launch' and said[('started', 0)]['at'] < 0.5
    # 0.3 s of the first, 0.2 after its end, a look every 0.5 s at most
    assert 0.45 <= said[('started', 1)]['at'] - said[('started', 0)]['at'] < 2.5
    assert said[('exited', 2)]['rc'] == 127 and 'since' in said[('exited', 2)]
    assert said[('started', 3)]['at'] >= said[('started', 1)]['at']
    assert said[('never_started', 4)]['since'] == ['end', 3]
    assert exited == {0, 1}


def test_the_page_says_when_each_command_started_and_from_where():
    from exp_assignment2.grading.report import starts as report_starts
    run = {'commands': ['roslaunch p w.launch', 'roslaunch --wait p all.launch', 'rosrun p a.py',
                        'rosrun p after.py'],
           'events': [{'event': 'master', 'up': True},
                      {'event': 'started', 'index': 0, 'at': 0.0, 'after': 0, 'since': None},
                      {'event': 'started', 'index': 1, 'at': 5.01, 'after': 5,
                       'since': ['start', 0], 'cwd': 'launch'},
                      {'event': 'started', 'index': 2, 'at': 7.02, 'after': 7,
                       'since': ['start', 0]},
                      {'event': 'exited', 'index': 2, 'rc': 1},
                      {'event': 'never_started', 'index': 3, 'after': 0, 'since': ['end', 1]}]}
    assert [(r['cwd'], r['planned'], r['at'], r['what']) for r in report_starts.rows(run)] == [
        ('', 'at once', 0.0, ''),
        ('launch', '5 s after `roslaunch p w.launch` started', 5.01, ''),
        ('', '7 s after `roslaunch p w.launch` started', 7.02, ''),
        ('', 'as soon as `roslaunch --wait p all.launch` ended', None,
         'never started: its shell still waited for `roslaunch --wait p all.launch` to end')]
    page = report_starts.table(run)
    assert '<td>5.0</td>' in page and '<td>launch</td>' in page
    # not built: nothing started, the commands are all there is
    assert report_starts.table({'commands': ['a b c'], 'events': []}) == '<pre>a b c</pre>'
