"""Loops of a submission's Python that go round without waiting
(exp_assignment2.grading.plan.busy_loops; no ROS): the shapes of a real class's
(a loop that sleeps in one branch only, ``rate.sleep`` without its call, a wait on a
flag a callback sets), Python 2 files, and loops that do wait."""
import textwrap

from exp_assignment2.grading.plan import busy_loops


def lines(source):
    return busy_loops.in_tree(busy_loops._tree(textwrap.dedent(source), 'node.py'))


def test_a_loop_that_waits_on_every_way_round_is_not_busy():
    assert lines('''
        while not rospy.is_shutdown():
            if seen:
                pub.publish(twist)
            rate.sleep()
        while client.get_state() != 3:
            rospy.sleep(0.1)
        while True:
            msg = rospy.wait_for_message('/odom', Odometry)
            if msg.pose.pose.position.x > 1:
                break
        ''') == []


def test_the_busy_shapes_of_a_real_class():
    """(polling the parameter server or a service in a loop that never sleeps is
    busy too: it keeps the master's core busy as well as its own)"""
    assert lines('''
        while not self.arrived:                      # a flag a callback sets
            pass
        while not rospy.is_shutdown():               # sleeps in one state only
            if self.behaviour == 'normal':
                self.go()
                self.rate.sleep()
            elif self.behaviour == 'play':
                self.follow()
        while not rospy.is_shutdown():
            self.rate.sleep                          # the call forgotten
        while True:
            if not seen:
                continue                             # round again at once
            rospy.sleep(1)
        ''') == [2, 4, 10, 12]


def test_functions_defined_in_a_loop_do_not_wait_for_it_and_leaving_is_not_busy():
    assert lines('''
        while running:
            def callback(msg):
                rospy.sleep(1)
            sub = rospy.Subscriber('/a', String, callback)
        while True:
            if ready():
                break
            else:
                return
        ''') == [2]


def test_a_python_2_node_is_read_as_its_environment_runs_it():
    source = ('#!/usr/bin/env python\n'
              'import rospy\n'
              'def main():\n'
              '\tprint "waiting"\n'
              '\twhile not flag:\n'
              '\t\tx = 1\n'
              '        print "done"\n')            # a tab and eight spaces: Python 2's one level
    assert busy_loops.in_tree(busy_loops._tree(source, 'node')) == [5]


def test_a_submission_s_built_packages_are_read_and_nothing_else(tmp_path):
    pkg = tmp_path / 'pkg' / 'scripts'
    pkg.mkdir(parents=True)
    (pkg / 'spin.py').write_text('while not done:\n    pass\n')
    (pkg / 'node').write_text('#!/usr/bin/env python3\nwhile True:\n    x = 1\n')
    (pkg / 'notes.txt').write_text('while True:\n    pass\n')
    (pkg / 'broken.py').write_text('while (:\n')
    other = tmp_path / 'vendored'
    other.mkdir()
    (other / 'spin.py').write_text('while 1:\n    pass\n')
    assert busy_loops.in_folders(str(tmp_path), ['pkg']) == [
        ('pkg/scripts/node', 2), ('pkg/scripts/spin.py', 1)]


def test_a_hostile_python_2_file_is_not_translated_for_long(tmp_path):
    """2to3 takes 0.03 s a kilobyte or more: a large Python 2 file is left unread
    (not known to loop), and one submission's translations stop at their time."""
    big = ''.join('def f%d(x):\n    print "a", x\n    while x:\n        pass\n' % i
                  for i in range(3000))
    assert len(big) > busy_loops.MOST_TRANSLATED
    pkg = tmp_path / 'pkg'
    pkg.mkdir()
    (pkg / 'big.py').write_text(big)
    (pkg / 'small.py').write_text('print "a"\nwhile 1:\n    pass\n')
    assert busy_loops.in_folders(str(tmp_path), ['pkg']) == [('pkg/small.py', 2)]
    spent = busy_loops.Budget(0.0)
    assert busy_loops._tree('print "a"\n', 'small.py', spent) is None


def test_a_file_too_deep_to_follow_is_not_known_to_loop(tmp_path):
    """Two thousand elifs parse, and are deeper than a path can be followed."""
    pkg = tmp_path / 'pkg'
    pkg.mkdir()
    (pkg / 'deep.py').write_text('while x:\n    if a == 0:\n        pass\n' + ''.join(
        '    elif a == %d:\n        pass\n' % i for i in range(1, 2000)))
    (pkg / 'spin.py').write_text('while 1:\n    pass\n')
    assert busy_loops.in_folders(str(tmp_path), ['pkg']) == [('pkg/spin.py', 1)]
