"""Hand-made records shaped like the simulator's (sim.model_facts) for the tests
of the roles (test_grading_roles.py): a dog as students build it, a ball, a
person, and a run in which the robot drives to the ball and turns its head."""
import math

from exp_assignment2.grading.judge import metrics, roles
from exp_assignment2.grading.plan import profiles

DOG = profiles.load('dog')


def joint(kind, parent, child, axis=None):
    return {'type': kind, 'parent': parent, 'child': child, 'axis': axis}


def robot_facts(name='robot2', namespace='robot2', head='camera_joint', camera=True,
                head_type='revolute', axis=(0.0, 0.0, 1.0)):
    """A dog as students build it: wheels, a neck, a head on ``head``, a camera on it."""
    facts = {'name': name, 'namespace': namespace, 'root': 'link_chassis', 'static': False,
             'kinematic': False, 'sphere': None, 'colour': None,
             'links': ['link_chassis', 'link_left_wheel', 'link_right_wheel', 'link_neck',
                       'link_head', 'camera_link'],
             'joints': {'joint_left_wheel': joint('continuous', 'link_chassis',
                                                  'link_left_wheel', [0.0, 1.0, 0.0]),
                        'joint_right_wheel': joint('continuous', 'link_chassis',
                                                   'link_right_wheel', [0.0, 1.0, 0.0]),
                        'joint_neck': joint('fixed', 'link_chassis', 'link_neck'),
                        head: joint(head_type, 'link_neck', 'link_head',
                                    list(axis) if head_type != 'fixed' else None),
                        'joint_camera': joint('fixed', 'link_head', 'camera_link')},
             'sensors': [], 'plugins': [
                 {'file': 'libgazebo_ros_diff_drive.so', 'name': 'drive', 'drive': True,
                  'command': '/%s/cmd_vel' % namespace,
                  'joints': ['joint_left_wheel', 'joint_right_wheel']}]}
    if camera:
        facts['sensors'] = [{'type': 'camera', 'name': 'camera1', 'link': 'camera_link'}]
        facts['plugins'].append({'file': 'libgazebo_ros_camera.so', 'name': 'cam',
                                 'sensor': facts['sensors'][0], 'camera': 'camera1',
                                 'image': '/%s/camera1/image_raw/compressed' % namespace})
    return facts


def ball_facts(name='toy', plugins=True):
    return {'name': name, 'namespace': name, 'root': 'ball_link', 'static': False,
            'kinematic': True, 'sphere': 0.5, 'colour': [0, 0.8, 0, 1], 'links': ['ball_link'],
            'joints': {}, 'sensors': [], 'plugins': [
                {'file': 'libgazebo_ros_planar_move.so', 'name': 'move', 'drive': True,
                 'command': '/%s/cmd_vel' % name, 'joints': []}] if plugins else []}


def person_facts():
    """A second robot-like model: a person on wheels nobody drives, with no camera."""
    facts = robot_facts(name='person', namespace='person', camera=False)
    return facts


def states(robot='robot2', ball='toy', head='camera_joint', wiggle=0.8, fed=None, placed=None,
           until=30.0, extra=None):
    """The robot drives to 1.5 m of the ball by t = 10 s, then turns its head."""
    out = []
    for i in range(int(until * 10) + 1):
        t = i / 10.0
        x = min(2.5, 2.5 * t / 10.0)
        models = {robot: [x, 0.0, 0.1, 0.0], ball: [4.0, 0.0, 0.5, 0.0]}
        models.update(extra or {})
        state = {'t': t, 'models': models,
                 'joints': {robot: {head: wiggle * math.sin(t) if t > 10 else 0.0,
                                    'joint_left_wheel': t, 'joint_right_wheel': t}}}
        state['fed'] = dict(fed if fed is not None else {robot: 10 * i, ball: 0})
        if placed:
            state['placed'] = dict(placed)
        out.append(state)
    return out


def trace_of(facts, **kwargs):
    return metrics.Trace(states(**kwargs), models={f['name']: f for f in facts})


def outcome(trace, profile=DOG):
    found = roles.find(trace, profile)
    return found, {c['metric']: (c['value'], c['passed'])
                   for c in metrics.evaluate(trace, profile, found)}
