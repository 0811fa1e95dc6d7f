"""What the grader reads in a run's logs (exp_assignment2.grading.judge.logs), on hand-written
logs in roslaunch's, Python's, Qt's and C++'s words."""
from exp_assignment2.grading.judge import logs
from exp_assignment2.grading.judge import python_errors

ROSLAUNCH_MISSING = '''... logging to /w/ros_home/log/abc/roslaunch-host-77.log
started roslaunch server http://localhost:40000/

SUMMARY
========

NODES
  /
    dog (exp_assignment2/dog.py)
    ghost (exp_assignment2/ghost.py)

ERROR: cannot launch node of type [exp_assignment2/ghost.py]: Cannot locate node of type [ghost.py] in package [exp_assignment2]. Make sure file exists in package path and permission is set to executable (chmod +x)
process[dog-2]: started with pid [90]
'''

QT_ABORT = '''process[viewer-3]: started with pid [120]
[INFO] [1.0]: the camera is up
qt.qpa.xcb: could not connect to display 
qt.qpa.plugin: Could not load the Qt platform plugin "xcb" in "/usr/lib/python3/dist-packages/cv2/qt/plugins" even though it was found.
This application failed to start because no Qt platform plugin could be initialized. Reinstalling the application may fix this problem.

Available platform plugins are: xcb.

[viewer-3] process has died [pid 120, exit code -6, cmd /w/src/scripts/viewer.py __name:=viewer __log:=/w/ros_home/log/abc/viewer-3.log].
log file: /w/ros_home/log/abc/viewer-3*.log
'''

CPP_ABORT = '''process[counter-4]: started with pid [130]
counting
terminate called after throwing an instance of 'std::runtime_error'
  what():  the counter has no numbers
[counter-4] process has died [pid 130, exit code -6, cmd /w/devel/lib/p/counter __name:=counter __log:=/w/ros_home/log/abc/counter-4.log].
'''

PY_CRASH = '''process[dog-5]: started with pid [88]
Traceback (most recent call last):
  File "/w/src/scripts/dog.py", line 4, in <module>
    raise RuntimeError('the dog has no legs')
RuntimeError: the dog has no legs
[dog-5] process has died [pid 88, exit code 1, cmd /w/src/scripts/dog.py __name:=dog __log:=/w/ros_home/log/abc/dog-5.log].
'''


def test_a_node_roslaunch_cannot_start_is_found_and_is_not_a_start_failure():
    found = logs.cannot_launch([('logs/command-1.log', ROSLAUNCH_MISSING)])
    assert found == [('logs/command-1.log', 'ERROR: cannot launch node of type '
                      '[exp_assignment2/ghost.py]: Cannot locate node of type [ghost.py] in '
                      'package [exp_assignment2]. Make sure file exists in package path and '
                      'permission is set to executable (chmod +x)')]
    assert logs.started_nothing(ROSLAUNCH_MISSING) is None
    assert logs.deaths([('logs/command-1.log', ROSLAUNCH_MISSING)]) == []


def test_commands_that_started_nothing():
    for text, line in [
            ('RLException: [x.launch] is neither a launch file in package [p] nor is [p] a '
             'launch file name\nThe traceback for the exception was written to the log file\n',
             'RLException: [x.launch] is neither a launch file in package [p] nor is [p] a '
             'launch file name'),
            ('... logging to x\nRLException: Invalid roslaunch XML syntax: mismatched tag: '
             'line 9, column 2\n', 'RLException: Invalid roslaunch XML syntax: mismatched tag: '
             'line 9, column 2'),
            ("[rosrun] Couldn't find executable named ghost.py below /w/src\n",
             "[rosrun] Couldn't find executable named ghost.py below /w/src"),
            ("[rospack] Error: package 'nope' not found\n",
             "[rospack] Error: package 'nope' not found"),
            ('Resource not found: nope\nROS path [0]=/opt/ros\n', 'Resource not found: nope')]:
        assert logs.started_nothing(text) == line


def test_an_abort_after_qt_says_why_and_names_its_signal(tmp_path):
    work = tmp_path / 'work'
    own = work / 'ros_home' / 'log' / 'abc'
    own.mkdir(parents=True)
    (own / 'viewer-3.log').write_text('[rospy.client][INFO] init_node, name[/viewer]\n')
    text = QT_ABORT.replace('/w/', str(work) + '/')
    sizes = {'logs/command-0.log': len(text), 'ros_home/log/abc/viewer-3.log': 100}
    (d,) = logs.deaths([('logs/command-0.log', text)], str(work), sizes)
    assert (d['node'], d['code'], d['exit']) == ('viewer-3', -6, '-6 (SIGABRT)')
    assert d['abort'].split('\n')[0] == 'qt.qpa.xcb: could not connect to display'
    assert 'This application failed to start because no Qt platform plugin' in d['abort']
    assert d['output'].splitlines()[0] == 'process[viewer-3]: started with pid [120]'
    assert d['node_logs'] == [{'log': 'ros_home/log/abc/viewer-3.log',
                               'tail': '[rospy.client][INFO] init_node, name[/viewer]'}]


def test_a_cpp_terminate_is_the_abort_message():
    (d,) = logs.deaths([('logs/command-0.log', CPP_ABORT)])
    assert d['exit'] == '-6 (SIGABRT)'
    assert d['abort'] == ("terminate called after throwing an instance of "
                          "'std::runtime_error'\nwhat():  the counter has no numbers")


def test_a_python_crash_has_its_traceback_and_no_abort():
    (d,) = logs.deaths([('logs/command-0.log', PY_CRASH)])
    assert (d['exit'], d['abort']) == ('1', '')
    assert d['output'].splitlines()[-1] == 'RuntimeError: the dog has no legs'
    (error,) = python_errors.python_errors([('logs/command-0.log', PY_CRASH)])
    assert (error['line'], error['summary']) == (2, 'RuntimeError: the dog has no legs')


def test_tracebacks_in_a_log_and_quiet_endings_left_out():
    text = ('[INFO] starting\nTraceback (most recent call last):\n  File "x.py", line 3, '
            'in <module>\n    go()\nZeroDivisionError: division by zero\n[INFO] more\n')
    found = python_errors.tracebacks(text, 'logs/command-0.log')
    assert [(e['line'], e['summary']) for e in found] == [(2, 'ZeroDivisionError: division '
                                                              'by zero')]
    quiet = 'Traceback (most recent call last):\n  File "x.py", line 3\nKeyboardInterrupt\n'
    assert python_errors.python_errors([('a', quiet)]) == []
    # a node's stdout and its own log say the same traceback: once
    assert len(python_errors.python_errors([('a', text), ('b', text)])) == 1


def test_colours_and_the_terminal_title_are_not_read(tmp_path):
    (tmp_path / 'logs').mkdir()
    (tmp_path / 'logs' / 'command-0.log').write_bytes(
        b'\x1b]2;/w/a.launch http://localhost:11311\x07\x1b[31mERROR: red\x1b[0m\n')
    assert logs.read_log(str(tmp_path), 'logs/command-0.log', {}) == 'ERROR: red\n'


def test_exit_codes_named():
    assert [logs.exit_name(c) for c in (1, -6, -11, -9, None)] == [
        '1', '-6 (SIGABRT)', '-11 (SIGSEGV)', '-9 (SIGKILL)', '?']


# roslaunch's words for a required node's death (pmon.py: the banner glued to its
# rule, the exit on the next line) and for a node it restarts (respawn="true")
REQUIRED_DEATH = '''process[dog-5]: started with pid [88]
Traceback (most recent call last):
  File "/w/src/scripts/dog.py", line 9, in <module>
    raise RuntimeError('the dog is tired')
RuntimeError: the dog is tired
================================================================================REQUIRED process [dog-5] has died!
process has died [pid 88, exit code 1, cmd /w/src/scripts/dog.py __name:=dog __log:=/w/ros_home/log/abc/dog-5.log].
log file: /w/ros_home/log/abc/dog-5*.log
Initiating shutdown!
================================================================================
[ball_spawner-4] killing on exit
'''
RESPAWNED = '''process[robot_state_publisher-3]: started with pid [70]
[ERROR] [1.0]: Could not find parameter robot_description on parameter server
[robot_state_publisher-3] process has died [pid 70, exit code 1, cmd /usr/lib/robot_state_publisher/robot_state_publisher __name:=robot_state_publisher __log:=/w/ros_home/log/abc/robot_state_publisher-3.log].
log file: /w/ros_home/log/abc/robot_state_publisher-3*.log
[robot_state_publisher-3] restarting process
process[robot_state_publisher-3]: started with pid [75]
[ERROR] [5.0]: Could not find parameter robot_description on parameter server
[robot_state_publisher-3] process has died [pid 75, exit code 1, cmd /usr/lib/robot_state_publisher/robot_state_publisher __name:=robot_state_publisher __log:=/w/ros_home/log/abc/robot_state_publisher-3.log].
log file: /w/ros_home/log/abc/robot_state_publisher-3*.log
[robot_state_publisher-3] restarting process
process[robot_state_publisher-3]: started with pid [80]
[ERROR] [9.0]: Could not find parameter robot_description on parameter server
[robot_state_publisher-3] process has died [pid 80, exit code 1, cmd /usr/lib/robot_state_publisher/robot_state_publisher __name:=robot_state_publisher __log:=/w/ros_home/log/abc/robot_state_publisher-3.log].
'''


def test_a_required_nodes_death_is_roslaunchs_banner_with_its_exit():
    (dead,) = logs.deaths([('logs/command-0.log', REQUIRED_DEATH)])
    assert (dead['node'], dead['code'], dead['required']) == ('dog-5', 1, True)
    assert dead['cmd'].startswith('/w/src/scripts/dog.py __name:=dog')
    assert dead['output'].endswith('RuntimeError: the dog is tired')
    # one that ended cleanly still ended the launch; one without an exit code is said so
    clean = REQUIRED_DEATH.replace('process has died [pid 88, exit code 1, cmd /w/src/scripts/'
                                   'dog.py __name:=dog __log:=/w/ros_home/log/abc/dog-5.log].',
                                   'process has finished cleanly')
    assert [(d['code'], d['required']) for d in logs.deaths([('l', clean)])] == [(0, True)]
    bare = REQUIRED_DEATH.replace('died [pid 88, exit code 1, cmd', 'died without exit code '
                                  '[pid 88, cmd')
    assert [(d['code'], d['exit']) for d in logs.deaths([('l', bare)])] == [(None, '?')]


def test_a_respawned_node_is_noted_once_with_how_often_it_died():
    (dead,) = logs.deaths([('logs/command-0.log', RESPAWNED)])
    assert (dead['node'], dead['deaths'], dead['restarted'], dead['required']) == (
        'robot_state_publisher-3', 3, 2, False)
    assert 'Could not find parameter robot_description' in dead['output']


def test_the_runner_sees_a_required_death_and_nothing_else(tmp_path):
    """Read as the logs grow, each byte once: a banner cut between two looks is found."""
    (tmp_path / 'logs').mkdir()
    watch = logs.RequiredWatch(str(tmp_path))
    assert watch.death() is None
    (tmp_path / 'logs' / 'command-0.log').write_text(ROSLAUNCH_MISSING + PY_CRASH + RESPAWNED)
    assert watch.death() is None          # deaths roslaunch runs on after
    cut = REQUIRED_DEATH.index('[dog-5] has')
    with open(str(tmp_path / 'logs' / 'command-1.log'), 'w') as f:
        f.write(REQUIRED_DEATH[:cut])
        f.flush()
        assert watch.death() is None
        f.write(REQUIRED_DEATH[cut:])
    assert watch.death() == 'dog-5'


HANDSHAKE = '''[rospy.internal][ERROR] 2026-11-27 05:13:57,820: Inbound TCP/IP connection failed:
Traceback (most recent call last):
  File "/usr/lib/python3/dist-packages/rospy/impl/tcpros_base.py", line 334, in _tcp_server_callback
    header = read_ros_handshake_header(sock, BytesIO(), buff_size)
rosgraph.network.ROSHandshakeException: connection from sender terminated before handshake header received. 0 bytes were received. Please check sender for additional details.
'''


def test_rospy_transport_noise_is_no_python_error():
    """A peer that hung up before its handshake (seen in a CI run, in the
    simulator's log): rospy logs a traceback; nothing the node's code did."""
    assert python_errors.python_errors([('ros_home/log/r/dog-5.log', HANDSHAKE)]) == []


def test_the_simulators_own_log_is_the_graders(tmp_path):
    """roslaunch's log names each node's command line and its log file: the
    simulator's (gzserver's, simulator.py's) are left out of the student's
    errors, a student node's are kept. Inside the sandbox the run's directory
    has another path: its ROS_HOME is the same place."""
    launch = ("[roslaunch][INFO] x: process[gazebo-1]: start w/ args [['/ws/gazebo_ros/scripts/"
              "gzserver', '-e', 'ode', '__name:=gazebo', '__log:=/tmp/exp2-grade-x/runs/L/work/"
              "ros_home/log/r/gazebo-1.log']]\n"
              "[roslaunch][INFO] x: process[dog-5]: start w/ args [['/w/src/scripts/dog.py', "
              "'__name:=dog', '__log:=%s/ros_home/log/r/dog-5.log']]\n" % tmp_path)
    files = {'ros_home/log/r/roslaunch-host-1.log': launch,
             'ros_home/log/r/gazebo-1.log': 'Traceback (most recent call last):\nValueError: x\n',
             'ros_home/log/r/dog-5.log': 'Traceback (most recent call last):\nValueError: y\n'}
    for rel, text in files.items():
        path = tmp_path / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    sizes = {rel: len(text) for rel, text in files.items()}
    assert logs.simulator_logs(str(tmp_path), sizes) == {'ros_home/log/r/gazebo-1.log'}


SYNTAX_AT_START = '''process[dog-5]: started with pid [88]
[original-env] waited for keyboard input at scripts/command_request.py:37
  File "/w/src/scripts/dog.py", line 12
    print "Reached"
    ^^^^^^^^^^^^^^^
SyntaxError: Missing parentheses in call to 'print'. Did you mean print(...)?
[dog-5] process has died [pid 88, exit code 1, cmd /w/src/scripts/dog.py __name:=dog].
'''


def test_a_script_that_cannot_compile_is_a_python_error_with_its_file_and_line():
    """Python prints a script's SyntaxError without a Traceback line."""
    (error,) = python_errors.python_errors([('logs/command-0.log', SYNTAX_AT_START)])
    assert (error['line'], error['summary']) == (
        3, "SyntaxError: Missing parentheses in call to 'print'. Did you mean print(...)? "
           "(/w/src/scripts/dog.py, line 12)")
    assert error['excerpt'].splitlines()[0] == '  File "/w/src/scripts/dog.py", line 12'
    indentation = ('  File "x.py", line 4\n    return 3\n              ^\n'
                   'IndentationError: unindent does not match any outer indentation level\n')
    (error,) = python_errors.tracebacks(indentation, 'a')
    assert error['summary'] == ('IndentationError: unindent does not match any outer '
                                'indentation level (x.py, line 4)')
    # said in the command's output and in the node's own log: once
    assert len(python_errors.python_errors([('a', SYNTAX_AT_START), ('b', SYNTAX_AT_START)])) == 1


def test_a_syntax_error_inside_a_traceback_is_counted_once():
    text = ('Traceback (most recent call last):\n  File "n.py", line 1, in <module>\n'
            '    import helper\n  File "/w/helper.py", line 3\n    print "x"\n    ^^^^^^^^^\n'
            "SyntaxError: Missing parentheses in call to 'print'. Did you mean print(...)?\n")
    (error,) = python_errors.tracebacks(text, 'a')
    assert error['summary'].startswith('SyntaxError: Missing parentheses')
    assert error['excerpt'].startswith('Traceback')


def test_waiting_for_the_keyboard_and_a_file_line_alone_are_no_errors():
    text = ('[original-env] waited for keyboard input at scripts/command_request.py:37\n'
            '  File "x.py", line 3\n    not followed by an error\nall done\n')
    assert python_errors.python_errors([('logs/command-0.log', text)]) == []


def test_a_module_a_node_could_not_import_is_named_for_what_it_is():
    """Never a bare ImportError: the submission's own package the run did not build,
    or a module the original environment lacks (its page's first error says which)."""
    text = ('Traceback (most recent call last):\n  File "a.py", line 3, in <module>\n'
            '    import %s\nModuleNotFoundError: No module named \'%s\'\n')
    own = python_errors.name_missing(python_errors.tracebacks(
        text % ('pet_msgs.msg', 'pet_msgs'), 'a'), {'pet_msgs', 'pet'})
    assert own[0]['summary'] == ("ModuleNotFoundError: No module named 'pet_msgs': the "
                                 "submission's own package pet_msgs, not built for this run "
                                 "(see its Packages)")
    lacking = python_errors.name_missing(python_errors.tracebacks(
        text % ('pcl', 'pcl'), 'a'), {'pet'})
    assert lacking[0]['summary'].endswith("missing from the original environment: neither "
                                          "this machine's ROS nor the package's stand-ins "
                                          "have pcl (docs/original_env_supplies.md)")
    other = python_errors.tracebacks('Traceback (most recent call last):\n  x\nKeyError: 1\n',
                                     'a')
    assert python_errors.name_missing(other, set()) == other
