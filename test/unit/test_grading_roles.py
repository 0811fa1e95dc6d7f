"""The robot, its head, its camera and the ball found by their roles, whatever
the student named them (grading.roles), and judged as such (grading.metrics,
scores): on hand-made records shaped like the simulator's (roles_records.py)."""
from exp_assignment2.grading.judge import metrics
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.judge import roles
from exp_assignment2.grading.judge import scores
from roles_records import (DOG, ball_facts, joint, outcome, person_facts, robot_facts, states,
                           trace_of)


def test_a_renamed_robot_head_and_ball_are_found_by_their_roles():
    """robot2 in its own namespace, its head on camera_joint, the ball called toy:
    judged as the robot, head and ball the profile calls robot, head and ball."""
    trace = trace_of([robot_facts(), ball_facts(), person_facts()],
                     fed={'robot2': 900, 'toy': 40}, extra={'person': [-7, 7, 0, 0]})
    found, got = outcome(trace)
    assert (found.robot.name, found.head.name, found.camera.name, found.ball.name) == (
        'robot2', 'camera_joint', 'robot2/camera1', 'toy')
    assert found.namespace == 'robot2'
    assert found.robot.why == ('`robot2`: driven through /robot2/cmd_vel (900 commands) and '
                               'carries camera `camera1` (no model `robot`)')
    assert found.head.why == ('`camera_joint`, the joint that turns camera `camera1` (on '
                              '`camera_link`)')
    assert found.ball.why == ('`toy`: a sphere of radius 0.5 m, moved through /toy/cmd_vel '
                              '(40 commands) (no model `ball`)')
    # the 30 s gave no sleep, no wander, no moving or hidden ball: those are not judged
    assert got == {'approaches': (1, True), 'first_approach_time': (3.2, True),
                   'looks_both_ways': (1.0, True), 'follows_ball': (None, None),
                   'gives_up_ball': (None, None), 'sleeps': (None, None),
                   'wanders': (None, None), 'path_length': (2.5, True),
                   'python_errors': (0, True)}


def test_the_profiles_names_come_first():
    """A model called robot is the robot, even beside another that is driven more."""
    trace = trace_of([robot_facts(name='robot', namespace='robot', head='joint_head'),
                      robot_facts(name='rover', namespace='rover'), ball_facts(name='ball')],
                     robot='robot', ball='ball', head='joint_head',
                     fed={'robot': 5, 'rover': 5000})
    found, got = outcome(trace)
    assert (found.robot.name, found.head.name, found.ball.name) == ('robot', 'joint_head', 'ball')
    assert found.robot.why == '`robot`, as the profile names it'
    assert found.head.why == '`joint_head`, named like `head` as the profile asks'
    assert got['looks_both_ways'] == (1.0, True)


def test_the_person_is_not_the_robot_and_the_ball_is_the_sphere():
    """Nothing drove anything yet: the robot is the one with the camera; the
    ball is the sphere no command moved (the ball server never ran)."""
    trace = trace_of([person_facts(), robot_facts(name='dog', namespace=''),
                      ball_facts(name='green', plugins=False)],
                     robot='dog', ball='green', fed={}, extra={'person': [-7, 7, 0, 0]})
    found, _ = outcome(trace)
    assert (found.robot.name, found.ball.name) == ('dog', 'green')
    assert found.ball.why == '`green`: a sphere of radius 0.5 m (no model `ball`)'
    assert found.namespace == ''


def test_a_camera_fixed_to_a_robot_with_no_other_joint_is_no_head():
    """The thing is absent: the check fails, saying so."""
    trace = trace_of([robot_facts(head_type='fixed'), ball_facts()])
    found, got = outcome(trace)
    assert found.head.name is None and found.head.absent
    assert got['looks_both_ways'] == (None, False)
    detail = next(c['detail'] for c in metrics.evaluate(trace, DOG, found)
                  if c['metric'] == 'looks_both_ways')
    assert detail == ('camera `camera1` on `camera_link` is fixed and no joint but the wheels '
                      'moves: `robot2` has no head')


def test_a_head_that_cannot_be_told_is_not_judged_and_its_points_wait_for_a_person():
    """The camera is fixed to the chassis and another joint turns something else:
    a person must look. The check is not run, neither passed nor failed; its
    points are pending; the verdict's reason says which was not judged."""
    facts = robot_facts(head_type='fixed')
    facts['joints']['flag_joint'] = joint('revolute', 'link_chassis', 'flag', [0, 0, 1])
    trace = trace_of([facts, ball_facts()])
    found, got = outcome(trace)
    assert found.head.name is None and not found.head.absent
    assert 'which is the head cannot be told' in found.head.why
    assert got['looks_both_ways'] == (None, None)
    assert got['approaches'] == (1, True)
    checks = metrics.evaluate(trace, DOG, found)
    head = next(c for c in checks if c['metric'] == 'looks_both_ways')
    assert head['judged'] is False and head['detail'].startswith('not judged: no joint turns')
    marks = scores.run_score({'verdict': 'passed', 'checks': checks}, DOG)
    # the head's 15, and the behaviours the 30 s gave no occasion for (10 each)
    assert marks['score'] == 45.0 and marks['pending'] == 55.0
    assert 'not judged by the grader (head turns both ways at the ball, ' in marks['why']
    head_marks = next(c for c in marks['checks']
                      if c['name'] == 'head turns both ways at the ball')
    assert head_marks['points'] is None and head_marks['pending']


def test_no_robot_in_the_world_fails_what_needs_one():
    trace = metrics.Trace([{'t': t / 10.0, 'models': {'kennel': [7, 7, 0, 0]}, 'joints': {}}
                           for t in range(50)],
                          models={'kennel': dict(ball_facts('kennel', plugins=False),
                                                 static=True, sphere=None)})
    found, got = outcome(trace)
    assert found.robot.name is None and found.robot.absent
    assert got['path_length'] == (None, False) and got['approaches'] == (None, False)


def test_a_relative_topic_is_the_judged_robots():
    """A check's topic without a leading slash is under the robot's namespace."""
    profile = dict(DOG, checks=[{'name': 'goals', 'metric': 'arrivals', 'topic': 'goal',
                                 'tolerance': 0.5, 'min': 1}])
    trace = trace_of([robot_facts(), ball_facts()])
    trace.topics = [(1.0, '/robot2/goal', {'data': [2.5, 0.0]}),
                    (2.0, '/goal', {'data': [9.0, 9.0]})]
    _, got = outcome(trace, profile)
    assert got['arrivals'] == (1, True)


def test_roles_travel_in_the_run_record():
    trace = trace_of([robot_facts(), ball_facts()])
    found = roles.find(trace, DOG)
    again = roles.of_run({'roles': found.to_dict()}, metrics.Trace(), DOG)
    assert again.to_dict() == found.to_dict() and again.head.name == 'camera_joint'


def test_of_two_joints_named_head_the_one_that_turns_the_camera_left_and_right():
    """head_tilt and head_yaw both hold 'head': the yaw one turns the head around."""
    facts = robot_facts(head='head_tilt', axis=(0.0, 1.0, 0.0))
    facts['joints']['head_tilt']['parent'] = 'pan_link'
    facts['joints']['head_yaw'] = joint('revolute', 'link_neck', 'pan_link', [0.0, 0.0, 1.0])
    run = states(head='head_tilt')
    for state in run:
        state['joints']['robot2']['head_yaw'] = state['joints']['robot2']['head_tilt']
    trace = metrics.Trace(run, models={'robot2': facts, 'toy': ball_facts()})
    found = roles.find(trace, DOG)
    assert found.head.name == 'head_yaw' and found.camera.name == 'robot2/camera1'


def test_the_teacher_names_what_the_grader_could_not_tell():
    """A head that cannot be told (see above), named by the teacher for this
    submission in grading.yaml: judged, and the page says who named it."""
    facts = robot_facts(head='flag_joint', axis=(0.0, 0.0, 1.0))
    facts['joints']['flag_joint']['parent'] = 'link_chassis'     # not under the camera
    facts['joints']['flag_joint']['child'] = 'flag'
    facts['joints']['joint_neck_link'] = joint('fixed', 'link_neck', 'link_head')
    trace = metrics.Trace(states(head='flag_joint'),
                          models={'robot2': facts, 'toy': ball_facts()})
    assert roles.find(trace, DOG).head.name is None
    mine = profiles.with_teacher_roles(DOG, {'head': 'flag_joint', 'robot': 'robot2'})
    assert DOG['robot'] == 'robot' and DOG['checks'][2].get('joint') == 'head'   # unchanged
    found, got = outcome(trace, mine)
    assert found.head.name == 'flag_joint' and got['looks_both_ways'] == (1.0, True)
    assert found.head.why == '`flag_joint`, as grading.yaml names it for this submission'
    assert found.robot.why == '`robot2`, as grading.yaml names it for this submission'


def test_an_idle_template_robot_is_not_the_one_the_student_played_with():
    """The template's robot and ball are spawned and left alone; the student
    drives robot2 and moves toy: those are judged, the page saying why."""
    facts = [robot_facts(name='robot', namespace='robot', head='joint_head'), robot_facts(),
             ball_facts(name='ball'), ball_facts()]
    trace = trace_of(facts, fed={'robot2': 500, 'toy': 30},
                     extra={'robot': [-5, 7, 0, 0], 'ball': [-7, 6, 0.5, 0]})
    found, got = outcome(trace)
    assert (found.robot.name, found.ball.name) == ('robot2', 'toy')
    assert found.robot.why.endswith('(`robot` is there, but nothing drove it)')
    assert found.ball.why.endswith('(`ball` is there, but nothing moved it)')
    assert got['approaches'] == (1, True)


def test_the_ball_is_a_sphere_before_anything_a_command_moved():
    """The person was put somewhere once; the green sphere nobody moved is the ball."""
    person = dict(ball_facts(name='person', plugins=False), sphere=None, kinematic=False)
    trace = trace_of([robot_facts(), person, ball_facts(name='green', plugins=False)],
                     ball='green', fed={'robot2': 100}, placed={'person': 1},
                     extra={'person': [-7, 7, 0, 0]})
    assert roles.find(trace, DOG).ball.name == 'green'


def test_an_empty_world_fails_what_needs_a_robot():
    """Nothing was spawned: absent, not "cannot be told" (the run is not passed)."""
    trace = metrics.Trace([{'t': i / 10.0, 'models': {}, 'joints': {}} for i in range(50)])
    found, got = outcome(trace)
    assert found.robot.absent and got['path_length'] == (None, False)
    assert got['looks_both_ways'] == (None, False)


def test_a_joint_named_head_that_does_not_turn_the_camera_is_not_the_head():
    facts = robot_facts()
    facts['joints']['head_light'] = joint('revolute', 'link_chassis', 'light', [0, 0, 1])
    run = states()
    for state in run:
        state['joints']['robot2']['head_light'] = 0.0
    trace = metrics.Trace(run, models={'robot2': facts, 'toy': ball_facts()})
    found, got = outcome(trace)
    assert found.head.name == 'camera_joint' and got['looks_both_ways'] == (1.0, True)


def test_a_depth_camera_and_a_robot_with_no_drive_plugin():
    """A Kinect-like depth sensor is a camera; a robot driven through ros_control's
    velocity controllers (no drive plugin) is the robot by its camera and its way."""
    facts = robot_facts()
    facts['sensors'][0]['type'] = 'depth'
    facts['plugins'] = [p for p in facts['plugins'] if not p.get('drive')]
    trace = trace_of([facts, ball_facts()], fed={})
    found = roles.find(trace, DOG)
    assert (found.robot.name, found.head.name) == ('robot2', 'camera_joint')
    assert found.robot.why.startswith('`robot2`: carries camera `camera1`')


def test_casters_are_wheels_so_a_fixed_camera_means_no_head():
    facts = robot_facts(head_type='fixed')
    facts['joints']['caster'] = joint('continuous', 'link_chassis', 'caster', [0, 0, 1])
    found = roles.find(trace_of([facts, ball_facts()]), DOG)
    assert found.head.name is None and found.head.absent


def test_odd_facts_do_not_break_the_grading():
    """Facts with keys missing (an older or a hostile record) are read as unknown."""
    trace = trace_of([{'name': 'robot2'}, {'name': 'toy', 'sphere': 0.5}])
    found = roles.find(trace, DOG)
    assert (found.robot.name, found.ball.name) == ('robot2', 'toy')     # it went 2.5 m
    assert found.robot.why == '`robot2`: driven (3000 commands) (no model `robot`)'
    assert roles.Roles.from_dict({'robot': {'name': 'r', 'why': 'w', 'extra': 1},
                                  'head': 'nonsense'}).robot.name == 'r'


def test_a_head_the_teacher_names_that_the_robot_lacks_is_not_judged():
    trace = trace_of([robot_facts(), ball_facts()])
    found, got = outcome(trace, profiles.with_teacher_roles(DOG, {'head': 'neck_yaw'}))
    assert found.head.name is None and not found.head.absent
    assert found.head.why.startswith('grading.yaml names the head `neck_yaw`; `robot2` has no')
    assert got['looks_both_ways'] == (None, None)
