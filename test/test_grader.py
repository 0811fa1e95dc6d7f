"""The grader end to end, as a teacher runs it:

    bash tools/run grade SUBMISSIONS --out REPORT --jobs 2 ...

on the fixture folder (test/grading_fixtures.py: a dog that works, one with
Python 2's tabs, a C++ node that does not compile, a node that raises at
start, one that never moves, a hostile one, the dog as a .zip and as a
.tar.gz, a README offering alternatives, one naming another package, one
whose launch file names a node that is not there, a node that shows
every camera frame in a window, a robot, head and ball renamed, a node
importing what ROS desktop-full had, a helper that dies again and again, a
required node that dies, the dog in an xterm window, and those of
test_grader_shapes.py and test_grader_starts.py). Each ends with its expected
verdict; the folder and everything outside the runs' directories are
unchanged; the hostile run costs only its own verdict (the dog graded alone
gets the verdict it gets beside it); every process of every run is gone; the report's
pages open in headless Chromium with no missing image.
"""
import collections
import html
import json
import os
import re
import shutil
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import grading_fixtures  # noqa: E402
import launch_rule_fixtures  # noqa: E402
import miro_fixtures  # noqa: E402
from grading_run import FAST, GRADE, snapshot  # noqa: E402

pytestmark = pytest.mark.xdist_group('grader')


def test_each_submission_gets_its_verdict(graded):
    assert graded['proc'].returncode == 0, graded['proc'].stdout[-3000:]
    got = {name: s['verdict'] for name, s in graded['by_name'].items()}
    expected = {n: v for n, v in grading_fixtures.EXPECTED.items() if v}
    assert {n: got.get(n) for n in expected} == expected, {
        n: graded['by_name'][n]['reason'] for n in got}
    # the causes, as a teacher reads them
    assert 'counter.cpp:3' in graded['by_name']['cpp_broken']['reason']
    # roslaunch runs on without the dog that raised, and so does the run: judged, the death named
    assert graded['by_name']['raises']['reason'].endswith(
        '; dog-5 died (exit code 1): RuntimeError: the dog has no legs')
    assert graded['runs']['raises']['ended_by'] == 'duration'
    assert graded['by_name']['idle']['reason'].startswith('failed: reaches the ball')
    # roslaunch's rule: the node that could not start is noted, on its own command
    (error,) = graded['by_name']['missing_node']['launch_errors']
    assert error['command'] == 'roslaunch exp_assignment2 gazebo_world.launch', error
    assert error['line'].startswith('ERROR: cannot launch node of type '
                                    '[exp_assignment2/ghost.py]'), error
    with open(os.path.join(graded['out'], 'pages', 'missing_node.html')) as f:
        assert 'Nodes that could not start (1)' in f.read()
    # the terminal's summary line counts the verdicts the report has (the hostile's as it came)
    summary = [l for l in graded['proc'].stdout.splitlines() if l.startswith('[grade] graded ')]
    summary = summary[-1] if summary else graded['proc'].stdout[-2000:]
    counts = collections.Counter(got.values())
    assert summary.startswith('[grade] graded %d submissions: %s; report: ' % (
        len(grading_fixtures.EXPECTED), ', '.join('%d %s' % (counts[v], v) for v in (
            'passed', 'failed_checks', 'crashed', 'timed_out', 'not_started', 'not_built',
            'grader_error') if counts[v]))), summary
    # nothing of the grader's own machinery on the teacher's terminal
    assert 'Traceback' not in graded['proc'].stdout, graded['proc'].stdout[-3000:]


def test_a_report_says_where_commands_came_from_and_how_to_repeat(graded):
    works = graded['runs']['works']
    assert works['commands'] == ['roslaunch exp_assignment2 gazebo_world.launch']
    assert works['commands_from'] == "the submission's README.md"
    assert works['repeat_command'].startswith('bash tools/run grade ')
    assert works['real_time_factor'] > 0.5
    checks = {c['name']: c for c in graded['by_name']['works']['checks']}
    assert checks['reaches the ball']['passed'] and checks['reaches the ball']['value'] >= 1
    head = checks['head turns both ways at the ball']
    assert head['passed'] and head['value'] >= 0.5 and head['at'] is not None
    # a ball that never moved or hid, 30 s: the rest of the behaviours had no occasion
    assert [c['name'] for c in checks.values() if c['passed'] is None] == [
        'follows the moving ball', 'gives up a hidden ball', 'sleeps at home', 'wanders']
    assert graded['runs']['works']['truth']['frames'] > 0


def test_a_node_that_shows_its_camera_passes_and_its_window_is_on_its_page(graded):
    """cv2.imshow and waitKey in every image callback, as the assignment's
    template has it: the run's own display takes the window, and the page
    shows it, by its title, at each of the camera's moments."""
    run = graded['runs']['imshow']
    assert run['verdict'] == 'passed', run['reason']
    assert [e['display'] for e in run['events'] if e.get('event') == 'display']
    assert run['cpu_s'].get('display', 0) > 0
    import cv2
    import numpy
    pages = os.path.join(graded['out'], 'pages')
    with open(os.path.join(pages, 'imshow.html')) as f:
        page = f.read()
    title = html.escape(grading_fixtures.IMSHOW_TITLE)
    assert '<th>window &ldquo;%s&rdquo;</th>' % title in page
    circles = 0
    for moment in ('first sight of the ball', 'closest approach', 'end'):
        found = re.search(r'<img class="window" src="([^"]+)" alt="%s at %s">'
                          % (re.escape(title), moment), page)
        assert found, (moment, page[page.find('Camera and windows'):][:2000])
        picture = cv2.imread(os.path.join(pages, found.group(1)))
        assert picture is not None and picture.shape[0] > 100, moment
        # the yellow circle the node draws on the ball
        circles += int(numpy.count_nonzero((picture[:, :, 0] < 90) & (picture[:, :, 1] > 190) &
                                           (picture[:, :, 2] > 190)) > 20)
    assert circles >= 1
    # a node without a window has no window on its page
    with open(os.path.join(pages, 'works.html')) as f:
        assert '<th>window &ldquo;' not in f.read()


def test_roslaunchs_rules_for_a_node_that_dies(graded):
    """A node that dies ends nothing (roslaunch restarts it with respawn="true"):
    noted once; a required node's death ends the run as it ends roslaunch."""
    helper = graded['runs']['helper_dies']
    assert (helper['verdict'], helper['ended_by']) == ('passed', 'duration'), helper['reason']
    assert helper['truth']['sim_time'] >= 30 and helper['error_count'] == 0
    (dead,) = helper['died']
    assert dead['node'].startswith('robot_state_publisher-') and dead['code'] == 1
    assert dead['deaths'] >= 2 and dead['restarted'] >= 1 and not dead['required']
    assert 'Could not find parameter robot_description' in dead['output']
    with open(os.path.join(graded['out'], 'pages', 'helper_dies.html')) as f:
        assert 'Nodes that died (1)' in f.read()
    required = graded['runs']['required_dies']
    assert (required['verdict'], required['ended_by'], required['required_node']) == (
        'crashed', 'required_node_died', 'dog-5'), required['reason']
    assert required['reason'].startswith('dog-5 died (exit code 1): %s; it was required="true"'
                                         % launch_rule_fixtures.TIRED), required['reason']
    assert required['truth']['sim_time'] < 20 and required['checks_until'] == 'crashed'


def test_a_node_in_an_xterm_window_passes_its_window_on_its_page(graded):
    """launch-prefix="xterm -e": a real window on the run's display, its output
    still in roslaunch's screen (the command's log)."""
    run = graded['runs']['xterm_dog']
    assert run['verdict'] == 'passed', run['reason']
    with open(os.path.join(graded['out'], 'pages', 'xterm_dog.html')) as f:
        page = f.read()
    assert '<th>window &ldquo;dog.py&rdquo;</th>' in page
    assert re.search(r'<img class="window" src="[^"]+" alt="dog.py at end">', page)
    with open(os.path.join(graded['out'], 'runs', 'xterm_dog', 'work', 'logs', 'command-0.log'),
              errors='replace') as f:
        assert launch_rule_fixtures.XTERM_SAYS in f.read()


def test_a_readme_is_read_as_a_person_reads_it(graded):
    """One world of the README's alternatives runs, the others are noted; a
    README naming another package runs the submission's own."""
    alternatives = graded['runs']['alternatives']
    assert alternatives['commands'] == ['roslaunch exp_assignment2 everything.launch']
    everything = 'an alternative to `roslaunch exp_assignment2 everything.launch`'
    assert alternatives['notes'][:3] == [
        '`roslaunch exp_assignment2 world_random.launch`: left out: also starts /gazebo, '
        + everything,
        '`rosrun exp_assignment2 dog.py`: left out: also starts /dog, ' + everything,
        '`roslaunch exp_assignment2 world_fixed.launch`: left out: also starts /gazebo, '
        + everything]
    assert [c['ran'] for c in alternatives['readme_commands']] == [True, False, False, False]
    other = graded['runs']['other_name']
    assert other['commands'] == ['roslaunch exp_assignment2 gazebo_world.launch']
    assert other['notes'][0].startswith('`roslaunch assignment2 gazebo_world.launch`: there '
                                        'is no package assignment2: runs the submission')
    with open(os.path.join(graded['out'], 'pages', 'alternatives.html')) as f:
        assert 'left out: also starts /gazebo' in f.read()


def test_the_hostile_submission_costs_only_its_own_verdict(graded, tmp_path):
    hostile = graded['by_name']['hostile']
    assert hostile['verdict'] not in ('passed', 'grader_error'), hostile
    # wall-clock waits (time.sleep) in its code: run at real time, and said so
    assert any('wall clock' in n for n in graded['runs']['hostile']['notes'])
    # nothing outside the runs' directories was written: the folder, the file beside it
    after = snapshot(graded['base'])
    changed = {k for k in set(graded['before']) | set(after)
               if not k.startswith('report') and graded['before'].get(k) != after.get(k)}
    assert changed == set()
    for path in ('/etc/hostile', '/work/hostile', '/root/hostile'):
        assert not os.path.exists(path)
    # what it saw from inside: a read-only machine, and no other run
    with open(os.path.join(graded['out'], 'runs', 'hostile', 'work', 'logs', 'command-0.log'),
              'rb') as f:
        said = f.read(1 << 20).decode(errors='replace')
    assert 'REFUSED /etc/hostile Read-only file system' in said
    assert 'OTHERS []' in said
    # every process of every run is gone
    assert all(r['all_gone'] for r in graded['runs'].values()
               if r['ended_by'] != 'not_run')       # a row with no sandbox has nothing to end
    # the dog graded alone: the same verdict as beside the hostile one
    out = str(tmp_path / 'alone')
    proc = subprocess.run(GRADE + [graded['folder'], '--only', 'works', '--out', out] + FAST,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=900)
    assert proc.returncode == 0, proc.stdout[-2000:]
    with open(os.path.join(out, 'report.json')) as f:
        alone = json.load(f)['submissions'][0]
    assert alone['verdict'] == graded['by_name']['works']['verdict'] == 'passed'


def test_the_report_opens_in_a_browser_with_every_image(graded, tmp_path):
    out = graded['out']
    pages = [os.path.join(out, 'index.html')] + [
        os.path.join(out, 'pages', n) for n in sorted(os.listdir(os.path.join(out, 'pages')))
        if n.endswith('.html')]
    assert len(pages) == len(grading_fixtures.EXPECTED) + 1
    browser = shutil.which('chromium')
    assert browser, 'chromium is not installed (tools/run test installs it)'
    for page in pages:
        proc = subprocess.run([browser, '--headless', '--no-sandbox', '--disable-gpu',
                               '--user-data-dir=%s' % tmp_path, '--virtual-time-budget=3000',
                               '--dump-dom', 'file://' + page], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, universal_newlines=True, timeout=120)
        assert 'data-images-missing="0"' in proc.stdout, (page, proc.stdout[:500])
    with open(pages[0]) as f:
        index = f.read()
    assert index.count('<tr><td><a href="pages/') == len(grading_fixtures.EXPECTED)
    with open(os.path.join(out, 'grades.csv')) as f:
        lines = f.read().strip().splitlines()
    assert len(lines) == len(grading_fixtures.EXPECTED) + 1
    assert lines[0].startswith('submission,verdict,flaky,score,max,')
    # the students' pages and Gradescope's results, one each (docs/grading.md)
    for name in grading_fixtures.EXPECTED:
        assert os.path.isfile(os.path.join(out, 'feedback', name + '.html'))
        assert os.path.isfile(os.path.join(out, 'gradescope', name, 'results.json'))


def test_the_report_is_made_again_without_running(graded):
    os.remove(os.path.join(graded['out'], 'index.html'))
    proc = subprocess.run(GRADE + [graded['folder'], '--out', graded['out'], '--report-only'],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=300)
    assert proc.returncode == 0, proc.stdout[-2000:]
    assert os.path.exists(os.path.join(graded['out'], 'index.html'))
    assert 'graded %d submissions' % len(grading_fixtures.EXPECTED) in proc.stdout


def test_students_earlier_ros_and_the_courses_own_world(graded):
    """A Kinetic-era launch file (robot_state_publisher's state_publisher) runs
    as it did, with one line; a package of the student's own name in this
    package's world (its simulator.launch, started through the workspace's
    devel-space relay) is judged from that simulator's truth."""
    assert graded['by_name']['old_names']['verdict'] == 'passed'
    with open(os.path.join(graded['out'], 'runs', 'old_names', 'work', 'logs',
                           'command-0.log'), errors='replace') as f:
        said = f.read()
    assert 'robot_state_publisher/state_publisher: started as ' \
        'robot_state_publisher/robot_state_publisher' in said
    own = graded['runs']['own_world']
    assert own['verdict'] == 'passed', (own['reason'], own.get('checks'))
    assert own['commands'] == ['roslaunch exp_assignment2 simulator.launch robot_model:=original',
                               'rosrun dog_on_sim dog.py']
    assert own['truth']['refused_peers'] == []
    assert 'simulator.py' in own['truth']['simulator']


def test_miro_submissions_under_the_miro_profile(tmp_path):
    """As a teacher grades after the README's set-up: the profile's world
    (miro_world.launch, as Stage was) first, then each submission's README
    commands; judged by its arrivals at the commanded targets. One package is
    named exp_assignment2 (the world is then exp_assignment2_sim), one has
    its own name (the world is this package's, its simulator started through
    the workspace's devel-space relay)."""
    folder = tmp_path / 'miro_class'
    miro_fixtures.make_miro(str(folder / 'miro_student'))
    miro_fixtures.make_miro(str(folder / 'miro_own_name'), package='assignment1')
    out = str(tmp_path / 'report')
    proc = subprocess.run(GRADE + [str(folder), '--out', out, '--profile', 'miro', '--jobs', '2',
                                   '--duration', '60', '--real-time-factor', '2'],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=900)
    assert proc.returncode == 0, proc.stdout[-3000:]
    assert 'Traceback' not in proc.stdout, proc.stdout[-3000:]
    with open(os.path.join(out, 'report.json')) as f:
        runs = {r['label']: r for r in json.load(f)['runs']}
    assert runs['miro_student']['commands'] == [
        'roslaunch exp_assignment2_sim miro_world.launch',
        'rosrun exp_assignment2 miro_state_manager.py',
        'roslaunch exp_assignment2 miro_user.launch']
    assert runs['miro_own_name']['commands'] == [
        'roslaunch exp_assignment2 miro_world.launch',
        'rosrun assignment1 miro_state_manager.py',
        'roslaunch assignment1 miro_user.launch']
    for run in runs.values():
        assert run['verdict'] == 'passed', (run['label'], run['reason'], run.get('checks'))
        assert run['truth']['refused_peers'] == [], run['truth']
        arrivals = {c['metric']: c['value'] for c in run['checks']}['arrivals']
        assert arrivals >= 3
